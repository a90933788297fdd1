// SPDX-License-Identifier: MIT
// satviz app: the user's actions on the document and the viewer. The interface that calls them is in panels.cpp
// and canvas.cpp.
#include "app.h"

#include "outline_edit.h"

#include <satviz/scene_world.h>
#include <satviz/world_cut.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

namespace satviz
{

namespace
{

std::string UniqueName(const Scene& scene, const std::string& stem)
{
    for (int i = 1;; ++i)
    {
        const std::string name = stem + std::to_string(i);
        if (std::none_of(scene.bodies.begin(), scene.bodies.end(), [&](const Body& b) { return b.name == name; }))
        {
            return name;
        }
    }
}

} // namespace

std::string FindBundledScenes(const std::filesystem::path& programDir, const std::filesystem::path& dataDir)
{
    std::error_code code;
    const std::filesystem::path data = (programDir / dataDir / "scenes").lexically_normal();
    if (std::filesystem::is_directory(data, code))
    {
        return data.string();
    }
    for (std::filesystem::path dir = programDir; !dir.empty(); dir = dir.parent_path())
    {
        const std::filesystem::path source = dir / "tutorials" / "scenes";
        if (std::filesystem::is_directory(source, code))
        {
            return source.string();
        }
        if (dir == dir.parent_path())
        {
            break;
        }
    }
    return "";
}

App::App(const FigureFonts& fonts, AppOptions options)
    : fonts_(fonts), options_(std::move(options)), viewer_(options_.backgroundVertices), panels_(*this),
      recent_(options_.recentFile, options_.updateRecent)
{
    if (options_.lessonsDir.empty() && !options_.scenesDir.empty())
    {
        options_.lessonsDir = std::filesystem::path(options_.scenesDir).parent_path().string();
    }
    if (!options_.lessonsDir.empty())
    {
        lessons_ = FindLessons(options_.lessonsDir);
    }
}

void App::Frame()
{
    TakeFinishedTest();
    panels_.Shortcuts();
    viewer_.Advance(ImGui::GetIO().DeltaTime);
    if (sim_.Advance(ImGui::GetIO().DeltaTime))
    {
        Refresh();
    }
    panels_.Draw();
}

double App::SecondsUntilChange() const
{
    if (viewer_.Studying())
    {
        return 0.03; // the worker thread's figure is taken in by a frame
    }
    double change = -1.0;
    if (viewer_.Playing())
    {
        change = viewer_.SecondsUntilNextStep();
    }
    if (sim_.Playing())
    {
        change = change < 0.0 ? sim_.SecondsUntilNextStep() : std::min(change, sim_.SecondsUntilNextStep());
    }
    return change;
}

// [SECTION] Files

bool App::Open(const std::string& path)
{
    const OpenResult opened = document_.Open(path, options_.scenesDir);
    if (!opened.ok)
    {
        SetStatus(opened.error, true);
        return false;
    }
    selected_ = -1;
    viewer_.Reset(document_.GetScene());
    sim_ = Simulation{};
    Refresh();
    const int simSteps = opened.simSteps;
    if (simSteps > 0 && sim_.Error().empty())
    {
        // The view asks for the bodies where these steps leave them: the simulation takes them, so that the
        // scene opens there, ready to play on or to go back to step 0.
        while (sim_.Shown() < simSteps)
        {
            sim_.StepForward();
        }
        Refresh();
    }
    recent_.Remember(path);
    SetStatus("Opened " + path +
                  (simSteps > 0
                       ? ", after " + std::to_string(simSteps) + " rigid-body step" + (simSteps == 1 ? "" : "s") +
                             " of the simulation (its view's sim_steps; Reset goes back to the scene as written)"
                       : "") +
                  (document_.ReadOnly() ? " (a bundled scene: Save asks for a new file)" : ""),
              false);
    return true;
}

bool App::RequestOpen(const std::string& path)
{
    if (!document_.Dirty())
    {
        return Open(path);
    }
    pendingOpen_ = path;
    panels_.AskBeforeOpening();
    return false;
}

bool App::Save(const std::string& path)
{
    std::string error;
    if (!document_.Save(SceneForSaving(), path, error))
    {
        SetStatus(error, true);
        return false;
    }
    recent_.Remember(path);
    SetStatus("Saved " + path, false);
    return true;
}

Scene App::SceneForSaving() const
{
    Scene saved = document_.GetScene();
    viewer_.WriteView(saved);
    // The step of the simulation shown: satviz-render steps the scene as far, to the same bits.
    saved.view.simSteps = sim_.Error().empty() ? sim_.Shown() : 0;
    return saved;
}

FigureSetup App::ExportFigure() const
{
    return SetUpFigure(SceneForSaving(), {});
}

void App::RequestExport()
{
    exportRequested_ = true;
    std::filesystem::path target = options_.exportPath;
    if (target.empty())
    {
        const std::filesystem::path base = document_.File().empty() ? "satviz.json" : document_.File();
        target = base.parent_path() / (base.stem().string() + "-step" + std::to_string(viewer_.Step() + 1) + ".png");
    }
    exportPath_ = target.string();
}

bool App::TakeExportRequest(std::string& path)
{
    if (!exportRequested_)
    {
        return false;
    }
    exportRequested_ = false;
    path = exportPath_;
    return true;
}

std::vector<std::string> App::BundledScenes() const
{
    std::vector<std::string> files;
    std::error_code code;
    for (const auto& entry : std::filesystem::directory_iterator(options_.scenesDir, code))
    {
        if (entry.path().extension() == ".json")
        {
            files.push_back(entry.path().string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

bool App::RequestQuit()
{
    if (!document_.Dirty() || quitConfirmed_)
    {
        quitConfirmed_ = true;
        return true;
    }
    panels_.AskBeforeQuitting();
    return false;
}

// [SECTION] The document

bool App::Undo()
{
    ViewChoices choices = viewer_.Choices();
    if (!document_.Undo(choices))
    {
        return false;
    }
    viewer_.SetChoices(choices);
    selected_ = std::min(selected_, static_cast<int>(document_.GetScene().bodies.size()) - 1);
    Refresh();
    ClearError();
    return true;
}

bool App::Redo()
{
    ViewChoices choices = viewer_.Choices();
    if (!document_.Redo(choices))
    {
        return false;
    }
    viewer_.SetChoices(choices);
    selected_ = std::min(selected_, static_cast<int>(document_.GetScene().bodies.size()) - 1);
    Refresh();
    ClearError();
    return true;
}

bool App::BodyExists(int index) const
{
    return index >= 0 && index < static_cast<int>(document_.GetScene().bodies.size());
}

void App::BeginEdit()
{
    if (!document_.EditOpen())
    {
        stateTaken_ = false;
        sim_.SetPlaying(false);
    }
    document_.BeginEdit(viewer_.Choices());
}

void App::EndEdit()
{
    document_.CommitEdit();
    stateTaken_ = false;
}

void App::TakeShownState()
{
    if (stateTaken_ || sim_.Shown() == 0 || !sim_.Error().empty())
    {
        return;
    }
    stateTaken_ = true;
    const int step = sim_.Shown();
    const Scene& shown = sim_.ShownScene();
    for (size_t i = 0; i < shown.bodies.size(); ++i)
    {
        Body& body = document_.EditBody(i);
        body.position = shown.bodies[i].position;
        body.angle = shown.bodies[i].angle;
        body.velocity = shown.bodies[i].velocity;
        body.angularVelocity = shown.bodies[i].angularVelocity;
    }
    SetStatus("Edited the bodies as they are at step " + std::to_string(step) +
                  ": that state is now the scene, step 0 (ctrl+z goes back to step " + std::to_string(step) + ")",
              false);
}

Body& App::EditBody(int index)
{
    TakeShownState();
    return document_.EditBody(static_cast<size_t>(index));
}

const Scene& App::ShownScene() const
{
    return sim_.Shown() > 0 && sim_.Error().empty() ? sim_.ShownScene() : document_.GetScene();
}

void App::MoveBody(int index, Vec2 position)
{
    // No change is no edit: a click on a body at a later step leaves that step shown.
    if (!BodyExists(index) || ShownScene().bodies[static_cast<size_t>(index)].position == position)
    {
        return;
    }
    const bool single = !document_.EditOpen();
    BeginEdit();
    EditBody(index).position = position;
    if (single)
    {
        EndEdit();
    }
    Refresh();
}

void App::TurnBody(int index, double angle)
{
    // No change is no edit: a click on a body at a later step leaves that step shown.
    if (!BodyExists(index) || ShownScene().bodies[static_cast<size_t>(index)].angle == angle)
    {
        return;
    }
    const bool single = !document_.EditOpen();
    BeginEdit();
    EditBody(index).angle = angle;
    if (single)
    {
        EndEdit();
    }
    Refresh();
}

void App::SetVelocity(int index, Vec2 velocity)
{
    // No change is no edit: a click on a body at a later step leaves that step shown.
    if (!BodyExists(index) || ShownScene().bodies[static_cast<size_t>(index)].velocity == velocity)
    {
        return;
    }
    const bool single = !document_.EditOpen();
    BeginEdit();
    EditBody(index).velocity = velocity;
    if (single)
    {
        EndEdit();
    }
    Refresh();
}

bool App::MoveVertex(int index, int vertex, Vec2 world)
{
    if (!BodyExists(index))
    {
        return false;
    }
    const Body& body = ShownScene().bodies[static_cast<size_t>(index)];
    std::vector<Vec2> outline = EditableOutline(body);
    if (vertex < 0 || vertex >= static_cast<int>(outline.size()))
    {
        return false;
    }
    const Vec2 local = InvTransformPoint(body.Xf(), world);
    if (outline[static_cast<size_t>(vertex)] == local)
    {
        return true;
    }
    outline[static_cast<size_t>(vertex)] = local;
    Body reshaped = body;
    if (const std::string why = ReshapeToOutline(reshaped, outline); !why.empty())
    {
        // During a drag the vertex has followed the pointer as far as the outline stayed simple: it stays there,
        // which is where it was only when the first move was refused.
        SetStatus("Vertex " + std::to_string(vertex) +
                      " stays at its last position that keeps the polygon simple: at the pointer, the " + why,
                  true);
        Refresh();
        return false;
    }
    const bool single = !document_.EditOpen();
    BeginEdit();
    Body& edited = EditBody(index);
    edited.shape = std::move(reshaped.shape);
    edited.concave = std::move(reshaped.concave);
    edited.outline = std::move(reshaped.outline);
    if (single)
    {
        EndEdit();
    }
    ClearError();
    Refresh();
    return true;
}

bool App::AddDrawnPolygon(const std::vector<Vec2>& vertices)
{
    if (vertices.size() < 3)
    {
        SetStatus("A polygon needs at least three vertices", true);
        return false;
    }
    Body body;
    body.name = UniqueName(document_.GetScene(), "polygon");
    body.position = OutlineCentroid(vertices);
    std::vector<Vec2> local;
    for (const Vec2& v : vertices)
    {
        local.push_back(v - body.position);
    }
    if (const std::string why = ReshapeToOutline(body, local); !why.empty())
    {
        SetStatus("The drawn polygon was not added: the " + why, true);
        return false;
    }
    const size_t pieces = body.IsConcave() ? body.concave.parts.size() : 1;
    const std::string name = body.name;
    BeginEdit();
    TakeShownState();
    document_.AddBody(std::move(body));
    selected_ = static_cast<int>(document_.GetScene().bodies.size()) - 1;
    EndEdit();
    Refresh();
    SetStatus("Added " + name + ": " + std::to_string(vertices.size()) + " vertices, " +
                  (pieces == 1 ? std::string("convex") : std::to_string(pieces) + " convex pieces"),
              false);
    return true;
}

int App::CutAlong(Vec2 a, Vec2 b)
{
    const Scene shown = ShownScene();
    if (const std::string why = ValidateSceneWorld(shown); !why.empty())
    {
        SetStatus("Nothing was cut: " + why, true);
        return 0;
    }
    // The world of the state shown: CutBody gives each part its mass and its share of the motion.
    World world = MakeWorld(shown);
    struct Done
    {
        size_t index;
        BodyCut cut;
    };
    std::vector<Done> done;
    std::string why;
    for (size_t i = 0; i < shown.bodies.size(); ++i)
    {
        if (shown.bodies[i].shape.type != ShapeType::Polygon)
        {
            continue;
        }
        CutOptions options;
        options.method = shown.bodies[i].decompose;
        BodyCut cut = CutBody(world, static_cast<int>(i), a, b, options);
        if (cut.cut)
        {
            done.push_back({i, std::move(cut)});
        }
        else if (why.empty() && cut.reason != "the segment does not cut the body from side to side")
        {
            why = shown.bodies[i].name + ": " + cut.reason;
        }
    }
    if (done.empty())
    {
        SetStatus(why.empty() ? "Nothing was cut: draw the cut across a polygon, from outside to outside"
                              : "Nothing was cut: " + why,
                  true);
        return 0;
    }
    BeginEdit();
    TakeShownState();
    std::string said;
    int slivers = 0;
    for (const Done& d : done)
    {
        const Body original = shown.bodies[d.index];
        std::vector<std::string> names;
        for (size_t k = 0; k < d.cut.bodies.size(); ++k)
        {
            Body part = original;
            const RigidBody& rigid = world.bodies[static_cast<size_t>(d.cut.bodies[k])];
            // The scene's body frame is the world body's, so the part's outline is the cut's as it stands.
            ReshapeToOutline(part, d.cut.outlines[k]);
            if (!original.isStatic)
            {
                part.velocity = rigid.velocity;
                part.angularVelocity = rigid.angularVelocity;
            }
            if (k == 0)
            {
                document_.EditBody(d.index) = std::move(part);
                names.push_back(original.name);
            }
            else
            {
                part.name = UniqueName(document_.GetScene(), original.name + ".");
                names.push_back(part.name);
                document_.AddBody(std::move(part));
            }
        }
        slivers += d.cut.slivers;
        said += (said.empty() ? "Cut " : "; cut ") + original.name + " into";
        for (size_t k = 0; k < names.size(); ++k)
        {
            said += (k == 0 ? " " : (k + 1 == names.size() ? " and " : ", ")) + names[k];
        }
    }
    if (slivers > 0)
    {
        char area[32];
        std::snprintf(area, sizeof area, "%g", kMinCutArea);
        said += " (" + std::to_string(slivers) + (slivers == 1 ? " sliver" : " slivers") + " below " + area +
                " square units dropped)";
    }
    EndEdit();
    Refresh();
    SetStatus(said, false);
    return static_cast<int>(done.size());
}

void App::AddBody(Shape shape, const std::string& stem)
{
    BeginEdit();
    TakeShownState();
    Body body;
    body.name = UniqueName(document_.GetScene(), stem);
    body.shape = std::move(shape);
    body.position = viewer_.Camera().center;
    const std::string name = body.name;
    document_.AddBody(std::move(body));
    selected_ = static_cast<int>(document_.GetScene().bodies.size()) - 1;
    EndEdit();
    Refresh();
    SetStatus("Added " + name + ": drag it into place", false);
}

void App::DeleteSelected()
{
    if (!BodyExists(selected_))
    {
        SetStatus("Select a body first (click it)", true);
        return;
    }
    if (document_.GetScene().bodies.size() <= 2)
    {
        SetStatus("The scene keeps at least two bodies: add one before deleting this one", true);
        return;
    }
    BeginEdit();
    TakeShownState();
    const std::string name = document_.GetScene().bodies[static_cast<size_t>(selected_)].name;
    document_.RemoveBody(static_cast<size_t>(selected_));
    selected_ = -1;
    EndEdit();
    Refresh();
    SetStatus("Deleted " + name, false);
}

// [SECTION] The viewer

void App::ChangeChoices(const ViewChoices& choices)
{
    if (choices == viewer_.Choices())
    {
        return;
    }
    document_.RecordChoices(viewer_.Choices());
    viewer_.SetChoices(choices);
    Refresh();
}

void App::SetPair(const std::string& bodyA, const std::string& bodyB)
{
    const Viewer& viewer = viewer_;
    if (viewer.TestsPair())
    {
        // The pair shown may come from the scene's first two bodies rather than from names: naming it is no change.
        const Scene& studied = viewer.Studied();
        if (studied.bodies[static_cast<size_t>(viewer.Setup().study.bodyA)].name == bodyA &&
            studied.bodies[static_cast<size_t>(viewer.Setup().study.bodyB)].name == bodyB)
        {
            return;
        }
    }
    ViewChoices choices = viewer_.Choices();
    choices.bodyA = bodyA;
    choices.bodyB = bodyB;
    ChangeChoices(choices);
}

void App::SetQuery(ViewQuery query)
{
    ViewChoices choices = viewer_.Choices();
    choices.query = query;
    ChangeChoices(choices);
}

void App::SetStepView(StepView steps)
{
    ViewChoices choices = viewer_.Choices();
    choices.steps = steps;
    ChangeChoices(choices);
}

void App::SetPitfall(Pitfall pitfall)
{
    ViewChoices choices = viewer_.Choices();
    choices.pitfall = pitfall;
    ChangeChoices(choices);
}

void App::SetPrecision(bool singlePrecision)
{
    ViewChoices choices = viewer_.Choices();
    choices.singlePrecision = singlePrecision;
    ChangeChoices(choices);
}

void App::SetLayers(LayerMask layers)
{
    ViewChoices choices = viewer_.Choices();
    choices.layers = layers & kAllLayers;
    ChangeChoices(choices);
}

void App::FitCamera()
{
    viewer_.FitCamera();
    Refresh();
}

void App::PlaceCanvas(ScreenPoint origin, int width, int height)
{
    if (viewer_.PlaceCanvas(origin, width, height))
    {
        Refresh();
    }
}

void App::Refresh()
{
    const Scene& scene = document_.GetScene();
    if (!sim_.StartedFrom(scene))
    {
        const int was = sim_.Shown();
        sim_.Restart(scene, -1, -1);
        if (was > 0 && sim_.Shown() > 0 && !document_.EditOpen())
        {
            SetStatus("Back at step " + std::to_string(sim_.Shown()) + " of the simulation", false);
        }
    }
    bool fresh = false;
    if (sim_.Shown() > 0 && sim_.Error().empty())
    {
        Scene shown = scene;
        CopyWorldState(sim_.Record().world, shown);
        // The scene's caption describes it as written, at step 0.
        char caption[120];
        std::snprintf(caption, sizeof caption, "After %d step%s of the simulation (time %.4g)", sim_.Shown(),
                      sim_.Shown() == 1 ? "" : "s", sim_.Record().world.time);
        shown.view.caption = caption;
        fresh = viewer_.Refresh(shown);
    }
    else
    {
        fresh = viewer_.Refresh(scene);
    }
    if (viewer_.TestsPair())
    {
        sim_.ChoosePair(viewer_.Setup().study.bodyA, viewer_.Setup().study.bodyB);
    }
    viewer_.SetSim(sim_.Error().empty() ? &sim_.Record() : nullptr);
    // A hit chosen is one of its step's: another step shows every hit again.
    viewer_.SetHit(sim_.Error().empty() && sim_.Shown() == simHitStep_ &&
                           simHit_ < static_cast<int>(sim_.Record().lastStep.hits.size())
                       ? simHit_
                       : -1);
    if (fresh && !viewer_.Setup().Ok())
    {
        SetStatus(viewer_.Setup().error, true);
    }
}

// [SECTION] The simulation

void App::SimPlay(bool playing)
{
    sim_.SetPlaying(playing);
    if (playing && !sim_.Error().empty())
    {
        SetStatus("This scene cannot be stepped as a world: " + sim_.Error(), true);
    }
}

void App::SimForward()
{
    sim_.SetPlaying(false);
    sim_.StepForward();
    Refresh();
}

void App::SimBack()
{
    sim_.SetPlaying(false);
    sim_.StepBack();
    Refresh();
}

void App::SimShowStep(int step)
{
    sim_.SetPlaying(false);
    sim_.ShowStep(step);
    Refresh();
}

void App::SimReset()
{
    SimShowStep(0);
}

void App::SimSpeed(double stepsPerSecond)
{
    sim_.SetSpeed(stepsPerSecond);
}

void App::SimHand(int index, Vec2 position, Vec2 pointerVelocity)
{
    if (!BodyExists(index) || !sim_.Error().empty())
    {
        return;
    }
    // Simulated time runs Speed() * dt times as fast as the user's.
    const double rate = sim_.Speed() * sim_.Record().dt;
    sim_.Hand(index, position, rate > 0.0 ? (1.0 / rate) * pointerVelocity : pointerVelocity);
    Refresh();
}

void App::SimChooseHit(int hit)
{
    sim_.SetPlaying(false);
    const bool again = hit == simHit_ && simHitStep_ == sim_.Shown();
    simHit_ = again ? -1 : hit;
    simHitStep_ = sim_.Shown();
    Refresh();
}

void App::SimChooseContact(int a, int b)
{
    const Scene& scene = document_.GetScene();
    if (a < 0 || b < 0 || a >= static_cast<int>(scene.bodies.size()) || b >= static_cast<int>(scene.bodies.size()))
    {
        return;
    }
    SetPair(scene.bodies[static_cast<size_t>(a)].name, scene.bodies[static_cast<size_t>(b)].name);
}

void App::SetMaterial(int index, bool isStatic, double density, const Material& material)
{
    if (!BodyExists(index))
    {
        return;
    }
    const Body& now = ShownScene().bodies[static_cast<size_t>(index)];
    if (now.isStatic == isStatic && now.density == density && now.material.restitution == material.restitution &&
        now.material.friction == material.friction && now.material.staticFriction == material.staticFriction)
    {
        return;
    }
    const bool single = !document_.EditOpen();
    BeginEdit();
    Body& body = EditBody(index);
    body.isStatic = isStatic;
    body.density = density;
    body.material = material;
    if (single)
    {
        EndEdit();
    }
    Refresh();
}

void App::TakeFinishedTest()
{
    if (!viewer_.TakeFinishedTest())
    {
        return;
    }
    if (!viewer_.Setup().Ok())
    {
        SetStatus(viewer_.Setup().error, true);
    }
    if (viewer_.TakeRetest())
    {
        Refresh();
    }
    else if (!statusIsError_)
    {
        SetStatus("Tested the pair (" + std::to_string(viewer_.PairVertices(document_.GetScene())) +
                      " vertices) in the background",
                  false);
    }
}

// [SECTION] Lessons and the status line

bool App::OpenLesson(int index)
{
    if (index < 0 || index >= static_cast<int>(lessons_.size()))
    {
        return false;
    }
    const Lesson& lesson = lessons_[static_cast<size_t>(index)];
    std::vector<LessonBlock> blocks;
    std::string error;
    if (!LoadLesson(lesson.file, blocks, error))
    {
        SetStatus(error, true);
        return false;
    }
    lesson_ = index;
    lessonBlocks_ = std::move(blocks);
    lessonShown_ = true;
    panels_.ScrollLessonToTop();
    if (!lesson.scenes.empty() && lesson.scenes.front() != document_.File())
    {
        RequestOpen(lesson.scenes.front());
    }
    return true;
}

void App::SetStatus(const std::string& message, bool error)
{
    status_ = message;
    statusIsError_ = error;
}

void App::ClearError()
{
    // An error said why an edit was refused or failed: after an undo or a redo it no longer describes the scene.
    if (statusIsError_ && viewer_.Setup().Ok())
    {
        SetStatus("", false);
    }
}

} // namespace satviz
