// SPDX-License-Identifier: MIT
// Helpers of the painter's tests: loading a scene as satviz-render draws it, stepping a lesson's world, random pairs,
// painting a step on a recording canvas, projecting a placed shape, reading a number from the drawn texts, the lists of
// the course's figures and what a drawn label names.
#pragma once

#include "support/random_shapes.h"

#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/scene_world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace satviz::painter_test
{

/// A scene file, which must load (a polygon may be concave, as satviz-render reads it).
inline Scene Load(const std::string& file)
{
    SceneResult result = LoadScene(file, SceneOptions{true});
    INFO(result.error);
    REQUIRE(result.Ok());
    return result.scene;
}

/// A scene file as satviz-render draws it: loaded (Load) and, a scene of a world, stepped to the step its view
/// shows (view.simSteps).
inline Scene LoadSimulated(const std::string& file)
{
    Scene scene = Load(file);
    REQUIRE(SimulateScene(scene, scene.view.simSteps).empty());
    return scene;
}

/// tutorials/scenes/`stem`.json as satviz-render draws it (LoadSimulated).
inline Scene LessonScene(const std::string& stem)
{
    return LoadSimulated(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + stem + ".json");
}

/// A scene of tutorials/scenes stepped by the world, with the record of its steps.
struct SteppedScene
{
    Scene scene;       ///< with the world's state after the last step, as satviz-sim stores it
    SimRecord record;  ///< the steps, recorded with the pair the scene's figure shows (FigurePair)
    FigureSetup setup; ///< the figure of the last step, once a test has set one up
};

/// tutorials/scenes/`name`, which must load and step, stepped `steps` times from its start as satviz-sim steps it
/// (SimulateSceneRecorded).
inline SteppedScene StepScene(const std::string& name, int steps)
{
    SteppedScene s;
    s.scene = Load(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + name);
    int a = -1;
    int b = -1;
    REQUIRE(FigurePair(s.scene, a, b));
    REQUIRE(SimulateSceneRecorded(s.scene, steps, a, b, s.record).empty());
    return s;
}

/// A scene of two bodies named A and B, each made by `make(k)`: k = 0 for A, then k = 1 for B (so that random draws
/// come in that order).
template <typename MakeBody>
Scene PairOf(MakeBody make)
{
    Scene scene;
    for (int k = 0; k < 2; ++k)
    {
        Body body = make(k);
        body.name = k == 0 ? "A" : "B";
        scene.bodies.push_back(std::move(body));
    }
    return scene;
}

/// Two random convex polygons A and B of 3 to maxVertices vertices, radius 1 scaled by minScale to 1, at random
/// places within 1.2 of the origin on each axis and random angles: the random pairs of the views' property tests.
inline Scene RandomPolygonPair(testing::Rng& rng, int maxVertices, double minScale)
{
    return PairOf([&](int) {
        Body body;
        body.shape = MakeShape(testing::RandomPolygon(rng, rng.Int(3, maxVertices), 1.0, rng.Uniform(minScale, 1.0)));
        body.position = {rng.Uniform(-1.2, 1.2), rng.Uniform(-1.2, 1.2)};
        body.angle = rng.Uniform(-3.0, 3.0);
        return body;
    });
}

/// The figure of one step with the given layers, on a recording canvas.
inline RecordingCanvas Paint(const Scene& scene, FigureSetup& setup, int step, LayerMask layers)
{
    setup.figure.step = step;
    setup.figure.layers = layers;
    RecordingCanvas canvas;
    PaintFigure(canvas, scene, setup.study, setup.figure);
    return canvas;
}

/// Step `step` of the figure `setup` of `scene` with the figure's own layers, on a recording canvas.
inline RecordingCanvas PaintStep(const Scene& scene, FigureSetup& setup, int step)
{
    setup.figure.step = step;
    RecordingCanvas canvas;
    PaintFigure(canvas, scene, setup.study, setup.figure);
    return canvas;
}

/// Lowest and highest projection of a placed shape onto d, from its vertices (or centre and radius).
inline std::pair<double, double> Project(const Body& body, Vec2 d)
{
    const Transform xf = body.Xf();
    if (body.shape.type == ShapeType::Circle)
    {
        const double c = Dot(TransformPoint(xf, body.shape.circle.center), d);
        return {c - body.shape.circle.radius, c + body.shape.circle.radius};
    }
    double lo = INFINITY;
    double hi = -INFINITY;
    for (const Vec2& v : body.shape.polygon.Vertices())
    {
        const double s = Dot(TransformPoint(xf, v), d);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
    return {lo, hi};
}

/// The number after `prefix` in the first text of the group that starts with it; NaN when there is none.
inline double NumberAfter(const RecordingCanvas& canvas, const std::string& group, const std::string& prefix)
{
    for (const DrawCommand* c : canvas.InGroup(group))
    {
        if (c->kind == DrawCommand::Kind::Text && c->text.rfind(prefix, 0) == 0)
        {
            return std::strtod(c->text.c_str() + prefix.size(), nullptr);
        }
    }
    return std::nan("");
}

/// The lists of tutorials/figures.cmake, by name (SATVIZ_FIGURE_SCENES, SATVIZ_STEP_SCENES, ...): the scene stems of
/// each set(NAME ...) block.
inline std::map<std::string, std::vector<std::string>> CourseFigureLists()
{
    std::ifstream in(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/figures.cmake");
    REQUIRE(in);
    std::map<std::string, std::vector<std::string>> lists;
    std::string current;
    for (std::string line; std::getline(in, line);)
    {
        if (line.rfind("set(SATVIZ_", 0) == 0)
        {
            current = line.substr(4, line.find_first_of(" )", 4) - 4);
            lists[current];
            continue;
        }
        std::istringstream words(line);
        for (std::string word; !current.empty() && words >> word;)
        {
            if (word == ")")
            {
                current.clear();
                break;
            }
            lists[current].push_back(word);
        }
    }
    return lists;
}

/// Whether a label is an edge's name, "e" and a number ("e3").
inline bool IsEdgeName(const std::string& text)
{
    return text.size() >= 2 && text[0] == 'e' && text.find_first_not_of("0123456789", 1) == std::string::npos;
}

/// Whether a label is a vertex number ("3").
inline bool IsVertexNumber(const std::string& text)
{
    return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
}

} // namespace satviz::painter_test
