// SPDX-License-Identifier: MIT
// satviz: slicing: a convex polygon cut by a line into two convex polygons, a simple polygon cut along a segment.
#pragma once

#include <satviz/polygon.h>

#include <vector>

namespace satviz
{

/// The two sides of a convex polygon cut by a line.
template <typename S>
struct ConvexSliceT
{
    bool cut = false;  ///< the line crosses the polygon's interior, leaving two parts of at least the least area
    PolygonT<S> left;  ///< the part to the left of the directed line (empty when not cut)
    PolygonT<S> right; ///< the part to its right (empty when not cut)
};

/// Double-precision convex slice.
using ConvexSlice = ConvexSliceT<double>;

/// Cuts a convex polygon by the line through `point` along `direction` (the polygon's frame): each vertex goes to
/// the side it lies on, and each edge the line crosses gives both parts the crossing point (Sutherland-Hodgman
/// against each half-plane). A part whose area is below `minArea`, or that the turn test of MakePolygon cannot
/// tell from a sliver (a cut within rounding of a vertex), is no part: then `cut` is false and the polygon is
/// whole. Both parts are convex, and their areas sum to the polygon's.
template <typename S>
ConvexSliceT<S> SliceConvex(const PolygonT<S>& polygon, Vec2T<S> point, Vec2T<S> direction, S minArea = S(0));

/// Cuts a simple polygon (an outline, either orientation, no holes) along the segment from a to b: wherever the
/// segment runs through the interior from one point of the outline to another, the polygon is split there. A
/// segment that stops inside the polygon does not cut that far (a slit is no cut). Returns the parts as
/// counter-clockwise outlines (concave in general: Decompose cuts them into convex pieces); a single part, the
/// outline itself, when nothing is cut. Parts below `minArea` are dropped. The outline must be simple (Decompose
/// checks it); crossings at a vertex and along an edge are taken as crossings at that vertex.
template <typename S>
std::vector<std::vector<Vec2T<S>>> SliceAlongSegment(const std::vector<Vec2T<S>>& outline, Vec2T<S> a, Vec2T<S> b,
                                                     S minArea = S(0));

} // namespace satviz
