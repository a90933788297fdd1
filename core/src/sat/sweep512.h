// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face loops of the sweep of two polygons of up to 8 vertices on 512-bit vectors
// (AVX-512F): every face of both polygons at once, then one decision. Used only in code compiled for AVX-512 (entry.h:
// RunWide512), where the processor has it (cpu_dispatch.h). The same verdict, time and face to the bit as the face
// loops of sweep_faces.h.
#pragma once

#include "collide512.h"
#include "cpu_dispatch.h"
#include "lanes8.h"
#include "overlap512.h"
#include "sweep_axis.h"
#include "sweep_faces.h"

#include <satviz/polygon.h>

#include <algorithm>
#include <limits>

namespace satviz::detail
{

#if SATVIZ_WIDE
// What the face loops of two polygons of at most 8 faces decide, found from every face of both at once on 512-bit
// vectors (SmallSweep512): whether the test goes on, the latest entry and its face, whether every separation is < 0,
// and the separations themselves, for the static manifold of an interpenetrating start.
struct SmallSweepVerdict
{
    bool going = false;
    SweepState<double> state;
    Lanes8 sepA;
    Lanes8 sepB;
    MappedPair512 mapped; // both polygons, each mapped into the other's frame
};

// The entry and exit times of the faces of `ref` (at most 8, one per lane) whose separations are `separations`
// (FaceSeparations512; -infinity past the last face), moving at `velocity` (ref's frame, as SweepFaces takes it):
// AxisLanes in eight lanes, so the same bits as the face loops of four. A lane past the last face enters never
// (-infinity) and exits never (+infinity): it takes no part. NaN entries and exits (0 / 0: a face touching at t = 0
// with the motion along it) become -infinity and +infinity, which the lanes of SweepLanes never take either, so that
// the reductions of one register see no NaN. Returns the lanes of the faces that are apart (separation >= 0) and,
// in `never`, those that never close.
[[gnu::target("avx2,avx512f")]] inline int FaceTimes512(const PolygonT<double>& ref, const Lanes8& separations,
                                                        Vec2T<double> velocity, Lanes8& entry, Lanes8& leave,
                                                        int& never)
{
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const int n = ref.Count();
    Lanes8 nx;
    Lanes8 ny;
    Lanes8::LoadPoints(&ref.InlineBlock()[n + 1].x, nx, ny);
    const Lanes8 rates = nx * Lanes8::Fill(velocity.x) + ny * Lanes8::Fill(velocity.y);
    const AxisLanes<Lanes8> axes(separations, rates, StillRate(velocity));
    entry = Select(axes.entry == axes.entry, axes.entry, Lanes8::Fill(-kInf));
    leave = Select(axes.leave == axes.leave, axes.leave, Lanes8::Fill(kInf));
    never = axes.never.Bits();
    return axes.apart.Bits();
}

// The face loops of a sweep of two polygons of at most 8 faces (SweepFaces of A, then of B) on 512-bit vectors:
// every face of both polygons at once, then one decision, where the face loops decide after each polygon. The same
// verdict, latest entry and face: each bound only tightens from face to face, so a test that ends after A's faces
// also ends after both; the latest entry is the largest entry of all, its face the first face that has it (A's
// faces first), as SweepLanes::Combine finds them. `bInA`, `aInB`: each polygon's frame in the other's.
[[gnu::target("avx2,avx512f")]] inline SmallSweepVerdict
SmallSweep512(const PolygonT<double>& a, const PolygonT<double>& b, const TransformT<double>& bInA,
              const TransformT<double>& aInB, Vec2T<double> velocityInA, Vec2T<double> velocityInB)
{
    SmallSweepVerdict out;
    out.mapped = MapPair512(a, b, bInA, aInB);
    PairSeparations512(a, b, out.mapped, 0, out.sepA, out.sepB);
    Lanes8 entryA;
    Lanes8 leaveA;
    Lanes8 entryB;
    Lanes8 leaveB;
    int neverA = 0;
    int neverB = 0;
    const int apartA = FaceTimes512(a, out.sepA, velocityInA, entryA, leaveA, neverA);
    const int apartB = FaceTimes512(b, out.sepB, -velocityInB, entryB, leaveB, neverB);
    const double first = std::max(entryA.MaxLane(), entryB.MaxLane());
    const double last = std::min(leaveA.MinLane(), leaveB.MinLane());
    const int hitsA = entryA.EqualBits(Lanes8::Fill(first)) & ((1 << a.Count()) - 1);
    const int hitsB = entryB.EqualBits(Lanes8::Fill(first)) & ((1 << b.Count()) - 1);
    out.state.first = first;
    out.state.last = last;
    out.state.firstSide = hitsA == 0 && hitsB != 0 ? 1 : 0;
    out.state.firstFace = hitsA != 0   ? __builtin_ctz(static_cast<unsigned>(hitsA))
                          : hitsB != 0 ? __builtin_ctz(static_cast<unsigned>(hitsB))
                                       : 0;
    out.state.inside = (apartA | apartB) == 0;
    out.going = (neverA | neverB) == 0 && !(first > 1.0) && !(first >= last);
    return out;
}
#endif

} // namespace satviz::detail
