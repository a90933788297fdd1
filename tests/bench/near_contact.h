// SPDX-License-Identifier: MIT
// Near-contact pairs: what a narrowphase receives once a broadphase has culled the pairs whose bounds are apart.
// Each pair is placed along a random direction at a known distance from touching, found by bisection with the
// textbook separation below (plain loops over world vertices, no code of the library under test), so the pool does
// not lean towards any one axis or query order.
#pragma once

#include "support/random_shapes.h"

#include <satviz/sat.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace satviz::bench
{

/// The largest separation of two convex outlines in world space over the unit face normals of both (the textbook
/// SAT): > 0 apart, <= 0 overlapping or touching. Both outlines counter-clockwise.
inline double TextbookSeparation(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    double largest = -std::numeric_limits<double>::infinity();
    for (int pass = 0; pass < 2; ++pass)
    {
        const std::vector<Vec2>& ref = pass == 0 ? a : b;
        const std::vector<Vec2>& other = pass == 0 ? b : a;
        for (size_t i = 0; i < ref.size(); ++i)
        {
            const Vec2 normal = Normalize(RightPerp(ref[(i + 1) % ref.size()] - ref[i]));
            double lowest = std::numeric_limits<double>::infinity();
            for (const Vec2& v : other)
            {
                lowest = std::min(lowest, Dot(normal, v - ref[i]));
            }
            largest = std::max(largest, lowest);
        }
    }
    return largest;
}

/// The outline of a polygon placed by `xf`, moved by `offset`.
inline std::vector<Vec2> PlacedOutline(const Polygon& polygon, const Transform& xf, Vec2 offset = {})
{
    std::vector<Vec2> out;
    for (const Vec2& v : polygon.Vertices())
    {
        out.push_back(TransformPoint(xf, v) + offset);
    }
    return out;
}

/// A random convex n-gon on an ellipse (as the other pools draw them) with its body origin at its vertex average.
inline Polygon CenteredPolygon(testing::Rng& rng, int n)
{
    for (;;)
    {
        const Polygon drawn = testing::RandomPolygon(rng, n, rng.Uniform(0.5, 1.5), rng.Uniform(0.35, 1.0));
        Vec2 average{};
        for (const Vec2& v : drawn.Vertices())
        {
            average = average + v;
        }
        average = (1.0 / n) * average;
        std::vector<Vec2> points;
        for (const Vec2& v : drawn.Vertices())
        {
            points.push_back(v - average);
        }
        PolygonResult result = MakePolygon(points);
        if (result.Ok())
        {
            return result.polygon;
        }
    }
}

/// Two random n-gons at random angles, B placed from A along a random direction u: at the distance t* along u where
/// they touch (bisection of TextbookSeparation, starting with both origins together, where they overlap), then
/// moved along u by a signed distance: into A by up to half the smaller width along u (Overlap), within 1e-9 either
/// way (Touch), or away by up to that half width (Separated), uniformly. Every separated pair is so within half a
/// polygon width of contact, where the bounds of both still overlap.
inline testing::RandomPair NearContactPair(testing::Rng& rng, int n, testing::PairCategory category)
{
    testing::RandomPair pair;
    const Polygon a = CenteredPolygon(rng, n);
    const Polygon b = CenteredPolygon(rng, n);
    pair.xfA =
        MakeTransform(Vec2{rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)}, rng.Uniform(-testing::kPi, testing::kPi));
    pair.xfB = MakeTransform(pair.xfA.p, rng.Uniform(-testing::kPi, testing::kPi));
    const double direction = rng.Uniform(0.0, 2.0 * testing::kPi);
    const Vec2 u{std::cos(direction), std::sin(direction)};

    const std::vector<Vec2> outlineA = PlacedOutline(a, pair.xfA);
    const std::vector<Vec2> outlineB = PlacedOutline(b, pair.xfB);
    const auto extent = [u](const std::vector<Vec2>& outline) {
        double lo = std::numeric_limits<double>::infinity();
        double hi = -lo;
        for (const Vec2& v : outline)
        {
            lo = std::min(lo, Dot(u, v));
            hi = std::max(hi, Dot(u, v));
        }
        return hi - lo;
    };
    const double halfWidth = 0.5 * std::min(extent(outlineA), extent(outlineB));

    double lo = 0.0;                                               // overlapping: both origins at one point inside both
    double hi = 0.5 * (extent(outlineA) + extent(outlineB)) + 1.0; // apart
    while (hi - lo > 1e-13 * std::max(1.0, hi))
    {
        const double mid = 0.5 * (lo + hi);
        if (TextbookSeparation(outlineA, PlacedOutline(b, pair.xfB, mid * u)) > 0.0)
        {
            hi = mid;
        }
        else
        {
            lo = mid;
        }
    }
    const double touching = 0.5 * (lo + hi);
    double offset = 0.0;
    switch (category)
    {
    case testing::PairCategory::Overlap:
        offset = -std::min(touching, halfWidth) * rng.Uniform(1e-6, 1.0);
        break;
    case testing::PairCategory::Touch:
        offset = rng.Uniform(-1e-9, 1e-9);
        break;
    case testing::PairCategory::Separated:
        offset = halfWidth * rng.Uniform(1e-6, 1.0);
        break;
    }
    pair.a = MakeShape(a);
    pair.b = MakeShape(b);
    pair.xfB.p = pair.xfA.p + (touching + offset) * u;
    return pair;
}

} // namespace satviz::bench
