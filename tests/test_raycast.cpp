// SPDX-License-Identifier: MIT
// Segment casts against a quadruple-precision oracle: clipping in world space with __float128 for polygons, the
// quadratic in __float128 for circles.
#include "support/random_shapes.h"
#include "support/reference.h"
#include "support/reference_ray.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace satviz;
using namespace satviz::testing;

namespace
{

double Scale(const Polygon& polygon)
{
    return Radius(polygon);
}

} // namespace

TEST_CASE("RayCast against polygons agrees with a quad-precision clipping on 100 000 random segments", "[raycast]")
{
    Rng rng(909);
    int hits = 0;
    int inside = 0;
    double worst = 0.0;
    for (int i = 0; i < 100000; ++i)
    {
        const int n = rng.Chance(0.9) ? rng.Int(3, 12) : rng.Int(13, 200);
        const Polygon polygon =
            RandomPolygon(rng, n, rng.Uniform(0.3, 2.0), rng.Chance(0.1) ? 0.01 : rng.Uniform(0.3, 1.0));
        const double offset = rng.Chance(0.2) ? rng.LogUniform(3.0, 8.0) : 0.0;
        const Transform xf =
            MakeTransform(Vec2{offset + rng.Uniform(-1, 1), -offset + rng.Uniform(-1, 1)}, rng.Uniform(-kPi, kPi));
        const double angle = rng.Uniform(0.0, 2.0 * kPi);
        const double from = rng.Uniform(0.0, 5.0);
        const Vec2 p1 = xf.p + Vec2{from * std::cos(angle), from * std::sin(angle)};
        const Vec2 aim = xf.p + Vec2{rng.Uniform(-2.5, 2.5), rng.Uniform(-2.5, 2.5)};
        const Vec2 p2 = p1 + rng.Uniform(0.2, 2.0) * (aim - p1);
        const RayHit got = RayCast(polygon, xf, p1, p2);
        const ReferenceRay ref = ReferencePolygonRay(polygon, xf, p1, p2);
        const double scale = Scale(polygon);
        if (static_cast<double>(ref.margin) <= 1e-12 * (scale + Length(p2 - p1)))
        {
            continue; // grazing, ending on the surface or starting on it: either answer
        }
        INFO("segment " << i);
        REQUIRE(got.hit == ref.hit);
        REQUIRE(got.startsInside == ref.inside);
        if (got.hit && !got.startsInside)
        {
            const double error = std::abs(got.fraction - static_cast<double>(ref.enter));
            worst = std::max(worst, error * Length(p2 - p1) / scale);
            CHECK(error * Length(p2 - p1) <= 1e-12 * scale);
            // The point lies on the face hit, whose normal points against the segment.
            CHECK(Dot(got.normal, p2 - p1) < 0.0);
            CHECK(std::abs(Length(got.normal) - 1.0) < 1e-14);
            ++hits;
        }
        inside += got.startsInside ? 1 : 0;
    }
    INFO(hits << " hits, " << inside << " starting inside, worst fraction error " << worst << " of the size");
    CHECK(hits > 20000);
    CHECK(inside > 1000);
    CHECK(worst <= 1e-13);
}

TEST_CASE("RayCast against polygons above 32 vertices, whose crossing faces are found by bisection, agrees with the "
          "quad-precision clipping",
          "[raycast][properties]")
{
    Rng rng(1717);
    int hits = 0;
    int inside = 0;
    int misses = 0;
    // 40 segments for each of 100 polygons.
    for (int i = 0; i < 4000; ++i)
    {
        static Polygon polygon;
        static Transform xf;
        if (i % 40 == 0)
        {
            polygon = RandomPolygon(rng, rng.Int(33, 1500), rng.Uniform(0.3, 2.0),
                                    rng.Chance(0.1) ? 0.01 : rng.Uniform(0.3, 1.0));
            const double offset = rng.Chance(0.2) ? rng.LogUniform(3.0, 8.0) : 0.0;
            xf = MakeTransform(Vec2{offset + rng.Uniform(-1, 1), -offset + rng.Uniform(-1, 1)}, rng.Uniform(-kPi, kPi));
        }
        const int n = polygon.Count();
        // From near or far (bullets), aimed at or past the polygon, short and long.
        const double angle = rng.Uniform(0.0, 2.0 * kPi);
        const double from = rng.Chance(0.2) ? rng.LogUniform(1.0, 4.0) : rng.Uniform(0.0, 5.0);
        const Vec2 p1 = xf.p + Vec2{from * std::cos(angle), from * std::sin(angle)};
        const Vec2 aim = xf.p + Vec2{rng.Uniform(-2.5, 2.5), rng.Uniform(-2.5, 2.5)};
        const Vec2 p2 = p1 + rng.Uniform(0.2, 2.0) * (aim - p1);
        const RayHit got = RayCast(polygon, xf, p1, p2);
        const ReferenceRay ref = ReferencePolygonRay(polygon, xf, p1, p2);
        const double scale = Scale(polygon) + Length(p1 - xf.p);
        if (static_cast<double>(ref.margin) <= 1e-12 * (scale + Length(p2 - p1)))
        {
            continue;
        }
        INFO("segment " << i << ", " << n << " vertices");
        REQUIRE(got.hit == ref.hit);
        REQUIRE(got.startsInside == ref.inside);
        if (got.hit && !got.startsInside)
        {
            REQUIRE(std::abs(got.fraction - static_cast<double>(ref.enter)) * Length(p2 - p1) <= 1e-12 * scale);
            // The point lies on the edge reported (up to the rounding of world coordinates), whose normal points
            // against the segment.
            REQUIRE(got.edge >= 0);
            REQUIRE(got.edge < n);
            const Vec2 v1 = TransformPoint(xf, polygon.Vertices()[got.edge]);
            const Vec2 v2 = TransformPoint(xf, polygon.Vertices()[(got.edge + 1) % n]);
            REQUIRE(std::abs(Cross(Normalize(v2 - v1), got.point - v1)) <= 1e-12 * (scale + Length(xf.p)));
            REQUIRE(Dot(got.normal, p2 - p1) < 0.0);
            ++hits;
        }
        inside += got.startsInside ? 1 : 0;
        misses += got.hit ? 0 : 1;
    }
    CHECK(hits > 800);
    CHECK(inside > 200);
    CHECK(misses > 800);
}

TEST_CASE("RayCast against circles agrees with the quad-precision quadratic", "[raycast]")
{
    Rng rng(910);
    int hits = 0;
    for (int i = 0; i < 50000; ++i)
    {
        const Circle circle{{rng.Uniform(-0.3, 0.3), rng.Uniform(-0.3, 0.3)}, rng.Uniform(0.1, 2.0)};
        const Transform xf = MakeTransform(Vec2{rng.Uniform(-3, 3), rng.Uniform(-3, 3)}, rng.Uniform(-kPi, kPi));
        const Vec2 p1{rng.Uniform(-6, 6), rng.Uniform(-6, 6)};
        const Vec2 p2 = p1 + rng.Uniform(0.2, 2.0) * (xf.p + Vec2{rng.Uniform(-2, 2), rng.Uniform(-2, 2)} - p1);
        const RayHit got = RayCast(circle, xf, p1, p2);
        const QVec c = QTransform(xf, circle.center);
        const QVec m{Quad(p1.x) - c.x, Quad(p1.y) - c.y};
        const QVec d{Quad(p2.x) - Quad(p1.x), Quad(p2.y) - Quad(p1.y)};
        const Quad a = QDot(d, d);
        const Quad b = QDot(m, d);
        const Quad cc = QDot(m, m) - Quad(circle.radius) * Quad(circle.radius);
        const Quad disc = b * b - a * cc;
        const bool inside = cc <= 0;
        const Quad t = disc >= 0 ? (-b - sqrtq(disc)) / a : Quad(2);
        const bool hit = inside || (disc >= 0 && b < 0 && t <= 1);
        const double margin = std::min({std::abs(static_cast<double>(cc)), std::abs(static_cast<double>(disc)),
                                        std::abs(static_cast<double>(1 - t))});
        if (margin < 1e-10)
        {
            continue;
        }
        INFO("segment " << i);
        REQUIRE(got.hit == hit);
        REQUIRE(got.startsInside == inside);
        if (hit && !inside)
        {
            CHECK(std::abs(got.fraction - static_cast<double>(t)) <= 1e-13);
            CHECK(std::abs(Length(got.point - ConvertVec<double>(
                                                  Vec2T<double>{static_cast<double>(c.x), static_cast<double>(c.y)})) -
                           circle.radius) <= 1e-12 * (1.0 + circle.radius));
            ++hits;
        }
    }
    CHECK(hits > 5000);
}

TEST_CASE("RayCast edge cases: parallel, grazing, too short, zero length, NaN", "[raycast]")
{
    const Polygon box = MakeBox(1.0, 1.0).polygon; // [-1, 1]^2
    const Transform at{{0.0, 0.0}, {1.0, 0.0}};
    // Straight in from the left: enters the left face at x = -1.
    RayHit hit = RayCast(box, at, Vec2{-3.0, 0.5}, Vec2{1.0, 0.5});
    REQUIRE(hit.hit);
    CHECK(hit.fraction == 0.5);
    CHECK(hit.point == Vec2{-1.0, 0.5});
    CHECK(hit.normal == Vec2{-1.0, 0.0});
    // Parallel to the top face, above it: miss. Along the top face: touching counts.
    CHECK(!RayCast(box, at, Vec2{-3.0, 1.5}, Vec2{3.0, 1.5}).hit);
    CHECK(RayCast(box, at, Vec2{-3.0, 1.0}, Vec2{3.0, 1.0}).hit);
    // Stops short of the box.
    CHECK(!RayCast(box, at, Vec2{-3.0, 0.0}, Vec2{-1.5, 0.0}).hit);
    // Starts inside.
    hit = RayCast(box, at, Vec2{0.0, 0.0}, Vec2{5.0, 0.0});
    CHECK(hit.hit);
    CHECK(hit.startsInside);
    CHECK(hit.fraction == 0.0);
    // Zero length outside, and NaN: no hit, no crash.
    CHECK(!RayCast(box, at, Vec2{3.0, 3.0}, Vec2{3.0, 3.0}).hit);
    CHECK(!RayCast(box, at, Vec2{std::nan(""), 0.0}, Vec2{1.0, 0.0}).hit);
    // A bullet 1e8 from the origin hits a 1e-3 wall at the exact fraction.
    const Polygon wall = MakeBox(0.0005, 1.0).polygon;
    const Transform far{{1e8, 1e8}, {1.0, 0.0}};
    hit = RayCast(wall, far, Vec2{1e8 - 1000.0, 1e8}, Vec2{1e8 + 1000.0, 1e8});
    REQUIRE(hit.hit);
    CHECK(std::abs(hit.fraction - (1000.0 - 0.0005) / 2000.0) < 1e-15);
    // Circles: from outside, from inside, missing.
    const Circle ball{{0.0, 0.0}, 1.0};
    hit = RayCast(ball, at, Vec2{-3.0, 0.0}, Vec2{1.0, 0.0});
    REQUIRE(hit.hit);
    CHECK(hit.fraction == 0.5);
    CHECK(hit.normal == Vec2{-1.0, 0.0});
    CHECK(RayCast(ball, at, Vec2{0.5, 0.0}, Vec2{3.0, 0.0}).startsInside);
    CHECK(!RayCast(ball, at, Vec2{-3.0, 1.5}, Vec2{3.0, 1.5}).hit);
    CHECK(!RayCast(ball, at, Vec2{3.0, 0.0}, Vec2{5.0, 0.0}).hit); // pointing away
}
