// SPDX-License-Identifier: MIT
// satviz app: the state and the user interface of the interactive tool, without any window system. main.cpp owns
// the GLFW window and the OpenGL backend; everything here talks to Dear ImGui only, so tests drive it through
// ImGui's input fields without a display.
#pragma once

#include "lessons.h"

#include <satviz/render/figure.h>
#include <satviz/render/imgui_canvas.h>
#include <satviz/scene.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace satviz
{

/// Width of the lesson column on the left of the canvas, in pixels, while a lesson is open.
constexpr float kLessonWidth = 440.0f;

/// Key codes of the keys the app reads beyond ImGui's own key map (letters and function keys): the window system
/// fills them in (GLFW key codes in main.cpp), tests pick their own.
struct AppKeys
{
    int s = 'S';  ///< ctrl+s saves
    int o = 'O';  ///< ctrl+o opens
    int e = 'E';  ///< ctrl+e exports a PNG
    int q = 'Q';  ///< ctrl+q quits
    int f = 'F';  ///< f frames the pair
    int f1 = 290; ///< F1 shows the help
};

/// Start-up choices of the app.
struct AppOptions
{
    std::string scenesDir;    ///< folder of the bundled scenes (the File menu lists them)
    std::string lessonsDir;   ///< folder of the lessons (Help > Lessons); empty: the scenes folder's parent
    std::string recentFile;   ///< where the recent files are remembered; empty: not remembered
    bool updateRecent = true; ///< files opened or saved join the recent list; false: it is shown but left as it is
    std::string exportPath;   ///< where ctrl+e writes the PNG; empty: next to the scene, SCENE-stepN.png
    AppKeys keys;             ///< key codes
    /// A pair with more vertices than this (A's and B's together) is tested on a worker thread: its traced
    /// queries and the camera fit grow with the square of the count, about 13 ms at 2048 vertices.
    int backgroundVertices = 2048;
};

/// The folder of the bundled scenes for the program in `programDir`, whose data folder (the lessons, and the scenes
/// in its scenes/) is `programDir / dataDir` ("../share/satviz" beside an install prefix's bin/; the build tree
/// has the same layout, with a link to tutorials/). Else, in a build directory inside the source tree,
/// tutorials/scenes in the nearest ancestor of `programDir` that has one. Empty when neither exists.
std::string FindBundledScenes(const std::filesystem::path& programDir, const std::filesystem::path& dataDir);

/// What a drag on the canvas does, decided when the mouse button goes down.
enum class DragKind
{
    None,     ///< no drag
    Pan,      ///< moves the camera
    Body,     ///< moves the selected body
    Rotate,   ///< turns the selected body about its centre
    Vertex,   ///< moves one vertex of the selected polygon (refused where it would break convexity)
    Velocity, ///< sets the selected body's velocity (its displacement over one step)
};

/// The interactive app: a scene, the pair it studies, the step shown, the camera, the edit history.
class App
{
  public:
    /// An app that draws figures with `fonts` (already in ImGui's font atlas).
    App(const FigureFonts& fonts, AppOptions options);

    /// Opens a scene file. On failure the current scene stays and the error is shown in the app.
    bool Open(const std::string& file);
    /// The user wants to open `file` (ctrl+o, the Bundled scenes or Recent menu): opens it now when nothing is
    /// unsaved, else asks first (save and open, open without saving, cancel) and returns false.
    bool RequestOpen(const std::string& file);
    /// Builds the whole user interface for one ImGui frame (between NewFrame and Render).
    void Frame();
    /// The user wants to close the window: true when the app may close now; with unsaved changes it asks first.
    bool RequestQuit();
    /// True once the user confirmed quitting (from the prompt or the menu).
    bool QuitConfirmed() const { return quitConfirmed_; }
    /// True, once, when the user asked for a PNG export; `path` receives the file to write.
    bool TakeExportRequest(std::string& path);
    /// The scene as it would be saved now: the bodies and a view block with the current camera (or "fit"), the
    /// canvas size, the layers, the pair, the query, the step and the time.
    Scene SceneForSaving() const;
    /// The figure of the current view, exactly what satviz-render draws from SceneForSaving().
    FigureSetup ExportFigure() const;
    /// Opens lesson `index` of Lessons(): its text in the lesson window and its first scene (asking first when the
    /// scene has unsaved changes). False for an index out of range or a lesson that cannot be read.
    bool OpenLesson(int index);
    /// The lessons found in the lessons folder, in order.
    const std::vector<Lesson>& Lessons() const { return lessons_; }
    /// The lesson shown, -1 for none.
    int CurrentLesson() const { return lesson_; }
    /// The blocks of the lesson shown.
    const std::vector<LessonBlock>& LessonBlocks() const { return lessonBlocks_; }
    /// Shows a one-line message in the status bar (an export result, an error).
    void SetStatus(const std::string& message, bool error);

    // State, public for the tests and the window loop.
    Scene scene;                       ///< the scene being edited
    std::string file;                  ///< its file; empty for a new scene
    bool readOnly = false;             ///< a bundled scene: saving asks for another file
    bool dirty = false;                ///< unsaved changes
    FigureSetup setup;                 ///< the pair's queries and the current figure
    int step = 0;                      ///< the trace step shown
    bool playing = false;              ///< stepping automatically
    LayerMask layers = kDefaultLayers; ///< layers drawn
    View camera;                       ///< the canvas camera
    bool cameraFit = true;             ///< the camera follows FitFigure (until the user pans or zooms)
    int selected = -1;                 ///< the selected body, -1 for none
    DragKind drag = DragKind::None;    ///< the drag in progress
    int dragVertex = -1;               ///< the vertex being dragged
    float canvasX = 0.0f;              ///< canvas position in the window (pixels)
    float canvasY = 0.0f;              ///< canvas position in the window (pixels)
    int canvasWidth = 800;             ///< canvas size (pixels)
    int canvasHeight = 600;            ///< canvas size (pixels)
    bool showHelp = false;             ///< the help overlay is open
    bool showLesson = false;           ///< the lesson window is open
    std::vector<std::string> recent;   ///< recently opened files, newest first
    std::string status;                ///< the status line
    bool statusIsError = false;        ///< the status line reports an error

    /// Undoes the last edit; false when there is nothing to undo.
    bool Undo();
    /// Redoes the last undone edit; false when there is nothing to redo.
    bool Redo();
    /// Number of edits that can be undone.
    size_t UndoDepth() const { return undo_.size(); }
    /// Re-runs the queries after an edit, keeping the step where it still exists. A pair with more vertices
    /// than AppOptions::backgroundVertices is tested on a worker thread: the figure keeps showing the last
    /// finished test until Frame() takes the new one in.
    void Refresh();
    /// True while a test of the pair runs on the worker thread.
    bool Studying() const;
    /// The scene that `setup` describes: the current one, or the one before the edits whose test still runs.
    const Scene& Studied() const { return studied_; }

  private:
    /// A test of the pair on the worker thread: the scene and options it runs on, its result once done.
    struct StudyJob
    {
        Scene scene;
        FigureOptions options;
        FigureSetup result;
        std::atomic<bool> done{false};
    };

    int PairVertices() const;
    void PollStudy();
    void Adopt(FigureSetup fresh, Scene studied);
    void ShowStep();
    void BeginEdit();
    void CommitEdit();
    void CancelEdit();
    void MenuBar();
    void SidePanel();
    void StepControls();
    void Inspector();
    void LayerToggles();
    void CanvasWindow();
    void CanvasInput(ImVec2 origin, bool hovered);
    void Handles(ImDrawList* list, ImVec2 origin);
    void Popups();
    void HelpOverlay();
    void LessonWindow();
    void LessonsMenu();
    void Shortcuts();
    void StatusBar();
    void Save(const std::string& path);
    void AddBody(Shape shape, const std::string& stem);
    void DeleteSelected();
    int BodyAt(Vec2 world) const;
    void Remember(const std::string& path);
    void LoadRecent();
    void SaveRecent() const;
    std::vector<std::string> BundledScenes() const;

    Scene studied_;                 // the scene `setup` was made from
    std::shared_ptr<StudyJob> job_; // the test running on the worker thread, if any
    bool rerun_ = false;            // the scene changed while it ran: test again when it ends
    bool canvasSized_ = false;      // the canvas has had its first frame (and so its size)
    FigureFonts fonts_;
    std::vector<Lesson> lessons_;
    int lesson_ = -1;
    std::vector<LessonBlock> lessonBlocks_;
    bool lessonScrollTop_ = false;
    AppOptions options_;
    std::vector<Scene> undo_;
    std::vector<Scene> redo_;
    bool editOpen_ = false;
    Scene editStart_;
    ImVec2 dragStart_{};
    Vec2 grabOffset_{};
    double grabAngle_ = 0.0;
    double playClock_ = 0.0;
    bool quitConfirmed_ = false;
    bool canvasAnnounced_ = false;
    int newSides_ = 5;
    bool askQuit_ = false;
    bool askOpen_ = false;
    bool askOpenUnsaved_ = false;
    std::string pendingOpen_;      // the file to open once the unsaved changes are dealt with
    bool openAfterSaveAs_ = false; // the Save as popup was opened by "Save and open"

    bool askSaveAs_ = false;
    bool exportRequested_ = false;
    std::string exportPath_;
    char pathBuffer_[1024] = {};
};

} // namespace satviz
