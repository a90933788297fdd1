// SPDX-License-Identifier: MIT
// satviz app: the panels on Dear ImGui. The canvas and its mouse handling are in canvas.cpp.
//
// Index:
// [SECTION] Helpers
// [SECTION] Keyboard shortcuts
// [SECTION] Menus
// [SECTION] Side panel: the pair, the steps, the numbers, the layers
// [SECTION] Status bar, popups and help
// [SECTION] Lesson window
#include "app.h"
#include "study_numbers.h"
#include "wrapped_text.h"

#include <satviz/render/describe.h>
#include <satviz/layers.h>
#include <satviz/render/response_steps.h>
#include <satviz/render/world_words.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

namespace satviz
{

// [SECTION] Helpers

SliderGrabSpan SliderGrab(float frameMin, float frameMax, float ratio, int values, float grabMinSize)
{
    // As SliderBehaviorT places it: 2 pixels in from the frame, its centre moving over the frame less the grab.
    const float padding = 2.0f;
    const float length = std::max(frameMax - frameMin - 2.0f * padding, 0.0f);
    float size = values > 0 ? std::max(length / static_cast<float>(values), grabMinSize) : grabMinSize;
    size = std::min(size, length);
    const float centre = frameMin + padding + 0.5f * size + std::clamp(ratio, 0.0f, 1.0f) * (length - size);
    return {centre - 0.5f * size, centre + 0.5f * size};
}

float SliderTextX(float frameMin, float frameMax, SliderGrabSpan grab, float width)
{
    const float gap = 4.0f; // between the text and the grab
    const float centred = 0.5f * (frameMin + frameMax - width);
    if (centred + width + gap <= grab.min || centred >= grab.max + gap)
    {
        return centred;
    }
    const float left = grab.min - frameMin;
    const float right = frameMax - grab.max;
    if (right >= left && right >= width + 2.0f * gap)
    {
        return grab.max + 0.5f * (right - width);
    }
    if (left >= width + 2.0f * gap)
    {
        return frameMin + 0.5f * (left - width);
    }
    return std::max(frameMin, 0.5f * (grab.min + grab.max - width));
}

namespace
{

// Writes `text` in the frame of the slider just drawn (with no text of its own), `frameWidth` wide, beside its grab
// rather than over it: Dear ImGui centres a slider's text, where the grab passes under part of it.
void SliderTextBesideGrab(float frameWidth, float ratio, int values, const std::string& text)
{
    const ImVec2 low = ImGui::GetItemRectMin();
    const ImVec2 high(low.x + frameWidth, ImGui::GetItemRectMax().y);
    const SliderGrabSpan grab = SliderGrab(low.x, high.x, ratio, values, ImGui::GetStyle().GrabMinSize);
    const float x = SliderTextX(low.x, high.x, grab, ImGui::CalcTextSize(text.c_str()).x);
    const ImVec4 clip(low.x, low.y, high.x, high.y);
    ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                                        ImVec2(x, 0.5f * (low.y + high.y - ImGui::GetFontSize())),
                                        ImGui::GetColorU32(ImGuiCol_Text), text.c_str(), nullptr, 0.0f, &clip);
}

bool Ctrl()
{
    return ImGui::GetIO().KeyCtrl;
}

bool Pressed(int key)
{
    return key >= 0 && ImGui::IsKeyPressed(key, false);
}

bool PressedNamed(ImGuiKey key)
{
    return Pressed(ImGui::GetKeyIndex(key));
}

// A modal popup asking for a file path; true on the frame the user confirms it (button or Enter).
bool PathPopup(const char* title, const char* prompt, const char* action, char* buffer, size_t size)
{
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        return false;
    }
    ImGui::TextUnformatted(prompt);
    ImGui::SetNextItemWidth(480.0f);
    if (ImGui::IsWindowAppearing())
    {
        ImGui::SetKeyboardFocusHere();
    }
    const bool enter = ImGui::InputText("##path", buffer, size, ImGuiInputTextFlags_EnterReturnsTrue);
    const bool confirmed = ImGui::Button(action) || enter;
    ImGui::SameLine();
    // Escape cancels, as it closes every other question of the app.
    if (ImGui::Button("Cancel") || confirmed || PressedNamed(ImGuiKey_Escape))
    {
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return confirmed;
}

// A bullet of the help whose text wraps at the window's edge (BulletText would run past it).
void HelpBullet(const char* text)
{
    ImGui::Bullet();
    WrappedText(text);
}

void HelpMarker(const char* text)
{
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
    {
        ImGui::BeginTooltip();
        ImGui::TextUnformatted(WrapToWidth(text, ImGui::GetFontSize() * 28.0f).c_str());
        ImGui::EndTooltip();
    }
}

// One number, or a point's two coordinates (`parts`), of the Numbers panel: on its label's line when that fits,
// else on a line of its own below the label, a point's coordinates one per line when they do not fit together: no
// number runs past the panel's edge or is broken inside its digits.
void NumberLine(const std::string& label, const std::vector<std::string>& parts)
{
    const std::string value = parts.size() == 1 ? parts[0] : "(" + parts[0] + ", " + parts[1] + ")";
    const std::string line = label + ": " + value;
    if (ImGui::CalcTextSize(line.c_str()).x <= ImGui::GetContentRegionAvail().x)
    {
        ImGui::TextUnformatted(line.c_str());
        return;
    }
    // A label too long for the panel ("deciding axis 3, the axis from box's vertex 2 to ball's centre") wraps
    // between words, as the panel's sentences do.
    WrappedText(label + ":");
    ImGui::Indent();
    if (parts.size() == 1 || ImGui::CalcTextSize(value.c_str()).x <= ImGui::GetContentRegionAvail().x)
    {
        ImGui::TextUnformatted(value.c_str());
    }
    else
    {
        ImGui::TextUnformatted(("(" + parts[0] + ",").c_str());
        ImGui::TextUnformatted((" " + parts[1] + ")").c_str());
    }
    ImGui::Unindent();
}

} // namespace

void Panels::Draw()
{
    MenuBar();
    CanvasWindow();
    SidePanel();
    StatusBar();
    if (m_showHelp)
    {
        HelpOverlay();
    }
    if (m_app.LessonShown())
    {
        LessonWindow();
    }
    // The popups come last: a window that appears after a modal popup has been begun in the same frame ends
    // Dear ImGui 1.86 on an assertion (no blocking modal found for it, as the modal is not yet active), and the
    // menus and the lesson window both open windows and ask questions in one frame (Help > Lessons with unsaved
    // changes shows the lesson and asks before opening its scene).
    Popups();
}

// Prints, once, where the item just built is on the screen ("satviz: WHAT at X,Y", its centre), for scripts that
// drive the window (the end-to-end test clicks menus and buttons there), as the canvas prints its place. Only once
// the item has stayed put for a frame: a popup is placed and sized over its first frames.
void Panels::Announce(const std::string& what)
{
    const ImVec2 low = ImGui::GetItemRectMin();
    const ImVec2 high = ImGui::GetItemRectMax();
    const ImVec2 center((low.x + high.x) * 0.5f, (low.y + high.y) * 0.5f);
    const auto seen = m_announceAt.find(what);
    const bool still = seen != m_announceAt.end() && seen->second.x == center.x && seen->second.y == center.y;
    m_announceAt[what] = center;
    if (still && !m_announced[what])
    {
        m_announced[what] = true;
        std::printf("satviz: %s at %.0f,%.0f\n", what.c_str(), center.x, center.y);
        std::fflush(stdout);
    }
}

// Saves to the scene's file, or asks for one when it has none or is a bundled scene.
void Panels::SaveOrAsk()
{
    const Document& document = m_app.GetDocument();
    if (document.File().empty() || document.ReadOnly())
    {
        m_askSaveAs = true;
    }
    else
    {
        m_app.Save(document.File());
    }
}

// The row that walks the figure's steps: back and forward (past the faces a sweep decided without evaluating them,
// Viewer::NextStep), Play, Verdict, and a slider showing `name`.
void Panels::StepRow(const std::string& name)
{
    const Viewer& viewer = m_app.GetViewer();
    const int step = viewer.Step();
    const int last = viewer.VerdictStep();
    ImGui::BeginDisabled(step <= 0);
    if (ImGui::ArrowButton("##previous", ImGuiDir_Left))
    {
        m_app.ShowStep(viewer.NextStep(step, -1));
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(step >= last);
    if (ImGui::ArrowButton("##next", ImGuiDir_Right))
    {
        m_app.ShowStep(viewer.NextStep(step, 1));
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button(viewer.Playing() ? "Pause" : "Play"))
    {
        m_app.TogglePlay();
    }
    ImGui::SameLine();
    if (ImGui::Button("Verdict"))
    {
        m_app.ShowStep(last);
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    const float width = ImGui::CalcItemWidth();
    int shown = step;
    if (ImGui::SliderInt("##step", &shown, 0, last, "") && shown != step)
    {
        m_app.ShowStep(shown);
    }
    SliderTextBesideGrab(width, last > 0 ? static_cast<float>(step) / static_cast<float>(last) : 0.0f, last + 1,
                         name);
}

// [SECTION] Keyboard shortcuts

void Panels::Shortcuts()
{
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput)
    {
        return;
    }
    // While a question is open (unsaved changes, a file name) it alone takes the keys: a shortcut acting behind it
    // would open another dialog in its place, and the question would be gone unanswered.
    if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel))
    {
        return;
    }
    const AppKeys& k = m_app.Options().keys;
    if (Ctrl())
    {
        if (PressedNamed(ImGuiKey_Z))
        {
            if (!m_app.Undo())
            {
                m_app.SetStatus("Nothing to undo", false);
            }
        }
        if (PressedNamed(ImGuiKey_Y))
        {
            if (!m_app.Redo())
            {
                m_app.SetStatus("Nothing to redo", false);
            }
        }
        if (Pressed(k.s))
        {
            SaveOrAsk();
        }
        if (Pressed(k.o))
        {
            m_askOpen = true;
        }
        if (Pressed(k.e))
        {
            m_app.RequestExport();
        }
        if (Pressed(k.q))
        {
            m_app.RequestQuit();
        }
        return;
    }
    if (Pressed(k.p))
    {
        m_app.SimPlay(!m_app.GetSimulation().Playing());
    }
    if (Pressed(k.period))
    {
        m_app.SimForward();
    }
    if (Pressed(k.comma))
    {
        m_app.SimBack();
    }
    const Viewer& viewer = m_app.GetViewer();
    if (PressedNamed(ImGuiKey_Space))
    {
        m_app.TogglePlay();
    }
    // The arrows pass over the faces a sweep decided without evaluating them (PairStudy::NextStep).
    if (PressedNamed(ImGuiKey_RightArrow) && viewer.Step() < viewer.VerdictStep())
    {
        m_app.ShowStep(viewer.NextStep(viewer.Step(), 1));
    }
    if (PressedNamed(ImGuiKey_LeftArrow) && viewer.Step() > 0)
    {
        m_app.ShowStep(viewer.NextStep(viewer.Step(), -1));
    }
    if (PressedNamed(ImGuiKey_Delete))
    {
        m_app.DeleteSelected();
    }
    if (Pressed(k.f1))
    {
        m_showHelp = !m_showHelp;
    }
    if (Pressed(k.f))
    {
        m_app.FitCamera();
    }
    if (Pressed(k.d))
    {
        SetTool(m_tool == CanvasTool::Draw ? CanvasTool::Select : CanvasTool::Draw);
    }
    if (Pressed(k.x))
    {
        SetTool(m_tool == CanvasTool::Cut ? CanvasTool::Select : CanvasTool::Cut);
    }
    if (m_tool == CanvasTool::Draw && PressedNamed(ImGuiKey_Enter))
    {
        FinishDrawing();
    }
    if (PressedNamed(ImGuiKey_Escape))
    {
        m_showHelp = false;
        if (m_tool != CanvasTool::Select)
        {
            SetTool(CanvasTool::Select);
        }
    }
}

// [SECTION] Menus

void Panels::MenuBar()
{
    if (!ImGui::BeginMainMenuBar())
    {
        return;
    }
    if (ImGui::BeginMenu("File"))
    {
        if (ImGui::MenuItem("Open...", "Ctrl+O"))
        {
            m_askOpen = true;
        }
        if (ImGui::BeginMenu("Bundled scenes"))
        {
            for (const std::string& path : m_app.BundledScenes())
            {
                if (ImGui::MenuItem(std::filesystem::path(path).stem().string().c_str()))
                {
                    m_app.RequestOpen(path);
                }
            }
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("Recent", !m_app.Recent().empty()))
        {
            // A copy: opening a file reorders the list.
            for (const std::string& path : std::vector<std::string>(m_app.Recent()))
            {
                if (ImGui::MenuItem(path.c_str()))
                {
                    m_app.RequestOpen(path);
                }
            }
            ImGui::EndMenu();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Save", "Ctrl+S"))
        {
            SaveOrAsk();
        }
        if (ImGui::MenuItem("Save as..."))
        {
            m_askSaveAs = true;
        }
        if (ImGui::MenuItem("Export PNG", "Ctrl+E"))
        {
            m_app.RequestExport();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q"))
        {
            m_app.RequestQuit();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit"))
    {
        if (ImGui::MenuItem("Undo", "Ctrl+Z", false, m_app.GetDocument().UndoDepth() > 0))
        {
            m_app.Undo();
        }
        if (ImGui::MenuItem("Redo", "Ctrl+Y", false, m_app.GetDocument().RedoDepth() > 0))
        {
            m_app.Redo();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Add box"))
        {
            m_app.AddBody(MakeShape(MakeBox(0.5, 0.5).polygon), "box");
        }
        if (ImGui::MenuItem("Add triangle"))
        {
            m_app.AddBody(MakeShape(MakeRegularPolygon(3, 0.6).polygon), "triangle");
        }
        if (ImGui::MenuItem("Add regular polygon"))
        {
            m_app.AddBody(MakeShape(MakeRegularPolygon(m_newSides, 0.6).polygon), "polygon");
        }
        ImGui::SetNextItemWidth(120.0f);
        if (ImGui::InputInt("sides", &m_newSides))
        {
            m_newSides = std::clamp(m_newSides, 3, 4096);
        }
        if (ImGui::MenuItem("Add circle"))
        {
            m_app.AddBody(MakeShape(Circle{{0.0, 0.0}, 0.5}), "circle");
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Draw a polygon", "D", m_tool == CanvasTool::Draw))
        {
            SetTool(m_tool == CanvasTool::Draw ? CanvasTool::Select : CanvasTool::Draw);
        }
        if (ImGui::MenuItem("Cut", "X", m_tool == CanvasTool::Cut))
        {
            SetTool(m_tool == CanvasTool::Cut ? CanvasTool::Select : CanvasTool::Cut);
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Delete selected", "Del", false, m_app.Selected() >= 0))
        {
            m_app.DeleteSelected();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View"))
    {
        if (ImGui::MenuItem("Fit the pair", "F"))
        {
            m_app.FitCamera();
        }
        ImGui::Separator();
        LayerToggles();
        ImGui::Separator();
        ImGui::MenuItem("Help", "F1", &m_showHelp);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help"))
    {
        ImGui::MenuItem("Controls and conventions", "F1", &m_showHelp);
        LessonsMenu();
        ImGui::EndMenu();
    }
    else
    {
        Announce("menu Help");
    }
    ImGui::EndMainMenuBar();
}

void Panels::LessonsMenu()
{
    const std::vector<Lesson>& lessons = m_app.Lessons();
    if (!ImGui::BeginMenu("Lessons", !lessons.empty()))
    {
        Announce("menu Help > Lessons");
        return;
    }
    for (size_t i = 0; i < lessons.size(); ++i)
    {
        const bool chosen = ImGui::MenuItem(lessons[i].title.c_str(), nullptr,
                                            static_cast<int>(i) == m_app.CurrentLesson() && m_app.LessonShown());
        Announce("menu Help > Lessons > " + std::to_string(i + 1));
        if (chosen)
        {
            m_app.OpenLesson(static_cast<int>(i));
        }
    }
    ImGui::EndMenu();
}

// One switch per row of the layer table, with its description as the tooltip.
void Panels::LayerToggles()
{
    const LayerMask layers = m_app.GetViewer().Choices().layers;
    for (const LayerInfo& layer : kLayerTable)
    {
        bool on = (layers & layer.bit) != 0;
        if (ImGui::Checkbox(std::string(layer.name).c_str(), &on))
        {
            m_app.SetLayers(on ? (layers | layer.bit) : (layers & ~layer.bit));
        }
        if (ImGui::IsItemHovered())
        {
            ImGui::SetTooltip("%.*s", static_cast<int>(layer.description.size()), layer.description.data());
        }
    }
}

// [SECTION] Side panel: the pair, the steps, the numbers, the layers

ImGuiWindowFlags Panels::ClearedBackground() const
{
    return m_app.Options().clearRect != nullptr ? ImGuiWindowFlags_NoBackground : ImGuiWindowFlags_None;
}

// The window's background, opaque, filled by clearing (AppOptions::clearRect) as its first drawing.
void Panels::ClearBackground()
{
    if (m_app.Options().clearRect == nullptr)
    {
        return;
    }
    const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    const ImU32 packed = ImGui::ColorConvertFloat4ToU32(ImVec4(bg.x, bg.y, bg.z, 1.0f));
    // ImU32 is ABGR; the callback reads RGBA, as a figure Color.
    const Color color =
        ((packed & 0xFFu) << 24) | (((packed >> 8) & 0xFFu) << 16) | (((packed >> 16) & 0xFFu) << 8) | 0xFFu;
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 min = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    list->PushClipRect(min, ImVec2(min.x + size.x, min.y + size.y), true);
    list->AddCallback(m_app.Options().clearRect, reinterpret_cast<void*>(static_cast<uintptr_t>(color)));
    list->PopClipRect();
}

void Panels::SidePanel()
{
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x - kPanelWidth, viewport->Pos.y + top));
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, viewport->Size.y - top - StatusHeight()));
    // Without a title or a resize grip, but with its scroll bar: the Numbers that run past the bottom look cut
    // without one, and nothing else says that the panel scrolls. Always there, narrow, so that the sections keep
    // their width (the axes list's rows, which cannot wrap, are fitted to it).
    ImGui::PushStyleVar(ImGuiStyleVar_ScrollbarSize, kPanelScrollbar);
    ImGui::Begin("##panel", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_AlwaysVerticalScrollbar | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                     ClearedBackground());
    ImGui::PopStyleVar();
    ClearBackground();
    const Document& document = m_app.GetDocument();
    const std::string title = (document.File().empty() ? std::string("untitled")
                                                       : std::filesystem::path(document.File()).filename().string()) +
                              (document.Dirty() ? " (modified)" : "");
    ImGui::TextUnformatted(title.c_str());
    if (!document.GetScene().description.empty())
    {
        WrappedTextDisabled(document.GetScene().description);
    }
    ImGui::Separator();
    // First, collapsed, where it is always in sight: below the step list and the numbers a short window scrolled it
    // out of sight, and a scene that turns a layer off (l13_overlap's axes) left no way to find it.
    if (ImGui::CollapsingHeader("Layers"))
    {
        LayerToggles();
    }
    SimulationControls();
    // l01_legend draws the legend alone: its two bodies are not drawn, and a test of them would be about nothing
    // the student sees.
    const LayerMask layers = m_app.GetViewer().Choices().layers;
    const bool legendAlone = (layers & kLayerLegend) != 0 && (layers & kLayerShapes) == 0;
    if (legendAlone && m_app.GetViewer().Setup().Ok())
    {
        WrappedText("This figure draws the legend alone, the key to the figures' colours and marks: its bodies are "
                    "not drawn, so no pair is tested here. Turn on the shapes layer (Layers, above) to see them and "
                    "their test.");
    }
    else if (m_app.GetViewer().TestsPair())
    {
        StepControls();
        if (m_app.GetViewer().ShowsSatNumbers())
        {
            Inspector();
        }
    }
    else if (m_app.GetViewer().Setup().Ok())
    {
        WrappedText("This figure, \"" + std::string(FigureKindName(m_app.GetViewer().CurrentFigure().kind)) +
                    "\", draws one body by itself: no pair is tested, so there are no steps to follow.");
    }
    ImGui::End();
}

void Panels::StepControls()
{
    const Viewer& viewer = m_app.GetViewer();
    const PairStudy& study = viewer.Setup().study;
    const Scene& studied = viewer.Studied();
    const ViewChoices& choices = viewer.Choices();
    // The pair and the test, named as in the scene that was tested (the current one, unless a test still runs
    // in the background).
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
    for (int s = 0; s < 2; ++s)
    {
        const int current = s == 0 ? study.bodyA : study.bodyB;
        ImGui::SetNextItemWidth(half);
        if (s == 1)
        {
            ImGui::SameLine();
        }
        const std::string label = s == 0 ? "##A" : "##B";
        if (ImGui::BeginCombo(
                label.c_str(),
                (std::string(s == 0 ? "A: " : "B: ") + studied.bodies[static_cast<size_t>(current)].name).c_str()))
        {
            for (size_t i = 0; i < studied.bodies.size(); ++i)
            {
                const int other = s == 0 ? study.bodyB : study.bodyA;
                if (static_cast<int>(i) == other)
                {
                    continue;
                }
                if (ImGui::Selectable(studied.bodies[i].name.c_str(), static_cast<int>(i) == current))
                {
                    const std::string& picked = studied.bodies[i].name;
                    const std::string& kept = studied.bodies[static_cast<size_t>(other)].name;
                    m_app.SetPair(s == 0 ? picked : kept, s == 0 ? kept : picked);
                }
            }
            ImGui::EndCombo();
        }
    }
    if (viewer.CurrentFigure().kind == FigureKind::Pieces)
    {
        // The steps and numbers below are those of SAT on two convex shapes; a concave body's would be its hull's.
        WrappedText("A concave body is tested piece by piece, as the canvas shows: first the pieces' boxes, then "
                    "each pair of pieces whose boxes overlap, then the merged verdict; the caption explains each "
                    "step. SAT's axes and numbers would be those of its hull, which is not the body, so they are not "
                    "shown.");
        ImGui::Separator();
        const int step = viewer.Step();
        const int last = viewer.VerdictStep();
        // Counted as the caption counts them ("Step 2 of 3: ..."), then named, on a line of its own: beside the
        // slider's grab a narrow column cut it ("step 2 of 2: verdi"); the slider keeps the short name.
        const std::string what = step == 0      ? std::string("the pieces' boxes")
                                 : step == last ? std::string("verdict")
                                                : "pair of pieces " + std::to_string(step) + " of " +
                                                      std::to_string(last - 1);
        WrappedText("Step " + std::to_string(step + 1) + " of " + std::to_string(last + 1) + ": " + what);
        StepRow(step == 0 ? std::string("boxes") : step == last ? std::string("verdict") : "pair " + std::to_string(step));
        return;
    }
    if (viewer.CurrentFigure().kind == FigureKind::DiscCast)
    {
        // The cast's answer is the canvas's (ShowsSatNumbers).
        WrappedText("The disc is cast along its path against the target, as the canvas shows: its caption gives the "
                    "time and the point of first contact. SAT's axes and numbers are not shown: for a concave target "
                    "they would be those of its hull, which is not the body.");
        return;
    }
    int query = static_cast<int>(choices.query);
    const char* queries[] = {"automatic (sweep when moving)", "static test (Collide)", "swept test (Sweep)"};
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::Combo("##query", &query, queries, 3))
    {
        m_app.SetQuery(static_cast<ViewQuery>(query));
    }
    int steps = choices.steps == StepView::Faces ? 1 : 0;
    const char* views[] = {"textbook SAT: both intervals per axis", "face tests, as the fast path runs them"};
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::Combo("##steps", &steps, views, 2))
    {
        m_app.SetStepView(steps == 1 ? StepView::Faces : StepView::Textbook);
    }
    if (ImGui::IsItemHovered())
    {
        ImGui::SetTooltip("The textbook test projects both shapes on each distinct axis and compares the intervals.\n"
                          "The fast queries test faces instead: does the other shape lie wholly beyond this face?\n"
                          "One face test per edge of both shapes, each about one side of its edge only, where the\n"
                          "textbook test checks both sides of each distinct axis; both give the same verdict and MTV.");
    }
    // A classic mistake beside the right answer: the library never takes it, the view shows what it would do.
    int pitfall = static_cast<int>(choices.pitfall);
    const char* pitfalls[] = {"no pitfall",
                              "pitfall: axes not normalised",
                              "pitfall: push direction not checked",
                              "pitfall: only A's axes tested",
                              "pitfall: motion sampled, not swept",
                              "pitfall: float on world coordinates"};
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::Combo("##pitfall", &pitfall, pitfalls, static_cast<int>(std::size(pitfalls))))
    {
        m_app.SetPitfall(static_cast<Pitfall>(pitfall));
    }
    if (ImGui::IsItemHovered())
    {
        ImGui::SetTooltip(
            "Shows what a classic SAT mistake would answer, beside the right answer, on the verdict step\n"
            "(a dashed arrow and a sentence). The library's queries never make it.");
    }

    ImGui::Separator();
    // Named as the step list and the sentence name the step ("axis 2 of 4", "face test 2 of 8", "verdict"), so
    // that the slider speaks of the view's own steps.
    std::string sliderText = StepName(studied, study, viewer.Step());
    if (!sliderText.empty())
    {
        sliderText[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(sliderText[0])));
    }
    StepRow(sliderText);
    // The verdict counts the contact points only where the picture draws them, as the figures do.
    WrappedText(DescribeStep(studied, study, viewer.Step(), (choices.layers & kLayerContacts) != 0));
    if (viewer.Step() != viewer.VerdictStep() && (choices.layers & kLayerProjection) == 0)
    {
        // A scene may leave the axis off to show something else (l13_overlap, the Minkowski view): the sentence
        // above speaks of an axis the picture does not draw.
        WrappedTextDisabled(std::string("The picture does not draw this axis: this scene has the projection layer "
                                        "off") +
                            ((choices.layers & kLayerMinkowski) ? " to show the Minkowski view (the inset)" : "") +
                            ". Turn it on here, or under Layers at the top of this panel.");
        if (ImGui::SmallButton("show the axes"))
        {
            m_app.SetLayers(choices.layers | kLayerProjection | kLayerAxes | kLayerNormals);
        }
    }

    ImGui::Separator();
    ImGui::TextUnformatted(study.Textbook() ? "Axes tested (click one)" : "Face tests run (click one)");
    HelpMarker(study.Textbook()
                   ? "Each row is one axis: the overlap of the two intervals on it (the shorter push that separates "
                     "them) or the gap between them. The test stops at the first axis with a gap (a separating axis)."
                   : "Each row is one face test: how far the other shape reaches behind the face, or how far beyond "
                     "it it lies. The test stops at the first face with the other shape wholly beyond it.\n"
                     "A sweep against a polygon above 16 vertices decides many faces without evaluating them: a "
                     "vertex already found bounds their gap (not walked to), or bisection rules them out (not "
                     "evaluated). Their rows are dimmed, and the arrows and Play pass over them.");
    const float rows = std::min<float>(static_cast<float>(study.StepCount()), 9.0f);
    if (ImGui::BeginChild("##axes", ImVec2(0.0f, rows * ImGui::GetTextLineHeightWithSpacing() + 8.0f), true))
    {
        // Only the rows in sight are built: a polygon of 100 000 vertices has as many steps.
        const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
        // The row of the step shown stays in sight when the step or the list changes (an edit, an undo, a change of
        // view rebuilds the list, and a student on the verdict stays on it, whose row may now be far down): the list
        // follows it until it is in sight, which may take a frame while the list grows. A scroll by the user leaves
        // the step as it is and is kept.
        const int steps = study.StepCount();
        if (ImGui::IsWindowAppearing() || viewer.Step() != m_listStep || steps != m_listSteps)
        {
            m_listStep = viewer.Step();
            m_listSteps = steps;
            m_listFollow = true;
        }
        if (m_listFollow)
        {
            const float top = static_cast<float>(viewer.Step()) * rowHeight;
            const float seen = ImGui::GetWindowHeight() - 2.0f * ImGui::GetStyle().WindowPadding.y;
            if (top >= ImGui::GetScrollY() && top + ImGui::GetTextLineHeight() <= ImGui::GetScrollY() + seen)
            {
                m_listFollow = false;
            }
            else
            {
                ImGui::SetScrollY(std::max(0.0f, (static_cast<float>(viewer.Step()) - 4.0f) * rowHeight));
            }
        }
        ImGuiListClipper clipper;
        clipper.Begin(study.StepCount(), rowHeight);
        while (clipper.Step())
        {
            for (int k = clipper.DisplayStart; k < clipper.DisplayEnd; ++k)
            {
                const bool decided = study.Decided(k);
                if (decided)
                {
                    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
                }
                if (ImGui::Selectable(StepTitle(studied, study, k).c_str(), k == viewer.Step()))
                {
                    m_app.ShowStep(k);
                }
                if (decided)
                {
                    ImGui::PopStyleColor();
                }
            }
        }
    }
    ImGui::EndChild();

    if (study.sweep)
    {
        // The bodies stay where the sweep starts, t = 0 (the caption, the number lines and the static test speak
        // of them there); the ghost is the moving bodies again, dashed, at time t.
        bool showTime = viewer.Time() >= 0.0;
        if (ImGui::Checkbox("ghost at time", &showTime))
        {
            if (!showTime)
            {
                m_ghostTime = viewer.Time();
            }
            // Ticked again, the ghost comes back where it was.
            m_app.SetTime(showTime ? m_ghostTime : -1.0);
        }
        if (ImGui::IsItemHovered())
        {
            ImGui::SetTooltip("Draws the moving bodies again, dashed, where they are at time t of the sweep; the "
                              "bodies themselves stay at t = 0, where the test starts");
        }
        ImGui::SameLine();
        // Unticked, the slider's grab stays where the ghost comes back to and its text says the ghost is off:
        // "t = 0.000" there read as a ghost drawn at the start.
        float t = static_cast<float>(showTime ? viewer.Time() : m_ghostTime);
        ImGui::SetNextItemWidth(-1.0f);
        const float width = ImGui::CalcItemWidth();
        ImGui::BeginDisabled(!showTime);
        if (ImGui::SliderFloat("##time", &t, 0.0f, 1.0f, ""))
        {
            m_app.SetTime(t);
        }
        char text[32];
        std::snprintf(text, sizeof(text), "t = %.3f", static_cast<double>(t));
        SliderTextBesideGrab(width, t, 0, showTime ? text : "off");
        ImGui::EndDisabled();
    }
}

void Panels::Inspector()
{
    if (!ImGui::CollapsingHeader("Numbers", ImGuiTreeNodeFlags_DefaultOpen))
    {
        return;
    }
    const Viewer& viewer = m_app.GetViewer();
    bool single = viewer.Choices().singlePrecision;
    if (ImGui::Checkbox("single precision (float)", &single))
    {
        m_app.SetPrecision(single);
    }
    HelpMarker("Runs the float instantiation of the queries on the shapes rounded to float: compare its numbers "
               "with double's to see what the precision costs.");
    // A change of the pair's test above may have left no figure until its test is in.
    if (!viewer.Setup().Ok())
    {
        return;
    }
    const PairStudy& study = viewer.Setup().study;
    if (single && !study.singlePrecision)
    {
        WrappedText("A polygon is not valid once rounded to float: the numbers are double.");
    }
    ImGui::Checkbox("all digits", &m_allDigits);
    HelpMarker("Shows each number as the shortest decimal that reads back as the same value (0.44999999999999996), "
               "where the panel otherwise gives the digits of the sentences and the figures (0.45).");
    // Every number as the step's sentence and the figure print it (FormatNumber, FormatPair), so that the same
    // number reads alike in the panel and beside the picture; with "all digits", in full.
    auto number = [&](const std::string& label, double v) {
        NumberLine(label, {PanelNumber(v, study, m_allDigits)});
    };
    auto point = [&](const std::string& label, Vec2 p) { NumberLine(label, PanelPair(p, study, m_allDigits)); };
    // A sweep's numbers first, as its verdict gives them; then the static test where the bodies start (t = 0),
    // under a heading of its own, since its gap or overlap is not the sweep's answer.
    if (study.sweep)
    {
        WrappedText(SweepHeading(m_app.ShownScene()));
        ImGui::Indent();
        const bool textbookSweep = study.Textbook();
        const SweepStatus status = textbookSweep ? study.textbookSweepResult.status : study.sweepResult.status;
        if (status == SweepStatus::Hit)
        {
            const SweepResult& r = study.sweepResult;
            number("time of impact t", textbookSweep ? study.textbookSweepResult.toi : r.toi);
            point("normal at impact (A to B)", textbookSweep ? study.textbookSweepResult.normal : r.normal);
            // The contacts the figure labels c1, c2 in a sweep (satviz-query's "toi_contacts", in that order).
            // Listed where the contacts layer draws them, as the static test's are (StaticTestNumbers).
            const int contacts = (viewer.Choices().layers & kLayerContacts) != 0 ? r.contactCount : 0;
            for (int i = 0; i < contacts; ++i)
            {
                point("contact c" + std::to_string(i + 1) + " at impact", r.contacts[i].point);
            }
        }
        else
        {
            WrappedText(SweepMissLine(m_app.ShownScene()));
        }
        ImGui::Unindent();
        ImGui::TextUnformatted("Static test at t = 0 (the start):");
        ImGui::Indent();
    }
    else if (study.startsOverlapping)
    {
        WrappedText("Moving, but overlapping at t = 0: no time of impact; the static test at t = 0:");
    }
    else
    {
        WrappedText(StaticHeading());
        ImGui::Indent();
    }
    for (const NumberRow& row : StaticTestNumbers(m_app.ShownScene(), study, m_allDigits, viewer.Choices().layers))
    {
        NumberLine(row.label, row.parts);
    }
    if (study.sweep || !study.startsOverlapping)
    {
        ImGui::Unindent();
    }
    const int selected = m_app.Selected();
    const std::vector<Body>& bodies = m_app.ShownScene().bodies;
    if (selected < 0 || selected >= static_cast<int>(bodies.size()))
    {
        return;
    }
    // Each field is one edit from the moment it is grabbed to the moment it is let go.
    const Body& body = bodies[static_cast<size_t>(selected)];
    ImGui::Separator();
    ImGui::Text("selected: %s", body.name.c_str());
    Vec2 position = body.position;
    const bool moved = ImGui::DragScalarN("position", ImGuiDataType_Double, &position.x, 2, 0.01f);
    if (ImGui::IsItemActivated())
    {
        m_app.BeginEdit();
    }
    if (moved)
    {
        m_app.MoveBody(selected, position);
    }
    if (ImGui::IsItemDeactivated())
    {
        m_app.EndEdit();
    }
    double angle = bodies[static_cast<size_t>(selected)].angle;
    const bool turned = ImGui::DragScalar("angle", ImGuiDataType_Double, &angle, 0.01f);
    if (ImGui::IsItemActivated())
    {
        m_app.BeginEdit();
    }
    if (turned)
    {
        m_app.TurnBody(selected, angle);
    }
    if (ImGui::IsItemDeactivated())
    {
        m_app.EndEdit();
    }
    Vec2 velocity = bodies[static_cast<size_t>(selected)].velocity;
    const bool launched = ImGui::DragScalarN("velocity", ImGuiDataType_Double, &velocity.x, 2, 0.01f);
    if (ImGui::IsItemActivated())
    {
        m_app.BeginEdit();
    }
    if (launched)
    {
        m_app.SetVelocity(selected, velocity);
    }
    if (ImGui::IsItemDeactivated())
    {
        m_app.EndEdit();
    }
    Materials(selected);
}

// The selected body's material: static or dynamic, density, restitution and frictions, each field one edit from
// the moment it is grabbed to the moment it is let go, within the values a scene file accepts.
void Panels::Materials(int selected)
{
    const Body& body = m_app.ShownScene().bodies[static_cast<size_t>(selected)];
    bool isStatic = body.isStatic;
    double density = body.density;
    Material material = body.material;
    bool changed = false;
    bool single = false;
    auto field = [&](const char* label, double* value, double low, double high, const char* tip) {
        const bool moved = ImGui::DragScalar(label, ImGuiDataType_Double, value, 0.01f, &low, &high, "%.3g",
                                             ImGuiSliderFlags_AlwaysClamp);
        if (ImGui::IsItemHovered())
        {
            ImGui::SetTooltip("%s", tip);
        }
        if (ImGui::IsItemActivated())
        {
            m_app.BeginEdit();
        }
        changed = changed || moved;
        return ImGui::IsItemDeactivated();
    };
    if (ImGui::Checkbox("static (never moves)", &isStatic))
    {
        changed = true;
        single = true;
    }
    bool ended = false;
    if (!isStatic)
    {
        ended = field("density", &density, 1e-3, 1e6, "mass per unit area") || ended;
    }
    ended = field("restitution", &material.restitution, 0.0, 1.0,
                  "bounce: the ratio of the separating to the approaching normal speed (0: a dead stop, 1: elastic)") ||
            ended;
    ended = field("friction", &material.friction, 0.0, 10.0,
                  "dynamic friction: while sliding, the friction impulse is this times the normal impulse") ||
            ended;
    ended = field("static friction", &material.staticFriction, 0.0, 10.0,
                  "a contact sticks while the friction impulse it needs is at most this times the normal impulse") ||
            ended;
    if (changed)
    {
        m_app.SetMaterial(selected, isStatic, density, material);
    }
    if (ended && !single)
    {
        m_app.EndEdit();
    }
}

// [SECTION] Side panel: the simulation

namespace
{

// The state of the world at the step shown, one line for scripts that drive the window (the end-to-end test
// compares it with satviz-sim): every number printed so that it reads back as the same double.
void PrintState(const Simulation& sim)
{
    std::string line = "satviz: state step " + std::to_string(sim.Shown());
    char number[40];
    for (const RigidBody& body : sim.Record().world.bodies)
    {
        for (const double v :
             {body.position.x, body.position.y, body.angle, body.velocity.x, body.velocity.y, body.angularVelocity})
        {
            std::snprintf(number, sizeof number, " %.17g", v + 0.0);
            line += number;
        }
    }
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

} // namespace

void Panels::SimulationControls()
{
    const Simulation& sim = m_app.GetSimulation();
    if (!ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen))
    {
        return;
    }
    if (!sim.Error().empty())
    {
        WrappedTextDisabled("This scene cannot be stepped as a world: " + sim.Error());
        return;
    }
    if (!m_app.CanStep())
    {
        // Stepped by the format's defaults, a whole time unit a step, a figure's overlapping bodies are thrown
        // apart in one step and can fall asleep still inside each other: not a state to show a student.
        WrappedText("This scene has no world block, so its bodies stay where they are: a world says how long a step "
                    "is and what the gravity is. Add one to step the scene.");
        if (ImGui::Button("Add a world"))
        {
            m_app.AddWorld();
        }
        Announce("simulation Add a world");
        if (ImGui::IsItemHovered())
        {
            ImGui::SetTooltip("Steps of 1/60 s without gravity, as in lessons 14 to 17 (an edit: ctrl+z takes it "
                              "back)");
        }
        return;
    }
    if (ImGui::Button("Reset"))
    {
        m_app.SimReset();
    }
    Announce("simulation Reset");
    ImGui::SameLine();
    if (ImGui::Button("< Back"))
    {
        m_app.SimBack();
    }
    Announce("simulation Back");
    ImGui::SameLine();
    if (ImGui::Button(sim.Playing() ? "Pause###play" : "Play###play", ImVec2(60.0f, 0.0f)))
    {
        m_app.SimPlay(!sim.Playing());
    }
    Announce("simulation Play");
    ImGui::SameLine();
    if (ImGui::Button("Forward >"))
    {
        m_app.SimForward();
    }
    Announce("simulation Forward");
    ImGui::SameLine();
    ImGui::TextDisabled("(P , .)");
    if (ImGui::IsItemHovered())
    {
        ImGui::SetTooltip("P plays or pauses, ',' goes a step back, '.' a step forward");
    }
    int step = sim.Shown();
    const int last = std::max(sim.Last(), sim.First() + 1);
    const float stepWidth = ImGui::CalcItemWidth();
    if (ImGui::SliderInt("step", &step, sim.First(), last, "", ImGuiSliderFlags_AlwaysClamp))
    {
        m_app.SimShowStep(step);
    }
    SliderTextBesideGrab(stepWidth,
                         static_cast<float>(sim.Shown() - sim.First()) / static_cast<float>(last - sim.First()),
                         last - sim.First() + 1, std::to_string(sim.Shown()));
    if (ImGui::IsItemHovered())
    {
        ImGui::SetTooltip("Scrubs through the steps taken so far (the last %d are kept)", sim.Last() - sim.First() + 1);
    }
    float speed = static_cast<float>(sim.Speed());
    const float speedWidth = ImGui::CalcItemWidth();
    if (ImGui::SliderFloat("steps/s", &speed, 1.0f, 240.0f, "", ImGuiSliderFlags_Logarithmic))
    {
        m_app.SimSpeed(speed);
    }
    char speedText[32];
    std::snprintf(speedText, sizeof(speedText), "%.0f", static_cast<double>(speed));
    SliderTextBesideGrab(speedWidth, std::log(std::max(speed, 1.0f)) / std::log(240.0f), 0, speedText);
    // The step's time in the digits of the response's sentences (DescribeWorld); how many steps the app took is its
    // own.
    const WorldWords world = DescribeWorld(m_app.ShownScene(), sim.Record());
    WrappedText(world.time + "; " + StepsTakenWords(sim.Shown(), sim.Last()));
    if (sim.First() > 0)
    {
        ImGui::TextDisabled("steps before %d are no longer held", sim.First());
    }
    if (!sim.Playing() && m_printedStep != sim.Shown())
    {
        m_printedStep = sim.Shown();
        PrintState(sim);
    }
    if (sim.Playing())
    {
        m_printedStep = -1;
    }
    ResponseSteps();
}

// The step's contacts to choose from, and the solver's response on the chosen one, step by step (DescribeResponse:
// the sentences the figure's response panel draws).
void Panels::ResponseSteps()
{
    const Simulation& sim = m_app.GetSimulation();
    const SimRecord& record = sim.Record();
    if (sim.Shown() == 0 || sim.Shown() == sim.First())
    {
        WrappedTextDisabled("Take a step to see the step's contacts and the solver's response.");
        return;
    }
    const Scene& scene = m_app.ShownScene();
    const auto name = [&](int i) { return scene.bodies[static_cast<size_t>(i)].name; };
    // The words come from DescribeWorld, which the render tests check against the world they describe.
    const WorldWords world = DescribeWorld(scene, record);
    ImGui::TextUnformatted(world.contactsTitle.c_str());
    WrappedTextDisabled(world.contactsNote);
    const int chosenA = std::min(record.contact.bodyA, record.contact.bodyB);
    const int chosenB = std::max(record.contact.bodyA, record.contact.bodyB);
    if (!world.contacts.empty())
    {
        // A row too long for the list wraps between words, never inside a number (cut with "...", it hid the
        // second overlap of "slope and box: 2 points, overlap 0.000946 and ..."). The list is as high as its first
        // five rows, wrapped to the width inside its frame and beside its scroll bar.
        const ImGuiStyle& style = ImGui::GetStyle();
        const float width =
            std::max(ImGui::GetContentRegionAvail().x - 2.0f * style.WindowPadding.x - style.ScrollbarSize, 1.0f);
        std::vector<std::string> rows;
        float height = 2.0f * style.WindowPadding.y;
        for (const WorldContactWords& c : world.contacts)
        {
            rows.push_back(WrapToWidth(c.text, width));
            if (rows.size() <= 5)
            {
                height += ImGui::CalcTextSize(rows.back().c_str()).y + style.ItemSpacing.y;
            }
        }
        if (ImGui::BeginChild("##contacts", ImVec2(0.0f, height), true))
        {
            for (size_t i = 0; i < world.contacts.size(); ++i)
            {
                const WorldContactWords& c = world.contacts[i];
                ImGui::PushID(static_cast<int>(i));
                if (ImGui::Selectable(rows[i].c_str(), c.a == chosenA && c.b == chosenB))
                {
                    m_app.SimChooseContact(c.a, c.b);
                }
                ImGui::PopID();
                Announce("contact " + name(c.a) + " " + name(c.b));
            }
        }
        ImGui::EndChild();
    }
    if (ImGui::TreeNode("Bodies after this step"))
    {
        for (const std::string& line : world.bodies)
        {
            WrappedText(line);
        }
        ImGui::TreePop();
    }
    if (chosenA < 0)
    {
        return;
    }
    const std::vector<ResponseStep> steps = DescribeResponse(scene, record);
    WrappedText("Response of " + name(chosenA) + " and " + name(chosenB) + " in step " + std::to_string(sim.Shown()) +
                ":");
    std::string printed;
    for (const ResponseStep& step : steps)
    {
        WrappedText(step.title, ImVec4(0.2f, 0.35f, 0.6f, 1.0f));
        ImGui::Indent();
        WrappedText(step.sentence);
        ImGui::Unindent();
        printed += "satviz: response step " + std::to_string(sim.Shown()) + " " + name(chosenA) + " " + name(chosenB) +
                   ": " + step.title + ": " + step.sentence + "\n";
    }
    if (!sim.Playing() && printed != m_printedResponse)
    {
        // For scripts that drive the window: the steps shown, once per step and pair.
        m_printedResponse = printed;
        std::fputs(printed.c_str(), stdout);
        std::fflush(stdout);
    }
}

// [SECTION] Status bar, popups and help

std::string Panels::StatusText() const
{
    const Viewer& viewer = m_app.GetViewer();
    if (viewer.Studying())
    {
        return "Testing the pair (" + std::to_string(viewer.PairVertices(m_app.GetDocument().GetScene())) +
               " vertices) on a worker thread: its traced queries take long at this size; the figure follows when "
               "done";
    }
    return m_app.Status().empty()
               ? "Drag a body to move it, shift-drag to turn it; arrows step through the test; F1 for help"
               : m_app.Status();
}

// The status bar's text wrapped to the window's width, between words: at the smallest window a long message takes
// two lines rather than being cut at the edge.
static std::string StatusLines(const std::string& text)
{
    return WrapToWidth(text, std::max(1.0f, ImGui::GetMainViewport()->Size.x - 2.0f * kStatusPadding));
}

float Panels::StatusHeight() const
{
    const std::string lines = StatusLines(StatusText());
    const float count = static_cast<float>(1 + std::count(lines.begin(), lines.end(), '\n'));
    // The lines as StatusBar lays them out: the item spacing between them, the padding above and below.
    return std::max(ImGui::GetFrameHeight(), count * ImGui::GetTextLineHeight() +
                                                 (count - 1.0f) * ImGui::GetStyle().ItemSpacing.y +
                                                 2.0f * kStatusPaddingY);
}

void Panels::StatusBar()
{
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float height = StatusHeight();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x, viewport->Pos.y + viewport->Size.y - height));
    ImGui::SetNextWindowSize(ImVec2(viewport->Size.x, height));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(kStatusPadding, kStatusPaddingY));
    // Dear ImGui keeps a window at least 32 pixels tall: a one-line bar would run off the bottom of the window.
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1.0f, 1.0f));
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    const bool error = m_app.StatusIsError();
    if (error)
    {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.2f, 0.05f, 1.0f));
    }
    // One item a line, spaced as the panels' lines are: a wrapped message's second line does not sit on the
    // window's bottom edge.
    const std::string lines = StatusLines(StatusText());
    for (size_t start = 0; start <= lines.size();)
    {
        const size_t end = std::min(lines.find('\n', start), lines.size());
        ImGui::TextUnformatted(lines.data() + start, lines.data() + end);
        start = end + 1;
    }
    if (error)
    {
        ImGui::PopStyleColor();
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
}

std::string SaveAsSuggestion(const Document& document)
{
    const std::string name = document.File().empty()
                                 ? "scene.json"
                                 : std::filesystem::path(document.File()).stem().string() + "-edited.json";
    std::error_code code;
    const std::filesystem::path full = std::filesystem::absolute(name, code);
    return code ? name : full.string();
}

void Panels::Popups()
{
    const Document& document = m_app.GetDocument();
    if (m_askOpen)
    {
        m_askOpen = false;
        m_pathBuffer[0] = '\0';
        ImGui::OpenPopup("Open scene");
    }
    if (m_askSaveAs)
    {
        m_askSaveAs = false;
        std::snprintf(m_pathBuffer, sizeof(m_pathBuffer), "%s", SaveAsSuggestion(document).c_str());
        ImGui::OpenPopup("Save scene as");
    }
    if (m_askQuit)
    {
        m_askQuit = false;
        ImGui::OpenPopup("Unsaved changes");
    }
    if (m_askOpenUnsaved)
    {
        m_askOpenUnsaved = false;
        ImGui::OpenPopup("Unsaved changes before opening");
    }
    const ImVec2 center = ImGui::GetMainViewport()->GetCenter();
    if (PathPopup("Open scene", "Scene file (JSON):", "Open", m_pathBuffer, sizeof(m_pathBuffer)))
    {
        m_app.RequestOpen(m_pathBuffer);
    }
    const bool saveAsOpen = ImGui::IsPopupOpen("Save scene as");
    if (PathPopup("Save scene as", "Save to (JSON):", "Save", m_pathBuffer, sizeof(m_pathBuffer)))
    {
        m_app.Save(m_pathBuffer);
        if (m_openAfterSaveAs && !document.Dirty())
        {
            m_app.Open(m_app.PendingOpen(), m_app.PendingStep(), m_app.PendingFaces());
        }
        m_openAfterSaveAs = false;
    }
    else if (saveAsOpen && !ImGui::IsPopupOpen("Save scene as"))
    {
        m_openAfterSaveAs = false; // cancelled: the scene stays, nothing is opened
    }
    const std::string name = document.File().empty() ? "The scene" : document.File();
    // A button of a question, announced for the scripts that answer it.
    auto button = [this](const char* question, const char* label) {
        const bool pressed = ImGui::Button(label);
        Announce(std::string(question) + ": " + label);
        return pressed;
    };
    ImGui::SetNextWindowPos(center, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("%s has unsaved changes.", name.c_str());
        if (button("Unsaved changes", "Save and quit"))
        {
            if (document.File().empty() || document.ReadOnly())
            {
                ImGui::CloseCurrentPopup();
                m_askSaveAs = true;
            }
            else
            {
                m_app.Save(document.File());
                if (!document.Dirty())
                {
                    m_app.ConfirmQuit();
                }
                ImGui::CloseCurrentPopup();
            }
        }
        ImGui::SameLine();
        if (button("Unsaved changes", "Quit without saving"))
        {
            m_app.ConfirmQuit();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (button("Unsaved changes", "Cancel") || PressedNamed(ImGuiKey_Escape))
        {
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(center, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes before opening", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("%s has unsaved changes.", name.c_str());
        ImGui::Text("Open %s?", m_app.PendingOpen().c_str());
        if (button("Unsaved changes before opening", "Save and open"))
        {
            ImGui::CloseCurrentPopup();
            if (document.File().empty() || document.ReadOnly())
            {
                m_openAfterSaveAs = true;
                m_askSaveAs = true;
            }
            else
            {
                m_app.Save(document.File());
                if (!document.Dirty())
                {
                    m_app.Open(m_app.PendingOpen(), m_app.PendingStep(), m_app.PendingFaces());
                }
            }
        }
        ImGui::SameLine();
        if (button("Unsaved changes before opening", "Open without saving"))
        {
            ImGui::CloseCurrentPopup();
            m_app.Open(m_app.PendingOpen(), m_app.PendingStep(), m_app.PendingFaces());
        }
        ImGui::SameLine();
        if (button("Unsaved changes before opening", "Cancel") || PressedNamed(ImGuiKey_Escape))
        {
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

// The help's sections after its opening paragraph: the mouse, the keys (every key of AppKeys), the conventions.
const std::vector<HelpSection>& HelpSections()
{
    static const std::vector<HelpSection> sections = {
        {"Mouse",
         {"drag a body: move it;  shift-drag, or the round handle above it: turn it",
          "drag a vertex handle of the selected polygon: reshape it (it may become concave: it is cut into convex "
          "pieces; its outline must not cross itself)",
          "d, then click: draw a polygon vertex by vertex; click the first vertex or press Enter to close it, Esc to "
          "stop",
          "x, then drag a line across polygons: cut them (in the simulation, the bodies as they move there); Esc to "
          "stop",
          "drag the arrow tip (the white diamond, or beside a still body the diamond marked v): set the velocity (the "
          "arrow: one time unit)",
          "the hits layer: click a hit on its time bar to see its bodies at that instant (again: all hits)",
          "while the simulation plays, drag a body: it follows the pointer, and leaves at the pointer's speed when "
          "you let go (a throw)",
          "drag empty space, or with the right button: pan;  wheel: zoom about the pointer"}},
        {"Keys",
         {"left / right: previous / next step (past faces decided without evaluation);  space: play or pause",
          "p: play or pause the simulation;  , (comma) / . (period): its step before / next step",
          "ctrl+z / ctrl+y: undo / redo;  del: delete the selected body;  f: fit the pair",
          "ctrl+o: open;  ctrl+s: save;  ctrl+e: export a PNG;  ctrl+q: quit;  F1: this help"}},
        // As the scene format has it (core/scene/README.md, "velocity" and "world"): units per time unit, a step
        // lasting dt.
        {"Conventions",
         {"world y points up; angles are radians, counter-clockwise",
          "polygon vertices go counter-clockwise, the interior on their left",
          "the normal points from A to B: moving B by depth x normal separates the pair",
          "a velocity is in units per time unit: its arrow and the swept test (t from 0 to 1) cover one time unit",
          "a scene without a world block is not stepped: its velocity is the displacement over the swept test's t "
          "from 0 to 1, which its figures call one step (\"per step\"); lessons 14 to 17 have a world in metres and "
          "seconds (m/s, steps of dt = 1/60 s), so t runs over one second, 60 steps",
          "the simulation steps a scene that has a world block; Add a world, under Simulation, gives one to a scene "
          "that has none (steps of 1/60 s, no gravity)"}},
    };
    return sections;
}

void Panels::HelpOverlay()
{
    // Centred between the menu bar and the status bar, and no taller than the room between them: in a small window
    // it scrolls rather than cover the menus and the status line.
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float top = viewport->Pos.y + ImGui::GetFrameHeight();
    const float room = std::max(100.0f, viewport->Size.y - ImGui::GetFrameHeight() - StatusHeight());
    const float width = std::min(620.0f, viewport->Size.x);
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + 0.5f * viewport->Size.x, top + 0.5f * room), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, room));
    ImGui::SetNextWindowBgAlpha(0.96f);
    if (ImGui::Begin("Help (F1 or Esc closes)", &m_showHelp,
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize))
    {
        WrappedText("The Separating Axis Theorem: two convex shapes do not touch if and only if some axis "
                    "exists on which their projections (intervals) do not overlap. For polygons it is "
                    "enough to try the normals of their edges. The test projects both shapes on each axis "
                    "in turn and stops at the first gap. When every axis overlaps, the axis needing the "
                    "smallest push gives the minimum translation vector (MTV).");
        for (const HelpSection& section : HelpSections())
        {
            if (section.title == std::string("Mouse"))
            {
                ImGui::Separator();
            }
            ImGui::TextUnformatted(section.title);
            for (const char* line : section.lines)
            {
                HelpBullet(line);
            }
        }
    }
    ImGui::End();
}

// [SECTION] Lesson window

// The lesson beside the canvas: its text from the Markdown (md4c), buttons for its scenes, previous and next.
void Panels::LessonWindow()
{
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x, viewport->Pos.y + top));
    ImGui::SetNextWindowSize(ImVec2(kLessonWidth, viewport->Size.y - top - StatusHeight()));
    const int current = m_app.CurrentLesson();
    const int count = static_cast<int>(m_app.Lessons().size());
    const Lesson& lesson = m_app.Lessons()[static_cast<size_t>(current)];
    bool open = true;
    const bool shown = ImGui::Begin("Lesson###lesson", &open,
                                    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                        ImGuiWindowFlags_NoSavedSettings);
    if (!open)
    {
        m_app.CloseLesson();
    }
    if (!shown)
    {
        ImGui::End();
        return;
    }
    int go = current;
    ImGui::BeginDisabled(current <= 0);
    if (ImGui::Button("< Previous"))
    {
        go = current - 1;
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(current + 1 >= count);
    if (ImGui::Button("Next >"))
    {
        go = current + 1;
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled("lesson %d of %d", current + 1, count);
    if (!lesson.scenes.empty())
    {
        // The buttons go on in a row, and on the next line where the next one would pass the column's edge.
        ImGui::TextUnformatted("Scenes:");
        const ImGuiStyle& style = ImGui::GetStyle();
        for (const std::string& scene : lesson.scenes)
        {
            const std::string name = std::filesystem::path(scene).stem().string();
            const float width = ImGui::CalcTextSize(name.c_str()).x + 2.0f * style.FramePadding.x;
            ImGui::SameLine();
            if (width > ImGui::GetContentRegionAvail().x)
            {
                ImGui::NewLine();
            }
            const bool clicked = ImGui::SmallButton(name.c_str());
            Announce("lesson scene " + name);
            if (clicked)
            {
                // The lesson's first scene opens where opening the lesson shows it, at the figure its text begins
                // with; the others as their views ask.
                if (scene == lesson.scenes.front())
                {
                    m_app.RequestOpen(scene, lesson.firstStep, lesson.firstFaces);
                }
                else
                {
                    m_app.RequestOpen(scene);
                }
            }
        }
    }
    ImGui::Separator();
    ImGui::BeginChild("##lesson-text");
    if (m_lessonScrollTop)
    {
        ImGui::SetScrollY(0.0f);
        m_lessonScrollTop = false;
    }
    // A block quote ("In satviz": implementation detail) is drawn in a tinted box with a coloured bar on its
    // left, behind its blocks (drawn first on channel 1, the box after on channel 0). A <details> section (the
    // exercises' answers) is a collapsed header the student opens; its state is the lesson's own.
    ImDrawList* drawList = ImGui::GetWindowDrawList();
    const float quoteIndent = 14.0f;
    const float quotePad = 4.0f;
    bool inQuote = false;
    float quoteTop = 0.0f;
    auto endQuote = [&]() {
        if (!inQuote)
        {
            return;
        }
        inQuote = false;
        ImGui::EndGroup();
        const float bottom = ImGui::GetItemRectMax().y + quotePad;
        ImGui::Unindent(quoteIndent);
        drawList->ChannelsSetCurrent(0);
        const float left = ImGui::GetCursorScreenPos().x;
        const float right = left + ImGui::GetContentRegionAvail().x;
        const ImGuiStyle& style = ImGui::GetStyle();
        ImVec4 tint = style.Colors[ImGuiCol_FrameBg];
        tint.w = 0.35f;
        drawList->AddRectFilled(ImVec2(left, quoteTop), ImVec2(right, bottom), ImGui::GetColorU32(tint), 3.0f);
        drawList->AddRectFilled(ImVec2(left, quoteTop), ImVec2(left + 4.0f, bottom),
                                ImGui::GetColorU32(ImGuiCol_CheckMark));
        drawList->ChannelsMerge();
        ImGui::Dummy(ImVec2(0.0f, quotePad));
    };
    int details = 0;
    bool detailsOpen = true;
    std::vector<std::string> tableHeader; // the cells of the last table heading row
    for (const LessonBlock& block : m_app.LessonBlocks())
    {
        if (inQuote && (!block.quote || block.details != details))
        {
            endQuote();
        }
        if (block.details != details)
        {
            if (details > 0)
            {
                // The end of a collapsible section: a rule keeps what follows from reading as part of it.
                ImGui::Separator();
                ImGui::Spacing();
            }
            details = block.details;
            if (details > 0)
            {
                ImGui::Spacing();
                ImGui::PushID(current);
                ImGui::PushID(details);
                detailsOpen = ImGui::CollapsingHeader(block.summary.c_str());
                ImGui::PopID();
                ImGui::PopID();
            }
        }
        if (details > 0 && !detailsOpen)
        {
            continue;
        }
        if (block.quote && !inQuote)
        {
            inQuote = true;
            drawList->ChannelsSplit(2);
            drawList->ChannelsSetCurrent(1);
            quoteTop = ImGui::GetCursorScreenPos().y;
            ImGui::Dummy(ImVec2(0.0f, quotePad));
            ImGui::Indent(quoteIndent);
            ImGui::BeginGroup();
        }
        switch (block.kind)
        {
        case LessonBlock::Kind::Heading:
            ImGui::Spacing();
            ImGui::PushFont(m_app.Fonts().heading);
            WrappedText(block.text);
            ImGui::PopFont();
            break;
        case LessonBlock::Kind::Paragraph:
            if (block.header)
            {
                // A table's heading row names the cells of the rows below, each shown under its row's first cell.
                tableHeader = block.cells;
                break;
            }
            if (!block.cells.empty())
            {
                WrappedText(block.cells.front());
                ImGui::Indent(14.0f);
                for (size_t i = 1; i < block.cells.size(); ++i)
                {
                    const std::string name = i < tableHeader.size() ? tableHeader[i] + ": " : std::string();
                    WrappedTextDisabled(name + block.cells[i]);
                }
                ImGui::Unindent(14.0f);
                ImGui::Spacing();
                break;
            }
            WrappedText(block.text);
            ImGui::Spacing();
            break;
        case LessonBlock::Kind::Item:
            ImGui::Indent(static_cast<float>(block.level - 1) * 14.0f);
            if (block.number > 0)
            {
                // A numbered list keeps its numbers: the answers and the steps refer to them.
                ImGui::TextUnformatted((std::to_string(block.number) + ".").c_str());
                ImGui::SameLine();
            }
            else
            {
                ImGui::Bullet();
            }
            WrappedText(block.text);
            ImGui::Unindent(static_cast<float>(block.level - 1) * 14.0f);
            break;
        case LessonBlock::Kind::Code:
            // Each line wraps between its words, its indentation kept on its first line.
            WrappedTextDisabled(block.text);
            ImGui::Spacing();
            break;
        case LessonBlock::Kind::Figure:
        {
            // The figure is the canvas: a figure of a scene opens that scene there.
            WrappedTextDisabled("Figure: " + block.text);
            const std::string stem = SceneOfFigure(block.target);
            const std::string scene = FigureSceneFile(m_app.Options().lessonsDir, block.target);
            if (!scene.empty())
            {
                ImGui::PushID(&block);
                if (ImGui::SmallButton(("show " + stem).c_str()))
                {
                    m_app.RequestOpen(scene, FigureStep(block.target), FigureOfFaces(block.target));
                }
                ImGui::PopID();
            }
            ImGui::Spacing();
            break;
        }
        case LessonBlock::Kind::Rule:
            ImGui::Separator();
            break;
        }
    }
    endQuote();
    if (details > 0)
    {
        ImGui::Separator();
    }
    ImGui::EndChild();
    ImGui::End();
    if (go != current)
    {
        m_app.OpenLesson(go);
    }
}

} // namespace satviz
