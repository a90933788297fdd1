// SPDX-License-Identifier: MIT
// satviz: the world's queries on a pair of bodies of which one at least is concave (internal). A convex pair never
// comes here: the step calls the convex queries on it directly, as it always has.
#pragma once

#include <satviz/collide.h>
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

/// The manifold of any pair of bodies, within `margin` (CollideWithin) when it is above 0, else Collide: the convex
/// queries for a convex pair, the concave ones (one merged manifold, seams dropped) when either body is concave.
/// For a convex pair pieceA and pieceB stay -1 and the piece counters 0.
inline ConcaveManifold CollidePair(const RigidBody& a, const Transform& xfA, const RigidBody& b, const Transform& xfB,
                                   double margin = 0.0)
{
    if (AnyConcave(a, b))
    {
        return margin > 0.0 ? CollideBodiesWithin(a, xfA, b, xfB, margin) : CollideBodies(a, xfA, b, xfB);
    }
    ConcaveManifold cm;
    cm.manifold = margin > 0.0 ? CollideWithin(a.shape, xfA, b.shape, xfB, margin) : Collide(a.shape, xfA, b.shape, xfB);
    return cm;
}

/// Sweep (concave.h) for the bodies' shapes at the given transforms, moving by vA and vB.
ConcaveSweepResult SweepBodies(const RigidBody& a, const Transform& xfA, Vec2 vA, const RigidBody& b,
                               const Transform& xfB, Vec2 vB);

} // namespace satviz::detail
