// SPDX-License-Identifier: MIT
// MoveAndSlide: stops at surfaces, slides along them, never sinks and never sticks.

#include "support/builders.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace satviz;
using namespace satviz::testing;
using Catch::Matchers::WithinAbs;

namespace
{

// Signed distance between the shapes along their manifold: > 0 apart, <= 0 touching or overlapping.
double Distance(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB)
{
    const Manifold m = Collide(a, xfA, b, xfB);
    return m.overlap ? -m.depth : m.gap;
}

} // namespace

TEST_CASE("Sliding along a floor for many steps neither sinks nor sticks", "[slide]")
{
    const Shape floor = BoxShape(1e4, 1.0);
    const Shape mover = BoxShape(0.5, 0.25);
    const Obstacle obstacles[] = {{&floor, At(0.0, -1.0)}};
    Transform xf = At(0.0, 0.25 + 1e-3);
    const double skin = DefaultSkin(mover, xf);
    for (int step = 0; step < 2000; ++step)
    {
        const double x = xf.p.x;
        const SlideResult r = MoveAndSlide(mover, xf, Vec2{0.05, -0.02}, obstacles, 1);
        xf = r.xf;
        INFO("step " << step << ", y " << xf.p.y);
        // Never into the floor, and resting on it (not hovering) once it has landed.
        const double gap = Distance(mover, xf, floor, obstacles[0].xf);
        REQUIRE(gap > 0.0);
        if (step > 0)
        {
            REQUIRE(gap <= 2.0 * skin);
        }
        // The whole horizontal displacement is made every step.
        REQUIRE(std::abs((xf.p.x - x) - 0.05) <= 1e-9);
    }
}

TEST_CASE("A wall stops the mover just short of it, even at huge speed", "[slide]")
{
    const Shape wall = BoxShape(5e-4, 10.0);
    const Shape mover = BoxShape(0.05, 0.05);
    const Obstacle obstacles[] = {{&wall, At(0.0, 0.0)}};
    for (double speed : {1.0, 1e3, 1e6})
    {
        INFO("speed " << speed);
        const Transform start = At(-0.5, 0.0);
        const SlideResult r = MoveAndSlide(mover, start, Vec2{speed, 0.0}, obstacles, 1);
        const double skin = DefaultSkin(mover, start);
        REQUIRE(r.contactCount == 1);
        CHECK(r.normals[0] == Vec2{1.0, 0.0});
        const double gap = Distance(mover, r.xf, wall, obstacles[0].xf);
        CHECK(gap > 0.0);
        CHECK_THAT(gap, WithinAbs(skin, 1e-12));
        // Pushing on from there does not move it into the wall.
        const SlideResult again = MoveAndSlide(mover, r.xf, Vec2{speed, 0.0}, obstacles, 1);
        CHECK(Distance(mover, again.xf, wall, obstacles[0].xf) > 0.0);
        CHECK(again.xf.p.x <= r.xf.p.x + 1e-12);
    }
}

TEST_CASE("Into a corner: both surfaces stop the mover", "[slide]")
{
    const Shape floor = BoxShape(10.0, 1.0);
    const Shape wall = BoxShape(1.0, 10.0);
    const Shape mover = BoxShape(0.25, 0.25);
    const Obstacle obstacles[] = {{&floor, At(0.0, -1.0)}, {&wall, At(3.0, 0.0)}};
    const SlideResult r = MoveAndSlide(mover, At(0.0, 1.0), Vec2{5.0, -5.0}, obstacles, 2);
    CHECK(r.contactCount == 2);
    CHECK(Distance(mover, r.xf, floor, obstacles[0].xf) > 0.0);
    CHECK(Distance(mover, r.xf, wall, obstacles[1].xf) > 0.0);
    CHECK_THAT(r.xf.p.x, WithinAbs(1.75, 1e-6));
    CHECK_THAT(r.xf.p.y, WithinAbs(0.25, 1e-6));
}

TEST_CASE("On a slope, a push straight down slides along it", "[slide]")
{
    const double angle = 0.5;
    const Shape ramp = BoxShape(10.0, 1.0);
    const Shape mover = BoxShape(0.2, 0.2);
    const Obstacle obstacles[] = {{&ramp, At(0.0, 0.0, angle)}};
    // Resting on the ramp's top face, turned like the ramp.
    const Vec2 up{-std::sin(angle), std::cos(angle)};
    const Transform start = MakeTransform((1.2 + 1e-4) * up, angle);
    const SlideResult r = MoveAndSlide(mover, start, Vec2{0.0, -1.0}, obstacles, 1);
    REQUIRE(r.contactCount == 1);
    // The part of (0, -1) along the ramp's downhill direction is sin(angle) in length.
    const Vec2 downhill{-std::cos(angle), -std::sin(angle)};
    const Vec2 moved = r.xf.p - start.p;
    CHECK(Dot(moved, downhill) > 0.9 * std::sin(angle));
    CHECK(Distance(mover, r.xf, ramp, obstacles[0].xf) > 0.0);
}

TEST_CASE("A mover that starts inside is pushed out first", "[slide]")
{
    const Shape floor = BoxShape(10.0, 1.0);
    const Shape mover = BoxShape(0.5, 0.5);
    const Obstacle obstacles[] = {{&floor, At(0.0, -1.0)}};
    const SlideResult r = MoveAndSlide(mover, At(0.0, 0.3), Vec2{}, obstacles, 1);
    CHECK(r.contactCount == 1);
    CHECK(Distance(mover, r.xf, floor, obstacles[0].xf) > 0.0);
    CHECK_THAT(r.xf.p.y, WithinAbs(0.5, 1e-6));
}
