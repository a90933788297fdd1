// SPDX-License-Identifier: MIT
// The world's record of a step (StepTrace, and the bodies' velocities in ContactSolveTrace): recording changes no
// bit of the state; the boxes, the broadphase's pairs and the hits agree with what is computed here from the bodies.
#include "support/builders.h"
#include "support/world_scenes.h"

#include <satviz/collide.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// A pile, a ball dropped on it, and two bullets against thin walls: contacts, sleeping bodies and hits.
World BusyWorld()
{
    World world = WorldWithGravity(9.81);
    AddGround(world);
    AddPyramid(world, {3, 2, 1});
    AddDynamic(world, DiscShape(0.3), {0.2, 6.0}, 0.0, {0.0, -2.0});
    AddStatic(world, BoxShape(0.01, 2.0), {8.0, 2.0});
    AddStatic(world, BoxShape(0.01, 2.0), {-8.0, 2.0});
    AddDynamic(world, DiscShape(0.1), {6.0, 1.0}, 0.0, {400.0, 0.0}, 0.0, MakeMaterial(0.8, 0.2, 0.2));
    AddDynamic(world, BoxShape(0.2, 0.05), {-6.0, 1.5}, 0.3, {-300.0, 5.0}, 40.0, MakeMaterial(0.5, 0.3, 0.3));
    return world;
}

bool Inside(const Aabb& outer, const Aabb& inner)
{
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && inner.max.x <= outer.max.x &&
           inner.max.y <= outer.max.y;
}

} // namespace

TEST_CASE("Stepping with the step's record on and off gives the same bits", "[world][trace][determinism]")
{
    World world = BusyWorld();
    World traced = world;
    StepTrace record;
    ContactSolveTrace contact;
    contact.bodyA = 0;
    contact.bodyB = 1;
    traced.stepTrace = &record;
    traced.trace = &contact;
    int64_t hits = 0;
    for (int i = 0; i < 240; ++i)
    {
        Step(world, kDt);
        Step(traced, kDt);
        hits += static_cast<int64_t>(record.hits.size());
        REQUIRE(SameState(world, traced));
    }
    CHECK(hits > 0);
}

TEST_CASE("The step's record: grown boxes, the broadphase's pairs and the hits, against the bodies", "[world][trace]")
{
    World world = BusyWorld();
    StepTrace record;
    world.stepTrace = &record;
    int64_t hitsSeen = 0;
    int sleepingSeen = 0;
    for (int step = 0; step < 240; ++step)
    {
        const World before = world;
        Step(world, kDt);
        INFO("step " << step + 1);
        const size_t n = world.bodies.size();
        REQUIRE(record.bounds.size() == n);
        REQUIRE(record.grow.size() == n);
        // Each box holds the body's own box at the start of the step, grown by the recorded amount on every side.
        for (size_t i = 0; i < n; ++i)
        {
            const Aabb own = ComputeAabb(before.bodies[i].shape, before.bodies[i].Xf());
            CHECK(record.grow[i] >= 0.0);
            CHECK(record.bounds[i].min.x == Approx(own.min.x - record.grow[i]).margin(1e-12));
            CHECK(record.bounds[i].max.y == Approx(own.max.y + record.grow[i]).margin(1e-12));
            CHECK(Inside(record.bounds[i], own));
        }
        // The pairs are exactly those whose boxes overlap, less static pairs and pairs with no awake body.
        std::set<std::pair<int, int>> expected;
        for (int i = 0; i < static_cast<int>(n); ++i)
        {
            for (int j = i + 1; j < static_cast<int>(n); ++j)
            {
                const RigidBody& a = before.bodies[static_cast<size_t>(i)];
                const RigidBody& b = before.bodies[static_cast<size_t>(j)];
                const bool awake = (a.type == BodyType::Dynamic && a.awake) || (b.type == BodyType::Dynamic && b.awake);
                if (awake && AabbOverlap(record.bounds[static_cast<size_t>(i)], record.bounds[static_cast<size_t>(j)]))
                {
                    expected.insert({i, j});
                }
            }
            sleepingSeen += before.bodies[static_cast<size_t>(i)].type == BodyType::Dynamic &&
                            !before.bodies[static_cast<size_t>(i)].awake;
        }
        const std::set<std::pair<int, int>> found(record.candidates.begin(), record.candidates.end());
        CHECK(found == expected);
        CHECK(static_cast<int64_t>(record.candidates.size()) == world.counts.tested);
        // The hits: as many as counted, in time order, the bodies touching in the recorded poses, and a hit between
        // two dynamic bodies keeps their momentum.
        REQUIRE(static_cast<int64_t>(record.hits.size()) == world.counts.hits);
        for (size_t h = 0; h < record.hits.size(); ++h)
        {
            const StepHit& hit = record.hits[h];
            CHECK(hit.a < hit.b);
            CHECK(hit.time >= 0.0);
            CHECK(hit.time <= 1.0);
            CHECK(Length(hit.normal) == Approx(1.0).epsilon(1e-9));
            if (h > 0)
            {
                CHECK(hit.time >= record.hits[h - 1].time);
            }
            const RigidBody& a = world.bodies[static_cast<size_t>(hit.a)];
            const RigidBody& b = world.bodies[static_cast<size_t>(hit.b)];
            const Manifold m = CollideWithin(a.shape, MakeTransform(hit.position[0], hit.angle[0]), b.shape,
                                             MakeTransform(hit.position[1], hit.angle[1]), 0.1);
            REQUIRE(m.contactCount > 0);
            double gap = INFINITY;
            for (int k = 0; k < m.contactCount; ++k)
            {
                gap = std::min(gap, m.contacts[k].separation);
            }
            CHECK(std::fabs(gap) <= 2.0 * world.settings.linearSlop);
            if (a.type == BodyType::Dynamic && b.type == BodyType::Dynamic)
            {
                const Vec2 p0 = a.mass * hit.velocityBefore[0] + b.mass * hit.velocityBefore[1];
                const Vec2 p1 = a.mass * hit.velocityAfter[0] + b.mass * hit.velocityAfter[1];
                CHECK(Length(p1 - p0) <= 1e-9 * (1.0 + Length(p0)));
            }
            ++hitsSeen;
        }
    }
    CHECK(hitsSeen > 0);
    CHECK(sleepingSeen > 0);
}

TEST_CASE("The solver's record of a lone contact: each body's velocity after is before, plus gravity, plus the "
          "impulses over its mass",
          "[world][trace]")
{
    // A box sliding on the ground: one contact, two points, friction at the dynamic limit.
    World world = WorldWithGravity(9.81);
    AddGround(world);
    const int box = AddDynamic(world, BoxShape(0.25, 0.25), {0.0, 0.25 - 0.002}, 0.0, {3.0, 0.0});
    ContactSolveTrace trace;
    trace.bodyA = box;
    trace.bodyB = 0;
    world.trace = &trace;
    StepN(world, 3);
    REQUIRE(trace.found);
    const RigidBody& body = world.bodies[static_cast<size_t>(box)];
    // The ground is the lower index: index 0 of the record, at rest.
    CHECK(trace.velocityBefore[0].x == 0.0);
    CHECK(trace.velocityAfter[0].y == 0.0);
    // The accumulated impulses: the last pass's per point, plus the restitution's.
    Vec2 impulse{};
    const Vec2 n = trace.normal;
    const Vec2 t{n.y, -n.x};
    std::vector<const ContactPointSolve*> last(static_cast<size_t>(trace.pointCount), nullptr);
    for (const ContactPointSolve& pass : trace.passes)
    {
        last[static_cast<size_t>(pass.point)] = &pass;
    }
    for (int p = 0; p < trace.pointCount; ++p)
    {
        const ContactPointSolve& s = *last[static_cast<size_t>(p)];
        const Vec2 P = (s.normalImpulse + trace.restitutionImpulse[p]) * n + s.tangentImpulse * t;
        impulse = impulse + P;
    }
    // The box (index 1) receives +P along the normal from the ground to it.
    const Vec2 expected = trace.velocityBefore[1] + kDt * world.settings.gravity + body.invMass * impulse;
    CHECK(trace.velocityAfter[1].x == Approx(expected.x).epsilon(1e-9));
    CHECK(trace.velocityAfter[1].y == Approx(expected.y).margin(1e-9));
    CHECK(trace.velocityAfter[1].x < trace.velocityBefore[1].x);
}
