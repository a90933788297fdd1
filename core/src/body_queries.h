// SPDX-License-Identifier: MIT
// satviz: the world's queries on a pair of bodies of which one at least is concave (internal). A convex pair never
// comes here: the step calls the convex queries on it directly, as it always has.
#pragma once

#include <satviz/concave.h>
#include <satviz/world.h>

namespace satviz::detail
{

/// True when the pair needs the concave queries.
inline bool AnyConcave(const RigidBody& a, const RigidBody& b)
{
    return a.IsConcave() || b.IsConcave();
}

/// The piece `piece` of a concave body, or the body's shape when it is convex (or piece < 0).
const Shape& PieceShape(const RigidBody& body, int piece);

/// Collide (concave.h) for the bodies' shapes at the given transforms.
ConcaveManifold CollideBodies(const RigidBody& a, const Transform& xfA, const RigidBody& b, const Transform& xfB);

/// CollideWithin (concave.h) for the bodies' shapes at the given transforms.
ConcaveManifold CollideBodiesWithin(const RigidBody& a, const Transform& xfA, const RigidBody& b, const Transform& xfB,
                                    double margin);

/// Sweep (concave.h) for the bodies' shapes at the given transforms, moving by vA and vB.
ConcaveSweepResult SweepBodies(const RigidBody& a, const Transform& xfA, Vec2 vA, const RigidBody& b,
                               const Transform& xfB, Vec2 vB);

} // namespace satviz::detail
