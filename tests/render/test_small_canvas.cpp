// SPDX-License-Identifier: MIT
// Every figure of the course on the app's canvases, through a recording canvas: the canvas a 900 x 650 window
// leaves beside its panels, the one beside a lesson, and the smallest. No text runs past the canvas's edges.
#include "render/painter_support.h"
#include "support/scene_files.h"

#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/sim_record.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace satviz;

namespace
{

/// The canvases of the app: beside the panels of a 900 x 650 window (512 x 608), beside a lesson in a 1280 x 800
/// window (460 x 758), and the smallest it keeps (kMinCanvasWidth x kMinCanvasHeight, 360 x 600).
const std::vector<std::pair<int, int>> kAppCanvases = {{512, 608}, {460, 758}, {360, 600}};

/// The texts of `canvas` that run past a `width` x `height` canvas's edges (by more than half a pixel of rounding),
/// each with where it lies. The key drawn alone runs on below the canvas's bottom on purpose, saying so: the rest of
/// it is dragged into sight.
std::vector<std::string> TextsOutside(const RecordingCanvas& canvas, int width, int height)
{
    const std::vector<std::string> texts = canvas.Texts();
    const bool keyScrolls = std::find(texts.begin(), texts.end(), "drag the canvas up for the rest of the key") !=
                            texts.end();
    std::vector<std::string> outside;
    for (const DrawCommand& c : canvas.commands)
    {
        if (c.kind != DrawCommand::Kind::Text || c.text.empty())
        {
            continue;
        }
        const ScreenPoint size = FontTextSize(c.text, c.style);
        const ScreenPoint at = c.points[0];
        const bool below = at.y + size.y > static_cast<float>(height) + 0.5f && !(keyScrolls && c.group == "legend");
        if (at.x < -0.5f || at.y < -0.5f || at.x + size.x > static_cast<float>(width) + 0.5f || below)
        {
            std::ostringstream where;
            where << "'" << c.text << "' (" << c.group << ") from " << at.x << ", " << at.y << " to "
                  << at.x + size.x << ", " << at.y + size.y;
            outside.push_back(where.str());
        }
    }
    return outside;
}

/// The pairs of texts of group `group` that overlap (by more than half a pixel each way).
std::vector<std::string> TextsOnTexts(const RecordingCanvas& canvas, const std::string& group)
{
    std::vector<std::string> overlaps;
    const std::vector<const DrawCommand*> drawn = canvas.InGroup(group);
    for (size_t i = 0; i < drawn.size(); ++i)
    {
        for (size_t j = i + 1; j < drawn.size(); ++j)
        {
            const DrawCommand& a = *drawn[i];
            const DrawCommand& b = *drawn[j];
            if (a.kind != DrawCommand::Kind::Text || b.kind != DrawCommand::Kind::Text)
            {
                continue;
            }
            const ScreenPoint sa = FontTextSize(a.text, a.style);
            const ScreenPoint sb = FontTextSize(b.text, b.style);
            const float dx = std::min(a.points[0].x + sa.x, b.points[0].x + sb.x) - std::max(a.points[0].x, b.points[0].x);
            const float dy = std::min(a.points[0].y + sa.y, b.points[0].y + sb.y) - std::max(a.points[0].y, b.points[0].y);
            if (dx > 0.5f && dy > 0.5f)
            {
                overlaps.push_back("'" + a.text + "' on '" + b.text + "' (" + group + ")");
            }
        }
    }
    return overlaps;
}

} // namespace

TEST_CASE("On the app's canvases no text of any figure of the course runs past the canvas's edges", "[painter]")
{
    // On the smallest canvas the slice and decomposition figures' subtitles ran past their panel and the canvas's
    // right edge, and at 512 x 608 (a 900 x 650 window) the plots' headers ran into each other ("total" over
    // "Momentum (kg m/s)") and off the canvas. Every scene of tutorials/ at every step of its figure, as the scene
    // asks for it, in the face view, and with the plots of its world for a scene that has one.
    std::vector<std::string> problems;
    int figures = 0;
    for (const std::string& file : testing::TutorialSceneFiles(true))
    {
        const std::string name = std::filesystem::relative(file, std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes")
                                     .generic_string();
        Scene scene = painter_test::Load(file);
        if (scene.bodies.empty())
        {
            continue;
        }
        // A world's scene as the app plays it: its steps recorded, the plots over them.
        SimRecord record;
        const bool world = scene.hasWorld;
        int a = -1;
        int b = -1;
        if (world && FigurePair(scene, a, b))
        {
            REQUIRE(SimulateSceneRecorded(scene, std::max(scene.view.simSteps, 60), a, b, record).empty());
        }
        for (const auto& [width, height] : kAppCanvases)
        {
            for (const int variant : {0, 1, 2})
            {
                // The figure as the scene asks for it; in the face view; with the plots of its world.
                const bool faces = variant == 1;
                const bool plots = variant == 2;
                if (plots && (!world || a < 0))
                {
                    continue;
                }
                FigureOptions options;
                options.width = width;
                options.height = height;
                options.setSteps = faces;
                options.steps = StepView::Faces;
                options.sim = world && a >= 0 ? &record : nullptr;
                FigureSetup setup = SetUpFigure(scene, options);
                if (!setup.Ok())
                {
                    continue;
                }
                if (plots)
                {
                    setup.figure.layers |= kLayerPlots;
                }
                if (faces && setup.figure.kind != FigureKind::Pair)
                {
                    continue;
                }
                const int steps = std::min(FigureStepCount(scene, setup), 40);
                for (int k = 0; k < steps; ++k)
                {
                    const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                    ++figures;
                    std::vector<std::string> found = TextsOutside(canvas, width, height);
                    // The plots' headers, value ranges and step numbers keep apart ("total" sat over "Momentum").
                    for (std::string& overlap : TextsOnTexts(canvas, "plots"))
                    {
                        found.push_back(std::move(overlap));
                    }
                    for (const std::string& text : found)
                    {
                        problems.push_back(name + (plots ? " with plots" : faces ? " faces" : "") + " step " +
                                           std::to_string(k + 1) +
                                           " at " + std::to_string(width) + " x " + std::to_string(height) + ": " +
                                           text);
                    }
                }
            }
        }
    }
    CHECK(figures > 1000);
    for (const std::string& p : problems)
    {
        UNSCOPED_INFO(p);
    }
    INFO(problems.size() << " texts outside");
    CHECK(problems.empty());
}
