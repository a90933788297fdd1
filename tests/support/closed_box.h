// SPDX-License-Identifier: MIT
// Worlds of fast bodies shut in a closed box of four static walls, built from any source of random draws (a seeded
// generator in the property tests, the fuzzer's bytes in the fuzz target), and the checks they must pass after
// every step: nothing is lost, nothing passes through a wall, nothing becomes NaN.
#pragma once

#include <satviz/collide.h>
#include <satviz/mass.h>
#include <satviz/polygon.h>
#include <satviz/world.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace satviz::testing
{

/// The interior of the box is [-halfWidth, halfWidth] x [-halfHeight, halfHeight]; the walls around it are `wall`
/// thick and overlap at the corners, so the box has no gap.
struct ClosedBox
{
    double halfWidth = 5.0;  ///< half the interior's width
    double halfHeight = 3.0; ///< half the interior's height
    double wall = 0.01;      ///< thickness of the walls
    int firstBody = 4;       ///< bodies before this index are the walls (and static obstacles follow them)
};

/// What a scene of fast bodies in a closed box is drawn from. Each field is a range the draws fall in.
struct ClosedBoxRanges
{
    int minBodies = 1;         ///< at least this many dynamic bodies (fewer when the box has no room left)
    int maxBodies = 20;        ///< at most this many dynamic bodies
    double maxSpeed = 1e5;     ///< in units per step, drawn log-uniformly from 0.01, for a lone body
    double crowdMaxSpeed = 50; ///< the same for the bodies of a crowd: 3000 units per time unit at dt 1/60
    double maxSpin = 600.0;    ///< radians per time unit, drawn log-uniformly from 0.01
    double minSize = 0.05;     ///< smallest radius of a body
    double maxSize = 0.5;      ///< largest radius of a body
    /// Thinnest body, as its inner radius: five times the world's slop. A resting contact keeps a slop of overlap,
    /// so the centre of a body not much thicker than that lies at the face of what it rests on.
    double minInner = 0.025;
    double dt = 1.0 / 60.0;    ///< the step
    bool allowObstacle = true; ///< sometimes a static post stands in the box
};

/// The scene's world and its box.
struct ClosedBoxScene
{
    World world;            ///< the walls, perhaps a post, and the dynamic bodies
    ClosedBox box;          ///< the box the bodies must stay in
    double dt = 0.0;        ///< the step to take
    bool inelastic = false; ///< every restitution is 0: the energy may only fall (up to EnergyBand)
};

/// A box shape of half-widths hx, hy (valid for hx, hy > 0).
inline Shape ClosedBoxPanel(double hx, double hy)
{
    return MakeShape(MakeBox(hx, hy).polygon);
}

/// Draws a scene from `source`, which has Uniform(lo, hi), Int(lo, hi) and Chance(p): the box's walls 0.01 to 1
/// thick, one body or a crowd (circles, boxes, convex 3- to 8-gons), started apart from each other and from the
/// walls, at speeds up to ranges.maxSpeed per step (ranges.crowdMaxSpeed in a crowd) in any direction, spinning, with
/// restitution 0 to 1 (often exactly 0 or 1), friction and static friction 0 to 1, gravity on or off.
template <typename Source>
ClosedBoxScene MakeClosedBoxScene(Source& source, const ClosedBoxRanges& ranges)
{
    ClosedBoxScene scene;
    ClosedBox& box = scene.box;
    World& world = scene.world;
    box.wall = std::pow(10.0, source.Uniform(-2.0, 0.0));
    scene.dt = ranges.dt;
    if (source.Chance(0.5))
    {
        world.settings.gravity = {0.0, -9.81};
    }
    const double mode = source.Uniform(0.0, 1.0);
    const double restitution = mode < 0.3 ? 1.0 : (mode < 0.5 ? 0.0 : source.Uniform(0.0, 1.0));
    scene.inelastic = restitution == 0.0;
    Material material;
    material.restitution = restitution;
    material.friction = source.Uniform(0.0, 1.0);
    material.staticFriction = material.friction + source.Uniform(0.0, 0.3);
    const double hw = box.halfWidth, hh = box.halfHeight, t = box.wall;
    const struct
    {
        Vec2 half, position;
    } walls[4] = {{{0.5 * t, hh + t}, {-hw - 0.5 * t, 0.0}},
                  {{0.5 * t, hh + t}, {hw + 0.5 * t, 0.0}},
                  {{hw + t, 0.5 * t}, {0.0, -hh - 0.5 * t}},
                  {{hw + t, 0.5 * t}, {0.0, hh + 0.5 * t}}};
    for (const auto& w : walls)
    {
        BodyDef def;
        def.shape = ClosedBoxPanel(w.half.x, w.half.y);
        def.type = BodyType::Static;
        def.position = w.position;
        def.material = material;
        AddBody(world, def);
    }
    if (ranges.allowObstacle && source.Chance(0.25))
    {
        // A thin post in the middle, at an angle: another static body to stay out of.
        BodyDef def;
        def.shape = ClosedBoxPanel(0.5 * std::pow(10.0, source.Uniform(-2.0, -0.5)), source.Uniform(0.3, 1.5));
        def.type = BodyType::Static;
        def.position = {source.Uniform(-2.0, 2.0), source.Uniform(-1.0, 1.0)};
        def.angle = source.Uniform(0.0, 3.14159);
        def.material = material;
        AddBody(world, def);
    }
    box.firstBody = static_cast<int>(world.bodies.size());
    const int wanted = source.Int(ranges.minBodies, std::max(ranges.minBodies, ranges.maxBodies));
    for (int attempt = 0; attempt < 4 * wanted && static_cast<int>(world.bodies.size()) - box.firstBody < wanted;
         ++attempt)
    {
        const double radius = source.Uniform(ranges.minSize, ranges.maxSize);
        const int kind = source.Int(0, 2);
        Shape shape;
        if (kind == 0)
        {
            Circle circle;
            circle.radius = radius;
            shape = MakeShape(circle);
        }
        else if (kind == 1)
        {
            shape = ClosedBoxPanel(radius, radius * source.Uniform(0.2, 1.0));
        }
        else
        {
            const int n = source.Int(3, 8);
            const double aspect = source.Uniform(0.3, 1.0);
            std::vector<Vec2> points(static_cast<size_t>(n));
            for (int k = 0; k < n; ++k)
            {
                const double angle = 2.0 * 3.14159265358979323846 * (k + source.Uniform(0.1, 0.9)) / n;
                points[static_cast<size_t>(k)] = {radius * std::cos(angle), radius * aspect * std::sin(angle)};
            }
            PolygonResult polygon = MakePolygon(points);
            shape = polygon.Ok() ? MakeShape(polygon.polygon) : ClosedBoxPanel(radius, radius);
        }
        if (InnerRadius(shape, ComputeMass(shape, 1.0).center) < ranges.minInner)
        {
            continue;
        }
        BodyDef def;
        def.shape = shape;
        def.material = material;
        def.position = {source.Uniform(-hw + 0.6, hw - 0.6), source.Uniform(-hh + 0.6, hh - 0.6)};
        def.angle = source.Uniform(0.0, 6.2832);
        const double top = wanted == 1 ? ranges.maxSpeed : ranges.crowdMaxSpeed;
        const double speed = std::pow(10.0, source.Uniform(-2.0, std::log10(top))) / scene.dt;
        const double heading = source.Uniform(0.0, 6.2832);
        def.velocity = {speed * std::cos(heading), speed * std::sin(heading)};
        def.angularVelocity =
            (source.Chance(0.5) ? 1.0 : -1.0) * std::pow(10.0, source.Uniform(-2.0, std::log10(ranges.maxSpin)));
        // Started apart from every body already placed, the walls and the post included.
        const Transform xf = MakeTransform(def.position, def.angle);
        bool apart = true;
        for (const RigidBody& other : world.bodies)
        {
            apart = apart && !Overlap(other.shape, other.Xf(), def.shape, xf);
        }
        if (apart)
        {
            AddBody(world, def);
        }
    }
    return scene;
}

/// Empty when every body is where it may be after a step, else what is wrong: a state that is not finite, a dynamic
/// body whose centre of mass has left the box's interior (it passed through a wall) or lies inside a static body
/// (a post).
inline std::string CheckClosedBox(const World& world, const ClosedBox& box)
{
    char text[256];
    for (size_t i = 0; i < world.bodies.size(); ++i)
    {
        const RigidBody& body = world.bodies[i];
        if (!IsFinite(body.position) || !std::isfinite(body.angle) || !IsFinite(body.velocity) ||
            !std::isfinite(body.angularVelocity))
        {
            std::snprintf(text, sizeof text, "body %zu: a state that is not finite", i);
            return text;
        }
        if (body.type != BodyType::Dynamic)
        {
            continue;
        }
        const Vec2 c = body.WorldCenter();
        if (!(std::fabs(c.x) < box.halfWidth && std::fabs(c.y) < box.halfHeight))
        {
            std::snprintf(text, sizeof text,
                          "body %zu: centre (%.9g, %.9g) outside the box, velocity (%.6g, %.6g), spin %.6g", i, c.x,
                          c.y, body.velocity.x, body.velocity.y, body.angularVelocity);
            return text;
        }
        Circle point;
        point.radius = 1e-12;
        for (int s = 4; s < box.firstBody; ++s)
        {
            const RigidBody& post = world.bodies[static_cast<size_t>(s)];
            if (Overlap(post.shape, post.Xf(), MakeShape(point), MakeTransform(c, 0.0)))
            {
                std::snprintf(text, sizeof text, "body %zu: centre (%.9g, %.9g) inside the static body %d", i, c.x, c.y,
                              s);
                return text;
            }
        }
    }
    return {};
}

/// Kinetic plus potential energy of the dynamic bodies (potential: -m g . c, against the world's gravity).
inline double MechanicalEnergy(const World& world)
{
    double energy = KineticEnergy(world);
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            energy -= body.mass * Dot(world.settings.gravity, body.WorldCenter());
        }
    }
    return energy;
}

} // namespace satviz::testing
