// SPDX-License-Identifier: MIT
// The app's logic without a window: ImGui frames with input set through its io fields, as the window system
// would. Drags move bodies, keys step through the trace, undo restores, refused edits say why.
#include "app.h"
#include "key_queue.h"
#include "study_numbers.h"
#include "wrapped_text.h"

#include <satviz/collide.h>
#include <satviz/decompose.h>
#include <satviz/render/describe.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/render/response_steps.h>
#include <satviz/render/world_words.h>
#include <satviz/render/wrap.h>
#include <satviz/query_json.h>
#include <satviz/scene_world.h>

#include <catch2/catch.hpp>
#include <imgui_internal.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <map>
#include <regex>
#include <sstream>
#include <thread>
#include <unistd.h>

using namespace satviz;
namespace fs = std::filesystem;

namespace
{

enum KeySlot
{
    kLeft = 1,
    kRight,
    kSpace,
    kDelete,
    kZ,
    kY,
    kEscape,
    kEnter,
};

/// The directory of this process's scene copies, removed when the tests end.
struct ScratchDirectory
{
    fs::path dir = fs::temp_directory_path() / ("satviz-app-test-" + std::to_string(::getpid()));

    ScratchDirectory() { fs::create_directories(dir); }
    ~ScratchDirectory()
    {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
};

/// A copy of a bundled scene that a test may edit and save.
fs::path ScratchCopy(const std::string& name)
{
    static const ScratchDirectory scratch;
    const fs::path copy = scratch.dir / name;
    fs::copy_file(fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes" / name, copy,
                  fs::copy_options::overwrite_existing);
    return copy;
}

/// An ImGui context without a renderer or a window, and the app in it.
struct Harness
{
    FigureFonts fonts;
    std::unique_ptr<App> app;
    ImGuiContext* context = nullptr;

    /// The app with `scene` open; `options` as given, with the bundled scenes' folder.
    explicit Harness(const std::string& scene, AppOptions options = {})
    {
        context = ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(1280.0f, 800.0f);
        io.DeltaTime = 1.0f / 60.0f;
        std::string error;
        REQUIRE(AddFigureFonts(*io.Fonts, fonts, error));
        io.FontDefault = fonts.body;
        unsigned char* pixels = nullptr;
        int width = 0;
        int height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
        io.KeyMap[ImGuiKey_LeftArrow] = kLeft;
        io.KeyMap[ImGuiKey_RightArrow] = kRight;
        io.KeyMap[ImGuiKey_Space] = kSpace;
        io.KeyMap[ImGuiKey_Delete] = kDelete;
        io.KeyMap[ImGuiKey_Z] = kZ;
        io.KeyMap[ImGuiKey_Y] = kY;
        io.KeyMap[ImGuiKey_Escape] = kEscape;
        io.KeyMap[ImGuiKey_Enter] = kEnter;
        options.scenesDir = std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes";
        app = std::make_unique<App>(fonts, options);
        REQUIRE(app->Open(scene));
        Frames(3);
    }
    ~Harness()
    {
        app.reset();
        ImGui::DestroyContext(context);
    }
    // The app's viewer: pair, step, camera, canvas, figure.
    const Viewer& View() const { return app->GetViewer(); }
    // The app's document: scene, file, history.
    const Document& Doc() const { return app->GetDocument(); }
    void Frames(int count)
    {
        for (int i = 0; i < count; ++i)
        {
            ImGui::NewFrame();
            app->Frame();
            ImGui::Render();
        }
    }
    // Screen position (in the window) of a world point on the canvas.
    ImVec2 OnScreen(Vec2 world) const
    {
        const ScreenPoint p = ToScreen(View().Camera(), world);
        const ScreenPoint origin = View().CanvasOrigin();
        return ImVec2(p.x + origin.x, p.y + origin.y);
    }
    // The canvas's top-left corner in the window.
    ImVec2 CanvasOrigin() const
    {
        const ScreenPoint origin = View().CanvasOrigin();
        return ImVec2(origin.x, origin.y);
    }
    void MoveTo(ImVec2 p)
    {
        ImGui::GetIO().MousePos = p;
        Frames(1);
    }
    // Press at `from`, move in steps to `to`, release.
    void Drag(ImVec2 from, ImVec2 to, int button = 0, bool shift = false)
    {
        ImGuiIO& io = ImGui::GetIO();
        MoveTo(from);
        io.KeyShift = shift;
        io.MouseDown[button] = true;
        Frames(1);
        for (int i = 1; i <= 8; ++i)
        {
            io.MousePos = ImVec2(from.x + (to.x - from.x) * i / 8.0f, from.y + (to.y - from.y) * i / 8.0f);
            Frames(1);
        }
        io.MouseDown[button] = false;
        Frames(1);
        io.KeyShift = false;
    }
    void Key(int slot, bool ctrl = false)
    {
        ImGuiIO& io = ImGui::GetIO();
        io.KeyCtrl = ctrl;
        io.KeysDown[slot] = true;
        Frames(1);
        io.KeysDown[slot] = false;
        Frames(1);
        io.KeyCtrl = false;
    }
    // Types into the text field that has the keyboard focus, then presses Enter.
    void TypeAndEnter(const std::string& text)
    {
        Frames(1);
        ImGui::GetIO().AddInputCharactersUTF8(text.c_str());
        Frames(1);
        Key(kEnter);
    }
    // True while the window (or popup) of that name is shown.
    static bool Showing(const char* window)
    {
        const ImGuiWindow* w = ImGui::FindWindowByName(window);
        return w != nullptr && w->Active;
    }
    // Clicks the button of that label in the window of that name: finds it by moving the pointer over the window
    // until ImGui reports the button hovered. False when the window or the button is not shown.
    bool ClickButton(const char* window, const char* label)
    {
        Frames(2); // a popup that just appeared is sized on its second frame
        ImGuiWindow* w = ImGui::FindWindowByName(window);
        if (w == nullptr || !w->Active)
        {
            return false;
        }
        const ImGuiID id = w->GetID(label);
        const ImVec2 low = w->Pos;
        const ImVec2 high(w->Pos.x + w->Size.x, w->Pos.y + w->Size.y);
        for (float y = low.y + 2.0f; y < high.y; y += 4.0f)
        {
            for (float x = low.x + 2.0f; x < high.x; x += 8.0f)
            {
                MoveTo(ImVec2(x, y));
                if (ImGui::GetCurrentContext()->HoveredId == id)
                {
                    ImGuiIO& io = ImGui::GetIO();
                    io.MouseDown[0] = true;
                    Frames(1);
                    io.MouseDown[0] = false;
                    Frames(2);
                    return true;
                }
            }
        }
        return false;
    }
    // Runs frames until the background test of the pair is taken in; false after 30 s.
    bool AwaitStudy()
    {
        for (int i = 0; i < 3000 && View().Studying(); ++i)
        {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            Frames(1);
        }
        return !View().Studying();
    }
    const Body& BodyNamed(const std::string& name) const
    {
        for (const Body& body : Doc().GetScene().bodies)
        {
            if (body.name == name)
            {
                return body;
            }
        }
        FAIL("no body " << name);
        return Doc().GetScene().bodies.front();
    }
};

Vec2 Centroid(const Body& body)
{
    return TransformPoint(body.Xf(), body.shape.type == ShapeType::Polygon ? body.shape.polygon.Centroid()
                                                                           : body.shape.circle.center);
}

} // namespace

TEST_CASE("Dragging a body moves it with the pointer, undo and redo restore each state", "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    const Vec2 before = h.BodyNamed("B").position;
    const double zoom = h.View().Camera().zoom;
    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 40.0f, from.y - 20.0f));
    const Vec2 after = h.BodyNamed("B").position;
    CHECK(after.x - before.x == Approx(40.0 / zoom).epsilon(1e-5));
    CHECK(after.y - before.y == Approx(20.0 / zoom).epsilon(1e-5));
    CHECK(h.Doc().Dirty());
    CHECK(h.Doc().UndoDepth() == 1);
    // The queries follow the edit.
    const Manifold& m = h.View().Setup().study.manifold;
    const Body& a = h.BodyNamed("A");
    const Body& b = h.BodyNamed("B");
    const Manifold fresh = Collide(a.shape, a.Xf(), b.shape, b.Xf());
    CHECK(m.depth == fresh.depth);

    h.Key(kZ, true);
    CHECK(h.BodyNamed("B").position == before);
    h.Key(kY, true);
    CHECK(h.BodyNamed("B").position == after);
    // A click without a move is not an edit.
    h.Drag(h.OnScreen(Centroid(h.BodyNamed("B"))), h.OnScreen(Centroid(h.BodyNamed("B"))));
    CHECK(h.Doc().UndoDepth() == 1);
}

TEST_CASE("Arrow keys and space step through the trace, edits keep the step where it still exists", "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    const int verdict = h.View().Setup().study.VerdictStep();
    CHECK(h.View().Step() == verdict);
    h.Key(kLeft);
    CHECK(h.View().Step() == verdict - 1);
    h.Key(kLeft);
    h.Key(kLeft);
    CHECK(h.View().Step() == verdict - 3);
    h.Key(kRight);
    CHECK(h.View().Step() == verdict - 2);
    const int kept = h.View().Step();
    CHECK(h.View().Setup().figure.step == kept);
    // Nudge a body: the pair still has as many steps, so the step stays.
    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 3.0f, from.y));
    CHECK(h.View().Step() == kept);
    // Space plays from the first step to the verdict.
    h.Key(kSpace);
    CHECK(h.View().Playing());
    h.Frames(60 * 20);
    CHECK(!h.View().Playing());
    CHECK(h.View().Step() == verdict);
}

TEST_CASE("A student reading the verdict stays on it through edits and changes of the view", "[app]")
{
    // The first axis separates the pair: the verdict is step 1. Moved onto the hexagon, the pair overlaps on every
    // axis, and step 1 is now an axis.
    Harness h(ScratchCopy("separated_triangle.json").string());
    const int apart = h.View().Setup().study.VerdictStep();
    REQUIRE(h.View().Step() == apart);
    h.app->MoveBody(1, Vec2{0.2, 0.1});
    const int verdict = h.View().Setup().study.VerdictStep();
    REQUIRE(verdict > apart);
    CHECK(h.View().Step() == verdict);
    h.app->SetStepView(StepView::Faces);
    CHECK(h.View().Step() == h.View().Setup().study.VerdictStep());
    h.app->SetQuery(ViewQuery::Sweep);
    CHECK(h.View().Step() == h.View().Setup().study.VerdictStep());
    REQUIRE(h.app->Undo());
    REQUIRE(h.app->Undo());
    REQUIRE(h.app->Undo());
    CHECK(h.View().Step() == apart);
    // Off the verdict, an edit keeps the step where it still exists.
    h.app->MoveBody(1, Vec2{0.2, 0.1});
    h.Key(kLeft);
    const int axis = h.View().Step();
    REQUIRE(axis < verdict);
    h.app->MoveBody(1, Vec2{0.25, 0.1});
    CHECK(h.View().Step() == axis);
}

TEST_CASE("The arrows and Play pass over the faces a large-polygon sweep decided without evaluating them", "[app]")
{
    // A 40-gon and a 100-gon thrown at it, in the face-test view: each polygon's faces are walked to only where they
    // can decide, and the others are steps of their own, flagged.
    const fs::path scene = ScratchCopy("many_sides.json").parent_path() / "walked_sweep.json";
    {
        std::ofstream out(scene);
        out << R"({"bodies": [{"name": "wheel", "regular": {"sides": 40, "radius": 1.0}},
                              {"name": "puck", "regular": {"sides": 100, "radius": 0.5}, "position": [2.2, 0.9],
                               "velocity": [-2.0, -1.0]}],
                   "view": {"query": "sweep", "steps": "faces"}})";
    }
    Harness h(scene.string());
    REQUIRE(h.AwaitStudy());
    const PairStudy& study = h.View().Setup().study;
    REQUIRE(study.sweep);
    REQUIRE_FALSE(study.Textbook());
    std::vector<int> evaluated;
    for (int k = 0; k < study.AxisCount(); ++k)
    {
        if (!study.Decided(k))
        {
            evaluated.push_back(k);
        }
    }
    REQUIRE(evaluated.size() >= 2);
    REQUIRE(study.AxisCount() > 10 * static_cast<int>(evaluated.size()));
    // From the verdict the left arrow visits the faces evaluated, latest first, and stays at the first one.
    CHECK(h.View().Step() == study.VerdictStep());
    for (size_t k = evaluated.size(); k-- > 0;)
    {
        h.Key(kLeft);
        CHECK(h.View().Step() == evaluated[k]);
    }
    h.Key(kLeft);
    CHECK(h.View().Step() == evaluated.front());
    h.Key(kRight);
    CHECK(h.View().Step() == evaluated[1]);
    // Play goes from the first face evaluated to the verdict through the faces evaluated alone.
    h.app->ShowStep(study.VerdictStep());
    h.Key(kSpace);
    CHECK(h.View().Step() == evaluated.front());
    std::vector<int> shown;
    while (h.View().Playing() && shown.size() < evaluated.size() + 2)
    {
        const int step = h.View().Step();
        if (shown.empty() || shown.back() != step)
        {
            shown.push_back(step);
        }
        h.Frames(1);
    }
    CHECK(h.View().Step() == study.VerdictStep());
    CHECK(shown == evaluated);
}

// Twice the signed area of a closed outline (shoelace), the oracle of the decompositions and cuts below.
long double Shoelace2(const std::vector<Vec2>& p)
{
    long double sum = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const Vec2& a = p[i];
        const Vec2& b = p[(i + 1) % p.size()];
        sum += static_cast<long double>(a.x) * b.y - static_cast<long double>(b.x) * a.y;
    }
    return sum;
}

// A body's area by its own outline: a concave body's as written, a polygon's vertices.
double OutlineArea(const Body& body)
{
    if (body.IsConcave())
    {
        return static_cast<double>(std::fabs(Shoelace2(body.outline)) / 2);
    }
    const std::vector<Vec2> v(body.shape.polygon.Vertices().begin(), body.shape.polygon.Vertices().end());
    return static_cast<double>(Shoelace2(v) / 2);
}

// The sum of the pieces' areas of a concave body.
double PiecesArea(const Body& body)
{
    double sum = 0;
    for (const ConcavePart& part : body.concave.parts)
    {
        const std::vector<Vec2> v(part.shape.polygon.Vertices().begin(), part.shape.polygon.Vertices().end());
        sum += static_cast<double>(Shoelace2(v) / 2);
    }
    return sum;
}

TEST_CASE("A vertex drag may make a polygon concave and decomposed but not make its outline cross itself", "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    const Body& b = h.BodyNamed("B");
    // Select B, then drag its vertex 0 past the diagonal through vertices 1 and 3: a dart, concave.
    h.Drag(h.OnScreen(Centroid(b)), h.OnScreen(Centroid(b)));
    REQUIRE(h.app->Selected() >= 0);
    const Vec2 v0 = TransformPoint(b.Xf(), b.shape.polygon.Vertices()[0]);
    const Vec2 v2 = TransformPoint(b.Xf(), b.shape.polygon.Vertices()[2]);
    const Vec2 dart = v0 + 0.7 * (v2 - v0);
    h.Drag(h.OnScreen(v0), h.OnScreen(dart));
    CHECK(!h.app->StatusIsError());
    const Body& concave = h.BodyNamed("B");
    REQUIRE(concave.IsConcave());
    CHECK(concave.concave.parts.size() == 2);
    REQUIRE(concave.outline.size() == 4);
    CHECK(Length(TransformPoint(concave.Xf(), concave.outline[0]) - dart) < 2.0 / h.View().Camera().zoom);
    // The pieces tile the outline: the dart's area is the box's less the triangle cut out of it.
    CHECK(PiecesArea(concave) == Approx(OutlineArea(concave)).epsilon(1e-12));
    CHECK(OutlineArea(concave) == Approx(1.0 - 0.7).margin(0.02));
    // The vertex handles are the outline's: vertex 0 is where the pointer left it, inside the hull.
    const Vec2 at = TransformPoint(concave.Xf(), concave.outline[0]);

    // Out past edge 1 the outline would cross itself: refused, the vertex left where it last kept it simple.
    const Vec2 beyond = TransformPoint(b.Xf(), Vec2{1.0, 0.0}); // past edge 1, which edge 3 would then cross
    h.Drag(h.OnScreen(at), h.OnScreen(beyond));
    CHECK(h.app->StatusIsError());
    CHECK(h.app->Status().find("stays at its last position that keeps the polygon simple") != std::string::npos);
    CHECK(h.app->Status().find("not simple") != std::string::npos);
    const Body& kept = h.BodyNamed("B");
    const std::vector<Vec2> keptOutline = kept.IsConcave() ? kept.outline
                                                          : std::vector<Vec2>(kept.shape.polygon.Vertices().begin(),
                                                                              kept.shape.polygon.Vertices().end());
    CHECK(Length(TransformPoint(kept.Xf(), keptOutline[0]) - beyond) > 0.1);
    CHECK(Decompose(keptOutline, DecomposeMethod::Fast).Ok());
    // Undo takes the refused drag back, then the dart's.
    h.Key(kZ, true);
    h.Key(kZ, true);
    const Body& undone = h.BodyNamed("B");
    CHECK(!undone.IsConcave());
    CHECK(Length(TransformPoint(undone.Xf(), undone.shape.polygon.Vertices()[0]) - v0) < 1e-12);
    // Redo brings the dart back, and a drag back outwards makes it a convex polygon again, in the same order.
    h.Key(kY, true);
    REQUIRE(h.BodyNamed("B").IsConcave());
    const Vec2 outward = v0 + 0.1 * (v0 - v2);
    h.Drag(h.OnScreen(dart), h.OnScreen(outward));
    const Body& convex = h.BodyNamed("B");
    CHECK(!convex.IsConcave());
    CHECK(Length(TransformPoint(convex.Xf(), convex.shape.polygon.Vertices()[0]) - outward) <
          2.0 / h.View().Camera().zoom);
}

TEST_CASE("Moving a vertex of a concave body inside its hull reshapes the body that the simulation steps", "[app]")
{
    const fs::path file = fs::temp_directory_path() / ("satviz-app-notch-" + std::to_string(::getpid()) + ".json");
    std::ofstream(file) << R"({"bodies": [{"name": "wall", "box": [1, 1], "position": [20, 0], "static": true},
        {"name": "U", "polygon": [[0,0],[3,0],[3,2],[2,2],[2,1],[1,1],[1,2],[0,2]]}], "world": {"dt": 1}})";
    Harness h(file.string());
    h.app->SimForward();
    REQUIRE(h.app->GetSimulation().Record().world.bodies[1].mass == Approx(5.0));
    h.app->SimReset();
    // The notch's floor lowered from 1 to 0.5: the hull is the same, the U loses half a square unit.
    const Body& u = h.BodyNamed("U");
    REQUIRE(h.app->MoveVertex(1, 4, TransformPoint(u.Xf(), Vec2{2, 0.5})));
    REQUIRE(h.app->MoveVertex(1, 5, TransformPoint(u.Xf(), Vec2{1, 0.5})));
    h.app->SimForward();
    CHECK(h.app->GetSimulation().Record().world.bodies[1].mass == Approx(4.5).epsilon(1e-12));
    fs::remove(file);
}

TEST_CASE("A polygon drawn by clicking its vertices is added, decomposed as it grows, and saved as its outline",
          "[app]")
{
    const fs::path file = ScratchCopy("overlapping_boxes.json");
    Harness h(file.string());
    auto click = [&](Vec2 world) {
        h.MoveTo(h.OnScreen(world));
        ImGui::GetIO().MouseDown[0] = true;
        h.Frames(1);
        ImGui::GetIO().MouseDown[0] = false;
        h.Frames(1);
    };
    // An arrow head pointing right, below the boxes: concave at its notch.
    const std::vector<Vec2> arrow{{-1.5, -1.8}, {0.5, -1.3}, {-1.5, -0.8}, {-1.0, -1.3}};
    h.Key('D');
    for (const Vec2& v : arrow)
    {
        click(v);
    }
    CHECK(h.app->Status().find("4 vertices, 2 convex pieces") != std::string::npos);
    CHECK(h.Doc().GetScene().bodies.size() == 2); // not yet closed
    click(arrow.front() + Vec2{0.01, 0.01}); // the first vertex closes it
    REQUIRE(h.Doc().GetScene().bodies.size() == 3);
    const Body& drawn = h.BodyNamed("polygon1");
    REQUIRE(drawn.IsConcave());
    CHECK(drawn.concave.parts.size() == 2);
    REQUIRE(drawn.outline.size() == arrow.size());
    const double pixel = 1.0 / h.View().Camera().zoom;
    for (size_t i = 0; i < arrow.size(); ++i)
    {
        CHECK(Length(TransformPoint(drawn.Xf(), drawn.outline[i]) - arrow[i]) < pixel);
    }
    // Area 0.75 by hand: the triangle (-1.5, -1.8), (0.5, -1.3), (-1.5, -0.8) of area 1, less the notch's 0.25.
    CHECK(OutlineArea(drawn) == Approx(0.75).margin(4 * pixel));
    CHECK(PiecesArea(drawn) == Approx(OutlineArea(drawn)).epsilon(1e-12));
    CHECK(h.app->Selected() == 2);

    // A triangle drawn clockwise, closed with Enter: one convex polygon.
    h.Key('D');
    for (const Vec2& v : {Vec2{-1.5, 1.0}, Vec2{-1.0, 1.5}, Vec2{-0.5, 1.0}})
    {
        click(v);
    }
    h.Key(kEnter);
    const Body& triangle = h.BodyNamed("polygon2");
    CHECK(!triangle.IsConcave());
    CHECK(triangle.shape.polygon.Count() == 3);
    CHECK(OutlineArea(triangle) == Approx(0.25).margin(4 * pixel));

    // Each is one edit; saved, the arrow is its outline and reads back concave.
    h.Key(kZ, true);
    CHECK(h.Doc().GetScene().bodies.size() == 3);
    REQUIRE(h.app->Save(file.string()));
    SceneOptions options;
    options.concave = true;
    const SceneResult saved = LoadScene(file.string(), options);
    REQUIRE(saved.Ok());
    REQUIRE(saved.scene.bodies.size() == 3);
    CHECK(saved.scene.bodies[2].IsConcave());
    CHECK(saved.scene.bodies[2].outline == drawn.outline);
}

TEST_CASE("A cut drawn with the mouse slices the polygon it crosses into bodies that keep its area and momentum",
          "[app]")
{
    const fs::path file = ScratchCopy("overlapping_boxes.json");
    Harness h(file.string());
    h.app->SetVelocity(1, {0.5, -0.25});
    const Body before = h.BodyNamed("B");
    const double area = OutlineArea(before);
    // Across B along its own x axis, from outside to outside; A is left whole (the cut stays clear of it).
    const Vec2 from = TransformPoint(before.Xf(), Vec2{-0.9, 0.2});
    const Vec2 to = TransformPoint(before.Xf(), Vec2{0.9, 0.2});
    h.Key('X');
    h.Drag(h.OnScreen(from), h.OnScreen(to));
    REQUIRE(h.Doc().GetScene().bodies.size() == 3);
    CHECK(h.app->Status() == "Cut B into B and B.1");
    const Body& b = h.BodyNamed("B");
    const Body& b1 = h.BodyNamed("B.1");
    // The two parts tile B: the strip above the cut is 0.3 tall, the rest 0.7, within the pointer's pixels.
    CHECK(OutlineArea(b) + OutlineArea(b1) == Approx(area).epsilon(1e-12));
    CHECK(std::min(OutlineArea(b), OutlineArea(b1)) == Approx(0.3).margin(4.0 / h.View().Camera().zoom));
    // Momentum: the parts' masses times their velocities add up to B's (B does not turn, so both move with it).
    CHECK(Length(b.velocity - before.velocity) < 1e-15);
    CHECK(Length(b1.velocity - before.velocity) < 1e-15);
    // One edit: undo gives B back whole.
    h.Key(kZ, true);
    CHECK(h.Doc().GetScene().bodies.size() == 2);
    CHECK(SceneToJson(h.Doc().GetScene()).find("B.1") == std::string::npos);
    h.Key(kY, true);
    REQUIRE(h.app->Save(file.string()));
    SceneOptions options;
    options.concave = true;
    const SceneResult saved = LoadScene(file.string(), options);
    REQUIRE(saved.Ok());
    REQUIRE(saved.scene.bodies.size() == 3);
    CHECK(saved.scene.bodies[2].name == "B.1");
}

TEST_CASE("A cut in the simulation cuts the world's body as it moves there, keeping the momentum of the state shown",
          "[app]")
{
    const fs::path file = fs::temp_directory_path() / ("satviz-app-cut-" + std::to_string(::getpid()) + ".json");
    // A U turning and flying, without gravity: its momentum and angular momentum stay what they were.
    std::ofstream(file) << R"({"bodies": [{"name": "wall", "box": [1, 1], "position": [20, 0], "static": true},
        {"name": "U", "polygon": [[0,0],[3,0],[3,2],[2,2],[2,1],[1,1],[1,2],[0,2]], "velocity": [1, 0.5],
         "angular_velocity": 0.8}], "world": {"dt": 0.05}})";
    Harness h(file.string());
    for (int i = 0; i < 5; ++i)
    {
        h.app->SimForward();
    }
    h.Frames(1);
    const Scene shown = h.app->ShownScene();
    const World world = MakeWorld(shown);
    const Vec2 p0 = LinearMomentum(world);
    const Vec2 origin{-3, 7};
    const double l0 = AngularMomentum(world, origin);
    const Body& u = shown.bodies[1];
    REQUIRE(u.IsConcave());
    // Through both prongs of the U, above its base: three parts.
    const Vec2 from = TransformPoint(u.Xf(), Vec2{-1, 1.5});
    const Vec2 to = TransformPoint(u.Xf(), Vec2{4, 1.5});
    CHECK(h.app->CutAlong(from, to) == 1);
    const Scene& cut = h.Doc().GetScene();
    REQUIRE(cut.bodies.size() == 4);
    CHECK(cut.bodies[2].name == "U.1");
    CHECK(cut.bodies[3].name == "U.2");
    // The state the cut was made in is the scene now; the world made from it has the same momentum.
    const World after = MakeWorld(cut);
    const Vec2 p1 = LinearMomentum(after);
    CHECK(Length(p1 - p0) < 1e-12 * Length(p0));
    CHECK(AngularMomentum(after, origin) == Approx(l0).epsilon(1e-12));
    double area = 0;
    for (size_t i = 1; i < cut.bodies.size(); ++i)
    {
        area += OutlineArea(cut.bodies[i]);
    }
    CHECK(area == Approx(5.0).epsilon(1e-12)); // the U: 3 x 2 less its 1 x 1 notch
    fs::remove(file);
}

TEST_CASE("A key tapped between two frames is seen down for a frame, and every event keeps its order", "[app]")
{
    KeyQueue queue;
    std::vector<std::string> frame;
    auto take = [&]() {
        frame.clear();
        queue.TakeFrame([&](const KeyEvent& e) { frame.push_back((e.press ? "+" : "-") + std::to_string(e.key)); });
        return frame;
    };
    // ctrl+q as xdotool types it (ctrl released before q), then a right arrow tapped twice, all before the next
    // frame: each press is seen with the keys held at that moment.
    for (const KeyEvent& e :
         {KeyEvent{341, 0, true, 0}, KeyEvent{81, 0, true, 2}, KeyEvent{341, 0, false, 2}, KeyEvent{81, 0, false, 0},
          KeyEvent{262, 0, true, 0}, KeyEvent{262, 0, false, 0}, KeyEvent{262, 0, true, 0}, KeyEvent{262, 0, false, 0}})
    {
        queue.Push(e);
    }
    CHECK(take() == std::vector<std::string>{"+341", "+81"});
    CHECK(queue.Waiting());
    CHECK(take() == std::vector<std::string>{"-341", "-81", "+262"});
    CHECK(take() == std::vector<std::string>{"-262", "+262"});
    CHECK(take() == std::vector<std::string>{"-262"});
    CHECK(!queue.Waiting());
    CHECK(take().empty());
    // A key held over frames is released in the frame its release comes.
    queue.Push({65, 0, true, 0});
    CHECK(take() == std::vector<std::string>{"+65"});
    queue.Push({65, 0, false, 0});
    queue.Push({66, 0, true, 0});
    CHECK(take() == std::vector<std::string>{"-65", "+66"});
}

TEST_CASE("The wheel zooms about the pointer and a drag on empty space pans", "[app]")
{
    Harness h(ScratchCopy("separated_triangle.json").string());
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 pointer(h.CanvasOrigin().x + 120.0f, h.CanvasOrigin().y + 140.0f);
    h.MoveTo(pointer);
    const Vec2 under = ToWorld(h.View().Camera(), {pointer.x - h.CanvasOrigin().x, pointer.y - h.CanvasOrigin().y});
    const double zoom = h.View().Camera().zoom;
    io.MouseWheel = 2.0f;
    h.Frames(1);
    io.MouseWheel = 0.0f;
    CHECK(h.View().Camera().zoom == Approx(zoom * 1.15 * 1.15));
    const Vec2 still = ToWorld(h.View().Camera(), {pointer.x - h.CanvasOrigin().x, pointer.y - h.CanvasOrigin().y});
    CHECK(Length(still - under) < 1e-9);
    CHECK(!h.View().CameraFit());
    const Vec2 center = h.View().Camera().center;
    h.Drag(pointer, ImVec2(pointer.x + 50.0f, pointer.y + 30.0f), 1);
    CHECK(h.View().Camera().center.x == Approx(center.x - 50.0 / h.View().Camera().zoom));
    CHECK(h.View().Camera().center.y == Approx(center.y + 30.0 / h.View().Camera().zoom));
}

TEST_CASE("Shift-drag turns a body and the velocity handle sets its velocity", "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    const Body& b = h.BodyNamed("B");
    const double angle = b.angle;
    const ImVec2 grab = h.OnScreen(b.position + Vec2{0.3, 0.0});
    // A quarter turn counter-clockwise around the body origin: from +x to +y.
    h.Drag(grab, h.OnScreen(b.position + Vec2{0.0, 0.3}), 0, true);
    CHECK(std::remainder(h.BodyNamed("B").angle - angle - 1.5707963267948966, 6.283185307179586) ==
          Approx(0.0).margin(0.02));
    // The velocity handle sits just right of the selected body as drawn, level with its origin, while it does not
    // move.
    const Body& turned = h.BodyNamed("B");
    float right = -INFINITY;
    for (const Vec2& v : turned.shape.polygon.Vertices())
    {
        right = std::max(right, ToScreen(h.View().Camera(), TransformPoint(turned.Xf(), v)).x);
    }
    const ScreenPoint origin = ToScreen(h.View().Camera(), turned.position);
    const ImVec2 handle(right + 22.0f + h.CanvasOrigin().x, origin.y + h.CanvasOrigin().y);
    const Vec2 target = turned.position + Vec2{-1.5, -0.25};
    h.Drag(handle, h.OnScreen(target));
    CHECK(Length(h.BodyNamed("B").velocity - Vec2{-1.5, -0.25}) < 2.0 / h.View().Camera().zoom);
    // The pair now moves but overlaps at t = 0: the swept test ran and handed over to the static one.
    CHECK(h.View().Setup().study.startsOverlapping);
}

TEST_CASE("A concave body's turning handle sits just above it, on the canvas, and follows it when it is dragged",
          "[app]")
{
    // Lesson 18's L turns about its corner (0, 0), 3.2 units from its far corner: the handle stands 26 pixels above
    // the L's top as drawn, over the corner, wherever the L is dragged; grabbed there it turns the L.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/l18_notch.json");
    auto handle = [&] {
        const Body& l = h.BodyNamed("L");
        float top = INFINITY;
        for (const Vec2& v : l.outline)
        {
            top = std::min(top, ToScreen(h.View().Camera(), TransformPoint(l.Xf(), v)).y);
        }
        const ScreenPoint corner = ToScreen(h.View().Camera(), l.position);
        return ImVec2(corner.x + h.CanvasOrigin().x, top - 26.0f + h.CanvasOrigin().y);
    };
    // Selected by a drag of its foot, down and to the right.
    const ImVec2 foot = h.OnScreen(Vec2{3.0, 0.5});
    h.Drag(foot, ImVec2(foot.x + 40.0f, foot.y + 30.0f));
    REQUIRE(h.app->Selected() == 0);
    REQUIRE(h.BodyNamed("L").position.x > 0.0);
    const ImVec2 grab = handle();
    CHECK(grab.y > h.CanvasOrigin().y);
    const View camera = h.View().Camera();
    // A drag from the handle to the right of the corner turns the L clockwise, and the camera stays.
    const ImVec2 corner = h.OnScreen(h.BodyNamed("L").position);
    h.Drag(grab, ImVec2(corner.x + (grab.y - corner.y) * -1.0f, corner.y));
    CHECK(h.BodyNamed("L").angle == Approx(-1.5707963267948966).margin(0.05));
    CHECK(h.View().Camera().center == camera.center);
}

TEST_CASE("Pair, query, step view, pitfall, precision and layer changes are edits that undo and redo restore", "[app]")
{
    // Three bodies; the file's view tests the bottom cushion and the moving ball, so the swept test.
    Harness h(ScratchCopy("l17_corner.json").string());
    REQUIRE(h.View().Setup().Ok());
    auto pair = [&h]() {
        const PairStudy& study = h.View().Setup().study;
        const Scene& studied = h.View().Studied();
        return studied.bodies[static_cast<size_t>(study.bodyA)].name + "," +
               studied.bodies[static_cast<size_t>(study.bodyB)].name;
    };
    CHECK(pair() == "bottom,ball");
    CHECK(h.View().Setup().study.sweep);
    CHECK(!h.Doc().Dirty());
    CHECK(h.Doc().UndoDepth() == 0);

    SECTION("the pair")
    {
        h.app->SetPair("right", "ball");
        CHECK(pair() == "right,ball");
        CHECK(!h.Doc().Dirty()); // how the scene is looked at, not a change of it
        CHECK(h.Doc().UndoDepth() == 1);
        CHECK(h.app->SceneForSaving().view.bodyA == "right");
        // ctrl+z and ctrl+y, as the user does it.
        h.Key(kZ, true);
        CHECK(pair() == "bottom,ball");
        CHECK(h.Doc().UndoDepth() == 0);
        CHECK(h.Doc().RedoDepth() == 1);
        CHECK(h.app->SceneForSaving().view.bodyA == "bottom");
        h.Key(kY, true);
        CHECK(pair() == "right,ball");
        CHECK(h.Doc().UndoDepth() == 1);
        // Naming the pair already shown is no edit.
        h.app->SetPair("right", "ball");
        CHECK(h.Doc().UndoDepth() == 1);
    }
    SECTION("the query")
    {
        h.app->SetQuery(ViewQuery::Collide);
        CHECK(h.View().Choices().query == ViewQuery::Collide);
        CHECK(!h.View().Setup().study.sweep);
        CHECK(h.Doc().UndoDepth() == 1);
        REQUIRE(h.app->Undo());
        CHECK(h.View().Choices().query == ViewQuery::Automatic);
        CHECK(h.View().Setup().study.sweep);
        REQUIRE(h.app->Redo());
        CHECK(h.View().Choices().query == ViewQuery::Collide);
        CHECK(!h.View().Setup().study.sweep);
        // Choosing the query already chosen is no edit.
        h.app->SetQuery(ViewQuery::Collide);
        CHECK(h.Doc().UndoDepth() == 1);
    }
    SECTION("the layers")
    {
        const LayerMask before = h.View().Choices().layers;
        REQUIRE(before == (kLayerShapes | kLayerLabels | kLayerSwept | kLayerGhost | kLayerCaption));
        const LayerMask after = before | kLayerNormals | kLayerMinkowski;
        h.app->SetLayers(after);
        CHECK(h.View().Setup().figure.layers == after);
        CHECK(!h.Doc().Dirty());
        CHECK(h.app->SceneForSaving().view.layers ==
              std::vector<std::string>{"shapes", "labels", "normals", "swept", "ghost", "caption", "minkowski"});
        REQUIRE(h.app->Undo());
        CHECK(h.View().Choices().layers == before);
        CHECK(h.View().Setup().figure.layers == before);
        CHECK(h.app->SceneForSaving().view.layers ==
              std::vector<std::string>{"shapes", "labels", "swept", "ghost", "caption"});
        REQUIRE(h.app->Redo());
        CHECK(h.View().Choices().layers == after);
        CHECK(h.View().Setup().figure.layers == after);
    }
    SECTION("the precision")
    {
        REQUIRE(!h.View().Setup().study.singlePrecision);
        h.app->SetPrecision(true);
        CHECK(h.View().Choices().singlePrecision);
        CHECK(h.View().Setup().study.singlePrecision);
        REQUIRE(h.app->Undo());
        CHECK(!h.View().Choices().singlePrecision);
        CHECK(!h.View().Setup().study.singlePrecision);
        CHECK(!h.app->SceneForSaving().view.singlePrecision);
        REQUIRE(h.app->Redo());
        CHECK(h.View().Setup().study.singlePrecision);
        CHECK(h.app->SceneForSaving().view.singlePrecision);
    }
    SECTION("the step view and the pitfall")
    {
        h.app->SetStepView(StepView::Faces);
        h.app->SetPitfall(Pitfall::OneShapesAxes);
        CHECK(!h.View().Setup().study.Textbook());
        CHECK(h.Doc().UndoDepth() == 2);
        REQUIRE(h.app->Undo());
        CHECK(h.View().Choices().pitfall == Pitfall::None);
        CHECK(h.View().Choices().steps == StepView::Faces);
        REQUIRE(h.app->Undo());
        CHECK(h.View().Choices().steps == StepView::Textbook);
        CHECK(h.View().Setup().study.Textbook());
        CHECK(!h.app->Undo());
        REQUIRE(h.app->Redo());
        REQUIRE(h.app->Redo());
        CHECK(h.View().Choices().pitfall == Pitfall::OneShapesAxes);
        CHECK(h.View().Choices().steps == StepView::Faces);
    }
}

TEST_CASE("Undo takes back body edits and view changes one at a time, in the order they were made", "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    const Vec2 start = h.BodyNamed("B").position;
    const LayerMask layers = h.View().Choices().layers;
    ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 20.0f, from.y));
    const Vec2 moved = h.BodyNamed("B").position;
    REQUIRE(moved != start);
    h.app->SetPrecision(true);
    h.app->SetLayers(layers | kLayerAxes);
    from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x, from.y + 20.0f));
    const Vec2 movedAgain = h.BodyNamed("B").position;
    REQUIRE(movedAgain != moved);
    CHECK(h.Doc().UndoDepth() == 4);

    // The last drag goes first; the view's choices stay as they were.
    REQUIRE(h.app->Undo());
    CHECK(h.BodyNamed("B").position == moved);
    CHECK(h.View().Choices().singlePrecision);
    CHECK(h.View().Choices().layers == (layers | kLayerAxes));
    REQUIRE(h.app->Undo());
    CHECK(h.View().Choices().layers == layers);
    CHECK(h.View().Choices().singlePrecision);
    CHECK(h.BodyNamed("B").position == moved);
    REQUIRE(h.app->Undo());
    CHECK(!h.View().Choices().singlePrecision);
    CHECK(h.BodyNamed("B").position == moved);
    REQUIRE(h.app->Undo());
    CHECK(h.BodyNamed("B").position == start);
    CHECK(!h.app->Undo());

    for (int i = 0; i < 4; ++i)
    {
        REQUIRE(h.app->Redo());
    }
    CHECK(!h.app->Redo());
    CHECK(h.BodyNamed("B").position == movedAgain);
    CHECK(h.View().Choices().singlePrecision);
    CHECK(h.View().Choices().layers == (layers | kLayerAxes));

    // A change after an undo starts a new branch: nothing is left to redo.
    REQUIRE(h.app->Undo());
    h.app->SetQuery(ViewQuery::Sweep);
    CHECK(h.Doc().RedoDepth() == 0);
    CHECK(h.Doc().UndoDepth() == 4);
}

TEST_CASE("Modified means differs from the file: undoing back to it, or changing only the view, is no change", "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    {
        // The view alone: query, step view, layers, precision, camera, step.
        Harness h(copy.string());
        REQUIRE(!h.Doc().Dirty());
        h.app->SetQuery(ViewQuery::Sweep);
        h.app->SetStepView(StepView::Faces);
        h.app->SetLayers(h.View().Choices().layers | kLayerNormals);
        h.app->SetPrecision(true);
        h.app->FitCamera();
        h.Key(kLeft);
        CHECK(!h.Doc().Dirty());
        CHECK(h.app->RequestQuit());
    }
    {
        // A drag, then undo: back to the file.
        Harness h(copy.string());
        const Vec2 start = h.BodyNamed("B").position;
        const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
        h.Drag(from, ImVec2(from.x + 30.0f, from.y));
        CHECK(h.Doc().Dirty());
        h.app->SetLayers(h.View().Choices().layers | kLayerAxes);
        h.Key(kZ, true);
        CHECK(h.Doc().Dirty()); // the layers were undone, the drag is still there
        h.Key(kZ, true);
        CHECK(!h.Doc().Dirty());
        CHECK(h.app->RequestQuit());
        h.Key(kY, true);
        CHECK(h.Doc().Dirty());
        // A move back to where the file has the body is no change either.
        h.app->MoveBody(1, start);
        CHECK(h.Doc().UndoDepth() == 2);
        CHECK(!h.Doc().Dirty());
    }
    {
        // Saved, edited, and undone back to the state saved: no change; one undo more, a change from the file.
        Harness h(copy.string());
        const ImVec2 grab = h.OnScreen(Centroid(h.BodyNamed("A")));
        h.Drag(grab, ImVec2(grab.x - 20.0f, grab.y));
        h.Key('S', true);
        REQUIRE(!h.Doc().Dirty());
        h.Drag(h.OnScreen(Centroid(h.BodyNamed("A"))), ImVec2(grab.x, grab.y + 25.0f));
        CHECK(h.Doc().Dirty());
        h.Key(kZ, true);
        CHECK(!h.Doc().Dirty());
        h.Key(kZ, true);
        CHECK(h.Doc().Dirty());
        CHECK(!h.app->RequestQuit());
    }
}

// The scene of `file` without its view block, as the document measures a change.
std::string BodiesOf(const std::string& file)
{
    SceneResult loaded = LoadScene(file);
    REQUIRE(loaded.Ok());
    loaded.scene.hasView = false;
    loaded.scene.view = SceneView{};
    loaded.scene.source = nullptr;
    return SceneToJson(loaded.scene);
}

// The copies in `folder`, by name.
std::vector<std::string> FilesIn(const fs::path& folder)
{
    std::vector<std::string> files;
    std::error_code code;
    for (const auto& entry : fs::directory_iterator(folder, code))
    {
        files.push_back(entry.path().string());
    }
    return files;
}

TEST_CASE("Unsaved changes are kept in a copy on disk until they are saved, undone or discarded, and a copy an app "
          "left is reported and taken back",
          "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    const fs::path folder = copy.parent_path() / "unsaved";
    fs::remove_all(folder);
    AppOptions options;
    options.unsavedDir = folder.string();
    std::string kept;
    {
        Harness h(copy.string(), options);
        CHECK(FilesIn(folder).empty());
        CHECK_FALSE(h.app->ReportLeftCopies()); // this app's own copy is not one left
        const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
        h.Drag(from, ImVec2(from.x + 30.0f, from.y - 10.0f));
        REQUIRE(h.Doc().Dirty());
        h.Frames(1);
        // The copy holds the scene as Save would write it: loaded back, the bodies the document has, not the file's.
        REQUIRE(FilesIn(folder).size() == 1);
        kept = h.app->UnsavedCopyPath();
        CHECK(kept == FilesIn(folder).front());
        CHECK(fs::path(kept).filename().string() == "overlapping_boxes.unsaved-" + std::to_string(::getpid()) + ".json");
        Scene bodies = h.Doc().GetScene();
        bodies.hasView = false;
        bodies.view = SceneView{};
        bodies.source = nullptr;
        CHECK(BodiesOf(kept) == SceneToJson(bodies));
        CHECK(BodiesOf(kept) != BodiesOf(copy.string()));
        CHECK_FALSE(h.app->ReportLeftCopies());
        // Undone back to the file: no copy. Redone: the copy again. Saved: none.
        h.Key(kZ, true);
        REQUIRE_FALSE(h.Doc().Dirty());
        h.Frames(1);
        CHECK(FilesIn(folder).empty());
        CHECK(h.app->UnsavedCopyPath().empty());
        h.Key(kY, true);
        h.Frames(1);
        CHECK(FilesIn(folder).size() == 1);
        h.Key('S', true);
        REQUIRE_FALSE(h.Doc().Dirty());
        h.Frames(1);
        CHECK(FilesIn(folder).empty());
        // Edited again and discarded on a quit: the app ends, its copy with it.
        const ImVec2 grab = h.OnScreen(Centroid(h.BodyNamed("A")));
        h.Drag(grab, ImVec2(grab.x - 20.0f, grab.y));
        h.Frames(1);
        CHECK(FilesIn(folder).size() == 1);
    }
    CHECK(FilesIn(folder).empty());

    // An app that ended without asking (its process gone) left a copy: the next app tells where it is; opened, it
    // saves to another file, and then the copy goes.
    pid_t gone = 4194303;
    while (gone > 2 && ::kill(gone, 0) == 0)
    {
        --gone;
    }
    fs::create_directories(folder);
    const fs::path left = folder / ("overlapping_boxes.unsaved-" + std::to_string(gone) + ".json");
    fs::copy_file(copy, left);
    {
        // The news passes as other news does: after a while with nothing done, or at the next edit.
        Harness h(copy.string(), options);
        REQUIRE(h.app->ReportLeftCopies());
        const std::string news = h.app->Status();
        ImGuiIO& io = ImGui::GetIO();
        io.DeltaTime = 1.0f;
        h.Frames(static_cast<int>(App::kPassingStatusSeconds) - 1);
        CHECK(h.app->Status() == news);
        h.Frames(2);
        CHECK(h.app->Status().empty());
        io.DeltaTime = 1.0f / 60.0f;
        REQUIRE(h.app->ReportLeftCopies());
        h.Frames(2);
        CHECK(h.app->Status() == news);
        const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
        h.Drag(from, ImVec2(from.x + 30.0f, from.y));
        CHECK(h.app->Status().find("ended before") == std::string::npos);
        // Or at the next step through the test.
        REQUIRE(h.app->ReportLeftCopies());
        h.Frames(2);
        CHECK(h.app->Status() == news);
        h.Key(kLeft);
        CHECK(h.app->Status().find("ended before") == std::string::npos);
    }
    {
        Harness h(copy.string(), options);
        REQUIRE(h.app->ReportLeftCopies());
        CHECK(h.app->Status().find(left.string()) != std::string::npos);
        REQUIRE(h.app->Open(left.string()));
        CHECK(h.Doc().ReadOnly());
        const fs::path mine = copy.parent_path() / "taken_back.json";
        REQUIRE(h.app->Save(mine.string()));
        CHECK_FALSE(fs::exists(left));
        CHECK(BodiesOf(mine.string()) == BodiesOf(copy.string()));
        CHECK_FALSE(h.app->ReportLeftCopies());
    }
}

TEST_CASE("While the quit question is open, the shortcuts wait: ctrl+o, F1 and the arrows leave it in place", "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    Harness h(copy.string());
    const ImVec2 grab = h.OnScreen(Centroid(h.BodyNamed("A")));
    h.Drag(grab, ImVec2(grab.x - 20.0f, grab.y));
    REQUIRE(h.Doc().Dirty());
    const int step = h.View().Step();
    h.Key('Q', true);
    h.Frames(2);
    REQUIRE(Harness::Showing("Unsaved changes"));
    h.Key('O', true);
    h.Key(290);
    h.Key(kLeft);
    CHECK(Harness::Showing("Unsaved changes"));
    CHECK(!Harness::Showing("Open scene"));
    CHECK(h.View().Step() == step);
    REQUIRE(h.ClickButton("Unsaved changes", "Cancel"));
    CHECK(!Harness::Showing("Unsaved changes"));
    // Answered, the keys act again.
    h.Key('O', true);
    CHECK(Harness::Showing("Open scene"));
}

TEST_CASE("A scene saved to a relative path says in which folder it went, and so does the save-as suggestion", "[app]")
{
    // Save as a bundled scene suggests "NAME-edited.json", written to the working folder: "Saved
    // overlapping_boxes-edited.json" did not say where that is (an app started from a menu has one of its own).
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    Harness h(copy.string());
    const fs::path target = copy.parent_path() / "saved-relative.json";
    const fs::path relative = fs::relative(target, fs::current_path());
    REQUIRE(relative.is_relative());
    REQUIRE(h.app->Save(relative.string()));
    CHECK(fs::exists(target));
    CHECK(h.app->Status() == "Saved " + fs::absolute(relative).lexically_normal().string());
    CHECK(fs::path(SaveAsSuggestion(h.Doc())).is_absolute());
    CHECK(fs::path(SaveAsSuggestion(h.Doc())).filename() == "saved-relative-edited.json");
}

TEST_CASE("Saving writes the view, the export figure is what satviz-render draws from the saved file", "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    Harness h(copy.string());
    h.Key(kLeft);
    h.Key(kLeft);
    h.app->SetLayers(h.View().Choices().layers | kLayerNormals);
    h.Key('S', true);
    CHECK(!h.Doc().Dirty());
    CHECK(h.app->Status().find("Saved") == 0);
    const SceneResult saved = LoadScene(copy.string());
    REQUIRE(saved.Ok());
    CHECK(saved.scene.view.step == h.View().Step());
    CHECK(saved.scene.view.width == h.View().CanvasWidth());
    CHECK(saved.scene.view.height == h.View().CanvasHeight());
    const FigureSetup fromFile = SetUpFigure(saved.scene, {});
    const FigureSetup fromApp = h.app->ExportFigure();
    REQUIRE(fromFile.Ok());
    CHECK(fromFile.figure.step == fromApp.figure.step);
    CHECK(fromFile.figure.layers == fromApp.figure.layers);
    CHECK((fromFile.figure.layers & kLayerNormals) != 0);
    CHECK(fromFile.figure.view.center == fromApp.figure.view.center);
    CHECK(fromFile.figure.view.zoom == fromApp.figure.view.zoom);
    CHECK(fromFile.figure.view.width == fromApp.figure.view.width);
    // The canvas shows that same figure.
    CHECK(fromApp.figure.view.center == h.View().Camera().center);
    CHECK(fromApp.figure.view.zoom == h.View().Camera().zoom);
}

TEST_CASE("A scene that fails to load keeps the current one and shows the error", "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    const std::string before = SceneToJson(h.Doc().GetScene());
    const fs::path broken = fs::temp_directory_path() / "satviz-app-broken.json";
    // A polygon that crosses itself: a concave one would load.
    std::ofstream(broken) << R"({"bodies": [{"polygon": [[0, 0], [1, 1], [1, 0], [0, 1]]}, {"box": [1, 1]}]})";
    CHECK(!h.app->Open(broken.string()));
    CHECK(h.app->StatusIsError());
    CHECK(h.app->Status().find("bodies[0].polygon") != std::string::npos);
    CHECK(SceneToJson(h.Doc().GetScene()) == before);
    fs::remove(broken);
}

TEST_CASE("A scene whose view asks for sim_steps opens at that step of its simulation, as satviz-render draws it",
          "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    const fs::path file = fs::temp_directory_path() / ("satviz-app-sim-" + std::to_string(::getpid()) + ".json");
    // Gravity 10, dt 0.1, 10 steps: the ball falls 10 * 0.1^2 * (1 + ... + 10) = 5.5.
    std::ofstream(file) << R"({"bodies": [{"name": "ground", "box": [4, 1], "position": [0, -10], "static": true},
        {"name": "ball", "circle": {"radius": 0.25}, "position": [0, 2]}],
        "world": {"gravity": [0, -10], "dt": 0.1}, "view": {"sim_steps": 10}})";
    REQUIRE(h.app->Open(file.string()));
    h.Frames(2);
    CHECK(!h.app->StatusIsError());
    CHECK(h.app->Status().find("after 10 rigid-body steps") != std::string::npos);
    CHECK(h.app->GetSimulation().Shown() == 10);
    CHECK(h.app->ShownScene().bodies[1].position.y == Approx(-3.5).margin(1e-12));
    CHECK(h.app->ShownScene().bodies[1].velocity.y == Approx(-10.0).margin(1e-12));
    CHECK(h.View().Studied().bodies[1].position.y == Approx(-3.5).margin(1e-12));
    // The scene stays as written, and a save or an export asks for the same steps.
    CHECK(h.Doc().GetScene().bodies[1].position.y == 2.0);
    CHECK(h.app->SceneForSaving().view.simSteps == 10);
    CHECK(!h.Doc().Dirty());
    h.app->SimReset();
    CHECK(h.app->SceneForSaving().view.simSteps == 0);
    fs::remove(file);
}

/// A copy of bundled scene `name` whose view block asks for trace step `step` (from 1, as the file counts them).
fs::path CopyAtStep(const std::string& name, int step)
{
    const fs::path copy = ScratchCopy(name);
    nlohmann::json scene;
    std::ifstream(copy) >> scene;
    scene["view"]["step"] = step;
    const fs::path asked = copy.parent_path() / ("step" + std::to_string(step) + "-" + name);
    std::ofstream(asked) << scene.dump(2);
    return asked;
}

TEST_CASE("A scene whose view.step is past its last step opens at the verdict and says so, naming the file and field",
          "[app]")
{
    // satviz-render refuses such a file; the app shows it, at the verdict, with one line that says why, and a save
    // writes the step shown. overlapping_boxes has 5 steps: its 4 axes and the verdict.
    Harness h(ScratchCopy("separated_triangle.json").string());
    const fs::path file = CopyAtStep("overlapping_boxes.json", 40);
    REQUIRE(h.app->Open(file.string()));
    h.Frames(2);
    REQUIRE(h.View().Setup().Ok());
    CHECK(h.View().Step() == h.View().VerdictStep());
    CHECK(h.app->StatusIsError());
    const std::string& said = h.app->Status();
    CHECK(said.find(file.string()) == 0);
    CHECK(said.find("view.step: step 40 does not exist: this figure has steps 1 to 5") != std::string::npos);
    CHECK(said.find("the verdict") != std::string::npos);
    CHECK(said.find('\n') == std::string::npos);
    CHECK(h.Doc().File() == file.string());
    CHECK(!h.Doc().Dirty());
    CHECK(h.app->SceneForSaving().view.step == h.View().VerdictStep());

    // A step that exists says nothing of it.
    REQUIRE(h.app->Open(CopyAtStep("overlapping_boxes.json", 3).string()));
    h.Frames(2);
    CHECK(h.View().Step() == 2);
    CHECK(!h.app->StatusIsError());

    // A large pair tested on the worker thread says it once its test is in.
    AppOptions background;
    background.backgroundVertices = 8;
    Harness large(ScratchCopy("separated_triangle.json").string(), background);
    const fs::path many = CopyAtStep("many_sides.json", 500);
    REQUIRE(large.app->Open(many.string()));
    REQUIRE(large.AwaitStudy());
    large.Frames(2);
    REQUIRE(large.View().Setup().Ok());
    CHECK(large.View().Step() == large.View().VerdictStep());
    CHECK(large.app->StatusIsError());
    CHECK(large.app->Status().find(many.string() + ": view.step: step 500 does not exist") == 0);
}

TEST_CASE("Quitting without changes needs no question", "[app]")
{
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    CHECK(h.app->RequestQuit());
    CHECK(h.app->QuitConfirmed());
}

TEST_CASE("Quitting with unsaved changes asks first, deleting keeps two bodies", "[app]")
{
    Harness edited(ScratchCopy("overlapping_boxes.json").string());
    const ImVec2 from = edited.OnScreen(Centroid(edited.BodyNamed("A")));
    edited.Drag(from, ImVec2(from.x - 10.0f, from.y));
    CHECK(!edited.app->RequestQuit());
    CHECK(!edited.app->QuitConfirmed());
    // Only two bodies: deleting one is refused.
    edited.Key(kDelete);
    CHECK(edited.Doc().GetScene().bodies.size() == 2);
    CHECK(edited.app->StatusIsError());
}

TEST_CASE("Opening a scene adds it to the recent file, unless the recent list is not to be updated", "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    const fs::path recentFile = copy.parent_path() / "config" / "recent.txt";
    fs::create_directories(recentFile.parent_path());
    std::ofstream(recentFile) << "/elsewhere/old.json\n";
    const auto contents = [&recentFile]() {
        std::ifstream in(recentFile);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    };
    AppOptions options;
    options.recentFile = recentFile.string();
    {
        // As for a --measure-fps run: the list is shown, but neither it nor its file changes.
        options.updateRecent = false;
        Harness h(copy.string(), options);
        CHECK(h.app->Recent() == std::vector<std::string>{"/elsewhere/old.json"});
        CHECK(contents() == "/elsewhere/old.json\n");
    }
    {
        options.updateRecent = true;
        Harness h(copy.string(), options);
        CHECK(h.app->Recent() == std::vector<std::string>{fs::absolute(copy).string(), "/elsewhere/old.json"});
        CHECK(contents() == fs::absolute(copy).string() + "\n/elsewhere/old.json\n");
    }
}

TEST_CASE("A camera beyond what a scene file accepts is saved within it, so the file opens again", "[app]")
{
    const fs::path copy = ScratchCopy("separated_triangle.json");
    Harness h(copy.string());
    h.app->SetCamera(h.View().Camera().center, 1e15);
    h.Key('S', true);
    CHECK(h.app->Status().find("Saved") == 0);
    SceneResult saved = LoadScene(copy.string());
    INFO(saved.error);
    REQUIRE(saved.Ok());
    CHECK(saved.scene.view.zoom == kMaxViewZoom);

    h.app->SetCamera({-5e12, 3.0}, 1e-12);
    h.Key('S', true);
    saved = LoadScene(copy.string());
    INFO(saved.error);
    REQUIRE(saved.Ok());
    CHECK(saved.scene.view.zoom == kMinViewZoom);
    CHECK(saved.scene.view.center == Vec2{-kMaxSceneValue, 3.0});
}

TEST_CASE("Saving after an edit keeps the file's $schema, its box shorthand and its key order", "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    Harness h(copy.string());
    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 30.0f, from.y));
    REQUIRE(h.Doc().Dirty());
    h.Key('S', true);
    REQUIRE(!h.Doc().Dirty());
    std::ifstream in(copy);
    const nlohmann::ordered_json saved = nlohmann::ordered_json::parse(in);
    CHECK(saved.begin().key() == "$schema");
    CHECK(saved["$schema"] == "../../core/scene/scene.schema.json");
    CHECK(saved["bodies"][0].dump() == R"({"name":"A","box":[2.0,1.0],"position":[0.0,0.0]})");
    const nlohmann::ordered_json& b = saved["bodies"][1];
    CHECK(b["polygon"].dump() == "[[-0.5,-0.5],[0.5,-0.5],[0.5,0.5],[-0.5,0.5]]");
    CHECK(b["position"][0].get<double>() == h.BodyNamed("B").position.x);
    CHECK(saved.contains("view"));
}

TEST_CASE("Opening another scene with unsaved changes asks first: cancel keeps them, or open without saving", "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    const fs::path other = ScratchCopy("separated_triangle.json");
    Harness h(copy.string());
    // Without changes, another scene opens at once.
    CHECK(h.app->RequestOpen(other.string()));
    CHECK(h.Doc().File() == other.string());
    REQUIRE(h.app->Open(copy.string()));
    h.Frames(2);

    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 30.0f, from.y));
    REQUIRE(h.Doc().Dirty());
    const Vec2 moved = h.BodyNamed("B").position;

    // ctrl+o, a path, Enter: the question comes before anything is opened.
    h.Key('O', true);
    REQUIRE(Harness::Showing("Open scene"));
    h.TypeAndEnter(other.string());
    CHECK(Harness::Showing("Unsaved changes before opening"));
    CHECK(h.Doc().File() == copy.string());
    REQUIRE(h.ClickButton("Unsaved changes before opening", "Cancel"));
    CHECK(!Harness::Showing("Unsaved changes before opening"));
    CHECK(h.Doc().File() == copy.string());
    CHECK(h.Doc().Dirty());
    CHECK(h.BodyNamed("B").position == moved);

    // The menus ask the same way; "Open without saving" opens the other scene and leaves the file as it was.
    CHECK(!h.app->RequestOpen(other.string()));
    REQUIRE(h.ClickButton("Unsaved changes before opening", "Open without saving"));
    CHECK(h.Doc().File() == other.string());
    CHECK(!h.Doc().Dirty());
    const SceneResult onDisk = LoadScene(copy.string());
    REQUIRE(onDisk.Ok());
    CHECK(onDisk.scene.bodies[1].position != moved);
}

TEST_CASE("Save and open saves the changes, then opens the other scene", "[app]")
{
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    const fs::path other = ScratchCopy("separated_triangle.json");
    Harness h(copy.string());
    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x - 25.0f, from.y + 10.0f));
    REQUIRE(h.Doc().Dirty());
    const Vec2 moved = h.BodyNamed("B").position;
    CHECK(!h.app->RequestOpen(other.string()));
    REQUIRE(h.ClickButton("Unsaved changes before opening", "Save and open"));
    CHECK(h.Doc().File() == other.string());
    CHECK(!h.Doc().Dirty());
    const SceneResult saved = LoadScene(copy.string());
    REQUIRE(saved.Ok());
    CHECK(saved.scene.bodies[1].position == moved);
}

TEST_CASE("Save and open on a bundled scene asks where to save, and opens nothing when that is cancelled", "[app]")
{
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    REQUIRE(h.Doc().ReadOnly());
    const std::string bundled = h.Doc().File();
    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 15.0f, from.y));
    REQUIRE(h.Doc().Dirty());
    CHECK(!h.app->RequestOpen(ScratchCopy("separated_triangle.json").string()));
    REQUIRE(h.ClickButton("Unsaved changes before opening", "Save and open"));
    REQUIRE(Harness::Showing("Save scene as"));
    REQUIRE(h.ClickButton("Save scene as", "Cancel"));
    CHECK(!Harness::Showing("Save scene as"));
    CHECK(h.Doc().File() == bundled);
    CHECK(h.Doc().Dirty());
}

TEST_CASE("Escape answers each question of the app as Cancel does: the work stays, unsaved", "[app]")
{
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 15.0f, from.y));
    REQUIRE(h.Doc().Dirty());
    h.Key('S', true); // a bundled scene: Save asks where
    h.Frames(2);
    REQUIRE(Harness::Showing("Save scene as"));
    h.Key(kEscape);
    h.Frames(2);
    CHECK(!Harness::Showing("Save scene as"));
    CHECK(!h.app->RequestOpen(ScratchCopy("separated_triangle.json").string()));
    h.Frames(2);
    REQUIRE(Harness::Showing("Unsaved changes before opening"));
    h.Key(kEscape);
    h.Frames(2);
    CHECK(!Harness::Showing("Unsaved changes before opening"));
    CHECK(!h.app->RequestQuit());
    h.Frames(2);
    REQUIRE(Harness::Showing("Unsaved changes"));
    h.Key(kEscape);
    h.Frames(2);
    CHECK(!Harness::Showing("Unsaved changes"));
    CHECK(!h.app->QuitConfirmed());
    CHECK(h.Doc().Dirty());
}

TEST_CASE("A large pair is tested on a worker thread while frames go on, and the figure follows", "[app]")
{
    // many_sides is a 64-gon and a triangle: over a limit of 8 vertices, it counts as large.
    AppOptions background;
    background.backgroundVertices = 8;
    Harness h(ScratchCopy("many_sides.json").string(), background);
    REQUIRE(h.AwaitStudy());
    REQUIRE(h.View().Setup().Ok());
    const Body& disc = h.BodyNamed("disc");
    const Body& triangle = h.BodyNamed("triangle");
    CHECK(h.View().Setup().study.manifold.depth == Collide(disc.shape, disc.Xf(), triangle.shape, triangle.Xf()).depth);
    // The textbook view: the 64-gon's opposite faces share an axis, 32 axes, then the triangle's 3 and the verdict.
    CHECK(h.View().Setup().study.StepCount() == 32 + 3 + 1);
    CHECK(h.View().Step() == h.View().Setup().study.VerdictStep());

    // An edit starts another test; the interface keeps the figure it has, and says why, until it is taken in.
    const Vec2 before = triangle.position;
    const ImVec2 from = h.OnScreen(Centroid(triangle));
    h.Drag(from, ImVec2(from.x + 40.0f, from.y));
    const Vec2 after = h.BodyNamed("triangle").position;
    REQUIRE(after != before);
    REQUIRE(h.AwaitStudy());
    CHECK(h.View().Studied().bodies[1].position == after);
    const Body& moved = h.BodyNamed("triangle");
    CHECK(h.View().Setup().study.manifold.depth == Collide(disc.shape, disc.Xf(), moved.shape, moved.Xf()).depth);

    // Stepping does not test again: it only picks another step of the same trace.
    h.Key(kLeft);
    CHECK(!h.View().Studying());
    CHECK(h.View().Step() == h.View().Setup().study.VerdictStep() - 1);
    CHECK(h.View().Setup().figure.step == h.View().Step());

    // Opening another scene drops the figure of the one before until its own test is in.
    REQUIRE(h.app->Open(ScratchCopy("many_sides.json").string()));
    CHECK(!h.View().Setup().Ok());
    h.Frames(1);
    // The worker may finish within that frame on a fast machine, so only what does not race is checked here.
    CHECK(h.app->Status().find("worker thread") == std::string::npos); // the status line shows it, not `status`
    REQUIRE(h.AwaitStudy());
    CHECK(h.View().Setup().Ok());
    CHECK(h.View().Studied().bodies[1].position == before);
}

TEST_CASE("Every scene a lesson names opens in the app, with a figure and its steps", "[app][lessons]")
{
    const fs::path tutorials = fs::path(SATVIZ_SOURCE_DIR) / "tutorials";
    std::set<std::string> scenes;
    for (const auto& entry : fs::directory_iterator(tutorials))
    {
        if (entry.path().extension() != ".md")
        {
            continue;
        }
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string lesson = text.str();
        for (const std::string& name : NamedScenes(lesson))
        {
            scenes.insert(name);
        }
    }
    REQUIRE(scenes.size() >= 10);
    for (const std::string& scene : scenes)
    {
        INFO(scene);
        Harness h((tutorials / "scenes" / (scene + ".json")).string());
        REQUIRE(h.View().Setup().Ok());
        CHECK(h.View().Setup().study.StepCount() >= 1);
        CHECK(!h.app->StatusIsError());
    }
}

TEST_CASE("Every bundled scene, in every folder of tutorials/scenes, opens in the app with its figure", "[app]")
{
    // The loader's rule against satviz-render's: a scene it draws, the app opens and shows, read-only (a bundled
    // scene). A scene of one body is drawn by a figure of one body only.
    const fs::path scenes = fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes";
    int opened = 0;
    int alone = 0;
    for (const auto& entry : fs::recursive_directory_iterator(scenes))
    {
        if (entry.path().extension() != ".json")
        {
            continue;
        }
        INFO(entry.path().string());
        const SceneResult loaded = LoadScene(entry.path().string(), SceneOptions{true});
        REQUIRE(loaded.Ok());
        FigureOptions options;
        options.width = 800;
        options.height = 600;
        const bool drawn = SetUpFigure(loaded.scene, options).Ok();
        Harness h((scenes / "overlapping_boxes.json").string());
        CHECK(h.app->Open(entry.path().string()) == drawn);
        if (!drawn)
        {
            continue;
        }
        ++opened;
        alone += loaded.scene.bodies.size() == 1 ? 1 : 0;
        CHECK(fs::equivalent(h.Doc().File(), entry.path()));
        CHECK(h.Doc().ReadOnly());
        h.Frames(3);
        h.AwaitStudy();
        CHECK(h.View().Setup().Ok());
        CHECK(!h.app->StatusIsError());
        // The arrows and the step keys on a figure without steps change nothing and break nothing.
        h.Key(kRight);
        h.Key(kLeft);
        h.Frames(2);
        CHECK(h.View().Setup().Ok());
    }
    CHECK(opened >= 100);
    CHECK(alone >= 4); // the decompositions and slices of lesson 18
}

TEST_CASE("A concave pair steps through its pieces: the boxes, each pair of pieces tested, the verdict", "[app]")
{
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/l18_across.json");
    REQUIRE(h.View().TestsPair());
    REQUIRE(h.View().CurrentFigure().kind == FigureKind::Pieces);
    const Scene& scene = h.Doc().GetScene();
    const ConcaveManifold m = Collide(scene.bodies[0].concave, scene.bodies[0].Xf(), scene.bodies[1].shape,
                                      scene.bodies[1].Xf());
    // The broadphase, one step per pair of pieces tested, the verdict.
    const int verdict = m.pairsTested + 1;
    REQUIRE(m.pairsTested == 2);
    CHECK(h.View().VerdictStep() == verdict);
    CHECK(h.View().Step() == verdict); // opened on the verdict
    for (int step = verdict - 1; step >= 0; --step)
    {
        h.Key(kLeft);
        CHECK(h.View().Step() == step);
        CHECK(h.View().CurrentFigure().step == step);
    }
    h.Key(kLeft);
    CHECK(h.View().Step() == 0);
    for (int step = 1; step <= verdict; ++step)
    {
        h.Key(kRight);
        CHECK(h.View().Step() == step);
    }
    h.Key(kRight);
    CHECK(h.View().Step() == verdict);
    // Play from the verdict starts at the boxes and stops at the verdict.
    h.Key(kSpace);
    CHECK(h.View().Step() == 0);
    CHECK(h.View().Playing());
    for (int i = 0; i < 400 && h.View().Playing(); ++i)
    {
        ImGui::GetIO().DeltaTime = 0.05f;
        h.Frames(1);
    }
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    CHECK(!h.View().Playing());
    CHECK(h.View().Step() == verdict);
}

TEST_CASE("No label of the canvas's figure lies under the selected body's turning or velocity handle", "[app]")
{
    // The box sunk into the L: at the verdict its push's depth is labelled right beside the box, where the velocity
    // handle of the box sits while it does not move.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/l18_across.json");
    REQUIRE(h.View().CurrentFigure().kind == FigureKind::Pieces);
    h.app->Select(1);
    h.Frames(1);
    const Body& box = h.BodyNamed("box");
    REQUIRE(box.velocity == Vec2{});
    // Where the canvas draws the handles, from the body as the user sees it: the turning handle 26 pixels above the
    // body's reach from its origin, the velocity handle (a disc of radius 5, the letter v right of it) 22 beside it.
    double extent = 0.0;
    for (const Vec2& v : box.shape.polygon.Vertices())
    {
        extent = std::max(extent, Length(v));
    }
    const View& camera = h.View().Camera();
    const ScreenPoint origin = ToScreen(camera, box.position);
    const float reach = static_cast<float>(extent * camera.zoom);
    struct Box
    {
        float minX, minY, maxX, maxY;
    };
    const Box turn{origin.x - 6.0f, origin.y - reach - 32.0f, origin.x + 6.0f, origin.y - reach - 20.0f};
    const Box velocity{origin.x + reach + 17.0f, origin.y - 8.0f, origin.x + reach + 37.0f, origin.y + 8.0f};
    Figure figure = CanvasFigure(*h.app);
    int pushes = 0;
    for (int step = 0; step <= h.View().VerdictStep(); ++step)
    {
        figure.step = step;
        RecordingCanvas canvas;
        PaintFigure(canvas, h.View().Studied(), h.View().Setup().study, figure);
        for (const DrawCommand& c : canvas.commands)
        {
            if (c.kind != DrawCommand::Kind::Text)
            {
                continue;
            }
            const ScreenPoint size = canvas.MeasureText(c.text, c.style);
            const Box label{c.points[0].x, c.points[0].y, c.points[0].x + size.x, c.points[0].y + size.y};
            for (const Box& handle : {turn, velocity})
            {
                const bool covered = label.minX < handle.maxX && handle.minX < label.maxX &&
                                     label.minY < handle.maxY && handle.minY < label.maxY;
                INFO("step " << step << ": \"" << c.text << "\" at " << label.minX << "," << label.minY);
                CHECK_FALSE(covered);
            }
            pushes += c.group == "labels" && c.text == "0.60" ? 1 : 0;
        }
    }
    CHECK(pushes > 0); // the push's label was drawn, beside the handle rather than under it
}

TEST_CASE("A selected moving body's velocity handle sits on the tip of the figure's arrow, named by one v", "[app]")
{
    // l13_sweep's triangle has its origin at a corner, not at its centroid, where the figure's arrow starts.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l13_sweep.json");
    h.app->Select(1);
    h.Frames(1);
    const Body& b = h.BodyNamed("B");
    REQUIRE(b.velocity != Vec2{});
    const View& camera = h.View().Camera();
    const ScreenPoint tip = ToScreen(camera, Centroid(b) + b.velocity);
    const ScreenPoint handle = VelocityHandleAt(camera, b);
    CHECK(std::hypot(handle.x - tip.x, handle.y - tip.y) < 0.5f);
    Figure figure = CanvasFigure(*h.app);
    // The figure's arrow, from the centroid to the handle.
    const ScreenPoint tail = ToScreen(camera, Centroid(b));
    const float length = std::hypot(tip.x - tail.x, tip.y - tail.y);
    REQUIRE(length > 0.0f);
    int near = 0;
    for (int step = 0; step <= h.View().VerdictStep(); ++step)
    {
        figure.step = step;
        RecordingCanvas canvas;
        PaintFigure(canvas, h.View().Studied(), h.View().Setup().study, figure);
        near = 0;
        for (const DrawCommand& c : canvas.commands)
        {
            if (c.kind == DrawCommand::Kind::Text && c.text == "v")
            {
                // Beside the arrow: within 24 pixels of its shaft, between its ends.
                const ScreenPoint size = canvas.MeasureText(c.text, c.style);
                const ScreenPoint m{c.points[0].x + size.x / 2.0f, c.points[0].y + size.y / 2.0f};
                const float along = ((m.x - tail.x) * (tip.x - tail.x) + (m.y - tail.y) * (tip.y - tail.y)) / length;
                const float across = std::abs((m.x - tail.x) * (tip.y - tail.y) - (m.y - tail.y) * (tip.x - tail.x)) /
                                     length;
                near += along > 0.0f && along < length + 24.0f && across < 24.0f ? 1 : 0;
            }
        }
        INFO("step " << step);
        CHECK(near == 1); // the figure names the arrow (by its head, or beside its shaft where that is crowded)
    }
    // The handle's own letter would be a second v beside it.
    CHECK(FigureNamesVelocity(*h.app));
    // A figure of one instant without the swept layer has no arrow: the handle names itself.
    h.app->SetLayers(h.View().Choices().layers & ~kLayerSwept);
    h.Frames(1);
    CHECK_FALSE(FigureNamesVelocity(*h.app));
}

TEST_CASE("The velocity handle is not drawn as a contact point: no vermillion dot where it lies", "[app]")
{
    // overlapping_boxes draws its two contact points as vermillion dots; B's velocity handle lies right of B, away
    // from them. Drawn in the contacts' colour it read as a third contact point.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    h.app->Select(1);
    h.Frames(2);
    const ScreenPoint at = VelocityHandleAt(h.View().Camera(), h.BodyNamed("B"));
    const ImVec2 origin = h.CanvasOrigin();
    const ImU32 vermillion = IM_COL32(0xD5, 0x5E, 0x00, 0xFF);
    int handleInk = 0;
    int vermillionNear = 0;
    const ImDrawData* data = ImGui::GetDrawData();
    REQUIRE(data != nullptr);
    for (int l = 0; l < data->CmdListsCount; ++l)
    {
        for (const ImDrawVert& v : data->CmdLists[l]->VtxBuffer)
        {
            if (std::hypot(v.pos.x - (at.x + origin.x), v.pos.y - (at.y + origin.y)) <= 7.0f)
            {
                ++handleInk;
                vermillionNear += v.col == vermillion ? 1 : 0;
            }
        }
    }
    CHECK(handleInk > 0); // the handle is drawn there
    CHECK(vermillionNear == 0);
}

TEST_CASE("A slider's text lies beside its grab, never half on it", "[app]")
{
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    // The grab as Dear ImGui places it (SliderBehavior) is the grab the text keeps away from.
    ImGui::NewFrame();
    ImGui::Begin("probe");
    const ImRect frame(ImVec2(100.0f, 10.0f), ImVec2(400.0f, 30.0f));
    const float least = ImGui::GetStyle().GrabMinSize;
    int checked = 0;
    for (const int last : {1, 2, 4, 9, 40})
    {
        for (int value = 0; value <= last; ++value)
        {
            int v = value;
            const int low = 0;
            ImRect grab;
            ImGui::SliderBehavior(frame, ImGui::GetID("##probe"), ImGuiDataType_S32, &v, &low, &last, "", 0, &grab);
            const SliderGrabSpan span = SliderGrab(frame.Min.x, frame.Max.x, static_cast<float>(value) / last,
                                                   last + 1, least);
            CHECK(span.min == Approx(grab.Min.x).margin(0.01));
            CHECK(span.max == Approx(grab.Max.x).margin(0.01));
            for (const float width : {12.0f, 60.0f, 90.0f})
            {
                const float x = SliderTextX(frame.Min.x, frame.Max.x, span, width);
                const bool fitsBeside = span.min - frame.Min.x >= width + 8.0f || frame.Max.x - span.max >= width + 8.0f;
                const bool onGrab = x < span.max && span.min < x + width;
                INFO("values " << last + 1 << ", value " << value << ", text " << width << " px at " << x);
                CHECK(x >= frame.Min.x);
                CHECK(x + width <= frame.Max.x);
                if (fitsBeside)
                {
                    CHECK_FALSE(onGrab);
                    ++checked;
                }
                else
                {
                    CHECK((x >= span.min && x + width <= span.max)); // wholly on a grab wider than the sides
                }
            }
        }
    }
    ImGui::End();
    ImGui::EndFrame();
    CHECK(checked > 100);
    // "axis 2 of 4" centred as Dear ImGui writes it has the grab under its middle.
    const SliderGrabSpan middle = SliderGrab(frame.Min.x, frame.Max.x, 0.5f, 5, least);
    const float centred = 0.5f * (frame.Min.x + frame.Max.x - 80.0f);
    CHECK((centred < middle.max && middle.min < centred + 80.0f));
    const float beside = SliderTextX(frame.Min.x, frame.Max.x, middle, 80.0f);
    CHECK_FALSE((beside < middle.max && middle.min < beside + 80.0f));
}

TEST_CASE("No label of the canvas's figure lies on a vertex handle of the selected body", "[app]")
{
    // Each polygon of each lesson scene selected in turn: the canvas draws a square of 8 pixels (and its stroke) on
    // each vertex, computed here from the body as the user sees it; at the first step and at the verdict, no label
    // the painter places among the shapes may lie on one (the number line's and the caption's bands have fixed
    // places, drawn over the shapes).
    const fs::path scenes = fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes";
    int selections = 0, labels = 0;
    for (const auto& entry : fs::directory_iterator(scenes))
    {
        if (entry.path().extension() != ".json")
        {
            continue;
        }
        Harness h(entry.path().string());
        h.AwaitStudy();
        if (!h.View().Setup().Ok())
        {
            continue;
        }
        const std::vector<Body>& bodies = h.app->ShownScene().bodies;
        for (int selected = 0; selected < static_cast<int>(bodies.size()); ++selected)
        {
            const Body& body = bodies[static_cast<size_t>(selected)];
            if (body.shape.type != ShapeType::Polygon || body.IsConcave())
            {
                continue;
            }
            h.app->Select(selected);
            h.Frames(1);
            ++selections;
            const View& camera = h.View().Camera();
            std::vector<ScreenPoint> corners;
            for (const Vec2& v : body.shape.polygon.Vertices())
            {
                corners.push_back(ToScreen(camera, TransformPoint(body.Xf(), v)));
            }
            Figure figure = CanvasFigure(*h.app);
            for (const int step : {0, h.View().VerdictStep()})
            {
                figure.step = step;
                RecordingCanvas canvas;
                PaintFigure(canvas, h.View().Studied(), h.View().Setup().study, figure);
                for (const DrawCommand& c : canvas.commands)
                {
                    if (c.kind != DrawCommand::Kind::Text || c.group != "labels")
                    {
                        continue;
                    }
                    ++labels;
                    const ScreenPoint size = canvas.MeasureText(c.text, c.style);
                    for (const ScreenPoint& corner : corners)
                    {
                        const float reach = 4.75f; // half the square and half its stroke
                        const bool covered = c.points[0].x < corner.x + reach && corner.x - reach < c.points[0].x + size.x &&
                                             c.points[0].y < corner.y + reach && corner.y - reach < c.points[0].y + size.y;
                        INFO(entry.path().filename().string() << ", body " << selected << ", step " << step << ": \""
                                                             << c.text << "\" at " << c.points[0].x << ","
                                                             << c.points[0].y << " on the vertex at " << corner.x
                                                             << "," << corner.y);
                        CHECK_FALSE(covered);
                    }
                }
            }
        }
    }
    CHECK(selections > 100);
    CHECK(labels > 1000);
}

TEST_CASE("A slice opens with its body and cut filling the before panel below the caption, whatever its length", "[app]")
{
    // The panel is read from what the canvas draws: the left half of the image, below the caption band's rule and
    // the panel's subtitle. Every point of the body and the cut lies in it, centred, and they fill half of it along
    // one direction at least.
    // On a narrow window the caption wraps to more lines and its band grows.
    for (const std::string scene : {"l19_bar_cut.json", "slice_u.json", "slice_stops_inside.json"})
    for (const float windowWidth : {1280.0f, 960.0f, 800.0f})
    {
        INFO(scene << " in a window " << windowWidth << " wide");
        Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/" + scene);
        ImGui::GetIO().DisplaySize = ImVec2(windowWidth, 800.0f);
        h.Frames(2);
        h.app->Open(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/" + scene);
        h.Frames(2);
        REQUIRE(h.View().CurrentFigure().kind == FigureKind::Slice);
        RecordingCanvas canvas;
        const Figure figure = CanvasFigure(*h.app);
        PaintFigure(canvas, h.View().Studied(), h.View().Setup().study, figure);
        float captionBottom = 0.0f, subtitleBottom = 0.0f;
        for (const DrawCommand& c : canvas.commands)
        {
            if (c.group == "caption" && c.kind == DrawCommand::Kind::FillRect)
            {
                captionBottom = std::max(captionBottom, c.points[1].y);
            }
            if (c.group == "before" && c.kind == DrawCommand::Kind::Text)
            {
                subtitleBottom = std::max(subtitleBottom, c.points[0].y + canvas.MeasureText(c.text, c.style).y);
            }
        }
        REQUIRE(captionBottom > 0.0f);
        REQUIRE(subtitleBottom > captionBottom);
        const Scene& studied = h.View().Studied();
        const Body& body = studied.bodies[static_cast<size_t>(figure.body)];
        std::vector<Vec2> points{studied.view.cut[0], studied.view.cut[1]};
        for (const Vec2& v : body.outline.empty() ? std::vector<Vec2>(body.shape.polygon.Vertices().begin(),
                                                                      body.shape.polygon.Vertices().end())
                                                  : body.outline)
        {
            points.push_back(TransformPoint(body.Xf(), v));
        }
        float minX = 1e9f, minY = 1e9f, maxX = -1e9f, maxY = -1e9f;
        for (const Vec2& p : points)
        {
            const ScreenPoint s = ToScreen(figure.view, p);
            minX = std::min(minX, s.x);
            minY = std::min(minY, s.y);
            maxX = std::max(maxX, s.x);
            maxY = std::max(maxY, s.y);
        }
        const float panelWidth = 0.5f * static_cast<float>(figure.view.width);
        const float panelHeight = static_cast<float>(figure.view.height) - subtitleBottom;
        CHECK(minX > 0.0f);
        CHECK(maxX < panelWidth);
        CHECK(minY > subtitleBottom);
        CHECK(maxY < static_cast<float>(figure.view.height));
        CHECK(std::max((maxX - minX) / panelWidth, (maxY - minY) / panelHeight) > 0.5f);
        // Centred in the panel (whose top is a few pixels below the subtitle).
        CHECK(std::fabs(0.5f * (minX + maxX) - 0.5f * panelWidth) < 4.0f);
        CHECK(std::fabs(0.5f * (minY + maxY) - 0.5f * (subtitleBottom + static_cast<float>(figure.view.height))) < 4.0f);
    }
}

TEST_CASE("In the disc-cast, slice and decomposition figures a dragged body is drawn where the pointer put it", "[app]")
{
    // The canvas maps the pointer to the world by its camera: each corner of the dragged polygon must be drawn at the
    // camera's image of that corner, not where a figure framing its bodies anew would put it (the decomposition
    // figure drew its outline framed in both panels, so that a drag moved the handles and not the shape).
    for (const auto& [scene, name] : {std::pair<std::string, std::string>{"disc_cast_corner.json", "wall"},
                                      std::pair<std::string, std::string>{"l19_bar_cut.json", "bar"},
                                      std::pair<std::string, std::string>{"l18_decompose.json", "flag"}})
    {
        INFO(scene);
        Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/" + scene);
        const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed(name)));
        h.Drag(from, ImVec2(from.x + 60.0f, from.y + 30.0f));
        const Body& body = h.BodyNamed(name);
        RecordingCanvas canvas;
        PaintFigure(canvas, h.View().Studied(), h.View().Setup().study, CanvasFigure(*h.app));
        for (const Vec2& v : body.shape.polygon.Vertices())
        {
            const ScreenPoint want = ToScreen(h.View().Camera(), TransformPoint(body.Xf(), v));
            bool drawn = false;
            for (const DrawCommand& c : canvas.commands)
            {
                for (const ScreenPoint& p : c.points)
                {
                    drawn = drawn || (c.kind != DrawCommand::Kind::Text && std::hypot(p.x - want.x, p.y - want.y) < 0.5f);
                }
            }
            INFO("corner at " << want.x << "," << want.y);
            CHECK(drawn);
        }
    }
}

TEST_CASE("Lesson Markdown is parsed with md4c into headings, text, items, code, figures and table rows",
          "[app][lessons]")
{
    const std::vector<LessonBlock> blocks = ParseLesson(R"(# 3. The overlap test

Some *running* text with a [link](x.md) and a check mark: <!--check scene /pairs/0/depth-->0.18.

- first item
- second item
  - nested

![Axis 1: a gap](figures/box_above_floor-step1.png)

```sh
satviz tutorials/scenes/x.json
```

| a | b |
| --- | --- |
| 1 | 2 |

---
)");
    REQUIRE(blocks.size() >= 8);
    CHECK(blocks[0].kind == LessonBlock::Kind::Heading);
    CHECK(blocks[0].level == 1);
    CHECK(blocks[0].text == "3. The overlap test");
    CHECK(blocks[1].kind == LessonBlock::Kind::Paragraph);
    CHECK(blocks[1].text == "Some running text with a link and a check mark: 0.18.");
    CHECK(blocks[2].kind == LessonBlock::Kind::Item);
    CHECK(blocks[2].text == "first item");
    CHECK(blocks[2].number == 0);
    CHECK(blocks[4].text == "nested");
    CHECK(blocks[4].level == 2);
    CHECK(blocks[5].kind == LessonBlock::Kind::Figure);
    CHECK(blocks[5].text == "Axis 1: a gap");
    CHECK(blocks[5].target == "figures/box_above_floor-step1.png");
    CHECK(blocks[6].kind == LessonBlock::Kind::Code);
    CHECK(blocks[6].text.find("satviz tutorials/scenes/x.json") == 0);
    CHECK(blocks[7].text == "a | b");
    CHECK(blocks[8].text == "1 | 2");
    // A table's rows keep their cells apart, for the panel to show each under its row's first cell.
    CHECK(blocks[7].cells == std::vector<std::string>{"a", "b"});
    CHECK(blocks[7].header);
    CHECK(blocks[8].cells == std::vector<std::string>{"1", "2"});
    CHECK(!blocks[8].header);
    CHECK(blocks[6].cells.empty());
    CHECK(blocks.back().kind == LessonBlock::Kind::Rule);
    // A numbered list keeps its numbers, from its start, and a list nested in it its bullets.
    const std::vector<LessonBlock> numbered = ParseLesson("3. third\n4. fourth\n   - under it\n5. fifth\n");
    REQUIRE(numbered.size() == 4);
    CHECK(numbered[0].number == 3);
    CHECK(numbered[1].number == 4);
    CHECK(numbered[2].number == 0);
    CHECK(numbered[2].level == 2);
    CHECK(numbered[3].number == 5);
    // Signs beyond the fonts' Latin-1 are written as plain text writes them.
    CHECK(ParseLesson("t = (minA \u2212 maxB) / s \u2264 1 \u2248 2")[0].text == "t = (minA - maxB) / s <= 1 ~ 2");
}

TEST_CASE("A lesson's block quotes are marked, and its <details> sections carry their summary", "[app][lessons]")
{
    const std::vector<LessonBlock> blocks = ParseLesson(R"(Before.

> **In satviz.** The queries run in A's frame
> on every step.
>
> - one item

Between.

<details><summary>Answers</summary>

1. The first answer.
2. The second answer.

> A quoted answer.

</details>

After.
)");
    REQUIRE(blocks.size() == 8);
    CHECK(blocks[0].text == "Before.");
    CHECK(!blocks[0].quote);
    CHECK(blocks[1].text == "In satviz. The queries run in A's frame on every step.");
    CHECK(blocks[1].quote);
    CHECK(blocks[2].kind == LessonBlock::Kind::Item);
    CHECK(blocks[2].quote);
    CHECK(blocks[3].text == "Between.");
    CHECK(!blocks[3].quote);
    CHECK(blocks[3].details == 0);
    // The summary is the section's title, not a paragraph of its own.
    CHECK(blocks[4].text == "The first answer.");
    CHECK(blocks[4].number == 1);
    CHECK(blocks[5].number == 2);
    CHECK(blocks[4].details == 1);
    CHECK(blocks[4].summary == "Answers");
    CHECK(blocks[5].details == 1);
    CHECK(blocks[6].text == "A quoted answer.");
    CHECK(blocks[6].quote);
    CHECK(blocks[6].details == 1);
    CHECK(blocks[7].text == "After.");
    CHECK(blocks[7].details == 0);
    CHECK(blocks[7].summary.empty());

    // Every lesson's answers are in a section of their own, and no summary is left as text.
    for (const Lesson& lesson : FindLessons(std::string(SATVIZ_SOURCE_DIR) + "/tutorials"))
    {
        INFO(lesson.file);
        std::vector<LessonBlock> parsed;
        std::string error;
        REQUIRE(LoadLesson(lesson.file, parsed, error));
        bool answers = false;
        for (const LessonBlock& block : parsed)
        {
            CHECK(block.text != "Answers");
            answers = answers || (block.details > 0 && block.summary == "Answers");
        }
        CHECK(answers);
    }
}

TEST_CASE("Every lesson has a button for each scene it shows or names and opens on its first figure's scene",
          "[app][lessons]")
{
    // The scene files on disk, by name, in scenes/ and its folders (scenes/concave/); a figure "NAME-stepN.png" or
    // "NAME.png" is drawn from NAME.json.
    const fs::path tutorials = fs::path(SATVIZ_SOURCE_DIR) / "tutorials";
    std::map<std::string, std::string> onDisk;
    for (const auto& entry : fs::recursive_directory_iterator(tutorials / "scenes"))
    {
        if (entry.path().extension() == ".json")
        {
            onDisk.emplace(entry.path().stem().string(), fs::weakly_canonical(entry.path()).string());
        }
    }
    const std::vector<Lesson> lessons = FindLessons(tutorials.string());
    REQUIRE(lessons.size() >= 19);
    for (const Lesson& lesson : lessons)
    {
        INFO(lesson.file);
        std::vector<std::string> buttons;
        for (const std::string& scene : lesson.scenes)
        {
            INFO(scene);
            REQUIRE(fs::is_regular_file(scene));
            buttons.push_back(fs::weakly_canonical(scene).string());
        }
        const auto has = [&](const std::string& file) {
            return std::find(buttons.begin(), buttons.end(), file) != buttons.end();
        };
        std::ifstream in(lesson.file);
        std::stringstream read;
        read << in.rdbuf();
        const std::string text = read.str();
        static const std::regex figure(R"(\]\(([^) ]*figures/[^) ]+\.png)\))");
        static const std::regex step(R"(-step[0-9]+$)");
        std::string first;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), figure); it != std::sregex_iterator(); ++it)
        {
            const std::string name = std::regex_replace(fs::path((*it)[1].str()).stem().string(), step, "");
            const auto found = onDisk.find(name);
            if (found == onDisk.end())
            {
                continue;
            }
            INFO("figure " << (*it)[1].str());
            first = first.empty() ? found->second : first;
            CHECK(has(found->second));
            // The figure's own "show" button.
            CHECK(fs::weakly_canonical(FigureSceneFile(tutorials.string(), (*it)[1].str())).string() == found->second);
        }
        static const std::regex named(R"(scenes/([A-Za-z0-9_/]+)\.json)");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), named); it != std::sregex_iterator(); ++it)
        {
            INFO("named " << (*it)[0].str());
            CHECK(has(fs::weakly_canonical(tutorials / (*it)[0].str()).string()));
        }
        REQUIRE(!buttons.empty());
        CHECK(buttons.front() == (first.empty() ? buttons.front() : first));
    }
}

TEST_CASE("Opening a lesson shows the step of the figure its text starts with, and so does a figure's button",
          "[app][lessons]")
{
    // Lesson 1 speaks of Axis 1 beside its first figure (l01_triangle_and_ball-step1.png): the canvas shows that
    // step, not the verdict. A figure without "-stepN" is drawn at the step its scene's view asks for.
    const fs::path tutorials = fs::path(SATVIZ_SOURCE_DIR) / "tutorials";
    Harness h((tutorials / "scenes" / "overlapping_boxes.json").string());
    const std::vector<Lesson>& lessons = h.app->Lessons();
    REQUIRE(lessons.size() >= 19);
    int stepped = 0;
    for (size_t i = 0; i < lessons.size(); ++i)
    {
        INFO(lessons[i].file);
        std::ifstream in(lessons[i].file);
        std::stringstream read;
        read << in.rdbuf();
        const std::string text = read.str();
        // The first figure whose scene is on disk, read from the Markdown here.
        static const std::regex figure(R"(\]\(([^) ]*figures/[^) ]+\.png)\))");
        std::string target;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), figure); it != std::sregex_iterator(); ++it)
        {
            if (!FigureSceneFile(tutorials.string(), (*it)[1].str()).empty())
            {
                target = (*it)[1].str();
                break;
            }
        }
        if (target.empty())
        {
            continue;
        }
        INFO(target);
        REQUIRE(h.app->OpenLesson(static_cast<int>(i)));
        h.Frames(2);
        REQUIRE(h.AwaitStudy());
        h.Frames(2);
        REQUIRE(h.View().Setup().Ok());
        const std::string stem = fs::path(target).stem().string();
        const size_t dash = stem.rfind("-step");
        int expected = -1;
        if (dash != std::string::npos)
        {
            expected = std::stoi(stem.substr(dash + 5)) - 1;
            ++stepped;
        }
        else
        {
            const FigureSetup own = SetUpFigure(h.Doc().GetScene(), {});
            REQUIRE(own.Ok());
            expected = own.figure.step;
        }
        CHECK((h.View().Choices().steps == StepView::Faces) == (target.find("figures/faces/") != std::string::npos));
        CHECK(h.View().Step() == expected);
        CHECK(h.View().Setup().figure.step == expected);
    }
    CHECK(stepped >= 5);
    // A lesson whose scene is open already: the app starts on overlapping_boxes, lesson 4's first figure is its
    // step 1 (overlapping_boxes-step1.png), which the canvas shows rather than the verdict it was on.
    {
        Harness fresh((tutorials / "scenes" / "overlapping_boxes.json").string());
        REQUIRE(fresh.AwaitStudy());
        fresh.Frames(2);
        REQUIRE(fresh.View().Step() != 0);
        const int lesson4 = 3;
        REQUIRE(fresh.app->OpenLesson(lesson4));
        fresh.Frames(2);
        REQUIRE(fresh.app->Lessons()[lesson4].firstStep == 0);
        CHECK(fresh.View().Step() == 0);
        CHECK(fresh.View().Setup().figure.step == 0);
    }
    // The figure's own button: lesson 4's face test 6 is the sixth step of the face view.
    REQUIRE(h.app->RequestOpen((tutorials / "scenes" / "overlapping_boxes.json").string(),
                               FigureStep("figures/faces/overlapping_boxes-step6.png"),
                               FigureOfFaces("figures/faces/overlapping_boxes-step6.png")));
    REQUIRE(h.AwaitStudy());
    h.Frames(2);
    CHECK(h.View().Choices().steps == StepView::Faces);
    CHECK(h.View().Step() == 5);
    CHECK_FALSE(h.Doc().Dirty());
}

TEST_CASE("A contact row too long for its list wraps between words, every word shown", "[app]")
{
    // Cut with "..." the rows hid what ended them: "slope and box: 2 points, overlap 0.000946 and ..." (l15_slope
    // after step 96), "floor and crate 4: 2 points, overlap 0.00 and ..." (l17_skips). The list's rows are read from
    // the child window ImGui lays out: nothing runs past its inner edge, and its rows take the lines the whole texts
    // need, wrapped between words to that width.
    for (const auto& [scene, steps] : {std::pair{"l15_slope.json", 96}, std::pair{"l17_skips.json", 150}})
    {
        INFO(scene);
        Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + scene);
        for (int i = 0; i < steps; ++i)
        {
            h.app->SimForward();
        }
        h.Frames(3);
        const Simulation& sim = h.app->GetSimulation();
        const WorldWords world = DescribeWorld(h.app->ShownScene(), sim.Record());
        REQUIRE(!world.contacts.empty());
        ImGuiWindow* list = nullptr;
        for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
        {
            if (w->Active && std::string(w->Name).find("##contacts") != std::string::npos)
            {
                list = w;
            }
        }
        REQUIRE(list != nullptr);
        const float inner = list->ContentRegionRect.GetWidth();
        ImGui::NewFrame();
        float needed = 0.0f;
        int wrapped = 0;
        for (const WorldContactWords& c : world.contacts)
        {
            const std::vector<std::string> lines =
                WrapLines(c.text, inner, [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; });
            needed += static_cast<float>(lines.size()) * ImGui::GetTextLineHeight();
            wrapped += lines.size() > 1 ? 1 : 0;
        }
        ImGui::EndFrame();
        CHECK(wrapped > 0); // the case at hand: a row longer than the list is wide
        CHECK(list->ContentSize.x <= inner + 0.5f);
        CHECK(list->ContentSize.y >= needed - 0.5f);
    }
}

TEST_CASE("Help > Lessons lists the lessons, and opening one shows its text and loads its scene", "[app][lessons]")
{
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    const std::vector<Lesson>& lessons = h.app->Lessons();
    REQUIRE(lessons.size() >= 12);
    CHECK(lessons[0].title.find("1.") == 0);
    for (size_t i = 0; i < lessons.size(); ++i)
    {
        INFO(lessons[i].file);
        CHECK(fs::path(lessons[i].file).filename().string().substr(0, 2) ==
              (i + 1 < 10 ? "0" : "") + std::to_string(i + 1));
    }
    REQUIRE(h.app->OpenLesson(2));
    h.Frames(3);
    CHECK(h.app->CurrentLesson() == 2);
    CHECK(h.app->LessonShown());
    REQUIRE(!h.app->LessonBlocks().empty());
    CHECK(h.app->LessonBlocks()[0].text == lessons[2].title);
    REQUIRE(!lessons[2].scenes.empty());
    CHECK(fs::equivalent(h.Doc().File(), lessons[2].scenes.front()));
    CHECK(h.View().Setup().Ok());
    REQUIRE(h.app->OpenLesson(3));
    h.Frames(3);
    CHECK(h.app->CurrentLesson() == 3);
    CHECK(fs::equivalent(h.Doc().File(), lessons[3].scenes.front()));
    CHECK_FALSE(h.app->OpenLesson(static_cast<int>(lessons.size())));
    CHECK(h.app->CurrentLesson() == 3);
}

TEST_CASE("Opening a lesson with unsaved changes shows it and asks before its scene replaces them", "[app][lessons]")
{
    // The lesson window appears in the frame that opens the question: Dear ImGui 1.86 ends the program on an
    // assertion when a window appears after a modal popup begun in the same frame.
    const fs::path copy = ScratchCopy("overlapping_boxes.json");
    Harness h(copy.string());
    const ImVec2 from = h.OnScreen(Centroid(h.BodyNamed("B")));
    h.Drag(from, ImVec2(from.x + 30.0f, from.y));
    REQUIRE(h.Doc().Dirty());
    REQUIRE(!h.app->LessonShown());
    const Vec2 moved = h.BodyNamed("B").position;
    REQUIRE(h.app->OpenLesson(0));
    h.Frames(3);
    CHECK(h.app->LessonShown());
    CHECK(Harness::Showing("Lesson###lesson"));
    CHECK(Harness::Showing("Unsaved changes before opening"));
    CHECK(h.Doc().File() == copy.string());
    REQUIRE(h.ClickButton("Unsaved changes before opening", "Cancel"));
    CHECK(h.Doc().Dirty());
    CHECK(h.BodyNamed("B").position == moved);
    // The scene still open is shown whole on the canvas left beside the lesson, narrower than the one it was dragged
    // on: every corner of both boxes lies inside it.
    h.Frames(2);
    REQUIRE(h.View().CanvasWidth() < 900);
    for (const Body& body : h.Doc().GetScene().bodies)
    {
        for (const Vec2& v : body.shape.polygon.Vertices())
        {
            const ScreenPoint p = ToScreen(h.View().Camera(), TransformPoint(body.Xf(), v));
            INFO(body.name << " corner at " << p.x << "," << p.y << " on a canvas of " << h.View().CanvasWidth() << "x"
                           << h.View().CanvasHeight());
            CHECK(p.x >= 0.0f);
            CHECK(p.x <= static_cast<float>(h.View().CanvasWidth()));
            CHECK(p.y >= 0.0f);
            CHECK(p.y <= static_cast<float>(h.View().CanvasHeight()));
        }
    }
    // F1 and a lesson in the same frame as the question: the help window appears after it too.
    h.app->CloseLesson();
    h.Frames(2);
    REQUIRE(!Harness::Showing("Lesson###lesson"));
    REQUIRE(h.app->OpenLesson(1));
    h.Key(h.app->Options().keys.f1);
    CHECK(Harness::Showing("Unsaved changes before opening"));
    CHECK(Harness::Showing("Lesson###lesson"));
    CHECK(Harness::Showing("Help (F1 or Esc closes)"));
}

TEST_CASE("F1 names every key the app answers to, the simulation's among them", "[app]")
{
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l14_head_on.json");
    h.Key(h.app->Options().keys.f1);
    REQUIRE(Harness::Showing("Help (F1 or Esc closes)"));
    std::string shown;
    for (const HelpSection& section : HelpSections())
    {
        for (const char* line : section.lines)
        {
            shown += std::string(line) + "\n";
        }
    }
    // One name for each key of AppKeys (and the step keys and undo), written as the help writes keys.
    for (const char* key : {"ctrl+s", "ctrl+o", "ctrl+e", "ctrl+q", "f: ", "F1", "p: ", ", (comma)", ". (period)",
                            "d, then", "x, then", "left / right", "space", "ctrl+z", "del"})
    {
        INFO(key);
        CHECK(shown.find(key) != std::string::npos);
    }
}

TEST_CASE("F1 says a scene without a world block is not stepped, and what its figures call a step", "[app]")
{
    // F1 said "without a world block a step lasts dt = 1", of scenes the simulation does not step: what such a scene
    // has is the swept test's span, t from 0 to 1, which its sentences call a step ("moves 1.588 per step").
    std::string line;
    for (const HelpSection& section : HelpSections())
    {
        for (const char* l : section.lines)
        {
            if (std::string(l).find("without a world block") != std::string::npos)
            {
                line = l;
            }
        }
    }
    INFO(line);
    REQUIRE(!line.empty());
    CHECK(line.find("is not stepped") != std::string::npos);
    CHECK(line.find("lasts dt = 1") == std::string::npos);
    CHECK(line.find("t from 0 to 1") != std::string::npos);
    CHECK(line.find("\"per step\"") != std::string::npos);
    // As the app says when p is pressed on such a scene, and as the sweep's sentences word it.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/circle_and_polygon.json");
    REQUIRE(!h.app->ShownScene().hasWorld);
    h.app->SimPlay(true);
    CHECK(h.app->Status().find("so it is not stepped") != std::string::npos);
    const PairStudy& study = h.View().Setup().study;
    REQUIRE(study.sweep);
    CHECK(DescribeStep(h.View().Studied(), study, 0).find(" per step ") != std::string::npos);
}

TEST_CASE("A scene that frames itself keeps its framing, scaled to the canvas left beside a lesson", "[app][lessons]")
{
    // The lessons' scenes frame their figures for 800 x 600 pixels; beside the lesson column and the side panel the
    // canvas is narrower. Every point of the pair that the scene's own figure shows in its scene area must show in
    // the canvas's scene area, and the figure's scene area must fill the canvas's in width or in height.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    REQUIRE(h.app->OpenLesson(16));
    h.Frames(3);
    REQUIRE(h.app->LessonShown());
    int framed = 0;
    for (const std::string& file : h.app->BundledScenes())
    {
        INFO(file);
        REQUIRE(h.app->RequestOpen(file));
        h.Frames(3);
        const Scene& scene = h.Doc().GetScene();
        if (scene.view.fit)
        {
            continue;
        }
        ++framed;
        const Viewer& viewer = h.View();
        REQUIRE(viewer.Setup().Ok());
        CHECK(viewer.CameraFramed());
        CHECK(viewer.CanvasWidth() < scene.view.width);
        const bool titled = !scene.view.caption.empty();
        const PairStudy& study = viewer.Setup().study;
        const LayerMask layers = viewer.Choices().layers;
        // The scene's own figure, as satviz-render draws it at the scene's size.
        FigureOptions own;
        own.setLayers = true;
        own.layers = layers;
        const FigureSetup ownFigure = SetUpFigure(scene, own);
        REQUIRE(ownFigure.Ok());
        const View authored = ownFigure.figure.view;
        REQUIRE(authored.width == scene.view.width);
        const FigureLayout from = LayoutFigure(study, layers, authored.width, authored.height, titled);
        const FigureLayout to = LayoutFigure(study, layers, viewer.CanvasWidth(), viewer.CanvasHeight(), titled);
        const View& camera = viewer.Camera();
        std::vector<Vec2> points;
        for (const int index : {study.bodyA, study.bodyB})
        {
            const Body& body = scene.bodies[static_cast<size_t>(index)];
            if (body.shape.type == ShapeType::Polygon)
            {
                for (const Vec2& v : body.shape.polygon.Vertices())
                {
                    points.push_back(TransformPoint(body.Xf(), v));
                }
            }
            else
            {
                const Vec2 c = TransformPoint(body.Xf(), body.shape.circle.center);
                const double r = body.shape.circle.radius;
                for (const Vec2 d : {Vec2{r, 0.0}, Vec2{-r, 0.0}, Vec2{0.0, r}, Vec2{0.0, -r}})
                {
                    points.push_back(c + d);
                }
            }
        }
        for (const Vec2& p : points)
        {
            const ScreenPoint before = ToScreen(authored, p);
            if (before.x < 0.0f || before.x > static_cast<float>(authored.width) || before.y < from.sceneTop ||
                before.y > from.sceneBottom)
            {
                continue; // not in the scene's own figure either
            }
            const ScreenPoint now = ToScreen(camera, p);
            INFO("(" << p.x << ", " << p.y << ") at " << now.x << ", " << now.y);
            CHECK(now.x >= -0.5f);
            CHECK(now.x <= static_cast<float>(viewer.CanvasWidth()) + 0.5f);
            CHECK(now.y >= to.sceneTop - 0.5f);
            CHECK(now.y <= to.sceneBottom + 0.5f);
        }
        // The corners of the figure's scene area, on the canvas: inside it, and as wide or as high as it.
        const ScreenPoint low = ToScreen(camera, ToWorld(authored, {0.0f, from.sceneBottom}));
        const ScreenPoint high =
            ToScreen(camera, ToWorld(authored, {static_cast<float>(authored.width), from.sceneTop}));
        CHECK(low.x >= -0.5f);
        CHECK(high.x <= static_cast<float>(viewer.CanvasWidth()) + 0.5f);
        CHECK(high.y >= to.sceneTop - 0.5f);
        CHECK(low.y <= to.sceneBottom + 0.5f);
        const bool fillsWidth = high.x - low.x >= static_cast<float>(viewer.CanvasWidth()) - 1.0f;
        const bool fillsHeight = low.y - high.y >= to.sceneBottom - to.sceneTop - 1.0f;
        CHECK((fillsWidth || fillsHeight));
    }
    CHECK(framed >= 20);

    // l17_skips: the tested wall, at the far right of the scene's figure, is on the canvas.
    REQUIRE(h.app->RequestOpen(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l17_skips.json"));
    h.Frames(3);
    const double narrow = h.View().Camera().zoom;
    const Body& wall = h.BodyNamed("right wall");
    for (const Vec2& v : wall.shape.polygon.Vertices())
    {
        const ScreenPoint p = ToScreen(h.View().Camera(), TransformPoint(wall.Xf(), v));
        CHECK(p.x >= 0.0f);
        CHECK(p.x <= static_cast<float>(h.View().CanvasWidth()));
    }
    // Closing the lesson widens the canvas, and the framing grows with it; a drag of the view takes it over.
    h.app->CloseLesson();
    h.Frames(3);
    CHECK(h.View().Camera().zoom > narrow);
    CHECK(h.View().CameraFramed());
    // Lesson 17's own first scene, open when the lesson opens again: the lesson keeps the view the student set, its
    // centre and all it showed, scaled to the narrower canvas.
    REQUIRE(h.app->RequestOpen(h.app->Lessons()[16].scenes.front()));
    h.Frames(3);
    const ImVec2 empty(h.CanvasOrigin().x + 20.0f, h.CanvasOrigin().y + 300.0f);
    h.Drag(empty, ImVec2(empty.x + 40.0f, empty.y));
    CHECK(!h.View().CameraFramed());
    const View held = h.View().Camera();
    REQUIRE(h.app->OpenLesson(16));
    h.Frames(3);
    const View narrowed = h.View().Camera();
    REQUIRE(narrowed.width < held.width);
    CHECK(narrowed.center == held.center);
    CHECK(narrowed.width / narrowed.zoom >= held.width / held.zoom * (1.0 - 1e-12));
    CHECK(narrowed.height / narrowed.zoom >= held.height / held.zoom * (1.0 - 1e-12));
    // Closed again, the canvas shows the view as the student left it.
    h.app->CloseLesson();
    h.Frames(3);
    CHECK(h.View().Camera().center == held.center);
    CHECK(h.View().Camera().zoom == Approx(held.zoom).epsilon(1e-12));
}

TEST_CASE("The Numbers panel gives the deciding axis as the figure and the lessons do, the normal as satviz-query",
          "[app]")
{
    // Lesson 3's table gives l03_corner_gap's axis 4 as (-0.80, -0.60), the outward normal of B's face e3, as the
    // figure draws it and satviz-query's trace lists it; satviz-query's "normal" is the same line from A to B,
    // (0.80, 0.60). The panel gives both, each under its own name, with at least the lessons' two decimals.
    for (const StepView view : {StepView::Textbook, StepView::Faces})
    {
        const std::string file = std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l03_corner_gap.json";
        SceneResult loaded = LoadScene(file);
        REQUIRE(loaded.Ok());
        const PairStudy study = StudyPair(loaded.scene, 0, 1, ViewQuery::Collide, false, view);
        const nlohmann::ordered_json answer = QuerySceneJson(loaded.scene, file, true, view);
        const nlohmann::ordered_json& pair = answer["pairs"][0];
        const std::vector<NumberRow> rows = StaticTestNumbers(loaded.scene, study);
        auto row = [&](const std::string& start) -> const NumberRow* {
            for (const NumberRow& r : rows)
            {
                if (r.label.rfind(start, 0) == 0)
                {
                    return &r;
                }
            }
            return nullptr;
        };
        // The axis that ended the test: the last one the trace lists.
        const nlohmann::ordered_json& axes = pair["trace"]["axes"];
        const size_t last = axes.size() - 1;
        const std::string which = view == StepView::Textbook ? "deciding axis " : "deciding face test ";
        const NumberRow* axis = row(which + std::to_string(last + 1) + ", the normal of B's edge 3");
        INFO(which);
        REQUIRE(axis != nullptr);
        REQUIRE(axis->parts.size() == 2);
        CHECK(axis->parts[0] == FormatNumber(axes[last]["direction"][0].get<double>()));
        CHECK(axis->parts[1] == FormatNumber(axes[last]["direction"][1].get<double>()));
        CHECK(axis->parts[0] == "-0.80");
        CHECK(axis->parts[1] == "-0.60");
        const NumberRow* normal = row("normal (A to B)");
        REQUIRE(normal != nullptr);
        CHECK(normal->parts[0] == FormatNumber(pair["normal"][0].get<double>()));
        CHECK(normal->parts[1] == FormatNumber(pair["normal"][1].get<double>()));
        CHECK(normal->parts[0] == "0.80");
        CHECK(normal->parts[1] == "0.60");
        // With "all digits", each number reads back as the double satviz-query gives.
        for (const NumberRow& r : StaticTestNumbers(loaded.scene, study, true))
        {
            if (r.label.rfind(which, 0) == 0)
            {
                CHECK(std::stod(r.parts[0]) == axes[last]["direction"][0].get<double>());
                CHECK(std::stod(r.parts[1]) == axes[last]["direction"][1].get<double>());
            }
            if (r.label == "gap on the separating axis" && view == StepView::Faces) // the query's gap is Collide's
            {
                CHECK(std::stod(r.parts[0]) == pair["gap"].get<double>());
            }
        }
    }
    CHECK(FullDecimal(0.20000000000000018) == "0.20000000000000018");
    CHECK(FullDecimal(0.4825f) == "0.4825");
    for (const double x : {0.1, -2.55, 123.0, 1e-7, 3e21, 0.30000000000000004})
    {
        CHECK(std::strtod(FullDecimal(x).c_str(), nullptr) == x);
    }
}

namespace
{

// Whether a number is printed as the sentences print them: at most three decimals, or three significant digits in
// an exponent form or below 0.01 (never a double in full, 0.44999999999999996), but for FormatPair's padding.
bool PrintedAsSentences(const std::string& text)
{
    const size_t e = text.find('e');
    std::string mantissa = text.substr(0, e);
    // FormatPair pads a coordinate with zeros to its partner's decimals: (0.99100, 0.00123).
    while (mantissa.find('.') != std::string::npos && mantissa.size() > mantissa.find('.') + 4 && mantissa.back() == '0')
    {
        mantissa.pop_back();
    }
    const size_t point = mantissa.find('.');
    const size_t decimals = point == std::string::npos ? 0 : mantissa.size() - point - 1;
    const size_t digits = mantissa.find_first_of("123456789");
    const size_t significant = digits == std::string::npos ? 0 : mantissa.size() - digits - (digits < point ? 1 : 0);
    return decimals <= 3 || significant <= 3;
}

} // namespace

TEST_CASE("The Numbers panel prints every number as the step's sentences do, the verdict's depth or gap as it",
          "[app]")
{
    // A student reads "gap 0.45" in the verdict and the same gap in the panel: both from one formatting, the
    // verdict's amount being the difference of the interval ends it shows. Every bundled scene, both views, the
    // static test and, for a moving pair, the static test at the start of its sweep.
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes"))
    {
        if (entry.path().extension() != ".json")
        {
            continue;
        }
        SceneResult loaded = LoadScene(entry.path().string());
        if (!loaded.Ok() || loaded.scene.bodies.size() < 2)
        {
            continue;
        }
        ++scenes;
        for (const StepView view : {StepView::Textbook, StepView::Faces})
        {
            for (const ViewQuery query : {ViewQuery::Collide, ViewQuery::Automatic})
            {
                const PairStudy study = StudyPair(loaded.scene, 0, 1, query, false, view);
                const std::string verdict = DescribeStep(loaded.scene, study, study.VerdictStep());
                INFO(entry.path().filename().string() << ": " << verdict);
                for (const NumberRow& row : StaticTestNumbers(loaded.scene, study))
                {
                    for (const std::string& part : row.parts)
                    {
                        INFO(row.label << ": " << part);
                        if (part.find_first_of("0123456789") != std::string::npos)
                        {
                            CHECK(PrintedAsSentences(part));
                        }
                    }
                    // The static verdict gives the depth or the gap: the panel gives the same digits.
                    const bool amount = row.label == "MTV length (depth)" || row.label == "gap on the separating axis";
                    if (amount && !study.sweep && !study.startsOverlapping && row.parts[0] != FormatNumber(0.0))
                    {
                        CHECK(verdict.find(" " + row.parts[0]) != std::string::npos);
                    }
                    if (row.label == "MTV direction (A to B)" && !study.sweep && !study.startsOverlapping &&
                        verdict.find("direction (") != std::string::npos)
                    {
                        CHECK(verdict.find("direction (" + row.parts[0] + ", " + row.parts[1] + ")") !=
                              std::string::npos);
                    }
                }
            }
        }
    }
    CHECK(scenes > 50);
}

TEST_CASE("An overlap or a gap of round-off size is worded as touching in the verdict, its row and the Numbers panel",
          "[app]")
{
    // l11_decimal_touch's B, 0.2 wide at x = 0.3, has its left face at 0.3 - 0.1, just below the 0.2 of A's right
    // face: the stored numbers overlap by that difference; B moved right by it and once more, they part by it.
    const std::string file = std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l11_decimal_touch.json";
    SceneResult loaded = LoadScene(file);
    REQUIRE(loaded.Ok());
    const double overlap = 0.2 - (0.3 - 0.1);
    REQUIRE(overlap > 0.0);
    REQUIRE(overlap < 1e-16);
    for (const bool apart : {false, true})
    {
        Scene scene = loaded.scene;
        if (apart)
        {
            scene.bodies[1].position.x += 2.0 * overlap + 1e-16;
        }
        for (const StepView view : {StepView::Textbook, StepView::Faces})
        {
            const PairStudy study = StudyPair(scene, 0, 1, ViewQuery::Collide, false, view);
            INFO((apart ? "apart" : "overlapping") << ", " << (view == StepView::Faces ? "face tests" : "textbook"));
            REQUIRE(RoundOffVerdict(study));
            const std::string verdict = DescribeStep(scene, study, study.VerdictStep());
            INFO(verdict);
            CHECK(verdict.find("is round-off in size: the shapes touch") != std::string::npos);
            const std::string title = StepTitle(scene, study, study.VerdictStep());
            CHECK(title.rfind("verdict: touching, round-off ", 0) == 0);
            const std::vector<NumberRow> rows = StaticTestNumbers(scene, study);
            REQUIRE(!rows.empty());
            CHECK(rows[0].parts[0] == (apart ? "no, by round-off: they touch" : "yes, by round-off: they touch"));
        }
    }
    // Far from the origin round-off is larger: the same pair a thousand metres out, overlapping by 1e-10 (the
    // doubles there are about 1e-13 apart), is touching in both views alike, measured against the coordinates.
    {
        Scene scene = loaded.scene;
        const double out = 1000.0;
        scene.bodies[0].position.x += out;
        scene.bodies[1].position.x += out - 1e-10;
        for (const StepView view : {StepView::Textbook, StepView::Faces})
        {
            const PairStudy study = StudyPair(scene, 0, 1, ViewQuery::Collide, false, view);
            INFO((view == StepView::Faces ? "face tests" : "textbook") << ", depth " << study.manifold.depth);
            REQUIRE(study.manifold.overlap);
            REQUIRE(study.manifold.depth > 1e-12);
            CHECK(RoundOffVerdict(study));
            CHECK(StepTitle(scene, study, study.VerdictStep()).rfind("verdict: touching, round-off ", 0) == 0);
        }
    }
    // A true overlap and a true gap are not round-off.
    for (const char* stem : {"overlapping_boxes", "l03_corner_gap", "l14_slide"})
    {
        SceneResult other = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + stem + ".json");
        REQUIRE(other.Ok());
        const PairStudy study = StudyPair(other.scene, 0, 1, ViewQuery::Collide, false, StepView::Textbook);
        CHECK_FALSE(RoundOffVerdict(study));
        CHECK(DescribeStep(other.scene, study, study.VerdictStep()).find("round-off") == std::string::npos);
    }
}

TEST_CASE("A scene's description gives its overlap as the verdict beside it prints it", "[app]")
{
    // l15_slope's box is placed into its slope: the side panel showed "overlaps the slope by 0.001 m" above a
    // verdict "MTV 0.000946".
    SceneResult loaded = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l15_slope.json");
    REQUIRE(loaded.Ok());
    const PairStudy study = StudyPair(loaded.scene, 0, 1, ViewQuery::Collide, false, StepView::Textbook);
    REQUIRE(study.textbookResult.overlap);
    const std::string depth = ShownVerdictAmount(study);
    INFO(loaded.scene.description);
    CHECK(loaded.scene.description.find("overlaps the slope by " + depth + " m") != std::string::npos);
}

TEST_CASE("The Numbers panel says touching shapes touch, as the verdict does, and overlap only when they do",
          "[app]")
{
    // l14_slide's box rests on its floor: in contact at depth 0, which the verdict calls touching without
    // overlapping; the panel read "overlap: yes" beside it.
    for (const StepView view : {StepView::Textbook, StepView::Faces})
    {
        for (const char* stem : {"l14_slide", "overlapping_boxes", "l03_corner_gap"})
        {
            const std::string file = std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + stem + ".json";
            SceneResult loaded = LoadScene(file);
            REQUIRE(loaded.Ok());
            const PairStudy study = StudyPair(loaded.scene, 0, 1, ViewQuery::Collide, false, view);
            const std::vector<NumberRow> rows = StaticTestNumbers(loaded.scene, study);
            REQUIRE(!rows.empty());
            REQUIRE(rows[0].label == "overlap");
            const std::string verdict = DescribeStep(loaded.scene, study, study.VerdictStep());
            INFO(stem << ": " << verdict);
            const bool touch = verdict.find("touch without overlapping") != std::string::npos;
            const bool collide = verdict.find("so the shapes collide") != std::string::npos;
            CHECK(touch == (std::string(stem) == "l14_slide"));
            CHECK(rows[0].parts[0] == (touch ? "no, they touch (in contact)" : collide ? "yes" : "no"));
        }
    }
}

TEST_CASE("Text in the panels wraps between words only: a number is never split, nor a bracketed pair", "[app]")
{
    // Dear ImGui's own wrapping breaks after '.' and ',' too ("direction (0." / "00, 1.00)"). The sentences of every
    // step of the bundled scenes, wrapped at many widths: the lines give every character of the sentence back, in
    // order; each line fits (a word too wide for the line goes on over the next ones); and a pair of numbers
    // (numbers, commas, spaces and signs between brackets) that fits the width closes on the line it opens on.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    ImGui::NewFrame();
    int lines = 0;
    const auto withoutSpaces = [](std::string s) {
        s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\n'; }), s.end());
        return s;
    };
    for (const std::string& file : h.app->BundledScenes())
    {
        const SceneResult loaded = LoadScene(file, SceneOptions{true}); // as the app opens them: concave too
        REQUIRE(loaded.Ok());
        const FigureSetup setup = SetUpFigure(loaded.scene, {});
        REQUIRE(setup.Ok());
        for (int step = 0; step < setup.study.StepCount(); ++step)
        {
            const std::string text = DescribeStep(loaded.scene, setup.study, step);
            for (float width = 60.0f; width <= 420.0f; width += 40.0f)
            {
                const std::string wrapped = WrapToWidth(text, width);
                INFO(file << " step " << step + 1 << " at " << width << " px:\n" << wrapped);
                REQUIRE(withoutSpaces(wrapped) == withoutSpaces(text));
                std::stringstream in(wrapped);
                for (std::string line; std::getline(in, line); ++lines)
                {
                    CHECK(ImGui::CalcTextSize(line.c_str()).x <= width);
                }
                static const std::regex pair(R"([\(\[][-+]?[0-9][0-9., +-]*[\)\]])");
                for (auto it = std::sregex_iterator(text.begin(), text.end(), pair); it != std::sregex_iterator();
                     ++it)
                {
                    if (ImGui::CalcTextSize(it->str().c_str()).x <= width)
                    {
                        CHECK(("\n" + wrapped + "\n").find(it->str()) != std::string::npos);
                    }
                }
            }
        }
    }
    ImGui::EndFrame();
    CHECK(lines > 1000);
    // A code line keeps its indentation on its first line; a newline always ends a line.
    CHECK(WrapToWidth("  satviz-query --trace", 1000.0f) == "  satviz-query --trace");
    CHECK(WrapToWidth("a\n\nb", 1000.0f) == "a\n\nb");
    // A web address wider than the column (the lessons' references) goes on over lines that each fit, broken where
    // an address reads as going on: after a '/' or before a '.', '-' and the like.
    const std::string link = "<https://www.metanetsoftware.com/2016/n-tutorial-a-collision-detection-and-response>";
    for (float width = 160.0f; width <= 400.0f; width += 40.0f)
    {
        const std::string wrapped = WrapToWidth("Read " + link + ".", width);
        INFO(width << " px:\n" << wrapped);
        std::vector<std::string> lines;
        std::stringstream in(wrapped);
        for (std::string line; std::getline(in, line);)
        {
            CHECK(ImGui::CalcTextSize(line.c_str()).x <= width);
            lines.push_back(line);
        }
        REQUIRE(lines.size() >= 2);
        CHECK(lines.front() == "Read");
        std::string joined;
        for (size_t i = 1; i < lines.size(); ++i)
        {
            joined += lines[i];
            if (i + 1 < lines.size())
            {
                const bool natural =
                    lines[i].back() == '/' || std::string(".-?#&=_").find(lines[i + 1].front()) != std::string::npos;
                CHECK(natural);
            }
        }
        CHECK(joined == link + ".");
    }
}

TEST_CASE("The status bar shows the whole of its message at the smallest window: a long one takes more lines",
          "[app]")
{
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    const float bar = ImGui::GetFrameHeight();
    ImGui::GetIO().DisplaySize = MinimumWindowSize(false, bar);
    const std::string file = "/home/student/satviz/my scenes/a rather long folder name/overlapping_boxes_copy.json";
    for (const std::string& message :
         {std::string("Drag a body to move it"), "Saved " + file + " (the view too: camera, pair and step)",
          "Cannot read " + file + ": line 12, field \"bodies\": expected an array of bodies, got a number"})
    {
        h.app->SetStatus(message, true);
        h.Frames(3);
        const ImGuiWindow* status = ImGui::FindWindowByName("##status");
        const ImGuiWindow* canvas = ImGui::FindWindowByName("##canvas");
        const ImGuiWindow* panel = ImGui::FindWindowByName("##panel");
        REQUIRE(status != nullptr);
        REQUIRE(canvas != nullptr);
        REQUIRE(panel != nullptr);
        INFO(message << ": the bar is " << status->Size.x << " x " << status->Size.y << ", its text "
                     << status->ContentSize.x << " x " << status->ContentSize.y);
        // Its text within its width and its height (3 pixels of padding above and below).
        CHECK(status->ContentSize.x <= status->Size.x - 2.0f * kStatusPadding + 0.5f);
        CHECK(status->ContentSize.y + 6.0f <= status->Size.y + 0.5f);
        CHECK(status->Pos.y + status->Size.y <= ImGui::GetIO().DisplaySize.y + 0.5f);
        CHECK((status->Size.y > bar + 0.5f) == (ImGui::CalcTextSize(message.c_str()).x > status->Size.x - 16.0f));
        // The windows above end where it begins.
        CHECK(canvas->Pos.y + canvas->Size.y <= status->Pos.y + 0.5f);
        CHECK(panel->Pos.y + panel->Size.y <= status->Pos.y + 0.5f);
    }
}

TEST_CASE("F1's help stays between the menu bar and the status bar, at the smallest window and beside a lesson too",
          "[app]")
{
    // At the smallest window the help, centred on the window and as tall as its text, covered the menu bar and the
    // status line; it scrolls within the room between them.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    const float bar = ImGui::GetFrameHeight();
    for (const bool lesson : {false, true})
    {
        if (lesson)
        {
            REQUIRE(h.app->OpenLesson(0));
        }
        for (const ImVec2 size : {MinimumWindowSize(lesson, bar), ImVec2(1280.0f, 800.0f)})
        {
            ImGui::GetIO().DisplaySize = size;
            h.Frames(2);
            if (!Harness::Showing("Help (F1 or Esc closes)"))
            {
                h.Key(h.app->Options().keys.f1);
            }
            h.Frames(3);
            const ImGuiWindow* help = ImGui::FindWindowByName("Help (F1 or Esc closes)");
            const ImGuiWindow* status = ImGui::FindWindowByName("##status");
            REQUIRE(help != nullptr);
            REQUIRE(help->Active);
            REQUIRE(status != nullptr);
            INFO("window " << size.x << " x " << size.y << (lesson ? " with a lesson" : "") << ": help from y "
                           << help->Pos.y << " to " << help->Pos.y + help->Size.y << ", status from "
                           << status->Pos.y);
            CHECK(help->Pos.y >= bar - 0.5f);
            CHECK(help->Pos.y + help->Size.y <= status->Pos.y + 0.5f);
            CHECK(help->Pos.x >= -0.5f);
            CHECK(help->Pos.x + help->Size.x <= size.x + 0.5f);
            // All of it can be read: what does not fit scrolls.
            CHECK((help->ScrollMax.y > 0.0f) == (help->ContentSize.y > help->InnerRect.GetHeight() + 0.5f));
        }
    }
}

TEST_CASE("The bundled scenes are found from the program's folder: the data folder, else tutorials/ above it", "[app]")
{
    const fs::path root = fs::temp_directory_path() / ("satviz-app-layout-" + std::to_string(::getpid()));
    fs::remove_all(root);
    // An install prefix: PREFIX/bin/satviz, PREFIX/share/satviz/scenes.
    fs::create_directories(root / "prefix" / "bin");
    fs::create_directories(root / "prefix" / "share" / "satviz" / "scenes");
    CHECK(FindBundledScenes(root / "prefix" / "bin", "../share/satviz") ==
          (root / "prefix" / "share" / "satviz" / "scenes").string());
    // A build directory inside the source tree, without a data folder: SOURCE/tutorials/scenes.
    fs::create_directories(root / "source" / "tutorials" / "scenes");
    fs::create_directories(root / "source" / "build" / "release" / "app");
    CHECK(FindBundledScenes(root / "source" / "build" / "release" / "app", "../share/satviz") ==
          (root / "source" / "tutorials" / "scenes").string());
    // The data folder comes first.
    fs::create_directories(root / "source" / "build" / "release" / "share" / "satviz" / "scenes");
    CHECK(FindBundledScenes(root / "source" / "build" / "release" / "app", "../share/satviz") ==
          (root / "source" / "build" / "release" / "share" / "satviz" / "scenes").string());
    // Neither.
    fs::create_directories(root / "elsewhere" / "bin");
    CHECK(FindBundledScenes(root / "elsewhere" / "bin", "../share/satviz").empty());
    fs::remove_all(root);
}

// [SECTION] The simulation

namespace
{

// The world satviz-sim steps: MakeWorld of the scene file, then Step by its dt, `steps` times.
World SteppedAsSatvizSim(const fs::path& file, int steps)
{
    const SceneResult loaded = LoadScene(file.string());
    REQUIRE(loaded.Ok());
    World world = MakeWorld(loaded.scene);
    for (int i = 0; i < steps; ++i)
    {
        Step(world, loaded.scene.world.dt);
    }
    return world;
}

// True when both worlds hold the same bits in every body's position, angle, velocity and spin.
bool SameState(const World& a, const World& b)
{
    if (a.bodies.size() != b.bodies.size() || a.time != b.time)
    {
        return false;
    }
    for (size_t i = 0; i < a.bodies.size(); ++i)
    {
        const RigidBody& p = a.bodies[i];
        const RigidBody& q = b.bodies[i];
        if (!(p.position == q.position) || p.angle != q.angle || !(p.velocity == q.velocity) ||
            p.angularVelocity != q.angularVelocity)
        {
            return false;
        }
    }
    return true;
}

} // namespace

TEST_CASE("The simulation plays, pauses, steps back and forward, each step the bits satviz-sim's world has",
          "[app][sim]")
{
    const fs::path file = ScratchCopy("l15_slope.json");
    Harness h(file.string());
    const Simulation& sim = h.app->GetSimulation();
    REQUIRE(sim.Error().empty());
    CHECK(sim.Shown() == 0);
    h.Key('P');
    CHECK(sim.Playing());
    h.Frames(30); // 1/60 s a frame at 60 steps a second: about one step a frame
    h.Key('P');
    CHECK_FALSE(sim.Playing());
    const int played = sim.Shown();
    CHECK(played >= 25);
    CHECK(SameState(sim.Record().world, SteppedAsSatvizSim(file, played)));
    // The figure shows the bodies where the world has them, and its world layers draw this record.
    const Body& box = h.View().Studied().bodies[1];
    CHECK(box.position == sim.Record().world.bodies[1].position);
    CHECK(h.View().CurrentFigure().sim == &sim.Record());
    h.Key(',');
    h.Key(',');
    CHECK(sim.Shown() == played - 2);
    CHECK(SameState(sim.Record().world, SteppedAsSatvizSim(file, played - 2)));
    // The record of the step shown is the step before taken again: its boxes and pairs are there.
    CHECK(sim.Record().steps == played - 2);
    CHECK_FALSE(sim.Record().lastStep.bounds.empty());
    h.Key('.');
    CHECK(sim.Shown() == played - 1);
    CHECK(SameState(sim.Record().world, SteppedAsSatvizSim(file, played - 1)));
    for (int i = 0; i < 3; ++i)
    {
        h.Key('.');
    }
    CHECK(sim.Shown() == played + 2);
    CHECK(sim.Last() == played + 2);
    CHECK(SameState(sim.Record().world, SteppedAsSatvizSim(file, played + 2)));
    h.app->SimShowStep(5);
    CHECK(SameState(sim.Record().world, SteppedAsSatvizSim(file, 5)));
    // A save at a step keeps the scene as written and asks for the steps: the file steps to the same bits.
    CHECK(h.app->SceneForSaving().view.simSteps == 5);
    CHECK_FALSE(h.Doc().Dirty());
    h.app->SimReset();
    CHECK(sim.Shown() == 0);
    CHECK(h.View().Studied().bodies[1].position == h.Doc().GetScene().bodies[1].position);
}

TEST_CASE("A drag while paused at a step edits the state at that step, and undo brings that step back", "[app][sim]")
{
    const fs::path file = ScratchCopy("l15_slope.json");
    Harness h(file.string());
    const Simulation& sim = h.app->GetSimulation();
    for (int i = 0; i < 20; ++i)
    {
        h.Key('.');
    }
    REQUIRE(sim.Shown() == 20);
    const World at20 = SteppedAsSatvizSim(file, 20);
    const Vec2 grabbed = at20.bodies[1].position;
    REQUIRE_FALSE(grabbed == h.Doc().GetScene().bodies[1].position);
    // Clicking the box selects it: no edit, the step stays.
    h.MoveTo(h.OnScreen(grabbed));
    ImGui::GetIO().MouseDown[0] = true;
    h.Frames(1);
    ImGui::GetIO().MouseDown[0] = false;
    h.Frames(1);
    CHECK(h.app->Selected() == 1);
    CHECK(sim.Shown() == 20);
    CHECK(h.Doc().UndoDepth() == 0);
    // Dragging it: the scene becomes the state of step 20 with the box moved.
    h.Drag(h.OnScreen(grabbed), h.OnScreen(grabbed + Vec2{0.0, 0.5}));
    CHECK(h.Doc().Dirty());
    CHECK(h.Doc().UndoDepth() == 1);
    const Body& box = h.Doc().GetScene().bodies[1];
    CHECK(box.position.x == Approx(grabbed.x).margin(0.02));
    CHECK(box.position.y == Approx(grabbed.y + 0.5).margin(0.02));
    CHECK(box.velocity == at20.bodies[1].velocity);
    CHECK(sim.Shown() == 0);
    // Undo: the scene as written, and the run it was made in, at step 20.
    REQUIRE(h.app->Undo());
    CHECK_FALSE(h.Doc().Dirty());
    CHECK(sim.Shown() == 20);
    CHECK(SameState(sim.Record().world, at20));
    // Redo: the edited state again, at its step 0.
    REQUIRE(h.app->Redo());
    CHECK(sim.Shown() == 0);
    CHECK(h.Doc().GetScene().bodies[1].position.y == Approx(grabbed.y + 0.5).margin(0.02));
}

TEST_CASE("The response of a contact chosen from the step's list is the world's record of that pair", "[app][sim]")
{
    const fs::path file = ScratchCopy("l16_peg.json");
    Harness h(file.string());
    const Simulation& sim = h.app->GetSimulation();
    const SceneResult loaded = LoadScene(file.string());
    REQUIRE(loaded.Ok());
    // The first step with a contact of a dynamic body, found by stepping the world alone.
    World world = MakeWorld(loaded.scene);
    int hit = 0;
    for (int i = 1; i <= 200 && hit == 0; ++i)
    {
        Step(world, loaded.scene.world.dt);
        if (std::any_of(world.contacts.begin(), world.contacts.end(), [](const WorldContact& c) { return !c.guard; }))
        {
            hit = i;
        }
    }
    REQUIRE(hit > 0);
    const WorldContact contact =
        *std::find_if(world.contacts.begin(), world.contacts.end(), [](const WorldContact& c) { return !c.guard; });
    h.app->SimShowStep(hit); // past the history: shows the latest
    while (sim.Shown() < hit)
    {
        h.app->SimForward();
    }
    h.app->SimChooseContact(contact.a, contact.b);
    h.Frames(2);
    const ContactSolveTrace& shown = sim.Record().contact;
    REQUIRE(shown.found);
    // The same step taken by a world of its own, recording that pair.
    World again = MakeWorld(loaded.scene);
    for (int i = 1; i < hit; ++i)
    {
        Step(again, loaded.scene.world.dt);
    }
    ContactSolveTrace trace;
    trace.bodyA = contact.a;
    trace.bodyB = contact.b;
    again.trace = &trace;
    Step(again, loaded.scene.world.dt);
    CHECK(shown.approachSpeed[0] == trace.approachSpeed[0]);
    CHECK(shown.normalMass[0] == trace.normalMass[0]);
    CHECK(shown.velocityAfter[1] == trace.velocityAfter[1]);
    // The panel's sentences quote it: the effective mass to three decimals.
    const std::vector<ResponseStep> steps = DescribeResponse(h.app->ShownScene(), sim.Record());
    char mass[32];
    std::snprintf(mass, sizeof mass, "%.3f kg", trace.normalMass[0]);
    CHECK(std::any_of(steps.begin(), steps.end(),
                      [&](const ResponseStep& s) { return s.sentence.find(mass) != std::string::npos; }));
    // The figure's pair is the chosen contact's, an edit of the view that undo takes back.
    const Scene& scene = h.Doc().GetScene();
    CHECK(h.View().Choices().bodyA == scene.bodies[static_cast<size_t>(contact.a)].name);
}

TEST_CASE("Materials of the selected body are edits that undo restores and a save writes", "[app][sim]")
{
    const fs::path file = ScratchCopy("l14_head_on.json");
    Harness h(file.string());
    Material material;
    material.restitution = 0.25;
    material.friction = 0.4;
    material.staticFriction = 0.6;
    const Body before = h.Doc().GetScene().bodies[1];
    h.app->SetMaterial(1, false, 2.5, material);
    CHECK(h.Doc().Dirty());
    CHECK(h.Doc().GetScene().bodies[1].density == 2.5);
    // The simulation starts over from the changed scene: B is now heavier.
    CHECK(h.app->GetSimulation().Record().world.bodies[1].mass ==
          Approx(2.5 * before.shape.circle.radius * before.shape.circle.radius * 3.141592653589793));
    h.app->SetMaterial(0, true, 1.0, h.Doc().GetScene().bodies[0].material);
    CHECK(h.Doc().GetScene().bodies[0].isStatic);
    REQUIRE(h.app->Undo());
    CHECK_FALSE(h.Doc().GetScene().bodies[0].isStatic);
    REQUIRE(h.app->Save(file.string()));
    const SceneResult saved = LoadScene(file.string());
    REQUIRE(saved.Ok());
    CHECK(saved.scene.bodies[1].density == 2.5);
    CHECK(saved.scene.bodies[1].material.restitution == 0.25);
    CHECK(saved.scene.bodies[1].material.friction == 0.4);
    CHECK(saved.scene.bodies[1].material.staticFriction == 0.6);
    REQUIRE(h.app->Undo());
    CHECK(h.Doc().GetScene().bodies[1].density == before.density);
    CHECK(h.Doc().GetScene().bodies[1].material.restitution == before.material.restitution);
}

TEST_CASE("The world's layers leave a framed scene room: its bodies stay on the canvas above their panels",
          "[app][sim]")
{
    Harness h(ScratchCopy("l14_head_on.json").string());
    h.app->SetLayers(kLayerShapes | kLayerLabels | kLayerCaption | kLayerBroadphase | kLayerResponse | kLayerHits |
                     kLayerPlots);
    for (int i = 0; i < 23; ++i)
    {
        h.app->SimForward();
    }
    h.Frames(2);
    const Viewer& viewer = h.View();
    const FigureLayout layout =
        LayoutFigure(viewer.Setup().study, viewer.Choices().layers, viewer.CanvasWidth(), viewer.CanvasHeight(), true);
    for (const Body& body : h.app->ShownScene().bodies)
    {
        const ScreenPoint p = ToScreen(viewer.Camera(), body.position);
        CHECK(p.x > 0.0f);
        CHECK(p.x < static_cast<float>(viewer.CanvasWidth()));
        CHECK(p.y > layout.sceneTop);
        CHECK(p.y < layout.sceneBottom);
    }
}

TEST_CASE("Clicking a contact point of the step shown chooses its pair for the response", "[app][sim]")
{
    Harness h(ScratchCopy("l17_skips.json").string());
    for (int i = 0; i < 5; ++i)
    {
        h.app->SimForward();
    }
    h.Frames(2);
    const World& world = h.app->GetSimulation().Record().world;
    // A contact not of the figure's pair, its point on the canvas.
    const int shownA = h.View().Setup().study.bodyA;
    const int shownB = h.View().Setup().study.bodyB;
    const auto other = std::find_if(world.contacts.begin(), world.contacts.end(), [&](const WorldContact& c) {
        return !c.guard && !(std::min(shownA, shownB) == c.a && std::max(shownA, shownB) == c.b);
    });
    REQUIRE(other != world.contacts.end());
    const WorldContact contact = *other;
    h.MoveTo(h.OnScreen(contact.points[0].point));
    ImGui::GetIO().MouseDown[0] = true;
    h.Frames(1);
    ImGui::GetIO().MouseDown[0] = false;
    h.Frames(2);
    const SimRecord& record = h.app->GetSimulation().Record();
    CHECK(std::min(record.contact.bodyA, record.contact.bodyB) == contact.a);
    CHECK(std::max(record.contact.bodyA, record.contact.bodyB) == contact.b);
    CHECK(record.contact.found);
    // Nothing moved: the click chose, it did not drag.
    CHECK(h.Doc().UndoDepth() == 1); // the pair's change, an edit of the view
    CHECK_FALSE(h.Doc().Dirty());
}

TEST_CASE("A body grabbed while the simulation plays follows the pointer and is thrown at its speed, and stepping "
          "back and forward shows the same states",
          "[app][sim]")
{
    const fs::path file = ScratchCopy("l15_slope.json");
    Harness h(file.string());
    const Simulation& sim = h.app->GetSimulation();
    h.Key('P');
    h.Frames(10);
    REQUIRE(sim.Playing());
    const Vec2 start = sim.Record().world.bodies[1].position;
    // Grab the box and move the pointer 1 m up and to the left in 8 frames of 1/60 s, then let go.
    const Vec2 move{-0.8, 0.6};
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = h.OnScreen(start);
    io.MouseDown[0] = true;
    h.Frames(1);
    CHECK(h.app->Selected() == 1);
    const Vec2 grabbedAt =
        ToWorld(h.View().Camera(), {io.MousePos.x - h.CanvasOrigin().x, io.MousePos.y - h.CanvasOrigin().y});
    std::vector<std::pair<int, World>> held; // the states shown while the box was held
    for (int i = 1; i <= 8; ++i)
    {
        io.MousePos = h.OnScreen(grabbedAt + (i / 8.0) * move);
        h.Frames(1);
        held.emplace_back(sim.Shown(), sim.Record().world);
        // The box is where the pointer holds it, at the step shown.
        const Vec2 at = sim.Record().world.bodies[1].position;
        CHECK(at.x == Approx(start.x + i / 8.0 * move.x).margin(0.01));
        CHECK(at.y == Approx(start.y + i / 8.0 * move.y).margin(0.01));
    }
    io.MouseDown[0] = false;
    h.Frames(1);
    REQUIRE(sim.Playing());
    const int thrownAt = sim.Shown();
    const World thrown = sim.Record().world;
    // The pointer moved 1/8 of `move` each 1/60 s, and stood still in the release frame: over the last 0.1 s
    // (six frames) it moved 5 or 6 eighths of `move` in 6 or 7 frames.
    const Vec2 velocity = thrown.bodies[1].velocity;
    const double speed = Length(move) / 8.0 * 60.0;
    CHECK(Dot(velocity, move) / (Length(velocity) * Length(move)) == Approx(1.0).margin(1e-3));
    CHECK(Length(velocity) >= 5.0 / 7.0 * speed * 0.99);
    CHECK(Length(velocity) <= speed * 1.01);
    CHECK(thrown.bodies[1].angularVelocity == 0.0);
    // A throw is not an edit of the scene.
    CHECK(h.Doc().UndoDepth() == 0);
    CHECK_FALSE(h.Doc().Dirty());
    h.Frames(6);
    h.Key('P');
    REQUIRE_FALSE(sim.Playing());
    const int last = sim.Shown();
    REQUIRE(last > thrownAt + 3);
    // The step after the throw is the world's step from the thrown state, as Step takes it.
    World after = thrown;
    Step(after, 1.0 / 60.0);
    h.app->SimShowStep(thrownAt + 1);
    CHECK(SameState(sim.Record().world, after));
    // Back to the steps the box was held in, and forward again: the same states, the hands kept with their steps.
    for (const auto& [step, world] : held)
    {
        h.app->SimShowStep(step);
        CHECK(sim.Shown() == step);
        CHECK(SameState(sim.Record().world, world));
    }
    h.app->SimShowStep(thrownAt);
    CHECK(SameState(sim.Record().world, thrown));
    // Not the world satviz-sim steps from the scene as written: the hand changed it.
    CHECK_FALSE(SameState(sim.Record().world, SteppedAsSatvizSim(file, thrownAt)));
}

TEST_CASE("A scene without a world block is not stepped until a world is added, then it steps as satviz-sim does",
          "[app][sim]")
{
    // l18_seam's box starts 0.8 deep in the L. Stepped by the format's defaults (a whole time unit a step) it was
    // thrown out of one piece into the other and fell asleep 0.37 inside it, its kept contact still saying 0.80.
    const std::string file = std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/l18_seam.json";
    Harness h(file);
    const Simulation& sim = h.app->GetSimulation();
    REQUIRE_FALSE(h.Doc().GetScene().hasWorld);
    CHECK_FALSE(h.app->CanStep());
    h.Key('.');
    h.Key('P');
    h.Frames(10);
    CHECK(sim.Shown() == 0);
    CHECK_FALSE(sim.Playing());
    CHECK(h.app->StatusIsError());
    CHECK(h.app->Status().find("no world") != std::string::npos);
    CHECK_FALSE(h.Doc().Dirty());

    h.app->AddWorld();
    REQUIRE(h.app->CanStep());
    CHECK(h.Doc().Dirty());
    const Scene written = h.Doc().GetScene();
    CHECK(written.world.dt == 1.0 / 60.0);
    CHECK(written.world.gravity == Vec2{0, 0});
    for (int i = 0; i < 120; ++i)
    {
        h.Key('.');
    }
    REQUIRE(sim.Shown() == 120);
    World oracle = MakeWorld(written);
    for (int i = 0; i < 120; ++i)
    {
        Step(oracle, written.world.dt);
    }
    CHECK(SameState(sim.Record().world, oracle));
    // Out of the L: the box (0.6 tall) rests on the bar's top, y = 1, to the right of the upright (x = 1).
    const RigidBody& box = sim.Record().world.bodies[1];
    CHECK(box.position.y == Approx(1.3).margin(0.02));
    CHECK(box.position.x - 0.6 > 1.0 - 0.02);
    CHECK(std::abs(box.angle) < 0.02);
    // Undo takes the world back, and the scene is no longer stepped.
    REQUIRE(h.app->Undo());
    CHECK_FALSE(h.Doc().GetScene().hasWorld);
    CHECK_FALSE(h.Doc().Dirty());
    CHECK_FALSE(h.app->CanStep());
}

TEST_CASE("The sweep's ghost at time is named as what it draws, and ticked again it comes back where it was", "[app]")
{
    // bullet_wall's view draws the ghost at t = 1 beside the bodies at t = 0: the control says "ghost", and
    // unticking and ticking it again does not move the ghost to another time (it jumped to 0.5, onto the ghost
    // at the time of impact, 0.482).
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/bullet_wall.json");
    REQUIRE(h.View().Time() == 1.0);
    REQUIRE(h.ClickButton("##panel", "ghost at time"));
    CHECK(h.View().Time() < 0.0);
    REQUIRE(h.ClickButton("##panel", "ghost at time"));
    CHECK(h.View().Time() == 1.0);
    // The bodies stay where the sweep starts: the figure draws the bullet at its position as written.
    CHECK(h.View().Studied().bodies[1].position == h.Doc().GetScene().bodies[1].position);
}

TEST_CASE("Reset says the world went back to its start after the steps taken, and the panel says where it is",
          "[app][sim]")
{
    // After 135 steps and Reset the simulation panel read "Step 0: time 0 s (dt 0.0167 s); 135 steps taken", as if
    // nothing had gone back, and Reset said nothing. The panel writes StepsTakenWords after the step's time.
    Harness h(ScratchCopy("l15_slope.json").string());
    const Simulation& sim = h.app->GetSimulation();
    for (int i = 0; i < 135; ++i)
    {
        h.app->SimForward();
    }
    REQUIRE(sim.Shown() == 135);
    CHECK(StepsTakenWords(sim.Shown(), sim.Last()) == "135 steps taken");
    h.app->SimReset();
    REQUIRE(sim.Shown() == 0);
    REQUIRE(sim.Last() == 135);
    CHECK(!h.app->StatusIsError());
    CHECK(h.app->Status() == "Reset: the world is back at its start, the scene as written, after 135 steps; Forward "
                             "and the step slider go through them again");
    h.Frames(1);
    CHECK(StepsTakenWords(sim.Shown(), sim.Last()) ==
          "back at the start, the scene as written, after 135 steps: Forward and the slider go through them again");
    h.app->SimShowStep(40);
    h.Frames(1);
    CHECK(StepsTakenWords(sim.Shown(), sim.Last()) == "back at step 40 of the 135 steps taken");
    // The passing message goes with the step it spoke of; a Reset at the start says nothing, nothing went back.
    CHECK(h.app->Status().empty());
    h.app->SimShowStep(0);
    h.Frames(1);
    h.app->SimReset();
    CHECK(h.app->Status().empty());
    CHECK(StepsTakenWords(0, 0) == "no step taken yet");
    CHECK(StepsTakenWords(1, 1) == "1 step taken");
}

TEST_CASE("The plots keep the totals of the latest kMaxSamples steps", "[app][sim]")
{
    const SceneResult loaded = LoadScene((fs::path(SATVIZ_SOURCE_DIR) / "tutorials/scenes/l14_head_on.json").string());
    REQUIRE(loaded.Ok());
    Simulation sim;
    sim.Restart(loaded.scene, 0, 1);
    const int steps = Simulation::kMaxSamples + 25;
    for (int i = 0; i < steps; ++i)
    {
        sim.StepForward();
    }
    const std::vector<SimSample>& history = sim.Record().history;
    REQUIRE(history.size() == static_cast<size_t>(Simulation::kMaxSamples));
    CHECK(history.back().step == steps);
    CHECK(history.front().step == steps - Simulation::kMaxSamples + 1);
    // Stepping back shows the samples up to the step shown, from the same oldest.
    sim.StepBack();
    CHECK(sim.Record().history.back().step == steps - 1);
    CHECK(sim.Record().history.front().step == steps - Simulation::kMaxSamples + 1);
}

namespace
{

void NoClear(const ImDrawList*, const ImDrawCmd*) {}

} // namespace

TEST_CASE("The window's canvas clears large opaque rectangles and fills outlined polygons without a fringe", "[app]")
{
    Harness h(ScratchCopy("l15_slope.json").string());
    ImGui::NewFrame();
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    ImDrawListCanvas canvas(list, h.app->Fonts());
    canvas.ClearLargeRects(NoClear);
    // An opaque rectangle of 190 x 90 px: one callback command, its clip rectangle the rectangle, no vertices.
    const int before = list->VtxBuffer.Size;
    canvas.FillRect({10.0f, 20.0f}, {200.0f, 110.0f}, 0x112233FFu);
    CHECK(list->VtxBuffer.Size == before);
    const auto cleared = std::find_if(list->CmdBuffer.begin(), list->CmdBuffer.end(),
                                      [](const ImDrawCmd& c) { return c.UserCallback == NoClear; });
    REQUIRE(cleared != list->CmdBuffer.end());
    CHECK(cleared->ClipRect.x == 10.0f);
    CHECK(cleared->ClipRect.y == 20.0f);
    CHECK(cleared->ClipRect.z == 200.0f);
    CHECK(cleared->ClipRect.w == 110.0f);
    CHECK(ClearColorOf(*cleared) == 0x112233FFu);
    // Translucent, or small: triangles.
    canvas.FillRect({10.0f, 20.0f}, {200.0f, 110.0f}, 0x11223380u);
    CHECK(list->VtxBuffer.Size == before + 4);
    canvas.FillRect({10.0f, 20.0f}, {40.0f, 50.0f}, 0x112233FFu);
    CHECK(list->VtxBuffer.Size == before + 8);
    // An outlined pentagon: with the fringe, ImGui's anti-aliased fill takes two vertices per point; without, one.
    const ScreenPoint pentagon[5] = {{300, 300}, {340, 310}, {345, 350}, {310, 365}, {290, 335}};
    const int start = list->VtxBuffer.Size;
    canvas.FillOutlined(pentagon, 5, 0x11223340u, 0x112233FFu, 2.0f);
    const int smooth = list->VtxBuffer.Size - start;
    canvas.PlainFillsUnderOutlines(true);
    canvas.FillOutlined(pentagon, 5, 0x11223340u, 0x112233FFu, 2.0f);
    const int plain = list->VtxBuffer.Size - start - smooth;
    CHECK(smooth - plain == 5);
    ImGui::Render();
}

// The rows of the step list in sight: [first, last] by its scroll and height; -1, -1 when the list is not shown.
std::pair<int, int> StepRowsInSight()
{
    for (ImGuiWindow* window : ImGui::GetCurrentContext()->Windows)
    {
        if (window->Active && std::string(window->Name).find("/##axes_") != std::string::npos)
        {
            // Row k's text spans [start + k * row, start + k * row + text] on the screen; in sight when the list's
            // clip rectangle holds it whole.
            const float row = ImGui::GetTextLineHeightWithSpacing();
            const float text = ImGui::GetTextLineHeight();
            const float start = window->Pos.y + window->WindowPadding.y - window->Scroll.y;
            const float low = window->InnerClipRect.Min.y;
            const float high = window->InnerClipRect.Max.y;
            return {static_cast<int>(std::ceil((low - start) / row - 1e-3f)),
                    static_cast<int>(std::floor((high - start - text) / row + 1e-3f))};
        }
    }
    return {-1, -1};
}

TEST_CASE("Undo and redo keep a student reading the verdict on the verdict, and its row in the step list in sight",
          "[app]")
{
    for (const std::string scene : {"many_sides.json", "separated_triangle.json", "overlapping_boxes.json",
                                    "concave/l18_notch.json", "concave/l18_across.json"})
    {
        INFO(scene);
        Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + scene);
        auto onVerdict = [&](const char* after) {
            INFO("after " << after);
            CHECK(h.View().Step() == h.View().VerdictStep());
            if (h.View().Setup().figure.kind != FigureKind::Pieces)
            {
                // The list has a row per step of the pair's test; the verdict's must be in sight.
                h.Frames(2);
                const auto [first, last] = StepRowsInSight();
                INFO("rows " << first << " to " << last << " in sight, of " << h.View().Setup().study.StepCount());
                CHECK(first <= h.View().Step());
                CHECK(h.View().Step() <= last);
            }
        };
        onVerdict("opening");
        // Far off, the pair is apart on its first axis, or one of the first few: a short list. Undo brings the long
        // one back, on its verdict.
        const int moved = h.View().TestsPair() ? h.View().Setup().study.bodyB : 1;
        const ImVec2 from = h.OnScreen(Centroid(h.Doc().GetScene().bodies[static_cast<size_t>(moved)]));
        h.Drag(from, ImVec2(from.x + 150.0f, from.y + 10.0f));
        onVerdict("a drag");
        h.Key(kZ, true);
        onVerdict("undoing the drag");
        h.Key(kY, true);
        onVerdict("redoing the drag");
        h.Key(kZ, true);
        onVerdict("undoing it again");
        h.app->SetStepView(StepView::Faces);
        onVerdict("the face view");
        h.app->SetQuery(ViewQuery::Sweep);
        onVerdict("the swept test");
        h.app->SetLayers(h.View().Choices().layers ^ kLayerLabels);
        onVerdict("a layer");
        for (int i = 0; i < 4; ++i)
        {
            h.Key(kZ, true);
            onVerdict("an undo");
        }
        for (int i = 0; i < 4; ++i)
        {
            h.Key(kY, true);
            onVerdict("a redo");
        }
    }
}

TEST_CASE("A large whole number is written alike in the step sentences, the Numbers panel and the labels: 100 000, "
          "not 100000.00",
          "[app]")
{
    // The bullet of l17_bullet flies at 100 000 m/s; its sentences quote the speed and what it covers.
    SceneResult loaded = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l17_bullet.json");
    REQUIRE(loaded.Ok());
    const Scene& scene = loaded.scene;
    REQUIRE(scene.bodies[1].velocity.x == 100000.0);
    std::string all;
    for (const ViewQuery query : {ViewQuery::Collide, ViewQuery::Sweep})
    {
        for (const StepView view : {StepView::Textbook, StepView::Faces})
        {
            const PairStudy study = StudyPair(scene, 0, 1, query, false, view);
            for (int step = 0; step < study.StepCount(); ++step)
            {
                all += DescribeStep(scene, study, step) + "\n" + StepTitle(scene, study, step) + "\n";
            }
            for (const NumberRow& row : StaticTestNumbers(scene, study))
            {
                for (const std::string& part : row.parts)
                {
                    all += part + "\n";
                }
            }
        }
    }
    INFO(all);
    CHECK(all.find("100000") == std::string::npos);
    CHECK(all.find("100 000") != std::string::npos);
    // Every printer goes through the one format, which an independent grouping of the digits checks.
    CHECK(FormatNumber(100000.0) == "100 000");
    CHECK(FormatNumber(-1234567.0) == "-1 234 567");
    CHECK(FormatNumber(12345.0) == "12 345");
    CHECK(FormatNumber(1667.0) == "1667.00");
    CHECK(FormatNumber(100000.5) == "100000.50");
    CHECK(FormatLabelNumber(100000.0) == FormatNumber(100000.0));
}

TEST_CASE("The panels show SAT's steps and numbers only where the canvas answers with SAT", "[app]")
{
    // disc_cast_cup's panels gave t = 0.34 at (2.008, 3.000), the cast against the cup's hull, under a canvas whose
    // caption says t = 0.74 at (2.488, 1.000) on the cup's floor.
    struct Case
    {
        const char* scene;
        bool sat;
    };
    for (const Case& c : {Case{"concave/disc_cast_cup.json", false}, Case{"concave/disc_cast_corner.json", false},
                          Case{"concave/l18_notch.json", false}, Case{"overlapping_boxes.json", true},
                          Case{"fly_by.json", true}})
    {
        INFO(c.scene);
        Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + c.scene);
        REQUIRE(h.View().TestsPair());
        CHECK(h.View().ShowsSatNumbers() == c.sat);
        // The figure is what the scene's view asks for: the cast and the pieces are answered on the canvas.
        const FigureKind kind = h.View().CurrentFigure().kind;
        CHECK((kind == FigureKind::Pair) == c.sat);
    }
}

TEST_CASE("Beside the lesson column every lesson scene opens with its pair below the caption band, at every step",
          "[app]")
{
    // On a canvas narrowed by the lesson column a long caption wraps to more lines than the figure's layout gives
    // it, and its band grew over the picture: disc_cast_cup's seven lines over its start disc. The band is read
    // from what the canvas draws at each step; the pair is placed by its geometry, each body at its scene position.
    const fs::path scenes = fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes";
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(scenes))
    {
        if (entry.path().extension() == ".json")
        {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    Harness h((scenes / "overlapping_boxes.json").string());
    REQUIRE(h.app->OpenLesson(0));
    int checked = 0;
    std::vector<std::string> covered;
    for (const ImVec2 window : {ImVec2(1300.0f, 850.0f), ImVec2(1180.0f, 650.0f)})
    {
        ImGui::GetIO().DisplaySize = window;
        h.Frames(2);
        for (const fs::path& file : files)
        {
            if (!h.app->Open(file.string()))
            {
                continue;
            }
            h.Frames(2);
            h.AwaitStudy();
            const Viewer& viewer = h.View();
            REQUIRE(h.app->LessonShown());
            if (!viewer.Setup().Ok() || viewer.Setup().figure.kind == FigureKind::Slice ||
                viewer.Setup().figure.kind == FigureKind::Decomposition ||
                viewer.Setup().study.bodyA < 0 || viewer.Setup().study.bodyB < 0)
            {
                continue;
            }
            const Scene& scene = viewer.Studied();
            const PairStudy& study = viewer.Setup().study;
            float top = INFINITY;
            for (const int index : {study.bodyA, study.bodyB})
            {
                const Body& body = scene.bodies[static_cast<size_t>(index)];
                float low = INFINITY;
                float high = -INFINITY;
                if (body.shape.type == ShapeType::Polygon)
                {
                    for (const Vec2& v : body.shape.polygon.Vertices())
                    {
                        const float y = ToScreen(viewer.Camera(), TransformPoint(body.Xf(), v)).y;
                        low = std::min(low, y);
                        high = std::max(high, y);
                    }
                }
                else
                {
                    const Vec2 c = TransformPoint(body.Xf(), body.shape.circle.center);
                    const float r = ToPixels(viewer.Camera(), body.shape.circle.radius);
                    low = ToScreen(viewer.Camera(), c).y - r;
                    high = low + 2.0f * r;
                }
                // A wall taller than the canvas (bullet_wall_close's) runs on out of sight by design.
                if (high - low < 0.75f * static_cast<float>(viewer.CanvasHeight()))
                {
                    top = std::min(top, low);
                }
            }
            const int steps = FigureStepCount(scene, viewer.Setup());
            for (int step = 0; step < steps && step < 40; ++step)
            {
                Figure figure = CanvasFigure(*h.app);
                figure.step = step;
                RecordingCanvas canvas;
                PaintFigure(canvas, scene, study, figure);
                float band = 0.0f;
                for (const DrawCommand* c : canvas.InGroup("caption"))
                {
                    for (const ScreenPoint& p : c->points)
                    {
                        band = std::max(band, p.y + (c->kind == DrawCommand::Kind::Text
                                                         ? canvas.MeasureText(c->text, c->style).y
                                                         : 0.0f));
                    }
                }
                ++checked;
                if (top < band)
                {
                    covered.push_back(file.filename().string() + " step " + std::to_string(step + 1) + " at " +
                                      std::to_string(viewer.CanvasWidth()) + "x" +
                                      std::to_string(viewer.CanvasHeight()) + ": band to " + std::to_string(band) +
                                      ", pair from " + std::to_string(top));
                }
            }
        }
    }
    CHECK(checked > 300);
    for (const std::string& c : covered)
    {
        UNSCOPED_INFO(c);
    }
    CHECK(covered.empty());
}

TEST_CASE("Every row of the axes list of a lesson scene fits the list's width", "[app]")
{
    // The list cannot wrap its rows (it builds only the rows in sight, of a height known before they are built): a
    // row wider than the list would be cut at its edge. Every step of every scene of the course, in both step views.
    const fs::path scenes = fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes";
    Harness h((scenes / "overlapping_boxes.json").string());
    std::vector<std::string> cut;
    int rows = 0;
    for (const auto& entry : fs::recursive_directory_iterator(scenes))
    {
        if (entry.path().extension() != ".json" || !h.app->Open(entry.path().string()))
        {
            continue;
        }
        for (const StepView view : {StepView::Textbook, StepView::Faces})
        {
            h.app->SetStepView(view);
            h.Frames(2);
            h.AwaitStudy();
            const Viewer& viewer = h.View();
            // The legend alone (l01_legend) has no list: its bodies are not drawn.
            if (!viewer.Setup().Ok() || viewer.Setup().figure.kind != FigureKind::Pair ||
                (viewer.Choices().layers & kLayerShapes) == 0)
            {
                continue;
            }
            ImGuiWindow* list = nullptr;
            for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
            {
                if (w->Active && std::string(w->Name).find("##axes") != std::string::npos)
                {
                    list = w;
                }
            }
            REQUIRE(list != nullptr);
            const float inner = list->ContentRegionRect.GetWidth();
            ImGui::NewFrame();
            const PairStudy& study = viewer.Setup().study;
            for (int k = 0; k < study.StepCount() && k < 64; ++k)
            {
                const std::string title = StepTitle(viewer.Studied(), study, k);
                ++rows;
                if (ImGui::CalcTextSize(title.c_str()).x > inner)
                {
                    cut.push_back(entry.path().filename().string() + ": " + title);
                }
            }
            ImGui::EndFrame();
        }
    }
    CHECK(rows > 500);
    for (const std::string& c : cut)
    {
        UNSCOPED_INFO(c);
    }
    CHECK(cut.empty());
}

TEST_CASE("A scene with the axis layers off says so beside an axis step, and the Layers panel is in sight", "[app]")
{
    // l13_overlap shows the Minkowski view: stepping its axes changed only the words, since its layers leave the
    // projection off, and the Layers panel that turns it on lay below the step list and the numbers, out of sight
    // in a short window.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l13_overlap.json");
    ImGui::GetIO().DisplaySize = ImVec2(1180.0f, 650.0f);
    h.Frames(2);
    h.app->ShowStep(0);
    h.Frames(2);
    REQUIRE((h.View().Choices().layers & kLayerProjection) == 0);
    const auto projected = [&]() {
        RecordingCanvas canvas;
        PaintFigure(canvas, h.View().Studied(), h.View().Setup().study, CanvasFigure(*h.app));
        return !canvas.InGroup("projection").empty();
    };
    CHECK(!projected());
    // The panel's button turns the axis on, and the picture draws it.
    REQUIRE(h.ClickButton("##panel", "show the axes"));
    h.Frames(2);
    CHECK((h.View().Choices().layers & kLayerProjection) != 0);
    CHECK(h.View().Step() == 0);
    CHECK(projected());
    // With the axis drawn, no note and no button.
    CHECK(!h.ClickButton("##panel", "show the axes"));
    // The Layers header is in the panel's sight (a click reaches it) with the step list and the numbers open.
    CHECK(h.ClickButton("##panel", "Layers"));
}

TEST_CASE("A sweep's numbers name what t from 0 to 1 covers as its verdict does: a step, or a world's second", "[app]")
{
    // l17_bullet after a step: the verdict said "no hit during the swept second" while the numbers said "Swept test
    // (t from 0 to 1)" and "no hit during the step". A world's velocities are per second, and the pair figure sweeps
    // them over a second, 60 of its steps.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l17_bullet.json");
    h.app->SimForward();
    h.app->SetQuery(ViewQuery::Sweep);
    h.Frames(3);
    REQUIRE(h.AwaitStudy());
    const PairStudy& study = h.View().Setup().study;
    REQUIRE(study.sweep);
    const Scene& scene = h.View().Studied();
    REQUIRE(scene.hasWorld);
    const std::string verdict = DescribeStep(scene, study, study.VerdictStep());
    INFO(verdict);
    REQUIRE(verdict.find("no hit during the swept second") != std::string::npos);
    CHECK(SweepMissLine(scene).find("no hit during the swept second") == 0);
    CHECK(SweepHeading(scene).find("one second") != std::string::npos);
    CHECK(SweepHeading(scene).find("t from 0 to 1") != std::string::npos);
    // A scene without a world sweeps one step, and says so in both places.
    const SceneResult wall = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/bullet_wall.json");
    REQUIRE(wall.Ok());
    CHECK(SweepMissLine(wall.scene).find("no hit during the step") == 0);
    CHECK(SweepHeading(wall.scene).find("over the step") != std::string::npos);
}

TEST_CASE("pitfall_direction's description names the faces its axis list and its pitfall name", "[app][lessons]")
{
    // The description said the slab's face with the smallest shared part is its bottom while the axis list named
    // that axis "slab edge 2" (the top, which the block touches): a student read two faces for one. Both faces are
    // named in it, each as the list and the pitfall's sentence name it, computed here.
    const SceneResult loaded = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/pitfall_direction.json");
    REQUIRE(loaded.Ok());
    FigureSetup setup = SetUpFigure(loaded.scene, FigureOptions{});
    REQUIRE(setup.Ok());
    const PairStudy& study = setup.study;
    const std::string& description = loaded.scene.description;
    INFO(description);
    // The axis of the smallest shared part (the smallest overlap here, as no interval holds the other), as the
    // list names it.
    int smallest = -1;
    for (int k = 0; k < study.AxisCount(); ++k)
    {
        const std::string title = StepTitle(loaded.scene, study, k);
        INFO(title);
        if (smallest < 0 || title.find("overlap 0.20") != std::string::npos)
        {
            smallest = k;
        }
    }
    const std::string title = StepTitle(loaded.scene, study, smallest);
    const size_t edge = title.find("slab edge ");
    REQUIRE(edge != std::string::npos);
    const std::string listed = title.substr(edge + 5, 6); // "edge 2"
    CHECK(description.find("(" + listed + ")") != std::string::npos);
    // The face the pitfall pushes along, as its sentence names it.
    const size_t pushed = study.pitfall.verdict.find("slab's edge ");
    REQUIRE(pushed != std::string::npos);
    const std::string face = study.pitfall.verdict.substr(pushed + 7, 6); // "edge 0"
    CHECK(face != listed);
    CHECK(description.find("(" + face + ")") != std::string::npos);
}

TEST_CASE("Beside a sweep's verdict the static gap names the axis it is measured on, at t = 0", "[app]")
{
    // fly_by's numbers said "gap on the separating axis: 0.50", the static test's at t = 0, beside a number line
    // showing the sweep's deciding axis 2 and its gap 0.60. The row now names its axis; the gap is checked by
    // projecting the two bodies, where they start, on that axis.
    const SceneResult loaded = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/fly_by.json");
    REQUIRE(loaded.Ok());
    const FigureSetup setup = SetUpFigure(loaded.scene, FigureOptions{});
    REQUIRE(setup.Ok());
    const PairStudy& study = setup.study;
    REQUIRE(study.sweep);
    const NumberRow* gap = nullptr;
    const std::vector<NumberRow> rows = StaticTestNumbers(loaded.scene, study);
    for (const NumberRow& row : rows)
    {
        gap = row.label.find("gap") != std::string::npos ? &row : gap;
    }
    REQUIRE(gap != nullptr);
    INFO(gap->label << ": " << gap->parts[0]);
    CHECK(gap->label.find("separating axis") == std::string::npos);
    CHECK(gap->label.find("t = 0") != std::string::npos);
    const size_t open = gap->label.find('(');
    REQUIRE(open != std::string::npos);
    double dx = 0.0, dy = 0.0;
    REQUIRE(std::sscanf(gap->label.c_str() + open, "(%lf, %lf)", &dx, &dy) == 2);
    const auto project = [&](const Body& body, double& lo, double& hi) {
        lo = INFINITY;
        hi = -INFINITY;
        for (const Vec2& v : body.shape.polygon.Vertices())
        {
            const Vec2 p = TransformPoint(body.Xf(), v);
            lo = std::min(lo, p.x * dx + p.y * dy);
            hi = std::max(hi, p.x * dx + p.y * dy);
        }
    };
    double loA = 0.0, hiA = 0.0, loB = 0.0, hiB = 0.0;
    project(loaded.scene.bodies[static_cast<size_t>(study.bodyA)], loA, hiA);
    project(loaded.scene.bodies[static_cast<size_t>(study.bodyB)], loB, hiB);
    CHECK(gap->parts[0] == FormatNumber(std::max(loB - hiA, loA - hiB)));
}

namespace
{

// The contact points' dots the app's canvas draws at the verdict of the pair it studies.
int ContactDotsAtVerdict(Harness& h)
{
    Figure figure = CanvasFigure(*h.app);
    figure.step = h.View().VerdictStep();
    RecordingCanvas canvas;
    PaintFigure(canvas, h.View().Studied(), h.View().Setup().study, figure);
    int dots = 0;
    for (const DrawCommand* c : canvas.InGroup("contacts"))
    {
        dots += c->kind == DrawCommand::Kind::FillCircle ? 1 : 0;
    }
    return dots;
}

} // namespace

TEST_CASE("The Numbers panel lists the contact points the figure draws, and only those", "[app]")
{
    // l02_box_and_triangle's view has no contacts layer: its verdict draws no contact dot, and the panel listed
    // "contact c1: (0.55, 0.45)" and "contact c2: (1.00, 0.45)" all the same.
    for (const char* name : {"l02_box_and_triangle.json", "l07_voronoi.json", "overlapping_boxes.json",
                             "containment.json", "l05_box_in_box.json"})
    {
        const fs::path file = fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes" / name;
        if (!fs::exists(file))
        {
            continue;
        }
        Harness h(file.string());
        h.app->ShowStep(h.View().VerdictStep());
        h.Frames(1);
        const PairStudy& study = h.View().Setup().study;
        REQUIRE_FALSE(study.sweep);
        const int dots = ContactDotsAtVerdict(h);
        int listed = 0;
        for (const NumberRow& row : StaticTestNumbers(h.View().Studied(), study, false, h.View().Choices().layers))
        {
            listed += row.label.rfind("contact", 0) == 0 ? 1 : 0;
        }
        INFO(name);
        CHECK(listed == dots);
        if (std::string(name) == "l02_box_and_triangle.json")
        {
            CHECK(study.manifold.contactCount == 2); // the case at hand: two points found, none drawn
            CHECK(dots == 0);
        }
    }
}

TEST_CASE("Beside a sweep the Numbers panel lists only the contacts the figure draws, those at impact", "[app]")
{
    // A sweep's figure draws the contact points at the time of impact (c1, c2), none at t = 0. sliding_past has no
    // hit and draws none, and its panel listed "contact 1: (-1.50, 0.25)" and "contact 2" under the static test;
    // ex09_touching listed them beside c1 and c2 in the other order, (-1.25, 0.25) as contact 1 where c1 is
    // (-0.75, 0.25).
    for (const char* name : {"sliding_past.json", "ex09_touching.json", "bullet_wall.json", "l08_throw.json"})
    {
        Harness h((fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes" / name).string());
        h.app->ShowStep(h.View().VerdictStep());
        h.Frames(1);
        const PairStudy& study = h.View().Setup().study;
        REQUIRE(study.sweep);
        const int dots = ContactDotsAtVerdict(h);
        // The panel's rows "contact cK at impact" (one per contact of a hit), then the static test's rows.
        const bool hit = (study.Textbook() ? study.textbookSweepResult.status : study.sweepResult.status) ==
                         SweepStatus::Hit;
        int listed = hit && (h.View().Choices().layers & kLayerContacts) != 0 ? study.sweepResult.contactCount : 0;
        for (const NumberRow& row : StaticTestNumbers(h.View().Studied(), study, false, h.View().Choices().layers))
        {
            listed += row.label.rfind("contact", 0) == 0 ? 1 : 0;
        }
        INFO(name);
        CHECK(listed == dots);
    }
}

TEST_CASE("The static test's numbers are the verdict's at every step, and their heading says so", "[app]")
{
    // At axis 1 of overlapping_boxes the list and the sentence give that axis's overlap, 0.525; the Numbers panel
    // gives the test's answer, an MTV of 0.184 along B's edge 3, under no heading, and read as axis 1's.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    h.app->ShowStep(0);
    h.Frames(1);
    const PairStudy& study = h.View().Setup().study;
    REQUIRE_FALSE(study.sweep);
    REQUIRE(h.View().Step() != h.View().VerdictStep());
    std::string depth;
    for (const NumberRow& row : StaticTestNumbers(h.View().Studied(), study, false, h.View().Choices().layers))
    {
        if (row.label == "MTV length (depth)")
        {
            depth = row.parts.front();
        }
    }
    CHECK(depth == FormatNumber(study.manifold.depth)); // the verdict's depth, at axis 1
    CHECK(depth != FormatNumber(study.textbook.axes.front().overlap));
    CHECK(StaticHeading().find("verdict") != std::string::npos);
    CHECK(StaticHeading().find("every step") != std::string::npos);
}

TEST_CASE("A status message of two lines has them spaced as the panels' lines, inside the bar", "[app]")
{
    // Opened at its view's sim_steps, l14_head_on_after's message takes two lines; the second sat on the window's
    // bottom edge, its descenders touching it.
    Harness h(ScratchCopy("l14_head_on_after.json").string());
    ImGui::GetIO().DisplaySize = ImVec2(1000.0f, 700.0f);
    h.Frames(3);
    ImGuiWindow* bar = ImGui::FindWindowByName("##status");
    REQUIRE(bar != nullptr);
    ImGui::NewFrame();
    const float line = ImGui::GetTextLineHeight();
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    ImGui::EndFrame();
    const float width = ImGui::CalcTextSize(h.app->Status().c_str()).x;
    REQUIRE(width > bar->Size.x); // the case at hand: two lines
    CHECK(bar->ContentSize.y >= 2.0f * line + spacing);
    // The bar holds its lines and its padding: nothing runs past its bottom edge.
    CHECK(bar->ContentSize.y + 2.0f * bar->WindowPadding.y <= bar->Size.y + 0.5f);
    CHECK(bar->Pos.y + bar->Size.y <= ImGui::GetMainViewport()->Size.y + 0.5f);
}

TEST_CASE("The side panel shows a scroll bar when its sections run past its bottom", "[app]")
{
    // overlapping_boxes's Numbers run past the bottom of a 700-pixel window ("contact c2" half shown), and the
    // panel, which scrolls with the wheel, showed no bar to say so.
    Harness h(ScratchCopy("overlapping_boxes.json").string());
    ImGui::GetIO().DisplaySize = ImVec2(1280.0f, 700.0f);
    h.Frames(3);
    ImGuiWindow* panel = ImGui::FindWindowByName("##panel");
    REQUIRE(panel != nullptr);
    REQUIRE(panel->ContentSize.y > panel->InnerRect.GetHeight()); // the case at hand: it runs past the bottom
    CHECK(panel->ScrollbarY);
    // Its lines wrap inside the bar: nothing laid out under it.
    CHECK(panel->ContentSize.x <= panel->ContentRegionRect.GetWidth() + 0.5f);
}

TEST_CASE("A lesson's first scene opens at the same step from its button as when the lesson opens", "[app]")
{
    // --lesson 4 opened overlapping_boxes at axis 1, the figure lesson 4 begins with, and its button in the
    // Scenes row at the verdict.
    Harness h(ScratchCopy("l04_wrong_way.json").string());
    const int lesson4 = 3;
    REQUIRE(h.app->OpenLesson(lesson4));
    REQUIRE(h.AwaitStudy());
    h.Frames(2);
    const Lesson& lesson = h.app->Lessons()[lesson4];
    REQUIRE(fs::path(lesson.scenes.front()).stem() == "overlapping_boxes");
    REQUIRE(lesson.firstStep == 0);
    REQUIRE(h.View().Step() == lesson.firstStep);
    h.app->ShowStep(h.View().VerdictStep());
    REQUIRE(h.ClickButton("Lesson###lesson", "l04_wrong_way"));
    REQUIRE(h.AwaitStudy());
    REQUIRE(fs::path(h.Doc().File()).stem() == "l04_wrong_way");
    REQUIRE(h.ClickButton("Lesson###lesson", "overlapping_boxes"));
    REQUIRE(h.AwaitStudy());
    h.Frames(2);
    CHECK(fs::path(h.Doc().File()).stem() == "overlapping_boxes");
    CHECK(h.View().Step() == lesson.firstStep);
}

TEST_CASE("The legend alone has no steps of a pair test, until the shapes layer shows its bodies", "[app]")
{
    // l01_legend draws the legend alone; the panel stepped a test of its two undrawn bodies ("Verdict: axis 2
    // separates the shapes: B lies 2.00 beyond A's edge 1").
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l01_legend.json");
    h.Frames(2);
    CHECK_FALSE(h.ClickButton("##panel", "Verdict"));
    h.app->SetLayers(h.View().Choices().layers | kLayerShapes);
    h.Frames(2);
    CHECK(h.ClickButton("##panel", "Verdict"));
}

TEST_CASE("A Numbers row whose label is wider than the side panel wraps between words", "[app]")
{
    // circle_corner's verdict names its deciding axis "deciding axis 3, the axis from box's vertex 2 to ball's
    // centre", wider than the side panel: the line ran past the panel's edge, cut at "ball's cen". Nothing the
    // panel lays out runs past its inner edge, and the label's last word is shown.
    Harness h(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/circle_corner.json");
    h.Frames(3);
    ImGuiWindow* panel = nullptr;
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
    {
        if (w->Active && std::string(w->Name) == "##panel")
        {
            panel = w;
        }
    }
    REQUIRE(panel != nullptr);
    const std::string label = "deciding axis 3, the axis from box's vertex 2 to ball's centre:";
    ImGui::NewFrame();
    const float wide = ImGui::CalcTextSize(label.c_str()).x;
    ImGui::EndFrame();
    CHECK(wide > panel->ContentRegionRect.GetWidth()); // the case at hand
    CHECK(panel->ContentSize.x <= panel->ContentRegionRect.GetWidth() + 0.5f);
}
