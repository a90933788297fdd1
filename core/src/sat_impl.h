// SPDX-License-Identifier: MIT
// satviz (private): the Separating Axis Theorem, written once as templates over the scalar type and a tracer.
//
// References:
//   C. Ericson, Real-Time Collision Detection (2005), 5.2.1 (separating-axis test), 5.2.6 (circle against
//     polygon, Voronoi regions), 5.1.1 (closest point).
//   D. Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013 (face queries with support points,
//     reference face and incident edge, clipping).
//   E. Catto, "Contact Manifolds", GDC 2007 (clipping the incident edge against the reference face's side planes).
#pragma once

#include "sat/cpu_dispatch.h"
#include "sat/face_scan.h"
#include "sat/lanes.h"
#include "sat/lanes2.h"
#include "sat/lanes8.h"
#include "sat/select.h"
#include "sat/tracer.h"

#include <satviz/manifold.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace satviz::detail
{

// ---------------------------------------------------------------------------------------------------------------
// Support points by walking
// ---------------------------------------------------------------------------------------------------------------

/// Index after i on a polygon of n vertices.
inline int Next(int i, int n)
{
    return i + 1 == n ? 0 : i + 1;
}

/// Index before i on a polygon of n vertices.
inline int Prev(int i, int n)
{
    return i == 0 ? n - 1 : i - 1;
}

/// Walks forward from `start` to the support vertex of `polygon` in direction `d` (polygon frame): while edge j
/// climbs along d, step to its end. Valid when the support lies ahead of `start` by less than half a turn, which
/// holds when d rotates counter-clockwise from the direction whose support `start` was. Deciding on the sign of
/// Dot(d, edge) rather than comparing two rounded projections keeps the walk exact up to the edge's own rounding.
/// Stops on the first vertex of a plateau (an edge perpendicular to d).
template <typename S>
int WalkToSupport(const PolygonT<S>& polygon, Vec2T<S> d, int start)
{
    const int n = polygon.Count();
    int j = start;
    for (int steps = 0; steps < n && Dot(d, polygon.Edge(j)) > S(0); ++steps)
    {
        j = Next(j, n);
    }
    return j;
}

/// The support vertex of `polygon` in direction `d` (polygon frame), climbing from `start`: forward while the next
/// vertex is higher, then backward while the previous one is. One maximum on a convex outline, so this finds it;
/// from the previous frame's support it takes a step or two. At most one lap (NaN input stops at once).
template <typename S>
int ClimbFrom(const PolygonT<S>& polygon, Vec2T<S> d, int start)
{
    const int n = polygon.Count();
    int i = start;
    for (int k = 0; k < n && Dot(d, polygon.Edge(i)) > S(0); ++k)
    {
        i = Next(i, n);
    }
    for (int k = 0; k < n && Dot(d, polygon.Edge(Prev(i, n))) < S(0); ++k)
    {
        i = Prev(i, n);
    }
    return i;
}

/// The support vertex of `polygon` in direction `d` (polygon frame) in O(log n) steps, for large polygons whose
/// walk from a fixed vertex would cost O(n).
/// Outline:
///   1. Along a counter-clockwise outline the edges turn counter-clockwise, one full turn in all. An edge climbs
///      along d while it points less than a quarter turn from d; the support vertex starts the first edge that
///      has turned past t = d turned a quarter turn counter-clockwise.
///   2. Measure every edge's turn from edge 0 (half-plane of the cross product, then the cross product within
///      the half): these turns increase with the index, so bisection finds the first edge whose turn is at least
///      t's, or none (the support is vertex 0).
///   3. Settle rounding with ClimbFrom, which decides on the same signs as the walks (Dot(d, edge) > 0): a step
///      or none.
template <typename S>
int BisectSupport(const PolygonT<S>& polygon, Vec2T<S> d)
{
    const int n = polygon.Count();
    const Vec2T<S> e0 = polygon.Edge(0);
    const Vec2T<S> t = LeftPerp(d);
    // Whether u has turned half a turn or more from edge 0.
    const auto pastHalf = [e0](Vec2T<S> u) {
        const S c = Cross(e0, u);
        return c < S(0) || (c == S(0) && Dot(e0, u) < S(0));
    };
    const bool tPastHalf = pastHalf(t);
    int lo = 0;
    int hi = n;
    while (lo < hi)
    {
        const int mid = lo + (hi - lo) / 2;
        const Vec2T<S> e = polygon.Edge(mid);
        const bool ePastHalf = pastHalf(e);
        const bool atOrAfter = ePastHalf != tPastHalf ? ePastHalf : Cross(t, e) >= S(0);
        if (atOrAfter)
        {
            hi = mid;
        }
        else
        {
            lo = mid + 1;
        }
    }
    return ClimbFrom(polygon, d, lo == n ? 0 : lo);
}

// ---------------------------------------------------------------------------------------------------------------
// Face queries
// ---------------------------------------------------------------------------------------------------------------

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

/// Polygons with at most this many vertices are scanned whole for each face instead of walked: for small
/// counts a branch-free scan of a few projections beats the data-dependent branches of the walk.
constexpr int kScanLimit = AlgorithmChoices::kScanLimit;

/// The incident polygon of a face query: the polygon, its transform into the reference frame, and, when it is
/// small enough to scan, its vertices mapped into that frame as a structure of arrays on the stack, followed by
/// vertex 0 again up to the next multiple of 4 entries past the last vertex: scans read whole blocks of 4, and
/// entry `count` closes the outline, so edge j runs from entry j to entry j + 1.
template <typename S>
struct IncidentPolygon
{
    static constexpr int kCapacity = kScanLimit + 4;
    const PolygonT<S>& polygon; ///< the incident polygon
    TransformT<S> xf;           ///< its frame relative to the reference polygon
    bool scan;                  ///< small: mapped below, scanned
    Vec2T<S> centroid;          ///< the polygon's centroid in the reference frame
    int padded = 0; ///< entries a scan reads, a multiple of 4 (entries from the vertex count to this one hold vertex 0)
    alignas(32) S x[kCapacity];
    alignas(32) S y[kCapacity];

    /// `p` with transform `xfInc` against a reference polygon with transform `xfRef`. `scanLimit` (at most
    /// kScanLimit) is the largest vertex count that is scanned. kWide: mapped with the wide vectors (the same bits),
    /// whose stores the wide scans then read whole. The relative transform is computed into the member itself: built
    /// elsewhere and copied in, its scalar stores were read back as pairs, which stalled store forwarding (computed
    /// here, Collide of 8-gons took 0.96 of the time).
    template <bool kWide = false>
    IncidentPolygon(const PolygonT<S>& p, const TransformT<S>& xfRef, const TransformT<S>& xfInc,
                    int scanLimit = kScanLimit, std::bool_constant<kWide> = {})
        : polygon(p), xf(InvMulTransforms(xfRef, xfInc)), scan(p.Count() > 0 && p.Count() <= scanLimit),
          centroid(TransformPoint(xf, p.centroid))
    {
        if (!scan)
        {
            return;
        }
        const int count = polygon.Count();
        padded = (count + 3) & ~3;
        // Four vertices at a time, with the operations of TransformPoint, so the same bits. The last block may read
        // up to three points past the vertices: the polygon's block holds vertex 0 again and the normals there.
        using L = Lanes<S, kWide && std::is_same_v<S, double>>;
        const L c = L::Fill(xf.q.c);
        const L s = L::Fill(xf.q.s);
        const L px = L::Fill(xf.p.x);
        const L py = L::Fill(xf.p.y);
        const auto map = [&](const Vec2T<S>* vertices) {
            for (int j = 0; j < count; j += 4)
            {
                L vx;
                L vy;
                L::LoadPoints(&vertices[j].x, vx, vy);
                ((c * vx - s * vy) + px).Store(x + j);
                ((s * vx + c * vy) + py).Store(y + j);
            }
        };
        if (count <= PolygonT<S>::kInlineVertices)
        {
            map(polygon.InlineBlock());
        }
        else
        {
            map(polygon.vertices.data);
        }
        // Vertex 0 again in the four entries after the last vertex (at most kScanLimit + 3 < kCapacity): those up to
        // `padded`, which the scans read, and one more. A fixed count, so no loop and no branch.
        for (int k = 0; k < 4; ++k)
        {
            x[count + k] = x[0];
            y[count + k] = y[0];
        }
    }

    /// The smallest projection on `normal` (reference frame), scan only.
    S Min(Vec2T<S> normal) const { return MinProjection(x, y, padded, normal.x, normal.y); }

    /// Scan only: the separation of a reference face (outward `normal`, a vertex `v` on it) from this polygon.
    S Separation(Vec2T<S> normal, Vec2T<S> v) const { return Min(normal) - Dot(normal, v); }

    /// The separation of a reference face from this polygon's vertex `support`, its support point.
    S Separation(Vec2T<S> normal, Vec2T<S> v, int support) const
    {
        return Dot(normal, TransformPoint(xf, polygon.vertices[support]) - v);
    }

    /// The first vertex whose projection on `normal` (reference frame) is the smallest: the support point in
    /// direction -normal. kWide: the smallest projection with the wide vectors (the same number).
    template <bool kWide = false>
    int Support(Vec2T<S> normal) const
    {
        if (!scan)
        {
            return BisectSupport(polygon, InvRotate(xf.q, -normal));
        }
        // The smallest projection is known exactly (MinProjection rounds each projection the same way); mark the
        // vertices that reach it and take the first. No chain of dependent comparisons.
        S low;
#if SATVIZ_WIDE
        if constexpr (kWide)
        {
            low = MinProjectionWide(x, y, padded, normal.x, normal.y);
        }
        else
#endif
        {
            low = Min(normal);
        }
        // Padding repeats vertex 0, so a padded entry that reaches the minimum comes after a real one.
        using L = Lanes<S, kWide && std::is_same_v<S, double>>;
        const L nx = L::Fill(normal.x);
        const L ny = L::Fill(normal.y);
        uint32_t hits = 0;
        for (int j = 0; j < padded; j += 4)
        {
            hits |= static_cast<uint32_t>((nx * L::Load(x + j) + ny * L::Load(y + j) == L::Fill(low)).Bits()) << j;
        }
        return hits != 0 ? __builtin_ctz(hits) : 0; // no hit only for NaN input
    }
};

/// The incident edge of a scanned inc against a reference face of unit normal `normal` (reference frame): the edge
/// whose outward normal is most anti-parallel to it, the first on a tie. Along a convex outline the normals turn
/// one way, so the two closest in angle to -normal are those of the edges at the support vertex in direction
/// -normal, and this is the better of those two. One scan of all the normals (in inc's frame, four per step) and
/// no support point first: a shorter chain of dependent steps than finding the support vertex, then comparing.
template <bool kWide = false, typename S>
int ScannedIncidentEdge(const IncidentPolygon<S>& inc, Vec2T<S> normal)
{
    using L = Lanes<S, kWide && std::is_same_v<S, double>>;
    const Vec2T<S> d = InvRotate(inc.xf.q, normal);
    const L dx = L::Fill(d.x);
    const L dy = L::Fill(d.y);
    const int count = inc.polygon.Count();
    const Vec2T<S>* normals = &inc.polygon.Normal(0);
    // Four normals from j as lanes, the last normal repeated past the end (which moves no first minimum).
    const auto dots = [&](int j) {
        L nx;
        L ny;
        if (j + 4 <= count)
        {
            L::LoadPoints(&normals[j].x, nx, ny);
        }
        else
        {
            const int j0 = std::min(j, count - 1);
            const int j1 = std::min(j + 1, count - 1);
            const int j2 = std::min(j + 2, count - 1);
            const int j3 = std::min(j + 3, count - 1);
            nx = L::Set(normals[j0].x, normals[j1].x, normals[j2].x, normals[j3].x);
            ny = L::Set(normals[j0].y, normals[j1].y, normals[j2].y, normals[j3].y);
        }
        return dx * nx + dy * ny;
    };
    uint32_t hits = 0;
    if (count <= 8)
    {
        // Up to eight normals, held in registers: the shortest chain from the face to the edge.
        const L dots0 = dots(0);
        const L dots1 = dots(4);
        const L least = L::Fill(Min(dots0, dots1).MinLane());
        hits = static_cast<uint32_t>((dots0 == least).Bits()) | static_cast<uint32_t>((dots1 == least).Bits()) << 4;
    }
    else
    {
        alignas(32) S stored[IncidentPolygon<S>::kCapacity];
        L low = L::Fill(std::numeric_limits<S>::infinity());
        for (int j = 0; j < count; j += 4)
        {
            const L block = dots(j);
            block.Store(stored + j);
            low = Min(low, block);
        }
        const L least = L::Fill(low.MinLane());
        for (int j = 0; j < count; j += 4)
        {
            hits |= static_cast<uint32_t>((L::Load(stored + j) == least).Bits()) << j;
        }
    }
    return hits != 0 ? __builtin_ctz(hits) : 0; // no hit only for NaN input
}

/// The signed distance of `point` (polygon frame) from the line of face i: Dot(Normal(i), point - v_i), > 0 outside.
template <typename S>
S FaceDistance(const PolygonT<S>& polygon, int i, Vec2T<S> point)
{
    return Dot(polygon.Normal(i), point - polygon.vertices[i]);
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
    const double* vertices = &polygon.vertices[0].x;
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
    const Vec2T<S> r = polygon.vertices[0] - polygon.centroid;
    const Vec2T<S> u = point - polygon.centroid;
    const auto pastHalf = [r](Vec2T<S> v) {
        const S c = Cross(r, v);
        return c < S(0) || (c == S(0) && Dot(r, v) < S(0));
    };
    const bool uPastHalf = pastHalf(u);
    // Whether the ray through v_j turns no farther from r than the point's: true for j = 0 .. wedge, false after.
    const auto noLater = [&](int j) {
        const Vec2T<S> v = polygon.vertices[j] - polygon.centroid;
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

/// The smallest projection of a scanned inc's N padded vertices on four normals at once (nx, ny in lanes): each
/// vertex is projected on all four and the minimum kept per lane, in the order FaceSeparation takes it. Four
/// vertices are loaded at a time and spread across the lanes from registers, which measured 4 to 9% faster for the
/// sweep of 8-gons than a broadcast load per vertex.
template <int N, typename S, typename L>
L ProjectionMinimum(const IncidentPolygon<S>& inc, const L& nx, const L& ny)
{
    L low = L::Fill(S(0));
    for (int j = 0; j < N; j += 4)
    {
        const L xs = L::Load(inc.x + j);
        const L ys = L::Load(inc.y + j);
        const L p0 = nx * xs.template Spread<0>() + ny * ys.template Spread<0>();
        low = j == 0 ? p0 : Min(low, p0);
        low = Min(low, nx * xs.template Spread<1>() + ny * ys.template Spread<1>());
        low = Min(low, nx * xs.template Spread<2>() + ny * ys.template Spread<2>());
        low = Min(low, nx * xs.template Spread<3>() + ny * ys.template Spread<3>());
    }
    return low;
}

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

/// The smallest projection of a scanned inc's N padded vertices on the normals of one or two blocks of faces
/// (kBlocks), per lane: each vertex is loaded once for both blocks, and the minimum is taken in vertex order, with
/// the same products and sums as FaceSeparation, so the same bits.
template <int N, int kBlocks, typename L, typename S>
void LowestProjections(const IncidentPolygon<S>& inc, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0,
                       L& low1)
{
    static_assert(kBlocks == 1 || kBlocks == 2, "one or two blocks");
    for (int j = 0; j < N; ++j)
    {
        const L x = L::Fill(inc.x[j]);
        const L y = L::Fill(inc.y[j]);
        const L projection0 = nx0 * x + ny0 * y;
        low0 = j == 0 ? projection0 : Min(low0, projection0);
        if constexpr (kBlocks == 2)
        {
            const L projection1 = nx1 * x + ny1 * y;
            low1 = j == 0 ? projection1 : Min(low1, projection1);
        }
    }
}

/// The separations of the faces of a small ref (kBlocks blocks of four, 1 or 2: at most 8 faces) from a scanned inc
/// of N padded vertices, per block in lanes, in one pass over inc's vertices: each vertex is loaded once, as lanes,
/// for both blocks, whose normals stay in registers. The same products, sums and minimum as FaceSeparation, so the
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
        LowestProjections<N, kBlocks>(inc, faces0.nx, faces0.ny, faces1.nx, faces1.ny, low0, low1);
        block0 = (low0 - faces0.Offset()) + L::Fill(S(0));
        block1 = kBlocks == 2 ? (low1 - faces1.Offset()) + L::Fill(S(0)) : block0;
    }
};

/// The face query of Collide (unit normals) for a ref of at most 8 faces against a scanned inc of N padded vertices
/// (QueryFacesN, steps 2, 4 and 6): the separations of all of ref's faces from one pass over inc's vertices, as
/// SmallRefSeparations takes them (the same bits), then one branch for all of them. A separating face ends the
/// query at the first such face; otherwise the largest separation is one reduction across the lanes and its first
/// face the first lane equal to it, read from the comparison's bits. ref's normals and vertices are loaded four at
/// a time, whole: a polygon of at most 8 vertices keeps them inline, so the lanes past its last face read its own
/// block and are masked out. A skipped face (anti-parallel to one already tested) and a NaN separation take no
/// part. The recorder replays the faces in order, up to the first separating one, with the same numbers. Against
/// ScanFaceBlocks with a branch per block, Collide of 8-gons took 0.97 of the time (satviz-bench).
template <int N, int kBlocks, typename S, typename Tracer>
FaceQuery<S> SmallRefFaceQuery(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second,
                               Tracer& tracer)
{
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    constexpr S kInfinity = std::numeric_limits<S>::infinity();
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
    LowestProjections<N, kBlocks>(inc, n0x, n0y, n1x, n1y, low0, low1);
    L block0 = (low0 - (n0x * v0x + n0y * v0y)) + L::Fill(S(0));
    L block1 = block0;
    if constexpr (kBlocks == 2)
    {
        block1 = (low1 - (n1x * v1x + n1y * v1y)) + L::Fill(S(0));
    }
    // Faces that take no part: the skipped ones, and the lanes past the last face, which read the polygon's block
    // beyond its vertices and normals.
    const uint64_t hidden = (skip | ~((uint64_t(1) << n) - 1)) & (kBlocks == 2 ? 0xFF : 0xF);
    if (hidden != 0)
    {
        const auto mask = [](uint64_t bits) {
            return L::Set(S(bits & 1), S(bits & 2), S(bits & 4), S(bits & 8)) > L::Fill(S(0));
        };
        block0 = Select(mask(hidden), L::Fill(-kInfinity), block0);
        block1 = kBlocks == 2 ? Select(mask(hidden >> 4), L::Fill(-kInfinity), block1) : block0;
    }
    const int live = (1 << n) - 1; // the faces
    const auto bits = [live](const typename L::Mask& m0, const typename L::Mask& m1) {
        return (m0.Bits() | m1.Bits() << 4) & live;
    };
    const L zero = L::Fill(S(0));
    const int separating = bits(block0 > zero, block1 > zero);
    FaceQuery<S> query;
    query.face = 0;
    int replayed = n; // faces the recorder shows
    if (separating != 0)
    {
        const int i = __builtin_ctz(static_cast<unsigned>(separating));
        query.separated = true;
        query.face = i;
        query.separation = i < 4 ? block0.Get(i) : block1.Get(i - 4);
        replayed = Tracer::kEarlyExit ? i + 1 : n;
    }
    else
    {
        // The largest separation over the faces, NaN ignored (no comparison holds for it), and its first face
        // (none for NaN input: face 0).
        const L low = L::Fill(-kInfinity);
        const L best0 = Select(block0 > low, block0, low);
        const L best = Select(block1 > best0, block1, best0);
        const S largest = best.MaxLane();
        const int hits = bits(block0 == L::Fill(largest), block1 == L::Fill(largest));
        query.separation = largest;
        query.face = hits != 0 ? __builtin_ctz(static_cast<unsigned>(hits)) : 0;
    }
    if constexpr (Tracer::kEnabled)
    {
        for (int i = 0; i < replayed; ++i)
        {
            if ((skip >> i) & 1)
            {
                tracer.SkippedFace(i, -1);
                continue;
            }
            const Vec2T<S> normal = ref.Normal(i);
            const S value = i < 4 ? block0.Get(i) : block1.Get(i - 4);
            tracer.FaceAxis(side, i, normal, value, inc.Support(normal), value > S(0));
        }
    }
    return query;
}

/// The face query of Collide (unit normals) against a scanned inc, four faces of ref at a time in lanes (QueryFacesN,
/// steps 2, 4 and 6). Each vertex of inc is projected on four normals at once, so no minimum is taken across lanes,
/// and a block of four faces costs one branch instead of one per face, whose outcome follows the geometry and would
/// be mispredicted. The last block repeats the last face, which changes no answer. Each lane keeps the largest
/// separation it saw and its first face; the lanes combine into the first face of the largest separation, as a
/// face-by-face loop finds it. A block that holds a separating face ends the query at the first such face. The
/// recorder replays the block's faces in order, up to that face, with the same numbers. A ref of at most 8 faces
/// takes SmallRefFaceQuery instead, and Overlap of small polygons SmallFacesSeparate (raw edge normals).
template <int N, typename S, typename Tracer>
FaceQuery<S> ScanFaceBlocks(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second,
                            Tracer& tracer)
{
    using L = Lanes<S, Tracer::kWide && std::is_same_v<S, double>>;
    constexpr S kInfinity = std::numeric_limits<S>::infinity();
    const int n = ref.Count();
    const uint64_t skip = SecondPassSkips<Tracer::kSkipParallel>(ref, inc, second);
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
            for (int l = 0; l < 4 && i0 + l < n && (l <= stop || !Tracer::kEarlyExit); ++l)
            {
                if ((skipped >> l) & 1)
                {
                    tracer.SkippedFace(i0 + l, -1);
                    continue;
                }
                const Vec2T<S> normal = ref.Normal(i0 + l);
                const S value = separation.Get(l);
                tracer.FaceAxis(side, i0 + l, normal, value, inc.Support(normal), value > S(0));
            }
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
        const FaceBlock<L, S> block(ref, ref.vertices.data, i0);
        if (take(i0, (ProjectionMinimum<N>(inc, block.nx, block.ny) - block.Offset()) + L::Fill(S(0))))
        {
            return query;
        }
    }
    if (!query.separated)
    {
        // The first face of the largest separation: the smallest face index among the lanes that hold it (none
        // for NaN input: face 0). A lane past the last face repeats it and comes after it.
        const S largest = best.MaxLane();
        const S face =
            Select(best == L::Fill(largest), bestBlock + L::Set(S(0), S(1), S(2), S(3)), L::Fill(S(n))).MinLane();
        query.separation = largest;
        query.face = face < S(n) ? static_cast<int>(face) : 0;
    }
    return query;
}

/// Face query of `ref` against `inc` (Gregorius): for each face i of ref, with outward normal n, the separation is
/// the signed distance from the face to inc's support point in direction -n, taken in ref's frame:
///     separation_i = Dot(n, support(inc, -n) - v_i).
/// Outline:
///   1. Start at face 0 (scanned inc), or at a face of ref farther from inc's centroid than its neighbours (walked
///      inc: in O(log n) steps, bisecting for the face whose normal points that way, then climbing; when the
///      centroid is outside ref, that is the farthest face), and go round once.
///   2. Small inc (kScanLimit vertices or fewer): inc's vertices are mapped into ref's frame once; each face takes
///      the smallest projection of all of them, without branches: O(n m) with a tiny constant. Overlap goes a face
///      at a time (polygons of up to 8 vertices: SmallFacesSeparate); Collide four faces at a time in lanes
///      (ScanFaceBlocks; a ref of up to 8 faces: SmallRefFaceQuery).
///   3. Large inc: the support point for the first face by bisection (BisectSupport, O(log m)). That point, the
///      witness, lies in inc, so its distance from a face's line bounds the face's separation from above. A face
///      whose bound is not above `floor` (Overlap: 0) nor above the best face so far (Collide) cannot change the
///      answer and is pruned. Collide: a vectorised search (FirstFaceAbove) jumps to the next face that can, and
///      the witness moves to each support found, which bounds the next faces more tightly. Overlap keeps one
///      witness, and the faces above 0 for it are those that see it: one run of consecutive faces, found from the
///      wedge of ref's fan that holds the witness (WedgeOf, O(log n)); none when it lies inside ref, and then the
///      polygons overlap. Only the faces left, near the contact, are walked to (ClimbFrom the last support).
///      O(n + m) in the worst case; for the random pairs of satviz-bench, a pass over a 1024-gon walks to 1 to 90
///      faces instead of 1024.
///   4. A separation > 0 is a separating axis: stop there (early exit).
///   5. Overlap's scan only, back-face pruning when Tracer::kPrune (off by default): separation_i <=
///      Dot(n, c - v_i) for inc's centroid c, which lies inside inc. When that bound is not above `floor` (Overlap: 0,
///      the face cannot separate) nor above the best face so far (Collide: the face cannot become the reference face),
///      the face is not scanned; in exact arithmetic the answer is the same. It scans fewer faces (3.6 of 10 for
///      Overlap of 8-gons) but its branch is mispredicted so often that Overlap of 3- to 8-gons ran 1.2 to 1.35 times
///      slower with it (satviz-bench, "with pruning").
///   6. Second pass only: a face of ref exactly anti-parallel to a face of inc repeats the test the first pass made
///      from that face, and is skipped (scan: the faces in `skip`; walk: inc's support edge is exactly
///      perpendicular to the direction).
/// kUnit selects unit normals (Collide: separations are distances, the best face is tracked) or raw edge normals
/// (Overlap: only the sign matters, so no square root or division is needed).
/// N is inc's padded vertex count when it is scanned (a multiple of 4), 0 when it is walked; QueryFaces picks it.
/// kInside (scan only) also finds the vertices of inc that lie inside ref (ScanFace), in `inside`.
template <bool kUnit, bool kInside, int N, typename S, typename Tracer>
FaceQuery<S> QueryFacesN(const PolygonT<S>& ref, const IncidentPolygon<S>& inc, int side, bool second, S floor,
                         Tracer& tracer, S* inside)
{
    // A scanned incident polygon starts at face 0, as each face there costs less than a search for a better
    // start; a walked (large) one at the face towards its centroid (below), where separated pairs usually end.
    static_assert(N % 4 == 0 && N <= IncidentPolygon<S>::kCapacity, "scan of a padded count");
    constexpr bool kScan = N > 0;
    if constexpr (kScan && kUnit)
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
    const int n = ref.Count();
    FaceQuery<S> query;

    // Records the separation of face i; true when the query stops there.
    const auto record = [&](int i, Vec2T<S> normal, S separation, int support) {
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
            if (!query.separated)
            {
                query.separation = separation;
                query.face = i;
                query.support = support;
            }
            query.separated = true;
            return Tracer::kEarlyExit;
        }
        return false;
    };

    if constexpr (kScan)
    {
        // The best face so far starts as the first one tested, so that it is a valid index even when no
        // comparison holds (NaN input).
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
            // Back-face pruning: inc's centroid lies inside inc, so its separation bounds the face's from above.
            // A face whose bound cannot beat the floor (Overlap: 0; Collide: the best face so far, which only a
            // strictly larger separation replaces) changes nothing and is not scanned.
            if constexpr (Tracer::kPrune)
            {
                const S bound = Dot(normal, inc.centroid - ref.vertices[i]);
                if (bound <= std::max(floor, query.separation))
                {
                    if constexpr (Tracer::kEnabled)
                    {
                        tracer.PrunedFace(side, i, normal, bound, inc.Support(normal));
                    }
                    continue;
                }
            }
            const S separation =
                FaceSeparation<N, kInside, Tracer::kWide>(inc.x, inc.y, normal, Dot(normal, ref.vertices[i]), inside);
            if (record(i, normal, separation, -1))
            {
                break;
            }
        }
        return query;
    }

    // Walked: the first face, towards inc's centroid, with inc's support point found by bisection. That support
    // point is the witness: a point of inc, so FaceDistance(ref, i, witness) bounds face i's separation from above.
    const Vec2T<S> towards = inc.centroid - ref.centroid;
    const int top = BisectSupport(ref, towards);
    const int start = ClimbFaceTowards(ref, inc.centroid, top);
    int support = BisectSupport(inc.polygon, InvRotate(inc.xf.q, -ref.Normal(start)));
    Vec2T<S> witness = TransformPoint(inc.xf, inc.polygon.vertices[support]);
    const auto faceAt = [start, n](int k) { return start + k < n ? start + k : start + k - n; };
    query.face = start;
    const Vec2T<S> firstNormal = kUnit ? ref.Normal(start) : RightPerp(ref.Edge(start));
    query.witness = support;
    const S firstSeparation = Dot(firstNormal, witness - ref.vertices[start]);
    query.witnessInside = firstSeparation <= S(0);
    if (record(start, firstNormal, firstSeparation, support))
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
        const Vec2T<S> point = TransformPoint(inc.xf, inc.polygon.vertices[support]);
        if (record(i, normal, Dot(normal, point - ref.vertices[i]), support))
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

/// The face query with inc's scan unrolled for its padded vertex count (QueryFacesN). `inside`, with kInside and
/// a scanned inc, receives for each of inc's vertices its largest separation from ref's faces (filled with
/// -infinity by the caller); it is not touched otherwise. A walked inc reports instead whether its witness lies
/// inside ref (FaceQuery::witnessInside).
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
/// FaceSeparation, so the same separations to the bit. A skipped face (second pass: anti-parallel to one of inc's
/// faces, already tested) and the lanes past the last face take no part. The recorder replays the faces in order,
/// up to the first separating one. True when a face separates.
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
    LowestProjections<N, kBlocks>(inc, faces0.nx, faces0.ny, faces1.nx, faces1.ny, low0, low1);
    const L separation0 = (low0 - faces0.offset) + L::Fill(S(0));
    const L separation1 = kBlocks == 2 ? (low1 - faces1.offset) + L::Fill(S(0)) : separation0;
    // Faces that take part, one bit each: the real ones, less the skipped.
    const int live = static_cast<int>(((uint64_t(1) << n) - 1) & ~skip);
    const int separating = (((separation0 > L::Fill(S(0))).Bits() | (separation1 > L::Fill(S(0))).Bits() << 4) & live);
    if constexpr (Tracer::kEnabled)
    {
        const int stop =
            separating != 0 && Tracer::kEarlyExit ? __builtin_ctz(static_cast<unsigned>(separating)) : n - 1;
        for (int i = 0; i <= stop; ++i)
        {
            if ((skip >> i) & 1)
            {
                tracer.SkippedFace(i, -1);
                continue;
            }
            const Vec2T<S> normal = RightPerp(ref.Edge(i));
            const S value = i < 4 ? separation0.Get(i) : separation1.Get(i - 4);
            tracer.FaceAxis(side, i, normal, value, inc.Support(normal), value > S(0));
        }
    }
    return separating != 0;
}

#if SATVIZ_WIDE
/// The vertices of a polygon of at most 8 vertices mapped by `xf` (as IncidentPolygon maps them, the same bits), one
/// per lane, held in registers: lanes past the last vertex hold vertex 0 again.
[[gnu::target("avx512f")]] inline void MapVertices512(const PolygonT<double>& polygon, const TransformT<double>& xf,
                                                      Lanes8& x, Lanes8& y)
{
    Lanes8 vx;
    Lanes8 vy;
    Lanes8::LoadPoints(&polygon.InlineBlock()[0].x, vx, vy);
    const Lanes8 c = Lanes8::Fill(xf.q.c);
    const Lanes8 s = Lanes8::Fill(xf.q.s);
    const int past = 0xFF & ~((1 << polygon.Count()) - 1);
    x = ((c * vx - s * vy) + Lanes8::Fill(xf.p.x)).FillFromFirst(past);
    y = ((s * vx + c * vy) + Lanes8::Fill(xf.p.y)).FillFromFirst(past);
}

/// Whether a face of `ref` (at most 8 faces, raw edge normals, all in one register of eight lanes) separates it from
/// the N vertices of the other polygon, mapped into ref's frame and held in registers (MapVertices512), less the
/// `skip`ped faces. The same products, sums and minimum per face, in the same order, as SmallFacesSeparate, so the
/// same separations to the bit; the vertices come from registers, not from an array on the stack.
template <int N>
[[gnu::target("avx512f")]] bool FacesSeparate512(const PolygonT<double>& ref, const Lanes8& x, const Lanes8& y,
                                                 uint64_t skip)
{
    Lanes8 vx;
    Lanes8 vy;
    Lanes8 wx;
    Lanes8 wy;
    Lanes8::LoadPoints(&ref.InlineBlock()[0].x, vx, vy);
    Lanes8::LoadPoints(&ref.InlineBlock()[1].x, wx, wy);
    const Lanes8 nx = wy - vy;
    const Lanes8 ny = vx - wx;
    const Lanes8 offset = nx * vx + ny * vy;
    Lanes8 low = Lanes8::Fill(0.0);
    for (int j = 0; j < N; ++j)
    {
        const Lanes8 projection = nx * x.Spread(j) + ny * y.Spread(j);
        low = j == 0 ? projection : Min(low, projection);
    }
    const Lanes8 separation = (low - offset) + Lanes8::Fill(0.0);
    const int live = static_cast<int>(((uint64_t(1) << ref.Count()) - 1) & ~skip);
    return (separation.GreaterBits(Lanes8::Fill(0.0)) & live) != 0;
}

/// Overlap of two polygons of at most 8 vertices on AVX-512 (OverlapPolygons, step 0): each polygon's faces in one
/// register against the other polygon's vertices mapped into its frame, held in registers, both decided at once.
[[gnu::target("avx512f")]] inline bool SmallPolygonsOverlap512(const PolygonT<double>& a, const TransformT<double>& xfA,
                                                               const PolygonT<double>& b, const TransformT<double>& xfB,
                                                               bool skipParallel)
{
    const TransformT<double> bInA = InvMulTransforms(xfA, xfB);
    const TransformT<double> aInB = InvMulTransforms(xfB, xfA);
    Lanes8 bx;
    Lanes8 by;
    Lanes8 ax;
    Lanes8 ay;
    MapVertices512(b, bInA, bx, by);
    MapVertices512(a, aInB, ax, ay);
    const uint64_t skip = skipParallel ? AntiParallelFaces(a, b, InvMulRot(aInB.q, RotT<double>{})) : uint64_t(0);
    const bool separatedA = b.Count() <= 4 ? FacesSeparate512<4>(a, bx, by, 0) : FacesSeparate512<8>(a, bx, by, 0);
    const bool separatedB =
        a.Count() <= 4 ? FacesSeparate512<4>(b, ax, ay, skip) : FacesSeparate512<8>(b, ax, ay, skip);
    return !(separatedA | separatedB);
}
#endif

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

// ---------------------------------------------------------------------------------------------------------------
// Polygon against polygon
// ---------------------------------------------------------------------------------------------------------------

/// Overlap of two polygons (Ericson 5.2.1; Gregorius).
/// Outline:
///   0. Both polygons of at most 8 vertices: A's faces against B mapped into A's frame, four faces at a time in
///      lanes (SmallFacesSeparate); a separating face ends the test; otherwise B's faces against A mapped into B's
///      frame, anti-parallel faces skipped. One branch per polygon instead of one per face: on random pairs this
///      took 0.78 of the time of steps 1 to 3 for 8-gons (satviz-bench), vertex shortcut included. With AVX-512
///      (Tracer::kWide512, SmallPolygonsOverlap512) each polygon's faces fit one register and cost so little that
///      both polygons are tested and decided by one branch: the branch between them, mispredicted on about half of
///      the pairs, cost more than B's faces (8-gons without it: 0.87 to 0.94 of the time, on random contact pairs).
///      Larger polygons:
///   1. Face query of A's faces against B mapped into A's frame, stopping at the first separating face. A walked A
///      tests only the run of faces that see the witness (B's support point for A's first face): every other face
///      has the witness on its inner side, so its separation is <= 0. The wedge of A's fan that holds the witness,
///      found by bisection (WedgeOf), tells whether the run is empty and where it is: O(log n) plus the run,
///      instead of a pass over every face.
///   2. A scanned B (kScanLimit vertices or fewer) also yields, per vertex of B, its largest separation from A's
///      faces, from the same projections. A vertex of B whose largest separation is <= 0 lies inside A: the
///      polygons share a point, so they overlap, and B's faces need no test. For polygons above 8 vertices this is
///      the usual way out of an overlapping pair (a corner of B pushed into A). A walked B offers one candidate,
///      the witness: it lies inside A when the run is empty (step 1 found that out anyway).
///   3. Otherwise the face query of B's faces against A, stopping at the first separating face; no separating face
///      on either polygon means overlap.
template <typename S, typename Tracer>
bool OverlapPolygons(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
                     Tracer& tracer)
{
#if SATVIZ_WIDE
    if constexpr (Tracer::kWide512 && !Tracer::kEnabled && !Tracer::kPrune && Tracer::kScanLimit >= 8 &&
                  std::is_same_v<S, double>)
    {
        if (a.Count() > 0 && a.Count() <= 8 && b.Count() > 0 && b.Count() <= 8)
        {
            return SmallPolygonsOverlap512(a, xfA, b, xfB, Tracer::kSkipParallel);
        }
    }
#endif
    const IncidentPolygon<S> incB(b, xfA, xfB, Tracer::kScanLimit, std::bool_constant<Tracer::kWide>{});
    if constexpr (!Tracer::kPrune)
    {
        if (incB.scan && a.Count() <= 8 && b.Count() <= 8)
        {
            bool separated = SmallFacesSeparate(a, incB, 0, false, tracer);
            if (!separated || !Tracer::kEarlyExit)
            {
                const IncidentPolygon<S> incA(a, xfB, xfA, Tracer::kScanLimit, std::bool_constant<Tracer::kWide>{});
                separated = SmallFacesSeparate(b, incA, 1, true, tracer) || separated;
            }
            if constexpr (Tracer::kEnabled)
            {
                ManifoldT<S> result;
                result.overlap = !separated;
                tracer.Finish(separated ? TraceExit::SeparatingAxis : TraceExit::AllAxesOverlap, result);
            }
            return !separated;
        }
    }
    // Pruned faces would leave gaps in the vertices' largest separations, so pruning turns the shortcut off.
    constexpr bool kInside = !Tracer::kPrune;
    alignas(32) S inside[IncidentPolygon<S>::kCapacity];
    if constexpr (kInside)
    {
        std::fill(inside, inside + incB.padded, -std::numeric_limits<S>::infinity());
    }
    const FaceQuery<S> queryA = QueryFaces<false, kInside>(a, incB, 0, false, S(0), tracer, inside);
    bool overlap = !queryA.separated;
    if (kInside && overlap)
    {
        int contained = -1;
        if (incB.scan)
        {
            for (int j = b.Count() - 1; j >= 0; --j)
            {
                contained = Select(inside[j] <= S(0), j, contained);
            }
        }
        else if (queryA.witnessInside)
        {
            // Walked: the witness, B's support point for A's first face, lay on or inside every face of A.
            contained = queryA.witness;
        }
        if (contained >= 0)
        {
            if constexpr (Tracer::kEnabled)
            {
                ManifoldT<S> result;
                result.overlap = true;
                tracer.ContainedVertex(1, contained);
                tracer.Finish(TraceExit::VertexInside, result);
            }
            return true;
        }
    }
    if (overlap || !Tracer::kEarlyExit)
    {
        const IncidentPolygon<S> incA(a, xfB, xfA, Tracer::kScanLimit, std::bool_constant<Tracer::kWide>{});
        overlap = !QueryFaces<false>(b, incA, 1, true, S(0), tracer).separated && overlap;
    }
    if constexpr (Tracer::kEnabled)
    {
        ManifoldT<S> result;
        result.overlap = overlap;
        tracer.Finish(overlap ? TraceExit::AllAxesOverlap : TraceExit::SeparatingAxis, result);
    }
    return overlap;
}

/// Overlap with frame coherence (SatCache): the cached separating face alone first; if it no longer separates,
/// the full query, remembering the face that separates this time (or nothing when the polygons overlap).
///   1. Cached face i of polygon s, raw normal n (only the sign matters): the other polygon's support point in
///      direction -n, climbed from the cached support (ClimbFrom), and its separation Dot(n, w - v_i) in s's
///      frame. Positive: separated, done in O(1) steps when the pair moved a little.
///   2. Otherwise the face queries of A, then B (OverlapPolygons), keeping the separating face they stop at and
///      its support point.
template <typename S>
bool OverlapPolygonsCached(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b,
                           const TransformT<S>& xfB, AxisRef& cached, int& cachedSupport)
{
    if (cached.kind == AxisKind::FaceNormal && (cached.shape == 0 || cached.shape == 1))
    {
        const PolygonT<S>& ref = cached.shape == 0 ? a : b;
        const PolygonT<S>& inc = cached.shape == 0 ? b : a;
        if (cached.index >= 0 && cached.index < ref.Count())
        {
            const TransformT<S> incInRef = cached.shape == 0 ? InvMulTransforms(xfA, xfB) : InvMulTransforms(xfB, xfA);
            const Vec2T<S> normal = RightPerp(ref.Edge(cached.index));
            const int start = cachedSupport >= 0 && cachedSupport < inc.Count() ? cachedSupport : 0;
            const int support = ClimbFrom(inc, InvRotate(incInRef.q, -normal), start);
            const S separation =
                Dot(normal, TransformPoint(incInRef, inc.vertices[support]) - ref.vertices[cached.index]);
            cachedSupport = support;
            if (separation > S(0))
            {
                return false;
            }
        }
    }
    NullTracer tracer;
    const IncidentPolygon<S> incB(b, xfA, xfB);
    FaceQuery<S> query = QueryFaces<false>(a, incB, 0, false, S(0), tracer);
    if (query.separated)
    {
        cached = {AxisKind::FaceNormal, 0, query.face};
        cachedSupport = query.support;
        return false;
    }
    const IncidentPolygon<S> incA(a, xfB, xfA);
    query = QueryFaces<false>(b, incA, 1, true, S(0), tracer);
    if (query.separated)
    {
        cached = {AxisKind::FaceNormal, 1, query.face};
        cachedSupport = query.support;
        return false;
    }
    cached = {};
    cachedSupport = -1;
    return true;
}

/// Contact points from clipping, in the reference polygon's frame, with what the trace shows of the clipping.
/// The arrays are valid up to their counts and left uninitialised beyond: zeroing the whole struct cost a block
/// store (rep stos) per manifold, about a tenth of Collide's time for 8-gons.
template <typename S>
struct ClipResult
{
    ContactPointT<S> contacts[2]; ///< halfway between the kept points and the reference face
    int contactCount = 0;         ///< 1 or 2
    int incidentEdge = -1;        ///< the incident edge
    Vec2T<S> w1, w2;              ///< incident edge, reference frame
    Vec2T<S> clip1[2];            ///< after the side plane through the face's first vertex
    int count1 = 0;               ///< points in clip1
    Vec2T<S> clip2[2];            ///< then after the side plane through its second vertex
    int count2 = 0;               ///< points in clip2
    S separations[2];             ///< of the clip2 points to the reference face
    bool kept[2];                 ///< clip2 points kept as contacts
    bool fallback = false;        ///< no point kept: the deepest incident vertex was used
};

/// Contact points of a reference face (Catto; Gregorius):
///   1. Incident edge: the edge of the incident polygon whose normal is most anti-parallel to the reference normal.
///      One of the two edges at the support vertex against the face: a scanned polygon compares all its normals
///      (ScannedIncidentEdge) and reads the edge's ends from its mapped vertices; a walked one compares the two
///      edges at `support`.
///   2. Clip it against the two side planes of the reference face (Sutherland-Hodgman), without branches.
///   3. Keep the clipped points whose separation from the face is at most `keepBelow` (0 for resting contact; a
///      little more at a time of impact, where touching points carry rounding of either sign). The contact point
///      is halfway between the kept point and the reference face.
///   4. If clipping keeps nothing (a rounding artefact at a vertex-vertex contact), use the deepest vertex: the
///      support vertex, or the deeper end of the incident edge, which is that vertex.
/// `support` is the incident support vertex if known, else -1. `shift`, if given, moves the incident polygon by that
/// much (reference frame) before clipping: a sweep clips at the time of impact with the polygon mapped at t = 0.
template <bool kWide = false, typename S>
ClipResult<S> ClipIncidentEdge(const PolygonT<S>& ref, int face, const IncidentPolygon<S>& inc, int support,
                               S keepBelow, const Vec2T<S>* shift = nullptr)
{
    ClipResult<S> out;
    const int m = inc.polygon.Count();
    const Vec2T<S> v1 = ref.vertices[face];
    const Vec2T<S> v2 = ref.vertices[Next(face, ref.Count())];
    const Vec2T<S> normal = ref.Normal(face);
    const Vec2T<S> tangent = LeftPerp(normal);

    int s = support;
    if (inc.scan && support < 0)
    {
        out.incidentEdge = ScannedIncidentEdge<kWide>(inc, normal);
        out.w1 = {inc.x[out.incidentEdge], inc.y[out.incidentEdge]};
        out.w2 = {inc.x[out.incidentEdge + 1], inc.y[out.incidentEdge + 1]};
    }
    else
    {
        s = support >= 0 ? support : inc.template Support<kWide>(normal);
        const int before = Prev(s, m);
        const S dotLeaving = Dot(normal, Rotate(inc.xf.q, inc.polygon.Normal(s)));
        const S dotEntering = Dot(normal, Rotate(inc.xf.q, inc.polygon.Normal(before)));
        out.incidentEdge = Select(dotEntering < dotLeaving, before, s);
        out.w1 = TransformPoint(inc.xf, inc.polygon.vertices[out.incidentEdge]);
        out.w2 = TransformPoint(inc.xf, inc.polygon.vertices[Next(out.incidentEdge, m)]);
    }
    if (shift != nullptr)
    {
        out.w1 = out.w1 + *shift;
        out.w2 = out.w2 + *shift;
    }
    // Clipping, both ends of the incident edge side by side in two lanes (lane 0: w1, lane 1: w2), so that each step
    // is one operation for both ends and each choice a mask: where an edge lies against the side planes varies from
    // pair to pair, and branches on it were mispredicted often enough to cost more than the clipping itself. An end
    // outside a side plane moves to the plane's crossing when the other end lies strictly inside; an end on a plane
    // stays, and an edge that only touches a plane keeps that one point.
    using P = Lanes2<S>;
    using M = typename P::Mask;
    const P x = P::Set(out.w1.x, out.w2.x);
    const P y = P::Set(out.w1.y, out.w2.y);
    const P zero = P::Fill(S(0));
    // How far each end lies outside side plane 1 (outward -tangent, through v1) and side plane 2 (outward tangent,
    // through v2); > 0 outside.
    const P d1 = P::Fill(-tangent.x) * (x - P::Fill(v1.x)) + P::Fill(-tangent.y) * (y - P::Fill(v1.y));
    const P d2 = P::Fill(tangent.x) * (x - P::Fill(v2.x)) + P::Fill(tangent.y) * (y - P::Fill(v2.y));
    // A plane is crossed strictly when one end lies inside it and the other outside (the same in both lanes).
    const auto crossed = [zero](const P& d) {
        const M below = d < zero;
        const M above = d > zero;
        return (below & above.Swap()) | (above & below.Swap());
    };
    const M cross1 = crossed(d1);
    const M cross2 = crossed(d2);
    const M inside1 = d1 <= zero;
    const M inside2 = d2 <= zero;
    // The crossing, from each end towards the other: at d / (d - d_other) of the way where the plane is crossed
    // strictly (so d - d_other is not 0); elsewhere the divisor is 1, so no infinity or NaN is ever formed, and the
    // number, though computed, is kept only in entries past the counts.
    const P towardX = x.Swap() - x;
    const P towardY = y.Swap() - y;
    const P one = P::Fill(S(1));
    const P t1 = d1 / Select(cross1, d1 - d1.Swap(), one);
    const P t2 = d2 / Select(cross2, d2 - d2.Swap(), one);
    // The first plane alone (the trace's first clip), then both: an end moves when it lies outside either plane
    // (they face opposite ways, so not both), to that plane's crossing.
    const P x1 = Select(inside1, x, x + t1 * towardX);
    const P y1 = Select(inside1, y, y + t1 * towardY);
    const M moves = ~(inside1 & inside2);
    const P t = Select(inside2, t1, t2);
    const P x2 = Select(moves, x + t * towardX, x);
    const P y2 = Select(moves, y + t * towardY, y);
    const M keep1 = inside1 | cross1;
    const M keep2 = keep1 & (inside2 | (cross2 & (d2 < zero).Swap()));
    // Each clipped end's separation from the face, and whether it is kept as a contact.
    const P separation = P::Fill(normal.x) * (x2 - P::Fill(v1.x)) + P::Fill(normal.y) * (y2 - P::Fill(v1.y));
    const int valid = (keep2 & (separation <= P::Fill(keepBelow))).Bits();
    // The contact points, halfway between the kept ends and the face; the first one is the first valid end.
    const P half = P::Fill(S(0.5)) * separation;
    const P cx = x2 - half * P::Fill(normal.x);
    const P cy = y2 - half * P::Fill(normal.y);
    const bool firstEnd = (valid & 1) != 0;
    out.contactCount = (valid & 1) + (valid >> 1);
    out.contacts[0].point = Select(firstEnd, Vec2T<S>{cx.Get(0), cy.Get(0)}, Vec2T<S>{cx.Get(1), cy.Get(1)});
    out.contacts[0].separation = Select(firstEnd, separation.Get(0), separation.Get(1));
    out.contacts[1].point = {cx.Get(1), cy.Get(1)};
    out.contacts[1].separation = separation.Get(1);
    // What the trace shows: the points after each plane, listed from w1's end, and which of the second are kept.
    const int kept1 = keep1.Bits();
    const int kept2 = keep2.Bits();
    out.count1 = (kept1 & 1) + (kept1 >> 1);
    out.clip1[0] = (kept1 & 1) != 0 ? Vec2T<S>{x1.Get(0), y1.Get(0)} : Vec2T<S>{x1.Get(1), y1.Get(1)};
    out.clip1[1] = {x1.Get(1), y1.Get(1)};
    out.count2 = (kept2 & 1) + (kept2 >> 1);
    out.clip2[0] = (kept2 & 1) != 0 ? Vec2T<S>{x2.Get(0), y2.Get(0)} : Vec2T<S>{x2.Get(1), y2.Get(1)};
    out.clip2[1] = {x2.Get(1), y2.Get(1)};
    out.separations[0] = (kept2 & 1) != 0 ? separation.Get(0) : separation.Get(1);
    out.separations[1] = separation.Get(1);
    out.kept[0] = ((kept2 & 1) != 0 ? valid & 1 : valid >> 1) != 0;
    out.kept[1] = (kept2 & 1) != 0 && (valid >> 1) != 0;
    out.fallback = out.contactCount == 0;
    if (out.fallback)
    {
        // The support vertex; for a scanned inc, the deeper end of the incident edge, which is that vertex.
        Vec2T<S> deepest = Dot(normal, out.w2 - out.w1) < S(0) ? out.w2 : out.w1;
        if (s >= 0)
        {
            deepest = TransformPoint(inc.xf, inc.polygon.vertices[s]);
            if (shift != nullptr)
            {
                deepest = deepest + *shift;
            }
        }
        const S separation = Dot(normal, deepest - v1);
        out.contacts[0].point = deepest - (S(0.5) * separation) * normal;
        out.contacts[0].separation = separation;
        out.contactCount = 1;
    }
    return out;
}

/// Contact k of a clipping in world space (`xfRef`: the reference polygon's transform), or zero past the count.
template <typename S>
ContactPointT<S> WorldContact(const ClipResult<S>& clip, int k, const TransformT<S>& xfRef)
{
    const bool real = k < clip.contactCount;
    return {Select(real, TransformPoint(xfRef, clip.contacts[k].point), Vec2T<S>{}),
            Select(real, clip.contacts[k].separation, S(0))};
}

/// The trace's view of a clipping, in world space.
template <typename S>
ClipTraceT<S> ClipTraceOf(const ClipResult<S>& r, const AxisRef& reference, const PolygonT<S>& ref,
                          const TransformT<S>& xfRef, const PolygonT<S>& inc, const TransformT<S>& xfInc,
                          int incidentShape)
{
    ClipTraceT<S> clip;
    clip.reference = reference;
    clip.referenceV1 = TransformPoint(xfRef, ref.vertices[reference.index]);
    clip.referenceV2 = TransformPoint(xfRef, ref.vertices[Next(reference.index, ref.Count())]);
    clip.referenceNormal = Rotate(xfRef.q, ref.Normal(reference.index));
    clip.incidentShape = incidentShape;
    clip.incidentEdge = r.incidentEdge;
    clip.incidentV1 = TransformPoint(xfInc, inc.vertices[r.incidentEdge]);
    clip.incidentV2 = TransformPoint(xfInc, inc.vertices[Next(r.incidentEdge, inc.Count())]);
    clip.sideClip1Count = r.count1;
    clip.sideClip2Count = r.count2;
    for (int k = 0; k < r.count1; ++k)
    {
        clip.sideClip1[k] = TransformPoint(xfRef, r.clip1[k]);
    }
    for (int k = 0; k < r.count2; ++k)
    {
        clip.sideClip2[k] = TransformPoint(xfRef, r.clip2[k]);
        clip.clippedSeparation[k] = r.separations[k];
        clip.kept[k] = r.kept[k];
    }
    clip.usedFallback = r.fallback;
    return clip;
}

/// The manifold of two polygons (Gregorius; Catto).
/// Outline:
///   1. Work in A's frame: B relative to A, so far-away pairs keep their relative precision.
///   2. Face query of A's faces, then of B's faces (in B's frame); stop at the first separating face.
///   3. Reference face: the face of largest separation (least penetration), A's on a tie. Its unit normal is the
///      minimum translation direction and -separation the depth, also when one polygon contains the other.
///   4. Contacts (ClipIncidentEdge): clip the incident edge against the side planes of the reference face and keep
///      the points on or below it.
template <typename S, typename Tracer>
ManifoldT<S> CollidePolygons(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b,
                             const TransformT<S>& xfB, Tracer& tracer)
{
    const IncidentPolygon<S> incB(b, xfA, xfB, kScanLimit, std::bool_constant<Tracer::kWide>{});
    const FaceQuery<S> queryA = QueryFaces<true>(a, incB, 0, false, -std::numeric_limits<S>::infinity(), tracer);
    if (queryA.separated)
    {
        // Every member written once, so the result is not first cleared whole.
        const ManifoldT<S> manifold{false,
                                    S(0),
                                    queryA.separation,
                                    Rotate(xfA.q, a.Normal(queryA.face)),
                                    {},
                                    0,
                                    {AxisKind::FaceNormal, 0, queryA.face},
                                    -1};
        if constexpr (Tracer::kEnabled)
        {
            tracer.Finish(TraceExit::SeparatingAxis, manifold);
        }
        return manifold;
    }
    const IncidentPolygon<S> incA(a, xfB, xfA, kScanLimit, std::bool_constant<Tracer::kWide>{});
    const FaceQuery<S> queryB = QueryFaces<true>(b, incA, 1, true, queryA.separation, tracer);
    if (queryB.separated)
    {
        const ManifoldT<S> manifold{false,
                                    S(0),
                                    queryB.separation,
                                    -Rotate(xfB.q, b.Normal(queryB.face)),
                                    {},
                                    0,
                                    {AxisKind::FaceNormal, 1, queryB.face},
                                    -1};
        if constexpr (Tracer::kEnabled)
        {
            tracer.Finish(TraceExit::SeparatingAxis, manifold);
        }
        return manifold;
    }

    // Reference face: B's only when strictly better, so ties (and skipped duplicates) keep A's face.
    const bool flip = queryB.separation > queryA.separation;
    const PolygonT<S>& ref = SelectRef(flip, b, a);
    const IncidentPolygon<S>& inc = SelectRef(flip, incA, incB);
    const TransformT<S>& xfRef = SelectRef(flip, xfB, xfA);
    const FaceQuery<S>& query = SelectRef(flip, queryB, queryA);

    const ClipResult<S> clip =
        ClipIncidentEdge<Tracer::kWide>(ref, query.face, inc, inc.scan ? -1 : query.support, S(0));
    const Vec2T<S> worldNormal = Rotate(xfRef.q, ref.Normal(query.face));
    const ManifoldT<S> manifold{true,
                                -query.separation,
                                S(0),
                                Select(flip, -worldNormal, worldNormal),
                                {WorldContact(clip, 0, xfRef), WorldContact(clip, 1, xfRef)},
                                clip.contactCount,
                                {AxisKind::FaceNormal, Select(flip, 1, 0), query.face},
                                clip.incidentEdge};

    if constexpr (Tracer::kEnabled)
    {
        tracer.Clip(ClipTraceOf(clip, manifold.axis, ref, xfRef, inc.polygon, flip ? xfA : xfB, flip ? 0 : 1));
        tracer.Finish(TraceExit::AllAxesOverlap, manifold);
    }
    return manifold;
}

// ---------------------------------------------------------------------------------------------------------------
// Polygon against circle
// ---------------------------------------------------------------------------------------------------------------

/// Polygon (side `polySide`) against circle (Ericson 5.2.6 and 5.1.1; the Voronoi regions of the polygon).
/// Outline:
///   1. Work in the polygon's frame: the circle's centre c relative to the polygon.
///   2. For each face: separation s_i = Dot(n_i, c - v_i) - r. s_i > 0 separates: stop (early exit).
///      Keep the face of largest separation.
///   3. If c lies inside the polygon, that face's normal is the axis of least penetration.
///   4. Otherwise c is in the Voronoi region of that face or of one of its two vertices. In a vertex region the
///      axis runs from the vertex to c (the closest point of the polygon is the vertex); in the face region the
///      face normal is the axis.
/// The face tests use the precomputed unit normals: the Voronoi step needs the face of largest true distance,
/// which raw normals would not give. kManifold = false answers only yes or no and compares squared distances, so
/// it takes no square root.
template <bool kManifold, typename S, typename Tracer>
ManifoldT<S> CollidePolygonCircle(const PolygonT<S>& polygon, const TransformT<S>& xfP, const CircleT<S>& circle,
                                  const TransformT<S>& xfC, int polySide, Tracer& tracer)
{
    ManifoldT<S> manifold;
    const S r = circle.radius;
    const Vec2T<S> c = InvRotate(xfP.q, (xfC.p - xfP.p) + Rotate(xfC.q, circle.center));
    // Normals point out of the polygon; the manifold's normal points from A to B.
    const S orient = polySide == 0 ? S(1) : S(-1);
    const int n = polygon.Count();

    S bestSeparation = -std::numeric_limits<S>::infinity(); // Dot(n, c - v) over the faces, before subtracting r
    int bestFace = 0;
    for (int i = 0; i < n; ++i)
    {
        const S s = Dot(polygon.Normal(i), c - polygon.vertices[i]);
        const bool separating = s > r;
        if (s > bestSeparation)
        {
            bestSeparation = s;
            bestFace = i;
        }
        if constexpr (Tracer::kEnabled)
        {
            tracer.FaceAxis(polySide, i, polygon.Normal(i), s - r, -1, separating);
        }
        if (separating)
        {
            if constexpr (kManifold)
            {
                manifold.gap = s - r;
                manifold.normal = orient * Rotate(xfP.q, polygon.Normal(i));
                manifold.axis = {AxisKind::FaceNormal, polySide, i};
            }
            if constexpr (Tracer::kEnabled)
            {
                tracer.Finish(TraceExit::SeparatingAxis, manifold);
            }
            return manifold;
        }
    }

    const Vec2T<S> v1 = polygon.vertices[bestFace];
    const Vec2T<S> v2 = polygon.vertices[Next(bestFace, n)];
    int vertex = -1;
    if (bestSeparation > S(0))
    {
        if (Dot(c - v1, v2 - v1) <= S(0))
        {
            vertex = bestFace;
        }
        else if (Dot(c - v2, v1 - v2) <= S(0))
        {
            vertex = Next(bestFace, n);
        }
    }

    if (vertex >= 0)
    {
        const Vec2T<S> v = polygon.vertices[vertex];
        const Vec2T<S> offset = c - v;
        const S distanceSquared = LengthSquared(offset);
        const bool separating = distanceSquared > r * r;
        if constexpr (Tracer::kEnabled)
        {
            const S distance = std::sqrt(distanceSquared);
            tracer.VertexAxis(polySide, vertex, Rotate(xfP.q, Normalize(offset)), distance - r, separating);
        }
        if constexpr (kManifold)
        {
            const S distance = std::sqrt(distanceSquared);
            // The centre is outside the polygon here, so the distance is positive.
            const Vec2T<S> direction = (S(1) / distance) * offset;
            manifold.normal = orient * Rotate(xfP.q, direction);
            manifold.axis = {AxisKind::VertexToCenter, polySide, vertex};
            if (separating)
            {
                manifold.gap = distance - r;
            }
            else
            {
                manifold.overlap = true;
                manifold.depth = r - distance;
                manifold.contactCount = 1;
                manifold.contacts[0].separation = distance - r;
                manifold.contacts[0].point = TransformPoint(xfP, v + (S(0.5) * (distance - r)) * direction);
            }
        }
        else
        {
            manifold.overlap = !separating;
        }
    }
    else
    {
        manifold.overlap = true;
        if constexpr (kManifold)
        {
            const Vec2T<S> normal = polygon.Normal(bestFace);
            manifold.depth = r - bestSeparation;
            manifold.normal = orient * Rotate(xfP.q, normal);
            manifold.axis = {AxisKind::FaceNormal, polySide, bestFace};
            manifold.contactCount = 1;
            manifold.contacts[0].separation = bestSeparation - r;
            // Halfway between the circle's deepest point c - r n and the face.
            manifold.contacts[0].point = TransformPoint(xfP, c - (S(0.5) * (r + bestSeparation)) * normal);
        }
    }
    if constexpr (Tracer::kEnabled)
    {
        tracer.Finish(manifold.overlap ? TraceExit::AllAxesOverlap : TraceExit::SeparatingAxis, manifold);
    }
    return manifold;
}

// ---------------------------------------------------------------------------------------------------------------
// Circle against circle
// ---------------------------------------------------------------------------------------------------------------

/// Two circles: the only axis is the line through their centres. Concentric circles use the normal (0, 1).
template <bool kManifold, typename S, typename Tracer>
ManifoldT<S> CollideCircles(const CircleT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b,
                            const TransformT<S>& xfB, Tracer& tracer)
{
    ManifoldT<S> manifold;
    const Vec2T<S> ca = Rotate(xfA.q, a.center);
    const Vec2T<S> d = (xfB.p - xfA.p) + Rotate(xfB.q, b.center) - ca;
    const S radii = a.radius + b.radius;
    const S distanceSquared = LengthSquared(d);
    const bool separating = distanceSquared > radii * radii;
    if constexpr (kManifold || Tracer::kEnabled)
    {
        const S distance = std::sqrt(distanceSquared);
        const Vec2T<S> normal = distance > S(0) ? (S(1) / distance) * d : Vec2T<S>{S(0), S(1)};
        if constexpr (kManifold)
        {
            manifold.normal = normal;
            manifold.axis = {AxisKind::CenterToCenter, -1, -1};
            if (separating)
            {
                manifold.gap = distance - radii;
            }
            else
            {
                manifold.depth = radii - distance;
                manifold.contactCount = 1;
                manifold.contacts[0].separation = distance - radii;
                const Vec2T<S> surfaceA = ca + a.radius * normal;
                manifold.contacts[0].point = xfA.p + (surfaceA + (S(0.5) * (distance - radii)) * normal);
            }
        }
        if constexpr (Tracer::kEnabled)
        {
            tracer.CenterAxis(normal, distance - radii, separating);
        }
    }
    manifold.overlap = !separating;
    if constexpr (Tracer::kEnabled)
    {
        tracer.Finish(separating ? TraceExit::SeparatingAxis : TraceExit::AllAxesOverlap, manifold);
    }
    return manifold;
}

} // namespace satviz::detail
