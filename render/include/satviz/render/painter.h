// SPDX-License-Identifier: MIT
// satviz render: the painter, the one place that decides what a SAT step looks like. It draws in world units
// through a View onto any Canvas; the app and satviz-render call it with the same figure and get the same picture.
#pragma once

#include <satviz/render/canvas.h>
#include <satviz/render/study.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace satviz
{

/// A set of drawing layers, one bit per layer.
using LayerMask = uint32_t;

/// The drawing layers. A layer that is off costs nothing: the painter skips its work entirely.
enum Layer : LayerMask
{
    kLayerShapes = 1u << 0,     ///< the bodies, filled and outlined
    kLayerLabels = 1u << 1,     ///< body names, vertex and edge numbers
    kLayerNormals = 1u << 2,    ///< outward edge normals
    kLayerAxes = 1u << 3,       ///< every candidate axis, faint, through the pair
    kLayerProjection = 1u << 4, ///< the current axis, both projection intervals on it and on a number line
    kLayerExit = 1u << 5,       ///< the early exit: the separating line of a separating axis
    kLayerBest = 1u << 6,       ///< the best (least overlap or latest entry) axis so far
    kLayerMtv = 1u << 7,        ///< the minimum translation vector and B moved out by it
    kLayerContacts = 1u << 8,   ///< contact points, reference face, incident edge, clipping planes
    kLayerSwept = 1u << 9,      ///< velocities, swept intervals, entry and exit times on a time bar
    kLayerGhost = 1u << 10,     ///< the moving shapes at the time of impact (and at the chosen time)
    kLayerCaption = 1u << 11,   ///< the caption above the figure
    /// An inset of the Minkowski difference A - B: the origin inside it exactly when the shapes overlap, the MTV as
    /// the origin's shortest way out, and for sweeps the relative motion as a ray from the origin.
    kLayerMinkowski = 1u << 12,
};

/// Every layer.
constexpr LayerMask kAllLayers = (1u << 13) - 1;
/// The layers drawn when a scene does not choose: all but the normals, the candidate axes and the Minkowski inset.
constexpr LayerMask kDefaultLayers = kAllLayers & ~(kLayerNormals | kLayerAxes | kLayerMinkowski);

/// The layer of a name of ViewLayerNames() ("shapes", "labels", ...), or 0 for an unknown name.
LayerMask LayerFromName(std::string_view name);

/// The mask of a list of layer names; unknown names are ignored (the scene loader rejects them).
LayerMask LayersFromNames(const std::vector<std::string>& names);

/// What to picture: the camera, the layers, the trace step and the time.
struct Figure
{
    View view;                         ///< camera and image size
    LayerMask layers = kDefaultLayers; ///< layers to draw
    int step = 0;                      ///< trace step: 0 .. StepCount() - 1 (the last is the verdict)
    double time = -1.0;                ///< sweeps: also draw the bodies at this time in [0, 1]; -1: not drawn
    std::string caption;               ///< the figure's title, drawn above the step's explanation; empty: none
};

/// Screen regions of a figure: the caption band on top, the number-line panel at the bottom, the scene between.
struct FigureLayout
{
    float sceneTop = 0.0f;    ///< top of the scene area
    float sceneBottom = 0.0f; ///< bottom of the scene area
    float panelTop = 0.0f;    ///< top of the panel (== height when there is none)
};

/// Where the caption, the scene and the panel go for these layers and image size; `titled`: the figure has a
/// caption of its own (a title line above the step's explanation).
FigureLayout LayoutFigure(const PairStudy& study, LayerMask layers, int width, int height, bool titled = false);

/// The camera that frames the pair (both shapes over the whole step when sweeping, and the room the axis line
/// needs beside them) in the scene area; the same for every step, so stepping does not move the picture.
View FitFigure(const Scene& scene, const PairStudy& study, LayerMask layers, int width, int height);

/// Paints the figure: the background, every body (the pair in colour, the others grey), the layers of the step.
void PaintFigure(Canvas& canvas, const Scene& scene, const PairStudy& study, const Figure& figure);

} // namespace satviz
