// SPDX-License-Identifier: MIT
// The study of a pair in single precision against the same study in double, on random pairs.

#include "render/painter_support.h"
#include "support/random_shapes.h"

#include <satviz/render/describe.h>
#include <satviz/render/study.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
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

TEST_CASE("A sweep where nothing moves says what the static test at t = 0 decided, with its gap", "[study]")
{
    // Two unit boxes moving together: no relative motion, so the static test decides. Apart, B's left face is
    // 1.50 - 0.50 - 0.50 = 0.50 beyond A's right one; at 1.00 they touch.
    auto verdict = [](double x, StepView view) {
        const std::string text = R"({"bodies": [
            {"name": "A", "box": [1, 1], "position": [0, 0], "velocity": [1, 0.5]},
            {"name": "B", "box": [1, 1], "position": [)" + std::to_string(x) + R"(, 0], "velocity": [1, 0.5]}]})";
        SceneResult loaded = ParseScene(text, "moving_together.json");
        REQUIRE(loaded.Ok());
        const PairStudy study = StudyPair(loaded.scene, 0, 1, ViewQuery::Sweep, false, view);
        REQUIRE(study.sweep);
        return DescribeStep(loaded.scene, study, study.VerdictStep());
    };
    for (const StepView view : {StepView::Textbook, StepView::Faces})
    {
        const std::string apart = verdict(1.5, view);
        INFO(apart);
        CHECK(apart.find("nothing moves") != std::string::npos);
        CHECK(apart.find("static test at t = 0 decides: it finds them apart, with a gap of 0.50") != std::string::npos);
        const std::string touching = verdict(1.0, view);
        INFO(touching);
        CHECK(touching.find("static test at t = 0 decides: it finds them touching without overlapping") != std::string::npos);
    }
}
