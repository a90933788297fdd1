// SPDX-License-Identifier: MIT
#include "concave_views.h"
#include "legend.h"
#include "world_views.h"

#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>

#include <algorithm>

namespace satviz
{

namespace
{

int BodyIndex(const Scene& scene, const std::string& name, int fallback)
{
    if (name.empty())
    {
        return fallback;
    }
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        if (scene.bodies[i].name == name)
        {
            return static_cast<int>(i);
        }
    }
    return -1;
}

// The figure of one body (a decomposition of a scene with one body): its index, the image size and layers.
FigureSetup SetUpBodyFigure(const Scene& scene, const FigureOptions& options)
{
    FigureSetup setup;
    const SceneView& view = scene.view;
    Figure& figure = setup.figure;
    figure.layers =
        options.setLayers ? options.layers : (view.layers.empty() ? kDefaultLayers : LayersFromNames(view.layers));
    figure.view.width = options.width > 0 ? options.width : view.width;
    figure.view.height = options.height > 0 ? options.height : view.height;
    figure.caption = view.caption;
    figure.kind = view.figure;
    figure.body = BodyIndex(scene, view.bodyA, 0);
    if (figure.body < 0)
    {
        setup.error = "view.figure: names no body to draw";
    }
    return setup;
}

} // namespace

bool FigurePair(const Scene& scene, int& a, int& b)
{
    a = -1;
    b = -1;
    if (scene.bodies.size() < 2)
    {
        return false;
    }
    const int first = BodyIndex(scene, scene.view.bodyA, 0);
    const int second = BodyIndex(scene, scene.view.bodyB, 1);
    if (first < 0 || second < 0 || first == second)
    {
        return false;
    }
    a = first;
    b = second;
    return true;
}

std::string MissingStep(const std::string& field, int step, int steps)
{
    return field + ": step " + std::to_string(step + 1) + " does not exist: this figure has steps 1 to " +
           std::to_string(steps) + " (the last is the verdict)";
}

int FigureStepCount(const Scene& scene, const FigureSetup& setup)
{
    switch (setup.figure.kind)
    {
    case FigureKind::Pair:
        return setup.study.StepCount();
    case FigureKind::Pieces:
        return PieceStepCount(scene, setup.study);
    default:
        return 1;
    }
}

bool FrameScene(const SceneView& frame, const PairStudy& study, LayerMask layers, int width, int height, View& view)
{
    const bool titled = !frame.caption.empty();
    const FigureLayout own = LayoutFigure(study, layers, frame.width, frame.height, titled);
    if (own.sceneBottom - own.sceneTop < 0.25f * static_cast<float>(frame.height))
    {
        return false;
    }
    // The world's panels take the bottom of the image: the view's centre moves up by half their height, to the
    // middle of what is left.
    SceneView shifted = frame;
    shifted.center.y -= 0.5 * WorldPanelsHeight(layers) / frame.zoom;
    view = Reframe(shifted, study, layers, titled, width, height);
    return true;
}

Vec2 SceneViewCenter(const View& camera, LayerMask layers)
{
    return {camera.center.x, camera.center.y + 0.5 * WorldPanelsHeight(layers) / camera.zoom};
}

CaptionReach MeasureCaption(const Scene& scene, const PairStudy& study, const Figure& figure, int steps)
{
    CaptionReach reach;
    if ((figure.layers & kLayerCaption) == 0)
    {
        return reach;
    }
    const ScreenRect whole{0.0f, 0.0f, static_cast<float>(figure.view.width), static_cast<float>(figure.view.height)};
    const auto measure = [&](int step) {
        Figure painted = figure;
        painted.step = step;
        RecordingCanvas canvas;
        PaintFigure(canvas, scene, study, painted);
        for (const DrawCommand* c : canvas.InGroup("caption"))
        {
            for (const ScreenPoint& p : c->points)
            {
                const float below = c->kind == DrawCommand::Kind::Text ? canvas.MeasureText(c->text, c->style).y : 0.0f;
                reach.bandBottom = std::max(reach.bandBottom, p.y + below);
            }
        }
        // What a key must not cover is what the band must not either: the picture, without its texts (the labels
        // keep off the band by themselves), grid, candidate axes and insets.
        const ScreenRect picture = KeyObstacles(canvas, whole);
        if (picture.minY <= picture.maxY)
        {
            reach.pictureTop = std::min(reach.pictureTop, picture.minY);
        }
    };
    if (steps > 40)
    {
        measure(figure.step);
    }
    for (int step = 0; step <= 40 && step < steps; ++step)
    {
        measure(step);
    }
    return reach;
}

View BelowCaption(const View& view, const PairStudy& study, LayerMask layers, bool titled, const CaptionReach& reach)
{
    const FigureLayout layout = LayoutFigure(study, layers, view.width, view.height, titled);
    const float margin = 6.0f; // between the band's rule and the picture
    const float top = reach.bandBottom + margin;
    // A picture that runs on past the canvas's top (a wall taller than the canvas) is framed so on purpose.
    if (top <= layout.sceneTop + 0.5f || reach.pictureTop >= top || reach.pictureTop < 0.5f ||
        layout.sceneBottom - top < 1.0f)
    {
        return view;
    }
    const double scale =
        static_cast<double>(layout.sceneBottom - top) / static_cast<double>(layout.sceneBottom - layout.sceneTop);
    View moved = view;
    moved.zoom = view.zoom * scale;
    // The world point in the middle of the old scene area goes to the middle of the new one.
    const Vec2 middle = ToWorld(view, {0.5f * static_cast<float>(view.width), 0.5f * (layout.sceneTop + layout.sceneBottom)});
    moved.center = {middle.x, middle.y + (0.5 * (top + layout.sceneBottom) - 0.5 * view.height) / moved.zoom};
    return moved;
}

FigureSetup SetUpFigure(const Scene& scene, const FigureOptions& options)
{
    FigureSetup setup;
    const SceneView& view = scene.view;
    if ((view.figure == FigureKind::Decomposition || view.figure == FigureKind::Slice) && scene.bodies.size() < 2)
    {
        // A figure of one body needs no pair: nothing is tested.
        return SetUpBodyFigure(scene, options);
    }
    if (scene.bodies.size() < 2)
    {
        setup.error =
            "bodies: a figure needs at least two bodies, the scene has " + std::to_string(scene.bodies.size());
        return setup;
    }
    const int a = BodyIndex(scene, view.bodyA, 0);
    const int b = BodyIndex(scene, view.bodyB, 1);
    if (a < 0 || b < 0 || a == b)
    {
        setup.error = "view.pair: names no pair of distinct bodies";
        return setup;
    }
    // SAT holds for convex shapes only: the pair figure of a concave body would test its hull, the classic
    // mistake. Its test is the concave one, piece by piece, which the pieces figure draws.
    const bool concavePair = scene.bodies[static_cast<size_t>(a)].IsConcave() || scene.bodies[static_cast<size_t>(b)].IsConcave();
    const FigureKind kind = view.figure == FigureKind::Pair && concavePair ? FigureKind::Pieces : view.figure;
    setup.study =
        StudyPair(scene, a, b, view.query, view.singlePrecision, options.setSteps ? options.steps : view.steps);
    setup.study.pitfall = RunPitfall(view.pitfall, scene, a, b);

    Figure& figure = setup.figure;
    figure.layers =
        options.setLayers ? options.layers : (view.layers.empty() ? kDefaultLayers : LayersFromNames(view.layers));
    const int width = options.width > 0 ? options.width : view.width;
    const int height = options.height > 0 ? options.height : view.height;
    if (view.fit || !FrameScene(view, setup.study, figure.layers, width, height, figure.view))
    {
        figure.view = FitFigure(scene, setup.study, figure.layers, width, height);
    }
    const int step = options.setStep ? options.step : view.step;
    figure.kind = kind;
    const int steps = FigureStepCount(scene, setup);
    if (step >= steps)
    {
        setup.error = MissingStep(options.setStep ? "--step" : "view.step", step, steps);
        return setup;
    }
    figure.step = step < 0 ? (kind == FigureKind::Pieces ? steps - 1 : setup.study.VerdictStep()) : step;
    figure.time = view.time;
    figure.caption = view.caption;
    figure.sim = options.sim;
    figure.kind = kind;
    figure.body = BodyIndex(scene, view.bodyA, 0);
    return setup;
}

} // namespace satviz
