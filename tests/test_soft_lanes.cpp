// SPDX-License-Identifier: MIT
// The soft step's passes over several contacts at a time in lanes (core/src/soft_lanes.h) against its visit of one
// contact (soft_solver.h): the same bits on the lanes of AVX2 and of AVX-512; and a world stepped with the soft step
// on each and on the baseline's instructions, which visit one contact at a time.

#include "sat/cpu_dispatch.h"
#include "soft_lanes.h"
#include "support/skip.h"
#include "support/world_scenes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace satviz;
using namespace satviz::testing;
using namespace satviz::detail;

namespace
{

bool Same(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// A batch's contacts, each between two bodies of its own (2k and 2k + 1), some against a body that does not move,
// and the states of those bodies; the two records after theirs are the sink and the body at rest of SolveSoft.
struct Case
{
    SoftContact contacts[kSoftLanes];
    std::vector<SoftBody> states;
    bool moves[2 * kSoftLanes];
    int lanes = kSoftLanes;
    SoftKind kind = SoftKind::OnePoint;
};

constexpr int kSink = 2 * kSoftLanes;
constexpr int kRest = kSink + 1;

Case RandomCase(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto chance = [&](double p) { return 0.5 * (unit(rng) + 1.0) < p; };
    Case out;
    out.kind = static_cast<SoftKind>(static_cast<int>(0.5 * (unit(rng) + 1.0) * 2.999));
    out.lanes = chance(0.4) ? 1 + static_cast<int>(0.5 * (unit(rng) + 1.0) * (kSoftLanes - 1.001)) : kSoftLanes;
    out.states.assign(kRest + 1, SoftBody{});
    for (int i = 0; i < 2 * kSoftLanes; ++i)
    {
        out.moves[i] = !chance(0.3);
        SoftBody& s = out.states[static_cast<size_t>(i)];
        if (out.moves[i])
        {
            s.v = {2.0 * unit(rng), 2.0 * unit(rng)};
            s.w = 3.0 * unit(rng);
            s.angle = 0.05 * unit(rng);
            s.position = {0.05 * unit(rng), 0.05 * unit(rng)};
            s.rotation = {std::cos(s.angle), std::sin(s.angle)};
        }
    }
    for (int k = 0; k < kSoftLanes; ++k)
    {
        SoftContact& c = out.contacts[k];
        c.a = 2 * k;
        c.b = 2 * k + 1;
        c.count = out.kind == SoftKind::OnePoint ? 1 : 2;
        c.block = out.kind == SoftKind::Block;
        c.stiff = !out.moves[c.a] || !out.moves[c.b];
        const double angle = 3.14159 * unit(rng);
        c.normal = {std::cos(angle), std::sin(angle)};
        c.friction = 0.5 * (unit(rng) + 1.0);
        c.staticFriction = chance(0.5) ? c.friction : 1.2 * c.friction;
        c.invMassA = out.moves[c.a] ? 1.0 + unit(rng) * 0.5 : 0.0;
        c.invInertiaA = out.moves[c.a] ? 2.0 + unit(rng) : 0.0;
        c.invMassB = out.moves[c.b] ? 1.0 + unit(rng) * 0.5 : 0.0;
        c.invInertiaB = out.moves[c.b] ? 2.0 + unit(rng) : 0.0;
        c.k11 = 1.5 + unit(rng);
        c.k22 = 1.5 + unit(rng);
        c.k12 = 0.4 * unit(rng);
        const bool idle = chance(0.3);
        for (int i = 0; i < 2; ++i)
        {
            SoftPoint& p = c.points[i];
            p.rnA = unit(rng);
            p.rnB = unit(rng);
            p.rtA = unit(rng);
            p.rtB = unit(rng);
            // Gaps and overlaps, a few of them open at any speed (the idle contacts' skip).
            p.separation = chance(0.2) ? 1.0 + unit(rng) : 0.05 * unit(rng);
            p.normalMass = 1.0 / (i == 0 ? c.k11 : c.k22);
            p.tangentMass = chance(0.1) ? 0.0 : 0.5 + 0.25 * unit(rng);
            p.normalImpulse = idle ? 0.0 : 0.5 * (unit(rng) + 1.0);
            p.tangentImpulse = idle ? 0.0 : 0.3 * unit(rng);
            p.maxNormalImpulse = chance(0.5) ? 0.0 : p.normalImpulse + 0.1;
            c.stuck[i] = chance(0.5);
        }
    }
    return out;
}

// The batch of the case's contacts, read and written as SolveSoft packs them.
SoftBatch Pack(const Case& c)
{
    SoftBatch batch;
    batch.lanes = c.lanes;
    batch.kind = c.kind;
    SoftContact padding{};
    padding.count = 2;
    padding.points[0].separation = 1.0;
    padding.points[1].separation = 1.0;
    for (int lane = 0; lane < kSoftLanes; ++lane)
    {
        if (lane >= c.lanes)
        {
            PackSoftLane(batch, lane, padding, kRest, kRest, kSink, kSink);
            continue;
        }
        const SoftContact& s = c.contacts[lane];
        PackSoftLane(batch, lane, s, s.a, s.b, c.moves[s.a] ? s.a : kSink, c.moves[s.b] ? s.b : kSink);
    }
    return batch;
}

// Runs pass `which` on the case's lanes and one contact at a time, and checks the bodies and contacts agree bit for
// bit; a body the passes do not move keeps its record, at rest.
void CheckPass(const Case& c, SoftPass which, const SoftPassConstants& k)
{
    Case scalar = c;
    for (int lane = 0; lane < c.lanes; ++lane)
    {
        SoftContact& s = scalar.contacts[lane];
        SoftBody& a = scalar.states[static_cast<size_t>(s.a)];
        SoftBody& b = scalar.states[static_cast<size_t>(s.b)];
        NullSolveRecorder quiet;
        const Softness& softness = s.stiff ? k.stiff : k.soft;
        if (which == SoftPass::WarmStart)
        {
            WarmStart(s, a, b);
        }
        else if (which == SoftPass::Solve)
        {
            SolveSoftContact<true>(s, a, b, softness, k.invH, k.maxPushSpeed, 0, quiet);
        }
        else
        {
            SolveSoftContact<false>(s, a, b, softness, k.invH, k.maxPushSpeed, 1, quiet);
        }
    }
    Case lanes = c;
    SoftBatch batch = Pack(c);
    SoftPassOverBatches(which, &batch, &batch + 1, lanes.states.data(), k);
    for (int lane = 0; lane < c.lanes; ++lane)
    {
        UnpackSoftLane(batch, lane, lanes.contacts[lane]);
    }
    for (int i = 0; i < 2 * kSoftLanes; ++i)
    {
        const SoftBody& p = lanes.states[static_cast<size_t>(i)];
        const SoftBody& q = scalar.states[static_cast<size_t>(i)];
        INFO("body " << i << (c.moves[i] ? " (moves)" : " (does not move)"));
        CHECK((Same(p.v.x, q.v.x) && Same(p.v.y, q.v.y) && Same(p.w, q.w)));
        if (!c.moves[i])
        {
            CHECK((Same(p.v.x, 0.0) && Same(p.v.y, 0.0) && Same(p.w, 0.0)));
        }
    }
    CHECK((Same(lanes.states[kRest].v.x, 0.0) && Same(lanes.states[kRest].w, 0.0)));
    for (int lane = 0; lane < c.lanes; ++lane)
    {
        const SoftContact& p = lanes.contacts[lane];
        const SoftContact& q = scalar.contacts[lane];
        for (int i = 0; i < q.count; ++i)
        {
            INFO("contact " << lane << ", point " << i);
            CHECK(Same(p.points[i].normalImpulse, q.points[i].normalImpulse));
            CHECK(Same(p.points[i].tangentImpulse, q.points[i].tangentImpulse));
            CHECK(Same(p.points[i].maxNormalImpulse, q.points[i].maxNormalImpulse));
            CHECK(p.stuck[i] == q.stuck[i]);
        }
    }
}

void CheckLanes()
{
    std::mt19937_64 rng(20261129);
    const double h = 1.0 / 240.0;
    const SoftPassConstants k{MakeSoftness(30.0, 10.0, h), MakeSoftness(60.0, 10.0, h), 1.0 / h, 3.0};
    for (int n = 0; n < 3000; ++n)
    {
        const Case c = RandomCase(rng);
        INFO("case " << n << ", kind " << static_cast<int>(c.kind) << ", " << c.lanes << " lanes");
        CheckPass(c, SoftPass::WarmStart, k);
        CheckPass(c, SoftPass::Solve, k);
        CheckPass(c, SoftPass::Relax, k);
    }
}

// A pile of boxes, discs and a few falling ones, with the soft step.
World SoftPile()
{
    World world = WorldWithGravity(kGravity);
    world.settings.softStep = true;
    AddGround(world);
    AddPyramid(world, {6, 5, 4, 3, 2, 1});
    for (int k = 0; k < 6; ++k)
    {
        AddDynamic(world, DiscShape(0.3 + 0.05 * k), {-3.0 + 1.1 * k, 8.0 + 0.7 * k}, 0.0, {0.5 * k - 1.0, -2.0});
        AddDynamic(world, BoxShape(0.4, 0.2 + 0.03 * k), {-2.5 + 1.0 * k, 10.0 + 0.5 * k}, 0.3 * k);
    }
    return world;
}

} // namespace

TEST_CASE("The soft step's lanes (AVX2) give the bits of its visit of one contact", "[soft-step][wide]")
{
    if (!WideVectorsEnabled())
    {
        SkipTestCase("this processor has no AVX2: the soft step's wide lanes were not checked");
        return;
    }
    const bool wide512 = Wide512Enabled();
    Wide512Enabled() = false;
    CheckLanes();
    Wide512Enabled() = wide512;
}

TEST_CASE("The soft step's lanes (AVX-512) give the bits of its visit of one contact", "[soft-step][wide]")
{
    if (!WideVectorsEnabled() || !Wide512Enabled())
    {
        SkipTestCase("this processor has no AVX-512F: the soft step's eight lanes were not checked");
        return;
    }
    CheckLanes();
}

TEST_CASE("A pile stepped with the soft step on each instruction set's lanes has the same bits", "[soft-step][wide]")
{
    const bool wide = WideVectorsEnabled();
    const bool wide512 = Wide512Enabled();
    if (!wide)
    {
        SkipTestCase("this processor has no AVX2: the soft step's wide lanes were not checked");
        return;
    }
    World baseline = SoftPile();
    World avx2 = SoftPile();
    World widest = SoftPile();
    for (int step = 0; step < 240; ++step)
    {
        WideVectorsEnabled() = false;
        Step(baseline, kDt);
        WideVectorsEnabled() = true;
        Wide512Enabled() = false;
        Step(avx2, kDt);
        Wide512Enabled() = wide512;
        Step(widest, kDt);
        INFO("step " << step);
        REQUIRE(SameState(baseline, avx2));
        REQUIRE(SameState(baseline, widest));
    }
}
