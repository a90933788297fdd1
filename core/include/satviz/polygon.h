// SPDX-License-Identifier: MIT
// satviz: convex polygons of any vertex count, their validation and construction.
#pragma once

#include <satviz/math.h>

#include <algorithm>
#include <string>
#include <vector>

namespace satviz
{

/// A read-only view of consecutive vectors, indexable and iterable.
template <typename S>
struct Vec2Span
{
    const Vec2T<S>* data = nullptr; ///< first element
    int count = 0;                  ///< number of elements
    /// Element i (0 <= i < count).
    const Vec2T<S>& operator[](int i) const { return data[i]; }
    /// Number of elements.
    size_t size() const { return static_cast<size_t>(count); }
    /// Start of the range.
    const Vec2T<S>* begin() const { return data; }
    /// End of the range.
    const Vec2T<S>* end() const { return data + count; }
};

/// Options for MakePolygon.
struct PolygonOptions
{
    /// Repair what can be repaired without changing the shape: drop repeated vertices and vertices collinear with
    /// their neighbours, and reverse a clockwise outline. A non-convex outline is still an error.
    bool repair = false;
};

/// The outcome of building a polygon (below).
template <typename S>
struct PolygonResultT;

/// Validates a counter-clockwise convex outline and precomputes its edges and normals.
/// Returns an error value (never asserts) for: fewer than 3 vertices, non-finite or too large coordinates,
/// repeated consecutive vertices, collinear vertices, clockwise winding, a right turn (not convex), and outlines
/// that wind around more than once (self-intersecting).
template <typename S>
PolygonResultT<S> MakePolygon(const std::vector<Vec2T<S>>& points, PolygonOptions options = {});

/// A convex polygon in its body frame: counter-clockwise vertices (interior to the left of each edge), y up.
/// Any vertex count from 3 upwards; there is no fixed cap. Edge i runs from vertex i to vertex i + 1 (mod count).
/// Vertices and normals live in one block: inside the polygon itself up to kInlineVertices vertices, so a query on
/// small polygons touches no other memory, and in one heap allocation beyond that. Edges are not stored: Edge(i)
/// subtracts two vertices, which costs less than the memory an edge array would take from every query.
/// Build polygons with MakePolygon, ComputeHull, MakeBox or MakeRegularPolygon, which validate the outline and
/// precompute the normals consistently; a default-constructed polygon is empty.
template <typename S>
class PolygonT
{
  public:
    /// Polygons with at most this many vertices keep their data inline.
    static constexpr int kInlineVertices = 8;

    /// An empty polygon.
    PolygonT() = default;
    /// A copy with its own storage.
    PolygonT(const PolygonT& other) { CopyFrom(other); }
    /// Takes over the other polygon's storage.
    PolygonT(PolygonT&& other) noexcept { MoveFrom(other); }
    /// Copies another polygon.
    PolygonT& operator=(const PolygonT& other)
    {
        if (this != &other)
        {
            CopyFrom(other);
        }
        return *this;
    }
    /// Takes over the other polygon's storage.
    PolygonT& operator=(PolygonT&& other) noexcept
    {
        if (this != &other)
        {
            MoveFrom(other);
        }
        return *this;
    }

    /// Number of vertices.
    int Count() const { return m_count; }

    /// The vertices in the body frame, counter-clockwise, strictly convex. The view stays valid while the polygon
    /// lives unmoved; the polygon owns the data and only its builders write it, so its invariants (convexity, unit
    /// normals matching the edges) hold for as long as it exists.
    Vec2Span<S> Vertices() const { return m_vertices; }

    /// The area centroid, body frame.
    Vec2T<S> Centroid() const { return m_centroid; }

    /// The block of vertices (vertex 0 again after the last) and normals of a polygon kept inline (Count() at most
    /// kInlineVertices): the same data as Vertices().data, at an address known without reading that pointer, so that
    /// a query's loads from it need not wait for another load.
    const Vec2T<S>* InlineBlock() const { return m_inline; }
    /// Unit outward normal of edge i (0 <= i < Count()): RightPerp(Edge(i)) / |Edge(i)|.
    const Vec2T<S>& Normal(int i) const { return m_vertices.data[m_count + 1 + i]; }

    /// The unit outward normals of all edges, in edge order.
    Vec2Span<S> Normals() const { return {m_vertices.data + m_count + 1, m_count}; }

    /// Edge i (0 <= i < Count()): vertices[i + 1] - vertices[i], where vertex Count() is vertex 0. The block keeps
    /// a copy of vertex 0 after the last vertex, so no index wraps.
    Vec2T<S> Edge(int i) const { return m_vertices.data[i + 1] - m_vertices.data[i]; }

  private:
    template <typename T>
    friend PolygonResultT<T> MakePolygon(const std::vector<Vec2T<T>>& points, PolygonOptions options);

    // Takes validated data: `storage` holds the count vertices, vertex 0 again, then the count normals
    // (2 * count + 1 vectors). Only MakePolygon, which validates them, builds a polygon from data.
    static PolygonT FromStorage(std::vector<Vec2T<S>> storage, Vec2T<S> centroid)
    {
        PolygonT polygon;
        polygon.m_count = static_cast<int>(storage.size() / 2);
        polygon.m_centroid = centroid;
        if (polygon.m_count <= kInlineVertices)
        {
            std::copy(storage.begin(), storage.end(), polygon.m_inline);
        }
        else
        {
            polygon.m_heap = std::move(storage);
        }
        polygon.Bind();
        return polygon;
    }

    void CopyFrom(const PolygonT& other)
    {
        m_count = other.m_count;
        m_centroid = other.m_centroid;
        std::copy(other.m_inline, other.m_inline + kInlineStorage, m_inline);
        m_heap = other.m_heap;
        Bind();
    }

    void MoveFrom(PolygonT& other)
    {
        m_count = other.m_count;
        m_centroid = other.m_centroid;
        std::copy(other.m_inline, other.m_inline + kInlineStorage, m_inline);
        m_heap = std::move(other.m_heap);
        Bind();
        other.m_count = other.m_count <= kInlineVertices ? other.m_count : 0;
        other.Bind();
    }

    void Bind()
    {
        const int n = m_count;
        const Vec2T<S>* base = n <= kInlineVertices ? m_inline : m_heap.data();
        m_vertices = {base, n};
    }

    static constexpr int kInlineStorage = 2 * kInlineVertices + 1;
    Vec2Span<S> m_vertices;
    Vec2T<S> m_centroid{};
    int m_count = 0;
    Vec2T<S> m_inline[kInlineStorage]{};
    std::vector<Vec2T<S>> m_heap;
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
    PolygonT<S> polygon;                     ///< the polygon; empty when error != None
    PolygonError error = PolygonError::None; ///< what is wrong, if anything
    int vertex = -1;                         ///< input index of the offending vertex, or -1
    /// True when the polygon was built.
    bool Ok() const { return error == PolygonError::None; }
};

/// Double-precision polygon result.
using PolygonResult = PolygonResultT<double>;

/// The convex hull of a point cloud (Andrew's monotone chain, O(n log n)), counter-clockwise, without collinear
/// or repeated points. Errors: NotFinite, TooLarge, or TooFewVertices when the points span no area.
template <typename S>
PolygonResultT<S> ComputeHull(const std::vector<Vec2T<S>>& points);

/// An axis-aligned box centred on the body origin, from half its width and half its height (both > 0): the box
/// spans [-halfWidth, halfWidth] x [-halfHeight, halfHeight]. A scene file's "box" gives the full width and height.
template <typename S>
PolygonResultT<S> MakeBox(S halfWidth, S halfHeight);

/// A regular polygon with `sides` vertices on a circle of `radius` around the body origin, the first vertex at
/// angle `phase` (radians).
template <typename S>
PolygonResultT<S> MakeRegularPolygon(int sides, S radius, S phase = S(0));

/// The same polygon in another scalar type, validated again in that type.
template <typename T, typename S>
PolygonResultT<T> ConvertPolygon(const PolygonT<S>& polygon)
{
    std::vector<Vec2T<T>> points;
    points.reserve(polygon.Vertices().size());
    for (const Vec2T<S>& v : polygon.Vertices())
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
