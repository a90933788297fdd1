// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face loops of small polygons four faces at a time, in lanes. The textbook loop
// (face_query.h) takes a face, scans the incident polygon's vertices, and branches on the separation: a branch per
// face, whose outcome follows the geometry and is mispredicted. Here each vertex is projected on four normals at
// once, the minimum is kept per lane, and a block of four faces (or all faces of a polygon of up to 8) costs one
// branch: the face-separation kernel (face_kernel.h), with the products, sums and minimum of the face-at-a-time scan
// (TextbookFaceQuery), so the same bits; the recorder takes the faces from the lanes the loop decided from, up to the
// face where it stopped (RecordLanes). Collide's face query (unit normals), the sweep's separations, and Overlap's test
// of polygons of up to 8 vertices (raw edge normals) use them.
#pragma once

#include "face_kernel.h"
#include "face_query.h"
#include "incident_polygon.h"
#include "lanes.h"
#include "select.h"

#include <satviz/polygon.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace satviz::detail
{

/// Four faces of `polygon` from face i0, the last face repeated past the end, as lanes: their unit normals
/// (nx, ny) and first vertices (vx, vy). A full block loads its normals and vertices whole.
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

/// The separations of the faces of a small ref (kBlocks blocks of four, 1 or 2: at most 8 faces) from a scanned inc
/// of N padded vertices, per block in lanes, in one pass over inc's vertices: each vertex is loaded once, as lanes,
/// for both blocks, whose normals stay in registers. The same products, sums and minimum as TextbookFaceQuery, so the
/// same bits. (Named members: arrays of lanes end up on the stack.)
template <int N, int kBlocks, typename L, typename S>
struct SmallRefSeparations
{
    static_assert(kBlocks == 1 || kBlocks == 2, "one or two blocks");
    FaceBlock<L, S> faces0; ///< faces 0 to 3
    FaceBlock<L, S> faces1; ///< faces 4 to 7 (kBlocks = 2; else faces 0 to 3 again)
    L block0;               ///< the separations of faces 0 to 3
    L block1;               ///< of faces 4 to 7 (kBlocks = 2; else those of faces 0 to 3)

    SmallRefSeparations(const PolygonT<S>& ref, const IncidentPolygon<S>& inc)
        : faces0(ref, ref.InlineBlock(), 0), faces1(kBlocks == 2 ? FaceBlock<L, S>(ref, ref.InlineBlock(), 4) : faces0)
    {
        L low0 = L::Fill(S(0));
        L low1 = L::Fill(S(0));
        LowestProjections<N, kBlocks, BroadcastVertices<L, S>>(inc, faces0.nx, faces0.ny, faces1.nx, faces1.ny, low0,
                                                               low1);
        block0 = SeparationsOf(low0, faces0.Offset());
        block1 = kBlocks == 2 ? SeparationsOf(low1, faces1.Offset()) : block0;
    }
};

/// The separations of a small ref's faces in blocks (SmallRefSeparations) with the faces that take no part set to
/// -infinity: the `skip`ped ones (bits), and the lanes past the last of its n faces, which read the polygon's block
/// beyond its vertices and normals. With one block, block1 repeats block0.
template <int kBlocks, typename L>
void HideFaces(uint64_t skip, int n, L& block0, L& block1)
{
    using S = std::decay_t<decltype(std::declval<L>().Get(0))>;
    const uint64_t hidden = (skip | ~((uint64_t(1) << n) - 1)) & (kBlocks == 2 ? 0xFF : 0xF);
    if (hidden != 0)
    {
        const auto mask = [](uint64_t bits) {
            return L::Set(S(bits & 1), S(bits & 2), S(bits & 4), S(bits & 8)) > L::Fill(S(0));
        };
        const L below = L::Fill(-std::numeric_limits<S>::infinity());
        block0 = Select(mask(hidden), below, block0);
        block1 = kBlocks == 2 ? Select(mask(hidden >> 4), below, block1) : block0;
    }
}

/// For the trace: the first `shown` faces of a small ref (at most 8) as its face loop holds them, in one or two blocks
/// of lanes (normals nx0, ny0 and separations block0: faces 0 to 3; nx1, ny1, block1: faces 4 to 7), the `skip`ped
/// ones (bits) as skipped. The loop calls it where it decides, with the face it stopped at: the trace is the lanes'
/// numbers, not a second computation.
template <typename Tracer, typename L, typename S>
void RecordLanes(Tracer& tracer, const IncidentPolygon<S>& inc, int side, int shown, uint64_t skip, const L& nx0,
                 const L& ny0, const L& block0, const L& nx1, const L& ny1, const L& block1)
{
    tracer.FaceLanes(side, 0, std::min(shown, 4), nx0, ny0, block0, skip, inc);
    if (shown > 4)
    {
        tracer.FaceLanes(side, 4, shown - 4, nx1, ny1, block1, skip >> 4, inc);
    }
}

/// The face query of Collide (unit normals) for a ref of at most 8 faces against a scanned inc of N padded vertices,
/// with the answer of the textbook loop (TextbookFaceQuery): the separations of all of ref's faces from one pass over
/// inc's vertices, as SmallRefSeparations takes them (the same bits), then one branch for all of them. A separating
/// face ends the query at the first such face (without the early exit, the query reports the largest separation, as
/// when no face separates); otherwise the largest separation is one reduction across the lanes and its first face the
/// first lane equal to it, read from the comparison's bits. ref's normals and vertices are loaded four at a time,
/// whole: a polygon of at most 8 vertices keeps them inline, so the lanes past its last face read its own block and are
/// masked out. A skipped face (anti-parallel to one already tested) and a NaN separation take no part. The recorder
/// takes the faces from the lanes, in order, up to the face where the query stopped (the first separating one).
/// One branch for both blocks rather than one per block (ScanFaceBlocks): for so few faces the branch costs more
/// than the lanes it would skip.
template <int N, int kBlocks, typename S, typename Tracer>
FaceQuery<S> SmallRefFaceQuery(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second,
                               Tracer& tracer)
{
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    const int n = ref.Count();
    const uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
    // At most 8 faces: the polygon is kept inline, and its block is read without waiting for vertices.data. Faces
    // 0 to 3, then 4 to 7 (kBlocks = 2; else 0 to 3 again): their normals and first vertices.
    const Vec2T<S>* block = ref.InlineBlock();
    L n0x, n0y, v0x, v0y;
    L::LoadPoints(&block[n + 1].x, n0x, n0y);
    L::LoadPoints(&block[0].x, v0x, v0y);
    L n1x = n0x;
    L n1y = n0y;
    L v1x = v0x;
    L v1y = v0y;
    if constexpr (kBlocks == 2)
    {
        L::LoadPoints(&block[n + 5].x, n1x, n1y);
        L::LoadPoints(&block[4].x, v1x, v1y);
    }
    L low0 = L::Fill(S(0));
    L low1 = L::Fill(S(0));
    LowestProjections<N, kBlocks, BroadcastVertices<L, S>>(inc, n0x, n0y, n1x, n1y, low0, low1);
    L block0 = SeparationsOf(low0, n0x * v0x + n0y * v0y);
    L block1 = block0;
    if constexpr (kBlocks == 2)
    {
        block1 = SeparationsOf(low1, n1x * v1x + n1y * v1y);
    }
    HideFaces<kBlocks>(skip, n, block0, block1);
    const L zero = L::Fill(S(0));
    const int separating = ((block0 > zero).Bits() | (block1 > zero).Bits() << 4) & ((1 << n) - 1);
    FaceQuery<S> query;
    query.face = 0;
    int tested = n; // the faces up to the one the query stopped at
    if (separating != 0 && Tracer::kEarlyExit)
    {
        const int i = __builtin_ctz(static_cast<unsigned>(separating));
        query.separated = true;
        query.face = i;
        query.separation = i < 4 ? block0.Get(i) : block1.Get(i - 4);
        tested = i + 1;
    }
    else
    {
        // No face separates, or (without the early exit) every face counts: the largest separation.
        query.separated = separating != 0;
        query.separation = LargestSeparation(n, query.face, block0, block1);
    }
    if constexpr (Tracer::kEnabled)
    {
        RecordLanes(tracer, inc, side, tested, skip, n0x, n0y, block0, n1x, n1y, block1);
    }
    return query;
}

/// The face query of Collide (unit normals) against a scanned inc, four faces of ref at a time in lanes, with the
/// answer of the textbook loop (TextbookFaceQuery). Each vertex of inc is projected on four normals at once, so no
/// minimum is taken across lanes, and a block of four faces costs one branch instead of one per face, whose outcome
/// follows the geometry and would be mispredicted. The last block repeats the last face, which changes no answer: a
/// skipped last face is skipped in every lane that repeats it, else its separation, which may round apart from that of
/// the other polygon's face it repeats, would count. Each lane keeps the largest separation it saw and its first face;
/// the lanes combine into the first face of the largest separation, as a face-by-face loop finds it. A block that holds
/// a separating face ends the query at the first such face. The recorder takes each block's faces from its lanes as
/// the loop decides on the block, in order, up to that face. A ref of at most 8 faces takes SmallRefFaceQuery instead,
/// and Overlap of small polygons SmallFacesSeparate (raw edge normals).
template <int N, typename S, typename Tracer>
FaceQuery<S> ScanFaceBlocks(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second,
                            Tracer& tracer)
{
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    constexpr S kInfinity = std::numeric_limits<S>::infinity();
    const int n = ref.Count();
    uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
    if (n < 64 && ((skip >> (n - 1)) & 1u) != 0)
    {
        // The lanes past the last face repeat it: a skipped last face is skipped in them too.
        skip |= ~uint64_t(0) << n;
    }
    FaceQuery<S> query;
    query.face = 0;
    L best = L::Fill(-kInfinity);
    L bestBlock = L::Fill(S(0));
    // Takes the separations of the four faces from i0; true when the query stops there.
    const auto take = [&](int i0, const L& blockSeparation) {
        L separation = blockSeparation;
        const int skipped = i0 < 64 ? static_cast<int>((skip >> i0) & 0xF) : 0;
        if (skipped != 0)
        {
            // A skipped face (anti-parallel to one already tested) takes no part.
            const typename L::Mask mask =
                L::Set(S(skipped & 1), S(skipped & 2), S(skipped & 4), S(skipped & 8)) > L::Fill(S(0));
            separation = Select(mask, L::Fill(-kInfinity), separation);
        }
        const int separating = (separation > L::Fill(S(0))).Bits();
        const int stop = separating != 0 ? __builtin_ctz(static_cast<unsigned>(separating)) : 4;
        if constexpr (Tracer::kEnabled)
        {
            // The block's faces, up to the one the query stops at, with the normals the loop loaded for them (loaded
            // again here: handing the block in changes how the untraced loop is compiled).
            const FaceBlock<L, S> block(ref, ref.Vertices().data, i0);
            const int tested = std::min(n - i0, Tracer::kEarlyExit ? std::min(stop + 1, 4) : 4);
            tracer.FaceLanes(side, i0, tested, block.nx, block.ny, separation, static_cast<uint64_t>(skipped), inc);
        }
        if (separating != 0 && !query.separated)
        {
            query.separated = true;
            query.face = std::min(i0 + stop, n - 1);
            query.separation = separation.Get(stop);
            if constexpr (Tracer::kEarlyExit)
            {
                return true;
            }
        }
        const typename L::Mask better = separation > best;
        best = Select(better, separation, best);
        bestBlock = Select(better, L::Fill(S(i0)), bestBlock);
        return false;
    };
    for (int i0 = 0; i0 < n; i0 += 4)
    {
        const FaceBlock<L, S> block(ref, ref.Vertices().data, i0);
        if (take(i0, SeparationsOf(LowestProjection<N, SpreadVertices<L, S>>(inc, block.nx, block.ny), block.Offset())))
        {
            return query;
        }
    }
    if (!query.separated || !Tracer::kEarlyExit)
    {
        // The first face of the largest separation (without the early exit, also when a face separates): the
        // smallest face index among the lanes that hold it (none for NaN input: face 0). A lane past the last face
        // repeats it and comes after it.
        const S largest = best.MaxLane();
        const S face =
            Select(best == L::Fill(largest), bestBlock + L::Set(S(0), S(1), S(2), S(3)), L::Fill(S(n))).MinLane();
        query.separation = largest;
        query.face = face < S(n) ? static_cast<int>(face) : 0;
    }
    return query;
}

/// Four faces of `polygon` from face i0 as lanes, with raw edge normals RightPerp(Edge(i)) (no square root, no
/// division: Overlap needs only the sign of a separation) and the offsets Dot(normal, v_i) of their lines. For a
/// polygon of at most 8 vertices, kept inline, whose block is read without waiting for vertices.data. Lanes past
/// the last face read that block beyond vertex 0's copy and hold no face: the caller masks them.
template <typename L, typename S>
struct EdgeNormalBlock
{
    L nx, ny; ///< the faces' raw outward normals
    L offset; ///< Dot(normal, first vertex) per face

    EdgeNormalBlock(const PolygonT<S>& polygon, int i0)
    {
        L vx;
        L vy;
        L wx;
        L wy;
        L::LoadPoints(&polygon.InlineBlock()[i0].x, vx, vy);
        L::LoadPoints(&polygon.InlineBlock()[i0 + 1].x, wx, wy);
        nx = wy - vy;
        ny = vx - wx;
        offset = nx * vx + ny * vy;
    }
};

/// Overlap's face query of a ref of at most 8 faces against a scanned inc of N padded vertices, its faces four at a
/// time in lanes (Gregorius's face query, as SmallRefFaceQuery does for Collide, with raw edge normals): one pass over
/// inc's vertices, each projected on all of ref's normals at once, then one branch for all of ref's faces instead
/// of one per face, whose outcome follows the geometry and is mispredicted. The same products, sums and minimum as
/// TextbookFaceQuery, so the same separations to the bit. A skipped face (second pass: anti-parallel to one of inc's
/// faces, already tested) and the lanes past the last face take no part. The recorder takes the faces from the lanes,
/// in order, up to the face where the test stopped (the first separating one). True when a face separates.
template <int N, int kBlocks, typename S, typename Tracer>
bool SmallFacesSeparate(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, Tracer& tracer)
{
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    const int n = ref.Count();
    const uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
    const EdgeNormalBlock<L, S> faces0(ref, 0);
    const EdgeNormalBlock<L, S> faces1(ref, kBlocks == 2 ? 4 : 0);
    L low0 = L::Fill(S(0));
    L low1 = L::Fill(S(0));
    LowestProjections<N, kBlocks, BroadcastVertices<L, S>>(inc, faces0.nx, faces0.ny, faces1.nx, faces1.ny, low0, low1);
    const L separation0 = SeparationsOf(low0, faces0.offset);
    const L separation1 = kBlocks == 2 ? SeparationsOf(low1, faces1.offset) : separation0;
    // Faces that take part, one bit each: the real ones, less the skipped.
    const int live = static_cast<int>(((uint64_t(1) << n) - 1) & ~skip);
    const int separating = (((separation0 > L::Fill(S(0))).Bits() | (separation1 > L::Fill(S(0))).Bits() << 4) & live);
    if constexpr (Tracer::kEnabled)
    {
        const int tested =
            separating != 0 && Tracer::kEarlyExit ? __builtin_ctz(static_cast<unsigned>(separating)) + 1 : n;
        RecordLanes(tracer, inc, side, tested, skip, faces0.nx, faces0.ny, separation0, faces1.nx, faces1.ny,
                    separation1);
    }
    return separating != 0;
}

/// SmallFacesSeparate for a ref of at most 8 faces and a scanned inc of at most 8 vertices, unrolled for both.
template <typename S, typename Tracer>
bool SmallFacesSeparate(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, Tracer& tracer)
{
    const bool twoBlocks = ref.Count() > 4;
    switch (inc.padded)
    {
    case 4:
        return twoBlocks ? SmallFacesSeparate<4, 2>(ref, inc, side, second, tracer)
                         : SmallFacesSeparate<4, 1>(ref, inc, side, second, tracer);
    case 8:
        return twoBlocks ? SmallFacesSeparate<8, 2>(ref, inc, side, second, tracer)
                         : SmallFacesSeparate<8, 1>(ref, inc, side, second, tracer);
    default:
        return false; // not scanned: the caller calls for none
    }
}

} // namespace satviz::detail
