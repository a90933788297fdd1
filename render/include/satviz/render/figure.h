// SPDX-License-Identifier: MIT
// satviz render: from a scene file to a figure, applying the scene's view block and the caller's overrides. The
// app's export and satviz-render both go through here, so the same scene gives the same picture.
#pragma once

#include <cmath>

#include <satviz/render/painter.h>

#include <string>

namespace satviz
{

/// Choices that override a scene's view block (satviz-render's options, the app's state). Unset fields keep the
/// scene's choice.
struct FigureOptions
{
    int width = 0;                       ///< image width; 0: the scene's (default 800)
    int height = 0;                      ///< image height; 0: the scene's (default 600)
    bool setStep = false;                ///< use `step` instead of the scene's
    int step = -1;                       ///< trace step, from 0 (a user's step N is N - 1); -1: the verdict
    bool setSteps = false;               ///< use `steps` instead of the scene's
    StepView steps = StepView::Textbook; ///< which algorithm the steps show
    bool setLayers = false;              ///< use `layers` instead of the scene's
    LayerMask layers = 0;                ///< layers to draw
    /// The stepped world for the world's layers (not owned; see Figure::sim); null: the scene was not stepped.
    const SimRecord* sim = nullptr;
};

/// A figure ready to paint, or why it cannot be made.
struct FigureSetup
{
    PairStudy study;   ///< the queries on the pictured pair
    Figure figure;     ///< camera, layers, step
    std::string error; ///< "view.step: ..." when the scene cannot be pictured; empty on success
    /// True when the figure can be painted.
    bool Ok() const { return error.empty(); }
};

/// The pair a figure of the scene pictures: view.pair's bodies, else the first two. False, with both -1, when the
/// scene has fewer than two bodies or view.pair names no pair of distinct bodies.
bool FigurePair(const Scene& scene, int& a, int& b);

/// The steps a figure of the scene can show: those of the pair's SAT test (PairStudy::StepCount), those of a
/// pieces figure (the broadphase over the pieces' boxes, each pair of pieces tested, the verdict), or 1 for a figure
/// of its own that has no steps (a decomposition, a slice, a disc cast).
int FigureStepCount(const Scene& scene, const FigureSetup& setup);

/// Why a figure has no trace step `step` (from 0) of the `steps` it has, asked for by `field` ("view.step",
/// "--step"): "view.step: step 9 does not exist: this figure has steps 1 to 5 (the last is the verdict)", its
/// steps counted from 1 as the file and the command line count them.
std::string MissingStep(const std::string& field, int step, int steps);

/// The camera of a slice figure (FigureKind::Slice) of the figure's size that draws `body` and the scene's cut
/// filling the before panel, the left half below the caption band and the panel's title, at the scale the figure
/// gives both panels when it frames itself. The app draws the slice through its camera and opens it so.
View FrameSlice(const Scene& scene, int body, const Figure& figure);

/// The camera of a decomposition figure (FigureKind::Decomposition) of the figure's size that draws `body` filling
/// the left panel below the caption band and the panel's title, at the scale the figure gives both panels when it
/// frames itself. The app draws the decomposition through its camera, the right panel half the image to the right,
/// and opens it so.
View FrameDecomposition(const Scene& scene, int body, const Figure& figure);

/// The camera of a pair figure of `width` x `height` for a scene that frames itself: `frame` is its view block, a
/// centre and zoom for a figure of frame.width x frame.height whose centre is the middle of what the world's panels
/// leave above them. The same world rectangle is shown, scaled to the new scene area and centred in it (Reframe); at
/// the frame's own size, that is the frame. False, leaving `view` as it was, when the frame leaves its scene almost no
/// room at its own size (the world's panels fill that figure): scaled, that sliver would show nothing, and the caller
/// fits the pair instead (FitFigure). SetUpFigure frames a figure of another size than its scene's so, and the app
/// frames a lesson's scene so on the canvas left beside the panels.
bool FrameScene(const SceneView& frame, const PairStudy& study, LayerMask layers, int width, int height, View& view);

/// The centre a view block gives for `camera` to be the camera of a figure of its size with these layers: the
/// inverse of FrameScene at the frame's own size. The app saves a scene's view so, and it opens as it was shown.
Vec2 SceneViewCenter(const View& camera, LayerMask layers);

/// What a caption band and a picture take of a figure's height, over its steps.
struct CaptionReach
{
    float bandBottom = 0.0f;      ///< the lowest the caption band reaches (0: no caption)
    float pictureTop = INFINITY;  ///< the highest the picture reaches in the image (bodies, marks; not texts, grid
                                  ///< or axes), 0 when it runs on past the top
};

/// How far down the caption band of `figure` reaches over its first `steps` steps (the band grows past
/// LayoutFigure's sceneTop when a long caption wraps on a narrow canvas), and how far up its picture does, measured
/// by painting each step on a recording canvas; above 40 steps only the figure's own step is painted.
CaptionReach MeasureCaption(const Scene& scene, const PairStudy& study, const Figure& figure, int steps);

/// `view`, which frames its picture in the scene area LayoutFigure gives (from sceneTop down), scaled and moved so
/// that the same picture lies in the area below the band instead, its middle in that area's middle, when the band
/// of `reach` would cover the picture; else `view` itself, as when the picture runs on past the canvas's top (a wall
/// taller than the canvas, framed so on purpose).
View BelowCaption(const View& view, const PairStudy& study, LayerMask layers, bool titled, const CaptionReach& reach);

/// Sets up the figure of a scene: picks the pair (view.pair, or the first two bodies), runs the queries, frames
/// the camera (fitting the pair, or framing the scene's own view for the figure's size: FrameScene), resolves the
/// step (-1: the verdict). Errors name the scene field at fault.
FigureSetup SetUpFigure(const Scene& scene, const FigureOptions& options);

} // namespace satviz
