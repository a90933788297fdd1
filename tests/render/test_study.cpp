// SPDX-License-Identifier: MIT
// The study of a pair in single precision against the same study in double, on random pairs.

#include "render/painter_support.h"
#include "support/random_shapes.h"

#include <satviz/render/study.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <utility>

using namespace satviz;

TEST_CASE("The single-precision study agrees with double within float rounding, step for step", "[study]")
{
    testing::Rng rng(7);
    int compared = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const Scene scene = painter_test::RandomPolygonPair(rng, 12, 0.4);
        const PairStudy exact = StudyPair(scene, 0, 1, ViewQuery::Collide, false);
        const PairStudy single = StudyPair(scene, 0, 1, ViewQuery::Collide, true);
        if (!single.singlePrecision)
        {
            continue; // a polygon did not survive rounding to float
        }
        // Decisions may differ only where the shapes nearly touch.
        const double margin = exact.manifold.overlap ? exact.manifold.depth : exact.manifold.gap;
        if (margin < 1e-4)
        {
            continue;
        }
        REQUIRE(single.manifold.overlap == exact.manifold.overlap);
        if (exact.manifold.overlap)
        {
            CHECK(std::abs(single.manifold.depth - exact.manifold.depth) < 1e-5);
        }
        REQUIRE(!single.trace.axes.empty());
        for (const AxisTest& t : single.trace.axes)
        {
            CHECK(std::isfinite(t.minA));
            CHECK(std::abs(Length(t.direction) - 1.0) < 1e-6);
        }
        ++compared;
    }
    CHECK(compared > 1500);
}
