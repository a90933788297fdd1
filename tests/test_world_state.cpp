// SPDX-License-Identifier: MIT
// The world's bookkeeping: the same world steps to the same bits (also copied mid-run), a settled pile sleeps and
// a body dropped on it wakes it, and the step counts add up, with each saving switched on and off.

#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/world_scenes.h"

#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// A ground with two walls and a pile of boxes, circles and hexagons dropped in a heap, with a seeded jitter.
World Pile(uint64_t seed)
{
    Rng rng(seed);
    World world = WorldWithGravity(kGravity);
    AddGround(world, 10.0);
    AddStatic(world, BoxShape(0.25, 3.0), {-3.25, 3.0});
    AddStatic(world, BoxShape(0.25, 3.0), {3.25, 3.0});
    PolygonResult hexagon = MakeRegularPolygon(6, 0.45);
    REQUIRE(hexagon.Ok());
    for (int i = 0; i < 16; ++i)
    {
        const Vec2 p{-2.0 + 1.3 * (i % 4) + rng.Uniform(-0.1, 0.1), 0.6 + 1.1 * (i / 4) + rng.Uniform(0.0, 0.1)};
        const int kind = i % 3;
        const Shape shape = kind == 0 ? BoxShape(0.45, 0.35) : kind == 1 ? DiscShape(0.4) : MakeShape(hexagon.polygon);
        const double angle = rng.Uniform(-0.5, 0.5);
        const double vx = rng.Uniform(-1.0, 1.0);
        AddDynamic(world, shape, p, angle, {vx, 0.0});
    }
    return world;
}

/// Steps until every dynamic body sleeps, at most `limit` steps; returns the steps taken or -1.
int StepUntilAsleep(World& world, int limit)
{
    for (int i = 1; i <= limit; ++i)
    {
        Step(world, kDt);
        bool asleep = true;
        int dynamic = 0;
        for (const RigidBody& b : world.bodies)
        {
            if (b.type == BodyType::Dynamic)
            {
                ++dynamic;
                asleep = asleep && !b.awake;
            }
        }
        if (asleep && world.counts.sleepingBodies == dynamic)
        {
            return i;
        }
    }
    return -1;
}

/// True when the two lists of contacts are the same geometry, bit for bit: pairs, normals, points, separations.
bool SameContacts(const std::vector<WorldContact>& a, const std::vector<WorldContact>& b)
{
    if (a.size() != b.size())
    {
        return false;
    }
    for (size_t i = 0; i < a.size(); ++i)
    {
        const WorldContact& p = a[i];
        const WorldContact& q = b[i];
        if (p.a != q.a || p.b != q.b || p.pointCount != q.pointCount || !SameDouble(p.normal.x, q.normal.x) ||
            !SameDouble(p.normal.y, q.normal.y))
        {
            return false;
        }
        for (int k = 0; k < p.pointCount; ++k)
        {
            if (!SameDouble(p.points[k].point.x, q.points[k].point.x) ||
                !SameDouble(p.points[k].point.y, q.points[k].point.y) ||
                !SameDouble(p.points[k].separation, q.points[k].separation) || p.points[k].key != q.points[k].key)
            {
                return false;
            }
        }
    }
    return true;
}

/// The contacts with at least one dynamic body.
std::vector<WorldContact> MovingContacts(const World& world)
{
    std::vector<WorldContact> moving;
    for (const WorldContact& c : world.contacts)
    {
        if (world.bodies[static_cast<size_t>(c.a)].type == BodyType::Dynamic ||
            world.bodies[static_cast<size_t>(c.b)].type == BodyType::Dynamic)
        {
            moving.push_back(c);
        }
    }
    return moving;
}

int64_t PairsOf(int64_t n)
{
    return n * (n - 1) / 2;
}

} // namespace

TEST_CASE("The same world built twice steps to the same bits", "[world][determinism]")
{
    World a = Pile(601);
    World b = Pile(601);
    int sleepingSteps = 0;
    for (int i = 0; i < 300; ++i)
    {
        Step(a, kDt);
        Step(b, kDt);
        INFO("step " << i);
        REQUIRE(SameState(a, b));
        REQUIRE(SameContacts(a.contacts, b.contacts));
        sleepingSteps += a.counts.sleepingBodies > 0 ? 1 : 0;
    }
    INFO("steps with sleeping bodies: " << sleepingSteps);
    CHECK(sleepingSteps > 0); // the run includes sleep
}

TEST_CASE("A world copied mid-run steps to the same bits as the original", "[world][determinism]")
{
    World original = Pile(602);
    StepN(original, 150);
    // A fast body dropped in at the copy, so that the copies meet swept hits and wake what sleeps.
    AddDynamic(original, DiscShape(0.1), {-1.5, 12.0}, 0.0, {0.0, -200.0});
    World copy = original;
    World emptied = original; // the broadphase's order is working memory, not state
    emptied.broadphase = SortAndSweep();
    emptied.sweptBroadphase = SortAndSweep();
    for (int i = 0; i < 150; ++i)
    {
        Step(original, kDt);
        Step(copy, kDt);
        Step(emptied, kDt);
        INFO("step " << i << " after the copy");
        REQUIRE(SameState(original, copy));
        REQUIRE(SameState(original, emptied));
    }
}

TEST_CASE("A body turned between steps steps as in a copy that starts afresh", "[world][determinism]")
{
    // The step keeps, between steps, working values it may reuse while the bodies are as it left them (the
    // rotation of each body's angle): a body turned by the caller must be stepped at its new angle, as in a copy,
    // whose working memory starts empty.
    const bool soft = GENERATE(false, true);
    INFO("soft step " << soft);
    World world = Pile(603);
    world.settings.softStep = soft;
    for (int i = 0; i < 40; ++i)
    {
        Step(world, kDt);
    }
    int turned = 0;
    for (size_t i = 0; i < world.bodies.size(); ++i)
    {
        RigidBody& body = world.bodies[i];
        if (body.type != BodyType::Dynamic)
        {
            continue;
        }
        // Every third body turned by a little, every third set to an angle of zero (-0 or +0).
        if (i % 3 == 0)
        {
            body.angle += 0.25;
            ++turned;
        }
        else if (i % 3 == 1)
        {
            body.angle = std::signbit(body.angle) ? 0.0 : -0.0;
            ++turned;
        }
    }
    REQUIRE(turned > 8);
    World copy = world;
    for (int i = 0; i < 60; ++i)
    {
        Step(world, kDt);
        Step(copy, kDt);
        INFO("step " << i << " after the turn");
        REQUIRE(SameState(world, copy));
    }
}

TEST_CASE("A settled pile sleeps, and a body dropped on it wakes it", "[world][sleep]")
{
    World world = WorldWithGravity(kGravity);
    AddGround(world);
    const std::vector<int> boxes = AddPyramid(world, {3, 2, 1});
    const int settled = StepUntilAsleep(world, 600);
    INFO("asleep after " << settled << " steps");
    REQUIRE(settled > 0);
    CHECK(world.counts.sleepingBodies == 6);
    CHECK(world.counts.awakeBodies == 0);
    // Asleep, nothing moves.
    std::vector<RigidBody> frozen = world.bodies;
    StepN(world, 30);
    for (size_t i = 0; i < frozen.size(); ++i)
    {
        CHECK(world.bodies[i].position == frozen[i].position);
        CHECK(world.bodies[i].angle == frozen[i].angle);
    }
    // A box dropped on the top one wakes the whole pile, which then settles and sleeps again.
    const Vec2 top = world.bodies[static_cast<size_t>(boxes.back())].position;
    AddDynamic(world, BoxShape(0.5, 0.5), top + Vec2{0.1, 2.0});
    int allAwake = -1;
    for (int i = 0; i < 120 && allAwake < 0; ++i)
    {
        Step(world, kDt);
        if (world.counts.awakeBodies == 7)
        {
            bool every = true;
            for (int b : boxes)
            {
                every = every && world.bodies[static_cast<size_t>(b)].awake;
            }
            allAwake = every ? i : -1;
        }
    }
    INFO("the pile woke " << allAwake << " steps after the drop");
    CHECK(allAwake >= 0);
    CHECK(StepUntilAsleep(world, 900) > 0);
    CHECK(world.counts.sleepingBodies == 7);
}

TEST_CASE("With sleeping off nothing sleeps", "[world][sleep]")
{
    World world = WorldWithGravity(kGravity);
    world.settings.sleeping = false;
    AddGround(world);
    AddPyramid(world, {3, 2, 1});
    for (int i = 0; i < 600; ++i)
    {
        Step(world, kDt);
        REQUIRE(world.counts.sleepingBodies == 0);
        REQUIRE(world.counts.awakeBodies == 6);
    }
    for (const RigidBody& b : world.bodies)
    {
        CHECK(b.awake);
    }
}

TEST_CASE("The step counts add up with each saving on and off", "[world][counts]")
{
    // Four static bodies (a ground, two walls standing on it, a shelf away from everything), a sleeping pyramid
    // of 6 boxes, and 4 awake bodies falling far above it.
    World world = WorldWithGravity(kGravity);
    AddGround(world, 10.0);
    AddStatic(world, BoxShape(0.25, 2.0), {-4.0, 2.0});
    AddStatic(world, BoxShape(0.25, 2.0), {4.0, 2.0});
    AddStatic(world, BoxShape(1.0, 0.1), {20.0, 20.0});
    const int statics = 4;
    AddPyramid(world, {3, 2, 1});
    REQUIRE(StepUntilAsleep(world, 600) > 0);
    const int sleeping = 6;
    AddDynamic(world, DiscShape(0.3), {-2.0, 10.0});
    AddDynamic(world, BoxShape(0.3, 0.3), {-1.2, 10.0}); // touching the next one
    AddDynamic(world, BoxShape(0.3, 0.3), {-0.6, 10.0});
    AddDynamic(world, DiscShape(0.3), {2.0, 12.0});
    const int64_t n = static_cast<int64_t>(world.bodies.size());
    REQUIRE(n == 14);
    // Static-static pairs, and pairs of two bodies neither of them awake with at least one asleep.
    const int64_t staticPairs = PairsOf(statics);
    const int64_t sleepingPairs = PairsOf(statics + sleeping) - staticPairs;

    struct Run
    {
        bool broadphase;
        bool skipStatic;
        World world;
    };
    std::vector<Run> runs;
    for (bool broadphase : {true, false})
    {
        for (bool skipStatic : {true, false})
        {
            Run run{broadphase, skipStatic, world};
            run.world.settings.broadphase = broadphase;
            run.world.settings.skipStaticPairs = skipStatic;
            Step(run.world, kDt);
            runs.push_back(run);
        }
    }
    for (const Run& run : runs)
    {
        const StepCounts& c = run.world.counts;
        INFO("broadphase " << run.broadphase << ", skip static pairs " << run.skipStatic << ": pairs " << c.pairs
                           << ", static " << c.staticPairs << ", sleeping " << c.sleepingPairs << ", bounds apart "
                           << c.boundsApart << ", tested " << c.tested << ", touching " << c.touching);
        CHECK(c.pairs == PairsOf(n));
        CHECK(c.staticPairs + c.sleepingPairs + c.boundsApart + c.tested == c.pairs);
        CHECK(c.touching <= c.tested); // of the tested; the kept contacts of the sleeping pile are not counted
        CHECK(c.awakeBodies == 4);
        CHECK(c.sleepingBodies == 6);
        if (!run.skipStatic)
        {
            CHECK(c.staticPairs == 0);
        }
        if (!run.broadphase)
        {
            CHECK(c.boundsApart == 0);
            CHECK(c.sleepingPairs == sleepingPairs);
            CHECK(c.staticPairs == (run.skipStatic ? staticPairs : 0));
            CHECK(c.tested == c.pairs - c.staticPairs - c.sleepingPairs);
            CHECK(c.broadphaseComparisons == 0);
        }
        else
        {
            CHECK(c.boundsApart > 0);
            CHECK(c.tested < c.pairs - c.sleepingPairs - c.staticPairs);
        }
    }
    // The broadphase and the static skip save work, not contacts: the same contacts between bodies that can move
    // either way (whether two static bodies that touch make a contact is not asked).
    CHECK(runs[0].world.counts.touching >= 1); // the two falling boxes touch each other
    for (size_t i = 1; i < runs.size(); ++i)
    {
        INFO("run " << i);
        CHECK(SameContacts(MovingContacts(runs[0].world), MovingContacts(runs[i].world)));
    }
    // With static pairs tested, the ground-wall pairs reach the narrowphase.
    CHECK(runs[1].world.counts.tested >= runs[0].world.counts.tested + 2);
    CHECK(runs[3].world.counts.tested == runs[2].world.counts.tested + staticPairs);
}

TEST_CASE("A box gliding without friction on a resting box keeps their island awake and its speed",
          "[world][sleep][soft-step-fails]")
{
    // The lower box rests on the ground long enough to sleep, but the upper one, touching it, glides at 0.5: an island
    // sleeps only when every body in it has rested for timeToSleep. Without friction nothing slows the glide.
    World world = WorldWithGravity(kGravity);
    const Material ice = MakeMaterial(0.0, 0.0, 0.0);
    AddGround(world, 20.0, ice);
    const int base = AddDynamic(world, BoxShape(8.0, 0.5), {0.0, 0.5}, 0.0, {}, 0.0, ice);
    const int glider = AddDynamic(world, BoxShape(0.5, 0.5), {-4.0, 1.5}, 0.0, {0.5, 0.0}, 0.0, ice);
    // Not one body of the island sleeps at any step, not even for a step before the glider wakes it again.
    int asleep = 0;
    for (int i = 0; i < 180; ++i)
    {
        Step(world, kDt);
        asleep += world.bodies[base].awake && world.bodies[glider].awake ? 0 : 1;
    }
    INFO("after 3 s: glider at x = " << world.bodies[glider].position.x << ", speed "
                                      << world.bodies[glider].velocity.x << "; steps with a body asleep: " << asleep);
    CHECK(asleep == 0);
    CHECK(std::abs(world.bodies[glider].velocity.x - 0.5) <= 1e-6);
    CHECK(std::abs(world.bodies[glider].position.x - (-4.0 + 0.5 * world.time)) <= 1e-3);
}

TEST_CASE("A disc spinning in place on frictionless ground keeps spinning and never sleeps", "[world][sleep]")
{
    // At rest but turning at 2 rad/s: only a body slow in both its motions rests. Without friction no torque acts,
    // so the spin stays what it was.
    World world = WorldWithGravity(kGravity);
    const Material ice = MakeMaterial(0.0, 0.0, 0.0);
    AddGround(world, 20.0, ice);
    const int disc = AddDynamic(world, DiscShape(0.5), {0.0, 0.5}, 0.0, {}, 2.0, ice);
    StepN(world, 120);
    INFO("after 2 s: spin " << world.bodies[disc].angularVelocity << ", angle " << world.bodies[disc].angle);
    CHECK(world.bodies[disc].awake);
    CHECK(std::abs(world.bodies[disc].angularVelocity - 2.0) <= 1e-9);
    CHECK(std::abs(world.bodies[disc].angle - 2.0 * world.time) <= 1e-6);
}

TEST_CASE("A wheel turning in empty space keeps turning and never sleeps", "[world][sleep]")
{
    // No gravity, no contact: its centre rests but it turns at 1 rad/s, and nothing acts on it.
    World world;
    const int wheel = AddDynamic(world, BoxShape(0.5, 0.1), {1.0, 2.0}, 0.0, {}, 1.0);
    StepN(world, 120);
    INFO("after 2 s: spin " << world.bodies[wheel].angularVelocity << ", angle " << world.bodies[wheel].angle);
    CHECK(world.bodies[wheel].awake);
    CHECK(std::abs(world.bodies[wheel].angle - world.time) <= 1e-9);
}
