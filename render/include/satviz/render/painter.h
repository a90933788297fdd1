// SPDX-License-Identifier: MIT
// satviz render: the painter, the one place that decides what a SAT step looks like. It draws in world units
// through a View onto any Canvas; the app and satviz-render call it with the same figure and get the same picture.
#pragma once

#include <satviz/render/canvas.h>
#include <satviz/layers.h>
#include <satviz/render/study.h>
#include <satviz/sim_record.h>

#include <string>
#include <vector>

namespace satviz
{

/// A region of the image that the caller draws over once the figure is painted, in pixels.
struct DrawnOver
{
    ScreenPoint min; ///< top-left corner
    ScreenPoint max; ///< bottom-right corner
};

/// What to picture: the camera, the layers, the trace step and the time.
struct Figure
{
    View view;                         ///< camera and image size
    LayerMask layers = kDefaultLayers; ///< layers to draw
    int step = 0;                      ///< trace step: 0 .. StepCount() - 1 (the last is the verdict)
    double time = -1.0;                ///< sweeps: also draw the bodies at this time in [0, 1]; -1: not drawn
    std::string caption;               ///< the figure's title, drawn above the step's explanation; empty: none
    /// The stepped world the broadphase, response, hits and plots layers draw (not owned); null: the scene was
    /// not stepped, and those layers say so.
    const SimRecord* sim = nullptr;
    /// The hits layer: the hit of the step (an index into sim->lastStep.hits) whose instant is shown, its two
    /// bodies solid where they touch; -1: every hit, dashed.
    int hit = -1;
    /// What the figure shows: the pair's SAT test (Pair), or a figure of its own drawn in panels (a decomposition,
    /// ...), for which `view` gives only the image size.
    FigureKind kind = FigureKind::Pair;
    /// Figures of one body (a decomposition): that body's index in the scene.
    int body = -1;
    /// The pieces, disc-cast and slice figures frame their bodies themselves (true), or draw them through `view`'s
    /// camera (false, the before panel of a slice; its after panel half the image to the right): the app's
    /// canvas, which maps the pointer to the world by that camera, so that a body is dragged where it is drawn.
    bool framesItself = true;
    /// What the caller draws over the figure (the app's handles of the selected body): no label is placed on it,
    /// where it would be hidden.
    std::vector<DrawnOver> drawnOver;
};

/// Screen regions of a figure: the caption band on top, the number-line panel at the bottom, the scene between.
struct FigureLayout
{
    float sceneTop = 0.0f;    ///< top of the scene area
    float sceneBottom = 0.0f; ///< bottom of the scene area
    float panelTop = 0.0f;    ///< top of the panel (== worldTop when there is none)
    float worldTop = 0.0f;    ///< top of the world's panels below it (== height when there are none)
};

/// Where the caption, the scene and the panel go for these layers and image size; `titled`: the figure has a
/// caption of its own (a title line above the step's explanation).
FigureLayout LayoutFigure(const PairStudy& study, LayerMask layers, int width, int height, bool titled = false);

/// The camera that frames the pair (both shapes over the whole step when sweeping, and the room the axis line
/// needs beside them) in the scene area; the same for every step, so stepping does not move the picture.
View FitFigure(const Scene& scene, const PairStudy& study, LayerMask layers, int width, int height);

/// The camera that shows in a figure of `width` x `height` what `frame` (a view block's centre and zoom, for a
/// figure of its own size) showed in its scene area: the same world rectangle, scaled to fit the new scene area and
/// centred in it. The scene area lies between the caption band and the number line, which keep their sizes in
/// pixels. The app frames a scene that frames itself so on a canvas of another size.
View Reframe(const SceneView& frame, const PairStudy& study, LayerMask layers, bool titled, int width, int height);

/// A hit on the hits layer's time bar: its dot, and its label and the label's box, in figure pixels.
struct HitMark
{
    ScreenPoint dot;      ///< the hit's dot on the bar, at its time within the step
    ScreenPoint labelMin; ///< top-left corner of its label
    ScreenPoint labelMax; ///< bottom-right corner of its label
    std::string text;     ///< the label: number, bodies, time
};

/// Where the hits layer's time bar puts the figure's hits, in the order resolved (as many as it draws), with
/// `canvas` measuring the labels; empty when the hits layer is off or the figure has no stepped world.
std::vector<HitMark> HitMarks(Canvas& canvas, const Scene& scene, const PairStudy& study, const Figure& figure);

/// Paints the figure: the background, every body (the pair in colour, the others grey), the layers of the step.
void PaintFigure(Canvas& canvas, const Scene& scene, const PairStudy& study, const Figure& figure);

} // namespace satviz
