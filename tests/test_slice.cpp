// SPDX-License-Identifier: MIT
// Slicing: convex polygons by a line, simple polygons along a segment; the parts keep the area.

#include "support/random_concave.h"

#include <satviz/decompose.h>
#include <satviz/slice.h>

#include <catch2/catch.hpp>

using namespace satviz;
using namespace satviz::testing;

namespace
{

std::vector<Vec2> Corners(const Polygon& polygon)
{
    return {polygon.Vertices().begin(), polygon.Vertices().end()};
}

const std::vector<Vec2> kComb{{0, 0}, {9, 0}, {9, 4}, {8, 4}, {8, 1}, {7, 1}, {7, 4}, {6, 4}, {6, 1}, {5, 1},
                              {5, 4}, {4, 4}, {4, 1}, {3, 1}, {3, 4}, {2, 4}, {2, 1}, {1, 1}, {1, 4}, {0, 4}};

long double TotalArea(const std::vector<std::vector<Vec2>>& parts)
{
    long double sum = 0;
    for (const auto& part : parts)
    {
        sum += Area2(part);
    }
    return sum;
}

} // namespace

TEST_CASE("A convex polygon cut by a line gives two convex parts, one each side, with its area", "[slice]")
{
    Rng rng(41);
    int cuts = 0;
    for (int trial = 0; trial < 5000; ++trial)
    {
        const Polygon polygon = RandomPolygon(rng, rng.Int(3, 20), rng.LogUniform(-2, 2), rng.Uniform(0.1, 1.0));
        const double scale = std::abs(polygon.Vertices()[0].x) + std::abs(polygon.Vertices()[0].y);
        const Vec2 point{rng.Uniform(-scale, scale), rng.Uniform(-scale, scale)};
        const double angle = rng.Uniform(0, 2 * kPi);
        const Vec2 direction{std::cos(angle), std::sin(angle)};
        const ConvexSlice slice = SliceConvex(polygon, point, direction);
        // Oracle: the line cuts when vertices lie strictly on both sides.
        bool leftSide = false;
        bool rightSide = false;
        for (const Vec2& v : polygon.Vertices())
        {
            const double s = Cross(direction, v - point);
            leftSide |= s > 1e-9 * scale;
            rightSide |= s < -1e-9 * scale;
        }
        INFO("trial " << trial);
        if (!(leftSide && rightSide))
        {
            CHECK(!slice.cut);
            continue;
        }
        if (!slice.cut)
        {
            continue; // a sliver within rounding of a vertex: the polygon stays whole
        }
        ++cuts;
        const std::vector<Vec2> l = Corners(slice.left);
        const std::vector<Vec2> r = Corners(slice.right);
        const long double area = Area2(Corners(polygon));
        CHECK(std::abs(static_cast<double>((Area2(l) + Area2(r) - area) / area)) <= 1e-12);
        for (const Vec2& v : l)
        {
            CHECK(Cross(direction, v - point) >= -1e-12 * scale);
        }
        for (const Vec2& v : r)
        {
            CHECK(Cross(direction, v - point) <= 1e-12 * scale);
        }
    }
    CHECK(cuts > 1000);
    // Parts below the least area are no cut.
    const Polygon square = MakeBox(1.0, 1.0).polygon;
    CHECK(SliceConvex(square, Vec2{0, 0.99}, Vec2{1, 0}).cut);
    CHECK(!SliceConvex(square, Vec2{0, 0.99}, Vec2{1, 0}, 0.03).cut);
    CHECK(SliceConvex(square, Vec2{0, 0.99}, Vec2{1, 0}, 0.01).cut);
}

TEST_CASE("A comb cut along a segment across its teeth", "[slice]")
{
    const long double area = Area2(kComb);
    // Across all five teeth: five tops and the rest.
    const auto all = SliceAlongSegment(kComb, Vec2{-1, 2}, Vec2{10, 2});
    CHECK(all.size() == 6);
    CHECK(std::abs(static_cast<double>(TotalArea(all) - area)) <= 1e-12);
    for (const auto& part : all)
    {
        CHECK(Decompose(part, DecomposeMethod::Fast).Ok());
    }
    // Ending inside the third tooth: two teeth cut, the third slit, which is no cut.
    const auto two = SliceAlongSegment(kComb, Vec2{-1, 2}, Vec2{4.5, 2});
    CHECK(two.size() == 3);
    CHECK(std::abs(static_cast<double>(TotalArea(two) - area)) <= 1e-12);
    // Missing the comb: the outline itself.
    CHECK(SliceAlongSegment(kComb, Vec2{-1, 5}, Vec2{10, 5}).size() == 1);
    // Along an edge and through two vertices of an L: its foot and its upright.
    const std::vector<Vec2> ell{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
    const auto ellParts = SliceAlongSegment(ell, Vec2{-1, 1}, Vec2{5, 1});
    REQUIRE(ellParts.size() == 2);
    CHECK(std::abs(static_cast<double>(Area2(ellParts[0]))) + std::abs(static_cast<double>(Area2(ellParts[1]))) ==
          Approx(14.0));
    // Slivers below the least area are dropped.
    CHECK(SliceAlongSegment(kComb, Vec2{-1, 3.999}, Vec2{10, 3.999}, 0.01).size() == 1);
}

TEST_CASE("Random simple polygons cut along random segments keep their area in simple parts", "[slice]")
{
    Rng rng(43);
    int split = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const std::vector<Vec2> outline = trial % 2 == 0 ? RandomStarPolygon(rng, rng.Int(4, 30), 1.0, 0.2)
                                                         : RandomUntangledPolygon(rng, rng.Int(4, 20), 2.0);
        const Vec2 a{rng.Uniform(-2, 2), rng.Uniform(-2, 2)};
        const Vec2 b{rng.Uniform(-2, 2), rng.Uniform(-2, 2)};
        const auto parts = SliceAlongSegment(outline, a, b);
        INFO("trial " << trial);
        REQUIRE(!parts.empty());
        split += parts.size() > 1;
        const long double area = std::abs(Area2(outline));
        CHECK(std::abs(static_cast<double>((TotalArea(parts) - area) / area)) <= 1e-12);
        for (const auto& part : parts)
        {
            CHECK(Area2(part) > 0);
            CHECK(Decompose(part, DecomposeMethod::Fast).Ok());
        }
    }
    CHECK(split > 500);
}
