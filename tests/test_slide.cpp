// SPDX-License-Identifier: MIT
// MoveAndSlide: stops at surfaces, slides along them, never sinks and never sticks.

#include "support/builders.h"
#include "support/random_shapes.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

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

TEST_CASE("A box touching a wall, pushed into it and along it, slides along", "[slide]")
{
    // The box touches the wall's left face exactly (gap 0) and is pushed right and up; and a box turned by a right
    // angle (its rotation rounded) resting exactly on a floor and pushed along and down. Each step makes the whole
    // motion along the surface.
    const Shape mover = BoxShape(0.25, 0.25);
    const Shape wall = BoxShape(1.0, 20.0);
    const Obstacle walls[] = {{&wall, At(2.0, 0.0)}};
    Transform xf = At(0.75, 0.0);
    for (int step = 0; step < 100; ++step)
    {
        INFO("step " << step);
        const SlideResult r = MoveAndSlide(mover, xf, Vec2{0.5, 0.1}, walls, 1);
        REQUIRE(r.remaining == Vec2{});
        REQUIRE(std::abs((r.xf.p.y - xf.p.y) - 0.1) <= 1e-12);
        REQUIRE(r.xf.p.x <= 0.75);
        REQUIRE(Distance(mover, r.xf, wall, walls[0].xf) >= 0.0);
        xf = r.xf;
    }
    const Shape floor = BoxShape(50.0, 0.5);
    const Obstacle floors[] = {{&floor, At(0.0, 0.0)}};
    for (const double angle : {0.5 * kPi, kPi, -0.5 * kPi})
    {
        xf = At(0.0, 0.75, angle);
        for (int step = 0; step < 100; ++step)
        {
            INFO("angle " << angle << ", step " << step);
            const SlideResult r = MoveAndSlide(mover, xf, Vec2{0.05, -0.02}, floors, 1);
            REQUIRE(r.remaining == Vec2{});
            REQUIRE(std::abs((r.xf.p.x - xf.p.x) - 0.05) <= 1e-12);
            REQUIRE(Distance(mover, r.xf, floor, floors[0].xf) >= -1e-15);
            xf = r.xf;
        }
    }
}

namespace
{

// A mover touching the top face of a long floor (a box 40 by 2), up to the rounding of the world coordinates. The
// floor is turned any way (so its top face is also a wall or a ceiling), by an exact or a rounded right angle now
// and then; the mover (a box, a random polygon or a circle) turned like the floor, by a right angle, or any way.
struct OnFloor
{
    Shape floor;
    Transform xfFloor;
    Shape mover;
    Transform xf;
    Vec2 up;    ///< the floor's top face normal, world
    Vec2 along; ///< along the floor's top face, world
};

OnFloor TouchingFloor(Rng& rng, int kind)
{
    OnFloor out;
    out.floor = BoxShape(20.0, 1.0);
    const Vec2 position{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)};
    const double u = rng.Uniform(0.0, 1.0);
    const int quarter = rng.Int(0, 3);
    const Rot exact[] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    const double tilt = u < 0.5 ? rng.Uniform(-kPi, kPi) : quarter * (kPi / 2.0);
    out.xfFloor = u < 0.25 ? Transform{position, exact[quarter]} : MakeTransform(position, tilt);
    out.up = Rotate(out.xfFloor.q, Vec2{0.0, 1.0});
    out.along = Rotate(out.xfFloor.q, Vec2{1.0, 0.0});

    if (kind == 0)
    {
        out.mover = BoxShape(rng.Uniform(0.05, 0.5), rng.Uniform(0.05, 0.5));
    }
    else if (kind == 1)
    {
        out.mover = MakeShape(RandomPolygon(rng, rng.Int(3, 12), rng.Uniform(0.1, 0.5), rng.Uniform(0.35, 1.0)));
    }
    else
    {
        Circle circle;
        circle.radius = rng.Uniform(0.05, 0.5);
        circle.center = rng.Chance(0.5) ? Vec2{rng.Uniform(-0.1, 0.1), rng.Uniform(-0.1, 0.1)} : Vec2{};
        out.mover = MakeShape(circle);
    }
    const double w = rng.Uniform(0.0, 1.0);
    const double angle =
        w < 0.4 ? tilt + rng.Int(0, 3) * (kPi / 2.0) : (w < 0.6 ? rng.Int(0, 3) * (kPi / 2.0) : rng.Uniform(-kPi, kPi));
    const Rot q = MakeRot(angle);
    // The mover's lowest point towards the floor, relative to its origin.
    Vec2 lowest;
    if (out.mover.type == ShapeType::Circle)
    {
        lowest = Rotate(q, out.mover.circle.center) - out.mover.circle.radius * out.up;
    }
    else
    {
        lowest = Rotate(q, out.mover.polygon.Vertices()[0]);
        for (const Vec2& v : out.mover.polygon.Vertices())
        {
            lowest = Dot(Rotate(q, v), out.up) < Dot(lowest, out.up) ? Rotate(q, v) : lowest;
        }
    }
    out.xf = Transform{TransformPoint(out.xfFloor, Vec2{rng.Uniform(-5.0, 5.0), 1.0}) - lowest, q};
    return out;
}

// What a run of steps saw: the largest error of the motion along the floor and the largest depth into it, in units
// of their bounds.
struct SlideStats
{
    double progress = 0.0;
    double depth = 0.0;
    int steps = 0;
};

// Moves the mover by `displacement` for `steps` steps over the obstacles (a floor, or the tiles of one). Every
// step: the whole displacement is used (no contact budget runs out), the motion along the floor is the
// displacement's part along it within a few roundings of the coordinates, and the mover is not in any obstacle
// deeper than a few roundings of the floor's coordinates (`extent` from its origin); pushed into the floor, it stays
// on it within twice the skin.
template <typename S>
void RunAlongFloor(const ObstacleT<S>* obstacles, int count, S extent, const ShapeT<S>& mover, TransformT<S> xf,
                   Vec2T<S> up, Vec2T<S> along, Vec2T<S> displacement, int steps, SlideStats& stats)
{
    const S eps = std::numeric_limits<S>::epsilon();
    const S tangential = Dot(displacement, along);
    const bool pushing = Dot(displacement, up) < S(0);
    const S depthBound = S(64) * eps * (extent + Length(obstacles[0].xf.p));
    for (int step = 0; step < steps; ++step)
    {
        const SlideResultT<S> r = MoveAndSlide(mover, xf, displacement, obstacles, count);
        const S progress = Dot(r.xf.p - xf.p, along);
        const S progressBound = S(64) * eps * (S(1) + std::max(std::abs(xf.p.x), std::abs(xf.p.y)));
        S distance = std::numeric_limits<S>::infinity();
        for (int k = 0; k < count; ++k)
        {
            const ManifoldT<S> m = Collide(mover, r.xf, *obstacles[k].shape, obstacles[k].xf);
            distance = std::min(distance, m.overlap ? -m.depth : m.gap);
        }
        INFO("step " << step << ": from " << xf.p.x << ", " << xf.p.y << " to " << r.xf.p.x << ", " << r.xf.p.y
                     << ", along the floor " << progress << " of " << tangential << ", distance " << distance
                     << ", contacts " << r.contactCount);
        REQUIRE(r.remaining == Vec2T<S>{});
        REQUIRE(std::abs(progress - tangential) <= progressBound);
        REQUIRE(distance >= -depthBound);
        if (pushing)
        {
            REQUIRE(distance <= S(2) * DefaultSkin(mover, r.xf) + depthBound);
        }
        stats.progress = std::max(stats.progress, static_cast<double>(std::abs(progress - tangential) / progressBound));
        stats.depth = std::max(stats.depth, static_cast<double>(-distance / depthBound));
        ++stats.steps;
        xf = r.xf;
    }
}

template <typename S>
void RunAlongFloor(const ShapeT<S>& floor, const TransformT<S>& xfFloor, const ShapeT<S>& mover, TransformT<S> xf,
                   Vec2T<S> up, Vec2T<S> along, Vec2T<S> displacement, int steps, SlideStats& stats)
{
    // The floor's vertices are up to 20.1 from its origin.
    const ObstacleT<S> obstacles[] = {{&floor, xfFloor}};
    RunAlongFloor(obstacles, 1, S(21), mover, xf, up, along, displacement, steps, stats);
}

// What a failing run reports: its number, the mover's kind (0 box, 1 polygon, 2 circle), the floor and the motion.
std::string DescribeRun(int run, int kind, const OnFloor& start, Vec2 displacement)
{
    std::ostringstream text;
    text << "run " << run
         << (kind == 0   ? ", box"
             : kind == 1 ? ", polygon"
                         : ", circle")
         << ", floor at " << start.xfFloor.p.x << ", " << start.xfFloor.p.y << " turned " << start.xfFloor.q.c << ", "
         << start.xfFloor.q.s << ", displacement " << displacement.x << ", " << displacement.y;
    return text.str();
}

} // namespace

TEST_CASE("Starting on a tilted floor or against a wall, sliding along and pushing into it neither sticks nor sinks",
          "[slide]")
{
    // Boxes, random polygons and circles start touching the floor (gap 0 up to rounding), and move 200 steps along
    // it, along and into it, along and away from it, or straight into it. Catches MoveAndSlide sticking (moving 0
    // with every contact of its budget used) when the sweep from touching reported a hit at t = 0 on a wrong face,
    // or a hit at some time in the step for a slide along the face; and sinking where it reported a miss.
    Rng rng(7101);
    SlideStats stats;
    for (int i = 0; i < 600; ++i)
    {
        const int kind = i % 3;
        const OnFloor start = TouchingFloor(rng, kind);
        const double length = rng.Uniform(0.005, 0.05) * (rng.Chance(0.5) ? 1.0 : -1.0);
        const double u = rng.Uniform(0.0, 1.0);
        const double into =
            u < 0.3 ? 0.0 : (u < 0.8 ? rng.Uniform(0.1, 2.0) : -rng.Uniform(0.0, 0.5)) * std::abs(length);
        const bool straightIn = rng.Chance(0.1);
        const Vec2 displacement = straightIn ? -std::abs(length) * start.up : length * start.along - into * start.up;
        INFO(DescribeRun(i, kind, start, displacement));
        RunAlongFloor(start.floor, start.xfFloor, start.mover, start.xf, start.up, start.along, displacement, 200,
                      stats);
    }
    WARN(stats.steps << " steps; largest error along the floor " << stats.progress << " and depth " << stats.depth
                     << " of their bounds");
}

TEST_CASE("Starting on a tilted floor, sliding in float neither sticks nor sinks", "[slide][float]")
{
    // The same in single precision: the shapes and transforms rounded to float, touching up to that rounding.
    Rng rng(7202);
    SlideStats stats;
    for (int i = 0; i < 300; ++i)
    {
        const int kind = i % 3;
        const OnFloor start = TouchingFloor(rng, kind);
        const ShapeT<float> mover = ToFloat(start.mover);
        if (mover.type == ShapeType::Polygon && mover.polygon.Count() == 0)
        {
            continue;
        }
        const double length = rng.Uniform(0.005, 0.05) * (rng.Chance(0.5) ? 1.0 : -1.0);
        const double into = rng.Chance(0.3) ? 0.0 : rng.Uniform(0.1, 2.0) * std::abs(length);
        const Vec2 displacement = length * start.along - into * start.up;
        INFO(DescribeRun(i, kind, start, displacement));
        RunAlongFloor(ToFloat(start.floor), ToFloat(start.xfFloor), mover, ToFloat(start.xf),
                      ConvertVec<float>(start.up), ConvertVec<float>(start.along), ConvertVec<float>(displacement), 200,
                      stats);
    }
    WARN(stats.steps << " steps; largest error along the floor " << stats.progress << " and depth " << stats.depth
                     << " of their bounds");
}

TEST_CASE("A circle touching an obstacle and pushed into it does not pass through", "[slide][circle]")
{
    // A disc touching another disc, or a box's corner, pushed straight in (against the normal at the contact) by
    // more than the size of both: it stays where it is. Catches the sweep that missed from touching: the mover then
    // went straight through the obstacle.
    Rng rng(7303);
    const Shape box = BoxShape(0.5, 0.3);
    for (int i = 0; i < 2000; ++i)
    {
        const double radius = rng.Uniform(0.05, 1.0);
        const Shape mover = DiscShape(radius);
        const bool againstDisc = i % 2 == 0;
        const Shape obstacle = againstDisc ? DiscShape(rng.Uniform(0.05, 1.0)) : box;
        const Transform xfObstacle =
            MakeTransform(Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}, rng.Uniform(-kPi, kPi));
        const double angle = rng.Uniform(-kPi, kPi);
        Vec2 direction{std::cos(angle), std::sin(angle)};
        Vec2 contact = xfObstacle.p;
        if (againstDisc)
        {
            contact = contact + obstacle.circle.radius * direction;
        }
        else
        {
            // A corner, the centre off it between the normals of its two faces (the two axes of its quadrant).
            const Vec2 corner = box.polygon.Vertices()[rng.Int(0, 3)];
            const double turn =
                std::atan2(corner.y > 0.0 ? 1.0 : -1.0, corner.x > 0.0 ? 1.0 : -1.0) + rng.Uniform(-0.7, 0.7);
            direction = Rotate(xfObstacle.q, Vec2{std::cos(turn), std::sin(turn)});
            contact = TransformPoint(xfObstacle, corner);
        }
        const Transform start = At(contact.x + radius * direction.x, contact.y + radius * direction.y);
        const Vec2 push = -(2.0 * (radius + 1.0)) * direction;
        const Obstacle obstacles[] = {{&obstacle, xfObstacle}};
        const SlideResult r = MoveAndSlide(mover, start, push, obstacles, 1);
        INFO("case " << i << (againstDisc ? ", disc" : ", corner") << ": from " << start.p.x << ", " << start.p.y
                     << " to " << r.xf.p.x << ", " << r.xf.p.y);
        REQUIRE(Dot(r.xf.p - contact, direction) > 0.0);
        REQUIRE(Distance(mover, r.xf, obstacle, xfObstacle) >= -1e-12);
        REQUIRE(Length(r.xf.p - start.p) <= 1e-6);
    }
}

TEST_CASE("Starting on a tilted floor of tiles, sliding along it does not catch on the seams", "[slide]")
{
    // The floor as a row of 1 by 1 tiles edge to edge, turned any way: where two tiles meet, the next tile's corner
    // lies on the top face up to the rounding of its world coordinates. A mover that keeps the skin above the floor
    // passes over it; one that slides at zero distance (it started touching and was never lifted) runs into the
    // next tile's side face (or corner) and stops there, often for good. Boxes, random polygons and circles,
    // turned like the tiles or any way, sliding along or pushed along and into the floor.
    Rng rng(7404);
    const Shape tile = BoxShape(0.5, 0.5);
    SlideStats stats;
    for (int i = 0; i < 300; ++i)
    {
        const int kind = i % 3;
        const OnFloor start = TouchingFloor(rng, kind);
        // The floor's top face (local y = 1) is the tiles' top face.
        std::vector<Obstacle> tiles;
        for (int k = -16; k <= 16; ++k)
        {
            tiles.push_back({&tile, Transform{TransformPoint(start.xfFloor, Vec2{double(k), 0.5}), start.xfFloor.q}});
        }
        const double length = rng.Uniform(0.005, 0.05) * (rng.Chance(0.5) ? 1.0 : -1.0);
        const double into = rng.Chance(0.3) ? 0.0 : rng.Uniform(0.1, 2.0) * std::abs(length);
        const Vec2 displacement = length * start.along - into * start.up;
        INFO(DescribeRun(i, kind, start, displacement));
        RunAlongFloor(tiles.data(), static_cast<int>(tiles.size()), 21.0, start.mover, start.xf, start.up, start.along,
                      displacement, 200, stats);
    }
    WARN(stats.steps << " steps; largest error along the floor " << stats.progress << " and depth " << stats.depth
                     << " of their bounds");
}
