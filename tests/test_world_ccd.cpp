// SPDX-License-Identifier: MIT
// Fast bodies in the world: a bullet stops at a thin wall, takes two walls in the order it meets them, bounces
// between two walls along the exactly reflected path, and a fast-spinning plank never ends a step through a wall.

#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/world_scenes.h"

#include <satviz/collide.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// The half-thickness of the thin walls: 0.01 thick.
constexpr double kWall = 0.005;

/// Everything beyond x = xFace: a region the bodies on the near side must never reach.
Shape FarSide()
{
    return BoxShape(1e4, 1e4);
}

Transform FarSideAt(double xFace)
{
    return At(xFace + 1e4, 0.0);
}

/// Where a body bouncing elastically between x = a and x = b (its centre's range) is after moving `distance` from
/// `x0` in the direction of increasing x: the path unfolded into a straight line, folded back. Also the number of
/// bounces and the direction it ends in (+1 or -1).
struct Folded
{
    double x = 0.0;
    int bounces = 0;
    double direction = 1.0;
};

Folded Fold(double x0, double distance, double a, double b)
{
    const double width = b - a;
    const double u = (x0 - a) + distance;
    Folded f;
    f.bounces = static_cast<int>(std::floor(u / width));
    const double m = std::fmod(u, 2.0 * width);
    f.x = m <= width ? a + m : a + 2.0 * width - m;
    f.direction = f.bounces % 2 == 0 ? 1.0 : -1.0;
    return f;
}

} // namespace

TEST_CASE("A bullet at 1e5 stops at a 0.01 thick wall", "[world][ccd]")
{
    for (int shape = 0; shape < 2; ++shape)
    {
        for (double degrees : {0.0, 30.0, -60.0})
        {
            World world; // no gravity
            AddStatic(world, BoxShape(kWall, 1e4), {0.0, 0.0});
            const double angle = degrees * kPi / 180.0;
            const Vec2 v{1e5 * std::cos(angle), 1e5 * std::sin(angle)};
            const Shape bullet = shape == 0 ? DiscShape(0.05) : BoxShape(0.05, 0.03);
            const int body = AddDynamic(world, bullet, {-1.0, 0.0}, 0.4, v);
            bool onItsSide = true;
            for (int step = 0; step < 3 && onItsSide; ++step)
            {
                Step(world, kDt);
                const RigidBody& b = world.bodies[static_cast<size_t>(body)];
                onItsSide = b.position.x < -kWall && !Overlap(b.shape, b.Xf(), FarSide(), FarSideAt(kWall));
                INFO((shape == 0 ? "circle" : "box")
                     << " at " << degrees << " degrees, step " << step << ": centre at " << b.position.x << ", "
                     << b.position.y << ", velocity " << b.velocity.x << ", " << b.velocity.y << ", turning at "
                     << b.angularVelocity << ", " << world.counts.hits << " hits in the step");
                CHECK(onItsSide);
                CHECK(std::isfinite(b.velocity.x));
            }
        }
    }
}

TEST_CASE("A bullet meeting two thin walls in one step bounces off the first and never reaches the second",
          "[world][ccd]")
{
    for (int shape = 0; shape < 2; ++shape)
    {
        World world; // no gravity
        const Material elastic = MakeMaterial(1.0, 0.0, 0.0);
        AddStatic(world, BoxShape(kWall, 5.0), {0.0, 0.0}, 0.0, elastic);
        AddStatic(world, BoxShape(kWall, 5.0), {10.0, 0.0}, 0.0, elastic);
        const double half = 0.05;
        const Shape bullet = shape == 0 ? DiscShape(half) : BoxShape(half, half);
        const double x0 = -1.0;
        const double speed = 1e5;
        const int body = AddDynamic(world, bullet, {x0, 0.0}, 0.0, {speed, 0.0}, 0.0, elastic);
        // Within the step it travels 1667: to the first wall's face, then all the way back.
        const double face = -kWall - half;
        const double expected = face - (speed * kDt - (face - x0));
        Step(world, kDt);
        const RigidBody& b = world.bodies[static_cast<size_t>(body)];
        INFO((shape == 0 ? "circle" : "box")
             << ": ends at " << b.position.x << ", expected " << expected << ", velocity " << b.velocity.x);
        CHECK(std::abs(b.position.x - expected) <= 1e-6);
        CHECK(b.velocity.x == Approx(-speed).epsilon(1e-12));
        CHECK(std::abs(b.position.y) <= 1e-9);
        CHECK(std::abs(b.angularVelocity) <= 1e-9);
        StepN(world, 2);
        CHECK(world.bodies[static_cast<size_t>(body)].position.x < expected);
    }
}

TEST_CASE("A fast elastic ball between two walls follows the exactly reflected path", "[world][ccd]")
{
    // Walls at x = -1 and x = 1; the ball's centre bounces within [-a, a], a = 1 - 0.005 - r. Moving at 5.5 times
    // that range per step, it hits the walls 5 or 6 times a step, each at the time the unfolded path says.
    const double r = 0.1;
    const double a = 1.0 - kWall - r;
    for (double fraction : {5.5, 2.25, 9.9})
    {
        World world; // no gravity
        const Material elastic = MakeMaterial(1.0, 0.0, 0.0);
        AddStatic(world, BoxShape(kWall, 50.0), {-1.0, 0.0}, 0.0, elastic);
        AddStatic(world, BoxShape(kWall, 50.0), {1.0, 0.0}, 0.0, elastic);
        const double vx = fraction * 2.0 * a / kDt;
        const double vy = 3.0;
        const double x0 = 0.2, y0 = -1.0;
        const int body = AddDynamic(world, DiscShape(r), {x0, y0}, 0.0, {vx, vy}, 0.0, elastic);
        int bouncesBefore = 0;
        for (int step = 1; step <= 3; ++step)
        {
            Step(world, kDt);
            const RigidBody& b = world.bodies[static_cast<size_t>(body)];
            const Folded f = Fold(x0, vx * step * kDt, -a, a);
            INFO("speed " << vx << ", step " << step << ": at " << b.position.x << ", expected " << f.x << ", velocity "
                          << b.velocity.x << ", " << f.bounces << " bounces so far, " << world.counts.hits
                          << " hits in the step");
            CHECK(std::abs(b.position.x - f.x) <= 1e-6);
            CHECK(b.velocity.x == Approx(f.direction * vx).epsilon(1e-12));
            CHECK(std::abs(b.position.y - (y0 + vy * step * kDt)) <= 1e-9);
            CHECK(b.velocity.y == Approx(vy).epsilon(1e-12));
            CHECK(std::abs(b.angularVelocity) <= 1e-9);
            CHECK(world.counts.hits == f.bounces - bouncesBefore);
            bouncesBefore = f.bounces;
        }
    }
}

TEST_CASE("A fast-spinning plank never ends a step through a thin wall", "[world][ccd][spin]")
{
    // A 2 x 0.05 plank turning at 200 radians per time unit (its tips at 200 units per time unit, 3.3 radians a
    // step) drifts into a wall 0.01 thick.
    for (int bouncy = 0; bouncy < 2; ++bouncy)
    {
        World world; // no gravity
        const Material material = bouncy ? MakeMaterial(1.0, 0.0, 0.0) : Material{};
        AddStatic(world, BoxShape(kWall, 3.0), {0.0, 0.0}, 0.0, material);
        const int plank = AddDynamic(world, BoxShape(1.0, 0.025), {-1.5, 0.0}, 0.0, {0.3, 0.0}, 200.0, material);
        double reach = -1e300;
        bool touched = false;
        for (int step = 0; step < 300; ++step)
        {
            Step(world, kDt);
            const RigidBody& b = world.bodies[static_cast<size_t>(plank)];
            for (const Vec2& v : b.shape.polygon.Vertices())
            {
                reach = std::max(reach, TransformPoint(b.Xf(), v).x);
            }
            touched = touched || world.counts.hits > 0;
            for (const WorldContact& c : world.contacts)
            {
                touched = touched || c.points[0].normalImpulse > 0.0 || c.points[1].normalImpulse > 0.0;
            }
            INFO((bouncy ? "elastic" : "default material") << ", step " << step << ": centre at " << b.position.x
                                                           << ", " << b.position.y << ", farthest corner x " << reach);
            REQUIRE(b.position.x < -kWall);
            REQUIRE_FALSE(Overlap(b.shape, b.Xf(), FarSide(), FarSideAt(kWall)));
        }
        INFO("farthest any corner reached: x = " << reach);
        CHECK(touched);
        CHECK(reach < kWall);
    }
}

TEST_CASE("A ball at 1000 between walls 6 apart, within reach of a wall at the start of a step, stays in and follows "
          "the reflected path",
          "[world][ccd]")
{
    // Radius 0.25, no gravity, restitution 1, no friction: it bounces about three times a step. In the steps that
    // start within its reach (two radii) of a wall it used to get a speculative contact, bounce at the start of the
    // step instead of at the wall, and then pass through that wall after the bounce off the other one.
    const double r = 0.25;
    const double face = 3.0;
    const double a = face - r;
    World world;
    const Material elastic = MakeMaterial(1.0, 0.0, 0.0);
    AddStatic(world, BoxShape(0.5, 50.0), {-face - 0.5, 0.0}, 0.0, elastic);
    AddStatic(world, BoxShape(0.5, 50.0), {face + 0.5, 0.0}, 0.0, elastic);
    const double vx = 1000.0, x0 = 0.0;
    const int body = AddDynamic(world, DiscShape(r), {x0, 0.0}, 0.0, {vx, 0.0}, 0.0, elastic);
    double worst = 0.0;
    int withinReach = 0;
    for (int step = 1; step <= 600; ++step)
    {
        const double before = world.bodies[static_cast<size_t>(body)].position.x;
        withinReach += (a - std::abs(before) < 2.0 * r) ? 1 : 0;
        Step(world, kDt);
        const RigidBody& b = world.bodies[static_cast<size_t>(body)];
        const Folded f = Fold(x0, vx * step * kDt, -a, a);
        worst = std::max(worst, std::abs(b.position.x - f.x));
        INFO("step " << step << ": at " << b.position.x << ", expected " << f.x);
        REQUIRE(std::abs(b.position.x) < face);
        REQUIRE(std::abs(b.position.x - f.x) <= 1e-6);
    }
    INFO("worst position error " << worst << "; " << withinReach << " steps started within reach of a wall");
    CHECK(withinReach > 10);
}

TEST_CASE("A ball at 714 bouncing between floor and ceiling under gravity never leaves through the floor",
          "[world][ccd]")
{
    // Radius 0.27, restitution 1, friction 0.2, a little sideways motion, in a closed 10 x 6 box with walls 0.01
    // thick: it bounces between floor and ceiling about twice a step, and used to leave through the floor in the
    // step in which it first started within reach of it.
    World world = WorldWithGravity(kGravity);
    const Material material = MakeMaterial(1.0, 0.2, 0.2);
    const double t = 0.01;
    AddStatic(world, BoxShape(0.5 * t, 3.0 + t), {-5.0 - 0.5 * t, 0.0}, 0.0, material);
    AddStatic(world, BoxShape(0.5 * t, 3.0 + t), {5.0 + 0.5 * t, 0.0}, 0.0, material);
    AddStatic(world, BoxShape(5.0 + t, 0.5 * t), {0.0, -3.0 - 0.5 * t}, 0.0, material);
    AddStatic(world, BoxShape(5.0 + t, 0.5 * t), {0.0, 3.0 + 0.5 * t}, 0.0, material);
    const int body = AddDynamic(world, DiscShape(0.27), {0.3, -1.0}, 0.0, {2.0, 714.0}, 0.0, material);
    int64_t hits = 0;
    for (int step = 1; step <= 600; ++step)
    {
        Step(world, kDt);
        hits += world.counts.hits;
        const RigidBody& b = world.bodies[static_cast<size_t>(body)];
        INFO("step " << step << ": at " << b.position.x << ", " << b.position.y << ", velocity " << b.velocity.x << ", "
                     << b.velocity.y);
        REQUIRE(std::abs(b.position.x) < 5.0);
        REQUIRE(std::abs(b.position.y) < 3.0);
    }
    CHECK(hits > 600);
}

TEST_CASE("An elastic ball bouncing several times a step follows the reflected path to 1e-6, in every step",
          "[world][ccd][property]")
{
    // Random widths, radii, speeds (2 to 12 bounces a step) and starting points, 120 steps each, no gravity: the
    // position after every step is where the unfolded straight path puts it, also in the steps that start within
    // the ball's reach of a wall.
    double worst = 0.0;
    int withinReach = 0;
    for (int k = 0; k < 200; ++k)
    {
        Rng rng(0xb0c0000u + static_cast<uint64_t>(k));
        const double half = rng.Uniform(0.5, 5.0);
        const double r = rng.Uniform(0.05, 0.4) * half;
        const double a = half - r;
        World world;
        const Material elastic = MakeMaterial(1.0, 0.0, 0.0);
        AddStatic(world, BoxShape(kWall, 1e4), {-half - kWall, 0.0}, 0.0, elastic);
        AddStatic(world, BoxShape(kWall, 1e4), {half + kWall, 0.0}, 0.0, elastic);
        const double vx = rng.Uniform(2.0, 12.0) * 2.0 * a / kDt * (rng.Chance(0.5) ? 1.0 : -1.0);
        const double x0 = rng.Uniform(-a, a);
        const int body = AddDynamic(world, DiscShape(r), {x0, 0.0}, 0.0, {vx, 0.0}, 0.0, elastic);
        for (int step = 1; step <= 120; ++step)
        {
            const double before = world.bodies[static_cast<size_t>(body)].position.x;
            withinReach += (a - std::abs(before) < 2.0 * r) ? 1 : 0;
            Step(world, kDt);
            const RigidBody& b = world.bodies[static_cast<size_t>(body)];
            // The unfolded path runs forwards from -a; a ball starting leftwards is the mirror image.
            const double sign = vx > 0.0 ? 1.0 : -1.0;
            const Folded f = Fold(sign * x0, std::abs(vx) * step * kDt, -a, a);
            const double error = std::abs(b.position.x - sign * f.x);
            worst = std::max(worst, error);
            INFO("case " << k << ", step " << step << ": at " << b.position.x << ", expected " << sign * f.x);
            REQUIRE(error <= 1e-6);
        }
    }
    INFO("worst position error " << worst << "; " << withinReach << " steps started within reach of a wall");
    CHECK(withinReach > 1000);
}

TEST_CASE("A box falling at up to its speculative reach per step lands on the ground, neither sinking nor hovering",
          "[world][speculative]")
{
    // At 6 to 60 units a second a unit box moves 0.1 to 1 a step, within its reach (twice its outer radius): no sweep,
    // the speculative contact alone must stop it at the surface. It must be found before the boxes overlap, and the
    // solver must let the box close the gap it has: resting, its bottom is on y = 0 within the slop.
    for (double speed : {6.0, 20.0, 40.0, 60.0})
    {
        for (int phase = 0; phase < 4; ++phase)
        {
            World world = WorldWithGravity(kGravity);
            AddGround(world);
            const double height = 3.0 + 0.27 * phase;
            const int box = AddDynamic(world, BoxShape(0.5, 0.5), {0.0, 0.5 + height}, 0.0, {0.0, -speed});
            double deepest = 0.0;
            for (int i = 0; i < 90; ++i)
            {
                Step(world, kDt);
                deepest = std::max(deepest, 0.5 - world.bodies[box].position.y);
            }
            const double bottom = world.bodies[box].position.y - 0.5;
            INFO("falling at " << speed << " from " << height << ": deepest " << deepest << ", resting bottom at "
                               << bottom);
            CHECK(deepest <= 2.0 * world.settings.linearSlop);
            CHECK(std::abs(bottom) <= world.settings.linearSlop);
            CHECK(std::abs(world.bodies[box].velocity.y) <= 0.05);
        }
    }
}

TEST_CASE("A box falling within its reach of the ground has a speculative contact that closes the gap in the step",
          "[world][speculative][soft-step-fails]")
{
    // At the start of a step the box's bottom is `gap` above the ground and falls (|v| + g dt) dt in the step, its
    // reach: within the reach the pair must have a contact with that gap (a speculative one), and the box must
    // close the gap within the step, landing on the ground (within the slop), not stopping where it was.
    for (double speed : {10.0, 20.0, 40.0})
    {
        World world = WorldWithGravity(kGravity);
        AddGround(world);
        const int box = AddDynamic(world, BoxShape(0.5, 0.5), {0.0, 0.5 + 3.0}, 0.0, {0.0, -speed});
        int speculative = 0;
        for (int i = 0; i < 30; ++i)
        {
            const double gap = world.bodies[box].position.y - 0.5;
            const double v = world.bodies[box].velocity.y;
            const double reach = (std::abs(v) + kGravity * kDt) * kDt;
            Step(world, kDt);
            if (gap <= 0.05 || gap >= 0.9 * reach)
            {
                continue;
            }
            INFO("falling at " << speed << ", step " << i << ": gap " << gap << ", reach " << reach << ", bottom after "
                               << world.bodies[box].position.y - 0.5);
            REQUIRE(world.contacts.size() == 1);
            CHECK(world.contacts[0].points[0].separation > 0.0);
            CHECK(std::abs(world.bodies[box].position.y - 0.5) <= world.settings.linearSlop);
            ++speculative;
        }
        INFO("falling at " << speed);
        CHECK(speculative >= 1);
    }
}
