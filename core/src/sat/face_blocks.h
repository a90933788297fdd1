// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face loops of small polygons in blocks of faces, in lanes. Each takes the
// separations of a block of four faces (or of all faces of a polygon of up to 8) from the face-separation kernel
// (face_kernel.h), then decides with one branch where the textbook loop (face_query.h) takes one per face: Collide's
// face query (unit normals: the first separating face, else the largest separation), Overlap's test of polygons of
// up to 8 vertices (raw edge normals: whether a face separates), and the separations of the sweep's small polygons.
// The kernel's numbers are the textbook loop's, so the answers are too. These loops record nothing: a traced query
// runs the textbook loop, which records each face as it tests it.
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

/// The separations of the faces of a small ref (kBlocks blocks of four, 1 or 2: at most 8 faces) from a scanned inc
/// of N padded vertices, per block in lanes, in one pass over inc's vertices (the kernel, LowestProjections). The
/// last block repeats the last face, as FaceBlock loads it, so that every lane holds a face: the sweep takes the
/// bounds of all lanes. (Named members: arrays of lanes end up on the stack.)
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
        L low0 = faces0.nx;
        L low1 = faces1.nx;
        LowestProjections<N, kBlocks>(VerticesInMemory<L, S>{inc.x, inc.y}, faces0.nx, faces0.ny, faces1.nx, faces1.ny,
                                      low0, low1);
        block0 = (low0 - faces0.Offset()) + L::Fill(S(0));
        block1 = kBlocks == 2 ? (low1 - faces1.Offset()) + L::Fill(S(0)) : block0;
    }
};

/// The faces of a small ref that take no part in its decision, one bit each: the `skip`ped ones, and the lanes
/// past the last of its n faces.
inline int HiddenFaces(uint64_t skip, int n)
{
    return static_cast<int>((skip | ~((uint64_t(1) << n) - 1)) & 0xFF);
}

/// The face query of Collide (unit normals) for a ref of at most 8 faces against a scanned inc of N padded vertices,
/// with the answer of the textbook loop (TextbookFaces): the separations of all of ref's faces from one pass over
/// inc's vertices (the kernel), then one branch for all of them. A separating face ends the query at the first such
/// face (without the early exit, the query reports the largest separation, as when no face separates); otherwise
/// the largest separation is one reduction across the lanes and its first face the first lane equal to it. A
/// skipped face (anti-parallel to one already tested) and a NaN separation take no part. Untraced only: a traced
/// query runs the textbook loop, which records each face as it tests it.
template <int N, int kBlocks, typename S, typename Tracer>
FaceQuery<S> SmallRefFaceQuery(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, bool second)
{
    static_assert(!Tracer::kEnabled, "traced queries run the textbook loop");
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    const int n = ref.Count();
    const uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
    SmallSeparations<L, kBlocks> separations =
        SmallSeparations<L, kBlocks>::template Of<NormalKind::Unit, N>(ref, VerticesInMemory<L, S>{inc.x, inc.y});
    separations.Hide(HiddenFaces(skip, n));
    const int separating = separations.Positive() & ((1 << n) - 1);
    FaceQuery<S> query;
    query.face = 0;
    if (separating != 0 && Tracer::kEarlyExit)
    {
        const int i = __builtin_ctz(static_cast<unsigned>(separating));
        query.separated = true;
        query.face = i;
        query.separation = separations.Get(i);
    }
    else
    {
        // No face separates, or (without the early exit) every face counts: the largest separation.
        query.separated = separating != 0;
        query.separation = separations.Largest(n, query.face);
    }
    return query;
}

/// The face query of Collide (unit normals) against a scanned inc, four faces of ref at a time in lanes (the
/// kernel), with the answer of the textbook loop (TextbookFaces). A block of four faces costs one branch instead of
/// one per face. The last block repeats the last face, which changes no answer. Each lane keeps the largest
/// separation it saw and its first face; the lanes combine into the first face of the largest separation, as a
/// face-by-face loop finds it. A block that holds a separating face ends the query at the first such face. A ref of
/// at most 8 faces takes SmallRefFaceQuery instead. Untraced only, as SmallRefFaceQuery.
template <int N, typename S, typename Tracer>
FaceQuery<S> ScanFaceBlocks(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, bool second)
{
    static_assert(!Tracer::kEnabled, "traced queries run the textbook loop");
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    constexpr S kInfinity = std::numeric_limits<S>::infinity();
    const int n = ref.Count();
    const uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
    FaceQuery<S> query;
    query.face = 0;
    L best = L::Fill(-kInfinity);
    L bestBlock = L::Fill(S(0));
    for (int i0 = 0; i0 < n; i0 += 4)
    {
        const FaceBlock<L, S> block(ref, ref.Vertices().data, i0);
        L separation = Separations<N>(VerticesInFours<L, S>{inc.x, inc.y}, block.nx, block.ny, block.Offset());
        const int skipped = i0 < 64 ? static_cast<int>((skip >> i0) & 0xF) : 0;
        if (skipped != 0)
        {
            // A skipped face (anti-parallel to one already tested) takes no part.
            const typename L::Mask mask =
                L::Set(S(skipped & 1), S(skipped & 2), S(skipped & 4), S(skipped & 8)) > L::Fill(S(0));
            separation = Select(mask, L::Fill(-kInfinity), separation);
        }
        const int separating = (separation > L::Fill(S(0))).Bits();
        if (separating != 0 && !query.separated)
        {
            const int stop = __builtin_ctz(static_cast<unsigned>(separating));
            query.separated = true;
            query.face = std::min(i0 + stop, n - 1);
            query.separation = separation.Get(stop);
            if constexpr (Tracer::kEarlyExit)
            {
                return query;
            }
        }
        const typename L::Mask better = separation > best;
        best = Select(better, separation, best);
        bestBlock = Select(better, L::Fill(S(i0)), bestBlock);
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

/// Overlap's face query of a ref of at most 8 faces against a scanned inc of N padded vertices, its faces four at a
/// time in lanes with raw edge normals (the kernel, as SmallRefFaceQuery for Collide): one pass over inc's
/// vertices, then one branch for all of ref's faces. A skipped face (second pass: anti-parallel to one of inc's
/// faces, already tested) and the lanes past the last face take no part. True when a face separates. Untraced
/// only, as SmallRefFaceQuery.
template <int N, int kBlocks, typename S, typename Tracer>
bool SmallFacesSeparate(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, bool second)
{
    static_assert(!Tracer::kEnabled, "traced queries run the textbook loop");
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    const uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
    const SmallSeparations<L, kBlocks> separations =
        SmallSeparations<L, kBlocks>::template Of<NormalKind::Edge, N>(ref, VerticesInMemory<L, S>{inc.x, inc.y});
    return (separations.Positive() & LiveFaces(ref.Count(), skip)) != 0;
}

/// Overlap's face query of a ref of at most 8 faces against a scanned inc of at most 8 vertices, unrolled for both
/// counts (SmallFacesSeparate above): true when a face separates. Untraced only.
template <typename S, typename Tracer>
bool SmallFacesSeparate(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, bool second)
{
    const bool twoBlocks = ref.Count() > 4;
    switch (inc.padded)
    {
    case 4:
        return twoBlocks ? SmallFacesSeparate<4, 2, S, Tracer>(ref, inc, second)
                         : SmallFacesSeparate<4, 1, S, Tracer>(ref, inc, second);
    case 8:
        return twoBlocks ? SmallFacesSeparate<8, 2, S, Tracer>(ref, inc, second)
                         : SmallFacesSeparate<8, 1, S, Tracer>(ref, inc, second);
    default:
        return false; // not scanned: the caller calls for none
    }
}

} // namespace satviz::detail
