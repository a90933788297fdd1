// SPDX-License-Identifier: MIT
// satviz app: the user's actions on the document and the viewer. The interface that calls them is in panels.cpp
// and canvas.cpp.
#include "app.h"

#include "outline_edit.h"

#include <satviz/render/describe.h>
#include <satviz/render/response_steps.h>
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

namespace
{

// True when `path` is a file of `folder` (not of a folder in it).
bool InFolder(const std::string& path, const std::string& folder)
{
    std::error_code code;
    return std::filesystem::weakly_canonical(std::filesystem::path(path).parent_path(), code) ==
           std::filesystem::weakly_canonical(folder, code);
}

} // namespace

App::App(const FigureFonts& fonts, AppOptions options)
    : m_fonts(fonts), m_options(std::move(options)), m_viewer(m_options.backgroundVertices), m_panels(*this),
      m_recent(m_options.recentFile, m_options.updateRecent), m_unsaved(m_options.unsavedDir)
{
    if (m_options.lessonsDir.empty() && !m_options.scenesDir.empty())
    {
        m_options.lessonsDir = std::filesystem::path(m_options.scenesDir).parent_path().string();
    }
    if (!m_options.lessonsDir.empty())
    {
        m_lessons = FindLessons(m_options.lessonsDir);
    }
}

void App::Frame()
{
    TakeFinishedTest();
    m_panels.Shortcuts();
    m_viewer.Advance(ImGui::GetIO().DeltaTime);
    if (m_sim.Advance(ImGui::GetIO().DeltaTime))
    {
        Refresh();
    }
    m_panels.Draw();
    KeepUnsavedCopy();
    if (m_statusLeft >= 0.0)
    {
        m_statusLeft -= ImGui::GetIO().DeltaTime;
        if (m_statusLeft < 0.0 || m_document.Revision() != m_statusRevision || m_viewer.Step() != m_statusStep ||
            m_sim.Shown() != m_statusSimStep)
        {
            SetStatus("", false);
        }
    }
}

// The scene is copied as each change is committed, not while a drag goes on: a crash in the middle of a drag loses
// that drag at most.
void App::KeepUnsavedCopy()
{
    if (m_document.Revision() == m_copiedRevision)
    {
        return;
    }
    m_copiedRevision = m_document.Revision();
    if (!m_document.Dirty())
    {
        m_unsaved.Drop();
        return;
    }
    std::string error;
    if (!m_unsaved.Keep(SceneForSaving(), m_document.File(), error))
    {
        SetStatus("Unsaved changes cannot be kept aside: " + error, true);
    }
}

bool App::ReportLeftCopies()
{
    if (m_options.unsavedDir.empty())
    {
        return false;
    }
    const std::vector<std::string> left = LeftUnsavedCopies(m_options.unsavedDir);
    if (left.empty())
    {
        return false;
    }
    SetPassingStatus("satviz ended before these changes were saved; they are in " + left.front() +
                     (left.size() > 1 ? " (and " + std::to_string(left.size() - 1) + " more in that folder)" : "") +
                     ": File > Open to take them back");
    return true;
}

double App::SecondsUntilChange() const
{
    if (m_viewer.Studying())
    {
        return 0.03; // the worker thread's figure is taken in by a frame
    }
    double change = -1.0;
    if (m_viewer.Playing())
    {
        change = m_viewer.SecondsUntilNextStep();
    }
    if (m_sim.Playing())
    {
        change = change < 0.0 ? m_sim.SecondsUntilNextStep() : std::min(change, m_sim.SecondsUntilNextStep());
    }
    if (m_statusLeft >= 0.0)
    {
        // A frame when the passing message is due to go, so that an idle window does not keep it.
        change = change < 0.0 ? m_statusLeft : std::min(change, m_statusLeft);
    }
    return change;
}

// [SECTION] Files

bool App::Open(const std::string& path, int step, bool faces)
{
    const OpenResult opened = m_document.Open(path, m_options.scenesDir);
    if (!opened.ok)
    {
        SetStatus(opened.error, true);
        return false;
    }
    m_selected = -1;
    m_viewer.Reset(m_document.GetScene());
    if (faces)
    {
        // A choice of view, not an edit: nothing to undo, nothing to save.
        ViewChoices choices = m_viewer.Choices();
        choices.steps = StepView::Faces;
        m_viewer.SetChoices(choices);
    }
    if (step >= 0)
    {
        // Before the test is taken in: the viewer keeps the step and shows it once the test is done.
        m_viewer.ShowStep(step);
    }
    m_sim = Simulation{};
    Refresh();
    const int simSteps = opened.simSteps;
    if (simSteps > 0 && m_sim.Error().empty())
    {
        // The view asks for the bodies where these steps leave them: the simulation takes them, so that the
        // scene opens there, ready to play on or to go back to step 0.
        while (m_sim.Shown() < simSteps)
        {
            m_sim.StepForward();
        }
        Refresh();
    }
    m_recent.Remember(path);
    m_takenBack.clear();
    // A view.step past the figure's last step (the test taken in by now; a large pair's says it once its test is).
    const std::string stepNotice = m_viewer.TakeStepNotice();
    if (!m_options.unsavedDir.empty() && InFolder(path, m_options.unsavedDir))
    {
        // Changes an app left when it ended without saving: saved to a file of the user's, the copy goes.
        m_takenBack = path;
        m_document.AskForAnotherFile();
        SetStatus("Opened " + path + ", changes kept when satviz ended before saving them: Save asks for a file "
                                     "to keep them in, then this copy is removed",
                  false);
        return true;
    }
    if (!stepNotice.empty())
    {
        SetStatus(path + ": " + stepNotice, true);
        return true;
    }
    SetStatus("Opened " + path +
                  (simSteps > 0
                       ? ", after " + std::to_string(simSteps) + " rigid-body step" + (simSteps == 1 ? "" : "s") +
                             " of the simulation (its view's sim_steps; Reset goes back to the scene as written)"
                       : "") +
                  (m_document.ReadOnly() ? " (a bundled scene: Save asks for a new file)" : ""),
              false);
    return true;
}

bool App::RequestOpen(const std::string& path, int step, bool faces)
{
    if (!m_document.Dirty())
    {
        return Open(path, step, faces);
    }
    m_pendingOpen = path;
    m_pendingStep = step;
    m_pendingFaces = faces;
    m_panels.AskBeforeOpening();
    return false;
}

bool App::Save(const std::string& given)
{
    // The path in full, so that the status and the title say in which folder a relative one went.
    std::error_code code;
    const std::filesystem::path full = std::filesystem::absolute(given, code).lexically_normal();
    const std::string path = code ? given : full.string();
    std::string error;
    if (!m_document.Save(SceneForSaving(), path, error))
    {
        SetStatus(error, true);
        return false;
    }
    m_recent.Remember(path);
    SetStatus("Saved " + path, false);
    if (!m_takenBack.empty() && !InFolder(path, m_options.unsavedDir))
    {
        std::error_code code;
        std::filesystem::remove(m_takenBack, code);
        m_takenBack.clear();
    }
    return true;
}

Scene App::SceneForSaving() const
{
    Scene saved = m_document.GetScene();
    m_viewer.WriteView(saved);
    // The step of the simulation shown: satviz-render steps the scene as far, to the same bits.
    saved.view.simSteps = m_sim.Error().empty() ? m_sim.Shown() : 0;
    return saved;
}

FigureSetup App::ExportFigure() const
{
    return SetUpFigure(SceneForSaving(), {});
}

void App::RequestExport()
{
    m_exportRequested = true;
    std::filesystem::path target = m_options.exportPath;
    if (target.empty())
    {
        const std::filesystem::path base = m_document.File().empty() ? "satviz.json" : m_document.File();
        target = base.parent_path() / (base.stem().string() + "-step" + std::to_string(m_viewer.Step() + 1) + ".png");
    }
    m_exportPath = target.string();
}

bool App::TakeExportRequest(std::string& path)
{
    if (!m_exportRequested)
    {
        return false;
    }
    m_exportRequested = false;
    path = m_exportPath;
    return true;
}

std::vector<std::string> App::BundledScenes() const
{
    std::vector<std::string> files;
    std::error_code code;
    for (const auto& entry : std::filesystem::directory_iterator(m_options.scenesDir, code))
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
    if (!m_document.Dirty() || m_quitConfirmed)
    {
        m_quitConfirmed = true;
        return true;
    }
    m_panels.AskBeforeQuitting();
    return false;
}

// [SECTION] The document

bool App::Undo()
{
    ViewChoices choices = m_viewer.Choices();
    if (!m_document.Undo(choices))
    {
        return false;
    }
    m_viewer.SetChoices(choices);
    m_selected = std::min(m_selected, static_cast<int>(m_document.GetScene().bodies.size()) - 1);
    Refresh();
    ClearError();
    return true;
}

bool App::Redo()
{
    ViewChoices choices = m_viewer.Choices();
    if (!m_document.Redo(choices))
    {
        return false;
    }
    m_viewer.SetChoices(choices);
    m_selected = std::min(m_selected, static_cast<int>(m_document.GetScene().bodies.size()) - 1);
    Refresh();
    ClearError();
    return true;
}

bool App::BodyExists(int index) const
{
    return index >= 0 && index < static_cast<int>(m_document.GetScene().bodies.size());
}

void App::BeginEdit()
{
    if (!m_document.EditOpen())
    {
        m_stateTaken = false;
        m_sim.SetPlaying(false);
    }
    m_document.BeginEdit(m_viewer.Choices());
}

void App::EndEdit()
{
    m_document.CommitEdit();
    m_stateTaken = false;
}

void App::TakeShownState()
{
    if (m_stateTaken || m_sim.Shown() == 0 || !m_sim.Error().empty())
    {
        return;
    }
    m_stateTaken = true;
    const int step = m_sim.Shown();
    const Scene& shown = m_sim.ShownScene();
    for (size_t i = 0; i < shown.bodies.size(); ++i)
    {
        Body& body = m_document.EditBody(i);
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
    return m_document.EditBody(static_cast<size_t>(index));
}

const Scene& App::ShownScene() const
{
    return m_sim.Shown() > 0 && m_sim.Error().empty() ? m_sim.ShownScene() : m_document.GetScene();
}

void App::MoveBody(int index, Vec2 position)
{
    // No change is no edit: a click on a body at a later step leaves that step shown.
    if (!BodyExists(index) || ShownScene().bodies[static_cast<size_t>(index)].position == position)
    {
        return;
    }
    const bool single = !m_document.EditOpen();
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
    const bool single = !m_document.EditOpen();
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
    const bool single = !m_document.EditOpen();
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
    const bool single = !m_document.EditOpen();
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
    body.name = UniqueName(m_document.GetScene(), "polygon");
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
    m_document.AddBody(std::move(body));
    m_selected = static_cast<int>(m_document.GetScene().bodies.size()) - 1;
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
                m_document.EditBody(d.index) = std::move(part);
                names.push_back(original.name);
            }
            else
            {
                part.name = UniqueName(m_document.GetScene(), original.name + ".");
                names.push_back(part.name);
                m_document.AddBody(std::move(part));
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
    body.name = UniqueName(m_document.GetScene(), stem);
    body.shape = std::move(shape);
    body.position = m_viewer.Camera().center;
    const std::string name = body.name;
    m_document.AddBody(std::move(body));
    m_selected = static_cast<int>(m_document.GetScene().bodies.size()) - 1;
    EndEdit();
    Refresh();
    SetStatus("Added " + name + ": drag it into place", false);
}

void App::DeleteSelected()
{
    if (!BodyExists(m_selected))
    {
        SetStatus("Select a body first (click it)", true);
        return;
    }
    if (m_document.GetScene().bodies.size() <= 2)
    {
        SetStatus("The scene keeps at least two bodies: add one before deleting this one", true);
        return;
    }
    BeginEdit();
    TakeShownState();
    const std::string name = m_document.GetScene().bodies[static_cast<size_t>(m_selected)].name;
    m_document.RemoveBody(static_cast<size_t>(m_selected));
    m_selected = -1;
    EndEdit();
    Refresh();
    SetStatus("Deleted " + name, false);
}

// [SECTION] The viewer

void App::ChangeChoices(const ViewChoices& choices)
{
    if (choices == m_viewer.Choices())
    {
        return;
    }
    m_document.RecordChoices(m_viewer.Choices());
    m_viewer.SetChoices(choices);
    Refresh();
}

void App::SetPair(const std::string& bodyA, const std::string& bodyB)
{
    const Viewer& viewer = m_viewer;
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
    ViewChoices choices = m_viewer.Choices();
    choices.bodyA = bodyA;
    choices.bodyB = bodyB;
    ChangeChoices(choices);
}

void App::SetQuery(ViewQuery query)
{
    ViewChoices choices = m_viewer.Choices();
    choices.query = query;
    ChangeChoices(choices);
}

void App::SetStepView(StepView steps)
{
    ViewChoices choices = m_viewer.Choices();
    choices.steps = steps;
    ChangeChoices(choices);
}

void App::SetPitfall(Pitfall pitfall)
{
    ViewChoices choices = m_viewer.Choices();
    choices.pitfall = pitfall;
    ChangeChoices(choices);
}

void App::SetPrecision(bool singlePrecision)
{
    ViewChoices choices = m_viewer.Choices();
    choices.singlePrecision = singlePrecision;
    ChangeChoices(choices);
}

void App::SetLayers(LayerMask layers)
{
    ViewChoices choices = m_viewer.Choices();
    choices.layers = layers & kAllLayers;
    ChangeChoices(choices);
}

void App::FitCamera()
{
    m_viewer.FitCamera();
    Refresh();
}

void App::PlaceCanvas(ScreenPoint origin, int width, int height)
{
    if (m_viewer.PlaceCanvas(origin, width, height))
    {
        Refresh();
    }
}

void App::Refresh()
{
    const Scene& scene = m_document.GetScene();
    if (!m_sim.StartedFrom(scene))
    {
        const int was = m_sim.Shown();
        m_sim.Restart(scene, -1, -1);
        if (was > 0 && m_sim.Shown() > 0 && !m_document.EditOpen())
        {
            SetStatus("Back at step " + std::to_string(m_sim.Shown()) + " of the simulation", false);
        }
    }
    bool fresh = false;
    if (m_sim.Shown() > 0 && m_sim.Error().empty())
    {
        Scene shown = scene;
        CopyWorldState(m_sim.Record().world, shown);
        // The scene's caption describes it as written, at step 0. The time in the digits of the simulation panel.
        shown.view.caption = "After " + std::to_string(m_sim.Shown()) + (m_sim.Shown() == 1 ? " step" : " steps") +
                             " of the simulation (time " +
                             FormatNumber(m_sim.Record().world.time, kResponseDigits) + " s)";
        fresh = m_viewer.Refresh(shown);
    }
    else
    {
        fresh = m_viewer.Refresh(scene);
    }
    if (m_viewer.TestsPair())
    {
        m_sim.ChoosePair(m_viewer.Setup().study.bodyA, m_viewer.Setup().study.bodyB);
    }
    m_viewer.SetSim(m_sim.Error().empty() ? &m_sim.Record() : nullptr);
    // A hit chosen is one of its step's: another step shows every hit again.
    m_viewer.SetHit(m_sim.Error().empty() && m_sim.Shown() == m_simHitStep &&
                           m_simHit < static_cast<int>(m_sim.Record().lastStep.hits.size())
                       ? m_simHit
                       : -1);
    if (fresh && !m_viewer.Setup().Ok())
    {
        SetStatus(m_viewer.Setup().error, true);
    }
}

// [SECTION] The simulation

bool App::CanStep() const
{
    return m_document.GetScene().hasWorld || m_sim.Last() > 0;
}

void App::AddWorld()
{
    if (m_document.GetScene().hasWorld)
    {
        return;
    }
    SceneWorld world;
    world.dt = 1.0 / 60.0;
    const bool single = !m_document.EditOpen();
    BeginEdit();
    m_document.SetWorld(world);
    if (single)
    {
        EndEdit();
    }
    Refresh();
    SetStatus("Added a world: steps of 1/60 s, no gravity; Play steps it (ctrl+z takes the world back)", false);
}

bool App::RefuseStep()
{
    if (CanStep())
    {
        return false;
    }
    SetStatus("This scene has no world block, so it is not stepped: Add a world under Simulation gives it one", true);
    return true;
}

void App::SimPlay(bool playing)
{
    if (playing && RefuseStep())
    {
        return;
    }
    m_sim.SetPlaying(playing);
    if (playing && !m_sim.Error().empty())
    {
        SetStatus("This scene cannot be stepped as a world: " + m_sim.Error(), true);
    }
}

void App::SimForward()
{
    m_sim.SetPlaying(false);
    if (RefuseStep())
    {
        return;
    }
    m_sim.StepForward();
    Refresh();
}

void App::SimBack()
{
    m_sim.SetPlaying(false);
    m_sim.StepBack();
    Refresh();
}

void App::SimShowStep(int step)
{
    m_sim.SetPlaying(false);
    m_sim.ShowStep(step);
    Refresh();
}

void App::SimReset()
{
    const int taken = m_sim.Last();
    const bool back = m_sim.Shown() > 0;
    SimShowStep(0);
    if (back && m_sim.Error().empty())
    {
        // The steps are kept: Reset shows the world where it started (or the oldest step the history holds), it
        // takes none back.
        const std::string where = m_sim.Shown() == 0 ? "at its start, the scene as written,"
                                                     : "at step " + std::to_string(m_sim.Shown()) + ", the oldest held,";
        SetPassingStatus("Reset: the world is back " + where + " after " + std::to_string(taken) +
                         (taken == 1 ? " step" : " steps") + "; Forward and the step slider go through them again");
    }
}

void App::SimSpeed(double stepsPerSecond)
{
    m_sim.SetSpeed(stepsPerSecond);
}

void App::SimHand(int index, Vec2 position, Vec2 pointerVelocity)
{
    if (!BodyExists(index) || !m_sim.Error().empty())
    {
        return;
    }
    // Simulated time runs Speed() * dt times as fast as the user's.
    const double rate = m_sim.Speed() * m_sim.Record().dt;
    m_sim.Hand(index, position, rate > 0.0 ? (1.0 / rate) * pointerVelocity : pointerVelocity);
    Refresh();
}

void App::SimChooseHit(int hit)
{
    m_sim.SetPlaying(false);
    const bool again = hit == m_simHit && m_simHitStep == m_sim.Shown();
    m_simHit = again ? -1 : hit;
    m_simHitStep = m_sim.Shown();
    Refresh();
}

void App::SimChooseContact(int a, int b)
{
    const Scene& scene = m_document.GetScene();
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
    const bool single = !m_document.EditOpen();
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
    if (!m_viewer.TakeFinishedTest())
    {
        return;
    }
    if (!m_viewer.Setup().Ok())
    {
        SetStatus(m_viewer.Setup().error, true);
    }
    if (const std::string stepNotice = m_viewer.TakeStepNotice(); !stepNotice.empty())
    {
        SetStatus(m_document.File() + ": " + stepNotice, true);
    }
    if (m_viewer.TakeRetest())
    {
        Refresh();
    }
    else if (!m_statusIsError)
    {
        SetStatus("Tested the pair (" + std::to_string(m_viewer.PairVertices(m_document.GetScene())) +
                      " vertices) in the background",
                  false);
    }
}

// [SECTION] Lessons and the status line

bool App::OpenLesson(int index)
{
    if (index < 0 || index >= static_cast<int>(m_lessons.size()))
    {
        return false;
    }
    const Lesson& lesson = m_lessons[static_cast<size_t>(index)];
    std::vector<LessonBlock> blocks;
    std::string error;
    if (!LoadLesson(lesson.file, blocks, error))
    {
        SetStatus(error, true);
        return false;
    }
    m_lesson = index;
    m_lessonBlocks = std::move(blocks);
    m_lessonShown = true;
    m_panels.ScrollLessonToTop();
    if (!lesson.scenes.empty() && lesson.scenes.front() != m_document.File())
    {
        RequestOpen(lesson.scenes.front(), lesson.firstStep, lesson.firstFaces);
    }
    else if (!lesson.scenes.empty() && lesson.firstStep >= 0 && !lesson.firstFaces)
    {
        // Its scene is open already (the app starts on overlapping_boxes, lesson 4's): kept as it is, edits and
        // all, but shown at the step the lesson's text begins with.
        m_viewer.ShowStep(lesson.firstStep);
    }
    return true;
}

void App::SetStatus(const std::string& message, bool error)
{
    m_status = message;
    m_statusIsError = error;
    m_statusLeft = -1.0;
}

void App::SetPassingStatus(const std::string& message)
{
    SetStatus(message, false);
    m_statusLeft = kPassingStatusSeconds;
    m_statusRevision = m_document.Revision();
    m_statusStep = m_viewer.Step();
    m_statusSimStep = m_sim.Shown();
}

void App::ClearError()
{
    // An error said why an edit was refused or failed: after an undo or a redo it no longer describes the scene.
    if (m_statusIsError && m_viewer.Setup().Ok())
    {
        SetStatus("", false);
    }
}

} // namespace satviz
