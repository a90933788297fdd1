// SPDX-License-Identifier: MIT
#include "viewer.h"
#include "outline_edit.h"

#include <algorithm>
#include <thread>
#include <utility>

namespace satviz
{

namespace
{

// True when the scene's own framing leaves its scene almost no room in a figure of its own size with these layers
// (the world's layers take the bottom of the figure for their panels): scaled to the canvas, that sliver would
// show nothing, so the figure fits the pair instead.
bool FrameSqueezed(const SceneView& frame, const PairStudy& study, LayerMask layers, bool titled)
{
    const FigureLayout from = LayoutFigure(study, layers, frame.width, frame.height, titled);
    return from.sceneBottom - from.sceneTop < 0.25 * frame.height;
}

} // namespace

Viewer::Viewer(int backgroundVertices) : backgroundVertices_(backgroundVertices) {}

void Viewer::Reset(const Scene& scene)
{
    choices_ = ChoicesOfView(scene.view);
    playing_ = false;
    cameraFit_ = scene.view.fit;
    // A scene that frames itself (the lessons' scenes) was framed for a figure of its own size, 800 x 600 unless
    // it says otherwise; the canvas left beside the panels and a lesson is another size, so each figure scales
    // that framing to fit it (Adopt).
    framed_ = !cameraFit_;
    frame_ = scene.view;
    if (!cameraFit_)
    {
        camera_.center = scene.view.center;
        camera_.zoom = scene.view.zoom;
    }
    step_ = scene.view.step;
    time_ = scene.view.time;
    // The figure of the scene before is no longer shown, nor a test of it still running taken in.
    setup_ = FigureSetup{};
    setup_.error = "testing the pair";
    job_.reset();
    retest_ = false;
}

int Viewer::PairVertices(const Scene& scene) const
{
    auto count = [&](const std::string& name, size_t fallback) {
        for (const Body& body : scene.bodies)
        {
            if (body.name == name)
            {
                return body.shape.type == ShapeType::Polygon ? body.shape.polygon.Count() : 1;
            }
        }
        if (!name.empty() || fallback >= scene.bodies.size())
        {
            return 0;
        }
        const Body& body = scene.bodies[fallback];
        return body.shape.type == ShapeType::Polygon ? body.shape.polygon.Count() : 1;
    };
    return count(choices_.bodyA, 0) + count(choices_.bodyB, 1);
}

bool Viewer::Refresh(const Scene& scene)
{
    // The pair must still exist after edits (a deleted body, a renamed one).
    auto exists = [&](const std::string& name) {
        return std::any_of(scene.bodies.begin(), scene.bodies.end(), [&](const Body& b) { return b.name == name; });
    };
    if (!exists(choices_.bodyA) || !exists(choices_.bodyB) || choices_.bodyA == choices_.bodyB)
    {
        choices_.bodyA.clear();
        choices_.bodyB.clear();
    }
    FigureOptions options;
    options.width = canvasWidth_;
    options.height = canvasHeight_;
    options.setLayers = true;
    options.layers = choices_.layers;
    options.setStep = true;
    options.step = -1;
    Scene fitted = scene;
    WriteChoices(choices_, fitted.view);
    fitted.view.time = time_;
    fitted.view.fit = true;
    if (PairVertices(scene) <= backgroundVertices_)
    {
        FigureSetup fresh = SetUpFigure(fitted, options);
        Adopt(std::move(fresh), std::move(fitted));
        return true;
    }
    // The traced queries and the fit grow with the square of the vertex count (about 30 s for 100 000
    // vertices): they run on a worker thread while the interface goes on with the figure it has.
    if (!canvasSized_)
    {
        return false; // the canvas's first frame gives its size, then the test starts
    }
    if (job_ != nullptr)
    {
        retest_ = true; // one worker at a time; the latest scene runs when it ends
        return false;
    }
    job_ = std::make_shared<StudyJob>();
    job_->scene = std::move(fitted);
    job_->options = options;
    std::thread([job = job_] {
        job->result = SetUpFigure(job->scene, job->options);
        job->done.store(true, std::memory_order_release);
    }).detach();
    return false;
}

bool Viewer::TakeFinishedTest()
{
    if (job_ == nullptr || !job_->done.load(std::memory_order_acquire))
    {
        return false;
    }
    const std::shared_ptr<StudyJob> finished = std::move(job_);
    job_.reset();
    Adopt(std::move(finished->result), std::move(finished->scene));
    return true;
}

bool Viewer::TakeRetest()
{
    const bool retest = retest_;
    retest_ = false;
    return retest;
}

void Viewer::Adopt(FigureSetup fresh, Scene studied)
{
    // A student reading the verdict stays on it: the new test's verdict may be another step (a drag to overlap
    // adds axes), and its number would now show an axis.
    const bool onVerdict = setup_.Ok() && step_ == VerdictStep();
    setup_ = std::move(fresh);
    studied_ = std::move(studied);
    if (!setup_.Ok())
    {
        return;
    }
    ShowStep(onVerdict ? VerdictStep() : step_);
    if (cameraFit_ || (framed_ && FrameSqueezed(frame_, setup_.study, choices_.layers, !studied_.view.caption.empty())))
    {
        camera_ = setup_.figure.view;
    }
    else if (framed_)
    {
        camera_ =
            Reframe(frame_, setup_.study, choices_.layers, !studied_.view.caption.empty(), canvasWidth_, canvasHeight_);
    }
    if ((cameraFit_ || framed_) && setup_.figure.kind == FigureKind::Slice && setup_.figure.body >= 0 &&
        setup_.figure.body < static_cast<int>(studied_.bodies.size()))
    {
        // A slice draws its body through the camera in its before panel, the left half of the canvas: the body and
        // the cut fill that panel below the caption, until the camera is panned, zoomed or held by a drag.
        Figure sized = setup_.figure;
        sized.view.width = canvasWidth_;
        sized.view.height = canvasHeight_;
        camera_ = FrameSlice(studied_, setup_.figure.body, sized);
    }
    camera_.width = canvasWidth_;
    camera_.height = canvasHeight_;
    setup_.figure.view = camera_;
}

Figure Viewer::CurrentFigure() const
{
    Figure figure = setup_.figure;
    figure.view = camera_;
    figure.step = step_;
    figure.sim = sim_;
    figure.hit = sim_ != nullptr ? hit_ : -1;
    // The canvas maps the pointer by the camera: the pieces, disc-cast and slice figures are drawn through it too.
    figure.framesItself = false;
    return figure;
}

int Viewer::VerdictStep() const
{
    return setup_.figure.kind == FigureKind::Pieces ? FigureStepCount(studied_, setup_) - 1
                                                    : setup_.study.VerdictStep();
}

int Viewer::NextStep(int step, int direction) const
{
    if (setup_.figure.kind == FigureKind::Pieces)
    {
        return std::clamp(step + direction, 0, VerdictStep());
    }
    return setup_.study.NextStep(step, direction);
}

void Viewer::ShowStep(int step)
{
    step_ = step;
    if (!setup_.Ok())
    {
        return;
    }
    if (step_ < 0 || step_ > VerdictStep())
    {
        step_ = VerdictStep();
    }
    setup_.figure.step = step_;
    setup_.figure.time = time_;
    setup_.figure.caption = studied_.view.caption;
}

void Viewer::TogglePlay()
{
    playing_ = !playing_;
    playClock_ = 0.0;
    if (playing_ && step_ >= VerdictStep())
    {
        ShowStep(NextStep(-1, 1));
    }
}

void Viewer::Advance(double seconds)
{
    if (!playing_)
    {
        return;
    }
    playClock_ += seconds;
    if (playClock_ >= kPlayInterval)
    {
        playClock_ = 0.0;
        if (step_ < VerdictStep())
        {
            ShowStep(NextStep(step_, 1));
        }
        playing_ = step_ < VerdictStep();
    }
}

void Viewer::SetTime(double time)
{
    time_ = time;
    ShowStep(step_);
}

void Viewer::SetCamera(Vec2 center, double zoom)
{
    camera_.center = center;
    camera_.zoom = zoom;
    cameraFit_ = false;
    framed_ = false;
}

void Viewer::PanCamera(float dx, float dy)
{
    camera_ = Pan(camera_, dx, dy);
    cameraFit_ = false;
    framed_ = false;
}

void Viewer::ZoomCamera(ScreenPoint fixed, double factor)
{
    camera_ = ZoomAbout(camera_, fixed, factor);
    cameraFit_ = false;
    framed_ = false;
}

bool Viewer::PlaceCanvas(ScreenPoint origin, int width, int height)
{
    canvasOrigin_ = origin;
    if (canvasSized_ && width == canvasWidth_ && height == canvasHeight_)
    {
        return false;
    }
    canvasWidth_ = width;
    canvasHeight_ = height;
    canvasSized_ = true;
    return true;
}

void Viewer::WriteView(Scene& saved) const
{
    saved.hasView = true;
    SceneView& view = saved.view;
    view.fit = cameraFit_;
    if (!cameraFit_)
    {
        // Within what a scene file accepts, so that the saved file opens again (a fit to a huge or tiny pair can
        // leave the camera beyond them).
        view.center = {std::clamp(camera_.center.x, -kMaxSceneValue, kMaxSceneValue),
                       std::clamp(camera_.center.y, -kMaxSceneValue, kMaxSceneValue)};
        view.zoom = std::clamp(camera_.zoom, kMinViewZoom, kMaxViewZoom);
    }
    view.width = canvasWidth_;
    view.height = canvasHeight_;
    WriteChoices(choices_, view);
    if (TestsPair())
    {
        // The pair tested, named as in the scene it was tested on.
        view.bodyA = studied_.bodies[static_cast<size_t>(setup_.study.bodyA)].name;
        view.bodyB = studied_.bodies[static_cast<size_t>(setup_.study.bodyB)].name;
        auto saves = [&](const std::string& name) {
            return std::any_of(saved.bodies.begin(), saved.bodies.end(), [&](const Body& b) { return b.name == name; });
        };
        if (!saves(view.bodyA) || !saves(view.bodyB))
        {
            view.bodyA.clear(); // deleted while its test ran in the background
            view.bodyB.clear();
        }
    }
    view.step = step_;
    view.time = time_;
}

} // namespace satviz
