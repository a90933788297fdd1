// SPDX-License-Identifier: MIT
// satviz (private), chapter 3: the face query. A face of a convex polygon separates it from another convex polygon
// when the other one lies wholly outside the face's line; in 2D the face normals of both polygons are all the axes
// the separating axis test needs (Ericson 5.2.1). The face query tests the faces of one polygon, the reference
// polygon, against the other, the incident polygon: each face's separation is the signed distance of the incident
// polygon's support point beyond it (Gregorius). Here is the query as the textbook writes it, a face at a time, in
// plain scalar code: the reference the faster loops are tested against. The loop itself (FaceByFace) is written once;
// how a face finds the smallest projection is its argument: here one vertex after another, in face_scan.h the
// face-separation kernel in lanes. face_query_dispatch.h picks, for each pair of sizes, a loop that gives these
// numbers.
//
// References:
//   C. Ericson, Real-Time Collision Detection (2005), 5.2.1 (separating-axis test).
//   D. Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013 (face queries with support points).
#pragma once

#include "incident_polygon.h"
#include "select.h"

#include <satviz/polygon.h>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace satviz::detail
{

/// Outcome of testing the faces of one polygon against another.
template <typename S>
struct FaceQuery
{
    S separation = -std::numeric_limits<S>::infinity(); ///< largest separation found (> 0: separated)
    int face = -1;                                      ///< the face that has it
    int support = -1;                                   ///< walk only: the other polygon's support for that face
    bool separated = false;                             ///< stopped at a separating face
    /// Walk only: the vertex of the other polygon that bounded the faces' separations (the support point for the
    /// first face), and whether it lay on or inside every face tested or pruned (Overlap: inside this polygon, by
    /// the wedge that holds it): then, if the query went round all faces, that vertex lies inside this polygon.
    int witness = -1;
    bool witnessInside = true; ///< walk only: see witness
};

/// Faces of b (at most 64) exactly anti-parallel to a face of a, as a bit mask. Rotated normals are exact only
/// when the relative rotation is a multiple of a quarter turn (one of its components is zero), so other rotations
/// are not searched: the search would cost as much as the axes it could save.
template <typename S>
uint64_t AntiParallelFaces(const PolygonT<S>& a, const PolygonT<S>& b, const RotT<S>& bInA)
{
    uint64_t mask = 0;
    if ((bInA.s != S(0) && bInA.c != S(0)) || b.Count() > 64)
    {
        return mask;
    }
    for (int j = 0; j < b.Count(); ++j)
    {
        const Vec2T<S> nb = Rotate(bInA, b.Normal(j));
        for (int k = 0; k < a.Count(); ++k)
        {
            if (Cross(nb, a.Normal(k)) == S(0) && Dot(nb, a.Normal(k)) < S(0))
            {
                mask |= uint64_t(1) << j;
                break;
            }
        }
    }
    return mask;
}

/// The faces of ref that the second pass of a face query skips (SkipParallel: anti-parallel to a face of inc, whose
/// test the first pass made), as a bit mask; none in the first pass.
template <bool kSkipParallel, typename S>
uint64_t SecondPassSkips(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, bool second)
{
    return kSkipParallel && second ? AntiParallelFaces(inc.polygon, ref, InvMulRot(inc.xf.q, RotT<S>{})) : uint64_t(0);
}

/// The separation of a face from the smallest projection `low` of the other polygon's vertices on its normal and the
/// face's offset Dot(normal, v_i): low - offset. Rounding is monotonic, so subtracting before or after the minimum
/// gives the same number; adding +0 makes a zero separation +0 whichever zero the minimum kept, so every loop and
/// every lane width gives the same bits.
template <typename S>
S SeparationOf(S low, S offset)
{
    return (low - offset) + S(0);
}

/// Records the separation of face i of the reference polygon in `query`, and in the trace; true when the query
/// stops there (a separating face, with the early exit). kUnit (unit normals: Collide) also keeps the face of
/// largest separation and inc's `support` point for it; with raw edge normals (Overlap) only the sign counts.
/// kScan: inc is scanned, and the trace shows its support point found by a scan.
template <bool kUnit, bool kScan, typename S, typename Tracer>
bool RecordFace(FaceQuery<S>& query, const IncidentPolygon<S>& inc, int side, int i, Vec2T<S> normal, S separation,
                int support, Tracer& tracer)
{
    const bool separating = separation > S(0);
    if constexpr (kUnit)
    {
        // Collide needs the best face; selecting without a branch keeps the loop free of mispredictions.
        const bool better = separation > query.separation;
        query.face = Select(better, i, query.face);
        query.support = Select(better, support, query.support);
        query.separation = std::max(separation, query.separation);
    }
    if constexpr (Tracer::kEnabled)
    {
        tracer.FaceAxis(side, i, normal, separation, kScan ? inc.Support(normal) : support, separating);
    }
    if (separating)
    {
        // With the early exit the query reports the first separating face; without it (kUnit), the largest.
        if (!query.separated && (Tracer::kEarlyExit || !kUnit))
        {
            query.separation = separation;
            query.face = i;
            query.support = support;
        }
        query.separated = true;
        return Tracer::kEarlyExit;
    }
    return false;
}

/// Face query of `ref` against a scanned `inc` (Gregorius), a face at a time, with `lowest(normal, offset)` the
/// smallest projection of inc's vertices on the normal (offset: the face's Dot(normal, v_i), for kInside).
/// Outline:
///   1. For each face i of ref, with outward normal n and first vertex v_i, the separation is the signed distance
///      from the face to inc's support point in direction -n, which is inc's vertex of smallest projection on n:
///          separation_i = Dot(n, support(inc, -n) - v_i) = min_j Dot(n, w_j) - Dot(n, v_i),
///      over inc's vertices w_j, mapped into ref's frame once (IncidentPolygon). Each face takes one pass over them:
///      O(n m), and m is at most kScanLimit (larger polygons are walked, walked_faces.h), so linear in n: the
///      O(n + m) of sat.h.
///   2. A separation > 0 is a separating axis: stop there (early exit).
///   3. Keep the largest separation and its face (kUnit): when no face separates, the face of least penetration.
///   4. Second pass only: a face of ref exactly anti-parallel to a face of inc repeats the test the first pass made
///      from that face, and is skipped (the faces in SecondPassSkips).
/// kUnit selects unit normals (Collide: separations are distances, the best face is tracked) or raw edge normals
/// (Overlap: only the sign matters, so no square root or division is needed).
template <bool kUnit, typename S, typename Tracer, typename Lowest>
FaceQuery<S> FaceByFace(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, Tracer& tracer,
                        Lowest&& lowest)
{
    const int n = ref.Count();
    FaceQuery<S> query;
    // The best face so far starts as the first one tested, so that it is a valid index even when no comparison
    // holds (NaN input).
    query.face = 0;
    const uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
    for (int i = 0; i < n; ++i)
    {
        const Vec2T<S> normal = kUnit ? ref.Normal(i) : RightPerp(ref.Edge(i));
        if (skip != 0 && i < 64 && ((skip >> i) & 1u))
        {
            if constexpr (Tracer::kEnabled)
            {
                tracer.SkippedFace(i, -1);
            }
            continue;
        }
        const S offset = Dot(normal, ref.Vertices()[i]);
        const S separation = SeparationOf(lowest(normal, offset), offset);
        if (RecordFace<kUnit, true>(query, inc, side, i, normal, separation, -1, tracer))
        {
            break;
        }
    }
    return query;
}

/// The face query of `ref` against a scanned `inc` as the textbook writes it (FaceByFace), each face's smallest
/// projection taken one vertex after another. kInside also finds, for each vertex of inc, its largest separation
/// from ref's faces, in `inside`: a vertex whose largest separation is <= 0 lies inside ref.
template <bool kUnit, bool kInside = false, typename S, typename Tracer>
FaceQuery<S> TextbookFaceQuery(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second,
                               Tracer& tracer, S* inside = nullptr)
{
    return FaceByFace<kUnit>(ref, inc, side, second, tracer, [&](Vec2T<S> normal, S offset) {
        S low = std::numeric_limits<S>::infinity();
        for (int j = 0; j < inc.polygon.Count(); ++j)
        {
            const S projection = normal.x * inc.x[j] + normal.y * inc.y[j];
            if constexpr (kInside)
            {
                inside[j] = std::max(inside[j], projection - offset);
            }
            low = std::min(low, projection);
        }
        return low;
    });
}

} // namespace satviz::detail
