// SPDX-License-Identifier: MIT
// satviz app: the app, without any window system. It joins the document (the scene, its file and its undo history,
// document.h), the viewer (what the canvas shows of it, viewer.h) and the panels (the Dear ImGui interface,
// panels.h), and its methods are the user's actions: the panels call them, and so do the tests. main.cpp owns the
// GLFW window and the OpenGL backend.
#pragma once

#include "document.h"
#include "lessons.h"
#include "panels.h"
#include "recent_files.h"
#include "simulation.h"
#include "unsaved_copy.h"
#include "viewer.h"

#include <satviz/render/figure.h>
#include <satviz/render/imgui_canvas.h>
#include <satviz/scene.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace satviz
{

/// Key codes of the keys the app reads beyond ImGui's own key map (letters and function keys): the window system
/// fills them in (GLFW key codes in main.cpp), tests pick their own.
struct AppKeys
{
    int s = 'S';      ///< ctrl+s saves
    int o = 'O';      ///< ctrl+o opens
    int e = 'E';      ///< ctrl+e exports a PNG
    int q = 'Q';      ///< ctrl+q quits
    int f = 'F';      ///< f frames the pair
    int f1 = 290;     ///< F1 shows the help
    int p = 'P';      ///< p plays or pauses the simulation
    int period = '.'; ///< . shows the simulation's next step
    int comma = ',';  ///< , shows the simulation's step before
    int d = 'D';      ///< d draws a polygon by clicking its vertices
    int x = 'X';      ///< x draws a cut with the mouse
};

/// Start-up choices of the app.
struct AppOptions
{
    std::string scenesDir;    ///< folder of the bundled scenes (the File menu lists them)
    std::string lessonsDir;   ///< folder of the lessons (Help > Lessons); empty: the scenes folder's parent
    std::string recentFile;   ///< where the recent files are remembered; empty: not remembered
    bool updateRecent = true; ///< files opened or saved join the recent list; false: it is shown but left as it is
    std::string exportPath;   ///< where ctrl+e writes the PNG; empty: next to the scene, SCENE-stepN.png
    /// Where a copy of the scene is kept while it has unsaved changes (UnsavedCopy), and where the copies an app
    /// left when it ended without asking are found; empty: no copies.
    std::string unsavedDir;
    AppKeys keys;             ///< key codes
    /// A pair with more vertices than this (A's and B's together) is tested on a worker thread: its traced
    /// queries and the camera fit grow with the square of the count, and above it they take longer than a frame.
    int backgroundVertices = 2048;
    /// Fills a draw command's ClipRect with the colour in its UserCallbackData by clearing (the window system's
    /// scissored glClear): the figure's ground and panels and the big windows' backgrounds are drawn with it
    /// instead of triangles, which a software rasterizer shades pixel by pixel. Null (the tests): triangles.
    ImDrawCallback clearRect = nullptr;
};

/// The folder of the bundled scenes for the program in `programDir`, whose data folder (the lessons, and the scenes
/// in its scenes/) is `programDir / dataDir` ("../share/satviz" beside an install prefix's bin/; the build tree
/// has the same layout, with a link to tutorials/). Else, in a build directory inside the source tree,
/// tutorials/scenes in the nearest ancestor of `programDir` that has one. Empty when neither exists.
std::string FindBundledScenes(const std::filesystem::path& programDir, const std::filesystem::path& dataDir);

/// The interactive app: a document, its viewer and the panels, and the user's actions on them.
class App
{
  public:
    /// An app that draws figures with `fonts` (already in ImGui's font atlas).
    App(const FigureFonts& fonts, AppOptions options);
    App(const App&) = delete;            ///< the panels refer to their app
    App& operator=(const App&) = delete; ///< the panels refer to their app

    /// Builds the whole user interface for one ImGui frame (between NewFrame and Render).
    void Frame();
    /// Seconds until the app changes without input, so that the window system can wait for events until then: the
    /// next step while the steps play, a short while when a test runs on the worker thread; -1 when nothing
    /// changes without input.
    double SecondsUntilChange() const;

    // Files.

    /// Opens a scene file. On failure the current scene stays and the error is shown in the app.
    /// `step` >= 0 shows that step of the textbook test (a lesson's figure "NAME-stepN" is step N - 1), as the
    /// figure a lesson's text speaks of; -1 the step the scene's view asks for. `faces` shows the face tests' steps
    /// (a figure of figures/faces/), whose numbers `step` then counts.
    bool Open(const std::string& file, int step = -1, bool faces = false);
    /// The user wants to open `file` (ctrl+o, the Bundled scenes or Recent menu, a lesson; `step` as for Open): opens
    /// it now when nothing is unsaved, else asks first (save and open, open without saving, cancel) and returns false.
    bool RequestOpen(const std::string& file, int step = -1, bool faces = false);
    /// The step the file RequestOpen waits to open is to show, and in which view (as for Open).
    int PendingStep() const { return m_pendingStep; }
    bool PendingFaces() const { return m_pendingFaces; }
    /// The file RequestOpen waits to open until the unsaved changes are dealt with.
    const std::string& PendingOpen() const { return m_pendingOpen; }
    /// Saves the scene as SceneForSaving() gives it to `file`; true when it was written. The status line says how
    /// it went.
    bool Save(const std::string& file);
    /// The scene as it would be saved now: the bodies and a view block with the current camera (or "fit"), the
    /// canvas size, the layers, the pair, the query, the step and the time.
    Scene SceneForSaving() const;
    /// The figure of the current view, exactly what satviz-render draws from SceneForSaving().
    FigureSetup ExportFigure() const;
    /// Asks main.cpp for a PNG of the current view: at AppOptions::exportPath, else SCENE-stepN.png beside the
    /// scene.
    void RequestExport();
    /// True, once, when the user asked for a PNG export; `path` receives the file to write.
    bool TakeExportRequest(std::string& path);
    /// The bundled scenes (AppOptions::scenesDir), sorted.
    std::vector<std::string> BundledScenes() const;
    /// Recently opened files, newest first.
    const std::vector<std::string>& Recent() const { return m_recent.List(); }

    /// The user wants to close the window: true when the app may close now; with unsaved changes it asks first.
    bool RequestQuit();
    /// The user confirmed quitting (from the unsaved-changes prompt).
    void ConfirmQuit() { m_quitConfirmed = true; }
    /// True once the user confirmed quitting (from the prompt or the menu).
    bool QuitConfirmed() const { return m_quitConfirmed; }

    // The document: the scene, its file, the edit history.

    /// The scene being edited, its file and its history.
    const Document& GetDocument() const { return m_document; }
    /// Undoes the last edit (of the bodies, or of the pair, query, step view, pitfall, precision or layers);
    /// false when there is nothing to undo.
    bool Undo();
    /// Redoes the last undone edit; false when there is nothing to redo.
    bool Redo();
    /// The selected body, -1 for none.
    int Selected() const { return m_selected; }
    /// Selects body `index` (-1: none).
    void Select(int index) { m_selected = index; }
    /// Starts an edit of the bodies that lasts until EndEdit (a drag): it is undone in one step.
    void BeginEdit();
    /// Ends the edit begun by BeginEdit; it goes on the undo stack if it changed the scene.
    void EndEdit();
    /// Moves body `index`'s origin to world point `position`.
    void MoveBody(int index, Vec2 position);
    /// Turns body `index` to `angle` radians, counter-clockwise.
    void TurnBody(int index, double angle);
    /// Sets body `index`'s velocity (world units per time unit: its displacement over one time unit, which is one
    /// step when the scene's dt is 1).
    void SetVelocity(int index, Vec2 velocity);
    /// Moves vertex `vertex` of the outline of polygon body `index` (a concave body's outline as written, a convex
    /// polygon's vertices) to world point `world`. The polygon may become concave: it is decomposed again (the
    /// body's "decompose" method), and a concave one that becomes convex is a convex polygon again. Refused, and
    /// the status line says why, when the outline would cross itself: the vertex stays where it last was (during
    /// a drag, as far as it followed the pointer). True when it moved.
    bool MoveVertex(int index, int vertex, Vec2 world);
    /// Adds the polygon drawn by clicking `vertices` (world points in the order clicked, either orientation,
    /// convex or not), its origin at its centroid, named polygonN, and selects it. Refused, and the status line
    /// says why, for fewer than three vertices or an outline that crosses itself. True when added.
    bool AddDrawnPolygon(const std::vector<Vec2>& vertices);
    /// Cuts every polygon body that the segment from world point `a` to `b` crosses from outline to outline, as
    /// the world cuts a body (CutBody, world_cut.h) in the state shown: each part becomes a body of its own, at the
    /// same place, moving as its points moved; the first part keeps the body's name and index, the others are
    /// named after it (B.1, B.2...) and added after the other bodies; slivers below kMinCutArea are dropped. One
    /// edit. Returns the number of bodies cut; with none, the status line says why.
    int CutAlong(Vec2 a, Vec2 b);
    /// Adds a body of `shape` at the camera's centre, named `stem` with the first free number, and selects it.
    void AddBody(Shape shape, const std::string& stem);
    /// Deletes the selected body; refused (the status line says why) when none is selected or only two are left.
    void DeleteSelected();

    // The viewer: what the canvas shows. Changes of the pair, query, step view, pitfall, precision and layers go on
    // the undo stack and a save writes them, but they leave the scene unmodified: they change how it is looked at,
    // not the scene (Document::Dirty).

    /// The viewer: the choices, the step, the camera, the figure of the pair's test.
    const Viewer& GetViewer() const { return m_viewer; }
    /// Tests the pair named `bodyA` and `bodyB`.
    void SetPair(const std::string& bodyA, const std::string& bodyB);
    /// Shows the static test, the swept test, or either as the pair moves or not.
    void SetQuery(ViewQuery query);
    /// Shows the textbook test's steps or the face tests'.
    void SetStepView(StepView steps);
    /// Shows a classic mistake beside the right answer (Pitfall::None: none).
    void SetPitfall(Pitfall pitfall);
    /// Runs the queries in float (true) or double.
    void SetPrecision(bool singlePrecision);
    /// Draws the layers of `layers`.
    void SetLayers(LayerMask layers);
    /// Shows trace step `step` (from 0); one that does not exist shows the verdict.
    void ShowStep(int step) { m_viewer.ShowStep(step); }
    /// Starts or stops stepping through the trace automatically.
    void TogglePlay() { m_viewer.TogglePlay(); }
    /// Sweeps: draws the moving bodies again (a ghost) at time `time` in [0, 1]; -1: not drawn.
    void SetTime(double time) { m_viewer.SetTime(time); }
    /// Frames the pair again, and keeps it framed through edits until the user pans or zooms.
    void FitCamera();
    /// Puts the camera's centre at `center`, `zoom` pixels per world unit.
    void SetCamera(Vec2 center, double zoom) { m_viewer.SetCamera(center, zoom); }
    /// Moves the camera so the world follows a drag of (dx, dy) pixels.
    void PanCamera(float dx, float dy) { m_viewer.PanCamera(dx, dy); }
    /// Zooms by `factor` about canvas point `fixed` (the pointer).
    void ZoomCamera(ScreenPoint fixed, double factor) { m_viewer.ZoomCamera(fixed, factor); }
    /// Holds the camera where it is while the scene changes under the pointer.
    void HoldCamera() { m_viewer.HoldCamera(); }
    /// Places the canvas in the window (its first frame, a resize): a new size fits the figure to it.
    void PlaceCanvas(ScreenPoint origin, int width, int height);

    // The simulation: the scene stepped as a world. Step 0 is the document's scene; an edit of the bodies at a
    // later step is an edit of the state at that step: that state, with the change, becomes the scene (and undo
    // brings back the run it was made in, at that step).

    /// The simulation of the document's scene.
    const Simulation& GetSimulation() const { return m_sim; }
    /// The scene as the canvas shows it: the document's scene with its bodies where the simulation has them at the
    /// step shown.
    const Scene& ShownScene() const;
    /// True when the scene is to be stepped: it has a world block (how long a step is, and the gravity), or its
    /// view opened it at a later step. A scene without one is a figure of the test: stepped by the format's
    /// defaults, a whole time unit a step, bodies that start inside each other are thrown apart in one step and
    /// can fall asleep still overlapping, so it is not played until a world is added (AddWorld).
    bool CanStep() const;
    /// Gives the scene a world block of steps of 1/60 of its time unit, without gravity (the lessons' dt; the
    /// format's default gravity): one edit, undone by ctrl+z. Does nothing when it has one.
    void AddWorld();
    /// Plays or pauses the simulation; a scene that cannot be stepped (CanStep) stays paused, the status line
    /// saying why.
    void SimPlay(bool playing);
    /// Shows the simulation's next step, taking it when it is the latest; pauses. A scene that cannot be stepped
    /// stays at step 0, the status line saying why.
    void SimForward();
    /// Shows the simulation's step before; pauses.
    void SimBack();
    /// Shows step `step` of the history (the time slider); pauses.
    void SimShowStep(int step);
    /// Goes back to step 0, the scene as written; pauses.
    void SimReset();
    /// Sets the simulation's speed in steps per second.
    void SimSpeed(double stepsPerSecond);
    /// A hand on body `index` while the simulation plays (a grab and a throw with the mouse): in the step shown
    /// the body is at `position`, moving at `pointerVelocity` (world units per second of the user's time, which is
    /// simulated time at 1 / dt steps a second and scales with the speed), without spin. Not an edit of the
    /// scene: the simulation's history keeps it (Simulation::Hand).
    void SimHand(int index, Vec2 position, Vec2 pointerVelocity);
    /// Shows the instant of hit `hit` of the step shown (its index in the step's time order): its two bodies where
    /// they touch; the same hit again, or -1, shows every hit. Pauses.
    void SimChooseHit(int hit);
    /// Shows the solver's response on the contact of bodies `a` and `b` (the figure's pair becomes them).
    void SimChooseContact(int a, int b);
    /// Sets body `index`'s material, static or dynamic and density, as one edit.
    void SetMaterial(int index, bool isStatic, double density, const Material& material);

    // Lessons.

    /// Opens lesson `index` of Lessons(): its text in the lesson window and its first scene (asking first when the
    /// scene has unsaved changes). False for an index out of range or a lesson that cannot be read.
    bool OpenLesson(int index);
    /// The lessons found in the lessons folder, in order.
    const std::vector<Lesson>& Lessons() const { return m_lessons; }
    /// The lesson shown, -1 for none.
    int CurrentLesson() const { return m_lesson; }
    /// The blocks of the lesson shown.
    const std::vector<LessonBlock>& LessonBlocks() const { return m_lessonBlocks; }
    /// True while the lesson window is open.
    bool LessonShown() const { return m_lessonShown; }
    /// Closes the lesson window.
    void CloseLesson() { m_lessonShown = false; }

    // The status line and the rest.

    /// Shows a one-line message in the status bar (an export result, an error).
    void SetStatus(const std::string& message, bool error);
    /// Shows a message that passes: it goes at the next edit or step or after kPassingStatusSeconds, whichever comes first
    /// (news from the start, such as the copies a crash left, which the work that follows makes old).
    void SetPassingStatus(const std::string& message);
    /// How long a passing status message stays while nothing is edited.
    static constexpr double kPassingStatusSeconds = 15.0;
    /// The status line.
    const std::string& Status() const { return m_status; }
    /// True when the status line reports an error.
    bool StatusIsError() const { return m_statusIsError; }
    /// The start-up choices.
    const AppOptions& Options() const { return m_options; }
    /// The file that holds the unsaved changes while there are some (AppOptions::unsavedDir); empty otherwise.
    const std::string& UnsavedCopyPath() const { return m_unsaved.Path(); }
    /// Tells in the status bar of the copies of unsaved scenes that an app ended without saving left in
    /// AppOptions::unsavedDir (a crash, a killed process). False when there are none.
    bool ReportLeftCopies();
    /// The figure fonts.
    const FigureFonts& Fonts() const { return m_fonts; }

  private:
    // Re-runs the queries on the scene, keeping the step where it still exists. A pair with more vertices than
    // AppOptions::backgroundVertices is tested on a worker thread: the figure keeps showing the last finished test
    // until Frame() takes the new one in.
    void Refresh();
    // For a step asked of a scene that cannot be stepped (CanStep): the status line says why; true then.
    bool RefuseStep();
    // An edit at a later step than 0 starts from the state shown: it becomes the document's bodies, once per edit.
    Body& EditBody(int index);
    void TakeShownState();
    void TakeFinishedTest();
    void ChangeChoices(const ViewChoices& choices);
    void ClearError();
    void KeepUnsavedCopy();
    bool BodyExists(int index) const;

    FigureFonts m_fonts;
    AppOptions m_options;
    Document m_document;
    Viewer m_viewer;
    Simulation m_sim;
    bool m_stateTaken = false; // this edit already took the simulation's state
    int m_simHit = -1;         // the hit whose instant is shown, of step m_simHitStep
    int m_simHitStep = -1;
    Panels m_panels;
    RecentFiles m_recent;
    UnsavedCopy m_unsaved;
    size_t m_copiedRevision = ~size_t{0}; // the document's revision the unsaved copy was last made for
    std::string m_takenBack; // a copy an app left, opened: removed once saved to another file
    int m_selected = -1;
    std::string m_status;
    bool m_statusIsError = false;
    double m_statusLeft = -1.0;  // seconds a passing message has left (negative: the message stays)
    size_t m_statusRevision = 0; // the document's revision when a passing message was set
    int m_statusStep = 0;        // the test's step shown then
    int m_statusSimStep = 0;     // the simulation's step shown then
    std::vector<Lesson> m_lessons;
    int m_lesson = -1;
    std::vector<LessonBlock> m_lessonBlocks;
    bool m_lessonShown = false;
    std::string m_pendingOpen;
    int m_pendingStep = -1;
    bool m_pendingFaces = false;
    bool m_quitConfirmed = false;
    bool m_exportRequested = false;
    std::string m_exportPath;
};

/// The figure the canvas paints: the viewer's, its labels kept off the selected body's turning and velocity handles,
/// which the canvas draws over it.
Figure CanvasFigure(const App& app);

/// True when the canvas's figure draws the selected body's velocity arrow and names it "v": the velocity handle on
/// its tip then shows no letter of its own.
bool FigureNamesVelocity(const App& app);

/// Where the canvas draws the velocity handle of `body`: the tip of the figure's velocity arrow, from the body's
/// centre, or beside the body for a velocity too short to grab.
ScreenPoint VelocityHandleAt(const View& view, const Body& body);

} // namespace satviz
