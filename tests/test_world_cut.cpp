// SPDX-License-Identifier: MIT
// Cutting a body of the world: the parts' mass, centre and inertia against the shoelace sums of their outlines
// (long double, not the library's mass code), and the body's momentum and angular momentum kept (less what the
// dropped slivers carried), over random convex and concave bodies cut along random segments.

#include "support/random_concave.h"

#include <satviz/decompose.h>
#include <satviz/world.h>
#include <satviz/world_cut.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

// Mass properties of a simple outline of unit density by the shoelace sums, in long double, about the origin of
// its frame, then moved to the centroid.
struct OracleMass
{
    long double area = 0;
    long double cx = 0;
    long double cy = 0;
    long double inertia = 0; // about the centroid
};

OracleMass Oracle(const std::vector<Vec2>& p)
{
    long double a2 = 0, fx = 0, fy = 0, second = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const long double x0 = p[i].x, y0 = p[i].y;
        const long double x1 = p[(i + 1) % p.size()].x, y1 = p[(i + 1) % p.size()].y;
        const long double c = x0 * y1 - x1 * y0;
        a2 += c;
        fx += c * (x0 + x1);
        fy += c * (y0 + y1);
        second += c * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1);
    }
    OracleMass m;
    m.area = a2 / 2;
    m.cx = fx / (3 * a2);
    m.cy = fy / (3 * a2);
    m.inertia = second / 12 - m.area * (m.cx * m.cx + m.cy * m.cy);
    return m;
}

// A body of `outline` (decomposed when concave) at a random place, moving and turning.
BodyDef RandomBody(Rng& rng, const std::vector<Vec2>& outline)
{
    BodyDef def;
    const Decomposition d = Decompose(outline, DecomposeMethod::Fast);
    INFO(DescribeDecomposeError(d, outline));
    REQUIRE(d.Ok());
    if (d.pieces.size() == 1)
    {
        def.shape = MakeShape(d.pieces[0].polygon);
    }
    else
    {
        def.concave = MakeConcave(d.pieces);
    }
    def.position = {rng.Uniform(-50, 50), rng.Uniform(-50, 50)};
    def.angle = rng.Uniform(-4, 4);
    def.velocity = {rng.Uniform(-10, 10), rng.Uniform(-10, 10)};
    def.angularVelocity = rng.Uniform(-5, 5);
    def.density = rng.LogUniform(-1, 1);
    return def;
}

double Rel(long double got, long double want)
{
    return static_cast<double>(std::fabs(got - want) / std::max<long double>(std::fabs(want), 1e-300L));
}

} // namespace

TEST_CASE("A spinning box cut in two: each half's mass, centre, inertia and velocity by hand", "[world][cut]")
{
    World world;
    BodyDef def;
    def.shape = MakeShape(MakeBox(1.0, 0.5).polygon);
    def.position = {3, 1};
    def.velocity = {1, 0};
    def.angularVelocity = 2;
    def.density = 3;
    AddBody(world, def);
    BodyDef ground;
    ground.shape = MakeShape(MakeBox(5.0, 0.5).polygon);
    ground.type = BodyType::Static;
    ground.position = {0, -5};
    AddBody(world, ground);

    // A vertical cut through the centre, longer than the box.
    const BodyCut cut = CutBody(world, 0, {3, -2}, {3, 4});
    REQUIRE(cut.cut);
    REQUIRE(cut.bodies == std::vector<int>{0, 2});
    REQUIRE(world.bodies.size() == 3);
    CHECK(world.bodies[1].type == BodyType::Static); // the ground keeps its index
    CHECK(cut.slivers == 0);
    for (int i : cut.bodies)
    {
        const RigidBody& half = world.bodies[static_cast<size_t>(i)];
        // A 1 x 1 square of density 3: mass 3, inertia m (1 + 1) / 12 = 0.5, centre 0.5 from the cut.
        CHECK(half.mass == Approx(3.0).epsilon(1e-14));
        CHECK(half.inertia == Approx(0.5).epsilon(1e-13));
        CHECK(half.position == Vec2{3, 1});
        const Vec2 c = half.WorldCenter();
        CHECK(std::fabs(c.y - 1) < 1e-14);
        CHECK(std::fabs(std::fabs(c.x - 3) - 0.5) < 1e-14);
        // v + w x r: r = (+-0.5, 0) gives (1, +-1).
        CHECK(half.velocity.x == Approx(1.0));
        CHECK(half.velocity.y == Approx(2.0 * (c.x - 3)));
        CHECK(half.angularVelocity == 2.0);
    }
}

TEST_CASE("Random bodies cut along random segments keep their area, mass and motion", "[world][cut]")
{
    Rng rng(4242);
    int cuts = 0, concaveCuts = 0, withSlivers = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        INFO("trial " << trial);
        std::vector<Vec2> outline;
        switch (trial % 3)
        {
        case 0: {
            const Polygon p = RandomPolygon(rng, rng.Int(3, 12), rng.Uniform(0.5, 3), rng.Uniform(0.2, 1));
            outline.assign(p.Vertices().begin(), p.Vertices().end());
            break;
        }
        case 1: outline = RandomStarPolygon(rng, rng.Int(4, 30), rng.Uniform(0.5, 3), 0.2); break;
        default: outline = RandomUntangledPolygon(rng, rng.Int(4, 20), rng.Uniform(0.5, 3)); break;
        }
        if (!Decompose(outline, DecomposeMethod::Fast).Ok())
        {
            continue; // an untangled outline may touch itself; the world takes simple ones only
        }
        if (Area2(outline) < 0)
        {
            std::reverse(outline.begin(), outline.end());
        }
        World world;
        const BodyDef def = RandomBody(rng, outline);
        AddBody(world, def);
        const RigidBody before = world.bodies[0];
        const Vec2 origin{rng.Uniform(-100, 100), rng.Uniform(-100, 100)};
        const Vec2 momentum = LinearMomentum(world);
        const double spin = AngularMomentum(world, origin);
        const double mass = before.mass;
        const double energy = KineticEnergy(world);

        // A segment through a random point of the body's box, usually longer than the body.
        const Transform xf = before.Xf();
        const Vec2 inside = TransformPoint(xf, outline[static_cast<size_t>(rng.Int(0, int(outline.size()) - 1))]);
        const Vec2 towards = TransformPoint(xf, outline[static_cast<size_t>(rng.Int(0, int(outline.size()) - 1))]);
        const Vec2 mid = 0.5 * (inside + towards) + Vec2{rng.Uniform(-0.2, 0.2), rng.Uniform(-0.2, 0.2)};
        const double turn = rng.Uniform(0, 2 * kPi);
        const double reach = rng.Chance(0.8) ? 20.0 : rng.Uniform(0.1, 2.0);
        const Vec2 d{std::cos(turn) * reach, std::sin(turn) * reach};
        CutOptions options;
        options.minArea = rng.Chance(0.5) ? kMinCutArea : rng.Uniform(0.0, 0.3);
        const BodyCut cut = CutBody(world, 0, mid - d, mid + d, options);
        if (!cut.cut)
        {
            // Nothing changed.
            REQUIRE(world.bodies.size() == 1);
            CHECK(world.bodies[0].mass == mass);
            CHECK(!cut.reason.empty());
            continue;
        }
        ++cuts;
        concaveCuts += before.IsConcave();
        withSlivers += cut.slivers > 0;
        REQUIRE(cut.bodies.size() >= 2);
        REQUIRE(cut.outlines.size() == cut.bodies.size());
        REQUIRE(world.bodies.size() == cut.bodies.size());

        // Each part against the shoelace sums of its own outline.
        const long double density = static_cast<long double>(before.mass) / Oracle(outline).area;
        long double keptArea = 0;
        for (size_t k = 0; k < cut.bodies.size(); ++k)
        {
            const RigidBody& part = world.bodies[static_cast<size_t>(cut.bodies[k])];
            const OracleMass m = Oracle(cut.outlines[k]);
            CHECK(m.area >= options.minArea);
            keptArea += m.area;
            CHECK(Rel(part.mass, density * m.area) < 1e-11);
            CHECK(Rel(part.inertia, density * m.inertia) < 1e-9);
            const double scale = std::sqrt(static_cast<double>(m.area));
            CHECK(std::fabs(part.localCenter.x - static_cast<double>(m.cx)) < 1e-10 * (1 + scale));
            CHECK(std::fabs(part.localCenter.y - static_cast<double>(m.cy)) < 1e-10 * (1 + scale));
            CHECK(part.position == before.position);
            CHECK(part.angle == before.angle);
            CHECK(part.angularVelocity == before.angularVelocity);
            // Its outline is the body's outline in its own frame.
            const std::vector<Vec2> traced = BodyOutline(part);
            CHECK(std::fabs(static_cast<double>(Area2(traced) / 2 - m.area)) < 1e-12 * (1 + double(m.area)));
        }
        // The parts and slivers tile the body: no area made or lost.
        const long double area = Oracle(outline).area;
        const long double sliverArea = cut.sliverMass / density;
        CHECK(Rel(keptArea + sliverArea, area) < 1e-11);
        if (cut.slivers == 0)
        {
            CHECK(cut.sliverMass == 0.0);
        }
        // Momentum and angular momentum about a fixed point: the kept bodies' plus the slivers' are the body's.
        const Vec2 after = LinearMomentum(world);
        const double scaleP = mass * (Length(before.velocity) + std::fabs(before.angularVelocity) * 3 + 1);
        CHECK(std::fabs(after.x + cut.sliverMomentum.x - momentum.x) < 1e-10 * scaleP);
        CHECK(std::fabs(after.y + cut.sliverMomentum.y - momentum.y) < 1e-10 * scaleP);
        const Vec2 c = before.WorldCenter();
        const double sliverAboutOrigin = cut.sliverSpin + Cross(c - origin, cut.sliverMomentum);
        const double scaleL = scaleP * (Length(c - origin) + 3);
        CHECK(std::fabs(AngularMomentum(world, origin) + sliverAboutOrigin - spin) < 1e-10 * scaleL);
        // The kinetic energy cannot grow: the same rigid motion, less the slivers' share.
        CHECK(KineticEnergy(world) <= energy * (1 + 1e-12) + 1e-300);
    }
    CHECK(cuts > 1000);
    CHECK(concaveCuts > 500);
    CHECK(withSlivers > 10);
}

TEST_CASE("A cut that leaves only a sliver, a circle and a segment that stops inside leave the body whole",
          "[world][cut]")
{
    World world;
    BodyDef box;
    box.shape = MakeShape(MakeBox(1.0, 1.0).polygon);
    AddBody(world, box);
    BodyDef ball;
    ball.shape = MakeShape(Circle{{0, 0}, 1.0});
    ball.position = {5, 0};
    AddBody(world, ball);

    CutOptions options;
    options.minArea = 0.05;
    // A corner cut off, of area 0.02 * 0.02 / 2.
    BodyCut cut = CutBody(world, 0, {0.5, 1.48}, {1.48, 0.5}, options);
    CHECK(!cut.cut);
    CHECK(world.bodies.size() == 2);
    // A slit: the segment ends inside.
    cut = CutBody(world, 0, {-2, 0}, {0.5, 0});
    CHECK(!cut.cut);
    CHECK(cut.reason == "the segment does not cut the body from side to side");
    cut = CutBody(world, 1, {5, -3}, {5, 3});
    CHECK(!cut.cut);
    CHECK(cut.reason == "a circle cannot be cut");
    cut = CutBody(world, 2, {5, -3}, {5, 3});
    CHECK(!cut.cut);
    CHECK(world.bodies.size() == 2);
}

TEST_CASE("A comb cut across its teeth drops the thin tip of its short tooth and reports the mass it took",
          "[world][cut]")
{
    // Two teeth reach 4; the middle one only 2.0005, so the cut at 2 leaves it a tip 1 x 0.0005: below kMinCutArea.
    const std::vector<Vec2> comb{{0, 0}, {5, 0}, {5, 4}, {4, 4}, {4, 1},      {3, 1},
                                 {3, 2.0005}, {2, 2.0005}, {2, 1}, {1, 1}, {1, 4}, {0, 4}};
    World world;
    BodyDef def;
    const Decomposition d = Decompose(comb, DecomposeMethod::Fast);
    REQUIRE(d.Ok());
    def.concave = MakeConcave(d.pieces);
    def.velocity = {0, -1};
    def.density = 2;
    AddBody(world, def);
    const double mass = world.bodies[0].mass;
    CHECK(mass == Approx(2 * (5 + 3 * 2 + 1.0005)));
    const BodyCut cut = CutBody(world, 0, {-1, 2}, {6, 2});
    REQUIRE(cut.cut);
    // The base with the short tooth's stump, and the two long teeth's tops (1 x 2 each).
    REQUIRE(cut.bodies.size() == 3);
    CHECK(cut.slivers == 1);
    CHECK(cut.sliverMass == Approx(2 * 0.0005).epsilon(1e-9));
    CHECK(cut.sliverMomentum.y == Approx(-2 * 0.0005).epsilon(1e-9));
    double total = 0;
    for (int i : cut.bodies)
    {
        total += world.bodies[static_cast<size_t>(i)].mass;
    }
    CHECK(total + cut.sliverMass == Approx(mass).epsilon(1e-14));
    CHECK(world.bodies[static_cast<size_t>(cut.bodies[1])].mass == Approx(4.0).epsilon(1e-14));
    CHECK(world.bodies[static_cast<size_t>(cut.bodies[2])].mass == Approx(4.0).epsilon(1e-14));
}

TEST_CASE("Cutting the plank under a sleeping box wakes the box, drops the plank's contacts, and the halves fall",
          "[world][cut]")
{
    World world;
    world.settings.gravity = {0, -10};
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = MakeShape(MakeBox(10.0, 0.5).polygon);
    ground.position = {0, -0.5};
    AddBody(world, ground);
    BodyDef plank;
    plank.shape = MakeShape(MakeBox(2.0, 0.25).polygon);
    plank.position = {0, 0.25};
    AddBody(world, plank);
    BodyDef box;
    box.shape = MakeShape(MakeBox(0.25, 0.25).polygon);
    box.position = {1, 0.75};
    AddBody(world, box);
    for (int i = 0; i < 300; ++i)
    {
        Step(world, 1.0 / 60.0);
    }
    REQUIRE(!world.bodies[2].awake);
    const BodyCut cut = CutBody(world, 1, {0, 5}, {0, -0.2});
    REQUIRE(cut.cut);
    CHECK(world.bodies[2].awake);
    for (const WorldContact& contact : world.contacts)
    {
        CHECK(contact.a != 1);
        CHECK(contact.b != 1);
    }
    for (int i = 0; i < 120; ++i)
    {
        Step(world, 1.0 / 60.0);
    }
    // Both halves still rest on the ground, side by side, and the box on the right half.
    for (int i : cut.bodies)
    {
        const RigidBody& half = world.bodies[static_cast<size_t>(i)];
        CHECK(std::fabs(half.WorldCenter().y - 0.25) < 0.02);
    }
    CHECK(std::fabs(world.bodies[2].position.y - 0.75) < 0.02);
}
