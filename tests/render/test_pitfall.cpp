// SPDX-License-Identifier: MIT
// The pitfall scenes: each common mistake of the lessons shown going wrong beside the right answer, and on random
// pairs the mistakes that cannot lose a verdict never do.
#include "render/painter_support.h"
#include "support/random_shapes.h"

#include <satviz/render/describe.h>
#include <satviz/render/figure.h>
#include <satviz/render/pitfall.h>
#include <satviz/render/recording_canvas.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace satviz;
using namespace satviz::painter_test;

TEST_CASE("Each pitfall scene shows its mistake going wrong beside the right answer", "[painter][pitfall]")
{
    const std::string dir = std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/";
    {
        const Scene scene = Load(dir + "pitfall_unnormalised.json");
        const FigureSetup setup = SetUpFigure(scene, {});
        const PitfallResult& p = setup.study.pitfall;
        REQUIRE(p.ran);
        CHECK(p.overlap == setup.study.textbookResult.overlap);
        // It pushes sideways where the MTV goes up.
        CHECK(std::abs(Dot(p.normal, setup.study.textbookResult.normal)) < 1e-12);
        // The figure shows the wrong depth at work: the crate pushed by it still lies in the floor. Both are boxes
        // square to the axes, so the depth left is the smaller of the overlaps along x and along y.
        FigureSetup drawn = SetUpFigure(scene, {});
        const RecordingCanvas canvas = Paint(scene, drawn, drawn.study.VerdictStep(), kAllLayers);
        const auto [fx0, fx1] = Project(scene.bodies[0], {1.0, 0.0});
        const auto [fy0, fy1] = Project(scene.bodies[0], {0.0, 1.0});
        Body pushed = scene.bodies[1];
        pushed.position = pushed.position + p.depth * p.normal;
        const auto [cx0, cx1] = Project(pushed, {1.0, 0.0});
        const auto [cy0, cy1] = Project(pushed, {0.0, 1.0});
        const double left = std::min(std::min(fx1, cx1) - std::max(fx0, cx0), std::min(fy1, cy1) - std::max(fy0, cy0));
        REQUIRE(left > 0.0);
        const double shown = NumberAfter(canvas, "labels", "after the pitfall's push: still ");
        CHECK(std::abs(shown - left) < 0.0051);
    }
    {
        const Scene scene = Load(dir + "pitfall_direction.json");
        const FigureSetup setup = SetUpFigure(scene, {});
        const PitfallResult& p = setup.study.pitfall;
        REQUIRE(p.ran);
        CHECK(Dot(p.normal, setup.study.textbookResult.normal) < -0.99);
        // The sentence names the bodies as the picture labels them.
        CHECK(p.verdict.find("drives " + scene.bodies[1].name + " into " + scene.bodies[0].name) != std::string::npos);
        CHECK(p.verdict.find(" B ") == std::string::npos);
    }
    {
        const Scene scene = Load(dir + "pitfall_one_shape.json");
        const FigureSetup setup = SetUpFigure(scene, {});
        REQUIRE(setup.study.pitfall.ran);
        CHECK(setup.study.pitfall.overlap);
        CHECK_FALSE(setup.study.textbookResult.overlap);
        // The right answer is apart; the figure draws the mistake's push all the same (it was only in the
        // sentence): the box's axes alone, x and y, give the smaller of the two overlaps along them.
        FigureSetup drawn = SetUpFigure(scene, {});
        const RecordingCanvas canvas = Paint(scene, drawn, drawn.study.VerdictStep(), kAllLayers);
        const auto [bx0, bx1] = Project(scene.bodies[0], {1.0, 0.0});
        const auto [by0, by1] = Project(scene.bodies[0], {0.0, 1.0});
        const auto [dx0, dx1] = Project(scene.bodies[1], {1.0, 0.0});
        const auto [dy0, dy1] = Project(scene.bodies[1], {0.0, 1.0});
        const double push = std::min(std::min(bx1, dx1) - std::max(bx0, dx0), std::min(by1, dy1) - std::max(by0, dy0));
        CHECK(std::abs(NumberAfter(canvas, "labels", "pitfall ") - push) < 0.0051);
        CHECK_FALSE(canvas.InGroup("mtv").empty());
    }
    {
        const Scene scene = Load(dir + "pitfall_tunnel.json");
        const FigureSetup setup = SetUpFigure(scene, {});
        REQUIRE(setup.study.pitfall.ran);
        CHECK_FALSE(setup.study.pitfall.overlap);
        CHECK(setup.study.sweepResult.status == SweepStatus::Hit);
        CHECK(setup.study.pitfall.verdict.find("tunnel") != std::string::npos);
        // The verdict caption says both.
        const std::string verdict = DescribeStep(scene, setup.study, setup.study.VerdictStep());
        CHECK(verdict.find("first contact at t = ") != std::string::npos);
        CHECK(verdict.find("Pitfall (sampled motion)") != std::string::npos);
    }
}

TEST_CASE("The float pitfall far from the origin loses an overlap that double in A's frame keeps", "[painter][pitfall]")
{
    const Scene scene = Load(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/pitfall_float.json");
    const FigureSetup setup = SetUpFigure(scene, {});
    const PitfallResult& p = setup.study.pitfall;
    REQUIRE(p.ran);
    REQUIRE(setup.study.textbookResult.overlap);
    CHECK(setup.study.textbookResult.depth == Approx(0.03).margin(1e-9));
    // Float coordinates at 1e6 step by 0.0625: the 0.03 overlap cannot survive them.
    CHECK(std::abs(p.depth - 0.03) > 0.02);
    CHECK(p.verdict.find("steps of 0.0625") != std::string::npos);
    // A's coordinate, 1e6, in the form of B's 1000001.47 that the precision note gives just before it in the
    // verdict (it read "1 000 000" there).
    const std::string verdict = DescribeStep(scene, setup.study, setup.study.VerdictStep());
    CHECK(verdict.find("(1000001.47)") != std::string::npos);
    CHECK(verdict.find("as large as A's (1000000.00)") != std::string::npos);
    CHECK(verdict.find("1 000 000") == std::string::npos);
}

TEST_CASE("Pitfalls on random pairs: scaling keeps every verdict, fewer axes never miss a collision",
          "[painter][pitfall][property]")
{
    testing::Rng rng(31);
    for (int i = 0; i < 2000; ++i)
    {
        const Scene scene = RandomPolygonPair(rng, 10, 0.3);
        const TextbookResult right =
            TextbookCollide(scene.bodies[0].shape, scene.bodies[0].Xf(), scene.bodies[1].shape, scene.bodies[1].Xf());
        if (std::abs(right.overlap ? right.depth : right.gap) < 1e-9)
        {
            continue;
        }
        INFO("pair " << i);
        CHECK(RunPitfall(Pitfall::UnnormalisedAxes, scene, 0, 1).overlap == right.overlap);
        CHECK(RunPitfall(Pitfall::UncheckedDirection, scene, 0, 1).overlap == right.overlap);
        if (right.overlap)
        {
            CHECK(RunPitfall(Pitfall::OneShapesAxes, scene, 0, 1).overlap);
        }
    }
}
