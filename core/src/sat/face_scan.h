// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face scan, the textbook face query (face_query.h) a face at a time, each face
// against every vertex of a small incident polygon mapped into its frame (IncidentPolygon) by the face-separation
// kernel (face_kernel.h) in lanes, without a branch: two lanes of double in one SSE2 register, or four of float, in
// the baseline instructions; in the wide queries one AVX2 register, of four doubles or eight floats.
#pragma once

#include "face_kernel.h"
#include "face_query.h"
#include "incident_polygon.h"
#include "lanes.h"
#include "lanes2.h"
#include "lanes8.h"

#include <satviz/math.h>
#include <satviz/polygon.h>

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

/// The face query of `ref` against a scanned `inc` of N padded vertices (N a multiple of 4, known at compile time so
/// the scan unrolls), the textbook loop (FaceByFace, face_query.h) with each face's smallest projection taken by the
/// face-separation kernel on its side (ColumnVertices): the face's normal in every lane, inc's vertices spread over
/// the lanes, the smallest lane at the end; with the wide vectors when Tracer::kWide. Every lane rounds each
/// projection as the scalar expression does (no contraction), and a minimum is exact, so the same numbers as the
/// textbook loop. kInside: as TextbookFaceQuery, over inc's padded entries.
template <bool kUnit, bool kInside, int N, typename S, typename Tracer>
FaceQuery<S> ScanFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, Tracer& tracer,
                       S* inside)
{
    static_assert(N > 0 && N % 4 == 0 && N <= IncidentPolygon<S>::kCapacity, "a scan of a padded count");
    using L = ScanLanes<S, Tracer::kWide, N>;
    return FaceByFace<kUnit>(ref, inc, side, second, tracer, [&](Vec2T<S> normal, S offset) {
        const ScannedVertices<S> vertices{inc.x, inc.y, offset, inside};
        return LowestProjection<N, ColumnVertices<L, kInside, S>>(vertices, L::Fill(normal.x), L::Fill(normal.y))
            .MinLaneAnyOrder();
    });
}

} // namespace satviz::detail
