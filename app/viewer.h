// SPDX-License-Identifier: MIT
// satviz app: the viewer, what the canvas shows of the document's scene: the choices (pair, query, layers,
// precision...), the trace step, the time, the camera and the canvas, and the figure of the pair's test, run on a
// worker thread for large pairs. No ImGui here.
#pragma once

#include "view_choices.h"

#include <satviz/render/figure.h>
#include <satviz/render/view.h>
#include <satviz/scene.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <string>
#include <utility>

namespace satviz
{

/// The view of a scene: what is chosen to be shown, the step of the trace, the camera, and the test of the pair.
class Viewer
{
  public:
    /// A viewer that tests pairs of more than `backgroundVertices` vertices (A's and B's together) on a worker
    /// thread.
    explicit Viewer(int backgroundVertices);

    /// Starts over on a scene just opened: its view block's choices, camera, step and time; no figure until
    /// Refresh has tested the pair.
    void Reset(const Scene& scene);

    /// The choices of what is shown.
    const ViewChoices& Choices() const { return m_choices; }
    /// Takes other choices (a change in the panels, undo, redo); Refresh then tests the pair again.
    void SetChoices(const ViewChoices& choices) { m_choices = choices; }

    /// Tests the pair of `scene` again, keeping the verdict shown if it was, else the step where it still exists; a
    /// pair that no longer exists is dropped from the choices (the first two bodies are shown). A pair of more
    /// vertices than the background limit is tested on a worker thread, and the figure shows the last finished
    /// test until TakeFinishedTest.
    /// True when the new figure is in (false: it runs, or waits for the canvas's first frame).
    bool Refresh(const Scene& scene);
    /// Takes in the test that ran on the worker thread once it is done; true when it did.
    bool TakeFinishedTest();
    /// True, once, when the scene changed while the worker thread tested it: Refresh should test it again.
    bool TakeRetest();
    /// True while a test of the pair runs on the worker thread.
    bool Studying() const { return m_job != nullptr; }
    /// Vertices of the chosen pair of `scene` (a circle counts one).
    int PairVertices(const Scene& scene) const;
    /// The pair's queries and the figure of the last finished test.
    const FigureSetup& Setup() const { return m_setup; }
    /// True when the last finished test is of a pair: a figure of one body (a decomposition or a slice of a scene
    /// that holds that body alone) has a figure but no pair, no steps and nothing to inspect.
    bool TestsPair() const { return m_setup.Ok() && m_setup.study.bodyA >= 0 && m_setup.study.bodyB >= 0; }
    /// True when the panels show SAT's steps and numbers for the pair: not for a figure that answers by another
    /// method, piece by piece or by casting a disc, where they would be those of a concave body's hull and
    /// contradict the canvas (a disc stopped on the hull's lid, not in the cup).
    bool ShowsSatNumbers() const
    {
        return TestsPair() && m_setup.figure.kind != FigureKind::Pieces && m_setup.figure.kind != FigureKind::DiscCast;
    }
    /// The scene that Setup() describes: the current one, or the one before the edits whose test still runs.
    const Scene& Studied() const { return m_studied; }
    /// The figure to paint now: the last test's, with the camera, the step and the stepped world.
    Figure CurrentFigure() const;
    /// The stepped world the world's layers draw (not owned; it outlives the viewer's use of it); null: none.
    void SetSim(const SimRecord* sim) { m_sim = sim; }
    /// Shows the instant of hit `hit` of the stepped world's step (Figure::hit); -1: every hit.
    void SetHit(int hit) { m_hit = hit; }
    /// The hit whose instant is shown, -1 for none.
    int Hit() const { return m_hit; }

    /// The trace step shown, from 0.
    int Step() const { return m_step; }
    /// Shows trace step `step`; one that does not exist shows the verdict.
    void ShowStep(int step);
    /// Once, after the first test of a scene whose view.step is past the figure's last step (a file satviz-render
    /// refuses): why it is shown at the verdict instead, in one line that names the field; empty otherwise.
    std::string TakeStepNotice() { return std::exchange(m_stepNotice, std::string()); }
    /// The last step, the verdict: the pair's SAT test's (PairStudy::VerdictStep), or for a concave pair the
    /// pieces figure's, after the broadphase and each pair of pieces tested.
    int VerdictStep() const;
    /// The step after (direction 1) or before (-1) `step` that the arrows and Play show: PairStudy::NextStep, or
    /// for a concave pair the next piece step.
    int NextStep(int step, int direction) const;
    /// True while stepping automatically.
    bool Playing() const { return m_playing; }
    /// Starts or stops stepping automatically; starting at the verdict starts from the first step (that is not a
    /// face decided without evaluation, PairStudy::NextStep).
    void TogglePlay();
    /// Lets `seconds` pass: while playing, a step every kPlayInterval (past the faces decided without evaluation,
    /// PairStudy::NextStep), stopping at the verdict.
    void Advance(double seconds);
    /// While playing, the seconds until Advance shows the next step.
    double SecondsUntilNextStep() const { return std::max(0.0, kPlayInterval - m_playClock); }
    /// Sweeps: the time at which the moving bodies are drawn, in [0, 1]; -1: not drawn.
    double Time() const { return m_time; }
    /// Draws the moving bodies again (a ghost) at time `time` in [0, 1]; -1: not drawn.
    void SetTime(double time);

    /// The canvas camera.
    const View& Camera() const { return m_camera; }
    /// True while the camera follows the fit of the pair (until the user pans or zooms).
    bool CameraFit() const { return m_cameraFit; }
    /// True while the camera shows the framing of the scene's view block (its centre and zoom, made for a figure
    /// of its width and height) scaled to fit the canvas, until the user pans, zooms or fits the pair.
    bool CameraFramed() const { return m_framed; }
    /// Lets the camera follow the fit of the pair again, from the next Refresh.
    void FitCamera()
    {
        m_cameraFit = true;
        m_framed = false;
    }
    /// Holds the camera where it is (the scene changes under the pointer).
    void HoldCamera();
    /// Puts the camera's centre at world point `center`, `zoom` pixels per unit, and holds it there.
    void SetCamera(Vec2 center, double zoom);
    /// Moves the camera so the world follows a drag of (dx, dy) pixels, and holds it there.
    void PanCamera(float dx, float dy);
    /// Zooms by `factor` about screen point `fixed` of the canvas, and holds the camera there.
    void ZoomCamera(ScreenPoint fixed, double factor);

    /// Places the canvas at `origin` in the window, `width` x `height` pixels; true when its size changed (or on
    /// its first frame): Refresh then fits the figure to it. A held camera keeps its centre and scales its zoom by
    /// the canvas's change, so that what was in sight stays in sight.
    bool PlaceCanvas(ScreenPoint origin, int width, int height);
    /// The canvas's top-left corner in the window, in pixels.
    ScreenPoint CanvasOrigin() const { return m_canvasOrigin; }
    /// The canvas width in pixels.
    int CanvasWidth() const { return m_canvasWidth; }
    /// The canvas height in pixels.
    int CanvasHeight() const { return m_canvasHeight; }

    /// Writes what is shown into the view block of `saved` (the document's scene): the camera (or "fit"), the
    /// canvas size, the choices, the pair tested, the step and the time.
    void WriteView(Scene& saved) const;

    /// Seconds per step while playing.
    static constexpr double kPlayInterval = 0.9;

  private:
    /// A test of the pair on the worker thread: the scene and options it runs on, its result once done.
    struct StudyJob
    {
        Scene scene;
        FigureOptions options;
        FigureSetup result;
        std::atomic<bool> done{false};
    };

    void Adopt(FigureSetup fresh, Scene studied);
    // Keeps the camera as the user leaves it, with the canvas size of that moment (m_held).
    void Hold();

    int m_backgroundVertices;
    const SimRecord* m_sim = nullptr;
    int m_hit = -1;
    ViewChoices m_choices;
    FigureSetup m_setup;
    Scene m_studied;
    std::shared_ptr<StudyJob> m_job;
    bool m_retest = false;
    int m_step = 0;
    bool m_stepAsked = false;  // m_step is still the scene's view.step, not yet checked against a test of it
    std::string m_stepNotice;  // TakeStepNotice
    bool m_playing = false;
    double m_playClock = 0.0;
    double m_time = -1.0;
    View m_camera;
    bool m_cameraFit = true;
    bool m_framed = false;
    SceneView m_frame; // the scene's own framing, while m_framed
    View m_held{{}, 0.0, 0, 0}; // the camera as the user held it, and the canvas size then (PlaceCanvas scales it)
    ScreenPoint m_canvasOrigin{};
    int m_canvasWidth = 800;
    int m_canvasHeight = 600;
    bool m_canvasSized = false;
    CaptionReach m_captionReach;    // how far the caption band and the picture reach on this canvas
    bool m_captionMeasured = false; // m_captionReach is of this scene and canvas size
};

} // namespace satviz
