// SPDX-License-Identifier: MIT
// A fast spinning body that nothing touches in a step moves as its velocity takes it: the position passes move a
// body only out of an overlap there is, however far it turned in the step. Fast spinning bodies thrown about closed
// boxes of inelastic bodies, each step checked against free flight. And a body the sweep stops short of a contact
// keeps the velocity it had then, however often it is stopped in the step.

#include "support/closed_box.h"
#include "support/random_shapes.h"

#include <satviz/collide.h>
#include <satviz/step_trace.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// A body's state at the start of a step.
struct Start
{
    Vec2 center{};
    double angle = 0.0;
    Vec2 velocity{};
    double angularVelocity = 0.0;
};

/// The body's transform with its centre of mass at `center` and turned to `angle`.
Transform PoseWithCenter(const RigidBody& body, Vec2 center, double angle)
{
    const Transform xf = MakeTransform(Vec2{}, angle);
    return MakeTransform(center - Rotate(xf.q, body.localCenter), angle);
}

/// Whether the body is apart from every other body, placed at `xf`: apart from each where the step left it and
/// where its own velocity took it (a body the passes did not move ends there).
bool ApartFromAll(const World& world, const std::vector<Start>& start, double dt, size_t i, const Transform& xf)
{
    const RigidBody& body = world.bodies[i];
    for (size_t j = 0; j < world.bodies.size(); ++j)
    {
        if (j == i)
        {
            continue;
        }
        const RigidBody& other = world.bodies[j];
        if (Collide(body.shape, xf, other.shape, other.Xf()).overlap)
        {
            return false;
        }
        if (other.type == BodyType::Dynamic)
        {
            const Transform flown = PoseWithCenter(other, start[j].center + dt * other.velocity,
                                                   start[j].angle + dt * other.angularVelocity);
            if (Collide(body.shape, xf, other.shape, flown).overlap)
            {
                return false;
            }
        }
    }
    return true;
}

} // namespace

TEST_CASE("A fast spinning body that nothing touches in a step moves only as its velocity takes it",
          "[world][positions][property]")
{
    // Scenes of the world fuzz target, every restitution 0: one to six bodies at up to 1e5 units per step alone
    // (50 in a crowd), spinning at up to 600 rad/s, steps of 1/240 to 1/30, a thin post in a quarter of the boxes.
    // Checked: each body spinning faster than a contact follows (speculativeTurn: the sweep holds its pairs, not
    // the contacts) whose velocity changed by gravity alone and its spin not at all in the step (no contact
    // pushed it, no hit struck it). Such a body flies free: semi-implicit Euler moves its centre by dt times the
    // velocity at the end of the step and turns it by dt times its spin. It must end the step on that path, moved
    // and turned by the same fraction s of them, s = 1, or less when the sweep stopped its clock short of a contact
    // its passes could not reach (a stop that keeps the velocity; with gravity it is a kick, and not checked).
    // Unless, where it ended on that path, it overlaps another body (where that one ended, or where its own velocity
    // took it): then a position pass may have pushed it out. Any other place is a move without a cause, and a lift
    // of a free body is energy from nowhere.
    // The case the property is about, counted: such a body that started the step touching another (a contact, not
    // a guard), in a scene with hits in the steps before.
    int64_t free = 0, fromContact = 0, afterHits = 0;
    const int scenes = 2000;
    for (int k = 0; k < scenes; ++k)
    {
        Rng rng(0xf7ee0000u + static_cast<uint64_t>(k));
        ClosedBoxRanges ranges;
        ranges.maxBodies = 6;
        ranges.dt = 1.0 / rng.Uniform(30.0, 240.0);
        ClosedBoxScene scene = MakeClosedBoxScene(rng, ranges);
        World& world = scene.world;
        for (RigidBody& body : world.bodies)
        {
            body.material.restitution = 0.0;
        }
        const double dt = scene.dt;
        int64_t hitsBefore = 0;
        for (int step = 1; step <= 60; ++step)
        {
            std::vector<Start> start(world.bodies.size());
            for (size_t i = 0; i < world.bodies.size(); ++i)
            {
                const RigidBody& body = world.bodies[i];
                start[i] = {body.WorldCenter(), body.angle, body.velocity, body.angularVelocity};
            }
            Step(world, dt);
            for (size_t i = static_cast<size_t>(scene.box.firstBody); i < world.bodies.size(); ++i)
            {
                const RigidBody& body = world.bodies[i];
                const Start& s = start[i];
                const Vec2 kick = body.velocity - s.velocity - dt * world.settings.gravity;
                const bool pushed = std::sqrt(LengthSquared(kick)) > 1e-12 * (1.0 + Length(s.velocity)) ||
                                    body.angularVelocity != s.angularVelocity;
                const bool spinsFast = body.turnRadius > 0.0 &&
                                       std::fabs(body.angularVelocity) * dt > world.settings.speculativeTurn;
                if (!body.awake || pushed || !spinsFast)
                {
                    continue;
                }
                // The fraction of its free turn it made (at least a quarter radian of turn: well conditioned).
                const Vec2 path = dt * body.velocity;
                const double turn = dt * body.angularVelocity;
                const double fraction = (body.angle - s.angle) / turn;
                const double onPath = std::max(0.0, std::min(1.0, fraction));
                const Vec2 center = s.center + onPath * path;
                if (!ApartFromAll(world, start, dt, i, PoseWithCenter(body, center, s.angle + onPath * turn)))
                {
                    continue;
                }
                ++free;
                // Its contacts in this step: those found at its start.
                bool touched = false;
                for (const WorldContact& c : world.contacts)
                {
                    touched = touched || ((c.a == static_cast<int>(i) || c.b == static_cast<int>(i)) && !c.guard);
                }
                if (touched)
                {
                    ++fromContact;
                    afterHits += hitsBefore > 0 ? 1 : 0;
                }
                const Vec2 off = body.WorldCenter() - (s.center + fraction * path);
                std::ostringstream where;
                where << "scene " << k << ", step " << step << ", body " << i << " (spin " << body.angularVelocity
                      << " rad/s, dt " << dt << (touched ? ", touching at the start" : "") << "): turned "
                      << fraction << " of its free turn, and ended (" << off.x << ", " << off.y
                      << ") off its path at that fraction";
                INFO(where.str());
                const double roundOff = 1e-9 * (1.0 + Length(s.center) + Length(path));
                REQUIRE(fraction <= 1.0 + 1e-9);
                REQUIRE(fraction >= -1e-9);
                REQUIRE(std::sqrt(LengthSquared(off)) <= roundOff);
            }
            hitsBefore += world.counts.hits;
        }
    }
    INFO(free << " free fast spinning bodies checked, " << fromContact << " of them turning away from a contact, "
              << afterHits << " of those after hits in their scene");
    CHECK(free > 10000);
    CHECK(fromContact >= 20);
    CHECK(afterHits >= 10);
}

TEST_CASE("A body the sweep stops short of a contact gives back the gravity of the rest of the step once",
          "[world][ccd][property]")
{
    // Crowded scenes of the world fuzz target with gravity on: eight to twelve bodies, each spinning at 500 to 1500
    // rad/s, steps of 1/240 to 1/30. When conservative advancement runs out of passes short of a contact (a fast
    // spinner beside a wall), the sweep stops both bodies' clocks there: each keeps its velocity as of that time,
    // the velocity the passes gave it (with the whole step's gravity) less the gravity of the rest of the step.
    // Checked: each body awake at the start and the end of the step, with no guard (the position passes take the
    // approach of a body they lift out of a wall as a hit), whose hits in the step were all such stops (the step's
    // record lists them with no points), fewer than maxHitsPerBody of them, ends the step with the velocity it had
    // at its first stop less (1 - t) dt g, t that stop's time. Stopped again later (by another spinner), it has no
    // more gravity to give back: taking it off twice throws the body upwards, energy from nowhere.
    // The case the property is about, counted: bodies stopped twice or more in a step.
    int64_t checked = 0, stoppedAgain = 0;
    const int scenes = 3000;
    for (int k = 0; k < scenes; ++k)
    {
        Rng rng(0x5709000u + static_cast<uint64_t>(k));
        ClosedBoxRanges ranges;
        ranges.minBodies = 8;
        ranges.maxBodies = 12;
        ranges.dt = 1.0 / rng.Uniform(30.0, 240.0);
        ClosedBoxScene scene = MakeClosedBoxScene(rng, ranges);
        World& world = scene.world;
        world.settings.gravity = {0.0, -9.81};
        // Every body a fast spinner, so that a body stopped beside a wall is often stopped again by another.
        for (size_t i = static_cast<size_t>(scene.box.firstBody); i < world.bodies.size(); ++i)
        {
            world.bodies[i].angularVelocity = (rng.Chance(0.5) ? 1.0 : -1.0) * rng.Uniform(500.0, 1500.0);
        }
        StepTrace record;
        world.stepTrace = &record;
        const double dt = scene.dt;
        for (int step = 1; step <= 60; ++step)
        {
            std::vector<uint8_t> awake(world.bodies.size());
            for (size_t i = 0; i < world.bodies.size(); ++i)
            {
                awake[i] = world.bodies[i].awake ? 1 : 0;
            }
            Step(world, dt);
            for (size_t i = static_cast<size_t>(scene.box.firstBody); i < world.bodies.size(); ++i)
            {
                const int body = static_cast<int>(i);
                const StepHit* first = nullptr;
                int stops = 0;
                bool struck = false;
                for (const StepHit& hit : record.hits)
                {
                    if (hit.a != body && hit.b != body)
                    {
                        continue;
                    }
                    struck = struck || hit.pointCount > 0;
                    if (hit.pointCount == 0)
                    {
                        first = first != nullptr ? first : &hit;
                        ++stops;
                    }
                }
                if (!awake[i] || !world.bodies[i].awake || struck || stops == 0 ||
                    stops >= world.settings.maxHitsPerBody)
                {
                    continue;
                }
                // A body the position passes lifted out of a wall it sank into takes its approach there as a hit:
                // a body with a guard is left out.
                bool guarded = false;
                for (const WorldContact& c : world.contacts)
                {
                    guarded = guarded || ((c.a == body || c.b == body) && c.guard);
                }
                if (guarded)
                {
                    continue;
                }
                const int side = first->a == body ? 0 : 1;
                ++checked;
                stoppedAgain += stops >= 2 ? 1 : 0;
                const Vec2 atStop = first->velocityBefore[side];
                const Vec2 expected = atStop - ((1.0 - first->time) * dt) * world.settings.gravity;
                const Vec2 off = world.bodies[i].velocity - expected;
                std::ostringstream where;
                where << "scene " << k << ", step " << step << ", body " << i << ": stopped " << stops
                      << " times, first at " << first->time << " of the step; velocity (" << off.x << ", " << off.y
                      << ") off";
                INFO(where.str());
                REQUIRE(std::sqrt(LengthSquared(off)) <= 1e-9 * (1.0 + Length(atStop)));
            }
        }
    }
    INFO(checked << " stopped bodies checked, " << stoppedAgain << " of them stopped again");
    CHECK(checked >= 100);
    CHECK(stoppedAgain >= 5);
}
