// SPDX-License-Identifier: MIT
// satviz: slicing polygons.
//
// OUTLINE
//   Convex: Sutherland-Hodgman clipping against the two half-planes of the line (Foley, van Dam et al., Computer
//   Graphics, 3.14.1); MakePolygon with repair drops the crossing points that fall on a vertex.
//   Along a segment: the line's crossings with the outline, sorted along the line, bound intervals that alternate
//   between outside and inside; each inside interval lying within the segment is a chord from outline to outline.
//   The chords' ends are put into the outline as vertices, and the outline is split along each chord in turn, in
//   whichever part holds both its ends and its midpoint (chords on one line never cross, so each splits one part
//   in two).

#include <satviz/slice.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz
{
namespace
{

template <typename S>
S Area2(const std::vector<Vec2T<S>>& p)
{
    return SignedArea2(p);
}

template <typename S>
bool Inside(const std::vector<Vec2T<S>>& outline, Vec2T<S> p)
{
    bool inside = false;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
    {
        const Vec2T<S>& u = outline[i];
        const Vec2T<S>& v = outline[j];
        if ((u.y > p.y) != (v.y > p.y) && p.x < (v.x - u.x) * (p.y - u.y) / (v.y - u.y) + u.x)
        {
            inside = !inside;
        }
    }
    return inside;
}

// One side of a convex polygon: the vertices with side * Cross(direction, v - point) >= 0, and the crossings.
template <typename S>
std::vector<Vec2T<S>> ClipSide(const PolygonT<S>& polygon, Vec2T<S> point, Vec2T<S> direction, S side)
{
    std::vector<Vec2T<S>> out;
    const int n = polygon.Count();
    for (int i = 0; i < n; ++i)
    {
        const Vec2T<S> p = polygon.Vertices()[i];
        const Vec2T<S> q = polygon.Vertices()[(i + 1) % n];
        const S dp = side * Cross(direction, p - point);
        const S dq = side * Cross(direction, q - point);
        if (dp >= S(0))
        {
            out.push_back(p);
        }
        if ((dp > S(0) && dq < S(0)) || (dp < S(0) && dq > S(0)))
        {
            out.push_back(p + (dp / (dp - dq)) * (q - p));
        }
    }
    return out;
}

} // namespace

template <typename S>
ConvexSliceT<S> SliceConvex(const PolygonT<S>& polygon, Vec2T<S> point, Vec2T<S> direction, S minArea)
{
    ConvexSliceT<S> result;
    const std::vector<Vec2T<S>> left = ClipSide(polygon, point, direction, S(1));
    const std::vector<Vec2T<S>> right = ClipSide(polygon, point, direction, S(-1));
    if (left.size() < 3 || right.size() < 3 || Area2(left) <= S(2) * minArea || Area2(right) <= S(2) * minArea)
    {
        return result;
    }
    PolygonOptions repair;
    repair.repair = true;
    PolygonResultT<S> l = MakePolygon(left, repair);
    PolygonResultT<S> r = MakePolygon(right, repair);
    if (!l.Ok() || !r.Ok())
    {
        return result;
    }
    result.cut = true;
    result.left = std::move(l.polygon);
    result.right = std::move(r.polygon);
    return result;
}

template <typename S>
std::vector<std::vector<Vec2T<S>>> SliceAlongSegment(const std::vector<Vec2T<S>>& outline, Vec2T<S> a, Vec2T<S> b,
                                                     S minArea)
{
    std::vector<Vec2T<S>> ring = outline;
    if (Area2(ring) < S(0))
    {
        std::reverse(ring.begin(), ring.end());
    }
    const Vec2T<S> d = b - a;
    const int n = static_cast<int>(ring.size());
    if (n < 3 || LengthSquared(d) == S(0))
    {
        return {ring};
    }
    // Crossings of the line with the outline: (parameter along the line, edge, point). A vertex on the line is a
    // crossing at the vertex itself (edge -1 - vertex).
    struct Crossing
    {
        S t;
        int where; // >= 0: on edge `where`, strictly inside it; < 0: at vertex -1 - where
        Vec2T<S> point;
    };
    std::vector<Crossing> crossings;
    auto side = [&](Vec2T<S> p) { return Cross(d, p - a); };
    for (int i = 0; i < n; ++i)
    {
        const Vec2T<S> p = ring[i];
        const Vec2T<S> q = ring[(i + 1) % n];
        const S sp = side(p);
        const S sq = side(q);
        if (sp == S(0))
        {
            crossings.push_back({Dot(p - a, d) / Dot(d, d), -1 - i, p});
        }
        if ((sp > S(0) && sq < S(0)) || (sp < S(0) && sq > S(0)))
        {
            const Vec2T<S> x = p + (sp / (sp - sq)) * (q - p);
            crossings.push_back({Dot(x - a, d) / Dot(d, d), i, x});
        }
    }
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& u, const Crossing& v) { return u.t < v.t; });
    // Chords: consecutive crossings with the interior between them, within the segment.
    std::vector<std::pair<Crossing, Crossing>> chords;
    for (size_t k = 0; k + 1 < crossings.size(); ++k)
    {
        const Crossing& u = crossings[k];
        const Crossing& v = crossings[k + 1];
        if (u.t < S(0) || v.t > S(1) || !(u.t < v.t))
        {
            continue;
        }
        if (Inside(ring, a + ((u.t + v.t) / S(2)) * d))
        {
            chords.push_back({u, v});
        }
    }
    if (chords.empty())
    {
        return {ring};
    }
    // The outline with the chords' ends put in: each point gets an id, its index in `points`.
    std::vector<Vec2T<S>> points = ring;
    std::vector<std::vector<int>> onEdge(static_cast<size_t>(n));
    auto idOf = [&](const Crossing& c) {
        if (c.where < 0)
        {
            return -1 - c.where;
        }
        for (int id : onEdge[c.where])
        {
            if (points[id] == c.point)
            {
                return id;
            }
        }
        points.push_back(c.point);
        onEdge[c.where].push_back(static_cast<int>(points.size()) - 1);
        return static_cast<int>(points.size()) - 1;
    };
    std::vector<std::pair<int, int>> chordIds;
    for (const auto& [u, v] : chords)
    {
        chordIds.push_back({idOf(u), idOf(v)});
    }
    std::vector<int> first;
    for (int i = 0; i < n; ++i)
    {
        first.push_back(i);
        std::vector<int> extra = onEdge[i];
        const Vec2T<S> start = ring[i];
        std::sort(extra.begin(), extra.end(),
                  [&](int u, int v) { return LengthSquared(points[u] - start) < LengthSquared(points[v] - start); });
        first.insert(first.end(), extra.begin(), extra.end());
    }
    std::vector<std::vector<int>> parts{first};
    for (const auto& [u, v] : chordIds)
    {
        const Vec2T<S> mid = S(0.5) * (points[u] + points[v]);
        for (size_t p = 0; p < parts.size(); ++p)
        {
            std::vector<int>& part = parts[p];
            const auto iu = std::find(part.begin(), part.end(), u);
            const auto iv = std::find(part.begin(), part.end(), v);
            if (iu == part.end() || iv == part.end())
            {
                continue;
            }
            std::vector<Vec2T<S>> shape;
            for (int id : part)
            {
                shape.push_back(points[id]);
            }
            if (!Inside(shape, mid))
            {
                continue;
            }
            const int m = static_cast<int>(part.size());
            const int pu = static_cast<int>(iu - part.begin());
            const int pv = static_cast<int>(iv - part.begin());
            if ((pu + 1) % m == pv || (pv + 1) % m == pu)
            {
                break; // the chord is an edge of this part already
            }
            std::vector<int> one;
            std::vector<int> two;
            for (int k = pu;; k = (k + 1) % m)
            {
                one.push_back(part[k]);
                if (k == pv)
                {
                    break;
                }
            }
            for (int k = pv;; k = (k + 1) % m)
            {
                two.push_back(part[k]);
                if (k == pu)
                {
                    break;
                }
            }
            part = std::move(one);
            parts.push_back(std::move(two));
            break;
        }
    }
    std::vector<std::vector<Vec2T<S>>> result;
    for (const std::vector<int>& part : parts)
    {
        std::vector<Vec2T<S>> shape;
        for (int id : part)
        {
            shape.push_back(points[id]);
        }
        if (Area2(shape) > S(2) * minArea)
        {
            result.push_back(std::move(shape));
        }
    }
    return result;
}

template ConvexSliceT<double> SliceConvex(const PolygonT<double>&, Vec2T<double>, Vec2T<double>, double);
template ConvexSliceT<float> SliceConvex(const PolygonT<float>&, Vec2T<float>, Vec2T<float>, float);
template std::vector<std::vector<Vec2T<double>>> SliceAlongSegment(const std::vector<Vec2T<double>>&, Vec2T<double>,
                                                                   Vec2T<double>, double);
template std::vector<std::vector<Vec2T<float>>> SliceAlongSegment(const std::vector<Vec2T<float>>&, Vec2T<float>,
                                                                  Vec2T<float>, float);

} // namespace satviz
