// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face-separation kernel. The textbook loop (face_query.h) takes a face, finds the
// smallest projection of the other polygon's vertices on its normal, and branches on the separation. The kernel holds
// a block of faces in lanes, one face each (four lanes: two SSE2 registers or one AVX2 register; eight: one AVX-512
// register), projects each vertex of the other polygon on all of them at once and keeps the smallest projection per
// lane, with the products, sums and minimum of the textbook loop in its order: every instantiation gives its bits.
// It is written once, over the lanes and over where the vertices come from (read one at a time from the arrays of a
// scanned incident polygon, read four at a time and spread across the lanes from registers, or held in registers
// already). The same kernel turned on its side serves a loop that takes one face at a time: the face's normal in every
// lane and the other polygon's vertices spread over the lanes, a group of them each time (ColumnVertices), their
// smallest projection the smallest lane. What a loop decides from the separations is its own: the first separating
// face (Overlap), the largest separation (Collide), the entry and exit times (the sweep).
#pragma once

#include "lanes.h"
#include "lanes8.h"

#include <satviz/polygon.h>

#include <limits>
#include <type_traits>
#include <utility>

namespace satviz::detail
{

/// Maps a polygon's vertices by a transform into arrays x and y four at a time, in lanes (kWide: with the wide
/// vectors, whose stores the wide scans then read whole), with the operations of TransformPoint, so the same bits as
/// MapOneByOne (incident_polygon.h). The last block may read up to three points past the vertices: a polygon's
/// block holds vertex 0 again and the normals there.
template <bool kWide>
struct MapInLanes
{
    /// Writes the vertices of `p` mapped by `xf` to x[0 .. count) and y[0 .. count), and up to 3 entries beyond.
    template <typename S>
    void operator()(const PolygonT<S>& p, const TransformT<S>& xf, S* x, S* y) const
    {
        using L = Lanes<S, kWide && std::is_same_v<S, double>>;
        const int count = p.Count();
        const L c = L::Fill(xf.q.c);
        const L s = L::Fill(xf.q.s);
        const L px = L::Fill(xf.p.x);
        const L py = L::Fill(xf.p.y);
        const Vec2T<S>* vertices = count <= PolygonT<S>::kInlineVertices ? p.InlineBlock() : p.Vertices().data;
        for (int j = 0; j < count; j += 4)
        {
            L vx;
            L vy;
            L::LoadPoints(&vertices[j].x, vx, vy);
            ((c * vx - s * vy) + px).Store(x + j);
            ((s * vx + c * vy) + py).Store(y + j);
        }
    }
};

/// Vertex j0 of a scanned inc, its x (X<0>) and y (Y<0>) in every lane of L, read from inc's arrays by itself (a
/// broadcast load): the form for two blocks of faces taken together, whose normals fill the registers.
template <typename L, typename S>
struct BroadcastVertices
{
    static constexpr int kCount = 1;       ///< vertices per group
    static constexpr int kTakes = 1;       ///< projections per lane per group
    static constexpr bool kColumn = false; ///< a vertex per lane (ColumnVertices)
    const S* x;                            ///< vertex j0's x
    const S* y;                            ///< and y

    /// Vertex j0 of `inc` (an IncidentPolygon: its arrays x and y).
    template <typename Inc>
    BroadcastVertices(const Inc& inc, int j0) : x(inc.x + j0), y(inc.y + j0)
    {
    }
    /// Vertex j0 + k's x in every lane.
    template <int k>
    L X() const
    {
        return L::Fill(x[k]);
    }
    /// Vertex j0 + k's y in every lane.
    template <int k>
    L Y() const
    {
        return L::Fill(y[k]);
    }
};

/// Four vertices of a scanned inc from vertex j0, read together into one group of four lanes and spread across the
/// lanes from registers, which is faster than a broadcast load per vertex where one block of faces is taken alone.
template <typename L, typename S>
struct SpreadVertices
{
    static constexpr int kCount = 4;       ///< vertices per group
    static constexpr int kTakes = 4;       ///< projections per lane per group: each vertex in turn
    static constexpr bool kColumn = false; ///< a vertex per lane (ColumnVertices)
    L xs;                                  ///< the four vertices' x, one per lane
    L ys;                                  ///< and y

    /// The four vertices of `inc` (an IncidentPolygon) from vertex j0 (j0 a multiple of 4: inc's arrays are
    /// aligned for whole lanes).
    template <typename Inc>
    SpreadVertices(const Inc& inc, int j0) : xs(L::Load(inc.x + j0)), ys(L::Load(inc.y + j0))
    {
    }
    /// Vertex j0 + k's x in every lane.
    template <int k>
    L X() const
    {
        return xs.template Spread<k>();
    }
    /// Vertex j0 + k's y in every lane.
    template <int k>
    L Y() const
    {
        return ys.template Spread<k>();
    }
};

/// Where the vertices of a one-face scan come from: the x and y arrays of a scanned incident polygon, padded to
/// whole groups, and, when `inside` is not null, the per-vertex largest separation that the scan keeps (kInside).
template <typename S>
struct ScannedVertices
{
    const S* x; ///< the vertices' x
    const S* y; ///< and y
    S offset;   ///< the face's offset Dot(normal, v_i), for `inside`
    S* inside;  ///< kInside: each vertex's largest separation so far
};

/// A group of L::kCount vertices of a one-face scan from vertex j0, one per lane (j0 a multiple of L::kCount), the
/// face's normal in every lane: each lane keeps the smallest projection of its own vertices, and the face's is the
/// smallest lane. With kInside it also keeps, per vertex, the largest separation over the faces scanned so far:
/// inside[j] = max(inside[j], projection - offset); a vertex whose largest separation is <= 0 lies inside.
template <typename L, bool kInside, typename S>
struct ColumnVertices
{
    static constexpr int kCount = L::kCount; ///< vertices per group
    static constexpr int kTakes = 1;         ///< projections per lane per group
    static constexpr bool kColumn = true;    ///< a vertex per lane
    const S* x;                              ///< the group's x
    const S* y;                              ///< and y
    S offset;                                ///< the face's offset (kInside), held here: `inside` may not alias it
    S* inside;                               ///< the group's largest separations (kInside)

    /// The group from vertex j.
    ColumnVertices(const ScannedVertices<S>& v, int j)
        : x(v.x + j), y(v.y + j), offset(v.offset), inside(kInside ? v.inside + j : nullptr)
    {
    }
    /// The group's x, one vertex per lane.
    template <int k>
    L X() const
    {
        return L::Load(x);
    }
    /// The group's y.
    template <int k>
    L Y() const
    {
        return L::Load(y);
    }
    /// Keeps each vertex's largest separation (kInside) from its projection on the face's normal.
    template <int k>
    void Took(const L& projection) const
    {
        if constexpr (kInside)
        {
            Max(L::Load(inside), projection - L::Fill(offset)).Store(inside);
        }
    }
};

/// Takes vertex k of group w into the smallest projections of one or two blocks of normals (kBlocks): its
/// projection on each lane's normal, nx x + ny y, the first (`first`) or the smaller of it and the smallest so far
/// (Min keeps the second operand when either is NaN, as the textbook loop's comparison does).
template <int k, int kBlocks, typename Group, typename L>
void TakeVertex(const Group& w, bool first, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0, L& low1)
{
    const L x = w.template X<k>();
    const L y = w.template Y<k>();
    const L projection0 = nx0 * x + ny0 * y;
    if constexpr (Group::kColumn)
    {
        w.template Took<k>(projection0);
    }
    low0 = first ? projection0 : Min(low0, projection0);
    if constexpr (kBlocks == 2)
    {
        const L projection1 = nx1 * x + ny1 * y;
        low1 = first ? projection1 : Min(low1, projection1);
    }
}

/// The kernel: per lane, the smallest projection min_j (nx x_j + ny y_j) of the N vertices of `vertices` (N a
/// multiple of 4) on the lane's normal, for one block of normals (nx0, ny0) or two (kBlocks = 2: each vertex read
/// once for both). The vertices are taken in order, in groups (Group: how they are read, and how many at a time);
/// a group of a column (ColumnVertices) holds one vertex per lane, so that each lane sees its own vertices.
template <int N, int kBlocks, typename Group, typename Vertices, typename L>
void LowestProjections(const Vertices& vertices, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0,
                       L& low1)
{
    static_assert(N > 0 && N % 4 == 0 && (kBlocks == 1 || kBlocks == 2), "whole groups, one or two blocks");
    static_assert(N % Group::kCount == 0 && (Group::kTakes == 1 || Group::kTakes == 4), "whole groups");
    for (int j0 = 0; j0 < N; j0 += Group::kCount)
    {
        const Group w(vertices, j0);
        TakeVertex<0, kBlocks>(w, j0 == 0, nx0, ny0, nx1, ny1, low0, low1);
        if constexpr (Group::kTakes == 4)
        {
            TakeVertex<1, kBlocks>(w, false, nx0, ny0, nx1, ny1, low0, low1);
            TakeVertex<2, kBlocks>(w, false, nx0, ny0, nx1, ny1, low0, low1);
            TakeVertex<3, kBlocks>(w, false, nx0, ny0, nx1, ny1, low0, low1);
        }
    }
}

/// The kernel for one block of normals: per lane, the smallest projection of the N vertices on its normal.
template <int N, typename Group, typename Vertices, typename L>
L LowestProjection(const Vertices& vertices, const L& nx, const L& ny)
{
    L low = nx; // every lane replaced by the first vertex's projection
    LowestProjections<N, 1, Group>(vertices, nx, ny, nx, ny, low, low);
    return low;
}

/// The separations of a block of faces from the smallest projections `low` and the faces' offsets Dot(normal, v_i):
/// low - offset. Rounding is monotonic, so subtracting before or after the minimum gives the same number; adding +0
/// makes a zero separation +0 whichever zero the minimum kept, so every loop and width gives the same bits.
template <typename L>
L SeparationsOf(const L& low, const L& offset)
{
    return (low - offset) + L::Fill(0);
}

/// The largest separation over the n faces of a small polygon whose separations are held in lanes, one face a lane
/// (block0: faces 0 on, and the `more` blocks the faces after them, L::kCount a block), NaN ignored (no comparison
/// holds for it), and in `face` its first face (none for NaN input: face 0). Written once over the lane width: four
/// lanes in two blocks (face_blocks.h), eight in one (collide512.h).
template <typename L, typename... More>
auto LargestSeparation(int n, int& face, const L& block0, const More&... more)
{
    using S = std::decay_t<decltype(std::declval<L>().Get(0))>;
    const L low = L::Fill(-std::numeric_limits<S>::infinity());
    L best = Select(block0 > low, block0, low);
    ((best = Select(more > best, more, best)), ...);
    const S largest = best.MaxLane();
    const L top = L::Fill(largest);
    int hits = (block0 == top).Bits();
    [[maybe_unused]] int shift = 0;
    ((hits |= (more == top).Bits() << (shift += L::kCount)), ...);
    hits &= (1 << n) - 1;
    face = hits != 0 ? __builtin_ctz(static_cast<unsigned>(hits)) : 0;
    return largest;
}

#if SATVIZ_LANES8
/// The other polygon's vertices held in registers, one per lane of Lanes8 (MapVertices512, overlap512.h).
struct RegisterVertices8
{
    const Lanes8& x; ///< the vertices' x
    const Lanes8& y; ///< and y
};

/// Vertex j0 of them, spread across the lanes from those registers.
struct SpreadVertices8
{
    static constexpr int kCount = 1;       ///< vertices per group
    static constexpr int kTakes = 1;       ///< projections per lane per group
    static constexpr bool kColumn = false; ///< a vertex per lane (ColumnVertices)
    const Lanes8& xs;                      ///< the vertices' x
    const Lanes8& ys;                      ///< and y
    int j0;                                ///< the vertex

    /// Vertex j0.
    SpreadVertices8(const RegisterVertices8& v, int j) : xs(v.x), ys(v.y), j0(j) {}
    /// Vertex j0 + k's x in every lane.
    template <int k>
    [[gnu::target("avx512f")]] Lanes8 X() const
    {
        return xs.Spread(j0 + k);
    }
    /// Vertex j0 + k's y in every lane.
    template <int k>
    [[gnu::target("avx512f")]] Lanes8 Y() const
    {
        return ys.Spread(j0 + k);
    }
};
#endif

} // namespace satviz::detail
