// SPDX-License-Identifier: MIT
// satviz: the world's queries on pairs with a concave body: each side is the body's pieces or its one shape.

#include "body_queries.h"

namespace satviz::detail
{

const Shape& PieceShape(const RigidBody& body, int piece)
{
    return body.IsConcave() && piece >= 0 ? body.concave.parts[static_cast<size_t>(piece)].shape : body.shape;
}

ConcaveManifold CollideBodies(const RigidBody& a, const Transform& xfA, const RigidBody& b, const Transform& xfB)
{
    if (a.IsConcave() && b.IsConcave())
    {
        return Collide(a.concave, xfA, b.concave, xfB);
    }
    if (a.IsConcave())
    {
        return Collide(a.concave, xfA, b.shape, xfB);
    }
    return Collide(a.shape, xfA, b.concave, xfB);
}

ConcaveManifold CollideBodiesWithin(const RigidBody& a, const Transform& xfA, const RigidBody& b, const Transform& xfB,
                                    double margin)
{
    if (a.IsConcave() && b.IsConcave())
    {
        return CollideWithin(a.concave, xfA, b.concave, xfB, margin);
    }
    if (a.IsConcave())
    {
        return CollideWithin(a.concave, xfA, b.shape, xfB, margin);
    }
    return CollideWithin(a.shape, xfA, b.concave, xfB, margin);
}

ConcaveSweepResult SweepBodies(const RigidBody& a, const Transform& xfA, Vec2 vA, const RigidBody& b,
                               const Transform& xfB, Vec2 vB)
{
    if (a.IsConcave() && b.IsConcave())
    {
        return Sweep(a.concave, xfA, vA, b.concave, xfB, vB);
    }
    if (a.IsConcave())
    {
        return Sweep(a.concave, xfA, vA, b.shape, xfB, vB);
    }
    return Sweep(a.shape, xfA, vA, b.concave, xfB, vB);
}

} // namespace satviz::detail
