// SPDX-License-Identifier: MIT
// satviz (private), chapter 4: which face loop runs. The face query has one answer (face_query.h: the textbook
// loop) and several loops that give it, each faster on some pairs of sizes: the textbook loop itself, the loops of
// four faces at a time (face_blocks.h), and the walk over a large polygon (walked_faces.h). QueryFaces picks one.
#pragma once

#include "face_blocks.h"
#include "face_query.h"
#include "face_scan.h"
#include "incident_polygon.h"
#include "walked_faces.h"

#include <satviz/polygon.h>

namespace satviz::detail
{

/// The face query of `ref` against `inc` (Gregorius), for inc's padded vertex count N (a multiple of 4 when inc is
/// scanned, 0 when it is walked), by the loop that is fastest for it. Each gives the textbook loop's answer.
///   1. Small inc (kScanLimit vertices or fewer), mapped into ref's frame: each face takes the smallest projection
///      of all its vertices, without branches: O(n m) with a tiny constant. Overlap goes a face at a time (ScanFaces;
///      polygons of up to 8 vertices take SmallFacesSeparate before this); Collide four faces at a time in lanes
///      (ScanFaceBlocks; a ref of up to 8 faces: SmallRefFaceQuery), which costs one branch per block of faces.
///   2. Large inc: only the faces near the contact, walked to (WalkFaces).
/// The arguments are those of QueryFaces.
template <bool kUnit, bool kInside, int N, typename S, typename Tracer>
FaceQuery<S> QueryFacesN(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, S floor,
                         Tracer& tracer, S* inside)
{
    static_assert(N % 4 == 0 && N <= IncidentPolygon<S>::kCapacity, "scan of a padded count");
    if constexpr (N == 0)
    {
        return WalkFaces<kUnit>(ref, inc, side, second, floor, tracer);
    }
    else if constexpr (kUnit)
    {
        switch ((ref.Count() + 3) / 4)
        {
        case 1:
            return SmallRefFaceQuery<N, 1>(ref, inc, side, second, tracer);
        case 2:
            return SmallRefFaceQuery<N, 2>(ref, inc, side, second, tracer);
        default:
            return ScanFaceBlocks<N>(ref, inc, side, second, tracer);
        }
    }
    else
    {
        return ScanFaces<kUnit, kInside, N>(ref, inc, side, second, tracer, inside);
    }
}

/// The face query of `ref` against `inc`: the faces of polygon `side` (0: A, 1: B) of the pair, in the `second` pass
/// of the query or the first, with inc's scan unrolled for its padded vertex count (QueryFacesN). `floor` is the
/// separation below which a face cannot change the answer (Overlap: 0; Collide: -infinity in the first pass, the
/// first pass's largest separation in the second). kUnit: unit normals (Collide) or raw edge normals (Overlap).
/// `inside`, with kInside and a scanned inc, receives for each of inc's vertices its largest separation from ref's
/// faces (filled with -infinity by the caller); it is not touched otherwise. A walked inc reports instead whether its
/// witness lies inside ref (FaceQuery::witnessInside).
template <bool kUnit, bool kInside = false, typename S, typename Tracer>
FaceQuery<S> QueryFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, S floor,
                        Tracer& tracer, S* inside = nullptr)
{
    static_assert(kScanLimit <= 16, "QueryFaces unrolls scans of up to 16 vertices");
    switch (inc.scan ? inc.padded : 0)
    {
    case 4:
        return QueryFacesN<kUnit, kInside, 4>(ref, inc, side, second, floor, tracer, inside);
    case 8:
        return QueryFacesN<kUnit, kInside, 8>(ref, inc, side, second, floor, tracer, inside);
    case 12:
        return QueryFacesN<kUnit, kInside, 12>(ref, inc, side, second, floor, tracer, inside);
    case 16:
        return QueryFacesN<kUnit, kInside, 16>(ref, inc, side, second, floor, tracer, inside);
    default:
        return QueryFacesN<kUnit, kInside, 0>(ref, inc, side, second, floor, tracer, inside);
    }
}

} // namespace satviz::detail
