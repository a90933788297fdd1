// SPDX-License-Identifier: MIT
// satviz: CollideWithin's second half, on a manifold Collide already gave (internal), so that a caller asking for
// two margins of one pair, as the world's guards do, collides it once.
#pragma once

#include <satviz/collide.h>

namespace satviz::detail
{

/// Turns `m`, Collide's manifold of the shapes at the given transforms, into CollideWithin's for `margin` (>= 0):
/// the same bits as CollideWithin(a, xfA, b, xfB, margin). Returns false when Collide's manifold is already that
/// answer and `m` is left as it was, true when it was replaced.
template <typename S>
bool WidenWithin(ManifoldT<S>& m, const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                 const TransformT<S>& xfB, S margin);

} // namespace satviz::detail
