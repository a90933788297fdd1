// SPDX-License-Identifier: MIT
// Hostile numbers: the queries must not crash, hang or trip a sanitizer, whatever the transforms and velocities.
// (Polygons themselves cannot hold such numbers: MakePolygon refuses them.)

#include "support/random_shapes.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace satviz;
using namespace satviz::testing;

namespace
{

double Hostile(Rng& rng)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const double values[] = {nan, inf, -inf, 1e308, -1e308, 1e-308, 0.0, -0.0, 1e12, 3.0};
    return values[rng.Int(0, 9)];
}

Vec2 HostileVec(Rng& rng)
{
    return rng.Chance(0.5) ? Vec2{Hostile(rng), rng.Uniform(-1, 1)} : Vec2{Hostile(rng), Hostile(rng)};
}

} // namespace

TEST_CASE("NaN, infinite and extreme transforms and velocities do not crash any query", "[robustness]")
{
    Rng rng(666);
    Trace trace;
    SweepTrace sweepTrace;
    int answered = 0;
    for (int i = 0; i < 3000; ++i)
    {
        RandomPair pair = RandomShapePair(rng, 0.3);
        if (rng.Chance(0.7))
        {
            pair.xfB.p = HostileVec(rng);
        }
        if (rng.Chance(0.3))
        {
            pair.xfA.q = {Hostile(rng), Hostile(rng)};
        }
        const Vec2 v = rng.Chance(0.5) ? HostileVec(rng) : Vec2{rng.Uniform(-1, 1), 0.0};
        Overlap(pair.a, pair.xfA, pair.b, pair.xfB);
        Overlap(pair.a, pair.xfA, pair.b, pair.xfB, &trace);
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB, &trace);
        REQUIRE(m.contactCount >= 0);
        REQUIRE(m.contactCount <= 2);
        const SweepResult s = Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, v, &sweepTrace);
        REQUIRE(s.contactCount <= 2);
        const Obstacle obstacle{&pair.b, pair.xfB};
        const SlideResult r = MoveAndSlide(pair.a, pair.xfA, v, &obstacle, 1);
        REQUIRE(r.contactCount <= kMaxSlideContacts);
        ++answered;
    }
    CHECK(answered == 3000);
}
