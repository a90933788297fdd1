// SPDX-License-Identifier: MIT
// Fuzz target for the rigid-body world: the bytes become a closed box of four static walls (0.01 to 1 thick,
// sometimes a static post inside), one to six bodies of every kind (circles, boxes, convex polygons) started apart,
// their positions, velocities (up to 1e5 units per step for a lone body), spins, materials, gravity and the step
// (1/240 to 1/30).
// The world is stepped 60 times and checked after every step:
//  - every state is finite;
//  - no body has left the box or has its centre inside the post (it never passes through a static body);
//  - no step takes more time-ordered hits than maxHitsPerBody allows (no step can run away);
//  - a world without restitution never gains energy, whatever the number of bodies: kinetic plus potential energy
//    may rise by at most the band of EnergyBand (the slop the world leaves a resting body, the overlap the step
//    started with, and rounding).
// A failure aborts, which libFuzzer reports with the input.
#include "support/closed_box.h"

#include <satviz/collide.h>
#include <satviz/world.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{

/// Draws values from the fuzzer's bytes, with the interface of the tests' random source; zeros once they run out.
struct ByteSource
{
    const uint8_t* data;
    size_t size;
    size_t at = 0;

    uint8_t Byte() { return at < size ? data[at++] : 0; }
    /// In [lo, hi), from two bytes.
    double Uniform(double lo, double hi)
    {
        const double u = (Byte() | (Byte() << 8)) / 65536.0;
        return lo + (hi - lo) * u;
    }
    /// In [lo, hi].
    int Int(int lo, int hi) { return lo + Byte() % (hi - lo + 1); }
    /// True with probability about p.
    bool Chance(double p) { return Uniform(0.0, 1.0) < p; }
};

/// The overlap the step starts with, summed over the pairs with a dynamic body: energy an earlier step stored, as in
/// a compressed spring. The bodies of a time-ordered hit are left out of their step's position passes, and a light
/// body pressed under a heavy one shares its overlap by the masses, so two moving bodies can start a step deeper in
/// each other than the slop; the position passes then lift them apart by that much, a rise of potential energy the
/// step did not create.
double StoredOverlap(const satviz::World& world)
{
    double sum = 0.0;
    for (size_t i = 0; i < world.bodies.size(); ++i)
    {
        for (size_t j = i + 1; j < world.bodies.size(); ++j)
        {
            const satviz::RigidBody& a = world.bodies[i];
            const satviz::RigidBody& b = world.bodies[j];
            if (a.type != satviz::BodyType::Dynamic && b.type != satviz::BodyType::Dynamic)
            {
                continue;
            }
            const satviz::Manifold m = satviz::Collide(a.shape, a.Xf(), b.shape, b.Xf());
            if (m.overlap)
            {
                sum += m.depth;
            }
        }
    }
    return sum;
}

/// How much kinetic plus potential energy a step may add to the bodies in a box without restitution. The world
/// holds a resting body anywhere within the slop of a surface, on either side: the position passes lift a body that
/// sank until it overlaps by the slop, a contact stops one that falls within the slop of it. So a step may leave
/// each body up to two slops higher (m g 2 slop) and moving at up to two slops a step (the velocity passes keep
/// each group of touching bodies within that drift), plus a relative 1e-9 of the energy for the rounding of large
/// sums. An overlap the step starts with (StoredOverlap) may lift each body by as much again: no body is lifted
/// farther than all the overlap there is to remove. And the integrator's own error: the step moves each body with
/// its velocity at the end of the step (semi-implicit Euler), so a contact that turns a falling body upwards (a
/// ball meeting a plank's corner) lifts it by that upward velocity for the whole step, where the exact motion
/// would rise only after the turn: up to m g dt times the upward speed the contacts gave it (`previous` holds the
/// velocities at the start of the step). The error vanishes with dt.
double EnergyBand(const satviz::World& world, double dt, double energy, double storedOverlap,
                  const std::vector<satviz::Vec2>& previous)
{
    const double slop = 2.0 * world.settings.linearSlop;
    double band = 1e-9 * std::fabs(energy);
    for (const satviz::RigidBody& body : world.bodies)
    {
        if (body.type == satviz::BodyType::Dynamic)
        {
            band += body.mass * (satviz::Length(world.settings.gravity) * (slop + storedOverlap) +
                                 0.5 * (slop / dt) * (slop / dt));
            const satviz::Vec2 kick = body.velocity - previous[&body - world.bodies.data()] - dt * world.settings.gravity;
            band += body.mass * dt * std::max(0.0, -satviz::Dot(kick, world.settings.gravity));
        }
    }
    return band;
}

[[noreturn]] void Fail(const char* what, int step, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_world: step %d: %s %s\n", step, what, detail.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    ByteSource source{data, size};
    satviz::testing::ClosedBoxRanges ranges;
    ranges.maxBodies = 6;
    ranges.dt = 1.0 / source.Uniform(30.0, 240.0);
    satviz::testing::ClosedBoxScene scene = satviz::testing::MakeClosedBoxScene(source, ranges);
    satviz::World& world = scene.world;
    const int dynamic = static_cast<int>(world.bodies.size()) - scene.box.firstBody;
    const bool watchEnergy = scene.inelastic;
    double energy = satviz::testing::MechanicalEnergy(world);
    for (int step = 1; step <= 60; ++step)
    {
        const double stored = watchEnergy ? StoredOverlap(world) : 0.0;
        std::vector<satviz::Vec2> previous;
        for (const satviz::RigidBody& body : world.bodies)
        {
            previous.push_back(body.velocity);
        }
        satviz::Step(world, scene.dt);
        const std::string wrong = satviz::testing::CheckClosedBox(world, scene.box);
        if (!wrong.empty())
        {
            Fail("a body left the box:", step, wrong);
        }
        // Each resolution of hits counts against maxHitsPerBody of its bodies, and takes at most one hit per pair
        // of a body with another.
        const int64_t bodies = static_cast<int64_t>(world.bodies.size());
        if (world.counts.hits > static_cast<int64_t>(world.settings.maxHitsPerBody) * dynamic * bodies)
        {
            Fail("more hits than maxHitsPerBody allows:", step, std::to_string(world.counts.hits));
        }
        const double next = satviz::testing::MechanicalEnergy(world);
        if (watchEnergy && next - energy > EnergyBand(world, scene.dt, energy, stored, previous))
        {
            Fail("the energy rose:", step, std::to_string(energy) + " to " + std::to_string(next));
        }
        energy = next;
    }
    return 0;
}
