// SPDX-License-Identifier: MIT
#include "viewer.h"
#include "outline_edit.h"

#include <algorithm>
#include <thread>
#include <utility>

namespace satviz
{

Viewer::Viewer(int backgroundVertices) : m_backgroundVertices(backgroundVertices) {}

void Viewer::Reset(const Scene& scene)
{
    m_choices = ChoicesOfView(scene.view);
    m_playing = false;
    m_cameraFit = scene.view.fit;
    // A scene that frames itself (the lessons' scenes) was framed for a figure of its own size, 800 x 600 unless
    // it says otherwise; the canvas left beside the panels and a lesson is another size, so each figure scales
    // that framing to fit it (Adopt).
    m_framed = !m_cameraFit;
    m_frame = scene.view;
    if (!m_cameraFit)
    {
        m_camera.center = scene.view.center;
        m_camera.zoom = scene.view.zoom;
    }
    m_step = scene.view.step;
    m_stepAsked = true;
    m_stepNotice.clear();
    m_time = scene.view.time;
    // The figure of the scene before is no longer shown, nor a test of it still running taken in.
    m_setup = FigureSetup{};
    m_setup.error = "testing the pair";
    m_job.reset();
    m_retest = false;
    m_captionMeasured = false;
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
    return count(m_choices.bodyA, 0) + count(m_choices.bodyB, 1);
}

bool Viewer::Refresh(const Scene& scene)
{
    // The pair must still exist after edits (a deleted body, a renamed one).
    auto exists = [&](const std::string& name) {
        return std::any_of(scene.bodies.begin(), scene.bodies.end(), [&](const Body& b) { return b.name == name; });
    };
    if (!exists(m_choices.bodyA) || !exists(m_choices.bodyB) || m_choices.bodyA == m_choices.bodyB)
    {
        m_choices.bodyA.clear();
        m_choices.bodyB.clear();
    }
    FigureOptions options;
    options.width = m_canvasWidth;
    options.height = m_canvasHeight;
    options.setLayers = true;
    options.layers = m_choices.layers;
    options.setStep = true;
    options.step = -1;
    Scene fitted = scene;
    WriteChoices(m_choices, fitted.view);
    fitted.view.time = m_time;
    fitted.view.fit = true;
    if (PairVertices(scene) <= m_backgroundVertices)
    {
        FigureSetup fresh = SetUpFigure(fitted, options);
        Adopt(std::move(fresh), std::move(fitted));
        return true;
    }
    // The traced queries and the fit grow with the square of the vertex count: for a large pair they run on a
    // worker thread while the interface goes on with the figure it has.
    if (!m_canvasSized)
    {
        return false; // the canvas's first frame gives its size, then the test starts
    }
    if (m_job != nullptr)
    {
        m_retest = true; // one worker at a time; the latest scene runs when it ends
        return false;
    }
    m_job = std::make_shared<StudyJob>();
    m_job->scene = std::move(fitted);
    m_job->options = options;
    std::thread([job = m_job] {
        job->result = SetUpFigure(job->scene, job->options);
        job->done.store(true, std::memory_order_release);
    }).detach();
    return false;
}

bool Viewer::TakeFinishedTest()
{
    if (m_job == nullptr || !m_job->done.load(std::memory_order_acquire))
    {
        return false;
    }
    const std::shared_ptr<StudyJob> finished = std::move(m_job);
    m_job.reset();
    Adopt(std::move(finished->result), std::move(finished->scene));
    return true;
}

bool Viewer::TakeRetest()
{
    const bool retest = m_retest;
    m_retest = false;
    return retest;
}

void Viewer::Adopt(FigureSetup fresh, Scene studied)
{
    // A student reading the verdict stays on it: the new test's verdict may be another step (a drag to overlap
    // adds axes), and its number would now show an axis.
    const bool onVerdict = m_setup.Ok() && m_step == VerdictStep();
    m_setup = std::move(fresh);
    m_studied = std::move(studied);
    if (!m_setup.Ok())
    {
        return;
    }
    if (std::exchange(m_stepAsked, false))
    {
        // A step the file asks for and the figure does not have: satviz-render refuses the file; the app shows the
        // verdict, says so, and a save writes the step shown.
        const int steps = FigureStepCount(m_studied, m_setup);
        if (m_step >= steps)
        {
            m_stepNotice = MissingStep("view.step", m_step, steps) + ", so it opens at the verdict";
            m_step = VerdictStep();
        }
    }
    ShowStep(onVerdict ? VerdictStep() : m_step);
    // A scene that frames itself is framed for the canvas as satviz-render frames it for another size (FrameScene),
    // and fitted when that framing would show nothing.
    if (m_cameraFit ||
        (m_framed && !FrameScene(m_frame, m_setup.study, m_choices.layers, m_canvasWidth, m_canvasHeight, m_camera)))
    {
        m_camera = m_setup.figure.view;
    }
    if ((m_cameraFit || m_framed) && m_setup.figure.kind != FigureKind::Slice &&
        m_setup.figure.kind != FigureKind::Decomposition)
    {
        // The framing leaves the caption the band the figure's layout reserves; on a narrow canvas a long caption
        // wraps to more lines and its band grows over the picture's top (disc_cast_cup's seven lines over its start
        // disc). Where the band of its longest step would cover the picture, the picture goes under it; measured
        // once per scene and canvas size, so that stepping does not move it.
        Figure measured = m_setup.figure;
        measured.view = m_camera;
        measured.view.width = m_canvasWidth;
        measured.view.height = m_canvasHeight;
        measured.sim = m_sim;
        measured.hit = m_sim != nullptr ? m_hit : -1;
        measured.framesItself = false;
        if (!m_captionMeasured)
        {
            m_captionReach = MeasureCaption(m_studied, m_setup.study, measured, FigureStepCount(m_studied, m_setup));
            m_captionMeasured = true;
        }
        m_camera = BelowCaption(measured.view, m_setup.study, m_choices.layers, !m_studied.view.caption.empty(),
                                m_captionReach);
    }
    if ((m_cameraFit || m_framed) &&
        (m_setup.figure.kind == FigureKind::Slice || m_setup.figure.kind == FigureKind::Decomposition) &&
        m_setup.figure.body >= 0 && m_setup.figure.body < static_cast<int>(m_studied.bodies.size()))
    {
        // A slice or a decomposition draws its body through the camera in its left panel, the left half of the
        // canvas: the body (and a slice's cut) fill that panel below the caption, until the camera is panned,
        // zoomed or held by a drag.
        Figure sized = m_setup.figure;
        sized.view.width = m_canvasWidth;
        sized.view.height = m_canvasHeight;
        m_camera = m_setup.figure.kind == FigureKind::Slice ? FrameSlice(m_studied, m_setup.figure.body, sized)
                                                            : FrameDecomposition(m_studied, m_setup.figure.body, sized);
    }
    m_camera.width = m_canvasWidth;
    m_camera.height = m_canvasHeight;
    m_setup.figure.view = m_camera;
}

Figure Viewer::CurrentFigure() const
{
    Figure figure = m_setup.figure;
    figure.view = m_camera;
    figure.step = m_step;
    figure.sim = m_sim;
    figure.hit = m_sim != nullptr ? m_hit : -1;
    // The canvas maps the pointer by the camera: the pieces, disc-cast and slice figures are drawn through it too.
    figure.framesItself = false;
    return figure;
}

int Viewer::VerdictStep() const
{
    return m_setup.figure.kind == FigureKind::Pieces ? FigureStepCount(m_studied, m_setup) - 1
                                                    : m_setup.study.VerdictStep();
}

int Viewer::NextStep(int step, int direction) const
{
    if (m_setup.figure.kind == FigureKind::Pieces)
    {
        return std::clamp(step + direction, 0, VerdictStep());
    }
    return m_setup.study.NextStep(step, direction);
}

void Viewer::ShowStep(int step)
{
    m_step = step;
    m_stepAsked = false; // a step chosen (a lesson's) is no longer the file's
    if (!m_setup.Ok())
    {
        return;
    }
    if (m_step < 0 || m_step > VerdictStep())
    {
        m_step = VerdictStep();
    }
    m_setup.figure.step = m_step;
    m_setup.figure.time = m_time;
    m_setup.figure.caption = m_studied.view.caption;
}

void Viewer::TogglePlay()
{
    m_playing = !m_playing;
    m_playClock = 0.0;
    if (m_playing && m_step >= VerdictStep())
    {
        ShowStep(NextStep(-1, 1));
    }
}

void Viewer::Advance(double seconds)
{
    if (!m_playing)
    {
        return;
    }
    m_playClock += seconds;
    if (m_playClock >= kPlayInterval)
    {
        m_playClock = 0.0;
        if (m_step < VerdictStep())
        {
            ShowStep(NextStep(m_step, 1));
        }
        m_playing = m_step < VerdictStep();
    }
}

void Viewer::SetTime(double time)
{
    m_time = time;
    ShowStep(m_step);
}

void Viewer::HoldCamera()
{
    m_cameraFit = false;
    Hold();
}

void Viewer::Hold()
{
    m_held = m_camera;
    m_held.width = m_canvasWidth;
    m_held.height = m_canvasHeight;
}

void Viewer::SetCamera(Vec2 center, double zoom)
{
    m_camera.center = center;
    m_camera.zoom = zoom;
    m_cameraFit = false;
    m_framed = false;
    Hold();
}

void Viewer::PanCamera(float dx, float dy)
{
    m_camera = Pan(m_camera, dx, dy);
    m_cameraFit = false;
    m_framed = false;
    Hold();
}

void Viewer::ZoomCamera(ScreenPoint fixed, double factor)
{
    m_camera = ZoomAbout(m_camera, fixed, factor);
    m_cameraFit = false;
    m_framed = false;
    Hold();
}

bool Viewer::PlaceCanvas(ScreenPoint origin, int width, int height)
{
    m_canvasOrigin = origin;
    if (m_canvasSized && width == m_canvasWidth && height == m_canvasHeight)
    {
        return false;
    }
    if (m_canvasSized && !m_cameraFit && !m_framed && m_held.width > 0 && m_held.height > 0)
    {
        // A camera held where the user left it (a drag, a pan, a zoom) shows the world it showed then, scaled to the
        // new canvas about its centre: a lesson column that appears beside it, or a smaller window, does not cut off
        // what was in sight, and the canvas back at its size gives the same view again.
        m_camera.zoom = m_held.zoom * std::min(static_cast<double>(width) / m_held.width,
                                               static_cast<double>(height) / m_held.height);
    }
    m_canvasWidth = width;
    m_canvasHeight = height;
    m_canvasSized = true;
    m_captionMeasured = false;
    return true;
}

void Viewer::WriteView(Scene& saved) const
{
    saved.hasView = true;
    SceneView& view = saved.view;
    view.fit = m_cameraFit;
    if (!m_cameraFit)
    {
        // Within what a scene file accepts, so that the saved file opens again (a fit to a huge or tiny pair can
        // leave the camera beyond them).
        const Vec2 center = SceneViewCenter(m_camera, m_choices.layers);
        view.center = {std::clamp(center.x, -kMaxSceneValue, kMaxSceneValue),
                       std::clamp(center.y, -kMaxSceneValue, kMaxSceneValue)};
        view.zoom = std::clamp(m_camera.zoom, kMinViewZoom, kMaxViewZoom);
    }
    view.width = m_canvasWidth;
    view.height = m_canvasHeight;
    WriteChoices(m_choices, view);
    if (TestsPair())
    {
        // The pair tested, named as in the scene it was tested on.
        view.bodyA = m_studied.bodies[static_cast<size_t>(m_setup.study.bodyA)].name;
        view.bodyB = m_studied.bodies[static_cast<size_t>(m_setup.study.bodyB)].name;
        auto saves = [&](const std::string& name) {
            return std::any_of(saved.bodies.begin(), saved.bodies.end(), [&](const Body& b) { return b.name == name; });
        };
        if (!saves(view.bodyA) || !saves(view.bodyB))
        {
            view.bodyA.clear(); // deleted while its test ran in the background
            view.bodyB.clear();
        }
    }
    view.step = m_step;
    view.time = m_time;
}

} // namespace satviz
