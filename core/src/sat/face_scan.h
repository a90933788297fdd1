// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face-scan kernel, one face of the reference polygon against every vertex of a
// small incident polygon mapped into its frame (IncidentPolygon): the smallest projection of the vertices on the
// face's normal, without a branch. The textbook face query (face_query.h) calls it once per face. One kernel over
// lanes (lanes.h): four lanes (two SSE2 registers of double, or one of float) in the baseline instructions; in the
// wide queries one AVX2 register, of four doubles or eight floats. Every lane rounds each projection as the scalar
// expression does (no contraction), and a minimum is exact, so every width finds the same number.
#pragma once

#include "lanes.h"
#include "lanes2.h"
#include "lanes8.h"

#include <satviz/math.h>

#include <limits>
#include <type_traits>

namespace satviz::detail
{

#if SATVIZ_LANES8
/// The lanes of a face scan of N entries, one register each time: with kWide (code compiled for AVX2) one AVX2
/// register, of four doubles, or of eight floats when N is a multiple of 8; else one SSE2 register, of two doubles or
/// four floats. These widths measured fastest in satviz-bench on the pairs whose scans they run: eight floats rather
/// than four for float scans, and without the wide vectors two doubles in one SSE2 register rather than four in two.
template <typename S, bool kWide, int N>
using ScanLanes =
    std::conditional_t<std::is_same_v<S, double>, std::conditional_t<kWide, Lanes<double, true>, Lanes2<double>>,
                       std::conditional_t<kWide && N % 8 == 0, Lanes8F, Lanes<S, false>>>;
#else
/// The lanes of a face scan of N entries: four lanes in plain arrays.
template <typename S, bool kWide, int N>
using ScanLanes = Lanes<S, false>;
#endif

/// The smallest of the projections nx x[j] + ny y[j] over `count` entries, `count` a multiple of 4 (the caller pads
/// by repeating a vertex), in lanes L of four or two.
template <typename L, typename S>
S MinProjection(const S* x, const S* y, int count, S nx, S ny)
{
    const L vx = L::Fill(nx);
    const L vy = L::Fill(ny);
    L low = vx * L::Load(x) + vy * L::Load(y);
    for (int j = L::kCount; j < count; j += L::kCount)
    {
        low = Min(low, vx * L::Load(x + j) + vy * L::Load(y + j));
    }
    return low.MinLaneAnyOrder();
}

/// One face of a scan over N padded entries (N a multiple of the lanes' count, known at compile time so the loop
/// unrolls), in lanes L: the separation min_j (nx x[j] + ny y[j]) - offset. With kInside it also keeps, per entry,
/// the largest separation over the faces scanned so far: inside[j] = max(inside[j], nx x[j] + ny y[j] - offset). An
/// entry whose largest separation over all faces is <= 0 lies inside the polygon. Rounding is monotonic, so
/// subtracting the offset before or after taking the minimum gives the same separation to the bit.
template <typename L, int N, bool kInside, typename S>
S ScanFace(const S* x, const S* y, S nx, S ny, S offset, S* inside)
{
    static_assert(N % L::kCount == 0, "whole registers");
    const L vx = L::Fill(nx);
    const L vy = L::Fill(ny);
    const L off = L::Fill(offset);
    L low = L::Fill(std::numeric_limits<S>::infinity());
    for (int j = 0; j < N; j += L::kCount)
    {
        const L p = vx * L::Load(x + j) + vy * L::Load(y + j);
        if constexpr (kInside)
        {
            Max(L::Load(inside + j), p - off).Store(inside + j);
        }
        low = Min(low, p);
    }
    return low.MinLaneAnyOrder() - offset;
}

/// The separation of one face over a scan of N padded entries (ScanFace), with the wide vectors when kWide. The
/// smallest projection is the same number whatever the order the lanes combine it in, except for the sign of a
/// zero; adding +0 makes a zero separation +0, so every width gives the same bits.
template <int N, bool kInside, bool kWide, typename S>
S FaceSeparation(const S* x, const S* y, Vec2T<S> normal, S offset, S* inside)
{
    return ScanFace<ScanLanes<S, kWide, N>, N, kInside>(x, y, normal.x, normal.y, offset, inside) + S(0);
}

} // namespace satviz::detail
