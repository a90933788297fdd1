// SPDX-License-Identifier: MIT
// satviz (private), chapter 11: the face loop of the sweep. The faces of each polygon, four at a time in lanes, each
// with its entry and exit (sweep_axis.h): the latest entry and the earliest exit so far, and whether the test has
// ended, against another polygon small enough to scan. Larger polygons have their own loops, which find the same
// verdict from fewer faces: sweep_walked.h and sweep_bisected.h.
#pragma once

#include "face_blocks.h"
#include "incident_polygon.h"
#include "lanes.h"
#include "select.h"
#include "sweep_axis.h"

#include <satviz/polygon.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <limits>

namespace satviz::detail
{

// What the face loops of a polygon sweep carry from axis to axis.
template <typename S>
struct SweepState
{
    S first = -kInfinity<S>; // latest entry so far (none yet)
    S last = kInfinity<S>;   // earliest exit so far
    int firstSide = 0;       // the axis of the latest entry: its polygon
    int firstFace = 0;       // and its face
    bool inside = true;      // every separation so far is < 0
    SweepExit exit = SweepExit::AllAxesOverlap;
};

// A face's place in the order A's faces, then B's, as a lane value (exact in float up to 2^24).
constexpr int kSideShift = 16;
constexpr int kSideStride = 1 << kSideShift;

// What the face loops carry from A's faces to B's, per lane: the latest entry (and its face) and the earliest exit
// each lane saw, and whether every separation was < 0. The lanes are combined once, after both polygons (Combine),
// so B's faces need not wait for A's to be combined.
template <typename L, typename S>
struct SweepLanes
{
    L first = L::Fill(-kInfinity<S>);              // latest entry so far (none yet)
    L firstIndex = L::Fill(S(0));                  // its face: side * kSideStride + face
    L last = L::Fill(kInfinity<S>);                // earliest exit so far
    typename L::Mask inside = L::Mask::Fill(true); // every separation so far is < 0

    // Takes in a block of four faces (face indices as lane values, side * kSideStride + face), in face order:
    // each lane keeps the latest entry it saw and the first face that has it, and the earliest exit. Returns the
    // lanes whose axis ends the test: it never closes, or the latest entry is after t = 1.
    typename L::Mask Add(const AxisLanes<L>& axes, const L& faces)
    {
        // A NaN separation does not count as apart, and a NaN entry does not replace the latest one.
        inside = inside & ~axes.apart;
        const typename L::Mask later = axes.entry > first;
        first = Select(later, axes.entry, first);
        firstIndex = Select(later, faces, firstIndex);
        last = Min(axes.leave, last);
        return axes.never | (first > L::Fill(S(1)));
    }

    // The latest entry, at the first face that has it, and the earliest exit.
    void Combine(SweepState<S>& state) const
    {
        state.first = first.MaxLane();
        const L candidates = Select(first == L::Fill(state.first), firstIndex, L::Fill(S(1 << 30)));
        const int index = static_cast<int>(candidates.MinLane());
        // The index is not negative: a shift and a mask, not a signed division.
        state.firstSide = index >> kSideShift;
        state.firstFace = index & (kSideStride - 1);
        state.last = last.MinLane();
        state.inside = inside.All();
    }
};

// The separations at t = 0 of the faces of a polygon of at most 8 faces, as its face loop computed them (the blocks
// of SmallRefSeparations), kept for a start where the shapes interpenetrate: the static manifold's reference face is
// the face of largest separation, as Collide finds it from the same numbers, so no face is tested twice.
template <typename L>
struct KeptSeparations
{
    L block0 = L::Fill(0); // faces 0 to 3
    L block1 = L::Fill(0); // faces 4 to 7, or 0 to 3 again
    bool kept = false;     // the face loop was that of a small polygon (else nothing is kept)
    bool twoBlocks = false;
};

// The end of a pass over the faces of a polygon: `going` is whether the test goes on. A pass that ended the test on the
// latest entry against the earliest exit, which the loops compare once per pass (a face that ends it on its own said
// so as the lanes took it in), shows it on its last face evaluated. `view` holds why the test ended, for the trace.
template <typename S, typename Tracer>
bool EndPass(Tracer& tracer, SweepState<S>& view, bool going)
{
    if constexpr (Tracer::kEnabled)
    {
        if (!going && view.exit == SweepExit::AllAxesOverlap)
        {
            view.exit = SweepExit::EntryAfterExit;
            tracer.EndedAfterPass();
        }
    }
    return going;
}

// The faces of `ref` (side 0 = A, 1 = B) against `inc` mapped into ref's frame; `velocity` is B's motion relative
// to A in ref's frame, times -1 when ref is B (it is then A that moves towards ref). False when an axis ends the
// test with a miss. N is inc's padded vertex count (inc scanned; a walked inc goes to SweepBoundedFaces, a ref above
// kBisectFaces faces to SweepBisectedFaces).
//   Per face: separation s at t = 0 (as in the static face query, but with unit normals) and its rate
//   r = Dot(n, velocity), then its entry and exit (AxisLanes). The faces are decided four at a time, in lanes:
//   each lane keeps the latest entry it saw (and its face) and the earliest exit, so there is no branch per face,
//   whose outcome follows the geometry and would be mispredicted. The last block repeats the last face, which
//   changes no bound. A block that holds an axis that never closes, or an entry after t = 1, ends the test; the
//   latest entry against the earliest exit is compared once per polygon. Both bounds only tighten from face to
//   face, so this ends with the same verdict as stopping at the first face that fails, and the lanes combine to
//   the first face of the latest entry, as a face-by-face loop finds it. The recorder takes each block's faces from
//   the lanes as they take it in, up to a face that ends the test on its own, and a pass that ends on the latest
//   entry against the earliest exit on its last face (EndPass).
template <int N, int kBlocks, typename L, typename S, typename Tracer>
bool SweepFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, Vec2T<S> velocity,
                SweepLanes<L, S>& lanes, SweepState<S>& view, Tracer& tracer, KeptSeparations<L>& kept)
{
    static_assert(N > 0, "a scanned inc");
    constexpr bool kSmall = kBlocks > 0;
    // A small ref has the separations of all its faces, and its blocks, from one pass over inc's vertices.
    const auto small = [&]() {
        if constexpr (kSmall)
        {
            return SmallRefSeparations<N, kBlocks, L, S>(ref, inc);
        }
        else
        {
            return 0;
        }
    }();
    if constexpr (kSmall)
    {
        kept = {small.block0, small.block1, true, kBlocks == 2};
    }
    const int n = ref.Count();
    // A small ref has exactly kBlocks blocks, so its loop unrolls.
    const int blocksEnd = kSmall ? 4 * kBlocks : n;
    typename L::Mask ends = L::Mask::Fill(false);
    for (int i0 = 0; i0 < blocksEnd && !ends.Any(); i0 += 4)
    {
        // The block's normals and separations; the last block repeats the last face.
        L nx;
        L ny;
        L separations;
        if constexpr (kSmall)
        {
            const FaceBlock<L, S>& block = i0 == 0 ? small.faces0 : small.faces1;
            nx = block.nx;
            ny = block.ny;
            separations = i0 == 0 ? small.block0 : small.block1;
        }
        else
        {
            const FaceBlock<L, S> block(ref, ref.Vertices().data, i0);
            nx = block.nx;
            ny = block.ny;
            // The four faces side by side: each vertex of inc is projected on all four normals at once and the
            // minimum kept per lane, so no minimum is taken across lanes. The same products, sums and minimum as
            // TextbookFaceQuery, so the same bits.
            separations = SeparationsOf(LowestProjection<N, SpreadVertices<L, S>>(inc, nx, ny), block.Offset());
        }
        const L rates = nx * L::Fill(velocity.x) + ny * L::Fill(velocity.y);
        const AxisLanes<L> axes(separations, rates, StillRate(velocity));
        // Lane l holds face i0 + l, past the last face too: a lane that repeats the last face ties with that face's
        // own lane, whose smaller index Combine takes.
        ends = lanes.Add(axes, L::Fill(S(side * kSideStride + i0)) + L::Set(S(0), S(1), S(2), S(3)));
        if constexpr (Tracer::kEnabled)
        {
            const int ended = tracer.Block(side, i0, std::min(4, n - i0), separations, rates, axes, ends);
            if (ended >= 0)
            {
                view.exit = axes.never.Get(ended) ? SweepExit::NeverCloses : SweepExit::EntryAfterStep;
            }
        }
    }
    // A latest entry after t = 1 ended its own block (`ends`), so what is left to compare is the latest entry
    // against the earliest exit. Why the test ended is for the trace only, which the view has.
    return EndPass(tracer, view, !ends.Any() && !(lanes.first.MaxLane() >= lanes.last.MinLane()));
}

} // namespace satviz::detail
