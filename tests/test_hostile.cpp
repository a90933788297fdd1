// SPDX-License-Identifier: MIT
// Hostile numbers: the queries must not crash, hang or trip a sanitizer, whatever the transforms and velocities.
// (Polygons themselves cannot hold such numbers: MakePolygon refuses them.)

#include "support/random_shapes.h"
#include "support/same_bits.h"

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

// The shape that axis.shape names (0: A, 1: B), and its vertex count; -1 for a circle or no shape.
int CountOf(const RandomPair& pair, int shape)
{
    const Shape* s = shape == 0 ? &pair.a : shape == 1 ? &pair.b : nullptr;
    return s != nullptr && s->type == ShapeType::Polygon ? s->polygon.Count() : -1;
}

// The axis a result names exists: a face or vertex of the shape it names, or none at all.
void RequireValidAxis(const AxisRef& axis, const RandomPair& pair)
{
    REQUIRE(axis.shape >= -1);
    REQUIRE(axis.shape <= 1);
    if (axis.kind == AxisKind::FaceNormal || axis.kind == AxisKind::VertexToCenter)
    {
        REQUIRE(axis.index >= 0);
        REQUIRE(axis.index < CountOf(pair, axis.shape));
    }
    else
    {
        REQUIRE(axis.index == -1);
    }
}

} // namespace

TEST_CASE("NaN, infinite and extreme transforms and velocities do not crash any query", "[robustness]")
{
    // Whatever the numbers, each answer is well formed (axes, edges and contact counts in range, no contacts
    // without overlap or hit) and the traced query gives the untraced one's answer to the bit, but for the sign and
    // payload of a NaN.
    Rng rng(666);
    Trace trace;
    SweepTrace sweepTrace;
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
        INFO("pair " << i << ": B at " << pair.xfB.p.x << ", " << pair.xfB.p.y << ", A turned by " << pair.xfA.q.c
                     << ", " << pair.xfA.q.s << ", moving " << v.x << ", " << v.y);
        REQUIRE(Overlap(pair.a, pair.xfA, pair.b, pair.xfB) == Overlap(pair.a, pair.xfA, pair.b, pair.xfB, &trace));
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        REQUIRE(SameBits(m, Collide(pair.a, pair.xfA, pair.b, pair.xfB, &trace), true));
        REQUIRE(m.contactCount >= (m.overlap ? 1 : 0));
        REQUIRE(m.contactCount <= (m.overlap ? 2 : 0));
        RequireValidAxis(m.axis, pair);
        if (m.incidentEdge != -1)
        {
            // An edge of the polygon that does not hold the reference face.
            REQUIRE(m.incidentEdge >= 0);
            REQUIRE(m.incidentEdge < CountOf(pair, 1 - m.axis.shape));
        }
        const SweepResult s = Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, v);
        REQUIRE(SameBits(s, Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, v, &sweepTrace), true));
        REQUIRE(s.contactCount >= 0);
        REQUIRE(s.contactCount <= (s.status == SweepStatus::Hit ? 2 : 0));
        RequireValidAxis(s.axis, pair);
        const Obstacle obstacle{&pair.b, pair.xfB};
        const SlideResult r = MoveAndSlide(pair.a, pair.xfA, v, &obstacle, 1);
        REQUIRE(r.contactCount >= 0);
        REQUIRE(r.contactCount <= kMaxSlideContacts);
        for (int k = 0; k < r.contactCount; ++k)
        {
            REQUIRE(r.obstacles[k] == 0);
        }
    }
}
