// SPDX-License-Identifier: MIT
// Concave bodies in the world: mass properties against the shoelace sums of the outline, an L and a U that fall
// and rest, a box sliding over a floor of pieces against the same box on one convex floor, a box in an L's notch,
// a fast concave body against a thin wall and a post, and momentum in a free collision of two concave bodies.

#include "support/random_concave.h"
#include "support/world_scenes.h"

#include <satviz/concave.h>
#include <satviz/decompose.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

const std::vector<Vec2> kL = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
const std::vector<Vec2> kU = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

Concave ConcaveOf(const std::vector<Vec2>& outline, DecomposeMethod method = DecomposeMethod::Fast)
{
    const Decomposition d = Decompose(outline, method);
    REQUIRE(d.Ok());
    REQUIRE(d.pieces.size() >= 2);
    return MakeConcave(d.pieces);
}

int AddConcave(World& world, const Concave& concave, BodyType type, Vec2 position, double angle = 0.0,
               Vec2 velocity = {}, double angularVelocity = 0.0, Material material = Material{})
{
    BodyDef def;
    def.concave = concave;
    def.type = type;
    def.position = position;
    def.angle = angle;
    def.velocity = velocity;
    def.angularVelocity = angularVelocity;
    def.material = material;
    REQUIRE(ValidateBodyDef(def).empty());
    return AddBody(world, def);
}

Shape Box(double hx, double hy)
{
    return MakeShape(MakeBox(hx, hy).polygon);
}

// The deepest overlap between a body and another, piece against piece, measured by the convex Collide: an
// independent check of what the concave manifold merged.
double DeepestOverlap(const World& world, int i, int j)
{
    const auto partsOf = [](const RigidBody& body) {
        std::vector<const Shape*> parts;
        if (body.IsConcave())
        {
            for (const ConcavePart& part : body.concave.parts)
            {
                parts.push_back(&part.shape);
            }
        }
        else
        {
            parts.push_back(&body.shape);
        }
        return parts;
    };
    const RigidBody& a = world.bodies[static_cast<size_t>(i)];
    const RigidBody& b = world.bodies[static_cast<size_t>(j)];
    double deepest = 0.0;
    for (const Shape* pa : partsOf(a))
    {
        for (const Shape* pb : partsOf(b))
        {
            const Manifold m = Collide(*pa, a.Xf(), *pb, b.Xf());
            if (m.overlap)
            {
                deepest = std::max(deepest, m.depth);
            }
        }
    }
    return deepest;
}

// The lowest point of a body's outline in world space.
double Bottom(const RigidBody& body)
{
    double low = INFINITY;
    for (const ConcavePart& part : body.concave.parts)
    {
        for (const Vec2& v : part.shape.polygon.Vertices())
        {
            low = std::min(low, TransformPoint(body.Xf(), v).y);
        }
    }
    return low;
}

} // namespace

TEST_CASE("A concave body's mass, centre and inertia are those of its outline", "[world][concave]")
{
    for (const std::vector<Vec2>* outline : {&kL, &kU})
    {
        for (const DecomposeMethod method : {DecomposeMethod::Fast, DecomposeMethod::Fewest})
        {
            // The oracle: shoelace sums over the outline in long double (area, first moments, polar second moment
            // about the origin), moved to the centroid by the parallel-axis theorem. No pieces involved.
            const double density = 2.5;
            long double area2 = 0, sx = 0, sy = 0, polar = 0;
            const size_t n = outline->size();
            for (size_t k = 0; k < n; ++k)
            {
                const long double px = (*outline)[k].x, py = (*outline)[k].y;
                const long double qx = (*outline)[(k + 1) % n].x, qy = (*outline)[(k + 1) % n].y;
                const long double cross = px * qy - qx * py;
                area2 += cross;
                sx += (px + qx) * cross;
                sy += (py + qy) * cross;
                polar += cross * (px * px + px * qx + qx * qx + py * py + py * qy + qy * qy);
            }
            const long double mass = density * area2 / 2;
            const long double cx = sx / (3 * area2), cy = sy / (3 * area2);
            const long double inertia = density * polar / 12 - mass * (cx * cx + cy * cy);

            World world;
            BodyDef def;
            def.concave = ConcaveOf(*outline, method);
            def.density = density;
            const int i = AddBody(world, def);
            const RigidBody& body = world.bodies[static_cast<size_t>(i)];
            CHECK(body.mass == Approx(static_cast<double>(mass)).epsilon(1e-13));
            CHECK(body.localCenter.x == Approx(static_cast<double>(cx)).epsilon(1e-13));
            CHECK(body.localCenter.y == Approx(static_cast<double>(cy)).epsilon(1e-13));
            CHECK(body.inertia == Approx(static_cast<double>(inertia)).epsilon(1e-12));
            CHECK(body.invMass == Approx(1.0 / body.mass));
            // The hull bounds every piece: the broadphase box holds the body.
            for (const ConcavePart& part : body.concave.parts)
            {
                for (const Vec2& v : part.shape.polygon.Vertices())
                {
                    for (int e = 0; e < body.shape.polygon.Count(); ++e)
                    {
                        CHECK(Dot(body.shape.polygon.Normal(e), v - body.shape.polygon.Vertices()[e]) <= 1e-12);
                    }
                }
            }
        }
    }
}

TEST_CASE("An L and a U fall on the floor and come to rest on it", "[world][concave]")
{
    for (const std::vector<Vec2>* outline : {&kL, &kU})
    {
        World world;
        world.settings.gravity = {0, -kGravity};
        const int floor = AddStatic(world, Box(10, 0.5), {0, -0.5});
        // Tilted, so that it lands on a corner, turns and settles on a side.
        const int body = AddConcave(world, ConcaveOf(*outline), BodyType::Dynamic, {-1.5, 2.0}, 0.3);
        double deepest = 0.0;
        for (int step = 0; step < 600; ++step)
        {
            Step(world, kDt);
            deepest = std::max(deepest, DeepestOverlap(world, floor, body));
        }
        const RigidBody& b = world.bodies[static_cast<size_t>(body)];
        INFO("outline of " << outline->size() << " vertices, rests at angle " << b.angle);
        CHECK(Length(b.velocity) < 0.05);
        CHECK(std::abs(b.angularVelocity) < 0.05);
        // Resting on the floor's top (y = 0), no deeper than the slop and a little for the landing.
        CHECK(Bottom(b) > -2.0 * world.settings.linearSlop);
        CHECK(Bottom(b) < world.settings.linearSlop);
        CHECK(DeepestOverlap(world, floor, body) <= 2.0 * world.settings.linearSlop);
        CHECK(deepest < 0.05);
        // At rest, its centre of mass lies above its support: a flat side down, the angle a multiple of 90
        // degrees.
        const double quarter = b.angle / (0.5 * 3.14159265358979323846);
        CHECK(std::abs(quarter - std::round(quarter)) < 0.01);
    }
}

TEST_CASE("A box slides over a floor of pieces as over one convex floor, without catching on the seams",
          "[world][concave][soft-step-fails]")
{
    // The same box, pushed along the same floor top (y = 0): one run on a floor of ten unit tiles whose sides are
    // seams, one on a single convex floor. Coulomb's law says the speed falls by mu g dt each step, smoothly.
    const double mu = 0.3;
    const Material material = MakeMaterial(0.0, mu, mu);
    const auto run = [&](bool tiles) {
        World world;
        world.settings.gravity = {0, -kGravity};
        if (tiles)
        {
            AddConcave(world, TileFloor(10), BodyType::Static, {0, 0}, 0.0, {}, 0.0, material);
        }
        else
        {
            AddStatic(world, Box(5, 0.5), {5, -0.5}, 0.0, material);
        }
        const int box = AddDynamic(world, Box(0.25, 0.25), {0.5, 0.25}, 0.0, {4, 0}, 0.0, material);
        std::vector<Vec2> velocities;
        std::vector<double> xs;
        for (int step = 0; step < 120; ++step)
        {
            Step(world, kDt);
            velocities.push_back(world.bodies[static_cast<size_t>(box)].velocity);
            xs.push_back(world.bodies[static_cast<size_t>(box)].position.x);
        }
        return std::make_pair(velocities, xs);
    };
    const auto [tiled, tiledX] = run(true);
    const auto [single, singleX] = run(false);
    // It crosses at least two seams (x = 1 and x = 2) before it stops.
    REQUIRE(tiledX.back() > 2.5);
    const double drop = mu * kGravity * kDt;
    for (size_t k = 0; k < tiled.size(); ++k)
    {
        INFO("step " << k + 1 << " at x " << tiledX[k] << ": vx " << tiled[k].x << " against " << single[k].x);
        CHECK(std::abs(tiled[k].y) < 1e-3);
        // Once friction has stopped it (it comes to rest across the seam at x = 3), the solver leaves a creep of
        // rounding, on either floor.
        if (single[k].x < drop)
        {
            CHECK(std::abs(tiled[k].x - single[k].x) < 1e-3);
            continue;
        }
        CHECK(std::abs(tiled[k].x - single[k].x) < 1e-6);
        if (k > 0)
        {
            // Never faster, and never slowed by more than friction can: a seam that caught would stop it at once.
            CHECK(tiled[k].x <= tiled[k - 1].x + 1e-12);
            CHECK(tiled[k - 1].x - tiled[k].x <= drop * (1.0 + 1e-6) + 1e-12);
        }
    }
}

TEST_CASE("A box dropped into an L's notch rests in it, where the hull would hold it above", "[world][concave]")
{
    World world;
    world.settings.gravity = {0, -kGravity};
    const int l = AddConcave(world, ConcaveOf(kL), BodyType::Static, {0, 0});
    const int box = AddDynamic(world, Box(0.25, 0.25), {1.5, 3.5});
    for (int step = 0; step < 300; ++step)
    {
        Step(world, kDt);
    }
    const RigidBody& b = world.bodies[static_cast<size_t>(box)];
    // On the L's foot (its top at y = 1): the centre 0.25 above it. The hull's slanted face x + y = 4 would hold
    // the box's lower right corner (x = 1.75) at y = 2.25, its centre at 2.5.
    CHECK(b.position.x == Approx(1.5).margin(0.01));
    CHECK(b.position.y == Approx(1.25).margin(2.0 * world.settings.linearSlop));
    CHECK(Length(b.velocity) < 0.05);
    CHECK(DeepestOverlap(world, l, box) <= 2.0 * world.settings.linearSlop);
}

TEST_CASE("A fast concave body does not pass through a thin wall, and a post enters its notch", "[world][concave]")
{
    SECTION("thin wall")
    {
        // The U moves 5 units a step; the wall is 0.05 thick. No gravity.
        World world;
        const int wall = AddStatic(world, Box(0.025, 5), {10, 0});
        const int u = AddConcave(world, ConcaveOf(kU), BodyType::Dynamic, {0, -1}, 0.0, {300, 0});
        for (int step = 0; step < 30; ++step)
        {
            Step(world, kDt);
            const RigidBody& b = world.bodies[static_cast<size_t>(u)];
            INFO("step " << step + 1);
            REQUIRE(b.WorldCenter().x < 10.0);
            REQUIRE(DeepestOverlap(world, wall, u) <= 2.0 * world.settings.linearSlop);
        }
        // Stopped (restitution 0) with its right side (x = 3 in its frame) at the wall's left face (x = 9.975).
        const RigidBody& b = world.bodies[static_cast<size_t>(u)];
        CHECK(b.velocity.x <= 1e-9);
        CHECK(b.position.x + 3.0 == Approx(9.975).margin(2.0 * world.settings.linearSlop));
    }
    SECTION("post in the notch")
    {
        // The U, opening upward, moves up at 5 units a step at a thin post above its notch (x in [1, 2] of the U,
        // from y = 1 to its arms' tips at y = 2). Swept piece by piece, the post passes between the arms and stops
        // the U at the notch's floor; swept as its hull, the U would stop with its arms' tips at the post.
        World world;
        const int post = AddStatic(world, Box(0.05, 0.5), {1.5, 8});
        const int u = AddConcave(world, ConcaveOf(kU), BodyType::Dynamic, {0, 0}, 0.0, {0, 300});
        for (int step = 0; step < 3; ++step)
        {
            Step(world, kDt);
        }
        const RigidBody& b = world.bodies[static_cast<size_t>(u)];
        // The notch's floor (y = 1 in the U's frame) at the post's bottom (y = 7.5): the U's origin at 6.5; the
        // hull would have stopped it at 5.5.
        CHECK(b.position.y == Approx(6.5).margin(2.0 * world.settings.linearSlop));
        CHECK(b.position.x == Approx(0.0).margin(1e-9));
        CHECK(DeepestOverlap(world, post, u) <= 2.0 * world.settings.linearSlop);
    }
}

TEST_CASE("Two concave bodies collide freely and keep their momentum", "[world][concave]")
{
    World world;
    const Material bouncy = MakeMaterial(0.5, 0.4, 0.4);
    const int a = AddConcave(world, ConcaveOf(kL), BodyType::Dynamic, {-4, 0}, 0.2, {3, 0.2}, 0.5, bouncy);
    const int b =
        AddConcave(world, ConcaveOf(kU, DecomposeMethod::Fewest), BodyType::Dynamic, {3, 0.5}, -0.4, {-2, 0}, -1.0,
                   bouncy);
    const Vec2 p0 = LinearMomentum(world);
    const double l0 = AngularMomentum(world, {0, 0});
    const Vec2 va0 = world.bodies[static_cast<size_t>(a)].velocity;
    for (int step = 0; step < 120; ++step)
    {
        Step(world, kDt);
    }
    // They met: A's velocity changed.
    REQUIRE(Length(world.bodies[static_cast<size_t>(a)].velocity - va0) > 0.5);
    const Vec2 p1 = LinearMomentum(world);
    const double scale = Length(p0) + 1.0;
    CHECK(std::abs(p1.x - p0.x) <= 1e-9 * scale);
    CHECK(std::abs(p1.y - p0.y) <= 1e-9 * scale);
    // The position passes move bodies without impulses: angular momentum about a fixed point is kept by the
    // impulses to rounding, and the passes shift the centres by at most the overlap they remove.
    CHECK(AngularMomentum(world, {0, 0}) == Approx(l0).epsilon(1e-6).margin(1e-6));
    CHECK(DeepestOverlap(world, a, b) <= 2.0 * world.settings.linearSlop);
}
