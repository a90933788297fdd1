// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face query against a large polygon, walked. Above kScanLimit vertices, the
// incident polygon is not mapped whole: its support point for each face is walked to from the one before, and a
// point of it found early (the witness) bounds every face's separation, so that only the faces near the contact are
// walked to at all. The answer is that of the textbook loop (face_query.h); only the faces visited differ.
//
// References:
//   D. Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013 (face queries with support points).
//   J. O'Rourke, Computational Geometry in C (2nd ed., 1998), 7.3 (point in a convex polygon by bisection).
#pragma once

#include "face_query.h"
#include "incident_polygon.h"
#include "support.h"

#include <satviz/polygon.h>

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace satviz::detail
{

/// The signed distance of `point` (polygon frame) from the line of face i: Dot(Normal(i), point - v_i), > 0 outside.
template <typename S>
S FaceDistance(const PolygonT<S>& polygon, int i, Vec2T<S> point)
{
    return Dot(polygon.Normal(i), point - polygon.Vertices()[i]);
}

/// The first face i in [from, to) whose FaceDistance from `point` is above `threshold`, or `to` if none is (a NaN
/// distance is not above).
template <typename S>
int FirstFaceAbove(const PolygonT<S>& polygon, Vec2T<S> point, S threshold, int from, int to)
{
    int i = from;
    while (i < to && !(FaceDistance(polygon, i, point) > threshold))
    {
        ++i;
    }
    return i;
}

#if defined(__SSE2__)
/// FaceDistance of faces i and i + 1, one per lane: the same products and sum as Dot, so the same bits.
inline __m128d FaceDistancePair(const double* normals, const double* vertices, int i, __m128d point)
{
    const __m128d q0 = _mm_mul_pd(_mm_loadu_pd(normals + 2 * i), _mm_sub_pd(point, _mm_loadu_pd(vertices + 2 * i)));
    const __m128d q1 =
        _mm_mul_pd(_mm_loadu_pd(normals + 2 * i + 2), _mm_sub_pd(point, _mm_loadu_pd(vertices + 2 * i + 2)));
    return _mm_add_pd(_mm_unpacklo_pd(q0, q1), _mm_unpackhi_pd(q0, q1));
}

/// FirstFaceAbove with SSE2: four faces per step, one branch for the four.
inline int FirstFaceAbove(const PolygonT<double>& polygon, Vec2T<double> point, double threshold, int from, int to)
{
    const double* normals = &polygon.Normal(0).x;
    const double* vertices = &polygon.Vertices()[0].x;
    const __m128d p = _mm_set_pd(point.y, point.x);
    const __m128d limit = _mm_set1_pd(threshold);
    int i = from;
    for (; i + 4 <= to; i += 4)
    {
        const int low = _mm_movemask_pd(_mm_cmpgt_pd(FaceDistancePair(normals, vertices, i, p), limit));
        const int high = _mm_movemask_pd(_mm_cmpgt_pd(FaceDistancePair(normals, vertices, i + 2, p), limit));
        const int above = low | (high << 2);
        if (above != 0)
        {
            return i + __builtin_ctz(static_cast<unsigned>(above));
        }
    }
    while (i < to && !(FaceDistance(polygon, i, point) > threshold))
    {
        ++i;
    }
    return i;
}
#endif

/// A face of `polygon` farther from `point` than both its neighbours, climbing from face `start`: forward while
/// the next face is farther, then backward while the previous one is. When the point lies outside the polygon,
/// the distances of the faces that see it rise to one maximum and fall, so this is the farthest face.
template <typename S>
int ClimbFaceTowards(const PolygonT<S>& polygon, Vec2T<S> point, int start)
{
    const int n = polygon.Count();
    int i = start;
    S here = FaceDistance(polygon, i, point);
    // Steps with `step` (Next or Prev) while the face there is farther.
    const auto climb = [&](int (*step)(int, int)) {
        for (int k = 0; k < n; ++k)
        {
            const S there = FaceDistance(polygon, step(i, n), point);
            if (!(there > here))
            {
                break;
            }
            i = step(i, n);
            here = there;
        }
    };
    climb(Next);
    climb(Prev);
    return i;
}

/// The wedge of `polygon` that holds `point` (polygon frame): the vertex i such that the point lies between the
/// rays from the centroid through v_i (included) and v_{i+1}, searched from vertex `start` in O(log n) steps.
/// Outline (point in a convex polygon by bisection over its fan, as in O'Rourke, Computational Geometry in C,
/// 7.3, with the turn measured as in BisectSupport):
///   1. Measure each ray's turn from the ray through v_0 (half-plane of the cross product, then the cross product
///      within the half). Along a counter-clockwise outline the vertices' turns increase with the index, so
///      "v_j's ray comes no later than the point's" holds for j = 0 .. i and fails after: i is the wedge.
///   2. Gallop from `start` (steps 1, 2, 4, ...) towards the change, then bisect the bracket it found: a point near
///      vertex `start` takes a few steps through data already in cache, any point O(log n).
/// The triangle of wedge i and the centroid lies inside the polygon, so the point lies inside the polygon iff it
/// lies on the inner side of face i. NaN input returns some valid vertex.
template <typename S>
int WedgeOf(const PolygonT<S>& polygon, Vec2T<S> point, int start)
{
    const int n = polygon.Count();
    const Vec2T<S> r = polygon.Vertices()[0] - polygon.Centroid();
    const Vec2T<S> u = point - polygon.Centroid();
    const auto pastHalf = [r](Vec2T<S> v) {
        const S c = Cross(r, v);
        return c < S(0) || (c == S(0) && Dot(r, v) < S(0));
    };
    const bool uPastHalf = pastHalf(u);
    // Whether the ray through v_j turns no farther from r than the point's: true for j = 0 .. wedge, false after.
    const auto noLater = [&](int j) {
        const Vec2T<S> v = polygon.Vertices()[j] - polygon.Centroid();
        const bool vPastHalf = pastHalf(v);
        return vPastHalf != uPastHalf ? uPastHalf : Cross(v, u) >= S(0);
    };
    // Bracket [lo, hi): noLater(lo) holds (vertex 0 always does), and hi is n or a vertex where it fails.
    int lo = 0;
    int hi = n;
    if (noLater(start))
    {
        lo = start;
        for (int step = 1; lo + step < n; step *= 2)
        {
            if (!noLater(lo + step))
            {
                hi = lo + step;
                break;
            }
            lo += step;
        }
    }
    else
    {
        hi = start;
        for (int step = 1; hi - step > 0; step *= 2)
        {
            if (noLater(hi - step))
            {
                lo = hi - step;
                break;
            }
            hi -= step;
        }
    }
    while (hi - lo > 1)
    {
        const int mid = lo + (hi - lo) / 2;
        if (noLater(mid))
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return lo;
}

/// Face query of `ref` against a walked `inc` (more than kScanLimit vertices; Gregorius): the answer of ScanFaces,
/// from the faces near the contact.
/// Outline:
///   1. Start at a face of ref farther from inc's centroid than its neighbours, in O(log n) steps: bisect for the
///      face whose normal points that way (BisectSupport), then climb (ClimbFaceTowards); when the centroid is
///      outside ref, that is the farthest face, where separated pairs usually end. Go round once from there.
///   2. inc's support point for the first face by bisection (BisectSupport, O(log m)). That point, the witness,
///      lies in inc, so its distance from a face's line bounds the face's separation from above. A face whose bound
///      is not above `floor` (Overlap: 0) nor above the best face so far (Collide) cannot change the answer and is
///      pruned (Tracer::kPruneWalked; without it, a variant the benchmark measures, every face is walked to).
///   3. Collide: a vectorised search (FirstFaceAbove) jumps to the next face that can change the answer, and the
///      witness moves to each support found, which bounds the next faces more tightly.
///   4. Overlap keeps one witness, and the faces above 0 for it are those that see it: one run of consecutive
///      faces, found from the wedge of ref's fan that holds the witness (WedgeOf, O(log n)); none when it lies
///      inside ref, and then the polygons overlap (FaceQuery::witnessInside).
///   5. Only the faces left, near the contact, are walked to (ClimbFrom the last support), each recorded as in the
///      textbook loop (RecordFace): a separation > 0 stops the query. O(n + m) in the worst case; on pairs
///      apart or barely touching, a pass walks to a few faces near the contact instead of all n.
///   6. Second pass only: a face of ref exactly anti-parallel to a face of inc repeats the test the first pass made
///      from that face, and is skipped: inc's support edge is then exactly perpendicular to the direction.
/// kUnit selects unit normals (Collide) or raw edge normals (Overlap), as in ScanFaces.
template <bool kUnit, typename S, typename Tracer>
FaceQuery<S> WalkFaces(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, S floor,
                       Tracer& tracer)
{
    const int n = ref.Count();
    FaceQuery<S> query;
    // The first face, towards inc's centroid, with inc's support point found by bisection. That support
    // point is the witness: a point of inc, so FaceDistance(ref, i, witness) bounds face i's separation from above.
    const Vec2T<S> towards = inc.centroid - ref.Centroid();
    const int top = BisectSupport(ref, towards);
    const int start = ClimbFaceTowards(ref, inc.centroid, top);
    int support = BisectSupport(inc.polygon, InvRotate(inc.xf.q, -ref.Normal(start)));
    Vec2T<S> witness = TransformPoint(inc.xf, inc.polygon.Vertices()[support]);
    const auto faceAt = [start, n](int k) { return start + k < n ? start + k : start + k - n; };
    query.face = start;
    const Vec2T<S> firstNormal = kUnit ? ref.Normal(start) : RightPerp(ref.Edge(start));
    query.witness = support;
    const S firstSeparation = Dot(firstNormal, witness - ref.Vertices()[start]);
    query.witnessInside = firstSeparation <= S(0);
    if (RecordFace<kUnit, false>(query, inc, side, start, firstNormal, firstSeparation, support, tracer))
    {
        return query;
    }
    // Walks inc's support point on to face i and records the face; true when the query stops there. Collide then
    // takes that support point as the witness: it bounds the next faces more tightly than the first one, as the
    // support turns with the faces. (Overlap keeps one witness, whose bounds decide containment.)
    const auto walkTo = [&](int i) {
        const Vec2T<S> normal = kUnit ? ref.Normal(i) : RightPerp(ref.Edge(i));
        const Vec2T<S> d = InvRotate(inc.xf.q, -normal);
        support = Tracer::kPruneWalked ? ClimbFrom(inc.polygon, d, support) : WalkToSupport(inc.polygon, d, support);
        if (Tracer::kSkipParallel && second && Dot(d, inc.polygon.Edge(support)) == S(0))
        {
            if constexpr (Tracer::kEnabled)
            {
                tracer.SkippedFace(i, support);
            }
            return false;
        }
        const Vec2T<S> point = TransformPoint(inc.xf, inc.polygon.Vertices()[support]);
        if (RecordFace<kUnit, false>(query, inc, side, i, normal, Dot(normal, point - ref.Vertices()[i]), support,
                                     tracer))
        {
            return true;
        }
        if constexpr (kUnit)
        {
            witness = point;
        }
        return false;
    };
    // Traced: records face i as pruned by the witness (its support point is found for the view only).
    const auto tracePruned = [&](int i) {
        if constexpr (Tracer::kEnabled)
        {
            const Vec2T<S> normal = ref.Normal(i);
            tracer.PrunedFace(side, i, normal, FaceDistance(ref, i, witness),
                              ClimbFrom(inc.polygon, InvRotate(inc.xf.q, -normal), support));
        }
    };
    if constexpr (!kUnit && Tracer::kPruneWalked)
    {
        // Overlap: only the faces that see the witness (witness outside their line) can separate, and they form
        // one run of consecutive faces. The wedge of ref that holds the witness decides in O(log n) whether there
        // are any: its face sees the witness iff the witness lies outside ref. The run then grows from that face.
        const int wedge = WedgeOf(ref, witness, start);
        const int kWedge = wedge >= start ? wedge - start : wedge - start + n;
        const S wedgeDistance = FaceDistance(ref, wedge, witness);
        const bool seen = wedgeDistance > S(0);
        if (!seen || kWedge != 0)
        {
            // The faces tested: k in [first, last] (none when the witness lies inside).
            int first = 1;
            int last = 0;
            if (seen)
            {
                first = kWedge;
                last = kWedge;
                while (first > 1 && FaceDistance(ref, faceAt(first - 1), witness) > S(0))
                {
                    --first;
                }
                while (last < n - 1 && FaceDistance(ref, faceAt(last + 1), witness) > S(0))
                {
                    ++last;
                }
            }
            query.witnessInside = query.witnessInside && wedgeDistance <= S(0);
            // Traced: every face in order, those outside the run recorded as pruned.
            const int begin = Tracer::kEnabled ? 1 : first;
            const int end = Tracer::kEnabled ? n - 1 : last;
            for (int k = begin; k <= end; ++k)
            {
                if (k < first || k > last)
                {
                    tracePruned(faceAt(k));
                }
                else if (walkTo(faceAt(k)))
                {
                    break;
                }
            }
            return query;
        }
        // The wedge's face is the first face, which did not see the witness by its own test: rounding disagrees
        // about a witness on that face's line. The scan below settles it.
    }
    for (int k = 1; k < n; ++k)
    {
        if constexpr (Tracer::kPruneWalked)
        {
            // Only a face whose bound is above the floor and the best face so far can change the answer: jump to
            // the next one (in face order, from `start` round to start - 1).
            const S threshold = std::max(floor, query.separation);
            const int from = faceAt(k);
            const int to = from < start ? start : n;
            const int next = FirstFaceAbove(ref, witness, threshold, from, to);
            const int jump = k + (next - from);
            for (int j = k; Tracer::kEnabled && j < jump; ++j)
            {
                tracePruned(faceAt(j));
            }
            k = jump;
            if (next == to)
            {
                if (to == n)
                {
                    // Continue with face 0 on the next turn of the loop.
                    --k;
                    continue;
                }
                break;
            }
        }
        const int i = faceAt(k);
        // Pruned faces have the witness below a threshold that is at most 0 (the queries stop at a separation
        // above 0, and the floor is 0 or less), so this decides whether it lies inside every face.
        query.witnessInside = query.witnessInside && FaceDistance(ref, i, witness) <= S(0);
        if (walkTo(i))
        {
            break;
        }
    }
    return query;
}

} // namespace satviz::detail
