// SPDX-License-Identifier: MIT
// The private search helpers of the walked face queries against brute force.

#include "sat/walked_faces.h"
#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/reference.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace satviz;
using namespace satviz::testing;

namespace
{

// The turn of the ray from c through p, measured counter-clockwise from the ray through r, in [0, 2 pi).
long double TurnFrom(Vec2 c, Vec2 r, Vec2 p)
{
    const long double rx = static_cast<long double>(r.x) - c.x;
    const long double ry = static_cast<long double>(r.y) - c.y;
    const long double px = static_cast<long double>(p.x) - c.x;
    const long double py = static_cast<long double>(p.y) - c.y;
    long double turn = std::atan2(rx * py - ry * px, rx * px + ry * py);
    if (turn < 0.0L)
    {
        turn += 2.0L * static_cast<long double>(kPi);
    }
    return turn;
}

} // namespace

TEST_CASE("WedgeOf finds the wedge of the centroid's fan that holds a point, from any start, and so decides "
          "whether the point lies inside",
          "[walk][properties]")
{
    Rng rng(4242);
    int inside = 0;
    int outside = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const int n = rng.Chance(0.5) ? rng.Int(3, 20) : rng.Int(21, 3000);
        const double aspect = rng.Chance(0.1) ? rng.LogUniform(-3.0, -1.0) : rng.Uniform(0.35, 1.0);
        const Polygon polygon = RandomPolygon(rng, n, rng.Uniform(0.1, 10.0), aspect);
        // Points inside and outside, near the outline, at a vertex, and at the centroid.
        const int v = rng.Int(0, n - 1);
        Vec2 p;
        switch (rng.Int(0, 3))
        {
        case 0:
            p = polygon.Centroid() + rng.Uniform(0.0, 2.0) * (polygon.Vertices()[v] - polygon.Centroid());
            break;
        case 1:
            p = polygon.Vertices()[v] + rng.Uniform(-1e-9, 1e-9) * Vec2{rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)};
            break;
        case 2:
            p = Vec2{rng.Uniform(-20.0, 20.0), rng.Uniform(-20.0, 20.0)};
            break;
        default:
            p = polygon.Centroid();
            break;
        }
        const int start = rng.Int(0, n - 1);
        const int wedge = detail::WedgeOf(polygon, p, start);
        INFO("pair " << i << ", " << n << " vertices, start " << start << ", wedge " << wedge);
        REQUIRE(wedge >= 0);
        REQUIRE(wedge < n);
        // The point's ray lies between the wedge's rays (up to rounding of the turns).
        const Vec2 c = polygon.Centroid();
        const Vec2 r = polygon.Vertices()[0];
        const long double turn = TurnFrom(c, r, p);
        const long double from = wedge == 0 ? 0.0L : TurnFrom(c, r, polygon.Vertices()[wedge]);
        const long double to =
            wedge + 1 == n ? 2.0L * static_cast<long double>(kPi) : TurnFrom(c, r, polygon.Vertices()[wedge + 1]);
        const long double slack = 1e-12L;
        if (Length(p - c) > 1e-9 * Length(r - c))
        {
            // A point on the ray through v_0 turns by 0 or by a full turn: wedge 0 or the last one.
            const long double fullTurn = 2.0L * static_cast<long double>(kPi);
            const bool within = turn >= from - slack && turn <= to + slack;
            const bool onFirstRay = (turn < slack && wedge == n - 1) || (turn > fullTurn - slack && wedge == 0);
            REQUIRE((within || onFirstRay));
        }
        // Its face decides containment, against the distance from every face's line.
        const double depth = static_cast<double>(DepthOutside(polygon, At(0.0, 0.0), p));
        const double distance = detail::FaceDistance(polygon, wedge, p);
        if (std::abs(depth) > 1e-12 * Length(r - c))
        {
            REQUIRE((distance > 0.0) == (depth > 0.0));
            (depth > 0.0 ? outside : inside) += 1;
        }
    }
    CHECK(inside > 5000);
    CHECK(outside > 5000);
    // Invalid points end in a valid vertex, without a crash.
    const Polygon box = RandomPolygon(rng, 4, 1.0, 1.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int start = 0; start < 4; ++start)
    {
        const int wedge = detail::WedgeOf(box, Vec2{nan, 0.0}, start);
        CHECK((wedge >= 0 && wedge < 4));
    }
}
