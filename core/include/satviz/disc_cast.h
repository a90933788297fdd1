// SPDX-License-Identifier: MIT
// satviz: thick bullets: a disc cast along a segment against a shape, like RayCast with a radius.
#pragma once

#include <satviz/concave.h>
#include <satviz/shape.h>

namespace satviz
{

/// Where a disc moved along a segment first touches a shape.
template <typename S>
struct DiscHitT
{
    bool hit = false;          ///< the disc meets the shape on its way
    bool startsInside = false; ///< the disc overlaps the shape at p1 already (fraction 0, normal: the push out)
    S fraction{};              ///< how far along: centre = p1 + fraction * (p2 - p1), in [0, 1]
    Vec2T<S> center{};         ///< the disc's centre when it first touches
    Vec2T<S> point{};          ///< the point of contact on the shape's surface (world)
    Vec2T<S> normal{};         ///< unit outward normal of the shape there, towards the disc's centre
    int piece = -1;            ///< a concave shape: the piece touched; else -1
};

/// Double-precision disc hit.
using DiscHit = DiscHitT<double>;

/// The first point where a disc of `radius` (> 0) whose centre moves from p1 to p2 (world) touches the shape
/// placed by xf: the swept test (Sweep) of the disc against the still shape, which casts the centre against the
/// shape's outline pushed out by the radius (its faces moved out, and arcs around its vertices), exact at any
/// speed. A disc that only grazes the shape, touching it at one instant without entering, does not hit, as in
/// Sweep. A disc that overlaps the shape at p1 reports startsInside, with the normal that pushes it out.
template <typename S>
DiscHitT<S> CastDisc(const ShapeT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2, S radius);

/// The same against a concave shape: the earliest piece (Sweep for concave shapes).
template <typename S>
DiscHitT<S> CastDisc(const ConcaveT<S>& shape, const TransformT<S>& xf, Vec2T<S> p1, Vec2T<S> p2, S radius);

} // namespace satviz
