// SPDX-License-Identifier: MIT
// satviz: convex decomposition of simple polygons.
//
// OUTLINE
//   1. Check the coordinates, drop repeated consecutive vertices.
//   2. Check that the outline is simple: every pair of edges that do not share a vertex must not meet, and two
//      edges that share one must not fold back onto each other. The edges are sorted by their smallest x, and an
//      edge is tested against the edges that start before it ends in x: O(n log n) plus the pairs whose x ranges
//      overlap, O(n^2) at worst; it cannot hang.
//   3. Drop the vertices on the line through their neighbours (the turn test of MakePolygon, so that every piece
//      built from the rest passes MakePolygon), and orient the outline counter-clockwise.
//   4. Fast: ear clipping (Meisters' two-ears theorem; O(n^2) as in Eberly, "Triangulation by Ear Clipping"): a
//      convex vertex whose triangle with its neighbours holds no reflex vertex, not even on its border, is cut off;
//      only the two neighbours of a cut vertex change their status. Then Hertel-Mehlhorn (J. O'Rourke,
//      Computational Geometry in C, 2.5): remove each diagonal in turn when both its ends stay convex in the
//      merged piece; the result has at most four times the fewest pieces.
//   5. Fewest: a dynamic programme over the sub-polygons cut off by diagonals. Let Q(i, j), i < j, be the polygon
//      of vertices i, i+1, ..., j closed by the diagonal (or edge) from j to i. In any decomposition of Q(i, j) one
//      piece holds the edge j-i; its corners are a chain i = v0 < v1 < ... < vm = j of vertices joined by diagonals
//      or edges, turning left at every corner, and the pockets Q(vt, vt+1) it leaves are decomposed on their own.
//      So best(i, j) = 1 + min over such chains of the sum of best(vt, vt+1), with best(i, i+1) = 0; the chain's
//      minimum is itself a shortest path over pairs (previous corner, corner), because a corner's turn depends on
//      its two neighbours. The whole polygon is Q(0, n-1). It is exact among decompositions whose corners are the
//      polygon's vertices (Keil's problem without Steiner points; J. M. Keil, "Decomposing a polygon into simpler
//      components", SIAM J. Comput. 14, 1985, solves it in O(n^3 log n) by keeping only the narrowest chains;
//      the plain programme here, in decompose_fewest.cpp, is O(n^5) and kept to small outlines).

#include "decompose_fewest.h"
#include "decompose_predicates.h"

#include <satviz/decompose.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>

namespace satviz
{
namespace
{

using namespace decompose_detail;

template <typename S>
DecompositionT<S> Fail(DecomposeError error, int a, int b = -1)
{
    DecompositionT<S> result;
    result.error = error;
    result.edgeA = a;
    result.edgeB = b;
    return result;
}


// The first pair of edges (lowest first edge, then lowest second) of the closed outline that meet, other than at
// the vertex two consecutive edges share; {-1, -1} when the outline is simple. Indices are positions in `ring`.
template <typename S>
std::pair<int, int> FindCrossing(const std::vector<Vec2T<S>>& ring)
{
    const int n = static_cast<int>(ring.size());
    std::pair<int, int> found{-1, -1};
    auto consider = [&found](int a, int b) {
        const std::pair<int, int> pair{std::min(a, b), std::max(a, b)};
        if (found.first < 0 || pair < found)
        {
            found = pair;
        }
    };
    // Consecutive edges meet at their shared vertex; they overlap only when the second folds back along the first.
    for (int i = 0; i < n; ++i)
    {
        const Vec2T<S>& a = ring[i];
        const Vec2T<S>& b = ring[(i + 1) % n];
        const Vec2T<S>& c = ring[(i + 2) % n];
        if (IsStraight(a, b, c) && Dot(b - a, c - b) < S(0))
        {
            consider(i, (i + 1) % n);
        }
    }
    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    auto minX = [&](int e) { return std::min(ring[e].x, ring[(e + 1) % n].x); };
    auto maxX = [&](int e) { return std::max(ring[e].x, ring[(e + 1) % n].x); };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return minX(a) < minX(b); });
    for (int p = 0; p < n; ++p)
    {
        const int e = order[p];
        const S right = maxX(e);
        for (int q = p + 1; q < n && minX(order[q]) <= right; ++q)
        {
            const int f = order[q];
            if (f == (e + 1) % n || e == (f + 1) % n)
            {
                continue;
            }
            if (SegmentsMeet(ring[e], ring[(e + 1) % n], ring[f], ring[(f + 1) % n]))
            {
                consider(e, f);
            }
        }
    }
    return found;
}

// Ear clipping of a counter-clockwise simple polygon without straight vertices: the triangles as index triples.
template <typename S>
std::vector<std::vector<int>> EarClip(const std::vector<Vec2T<S>>& v)
{
    const int n = static_cast<int>(v.size());
    std::vector<std::vector<int>> triangles;
    std::vector<int> prev(static_cast<size_t>(n));
    std::vector<int> next(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
    {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    std::vector<char> alive(static_cast<size_t>(n), 1);
    auto convex = [&](int i) { return TurnsLeft(v[prev[i]], v[i], v[next[i]]); };
    // Reflex (or straight) vertices are the only ones that can lie in an ear's triangle; they never become reflex
    // again once convex, so the list only shrinks.
    std::vector<int> reflex;
    for (int i = 0; i < n; ++i)
    {
        if (!convex(i))
        {
            reflex.push_back(i);
        }
    }
    // strict: a vertex on the triangle's border does not block the ear (the fallback when no ear is found).
    auto isEar = [&](int i, bool strict) {
        if (!convex(i))
        {
            return false;
        }
        const int a = prev[i];
        const int c = next[i];
        // The triangle must also pass MakePolygon at its other two corners.
        if (!TurnsLeft(v[i], v[c], v[a]) || !TurnsLeft(v[c], v[a], v[i]))
        {
            return false;
        }
        for (int r : reflex)
        {
            if (!alive[r] || r == a || r == i || r == c)
            {
                continue;
            }
            const int o1 = Orientation(v[a], v[i], v[r]);
            const int o2 = Orientation(v[i], v[c], v[r]);
            const int o3 = Orientation(v[c], v[a], v[r]);
            if (strict ? (o1 > 0 && o2 > 0 && o3 > 0) : (o1 >= 0 && o2 >= 0 && o3 >= 0))
            {
                return false;
            }
        }
        return true;
    };
    std::vector<char> ear(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
    {
        ear[i] = isEar(i, false);
    }
    int remaining = n;
    int cursor = 0;
    while (remaining > 3)
    {
        // One lap for an ear; if none (rounding on nearly degenerate outlines), a lap with the strict test, then
        // the vertex of least turn is dropped (its sliver's area is below the rounding of the turn test). Each lap
        // removes a vertex, so the loop ends.
        int found = -1;
        for (int k = 0, i = cursor; k < remaining; ++k, i = next[i])
        {
            if (ear[i])
            {
                found = i;
                break;
            }
        }
        bool keepTriangle = true;
        if (found < 0)
        {
            // A reflex vertex clipped away may have freed an ear that is not a neighbour of the clipped vertex.
            for (int k = 0, i = cursor; k < remaining; ++k, i = next[i])
            {
                ear[i] = isEar(i, false);
                if (ear[i] && found < 0)
                {
                    found = i;
                }
            }
        }
        if (found < 0)
        {
            for (int k = 0, i = cursor; k < remaining; ++k, i = next[i])
            {
                if (isEar(i, true))
                {
                    found = i;
                    break;
                }
            }
        }
        if (found < 0)
        {
            S least = std::numeric_limits<S>::infinity();
            for (int k = 0, i = cursor; k < remaining; ++k, i = next[i])
            {
                const Vec2T<S> e1 = v[i] - v[prev[i]];
                const Vec2T<S> e2 = v[next[i]] - v[i];
                const S turn = std::abs(Cross(e1, e2)) / (Length(e1) * Length(e2));
                if (turn < least)
                {
                    least = turn;
                    found = i;
                }
            }
            keepTriangle = TurnsLeft(v[prev[found]], v[found], v[next[found]]) &&
                           TurnsLeft(v[found], v[next[found]], v[prev[found]]) &&
                           TurnsLeft(v[next[found]], v[prev[found]], v[found]);
        }
        const int a = prev[found];
        const int c = next[found];
        if (keepTriangle)
        {
            triangles.push_back({a, found, c});
        }
        alive[found] = 0;
        next[a] = c;
        prev[c] = a;
        --remaining;
        ear[a] = isEar(a, false);
        ear[c] = isEar(c, false);
        cursor = c;
    }
    const int a = cursor;
    const int b = next[a];
    const int c = next[b];
    if (TurnsLeft(v[a], v[b], v[c]) && TurnsLeft(v[b], v[c], v[a]) && TurnsLeft(v[c], v[a], v[b]))
    {
        triangles.push_back({a, b, c});
    }
    return triangles;
}

// Hertel-Mehlhorn: merge pieces across their shared diagonals while both ends of the diagonal stay convex.
template <typename S>
std::vector<std::vector<int>> MergeDiagonals(const std::vector<Vec2T<S>>& v, std::vector<std::vector<int>> pieces)
{
    const int n = static_cast<int>(v.size());
    auto key = [n](int a, int b) { return static_cast<std::int64_t>(std::min(a, b)) * n + std::max(a, b); };
    // Each diagonal, in the order the pieces hold it, with the two pieces on its sides.
    std::unordered_map<std::int64_t, std::pair<int, int>> sides;
    std::vector<std::int64_t> diagonals;
    for (int p = 0; p < static_cast<int>(pieces.size()); ++p)
    {
        const std::vector<int>& piece = pieces[p];
        for (size_t k = 0; k < piece.size(); ++k)
        {
            const int a = piece[k];
            const int b = piece[(k + 1) % piece.size()];
            if (b == (a + 1) % n || a == (b + 1) % n)
            {
                continue;
            }
            auto [it, inserted] = sides.try_emplace(key(a, b), p, -1);
            if (inserted)
            {
                diagonals.push_back(key(a, b));
            }
            else
            {
                it->second.second = p;
            }
        }
    }
    std::vector<int> parent(pieces.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&parent](int p) {
        while (parent[p] != p)
        {
            p = parent[p] = parent[parent[p]];
        }
        return p;
    };
    for (std::int64_t d : diagonals)
    {
        const auto [first, second] = sides[d];
        if (second < 0)
        {
            continue;
        }
        const int p = root(first);
        const int q = root(second);
        if (p == q)
        {
            continue;
        }
        const int lo = static_cast<int>(d / n);
        const int hi = static_cast<int>(d % n);
        std::vector<int>& P = pieces[p];
        std::vector<int>& Q = pieces[q];
        // In P the diagonal runs x -> y (counter-clockwise), in Q y -> x.
        const int np = static_cast<int>(P.size());
        const int nq = static_cast<int>(Q.size());
        int k = 0;
        while (k < np && !((P[k] == lo && P[(k + 1) % np] == hi) || (P[k] == hi && P[(k + 1) % np] == lo)))
        {
            ++k;
        }
        if (k == np)
        {
            continue;
        }
        const int x = P[k];
        const int y = P[(k + 1) % np];
        int m = 0;
        while (m < nq && !(Q[m] == y && Q[(m + 1) % nq] == x))
        {
            ++m;
        }
        if (m == nq)
        {
            continue;
        }
        // Corners after merging: at x, P's vertex before x, x, Q's vertex after x; at y, Q's vertex before y, y,
        // P's vertex after y.
        const int pBeforeX = P[(k + np - 1) % np];
        const int pAfterY = P[(k + 2) % np];
        const int qAfterX = Q[(m + 2) % nq];
        const int qBeforeY = Q[(m + nq - 1) % nq];
        if (!TurnsLeft(v[pBeforeX], v[x], v[qAfterX]) || !TurnsLeft(v[qBeforeY], v[y], v[pAfterY]))
        {
            continue;
        }
        std::vector<int> merged;
        merged.reserve(static_cast<size_t>(np + nq - 2));
        for (int t = 0; t < np; ++t)
        {
            merged.push_back(P[(k + 1 + t) % np]); // y ... x
        }
        for (int t = 2; t < nq; ++t)
        {
            merged.push_back(Q[(m + t) % nq]); // after x ... before y
        }
        P = std::move(merged);
        Q.clear();
        parent[q] = p;
    }
    std::vector<std::vector<int>> result;
    for (std::vector<int>& piece : pieces)
    {
        if (!piece.empty())
        {
            result.push_back(std::move(piece));
        }
    }
    return result;
}

} // namespace

template <typename S>
DecompositionT<S> Decompose(const std::vector<Vec2T<S>>& points, DecomposeMethod method)
{
    const int count = static_cast<int>(points.size());
    for (int i = 0; i < count; ++i)
    {
        if (!IsFinite(points[i]))
        {
            return Fail<S>(DecomposeError::NotFinite, i);
        }
        if (std::abs(points[i].x) > S(kMaxCoordinate) || std::abs(points[i].y) > S(kMaxCoordinate))
        {
            return Fail<S>(DecomposeError::TooLarge, i);
        }
    }
    // 1. Repeated consecutive vertices: keep the first of each run (the last vertex may repeat the first).
    std::vector<Vec2T<S>> ring;
    std::vector<int> source;
    for (int i = 0; i < count; ++i)
    {
        if (ring.empty() || !(points[i] == ring.back()))
        {
            ring.push_back(points[i]);
            source.push_back(i);
        }
    }
    while (ring.size() > 1 && ring.back() == ring.front())
    {
        ring.pop_back();
        source.pop_back();
    }
    if (ring.size() < 3)
    {
        return Fail<S>(DecomposeError::TooFewVertices, -1);
    }
    // 2. Simple?
    const std::pair<int, int> crossing = FindCrossing(ring);
    if (crossing.first >= 0)
    {
        return Fail<S>(DecomposeError::SelfIntersecting, source[crossing.first], source[crossing.second]);
    }
    // 3. Straight vertices, orientation.
    bool changed = true;
    while (changed && ring.size() >= 3)
    {
        changed = false;
        const size_t n = ring.size();
        for (size_t i = 0; i < n; ++i)
        {
            if (IsStraight(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]))
            {
                ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
                source.erase(source.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
                break;
            }
        }
    }
    if (ring.size() < 3 || SignedArea2(ring) == S(0))
    {
        return Fail<S>(DecomposeError::ZeroArea, -1);
    }
    if (SignedArea2(ring) < S(0))
    {
        std::reverse(ring.begin(), ring.end());
        std::reverse(source.begin(), source.end());
    }
    // 4, 5.
    std::vector<std::vector<int>> corners = MergeDiagonals(ring, EarClip(ring));
    if (method == DecomposeMethod::Fewest && static_cast<int>(ring.size()) <= kFewestMaxVertices)
    {
        std::vector<std::vector<int>> fewest = Fewest(ring);
        if (!fewest.empty() && fewest.size() <= corners.size())
        {
            corners = std::move(fewest);
        }
    }
    DecompositionT<S> result;
    const int n = static_cast<int>(ring.size());
    for (const std::vector<int>& piece : corners)
    {
        std::vector<Vec2T<S>> outline;
        ConvexPieceT<S> convex;
        for (size_t k = 0; k < piece.size(); ++k)
        {
            const int a = piece[k];
            const int b = piece[(k + 1) % piece.size()];
            outline.push_back(ring[a]);
            convex.source.push_back(source[a]);
            convex.internal.push_back(b != (a + 1) % n);
        }
        PolygonResultT<S> built = MakePolygon(outline);
        if (!built.Ok())
        {
            // The turn tests above are MakePolygon's own, so this is not expected; a piece that still fails is a
            // sliver below the rounding of the turn test, and is left out rather than passed on invalid.
            continue;
        }
        convex.polygon = std::move(built.polygon);
        result.pieces.push_back(std::move(convex));
    }
    return result;
}

template <typename S>
std::string DescribeDecomposeError(const DecompositionT<S>& decomposition, const std::vector<Vec2T<S>>& points)
{
    const int count = static_cast<int>(points.size());
    // The end of edge e: the next input vertex that differs from vertex e.
    auto end = [&](int e) {
        for (int k = 1; k < count; ++k)
        {
            const int i = (e + k) % count;
            if (!(points[i] == points[e]))
            {
                return i;
            }
        }
        return e;
    };
    auto edge = [&](int e) {
        return "edge " + std::to_string(e) + " (vertex " + std::to_string(e) + " to " + std::to_string(end(e)) + ")";
    };
    switch (decomposition.error)
    {
    case DecomposeError::None:
        return "no error";
    case DecomposeError::TooFewVertices:
        return "polygon has fewer than 3 distinct vertices";
    case DecomposeError::NotFinite:
        return "polygon vertex " + std::to_string(decomposition.edgeA) + " is not a finite number";
    case DecomposeError::TooLarge:
        return "polygon vertex " + std::to_string(decomposition.edgeA) + " is farther than 1e12 from the origin";
    case DecomposeError::ZeroArea:
        return "polygon encloses no area (its vertices lie on one line)";
    case DecomposeError::SelfIntersecting:
        return "polygon is not simple: " + edge(decomposition.edgeA) + " meets " + edge(decomposition.edgeB);
    }
    return "unknown error";
}

template DecompositionT<double> Decompose(const std::vector<Vec2T<double>>&, DecomposeMethod);
template DecompositionT<float> Decompose(const std::vector<Vec2T<float>>&, DecomposeMethod);
template std::string DescribeDecomposeError(const DecompositionT<double>&, const std::vector<Vec2T<double>>&);
template std::string DescribeDecomposeError(const DecompositionT<float>&, const std::vector<Vec2T<float>>&);

} // namespace satviz
