// SPDX-License-Identifier: MIT
// satviz: convex polygons of any vertex count, their validation and construction.
#pragma once

#include <satviz/math.h>

#include <string>
#include <vector>

namespace satviz
{

/// A convex polygon in its body frame: counter-clockwise vertices (interior to the left of each edge), y up.
/// Any vertex count from 3 upwards; there is no fixed cap. Edge i runs from vertex i to vertex i + 1 (mod count).
/// @warning Do not fill the fields by hand: build polygons with MakePolygon, ComputeHull, MakeBox or
/// MakeRegularPolygon, which validate the outline and precompute the edges and normals consistently.
template <typename S>
struct PolygonT
{
    std::vector<Vec2T<S>> vertices; ///< vertices in the body frame, counter-clockwise, strictly convex
    std::vector<Vec2T<S>> edges;    ///< edges[i] = vertices[i + 1] - vertices[i]
    std::vector<Vec2T<S>> normals;  ///< unit outward normal of edge i: RightPerp(edges[i]) / |edges[i]|
    /// Number of vertices.
    int Count() const { return static_cast<int>(vertices.size()); }
};

/// Double-precision polygon.
using Polygon = PolygonT<double>;

/// Why an outline is not a valid convex polygon.
enum class PolygonError
{
    None,             ///< valid
    TooFewVertices,   ///< fewer than 3 vertices (after repair, if asked)
    NotFinite,        ///< a coordinate is NaN or infinite
    TooLarge,         ///< a coordinate exceeds kMaxCoordinate in magnitude
    DuplicateVertex,  ///< a vertex equals the one before it
    CollinearVertex,  ///< a vertex lies on the line through its neighbours
    Clockwise,        ///< the outline winds clockwise (the convention is counter-clockwise, y up)
    NotConvex,        ///< the outline turns right at a vertex
    SelfIntersecting, ///< every turn is convex but the outline winds around more than once
};

/// Largest accepted coordinate magnitude. Products of two coordinates stay far from overflow, and the relative
/// arithmetic of the collision code keeps full precision for shapes this far from the origin.
constexpr double kMaxCoordinate = 1e12;

/// The outcome of building a polygon: the polygon, or an error and the vertex it concerns.
template <typename S>
struct PolygonResultT
{
    PolygonT<S> polygon;                    ///< the polygon; empty when error != None
    PolygonError error = PolygonError::None; ///< what is wrong, if anything
    int vertex = -1;                        ///< input index of the offending vertex, or -1
    /// True when the polygon was built.
    bool Ok() const { return error == PolygonError::None; }
};

/// Double-precision polygon result.
using PolygonResult = PolygonResultT<double>;

/// Options for MakePolygon.
struct PolygonOptions
{
    /// Repair what can be repaired without changing the shape: drop repeated vertices and vertices collinear with
    /// their neighbours, and reverse a clockwise outline. A non-convex outline is still an error.
    bool repair = false;
};

/// Validates a counter-clockwise convex outline and precomputes its edges and normals.
/// Returns an error value (never asserts) for: fewer than 3 vertices, non-finite or too large coordinates,
/// repeated consecutive vertices, collinear vertices, clockwise winding, a right turn (not convex), and outlines
/// that wind around more than once (self-intersecting).
template <typename S>
PolygonResultT<S> MakePolygon(const std::vector<Vec2T<S>>& points, PolygonOptions options = {});

/// The convex hull of a point cloud (Andrew's monotone chain, O(n log n)), counter-clockwise, without collinear
/// or repeated points. Errors: NotFinite, TooLarge, or TooFewVertices when the points span no area.
template <typename S>
PolygonResultT<S> ComputeHull(const std::vector<Vec2T<S>>& points);

/// An axis-aligned box centred on the body origin with half-widths hx and hy (both > 0).
template <typename S>
PolygonResultT<S> MakeBox(S hx, S hy);

/// A regular polygon with `sides` vertices on a circle of `radius` around the body origin, the first vertex at
/// angle `phase` (radians).
template <typename S>
PolygonResultT<S> MakeRegularPolygon(int sides, S radius, S phase = S(0));

/// The same polygon in another scalar type, validated again in that type.
template <typename T, typename S>
PolygonResultT<T> ConvertPolygon(const PolygonT<S>& polygon)
{
    std::vector<Vec2T<T>> points;
    points.reserve(polygon.vertices.size());
    for (const Vec2T<S>& v : polygon.vertices)
    {
        points.push_back(ConvertVec<T>(v));
    }
    return MakePolygon(points);
}

/// A one-line English description of the error, e.g. "polygon is not convex at vertex 3 (use a convex
/// decomposition)". `vertex` is the index reported with the error.
std::string DescribePolygonError(PolygonError error, int vertex);

/// Twice the signed area of a closed outline (positive for counter-clockwise).
template <typename S>
S SignedArea2(const std::vector<Vec2T<S>>& points);

} // namespace satviz
