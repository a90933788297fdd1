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
//    may rise by at most the band of EnergyBand (the slop the world leaves a resting body, and rounding).
// A failure aborts, which libFuzzer reports with the input.
#include "support/closed_box.h"

#include <satviz/world.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

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

/// How much kinetic plus potential energy a step may add to the bodies in a box without restitution. The world
/// holds a resting body anywhere within the slop of a surface, on either side: the position passes lift a body that
/// sank until it overlaps by the slop, a contact stops one that falls within the slop of it. So a step may leave
/// each body up to two slops higher (m g 2 slop) and moving at up to two slops a step (the velocity passes keep
/// each group of touching bodies within that drift), plus a relative 1e-9 of the energy for the rounding of large
/// sums.
double EnergyBand(const satviz::World& world, double dt, double energy)
{
    const double slop = 2.0 * world.settings.linearSlop;
    double band = 1e-9 * std::fabs(energy);
    for (const satviz::RigidBody& body : world.bodies)
    {
        if (body.type == satviz::BodyType::Dynamic)
        {
            band += body.mass * (satviz::Length(world.settings.gravity) * slop + 0.5 * (slop / dt) * (slop / dt));
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
        if (watchEnergy && next - energy > EnergyBand(world, scene.dt, energy))
        {
            Fail("the energy rose:", step, std::to_string(energy) + " to " + std::to_string(next));
        }
        energy = next;
    }
    return 0;
}
