// SPDX-License-Identifier: MIT
// satviz (private), chapter 1: support points. The support point of a convex polygon in a direction d is its
// vertex farthest along d; the face query (face_query.h) measures each face's separation from the other polygon's
// support point in the direction opposite the face's normal. Here: stepping round the outline, walking and climbing
// to the support point from a vertex near it, and finding it by bisection on large polygons.
//
// References:
//   C. Ericson, Real-Time Collision Detection (2005), 5.2.1 (separating-axis test).
//   D. Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013 (face queries with support points).
#pragma once

#include <satviz/polygon.h>

namespace satviz::detail
{

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

// The faces (or vertices) of a polygon along a counter-clockwise chain from `from`, by their offset k from it.
struct Chain
{
    int from;
    int n;
    int At(int k) const { return from + k < n ? from + k : from + k - n; }
};

// The first offset in [0, count) at which `past` holds, or `count`: `past` fails up to some offset and holds from
// there on, so bisection finds it.
template <typename Past>
int FirstPast(int count, Past&& past)
{
    int lo = 0;
    int left = count; // offsets from lo still in question
    while (left > 0)
    {
        const int half = left / 2;
        const bool beyond = past(lo + half);
        lo = beyond ? lo : lo + half + 1;
        left = beyond ? half : left - half - 1;
    }
    return lo;
}

// The support vertex of `polygon` in direction `d` (its frame), known to lie on the chain from vertex `lo` to vertex
// `hi` (counter-clockwise, less than half a turn): the first vertex there whose edge no longer climbs along d, by
// bisection, settled by ClimbFrom as in BisectSupport. O(log) of the chain's length.
template <typename S>
int BracketedSupport(const PolygonT<S>& polygon, Vec2T<S> d, int lo, int hi)
{
    const int n = polygon.Count();
    const Chain chain{lo, n};
    const int k =
        FirstPast(hi >= lo ? hi - lo : hi - lo + n, [&](int j) { return !(Dot(d, polygon.Edge(chain.At(j))) > S(0)); });
    return ClimbFrom(polygon, d, chain.At(k));
}

} // namespace satviz::detail
