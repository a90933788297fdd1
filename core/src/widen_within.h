// SPDX-License-Identifier: MIT
// satviz: CollideWithin's second half, on a manifold Collide already gave (internal), so that a caller asking for
// two margins of one pair, as the world's guards do, collides it once.
#pragma once

#include <satviz/collide.h>

namespace satviz::detail
{

/// Whether CollideWithin's answer for `margin` is Collide's manifold `m` of shapes `a` and `b` as it is. Collide's gap
/// is the separation of the first separating axis it met, at most the largest one: beyond the margin it already
/// proves the pair apart by more. An overlapping pair with two contacts kept both ends of its clipped incident edge,
/// and a circle has one contact: nothing is left to add.
template <typename S>
bool NothingToWiden(const ManifoldT<S>& m, const ShapeT<S>& a, const ShapeT<S>& b, S margin)
{
    return m.gap > margin ||
           (m.overlap && (m.contactCount == 2 || a.type != ShapeType::Polygon || b.type != ShapeType::Polygon));
}

/// WidenWithin past NothingToWiden: replaces `m` by CollideWithin's manifold for `margin`.
template <typename S>
void Widen(ManifoldT<S>& m, const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
           S margin);

/// Turns `m`, Collide's manifold of the shapes at the given transforms, into CollideWithin's for `margin` (>= 0):
/// the same bits as CollideWithin(a, xfA, b, xfB, margin). Returns false when Collide's manifold is already that
/// answer and `m` is left as it was, true when it was replaced. Inline up to the test, as most pairs of a world end
/// there and the call alone would cost them more than the test.
template <typename S>
inline bool WidenWithin(ManifoldT<S>& m, const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                        const TransformT<S>& xfB, S margin)
{
    if (NothingToWiden(m, a, b, margin))
    {
        return false;
    }
    Widen(m, a, xfA, b, xfB, margin);
    return true;
}

} // namespace satviz::detail
