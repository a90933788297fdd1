// SPDX-License-Identifier: MIT
// satviz app: the canvas panel, where the painter draws the figure and the mouse moves, turns, reshapes and launches
// bodies (after the "Canvas" example of imgui_demo.cpp: an invisible button over a draw list).
#include "app.h"
#include "outline_edit.h"

#include <satviz/decompose.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace satviz
{

namespace
{

constexpr float kHandleRadius = 8.0f; // pick distance of the handles, pixels
// A thrown body leaves at the pointer's speed over this many seconds before the release: long enough to span a
// few frames, short enough that a pause before letting go throws nothing.
constexpr double kThrowWindow = 0.1;

float Distance(ScreenPoint a, ScreenPoint b)
{
    return std::hypot(a.x - b.x, a.y - b.y);
}

// The box of the body as drawn, in canvas pixels (y down).
struct PixelBox
{
    float minX, minY, maxX, maxY;
};

PixelBox BodyPixels(const View& view, const Body& body)
{
    if (body.shape.type == ShapeType::Circle)
    {
        const ScreenPoint c = ToScreen(view, TransformPoint(body.Xf(), body.shape.circle.center));
        const float r = static_cast<float>(body.shape.circle.radius * view.zoom);
        return {c.x - r, c.y - r, c.x + r, c.y + r};
    }
    PixelBox box{INFINITY, INFINITY, -INFINITY, -INFINITY};
    const Transform xf = body.Xf();
    for (const Vec2& v : body.shape.polygon.Vertices())
    {
        const ScreenPoint p = ToScreen(view, TransformPoint(xf, v));
        box = {std::min(box.minX, p.x), std::min(box.minY, p.y), std::max(box.maxX, p.x), std::max(box.maxY, p.y)};
    }
    return box;
}

// The highest point of the body as drawn straight above or below canvas column x (within its box): where a stem
// from above meets it.
ScreenPoint TopAt(const View& view, const Body& body, float x)
{
    const PixelBox box = BodyPixels(view, body);
    float top = box.maxY;
    if (body.shape.type == ShapeType::Circle)
    {
        const ScreenPoint c = ToScreen(view, TransformPoint(body.Xf(), body.shape.circle.center));
        const float r = static_cast<float>(body.shape.circle.radius * view.zoom);
        top = c.y - std::sqrt(std::max(0.0f, r * r - (x - c.x) * (x - c.x)));
    }
    else
    {
        const std::vector<Vec2> outline = EditableOutline(body);
        const Transform xf = body.Xf();
        for (size_t i = 0; i < outline.size(); ++i)
        {
            const ScreenPoint p = ToScreen(view, TransformPoint(xf, outline[i]));
            const ScreenPoint q = ToScreen(view, TransformPoint(xf, outline[(i + 1) % outline.size()]));
            if (std::min(p.x, q.x) <= x && x <= std::max(p.x, q.x))
            {
                top = std::min(top, p.x == q.x ? std::min(p.y, q.y) : p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x));
            }
        }
    }
    return {x, std::clamp(top, box.minY, box.maxY)};
}

// The turning handle stands 26 pixels above the body as drawn, over its origin (the point it turns about) as far as
// the body reaches, and inside the canvas: a handle placed by the body's reach from its origin floated far above a
// body whose origin is a corner (lesson 18's L and U) and left the canvas.
ScreenPoint RotateHandle(const View& view, const Body& body)
{
    const ScreenPoint origin = ToScreen(view, body.position);
    const PixelBox box = BodyPixels(view, body);
    const ScreenPoint top = TopAt(view, body, std::clamp(origin.x, box.minX, box.maxX));
    return {top.x, std::max(top.y - 26.0f, 10.0f)};
}

// Where the turning handle's stem meets the body: straight below the handle, on the body's outline.
ScreenPoint StemFoot(const View& view, const Body& body)
{
    const ScreenPoint turn = RotateHandle(view, body);
    return {turn.x, std::max(TopAt(view, body, turn.x).y, turn.y + 6.0f)};
}

// Where the figure's velocity arrow starts: the body's centre (a polygon's centroid, a circle's centre), which is
// not its origin for a shape built around another point (l13_sweep's triangle).
Vec2 VelocityBase(const Body& body)
{
    return TransformPoint(body.Xf(),
                          body.shape.type == ShapeType::Polygon ? body.shape.polygon.Centroid() : body.shape.circle.center);
}

// The velocity handle: the velocity arrow's tip, or, for a velocity too short to grab, just right of the body as
// drawn, level with its origin as far as the body reaches.
ScreenPoint VelocityHandle(const View& view, const Body& body)
{
    if (Length(body.velocity) * view.zoom >= 14.0)
    {
        return ToScreen(view, VelocityBase(body) + body.velocity);
    }
    const ScreenPoint origin = ToScreen(view, body.position);
    const PixelBox box = BodyPixels(view, body);
    return {box.maxX + 22.0f, std::clamp(origin.y, box.minY, box.maxY)};
}

// Up to this many vertices a selected body shows a handle on each (more would hide its outline).
constexpr size_t kMaxVertexHandles = 64;

// The pixels the handles cover (see Panels::Handles): the turning handle, the velocity handle with its letter v,
// and the square on each vertex, with the square's stroke.
std::vector<DrawnOver> HandleRegions(const View& view, const Body& body)
{
    const ScreenPoint turn = RotateHandle(view, body);
    const ScreenPoint foot = StemFoot(view, body);
    const ScreenPoint velocity = VelocityHandle(view, body);
    std::vector<DrawnOver> regions{{{turn.x - 7.0f, turn.y - 7.0f}, {turn.x + 7.0f, turn.y + 7.0f}},
                                   {{turn.x - 2.0f, turn.y}, {turn.x + 2.0f, std::max(foot.y, turn.y)}},
                                   {{velocity.x - 6.0f, velocity.y - 8.0f}, {velocity.x + 16.0f, velocity.y + 8.0f}}};
    const std::vector<Vec2> outline = EditableOutline(body);
    if (outline.size() <= kMaxVertexHandles)
    {
        const Transform xf = body.Xf();
        for (const Vec2& v : outline)
        {
            const ScreenPoint p = ToScreen(view, TransformPoint(xf, v));
            regions.push_back({{p.x - 5.0f, p.y - 5.0f}, {p.x + 5.0f, p.y + 5.0f}});
        }
    }
    return regions;
}

bool Contains(const Body& body, Vec2 world)
{
    const Vec2 local = InvTransformPoint(body.Xf(), world);
    if (body.IsConcave())
    {
        return InsideOutline(body.outline, local); // not the hull: a click in an L's notch misses the L
    }
    if (body.shape.type == ShapeType::Circle)
    {
        return Length(local - body.shape.circle.center) <= body.shape.circle.radius;
    }
    const auto& poly = body.shape.polygon;
    for (int i = 0; i < poly.Count(); ++i)
    {
        if (Cross(poly.Edge(i), local - poly.Vertices()[i]) < 0.0)
        {
            return false;
        }
    }
    return true;
}

// The body under world point `world`, -1 for none. The pair is drawn above the other bodies, B on top.
int BodyAt(const Viewer& viewer, const Scene& scene, Vec2 world)
{
    if (viewer.TestsPair())
    {
        for (int index : {viewer.Setup().study.bodyB, viewer.Setup().study.bodyA})
        {
            if (index < static_cast<int>(scene.bodies.size()) &&
                Contains(scene.bodies[static_cast<size_t>(index)], world))
            {
                return index;
            }
        }
    }
    for (int i = static_cast<int>(scene.bodies.size()) - 1; i >= 0; --i)
    {
        if (Contains(scene.bodies[static_cast<size_t>(i)], world))
        {
            return i;
        }
    }
    return -1;
}

} // namespace

bool FigureNamesVelocity(const App& app)
{
    const Viewer& viewer = app.GetViewer();
    const std::vector<Body>& bodies = app.ShownScene().bodies;
    const int selected = app.Selected();
    if (selected < 0 || selected >= static_cast<int>(bodies.size()) || !viewer.Setup().Ok() ||
        viewer.CurrentFigure().kind != FigureKind::Pair || (viewer.Choices().layers & kLayerSwept) == 0 ||
        (selected != viewer.Setup().study.bodyA && selected != viewer.Setup().study.bodyB))
    {
        return false;
    }
    // The painter draws a moving body's arrow in a sweep, and in a figure of one instant when it is 20 pixels long.
    const double pixels = Length(bodies[static_cast<size_t>(selected)].velocity) * viewer.Camera().zoom;
    return viewer.Setup().study.sweep ? pixels > 0.0 : pixels >= 20.0;
}

ScreenPoint VelocityHandleAt(const View& view, const Body& body)
{
    return VelocityHandle(view, body);
}

Figure CanvasFigure(const App& app)
{
    Figure figure = app.GetViewer().CurrentFigure();
    const std::vector<Body>& bodies = app.ShownScene().bodies;
    if (app.Selected() >= 0 && app.Selected() < static_cast<int>(bodies.size()))
    {
        figure.drawnOver = HandleRegions(app.GetViewer().Camera(), bodies[static_cast<size_t>(app.Selected())]);
    }
    return figure;
}

void Panels::CanvasWindow()
{
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float top = ImGui::GetFrameHeight();
    // An open lesson takes a column on the left; the canvas keeps the rest.
    const float lessonWidth = m_app.LessonShown() ? kLessonWidth : 0.0f;
    const ImVec2 position(viewport->Pos.x + lessonWidth, viewport->Pos.y + top);
    const ImVec2 size(std::max(64.0f, viewport->Size.x - kPanelWidth - lessonWidth),
                      std::max(64.0f, viewport->Size.y - top - StatusHeight()));
    ImGui::SetNextWindowPos(position);
    ImGui::SetNextWindowSize(size);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::Begin("##canvas", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse |
                     ImGuiWindowFlags_NoBackground); // the figure paints its own ground
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    m_app.PlaceCanvas({origin.x, origin.y}, static_cast<int>(size.x), static_cast<int>(size.y));
    const Viewer& viewer = m_app.GetViewer();
    const ImVec2 least = MinimumWindowSize(m_app.LessonShown(), top);
    if (!m_canvasAnnounced && viewport->Size.x >= least.x && viewport->Size.y >= least.y)
    {
        // One line for scripts that drive the window (the end-to-end test): where the canvas is, and its camera
        // (a scene's own framing is scaled to the canvas), so that they can find a world point on the screen. Said
        // once the window has its least size: a canvas smaller than that is one the app is about to enlarge.
        const View& camera = viewer.Camera();
        std::printf("satviz: canvas at %.0f,%.0f size %dx%d camera %.17g,%.17g zoom %.17g\n", origin.x, origin.y,
                    viewer.CanvasWidth(), viewer.CanvasHeight(), camera.center.x, camera.center.y, camera.zoom);
        std::fflush(stdout);
        m_canvasAnnounced = true;
    }
    ImGui::InvisibleButton("##surface", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    CanvasInput(origin, ImGui::IsItemHovered());
    if (viewer.Setup().Ok())
    {
        ImDrawList* list = ImGui::GetWindowDrawList();
        ImDrawListCanvas canvas(list, m_app.Fonts(), origin);
        canvas.ClearLargeRects(m_app.Options().clearRect);
        canvas.PlainFillsUnderOutlines(true);
        const Figure figure = CanvasFigure(m_app);
        PaintFigure(canvas, viewer.Studied(), viewer.Setup().study, figure);
        Handles(list, origin);
        ToolOverlay(list, origin);
        AnnounceHits(canvas, figure, origin);
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
}

void Panels::CanvasInput(ImVec2 origin, bool hovered)
{
    const ImGuiIO& io = ImGui::GetIO();
    const Viewer& viewer = m_app.GetViewer();
    const std::vector<Body>& bodies = m_app.ShownScene().bodies;
    const ScreenPoint mouse{io.MousePos.x - origin.x, io.MousePos.y - origin.y};
    const Vec2 world = ToWorld(viewer.Camera(), mouse);
    if (hovered && io.MouseWheel != 0.0f)
    {
        m_app.ZoomCamera(mouse, std::pow(1.15, static_cast<double>(io.MouseWheel)));
    }
    if (m_drag == DragKind::None && hovered && (ImGui::IsMouseClicked(1) || ImGui::IsMouseClicked(2)))
    {
        m_drag = DragKind::Pan;
    }
    const bool playing = m_app.GetSimulation().Playing();
    if (m_tool != CanvasTool::Select && m_drag == DragKind::None && hovered && ImGui::IsMouseClicked(0))
    {
        // Drawing a polygon or a cut: the state shown stays still under the pointer.
        m_app.SimPlay(false);
        m_app.HoldCamera();
        if (m_tool == CanvasTool::Draw)
        {
            if (m_drawn.size() >= 3 && Distance(mouse, ToScreen(viewer.Camera(), m_drawn.front())) <= kHandleRadius)
            {
                FinishDrawing();
            }
            else if (m_drawn.empty() || Distance(mouse, ToScreen(viewer.Camera(), m_drawn.back())) > kHandleRadius)
            {
                // A second click on the last vertex (a double click) adds nothing.
                m_drawn.push_back(world);
                DrawingStatus();
            }
            return;
        }
        m_drag = DragKind::Cut;
        m_cutFrom = world;
        m_cutTo = world;
    }
    if (m_drag == DragKind::Cut)
    {
        m_cutTo = world;
        if (!ImGui::IsMouseDown(0))
        {
            m_drag = DragKind::None;
            // A click is no cut: the segment must span a few pixels.
            if (Length(m_cutTo - m_cutFrom) * viewer.Camera().zoom >= 4.0)
            {
                m_app.CutAlong(m_cutFrom, m_cutTo);
            }
        }
        return;
    }
    if (m_drag == DragKind::None && hovered && ImGui::IsMouseClicked(0))
    {
        const int selected = m_app.Selected();
        // While the simulation plays, a body is grabbed and thrown: its handles edit the scene, which pauses.
        if (!playing && selected >= 0 && selected < static_cast<int>(bodies.size()))
        {
            const Body& body = bodies[static_cast<size_t>(selected)];
            const View& camera = viewer.Camera();
            // The outline's vertices, as written: a concave body's, not its hull's.
            const std::vector<Vec2> outline = EditableOutline(body);
            if (outline.size() <= 64)
            {
                const Transform xf = body.Xf();
                for (size_t i = 0; i < outline.size(); ++i)
                {
                    if (Distance(mouse, ToScreen(camera, TransformPoint(xf, outline[i]))) <= kHandleRadius)
                    {
                        m_drag = DragKind::Vertex;
                        m_dragVertex = static_cast<int>(i);
                        break;
                    }
                }
            }
            if (m_drag == DragKind::None && Distance(mouse, RotateHandle(camera, body)) <= kHandleRadius)
            {
                m_drag = DragKind::Rotate;
            }
            if (m_drag == DragKind::None && Distance(mouse, VelocityHandle(camera, body)) <= kHandleRadius)
            {
                m_drag = DragKind::Velocity;
            }
        }
        if (m_drag == DragKind::None && !io.KeyShift && viewer.Setup().Ok())
        {
            // A hit on the hits layer's time bar: the bodies at its instant.
            ImDrawListCanvas measure(ImGui::GetWindowDrawList(), m_app.Fonts(), origin);
            const std::vector<HitMark> marks =
                HitMarks(measure, viewer.Studied(), viewer.Setup().study, viewer.CurrentFigure());
            for (size_t h = 0; h < marks.size() && m_drag == DragKind::None; ++h)
            {
                const HitMark& mark = marks[h];
                if (Distance(mouse, mark.dot) <= kHandleRadius ||
                    (mouse.x >= mark.labelMin.x && mouse.x <= mark.labelMax.x && mouse.y >= mark.labelMin.y &&
                     mouse.y <= mark.labelMax.y))
                {
                    m_app.SimChooseHit(static_cast<int>(h));
                    m_drag = DragKind::Pan;
                }
            }
        }
        if (m_drag == DragKind::None && !io.KeyShift && !playing)
        {
            // A contact point of the simulation's step: its pair's response is shown (the panel and the layer).
            const Simulation& sim = m_app.GetSimulation();
            for (const WorldContact& contact :
                 sim.Shown() > sim.First() ? sim.Record().world.contacts : std::vector<WorldContact>{})
            {
                for (int k = 0; k < contact.pointCount && !contact.guard; ++k)
                {
                    if (m_drag == DragKind::None &&
                        Distance(mouse, ToScreen(viewer.Camera(), contact.points[k].point)) <= kHandleRadius * 0.75f)
                    {
                        m_app.SimChooseContact(contact.a, contact.b);
                        m_drag = DragKind::Pan;
                    }
                }
            }
        }
        if (m_drag == DragKind::None)
        {
            const int hit = BodyAt(viewer, m_app.ShownScene(), world);
            m_app.Select(hit);
            const bool dynamic = hit >= 0 && !bodies[static_cast<size_t>(hit)].isStatic;
            if (hit < 0)
            {
                m_drag = DragKind::Pan;
            }
            else if (playing)
            {
                m_drag = dynamic ? DragKind::Throw : DragKind::Pan;
            }
            else
            {
                m_drag = io.KeyShift ? DragKind::Rotate : DragKind::Body;
            }
        }
        if (m_drag != DragKind::Pan)
        {
            // The camera holds still while the scene changes under the pointer.
            m_app.HoldCamera();
            const Body& body = bodies[static_cast<size_t>(m_app.Selected())];
            m_grabOffset = world - body.position;
            const Vec2 arm = world - body.position;
            m_grabAngle = std::atan2(arm.y, arm.x) - body.angle;
            m_throwTrail.clear();
            m_throwVelocity = {};
            m_throwFrames = 0;
            if (m_drag != DragKind::Throw)
            {
                m_app.BeginEdit();
            }
        }
    }
    if (m_drag == DragKind::None)
    {
        return;
    }
    const bool down = ImGui::IsMouseDown(0) || ImGui::IsMouseDown(1) || ImGui::IsMouseDown(2);
    const int selected = m_app.Selected();
    if (m_drag == DragKind::Pan)
    {
        if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)
        {
            m_app.PanCamera(io.MouseDelta.x, io.MouseDelta.y);
        }
    }
    else if (selected >= 0 && selected < static_cast<int>(bodies.size()))
    {
        const Body& body = bodies[static_cast<size_t>(selected)];
        switch (m_drag)
        {
        case DragKind::Body:
            m_app.MoveBody(selected, world - m_grabOffset);
            break;
        case DragKind::Rotate:
        {
            const Vec2 arm = world - body.position;
            if (Length(arm) > 0.0)
            {
                m_app.TurnBody(selected, std::atan2(arm.y, arm.x) - m_grabAngle);
            }
            break;
        }
        case DragKind::Vertex:
            m_app.MoveVertex(selected, m_dragVertex, world);
            break;
        case DragKind::Velocity:
            m_app.SetVelocity(selected, world - VelocityBase(body));
            break;
        case DragKind::Throw:
        {
            // The body follows the pointer at the pointer's recent speed, so that what it pushes is pushed at
            // that speed, and leaves at it on release.
            const double now = ImGui::GetTime();
            // A frame that comes slower than the window with the pointer where the last one saw it tells nothing
            // of a pause: on a loaded machine the pointer's last moves and the release fall in one slow frame
            // after the moving ones. The speed measured before it stands.
            const bool slowAndStill = !m_throwTrail.empty() && now - m_throwTrail.back().first >= kThrowWindow &&
                                      m_throwTrail.back().second.x == world.x && m_throwTrail.back().second.y == world.y;
            m_throwTrail.emplace_back(now, world);
            ++m_throwFrames;
            while (m_throwTrail.size() > 2 && now - m_throwTrail[1].first >= kThrowWindow)
            {
                m_throwTrail.pop_front();
            }
            // Over the window, or between the last two frames when the frames come slower than that (a loaded
            // machine): a pause before letting go is frames at one place over the window, which throws nothing.
            const double span = now - m_throwTrail.front().first;
            if (!slowAndStill)
            {
                m_throwVelocity = span > 1e-3 ? (1.0 / span) * (world - m_throwTrail.front().second) : Vec2{};
            }
            m_app.SimHand(selected, world - m_grabOffset, m_throwVelocity);
            if (!down)
            {
                const Body& thrown = m_app.ShownScene().bodies[static_cast<size_t>(selected)];
                std::printf("satviz: thrown %s at step %d velocity %.17g %.17g over %d frames\n", thrown.name.c_str(),
                            m_app.GetSimulation().Shown(), thrown.velocity.x, thrown.velocity.y, m_throwFrames);
                std::fflush(stdout);
            }
            break;
        }
        default:
            break;
        }
    }
    if (!down)
    {
        if (m_drag != DragKind::Pan && m_drag != DragKind::Throw)
        {
            m_app.EndEdit();
        }
        m_drag = DragKind::None;
        m_dragVertex = -1;
    }
}

// Where the hits layer's time bar puts the hits of the step shown, once per step and hit chosen, for scripts that
// drive the window (the end-to-end test); and the chosen hit's bodies at its instant.
void Panels::AnnounceHits(Canvas& canvas, const Figure& figure, ImVec2 origin)
{
    const Simulation& sim = m_app.GetSimulation();
    const std::string key = std::to_string(sim.Shown()) + " " + std::to_string(figure.hit);
    if (figure.sim == nullptr || key == m_announcedHits)
    {
        return;
    }
    m_announcedHits = key;
    const Viewer& viewer = m_app.GetViewer();
    const std::vector<HitMark> marks = HitMarks(canvas, viewer.Studied(), viewer.Setup().study, figure);
    for (size_t h = 0; h < marks.size(); ++h)
    {
        std::printf("satviz: hit %zu of step %d at %.0f,%.0f\n", h + 1, sim.Shown(), marks[h].dot.x + origin.x,
                    marks[h].dot.y + origin.y);
    }
    const std::vector<StepHit>& hits = figure.sim->lastStep.hits;
    if (figure.hit >= 0 && static_cast<size_t>(figure.hit) < hits.size())
    {
        const StepHit& hit = hits[static_cast<size_t>(figure.hit)];
        std::printf("satviz: hit %d of step %d shown: time %.17g bodies %d %d positions %.17g %.17g %.17g %.17g angles "
                    "%.17g %.17g\n",
                    figure.hit + 1, sim.Shown(), hit.time, hit.a, hit.b, hit.position[0].x, hit.position[0].y,
                    hit.position[1].x, hit.position[1].y, hit.angle[0], hit.angle[1]);
    }
    std::fflush(stdout);
}

// The selected body's handles: its vertices, the turning handle on a stem above it, and its velocity arrow's tip.
void Panels::Handles(ImDrawList* list, ImVec2 origin)
{
    const int selected = m_app.Selected();
    const std::vector<Body>& bodies = m_app.ShownScene().bodies;
    if (selected < 0 || selected >= static_cast<int>(bodies.size()))
    {
        return;
    }
    const Body& body = bodies[static_cast<size_t>(selected)];
    const View& camera = m_app.GetViewer().Camera();
    auto at = [&](ScreenPoint p) { return ImVec2(p.x + origin.x, p.y + origin.y); };
    const ImU32 ink = IM_COL32(43, 43, 43, 255);
    const ImU32 white = IM_COL32(255, 255, 255, 255);
    const std::vector<Vec2> outline = EditableOutline(body);
    if (outline.size() <= kMaxVertexHandles)
    {
        const Transform xf = body.Xf();
        for (const Vec2& v : outline)
        {
            const ImVec2 p = at(ToScreen(camera, TransformPoint(xf, v)));
            list->AddRectFilled(ImVec2(p.x - 4.0f, p.y - 4.0f), ImVec2(p.x + 4.0f, p.y + 4.0f), white);
            list->AddRect(ImVec2(p.x - 4.0f, p.y - 4.0f), ImVec2(p.x + 4.0f, p.y + 4.0f), ink, 0.0f, 0, 1.5f);
        }
    }
    const ImVec2 turn = at(RotateHandle(camera, body));
    list->AddLine(at(StemFoot(camera, body)), turn, IM_COL32(43, 43, 43, 120), 1.0f);
    list->AddCircleFilled(turn, 6.0f, white);
    list->AddCircle(turn, 6.0f, ink, 0, 1.5f);
    // The velocity handle is a white diamond, as the other handles are white and inked: a vermillion dot, the
    // figures' mark of a contact point, read as one more contact beside the pair's own.
    const ImVec2 velocity = at(VelocityHandle(camera, body));
    const ImVec2 top(velocity.x, velocity.y - 6.0f);
    const ImVec2 right(velocity.x + 6.0f, velocity.y);
    const ImVec2 bottom(velocity.x, velocity.y + 6.0f);
    const ImVec2 left(velocity.x - 6.0f, velocity.y);
    list->AddQuadFilled(top, right, bottom, left, white);
    list->AddQuad(top, right, bottom, left, ink, 1.5f);
    // Where the figure names the arrow whose tip this is, its "v" (kept off the handle) is the only one.
    if (!FigureNamesVelocity(m_app))
    {
        list->AddText(ImVec2(velocity.x + 7.0f, velocity.y - 8.0f), ink, "v");
    }
}

void Panels::SetTool(CanvasTool tool)
{
    m_tool = tool;
    m_drawn.clear();
    if (m_drag == DragKind::Cut)
    {
        m_drag = DragKind::None;
    }
    switch (tool)
    {
    case CanvasTool::Draw:
        m_app.SetStatus("Draw a polygon: click its vertices; click the first one or press Enter to close it, Esc to "
                       "stop",
                       false);
        break;
    case CanvasTool::Cut:
        m_app.SetStatus("Cut: drag a line across a polygon, from outside to outside; Esc to stop", false);
        break;
    case CanvasTool::Select:
        m_app.SetStatus("", false);
        break;
    }
}

// The status line while drawing: the vertex count and what the outline so far, closed, decomposes into.
void Panels::DrawingStatus()
{
    std::string said = "Drawing: " + std::to_string(m_drawn.size()) + (m_drawn.size() == 1 ? " vertex" : " vertices");
    if (m_drawn.size() >= 3)
    {
        const Decomposition pieces = Decompose(m_drawn, DecomposeMethod::Fast);
        if (pieces.Ok())
        {
            said += pieces.pieces.size() == 1 ? ", convex"
                                              : ", " + std::to_string(pieces.pieces.size()) + " convex pieces";
            said += "; click the first vertex or press Enter to close it";
        }
        else
        {
            said += "; closed now, the " + DescribeDecomposeError(pieces, m_drawn);
        }
    }
    m_app.SetStatus(said, false);
}

void Panels::FinishDrawing()
{
    if (m_drawn.size() < 3)
    {
        m_app.SetStatus("A polygon needs at least three vertices: click on", true);
        return;
    }
    if (m_app.AddDrawnPolygon(m_drawn))
    {
        m_drawn.clear();
        m_tool = CanvasTool::Select;
    }
}

// The polygon being drawn, closed and cut into its convex pieces as it grows (internal edges dashed), and the cut
// being drawn.
void Panels::ToolOverlay(ImDrawList* list, ImVec2 origin)
{
    const View& camera = m_app.GetViewer().Camera();
    auto at = [&](Vec2 world) {
        const ScreenPoint p = ToScreen(camera, world);
        return ImVec2(p.x + origin.x, p.y + origin.y);
    };
    const ImU32 ink = IM_COL32(43, 43, 43, 255);
    const ImU32 cutInk = IM_COL32(213, 94, 0, 255);
    const ImGuiIO& io = ImGui::GetIO();
    if (m_tool == CanvasTool::Draw && !m_drawn.empty())
    {
        if (m_drawn.size() >= 3)
        {
            const Decomposition pieces = Decompose(m_drawn, DecomposeMethod::Fast);
            // Distinct fills for the pieces (colour-blind safe, light), their seams dashed.
            static const ImU32 fills[] = {IM_COL32(86, 180, 233, 70), IM_COL32(230, 159, 0, 70),
                                          IM_COL32(0, 158, 115, 70), IM_COL32(204, 121, 167, 70),
                                          IM_COL32(240, 228, 66, 90)};
            for (size_t k = 0; pieces.Ok() && k < pieces.pieces.size(); ++k)
            {
                const Polygon& piece = pieces.pieces[k].polygon;
                std::vector<ImVec2> points;
                for (const Vec2& v : piece.Vertices())
                {
                    points.push_back(at(v));
                }
                list->AddConvexPolyFilled(points.data(), static_cast<int>(points.size()), fills[k % 5]);
                for (int e = 0; e < piece.Count(); ++e)
                {
                    if (!pieces.pieces[k].internal[static_cast<size_t>(e)])
                    {
                        continue;
                    }
                    const ImVec2 p = points[static_cast<size_t>(e)];
                    const ImVec2 q = points[static_cast<size_t>((e + 1) % piece.Count())];
                    const float length = std::hypot(q.x - p.x, q.y - p.y);
                    for (float t = 0.0f; t < length; t += 10.0f)
                    {
                        const float u = t / length;
                        const float w = std::min(t + 5.0f, length) / length;
                        list->AddLine(ImVec2(p.x + (q.x - p.x) * u, p.y + (q.y - p.y) * u),
                                      ImVec2(p.x + (q.x - p.x) * w, p.y + (q.y - p.y) * w), ink, 1.0f);
                    }
                }
            }
        }
        for (size_t i = 0; i + 1 < m_drawn.size(); ++i)
        {
            list->AddLine(at(m_drawn[i]), at(m_drawn[i + 1]), ink, 2.0f);
        }
        // The edge that follows the pointer, and the one that would close the polygon.
        list->AddLine(at(m_drawn.back()), io.MousePos, IM_COL32(43, 43, 43, 160), 1.0f);
        if (m_drawn.size() >= 2)
        {
            list->AddLine(io.MousePos, at(m_drawn.front()), IM_COL32(43, 43, 43, 90), 1.0f);
        }
        for (size_t i = 0; i < m_drawn.size(); ++i)
        {
            const ImVec2 p = at(m_drawn[i]);
            list->AddRectFilled(ImVec2(p.x - 4.0f, p.y - 4.0f), ImVec2(p.x + 4.0f, p.y + 4.0f),
                                IM_COL32(255, 255, 255, 255));
            list->AddRect(ImVec2(p.x - 4.0f, p.y - 4.0f), ImVec2(p.x + 4.0f, p.y + 4.0f), ink, 0.0f, 0, 1.5f);
        }
        // The first vertex closes the polygon: ringed once there are three.
        if (m_drawn.size() >= 3)
        {
            list->AddCircle(at(m_drawn.front()), kHandleRadius + 2.0f, ink, 0, 1.5f);
        }
    }
    if (m_drag == DragKind::Cut)
    {
        list->AddLine(at(m_cutFrom), at(m_cutTo), cutInk, 2.5f);
        list->AddCircleFilled(at(m_cutFrom), 3.5f, cutInk);
        list->AddCircleFilled(at(m_cutTo), 3.5f, cutInk);
    }
}

} // namespace satviz
