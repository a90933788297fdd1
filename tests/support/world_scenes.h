// SPDX-License-Identifier: MIT
// Small builders for the world tests: bodies, materials, standard scenes, and bit-for-bit state comparison.
#pragma once

#include "support/builders.h"

#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace satviz::testing
{

constexpr double kGravity = 9.81;
constexpr double kDt = 1.0 / 60.0;

/// Whether the world tests step with the soft step (WorldSettings::softStep): set by the environment variable
/// SATVIZ_TEST_SOFT_STEP=1, so that the same physics checks run against either solver (ctest runs the checks the
/// soft step holds a second time so). The builders below switch it on in the world they build or add to.
inline bool SoftStepUnderTest()
{
    static const bool on = [] {
        const char* value = std::getenv("SATVIZ_TEST_SOFT_STEP");
        return value != nullptr && std::strcmp(value, "1") == 0;
    }();
    return on;
}

/// Switches the soft step on in `world` when the tests run with it (SoftStepUnderTest).
inline void UseStepUnderTest(World& world)
{
    if (SoftStepUnderTest())
    {
        world.settings.softStep = true;
    }
}

/// A material from its three coefficients.
inline Material MakeMaterial(double restitution, double friction, double staticFriction)
{
    Material m;
    m.restitution = restitution;
    m.friction = friction;
    m.staticFriction = staticFriction;
    return m;
}

/// Adds a static body; the definition must be valid.
inline int AddStatic(World& world, const Shape& shape, Vec2 position, double angle = 0.0,
                     Material material = Material{})
{
    BodyDef def;
    def.shape = shape;
    def.type = BodyType::Static;
    def.position = position;
    def.angle = angle;
    def.material = material;
    REQUIRE(ValidateBodyDef(def).empty());
    UseStepUnderTest(world);
    return AddBody(world, def);
}

/// Adds a dynamic body; the definition must be valid.
inline int AddDynamic(World& world, const Shape& shape, Vec2 position, double angle = 0.0, Vec2 velocity = {},
                      double angularVelocity = 0.0, Material material = Material{}, double density = 1.0)
{
    BodyDef def;
    def.shape = shape;
    def.type = BodyType::Dynamic;
    def.position = position;
    def.angle = angle;
    def.velocity = velocity;
    def.angularVelocity = angularVelocity;
    def.material = material;
    def.density = density;
    REQUIRE(ValidateBodyDef(def).empty());
    UseStepUnderTest(world);
    return AddBody(world, def);
}

/// A world with gravity (0, -g).
inline World WorldWithGravity(double g)
{
    World world;
    world.settings.gravity = {0.0, -g};
    UseStepUnderTest(world);
    return world;
}

/// A ground whose top face is the line y = 0 over [-halfWidth, halfWidth]: a static box 1 tall.
inline int AddGround(World& world, double halfWidth = 20.0, Material material = Material{})
{
    return AddStatic(world, BoxShape(halfWidth, 0.5), {0.0, -0.5}, 0.0, material);
}

/// Steps the world n times.
inline void StepN(World& world, int n, double dt = kDt)
{
    for (int i = 0; i < n; ++i)
    {
        Step(world, dt);
    }
}

/// True when the two doubles have the same bits.
inline bool SameDouble(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// True when every body of the two worlds has the same state, bit for bit: position, angle, velocities, the sleep
/// state, and the world's time.
inline bool SameState(const World& a, const World& b)
{
    if (a.bodies.size() != b.bodies.size() || !SameDouble(a.time, b.time))
    {
        return false;
    }
    for (size_t i = 0; i < a.bodies.size(); ++i)
    {
        const RigidBody& p = a.bodies[i];
        const RigidBody& q = b.bodies[i];
        if (!SameDouble(p.position.x, q.position.x) || !SameDouble(p.position.y, q.position.y) ||
            !SameDouble(p.angle, q.angle) || !SameDouble(p.velocity.x, q.velocity.x) ||
            !SameDouble(p.velocity.y, q.velocity.y) || !SameDouble(p.angularVelocity, q.angularVelocity) ||
            p.awake != q.awake || !SameDouble(p.sleepTime, q.sleepTime))
        {
            return false;
        }
    }
    return true;
}

/// The pyramid of rows of unit boxes on the ground: row r (from 0 at the bottom) has rows[r] boxes 1 apart plus a
/// gap, centred on x = 0, each row resting on the one below. Returns the indices of the boxes, bottom row first.
inline std::vector<int> AddPyramid(World& world, const std::vector<int>& rows, double gap = 0.05, double x0 = 0.0)
{
    std::vector<int> indices;
    const Shape box = BoxShape(0.5, 0.5);
    for (size_t r = 0; r < rows.size(); ++r)
    {
        const int count = rows[r];
        const double pitch = 1.0 + gap;
        const double left = x0 - 0.5 * pitch * (count - 1);
        for (int k = 0; k < count; ++k)
        {
            indices.push_back(AddDynamic(world, box, {left + pitch * k, 0.5 + static_cast<double>(r)}));
        }
    }
    return indices;
}

} // namespace satviz::testing
