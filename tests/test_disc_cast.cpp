// SPDX-License-Identifier: MIT
// Thick bullets: a disc cast along a segment, against the outline pushed out by the radius worked out here.

#include "support/random_concave.h"

#include <satviz/disc_cast.h>

#include <catch2/catch.hpp>

using namespace satviz;
using namespace satviz::testing;

namespace
{

// Least t in [0, 1] at which the path p1 + t d meets the segment ab, or 2.
double SegmentHit(Vec2 p1, Vec2 d, Vec2 a, Vec2 b)
{
    const Vec2 e = b - a;
    const double denom = Cross(d, e);
    if (denom == 0)
    {
        return 2;
    }
    const double t = Cross(a - p1, e) / denom;
    const double u = Cross(a - p1, d) / denom;
    return t >= 0 && t <= 1 && u >= 0 && u <= 1 ? t : 2;
}

// Least t in [0, 1] at which the path enters the circle (c, r), or 2.
double CircleHit(Vec2 p1, Vec2 d, Vec2 c, double r)
{
    const Vec2 m = p1 - c;
    const double a = Dot(d, d);
    const double b = Dot(m, d);
    const double k = Dot(m, m) - r * r;
    const double disc = b * b - a * k;
    if (disc <= 0)
    {
        return 2;
    }
    const double t = (-b - std::sqrt(disc)) / a;
    return t >= 0 && t <= 1 ? t : 2;
}

double DistanceToPolygon(const std::vector<Vec2>& p, Vec2 q)
{
    if (InsideOutline(p, q))
    {
        return 0;
    }
    double best = 1e300;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const Vec2 a = p[i];
        const Vec2 ab = p[(i + 1) % p.size()] - a;
        const double t = std::clamp(Dot(q - a, ab) / Dot(ab, ab), 0.0, 1.0);
        best = std::min(best, Length(q - (a + t * ab)));
    }
    return best;
}

// The first time the centre reaches the outline pushed out by r: faces moved out along their normals, and a circle
// of radius r around each vertex (counter-clockwise outline).
double RoundedOutlineHit(const std::vector<Vec2>& p, Vec2 p1, Vec2 p2, double r)
{
    const Vec2 d = p2 - p1;
    double best = 2;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const Vec2 a = p[i];
        const Vec2 b = p[(i + 1) % p.size()];
        const Vec2 n = Normalize(RightPerp(b - a));
        best = std::min({best, SegmentHit(p1, d, a + r * n, b + r * n), CircleHit(p1, d, a, r)});
    }
    return best;
}

} // namespace

TEST_CASE("A disc cast at a polygon stops where the outline pushed out by its radius is reached", "[disc]")
{
    Rng rng(31);
    int hits = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const Polygon polygon = RandomPolygon(rng, rng.Int(3, 12), rng.Uniform(0.3, 2.0), rng.Uniform(0.3, 1.0));
        const Transform xf = MakeTransform(Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(0, 2 * kPi));
        std::vector<Vec2> placed;
        for (const Vec2& v : polygon.Vertices())
        {
            placed.push_back(TransformPoint(xf, v));
        }
        const Vec2 p1{rng.Uniform(-5, 5), rng.Uniform(-5, 5)};
        const Vec2 p2{rng.Uniform(-5, 5), rng.Uniform(-5, 5)};
        const double r = rng.LogUniform(-2, 0);
        const DiscHit hit = CastDisc(MakeShape(polygon), xf, p1, p2, r);
        INFO("trial " << trial);
        if (DistanceToPolygon(placed, p1) < r)
        {
            CHECK(hit.startsInside);
            continue;
        }
        const double expected = RoundedOutlineHit(placed, p1, p2, r);
        REQUIRE(hit.hit == (expected <= 1));
        if (expected <= 1)
        {
            ++hits;
            CHECK(hit.fraction == Approx(expected).margin(1e-9));
            // Touching: the centre is the radius from the polygon, the contact point on its outline.
            CHECK(DistanceToPolygon(placed, hit.center) == Approx(r).margin(1e-9));
            CHECK(DistanceToPolygon(placed, hit.point) == Approx(0.0).margin(1e-9));
            CHECK(Length(hit.center - hit.point) == Approx(r));
        }
    }
    CHECK(hits > 300);
}

TEST_CASE("A disc cast at a circle hits the circle grown by its radius", "[disc]")
{
    const Shape circle = MakeShape(Circle{{0.5, 0}, 1.0});
    const DiscHit hit = CastDisc(circle, MakeTransform(Vec2{1, 1}, 0.0), Vec2{-5, 1}, Vec2{5, 1}, 0.5);
    REQUIRE(hit.hit);
    CHECK(hit.center.x == Approx(1.5 - 1.5));
    CHECK(hit.fraction == Approx(5.0 / 10));
    CHECK(hit.normal.x == Approx(-1.0));
    CHECK(hit.point.x == Approx(0.5));
}

TEST_CASE("A disc wider than the gap between a comb's teeth rests on them and a narrower one falls through", "[disc]")
{
    const std::vector<Vec2> comb{{0, 0}, {9, 0}, {9, 4}, {8, 4}, {8, 1}, {7, 1}, {7, 4}, {6, 4}, {6, 1}, {5, 1},
                                 {5, 4}, {4, 4}, {4, 1}, {3, 1}, {3, 4}, {2, 4}, {2, 1}, {1, 1}, {1, 4}, {0, 4}};
    const Concave concave = MakeConcave(Decompose(comb, DecomposeMethod::Fewest).pieces);
    // Radius 0.6 over the gap [1, 2]: it touches both corners (1, 4) and (2, 4) when its centre is 0.6 from them.
    const DiscHit wide = CastDisc(concave, Transform{}, Vec2{1.5, 10}, Vec2{1.5, 0}, 0.6);
    REQUIRE(wide.hit);
    CHECK(wide.center.y == Approx(4 + std::sqrt(0.6 * 0.6 - 0.5 * 0.5)));
    CHECK(wide.piece >= 0);
    // Radius 0.4 fits: it lands on the spine's top, y = 1.
    const DiscHit narrow = CastDisc(concave, Transform{}, Vec2{1.5, 10}, Vec2{1.5, 0}, 0.4);
    REQUIRE(narrow.hit);
    CHECK(narrow.center.y == Approx(1.4));
    CHECK(narrow.normal.y == Approx(1.0));
    // A ray, the disc of radius 0, goes where the narrow disc does.
    const ConcaveRayHit ray = RayCast(concave, Transform{}, Vec2{1.5, 10}, Vec2{1.5, 0});
    CHECK(ray.hit.point.y == Approx(1.0));
}
