// SPDX-License-Identifier: MIT
// Frame coherence: Overlap with a SatCache answers as Overlap does, frame after frame, on moving pairs.
#include "support/random_shapes.h"
#include "support/reference.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

using namespace satviz;
using namespace satviz::testing;

TEST_CASE("Overlap with a cached separating axis answers as Overlap on moving pairs", "[cache]")
{
    Rng rng(808);
    int frames = 0;
    int differing = 0;
    int cachedSeparations = 0;
    for (int i = 0; i < 4000; ++i)
    {
        const int n = rng.Chance(0.8) ? rng.Int(3, 12) : rng.Int(13, 200);
        RandomPair p = ContactPair(rng, n, static_cast<PairCategory>(rng.Int(0, 2)));
        const Vec2 step{rng.Uniform(-0.05, 0.05), rng.Uniform(-0.05, 0.05)};
        const double spin = rng.Uniform(-0.02, 0.02);
        SatCache cache;
        for (int frame = 0; frame < 12; ++frame)
        {
            const Transform xfB = MakeTransform(p.xfB.p + static_cast<double>(frame) * step,
                                                std::atan2(p.xfB.q.s, p.xfB.q.c) + frame * spin);
            const AxisRef before = cache.axis;
            const bool cached = Overlap(p.a.polygon, p.xfA, p.b.polygon, xfB, cache);
            const bool plain = Overlap(p.a.polygon, p.xfA, p.b.polygon, xfB);
            ++frames;
            if (cached != plain)
            {
                // Only where the shapes touch within rounding.
                const Reference ref = ReferenceCollide(p.a, p.xfA, p.b, xfB);
                INFO("pair " << i << " frame " << frame << " separation " << static_cast<double>(ref.separation));
                CHECK(std::abs(static_cast<double>(ref.separation)) < 1e-12);
                ++differing;
            }
            if (!cached && before.kind == AxisKind::FaceNormal && cache.axis.kind == before.kind &&
                cache.axis.shape == before.shape && cache.axis.index == before.index)
            {
                ++cachedSeparations;
            }
            CHECK((cache.axis.kind == AxisKind::None) == cached); // a separated pair keeps its separating face
        }
    }
    INFO(frames << " frames, " << cachedSeparations << " kept the cached axis, " << differing << " differed");
    CHECK(differing <= frames / 10000);
    CHECK(cachedSeparations > frames / 5);
}

TEST_CASE("A stale or foreign cache entry is harmless", "[cache]")
{
    const Polygon box = MakeBox(0.5, 0.5).polygon;
    const Transform here{{0.0, 0.0}, {1.0, 0.0}};
    SatCache cache;
    cache.axis = {AxisKind::FaceNormal, 1, 99}; // an edge the polygon does not have
    CHECK(Overlap(box, here, box, Transform{{0.5, 0.0}, {1.0, 0.0}}, cache));
    CHECK(cache.axis.kind == AxisKind::None);
    cache.axis = {AxisKind::FaceNormal, 0, 1}; // A's right face, which does not separate a pair on the left
    CHECK(!Overlap(box, here, box, Transform{{-2.0, 0.0}, {1.0, 0.0}}, cache));
    CHECK(cache.axis.kind == AxisKind::FaceNormal);
    CHECK(!Overlap(box, here, box, Transform{{-2.1, 0.0}, {1.0, 0.0}}, cache)); // answered by the cached face
}
