// SPDX-License-Identifier: MIT
// The world never loses a body: fast bodies of every shape, spinning or not, alone or in crowds, shut in closed
// boxes with thin and thick walls, never end a step past a wall or inside a static body; two fast bodies thrown
// at each other never pass through each other.

#include "support/closed_box.h"
#include "support/random_shapes.h"
#include "support/world_scenes.h"

#include <satviz/collide.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// Steps a scene, checking the box after every step. Returns the number of steps it held; counts the hits and the
/// steps with contacts (so the test can say that the walls were met at all).
struct Run
{
    int steps = 0;
    int64_t hits = 0;
    int64_t contactSteps = 0;
    std::string failure;
};

Run StepInBox(ClosedBoxScene& scene, int steps)
{
    Run run;
    for (int s = 0; s < steps; ++s)
    {
        Step(scene.world, scene.dt);
        run.hits += scene.world.counts.hits;
        run.contactSteps += scene.world.contacts.empty() ? 0 : 1;
        run.failure = CheckClosedBox(scene.world, scene.box);
        if (!run.failure.empty())
        {
            run.failure = "step " + std::to_string(s + 1) + ": " + run.failure;
            return run;
        }
        ++run.steps;
    }
    return run;
}

} // namespace

namespace
{

/// Steps `scenes` random scenes drawn with `ranges` (seeds from `seed`) for `steps` steps each, checking the box
/// after every step; fails on the first body that leaves it, and checks that the bodies met the walls at all.
void CheckScenes(const ClosedBoxRanges& ranges, uint64_t seed, int scenes, int steps)
{
    int64_t checked = 0, hits = 0, scenesThatMet = 0;
    for (int k = 0; k < scenes; ++k)
    {
        Rng rng(seed + static_cast<uint64_t>(k));
        ClosedBoxScene scene = MakeClosedBoxScene(rng, ranges);
        const Run run = StepInBox(scene, steps);
        INFO("scene " << k << " (walls " << scene.box.wall << " thick, "
                      << scene.world.bodies.size() - static_cast<size_t>(scene.box.firstBody)
                      << " bodies): " << run.failure);
        REQUIRE(run.failure.empty());
        checked += run.steps;
        hits += run.hits;
        scenesThatMet += (run.hits > 0 || run.contactSteps > 0) ? 1 : 0;
    }
    // The property is about bodies that meet walls: nearly every scene must have had its bodies hit something.
    INFO(checked << " steps checked, " << hits << " time-ordered hits, " << scenesThatMet
                 << " scenes with a hit or a contact");
    CHECK(checked == static_cast<int64_t>(scenes) * steps);
    CHECK(scenesThatMet >= scenes * 9 / 10);
    CHECK(hits > scenes);
}

} // namespace

TEST_CASE("No lone body leaves a closed box: thousands of random scenes at up to 1e5 units per step, spinning",
          "[world][ccd][property]")
{
    // Circles, boxes and convex 3- to 8-gons 0.05 to 0.5 in radius; speeds up to 1e5 units per step (thousands of
    // times their size), spins up to 600 rad/s; walls 0.01 to 1 thick; restitution 0 to 1; friction 0 to 1;
    // gravity on and off; a thin static post in a quarter of the boxes. Checked after every step.
    ClosedBoxRanges ranges;
    ranges.minBodies = ranges.maxBodies = 1;
    CheckScenes(ranges, 0x5eed0000u, 3000, 120);
}

TEST_CASE("No body of a crowd leaves a closed box", "[world][ccd][property]")
{
    // Crowds of 2 to 20 bodies started apart, at up to 50 units per step (3000 units per time unit), pressing each
    // other into the walls.
    ClosedBoxRanges ranges;
    ranges.minBodies = 2;
    CheckScenes(ranges, 0xc20d0000u, 500, 120);
}

TEST_CASE("Two fast bodies thrown at each other never pass through each other", "[world][ccd][property]")
{
    // Head on: their centres of mass on one line, off it by less than a quarter of the smaller inner radius. Each
    // shape holds the disc of its inner radius about its centre of mass, and the two discs pass through each other
    // on that line, so the shapes must meet, at any speed up to 1e5 units per step each, spinning, in any material.
    // The body that started on one side of the other along the line is never found on the other side without a
    // hit or a contact between them first (after one, it may go round the other), and the two never end a step
    // overlapping by more than half the smaller inner radius.
    int met = 0;
    const int pairs = 1500;
    for (int k = 0; k < pairs; ++k)
    {
        Rng rng(0xdd000000u + static_cast<uint64_t>(k));
        World world; // no gravity, no walls
        Material material;
        material.restitution = rng.Chance(0.3) ? 1.0 : rng.Uniform(0.0, 1.0);
        material.friction = rng.Uniform(0.0, 1.0);
        material.staticFriction = material.friction;
        const double heading = rng.Uniform(0.0, 2.0 * kPi);
        const Vec2 d{std::cos(heading), std::sin(heading)};
        const Vec2 across{-d.y, d.x};
        const double distance = rng.Uniform(1.5, 20.0);
        for (int b = 0; b < 2; ++b)
        {
            BodyDef def;
            const double radius = rng.Uniform(0.05, 0.5);
            def.shape = rng.Chance(0.3) ? DiscShape(radius)
                                        : MakeShape(RandomPolygon(rng, rng.Int(3, 8), radius, rng.Uniform(0.4, 1.0)));
            def.material = material;
            def.angle = rng.Uniform(0.0, 2.0 * kPi);
            const double speed = rng.LogUniform(0.0, 5.0) / kDt;
            def.velocity = (b == 0 ? speed : -speed * rng.Uniform(0.0, 1.0)) * d;
            def.angularVelocity = rng.Uniform(-300.0, 300.0);
            AddBody(world, def);
        }
        // The centres of mass on the line, the second off it by a fraction of the smaller inner radius.
        const double size = std::min(world.bodies[0].innerRadius, world.bodies[1].innerRadius);
        const double off = rng.Uniform(-0.25, 0.25) * size;
        for (int b = 0; b < 2; ++b)
        {
            RigidBody& body = world.bodies[static_cast<size_t>(b)];
            const Vec2 centre = (b == 0 ? -0.5 : 0.5) * distance * d + (b == 0 ? 0.0 : off) * across;
            body.position = centre - Rotate(MakeRot(body.angle), body.localCenter);
        }
        const auto offset = [&]() { return world.bodies[1].WorldCenter() - world.bodies[0].WorldCenter(); };
        bool hit = false;
        for (int s = 0; s < 40; ++s)
        {
            Step(world, kDt);
            const RigidBody& a = world.bodies[0];
            const RigidBody& b = world.bodies[1];
            const Manifold m = Collide(a.shape, a.Xf(), b.shape, b.Xf());
            const Vec2 o = offset();
            hit = hit || world.counts.hits > 0 || !world.contacts.empty();
            INFO("pair " << k << ", step " << s + 1 << ": along the approach " << Dot(o, d) << ", across "
                         << Cross(o, d) << ", overlap " << (m.overlap ? m.depth : 0.0) << ", met: " << hit);
            REQUIRE((Dot(o, d) > 0.0 || hit));
            REQUIRE((!m.overlap || m.depth <= 0.5 * size));
        }
        met += hit ? 1 : 0;
    }
    // They must have met: a pair that never touched would say nothing.
    CHECK(met == pairs);
}

TEST_CASE("A body touching a wall, pressed by a body that overlaps it, is not pushed into the wall",
          "[world][property][soft-step-fails]")
{
    // No gravity, every body at rest: a disc or a box whose side lies on a wall's face (its gap a few ulps either
    // side of zero, so that the world's tests, which grow a shape by a margin and take it off again, round it to a
    // touch or not), and a heavier box overlapping it from the other side by 0.02 to 0.15 (less than a pass of the
    // position correction moves a body). The passes must push the heavy box out, not the small body into the wall:
    // it may end no deeper in the wall than twice the slop (the passes leave a resting body up to the slop deep, and
    // each pass pushes it out of the wall before it pushes the two bodies apart). Walls 0.01 to 1 thick, at any
    // angle, anywhere.
    int pressed = 0;
    const int cases = 3000;
    for (int k = 0; k < cases; ++k)
    {
        Rng rng(0x7a110000u + static_cast<uint64_t>(k));
        World world; // no gravity
        UseStepUnderTest(world);
        const double heading = rng.Uniform(0.0, 2.0 * kPi);
        const Vec2 d{std::cos(heading), std::sin(heading)}; // from the wall into the room
        const Vec2 across{-d.y, d.x};
        const Vec2 face = Vec2{rng.Uniform(-10.0, 10.0), rng.Uniform(-10.0, 10.0)};
        const double thickness = rng.LogUniform(-2.0, 0.0);
        const int wall = AddStatic(world, BoxShape(0.5 * thickness, 2.0), face - 0.5 * thickness * d, heading);
        const double size = rng.Uniform(0.05, 0.5);
        const bool disc = rng.Chance(0.5);
        // The small body's centre, a whole number of ulps off touching.
        Vec2 centre = face + size * d + rng.Uniform(-0.5, 0.5) * size * across;
        const int ulps = rng.Int(-3, 6);
        for (int u = 0; u < std::abs(ulps); ++u)
        {
            const Vec2 toward = ulps > 0 ? centre + d : centre - d;
            centre = {std::nextafter(centre.x, toward.x), std::nextafter(centre.y, toward.y)};
        }
        const int small = AddDynamic(world, disc ? DiscShape(size) : BoxShape(size, size), centre, heading);
        const double depth = rng.Uniform(0.02, std::min(0.15, size));
        const double half = rng.Uniform(1.0, 3.0) * size;
        const int heavy = AddDynamic(world, BoxShape(half, half),
                                     centre + (size + half - depth) * d + rng.Uniform(-0.5, 0.5) * size * across,
                                     heading, {}, 0.0, Material{}, rng.Uniform(1.0, 50.0));
        const auto overlap = [&](int i, int j) {
            const RigidBody& a = world.bodies[static_cast<size_t>(i)];
            const RigidBody& b = world.bodies[static_cast<size_t>(j)];
            const Manifold m = Collide(a.shape, a.Xf(), b.shape, b.Xf());
            return m.overlap ? m.depth : 0.0;
        };
        const double before = overlap(small, heavy);
        REQUIRE(before > 0.01);
        for (int s = 0; s < 10; ++s)
        {
            Step(world, kDt);
            // The event the check is about: the heavy box presses the small body (a contact where they overlap).
            for (const WorldContact& c : world.contacts)
            {
                pressed += s == 0 && c.a == small && c.b == heavy && c.points[0].separation < 0.0 ? 1 : 0;
            }
            INFO("case " << k << " (" << (disc ? "disc" : "box") << " " << size << ", " << ulps << " ulps off, wall "
                         << thickness << " thick), step " << s + 1);
            REQUIRE(overlap(small, wall) <= 2.0 * world.settings.linearSlop);
        }
    }
    CHECK(pressed == cases);
}
