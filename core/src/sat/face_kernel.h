// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face-separation kernel. The textbook loop (face_query.h) takes a face, finds the
// smallest projection of the other polygon's vertices on its normal, and branches on the separation: a branch per
// face, whose outcome follows the geometry and is mispredicted. The kernel holds a block of faces in lanes, one face
// each (four lanes: two SSE2 registers or one AVX2 register; eight: one AVX-512 register), projects every vertex of
// the other polygon on all of them at once and keeps the smallest projection per lane: the separations of the whole
// block for one branch. It is written once, over the lanes and over the kind of normal (unit normals for Collide
// and the sweep, whose separations are distances; raw edge normals for Overlap, which needs only their signs), and
// with the products, sums and minimum of the textbook loop in its order, so every instantiation gives its bits.
// What a query decides from the separations is its own: the first separating face (Overlap), the largest separation
// (Collide: LargestSeparation below), the entry and exit times (the sweep: sweep_axis.h).
#pragma once

#include "lanes.h"
#include "lanes8.h"

#include <satviz/polygon.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

namespace satviz::detail
{

/// The kind of normal a block of faces holds: unit normals (Normal(i)), or raw edge normals RightPerp(Edge(i)),
/// which need no square root or division and keep the sign of every separation.
enum class NormalKind
{
    Unit,
    Edge,
};

/// The scalar type of lanes L.
template <typename L>
using LaneScalar = std::decay_t<decltype(std::declval<L>().Get(0))>;

/// A block of faces of a polygon of at most 8 faces in lanes L, from face i0: their normals of kind K and the
/// offsets Dot(normal, v_i) of their lines. The polygon is kept inline, and its block (vertices, vertex 0 again,
/// then unit normals) is read whole, without waiting for vertices.data; lanes past the last face read on in that
/// block and hold no face: the caller leaves them out.
template <typename L, NormalKind K>
struct FaceLanes
{
    L nx;     ///< the faces' normals: x
    L ny;     ///< and y
    L offset; ///< Dot(normal, first vertex) per face

    /// The block from face i0 of `polygon` (at most 8 faces).
    template <typename S>
    FaceLanes(const PolygonT<S>& polygon, int i0)
    {
        const Vec2T<S>* block = polygon.InlineBlock();
        L vx;
        L vy;
        L::LoadPoints(&block[i0].x, vx, vy);
        if constexpr (K == NormalKind::Unit)
        {
            L::LoadPoints(&block[polygon.Count() + 1 + i0].x, nx, ny);
        }
        else
        {
            L wx;
            L wy;
            L::LoadPoints(&block[i0 + 1].x, wx, wy);
            nx = wy - vy;
            ny = vx - wx;
        }
        offset = nx * vx + ny * vy;
    }
};

/// Four faces of any polygon from face i0, the last face repeated past the end, as lanes: their unit normals
/// (nx, ny) and first vertices (vx, vy). A full block loads its normals and vertices whole. For polygons above 8
/// faces, whose block may end before the lanes do.
template <typename L, typename S>
struct FaceBlock
{
    L nx, ny; ///< the faces' unit normals
    L vx, vy; ///< their first vertices

    /// The face in lane l of the block from face i0, of a polygon of n faces.
    static int Face(int n, int i0, int l) { return std::min(i0 + l, n - 1); }

    /// The block from face i0 of `polygon`, whose vertices and normals are at `data` (vertices.data, or the
    /// InlineBlock of a polygon kept inline, which is read without waiting for the pointer).
    FaceBlock(const PolygonT<S>& polygon, const Vec2T<S>* data, int i0)
    {
        const int n = polygon.Count();
        const Vec2T<S>* normals = data + n + 1;
        const Vec2T<S>* v = data;
        if (i0 + 4 <= n)
        {
            L::LoadPoints(&normals[i0].x, nx, ny);
            L::LoadPoints(&v[i0].x, vx, vy);
            return;
        }
        const int f0 = Face(n, i0, 0);
        const int f1 = Face(n, i0, 1);
        const int f2 = Face(n, i0, 2);
        const int f3 = Face(n, i0, 3);
        nx = L::Set(normals[f0].x, normals[f1].x, normals[f2].x, normals[f3].x);
        ny = L::Set(normals[f0].y, normals[f1].y, normals[f2].y, normals[f3].y);
        vx = L::Set(v[f0].x, v[f1].x, v[f2].x, v[f3].x);
        vy = L::Set(v[f0].y, v[f1].y, v[f2].y, v[f3].y);
    }

    /// Dot(normal, first vertex) per face: the offset of each face's line.
    L Offset() const { return nx * vx + ny * vy; }
};

/// The other polygon's vertices as the kernel reads them, vertex j's x (X<j>) and y (Y<j>) in every lane, from the
/// arrays of a scanned incident polygon (IncidentPolygon::x, y): one broadcast load each.
template <typename L, typename S>
struct VerticesInMemory
{
    const S* x; ///< the vertices' x
    const S* y; ///< and y

    /// Vertex j's x in every lane.
    template <int j>
    L X() const
    {
        return L::Fill(x[j]);
    }
    /// Vertex j's y in every lane.
    template <int j>
    L Y() const
    {
        return L::Fill(y[j]);
    }
};

/// The vertices of a scanned incident polygon as VerticesInMemory, but read four at a time and spread across the
/// lanes from registers (VerticesInRegisters4; four lanes only), which is faster than a broadcast load per vertex
/// where a block of faces is taken alone (LowestProjections below).
template <typename L, typename S>
struct VerticesInFours
{
    const S* x; ///< the vertices' x, 16- or 32-byte aligned
    const S* y; ///< and y
};

/// Four vertices held in the lanes of two registers of four, one vertex per lane: vertex j spread from lane j % 4.
template <typename L>
struct VerticesInRegisters4
{
    L x; ///< the vertices' x
    L y; ///< and y

    /// Vertex j's x in every lane.
    template <int j>
    L X() const
    {
        return x.template Spread<(j & 3)>();
    }
    /// Vertex j's y in every lane.
    template <int j>
    L Y() const
    {
        return y.template Spread<(j & 3)>();
    }
};

#if SATVIZ_LANES8
/// The other polygon's vertices held in the lanes of two registers, one vertex per lane (MapVertices512): vertex
/// j spread from lane j.
struct VerticesInRegisters8
{
    Lanes8 x; ///< the vertices' x
    Lanes8 y; ///< and y

    /// Vertex j's x in every lane.
    template <int j>
    [[gnu::target("avx512f")]] Lanes8 X() const
    {
        return x.Spread(j);
    }
    /// Vertex j's y in every lane.
    template <int j>
    [[gnu::target("avx512f")]] Lanes8 Y() const
    {
        return y.Spread(j);
    }
};
#endif

/// Takes vertex j into the smallest projections of one or two blocks of normals (kBlocks): the projection of the
/// vertex on each lane's normal, the first of them, then the smaller of it and the smallest so far.
template <int j, int kBlocks, typename L, typename Vertices>
void TakeVertex(const Vertices& w, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0, L& low1)
{
    const L x = w.template X<j>();
    const L y = w.template Y<j>();
    const L projection0 = nx0 * x + ny0 * y;
    low0 = j == 0 ? projection0 : Min(low0, projection0);
    if constexpr (kBlocks == 2)
    {
        const L projection1 = nx1 * x + ny1 * y;
        low1 = j == 0 ? projection1 : Min(low1, projection1);
    }
}

/// TakeVertex for the vertices j..., in order.
template <int kBlocks, typename L, typename Vertices, int... j>
void TakeVertices(const Vertices& w, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0, L& low1,
                  std::integer_sequence<int, j...>)
{
    (TakeVertex<j, kBlocks>(w, nx0, ny0, nx1, ny1, low0, low1), ...);
}

/// The kernel: per lane, the smallest projection min_j (nx x_j + ny y_j) of the vertices j = 0 .. N - 1 of w on
/// the lane's normal, for one block of normals or two (kBlocks; each vertex read once for both). The vertices are
/// taken in order, unrolled at compile time. The same products, sums and minimum as the textbook loop.
template <int N, int kBlocks, typename L, typename Vertices>
void LowestProjections(const Vertices& w, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0, L& low1)
{
    static_assert(N > 0 && (kBlocks == 1 || kBlocks == 2), "at least one vertex, one or two blocks");
    TakeVertices<kBlocks>(w, nx0, ny0, nx1, ny1, low0, low1, std::make_integer_sequence<int, N>{});
}

/// LowestProjections from vertices loaded four at a time (VerticesInFours): each group of four loaded once, as
/// registers, and its vertices spread from them in order.
template <int N, int kBlocks, typename L, typename S>
void LowestProjections(const VerticesInFours<L, S>& w, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0,
                       L& low1)
{
    static_assert(N > 0 && N % 4 == 0 && (kBlocks == 1 || kBlocks == 2), "whole groups, one or two blocks");
    for (int j = 0; j < N; j += 4)
    {
        const VerticesInRegisters4<L> group{L::Load(w.x + j), L::Load(w.y + j)};
        if (j == 0)
        {
            TakeVertex<0, kBlocks>(group, nx0, ny0, nx1, ny1, low0, low1);
        }
        else
        {
            TakeVertex<4, kBlocks>(group, nx0, ny0, nx1, ny1, low0, low1);
        }
        TakeVertex<5, kBlocks>(group, nx0, ny0, nx1, ny1, low0, low1);
        TakeVertex<6, kBlocks>(group, nx0, ny0, nx1, ny1, low0, low1);
        TakeVertex<7, kBlocks>(group, nx0, ny0, nx1, ny1, low0, low1);
    }
}

/// The separations of a block of faces (normals nx, ny; offsets `offset`) from N vertices: the smallest projection
/// less the offset (LowestProjections). Rounding is monotonic, so subtracting before or after the minimum gives the
/// same number; adding +0 makes a zero separation +0 whichever zero the minimum kept, so every width agrees.
template <int N, typename L, typename Vertices>
L Separations(const Vertices& w, const L& nx, const L& ny, const L& offset)
{
    L low = nx;
    LowestProjections<N, 1>(w, nx, ny, nx, ny, low, low);
    return (low - offset) + L::Fill(LaneScalar<L>(0));
}

/// The separations of every face of a polygon of at most 8 faces (kind K) from N vertices of the other polygon,
/// all from one pass over the vertices: one register of eight lanes, or two blocks of four (the second only for a
/// polygon of more than four faces: kBlocks = 2; else it repeats the first). Lanes past the last face hold no face.
template <typename L, int kBlocks = (L::kCount == 8 ? 1 : 2)>
struct SmallSeparations
{
    static_assert(L::kCount * kBlocks <= 8 || kBlocks == 1, "at most 8 faces");
    using S = LaneScalar<L>;
    L block0; ///< faces 0 to kCount - 1
    L block1; ///< faces 4 to 7 (two blocks of four; else block0 again)

    /// The separations of the faces of `ref` (at most 8, kind K) from the N vertices `w`.
    template <NormalKind K, int N, typename Vertices>
    static SmallSeparations Of(const PolygonT<S>& ref, const Vertices& w)
    {
        SmallSeparations out;
        const FaceLanes<L, K> faces0(ref, 0);
        if constexpr (kBlocks == 2)
        {
            const FaceLanes<L, K> faces1(ref, 4);
            L low0 = faces0.nx;
            L low1 = faces1.nx;
            LowestProjections<N, 2>(w, faces0.nx, faces0.ny, faces1.nx, faces1.ny, low0, low1);
            out.block0 = (low0 - faces0.offset) + L::Fill(S(0));
            out.block1 = (low1 - faces1.offset) + L::Fill(S(0));
        }
        else
        {
            out.block0 = Separations<N>(w, faces0.nx, faces0.ny, faces0.offset);
            out.block1 = out.block0;
        }
        return out;
    }

    /// The separation of face i.
    S Get(int i) const
    {
        if constexpr (L::kCount == 8)
        {
            return block0.Get(i);
        }
        else
        {
            return i < 4 ? block0.Get(i) : block1.Get(i - 4);
        }
    }

    /// The faces whose separation is > 0, one bit each (bits past the last face hold no face).
    int Positive() const
    {
        if constexpr (L::kCount == 8)
        {
            return block0.GreaterBits(L::Fill(S(0)));
        }
        else
        {
            return (block0 > L::Fill(S(0))).Bits() | (block1 > L::Fill(S(0))).Bits() << 4;
        }
    }

    /// The faces whose bit is set in `hidden` (skipped ones, and lanes past the last face) set to -infinity, so that
    /// they take no part. With four lanes, a block whose faces all take part is left as it is, without a select.
    void Hide(int hidden)
    {
        constexpr S kBelow = -std::numeric_limits<S>::infinity();
        if constexpr (L::kCount == 8)
        {
            block0 = block0.Replace(hidden & 0xFF, kBelow);
        }
        else if ((hidden &= (1 << (4 * kBlocks)) - 1) != 0)
        {
            const auto mask = [](int bits) {
                return L::Set(S(bits & 1), S(bits & 2), S(bits & 4), S(bits & 8)) > L::Fill(S(0));
            };
            const L below = L::Fill(kBelow);
            block0 = Select(mask(hidden), below, block0);
            block1 = kBlocks == 2 ? Select(mask(hidden >> 4), below, block1) : block0;
        }
    }

    /// The largest separation over the first n faces (hidden ones at -infinity), NaN ignored (no comparison holds
    /// for it), and in `face` its first face (none above -infinity: face 0).
    S Largest(int n, int& face) const
    {
        constexpr S kBelow = -std::numeric_limits<S>::infinity();
        S largest;
        int hits;
        if constexpr (L::kCount == 8)
        {
            const int numbers = block0.GreaterBits(L::Fill(kBelow));
            largest = block0.Replace(~numbers & 0xFF, kBelow).MaxLane();
            hits = block0.EqualBits(L::Fill(largest));
        }
        else
        {
            const L low = L::Fill(kBelow);
            const L best0 = Select(block0 > low, block0, low);
            const L best = Select(block1 > best0, block1, best0);
            largest = best.MaxLane();
            hits = (block0 == L::Fill(largest)).Bits() | (block1 == L::Fill(largest)).Bits() << 4;
        }
        // No face has a separation above -infinity (NaN input): face 0, as the textbook loop, whose best face
        // changes only for a larger separation.
        hits &= largest > kBelow ? (1 << n) - 1 : 0;
        face = hits != 0 ? __builtin_ctz(static_cast<unsigned>(hits)) : 0;
        return largest;
    }
};

/// The faces of a polygon of n faces (at most 8) that take part, one bit each: the real ones, less the `skip`ped.
inline int LiveFaces(int n, uint64_t skip)
{
    return static_cast<int>(((uint64_t(1) << n) - 1) & ~skip);
}

} // namespace satviz::detail
