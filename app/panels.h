// SPDX-License-Identifier: MIT
// satviz app: the panels, the whole user interface on Dear ImGui: the menus, the side panel (pair, query, steps,
// numbers, layers), the canvas (canvas.cpp), the status bar, the popups, the help and the lesson window. They keep
// only what the interface needs between frames (a drag in progress, which popup to open); everything they show
// they read from the app, and everything they change goes through the app's methods.
#pragma once

#include <satviz/math.h>
#include <satviz/render/canvas.h>
#include <satviz/render/painter.h>

#include <imgui.h>

#include <cstddef>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace satviz
{

class App;

class Document;

/// What Save as suggests: the scene's name with "-edited" (or "scene.json"), in the working folder, in full so that
/// the student sees where it goes.
std::string SaveAsSuggestion(const Document& document);

/// A section of the help (F1): its title and its lines, each drawn as a bullet.
struct HelpSection
{
    const char* title;
    std::vector<const char*> lines;
};

/// The help's sections after its opening paragraph, as F1 shows them: the mouse, every key, the conventions.
const std::vector<HelpSection>& HelpSections();

/// Width of the lesson column on the left of the canvas, in pixels, while a lesson is open.
constexpr float kLessonWidth = 440.0f;

/// The status bar's padding left and right of its text, in pixels.
constexpr float kStatusPadding = 8.0f;
/// Padding above and below the status bar's lines, in pixels.
constexpr float kStatusPaddingY = 3.0f;

/// Width of the side panel's scroll bar, in pixels: kept beside its sections whether they overflow or not, so
/// that their width does not change when they do.
constexpr float kPanelScrollbar = 8.0f;
/// Width of the side panel on the right of the canvas, in pixels: 364 of sections, their padding and the scroll bar.
constexpr float kPanelWidth = 380.0f + kPanelScrollbar;

/// The smallest canvas the app leaves beside its panels, in pixels: on one this size every face a figure's sentences
/// name still has its name (the label test of the lessons' figures draws them so).
constexpr float kMinCanvasWidth = 360.0f;
/// See kMinCanvasWidth.
constexpr float kMinCanvasHeight = 600.0f;

/// The smallest window that leaves the canvas kMinCanvasWidth x kMinCanvasHeight beside the side panel and, while a
/// lesson is open, the lesson column, under the menu bar and above the status bar (each `barHeight` tall).
inline ImVec2 MinimumWindowSize(bool lessonShown, float barHeight)
{
    return {kPanelWidth + (lessonShown ? kLessonWidth : 0.0f) + kMinCanvasWidth, kMinCanvasHeight + 2.0f * barHeight};
}

/// The span of a horizontal slider's grab, in pixels along the window.
struct SliderGrabSpan
{
    float min = 0.0f; ///< left edge
    float max = 0.0f; ///< right edge
};

/// The grab of a Dear ImGui 1.86 horizontal slider whose frame spans [frameMin, frameMax], at `ratio` (0 to 1) of
/// its range: an integer slider of `values` values has a grab of 1/values of the frame, a float slider (`values` 0)
/// the least grab, `grabMinSize`.
SliderGrabSpan SliderGrab(float frameMin, float frameMax, float ratio, int values, float grabMinSize);

/// Where a slider's text `width` pixels wide starts so that the grab does not lie under part of it: centred in the
/// frame where the grab leaves it room, else centred in the wider side beside the grab, and on the grab only when
/// neither side holds it (a grab as wide as the frame).
float SliderTextX(float frameMin, float frameMax, SliderGrabSpan grab, float width);

/// What a drag on the canvas does, decided when the mouse button goes down.
enum class DragKind
{
    None,     ///< no drag
    Pan,      ///< moves the camera
    Body,     ///< moves the selected body
    Rotate,   ///< turns the selected body about its centre
    Vertex,   ///< moves one vertex of the selected polygon (refused where it would break convexity)
    Velocity, ///< sets the selected body's velocity (its displacement over one time unit)
    Throw,    ///< while the simulation plays: holds the body at the pointer, and throws it on release
    Cut,      ///< draws the segment of a cut, made on release
};

/// What a click on the canvas does.
enum class CanvasTool
{
    Select, ///< selects, moves, turns and reshapes bodies (the drags above)
    Draw,   ///< adds a vertex of a new polygon; the first vertex or Enter closes it, Esc drops it
    Cut,    ///< a drag draws a cut: every polygon it crosses from outside to outside is cut in two or more
};

/// The Dear ImGui interface of an app.
class Panels
{
  public:
    /// The panels of `app`, which outlives them.
    explicit Panels(App& app) : m_app(app) {}
    Panels(const Panels&) = delete;            ///< the panels refer to their app
    Panels& operator=(const Panels&) = delete; ///< the panels refer to their app

    /// Reads this frame's keyboard shortcuts (before the windows are built).
    void Shortcuts();
    /// Builds this frame's windows: menus, canvas, side panel, status bar, popups, help, lesson.
    void Draw();
    /// Asks what to do with the unsaved changes before opening App::PendingOpen() (from the next frame).
    void AskBeforeOpening() { m_askOpenUnsaved = true; }
    /// Asks what to do with the unsaved changes before quitting (from the next frame).
    void AskBeforeQuitting() { m_askQuit = true; }
    /// Shows the lesson window's text from its top (a lesson was just opened).
    void ScrollLessonToTop() { m_lessonScrollTop = true; }

  private:
    void SaveOrAsk();
    void MenuBar();
    void LessonsMenu();
    void LayerToggles();
    void SidePanel();
    void StepControls();
    void StepRow(const std::string& name);
    void SimulationControls();
    void ResponseSteps();
    void Materials(int selected);
    void Inspector();
    void StatusBar();
    /// What the status bar says: the worker thread's notice, the last status, or a hint.
    std::string StatusText() const;
    /// The status bar's height: one line, or as many as its text needs at the window's width (the windows above
    /// it end where it begins).
    float StatusHeight() const;
    void Popups();
    void HelpOverlay();
    void LessonWindow();
    void CanvasWindow();
    void CanvasInput(ImVec2 origin, bool hovered);
    void Handles(ImDrawList* list, ImVec2 origin);
    void ToolOverlay(ImDrawList* list, ImVec2 origin);
    void SetTool(CanvasTool tool);
    void FinishDrawing();
    void DrawingStatus();
    void AnnounceHits(Canvas& canvas, const Figure& figure, ImVec2 origin);
    void Announce(const std::string& what);
    ImGuiWindowFlags ClearedBackground() const;
    void ClearBackground();

    App& m_app;
    DragKind m_drag = DragKind::None;
    int m_dragVertex = -1;
    CanvasTool m_tool = CanvasTool::Select;
    std::vector<Vec2> m_drawn; // the vertices of the polygon being drawn, world points
    Vec2 m_cutFrom{};          // the cut being drawn, world points
    Vec2 m_cutTo{};
    Vec2 m_grabOffset{};
    double m_grabAngle = 0.0;
    // A throw: the pointer's world positions over the last kThrowWindow seconds, with their times.
    std::deque<std::pair<double, Vec2>> m_throwTrail;
    Vec2 m_throwVelocity{}; // the thrown body's velocity as last measured from the trail
    int m_throwFrames = 0;  // frames drawn while the body was held
    bool m_canvasAnnounced = false;
    bool m_showHelp = false;
    int m_newSides = 5;
    bool m_askOpen = false;
    bool m_askSaveAs = false;
    bool m_askQuit = false;
    bool m_askOpenUnsaved = false;
    bool m_openAfterSaveAs = false; // the Save as popup was opened by "Save and open"
    bool m_lessonScrollTop = false;
    int m_listStep = -1;       // the step and the number of steps the step list last showed
    int m_listSteps = -1;
    bool m_listFollow = false; // the step list scrolls until the row of the step shown is in sight
    bool m_allDigits = false;  // the Numbers panel gives every number in full
    char m_pathBuffer[1024] = {};
    // Announce: where each item named was last frame, and whether its place was printed.
    std::map<std::string, ImVec2> m_announceAt;
    std::map<std::string, bool> m_announced;
    // The simulation's step and pair last printed for scripts (PrintShownState, ResponseSteps).
    double m_ghostTime = 0.5; // the time of the sweep's ghost when "ghost at time" is ticked again
    int m_printedStep = -1;
    std::string m_printedResponse;
    std::string m_announcedHits; // the step and hit whose time bar was last printed
};

} // namespace satviz
