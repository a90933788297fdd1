// SPDX-License-Identifier: MIT
// Seeded random simple polygons (concave in general), and exact-enough geometry to check their decompositions
// without the library's own predicates.
#pragma once

#include "support/random_shapes.h"

#include <satviz/concave.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace satviz::testing
{

/// Twice the signed area (shoelace), in long double.
inline long double Area2(const std::vector<Vec2>& p)
{
    long double sum = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const Vec2& a = p[i];
        const Vec2& b = p[(i + 1) % p.size()];
        sum += static_cast<long double>(a.x) * b.y - static_cast<long double>(b.x) * a.y;
    }
    return sum;
}

/// Sign of the turn a -> b -> c in long double.
inline int TurnSign(Vec2 a, Vec2 b, Vec2 c)
{
    const long double cross = (static_cast<long double>(b.x) - a.x) * (static_cast<long double>(c.y) - a.y) -
                              (static_cast<long double>(b.y) - a.y) * (static_cast<long double>(c.x) - a.x);
    return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
}

/// The open segments ab and cd cross at one point inside both (general position).
inline bool ProperlyCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
    return TurnSign(a, b, c) * TurnSign(a, b, d) < 0 && TurnSign(c, d, a) * TurnSign(c, d, b) < 0;
}

/// p strictly inside the closed outline (crossing number; p not on the outline).
inline bool InsideOutline(const std::vector<Vec2>& outline, Vec2 p)
{
    bool inside = false;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
    {
        const Vec2& a = outline[i];
        const Vec2& b = outline[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
        {
            inside = !inside;
        }
    }
    return inside;
}

/// Points at jittered increasing angles around the origin (one in each of n equal sectors, so no gap between
/// neighbours reaches half a turn) with random radii in [minRadius, 1] * radius: star-shaped around the origin, so
/// simple; counter-clockwise.
inline std::vector<Vec2> RandomStarPolygon(Rng& rng, int n, double radius, double minRadius)
{
    std::vector<Vec2> points;
    const double start = rng.Uniform(0.0, 2.0 * kPi);
    for (int i = 0; i < n; ++i)
    {
        const double a = start + 2.0 * kPi * (i + rng.Uniform(0.05, 0.95)) / n;
        const double r = radius * rng.Uniform(minRadius, 1.0);
        points.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return points;
}

/// Random points in the unit square untangled by 2-opt moves (reverse the chain between two crossing edges, which
/// shortens the outline, so it ends): simple polygons that are in general not star-shaped. Either orientation.
inline std::vector<Vec2> RandomUntangledPolygon(Rng& rng, int n, double scale)
{
    std::vector<Vec2> p(static_cast<size_t>(n));
    for (Vec2& v : p)
    {
        v = {scale * rng.Uniform(0.0, 1.0), scale * rng.Uniform(0.0, 1.0)};
    }
    bool changed = true;
    while (changed)
    {
        changed = false;
        for (int i = 0; i < n && !changed; ++i)
        {
            for (int j = i + 2; j < n && !changed; ++j)
            {
                if (i == 0 && j == n - 1)
                {
                    continue;
                }
                if (ProperlyCross(p[i], p[i + 1], p[j], p[(j + 1) % n]))
                {
                    std::reverse(p.begin() + i + 1, p.begin() + j + 1);
                    changed = true;
                }
            }
        }
    }
    return p;
}

/// A floor of unit tiles [k, k+1] x [-1, 0], k = 0..count-1, whose shared sides are internal edges.
inline Concave TileFloor(int count)
{
    std::vector<ConvexPiece> pieces;
    for (int k = 0; k < count; ++k)
    {
        ConvexPiece piece;
        piece.polygon =
            MakePolygon(std::vector<Vec2>{{k + 0.0, -1}, {k + 1.0, -1}, {k + 1.0, 0}, {k + 0.0, 0}}).polygon;
        piece.source = {0, 1, 2, 3};
        piece.internal = {false, k + 1 < count, false, k > 0};
        pieces.push_back(piece);
    }
    return MakeConcave(pieces);
}

} // namespace satviz::testing
