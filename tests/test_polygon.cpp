// SPDX-License-Identifier: MIT
// Polygon validation, repair, convex hulls and constructors.

#include "support/random_shapes.h"

#include <satviz/polygon.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace satviz;
using namespace satviz::testing;

namespace
{

PolygonError ErrorOf(std::vector<Vec2> points, int* vertex = nullptr)
{
    const PolygonResult result = MakePolygon(points);
    if (vertex != nullptr)
    {
        *vertex = result.vertex;
    }
    return result.error;
}

} // namespace

TEST_CASE("A valid convex polygon gets edges and unit outward normals", "[polygon]")
{
    const PolygonResult result = MakePolygon<double>({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
    REQUIRE(result.Ok());
    const Polygon& p = result.polygon;
    REQUIRE(p.Count() == 4);
    CHECK(p.Edge(0) == Vec2{2, 0});
    CHECK(p.Edge(3) == Vec2{0, -1});
    CHECK(p.Normal(0) == Vec2{0, -1});
    CHECK(p.Normal(1) == Vec2{1, 0});
    CHECK(p.Normal(2) == Vec2{0, 1});
    CHECK(p.Normal(3) == Vec2{-1, 0});
}

TEST_CASE("Invalid outlines are reported with the offending vertex", "[polygon]")
{
    int vertex = -2;
    CHECK(ErrorOf({{0, 0}, {1, 0}}) == PolygonError::TooFewVertices);
    CHECK(ErrorOf({}) == PolygonError::TooFewVertices);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(ErrorOf({{0, 0}, {1, nan}, {0, 1}}, &vertex) == PolygonError::NotFinite);
    CHECK(vertex == 1);
    CHECK(ErrorOf({{0, 0}, {1, 0}, {inf, 1}}, &vertex) == PolygonError::NotFinite);
    CHECK(vertex == 2);
    CHECK(ErrorOf({{0, 0}, {1e13, 0}, {0, 1}}, &vertex) == PolygonError::TooLarge);
    CHECK(vertex == 1);
    CHECK(ErrorOf({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, &vertex) == PolygonError::DuplicateVertex);
    CHECK(vertex == 2);
    CHECK(ErrorOf({{0, 0}, {1, 0}, {2, 0}, {0, 1}}, &vertex) == PolygonError::CollinearVertex);
    CHECK(vertex == 1);
    CHECK(ErrorOf({{0, 0}, {0, 1}, {1, 1}, {1, 0}}) == PolygonError::Clockwise);
    CHECK(ErrorOf({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}, &vertex) == PolygonError::NotConvex);
    CHECK(vertex == 2);
    // A pentagram turns left at every vertex but winds around twice.
    std::vector<Vec2> star;
    for (int i = 0; i < 5; ++i)
    {
        const double angle = 2.0 * kPi * (2 * i) / 5.0;
        star.push_back({std::cos(angle), std::sin(angle)});
    }
    CHECK(ErrorOf(star) == PolygonError::SelfIntersecting);
    CHECK(DescribePolygonError(PolygonError::NotConvex, 3) ==
          "polygon is not convex at vertex 3 (use a convex decomposition)");
}

TEST_CASE("Repair drops duplicates and collinear points and fixes the winding", "[polygon]")
{
    PolygonOptions repair;
    repair.repair = true;
    const PolygonResult result =
        MakePolygon<double>({{0, 0}, {0, 1}, {0, 1}, {1, 1}, {1, 0.5}, {1, 0}, {0, 0}}, repair);
    REQUIRE(result.Ok());
    CHECK(result.polygon.Count() == 4);
    const Polygon& p = result.polygon;
    CHECK(SignedArea2(std::vector<Vec2>(p.Vertices().begin(), p.Vertices().end())) == 2.0);
    // Non-convex stays an error.
    CHECK(MakePolygon<double>({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}, repair).error == PolygonError::NotConvex);
}

TEST_CASE("Convex hull of random point clouds", "[polygon][hull]")
{
    Rng rng(7);
    for (int trial = 0; trial < 2000; ++trial)
    {
        const int n = rng.Int(3, 200);
        std::vector<Vec2> points;
        for (int i = 0; i < n; ++i)
        {
            // Integer grid points give exact duplicates and collinear runs.
            if (rng.Chance(0.5))
            {
                points.push_back({double(rng.Int(-5, 5)), double(rng.Int(-5, 5))});
            }
            else
            {
                points.push_back({rng.Uniform(-5, 5), rng.Uniform(-5, 5)});
            }
        }
        const PolygonResult hull = ComputeHull(points);
        if (!hull.Ok())
        {
            CHECK(hull.error == PolygonError::TooFewVertices);
            continue;
        }
        const Vec2Span<double>& h = hull.polygon.Vertices();
        const size_t m = h.size();
        INFO("trial " << trial);
        // Every point lies inside or on the hull, and every hull vertex is an input point.
        for (const Vec2& p : points)
        {
            for (size_t i = 0; i < m; ++i)
            {
                REQUIRE(Cross(h[(i + 1) % m] - h[i], p - h[i]) >= -1e-12);
            }
        }
        for (const Vec2& v : h)
        {
            REQUIRE(std::find(points.begin(), points.end(), v) != points.end());
        }
    }
    CHECK(ComputeHull<double>({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).error == PolygonError::TooFewVertices);
}

TEST_CASE("Regular polygons up to 4096 vertices, in double and float", "[polygon]")
{
    for (int n : {3, 8, 1024, 4096})
    {
        INFO(n << " sides");
        CHECK(MakeRegularPolygon(n, 1.0).Ok());
        CHECK(MakeRegularPolygon(n, 1.0f).Ok());
    }
    CHECK(MakeRegularPolygon(2, 1.0).error == PolygonError::TooFewVertices);
    const PolygonResultT<float> box = MakeBox(1.0f, 2.0f);
    REQUIRE(box.Ok());
    CHECK(box.polygon.Normal(1) == Vec2f{1.0f, 0.0f});
}
