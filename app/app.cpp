// SPDX-License-Identifier: MIT
// satviz app: menus, the side panel, popups and the edit history. The canvas and its mouse handling are in
// canvas.cpp.
#include "app.h"

#include <satviz/render/describe.h>
#include <satviz/render/layers.h>
#include <satviz/scene_world.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

namespace satviz
{

namespace
{

constexpr float kPanelWidth = 380.0f;
constexpr double kPlayInterval = 0.9; // seconds per step while playing

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
    if (confirmed || ImGui::Button("Cancel"))
    {
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return confirmed;
}

void HelpMarker(const char* text)
{
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
    {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
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

App::App(const FigureFonts& fonts, AppOptions options) : fonts_(fonts), options_(std::move(options))
{
    LoadRecent();
    if (options_.lessonsDir.empty() && !options_.scenesDir.empty())
    {
        options_.lessonsDir = std::filesystem::path(options_.scenesDir).parent_path().string();
    }
    if (!options_.lessonsDir.empty())
    {
        lessons_ = FindLessons(options_.lessonsDir);
    }
}

bool App::Open(const std::string& path)
{
    SceneResult result = LoadScene(path);
    if (!result.Ok())
    {
        SetStatus(result.error, true);
        return false;
    }
    if (result.scene.bodies.size() < 2)
    {
        SetStatus(path + ": bodies: the app needs at least two bodies to test", true);
        return false;
    }
    // A view that asks for rigid-body steps is shown where they leave the bodies, as satviz-render draws it. The
    // scene then holds that state, its sim_steps back to 0, so that a save or an export pictures what the canvas
    // shows.
    const int simSteps = result.scene.view.simSteps;
    if (const std::string error = SimulateScene(result.scene, simSteps); !error.empty())
    {
        SetStatus(path + ": " + error, true);
        return false;
    }
    result.scene.view.simSteps = 0;
    scene = std::move(result.scene);
    file = path;
    std::error_code code;
    const auto canonical = std::filesystem::weakly_canonical(path, code);
    const auto bundled = std::filesystem::weakly_canonical(options_.scenesDir, code);
    readOnly = !options_.scenesDir.empty() && canonical.parent_path() == bundled;
    dirty = false;
    undo_.clear();
    redo_.clear();
    selected = -1;
    drag = DragKind::None;
    playing = false;
    layers = scene.view.layers.empty() ? kDefaultLayers : LayersFromNames(scene.view.layers);
    cameraFit = scene.view.fit;
    if (!cameraFit)
    {
        camera.center = scene.view.center;
        camera.zoom = scene.view.zoom;
    }
    step = scene.view.step;
    // The figure of the scene before is no longer shown, nor a test of it still running taken in.
    setup = FigureSetup{};
    setup.error = "testing the pair";
    job_.reset();
    rerun_ = false;
    Refresh();
    Remember(path);
    SetStatus("Opened " + path +
                  (simSteps > 0 ? ", after " + std::to_string(simSteps) + " rigid-body step" +
                                      (simSteps == 1 ? "" : "s") + " (its view's sim_steps)"
                                : "") +
                  (readOnly ? " (a bundled scene: Save asks for a new file)" : ""),
              false);
    return true;
}

void App::SetStatus(const std::string& message, bool error)
{
    status = message;
    statusIsError = error;
}

int App::PairVertices() const
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
    return count(scene.view.bodyA, 0) + count(scene.view.bodyB, 1);
}

void App::Refresh()
{
    // The pair must still exist after edits (a deleted body, a renamed one).
    auto exists = [&](const std::string& name) {
        return std::any_of(scene.bodies.begin(), scene.bodies.end(), [&](const Body& b) { return b.name == name; });
    };
    if (!exists(scene.view.bodyA) || !exists(scene.view.bodyB) || scene.view.bodyA == scene.view.bodyB)
    {
        scene.view.bodyA.clear();
        scene.view.bodyB.clear();
    }
    FigureOptions options;
    options.width = canvasWidth;
    options.height = canvasHeight;
    options.setLayers = true;
    options.layers = layers;
    options.setStep = true;
    options.step = -1;
    Scene fitted = scene;
    fitted.view.fit = true;
    if (PairVertices() <= options_.backgroundVertices)
    {
        FigureSetup fresh = SetUpFigure(fitted, options);
        Adopt(std::move(fresh), std::move(fitted));
        return;
    }
    // The traced queries and the fit grow with the square of the vertex count (about 30 s for 100 000
    // vertices): they run on a worker thread while the interface goes on with the figure it has.
    if (!canvasSized_)
    {
        return; // the canvas's first frame gives its size, then the test starts
    }
    if (job_ != nullptr)
    {
        rerun_ = true; // one worker at a time; the latest scene runs when it ends
        return;
    }
    job_ = std::make_shared<StudyJob>();
    job_->scene = std::move(fitted);
    job_->options = options;
    std::thread([job = job_] {
        job->result = SetUpFigure(job->scene, job->options);
        job->done.store(true, std::memory_order_release);
    }).detach();
}

bool App::Studying() const
{
    return job_ != nullptr;
}

void App::PollStudy()
{
    if (job_ == nullptr || !job_->done.load(std::memory_order_acquire))
    {
        return;
    }
    const std::shared_ptr<StudyJob> finished = std::move(job_);
    job_.reset();
    Adopt(std::move(finished->result), std::move(finished->scene));
    if (rerun_)
    {
        rerun_ = false;
        Refresh();
    }
    else if (!statusIsError)
    {
        SetStatus("Tested the pair (" + std::to_string(PairVertices()) + " vertices) in the background", false);
    }
}

void App::Adopt(FigureSetup fresh, Scene studied)
{
    setup = std::move(fresh);
    studied_ = std::move(studied);
    if (!setup.Ok())
    {
        SetStatus(setup.error, true);
        return;
    }
    ShowStep();
    if (cameraFit)
    {
        camera = setup.figure.view;
    }
    camera.width = canvasWidth;
    camera.height = canvasHeight;
    setup.figure.view = camera;
}

void App::ShowStep()
{
    if (!setup.Ok())
    {
        return;
    }
    if (step < 0 || step >= setup.study.StepCount())
    {
        step = setup.study.VerdictStep();
    }
    setup.figure.step = step;
    setup.figure.time = scene.view.time;
    setup.figure.caption = scene.view.caption;
}

Scene App::SceneForSaving() const
{
    Scene saved = scene;
    saved.hasView = true;
    SceneView& view = saved.view;
    view.fit = cameraFit;
    if (!cameraFit)
    {
        // Within what a scene file accepts, so that the saved file opens again (a fit to a huge or tiny pair can
        // leave the camera beyond them).
        view.center = {std::clamp(camera.center.x, -kMaxSceneValue, kMaxSceneValue),
                       std::clamp(camera.center.y, -kMaxSceneValue, kMaxSceneValue)};
        view.zoom = std::clamp(camera.zoom, kMinViewZoom, kMaxViewZoom);
    }
    view.width = canvasWidth;
    view.height = canvasHeight;
    view.layers = LayerNames(layers);
    if (setup.Ok())
    {
        view.bodyA = studied_.bodies[static_cast<size_t>(setup.study.bodyA)].name;
        view.bodyB = studied_.bodies[static_cast<size_t>(setup.study.bodyB)].name;
        if (std::none_of(saved.bodies.begin(), saved.bodies.end(),
                         [&](const Body& b) { return b.name == view.bodyA; }) ||
            std::none_of(saved.bodies.begin(), saved.bodies.end(), [&](const Body& b) { return b.name == view.bodyB; }))
        {
            view.bodyA.clear(); // deleted while its test ran in the background
            view.bodyB.clear();
        }
    }
    view.step = step;
    return saved;
}

FigureSetup App::ExportFigure() const
{
    return SetUpFigure(SceneForSaving(), {});
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

bool App::RequestOpen(const std::string& path)
{
    if (!dirty)
    {
        return Open(path);
    }
    pendingOpen_ = path;
    askOpenUnsaved_ = true;
    return false;
}

bool App::RequestQuit()
{
    if (!dirty || quitConfirmed_)
    {
        quitConfirmed_ = true;
        return true;
    }
    askQuit_ = true;
    return false;
}

void App::BeginEdit()
{
    editStart_ = scene;
    editOpen_ = true;
}

void App::CommitEdit()
{
    if (!editOpen_)
    {
        return;
    }
    editOpen_ = false;
    if (SceneToJson(editStart_) == SceneToJson(scene))
    {
        return; // a click without a change is not an edit
    }
    undo_.push_back(std::move(editStart_));
    redo_.clear();
    dirty = true;
}

void App::CancelEdit()
{
    if (editOpen_)
    {
        scene = editStart_;
        editOpen_ = false;
        Refresh();
    }
}

bool App::Undo()
{
    if (undo_.empty() || editOpen_)
    {
        return false;
    }
    redo_.push_back(scene);
    scene = std::move(undo_.back());
    undo_.pop_back();
    dirty = true;
    selected = std::min(selected, static_cast<int>(scene.bodies.size()) - 1);
    Refresh();
    return true;
}

bool App::Redo()
{
    if (redo_.empty() || editOpen_)
    {
        return false;
    }
    undo_.push_back(scene);
    scene = std::move(redo_.back());
    redo_.pop_back();
    dirty = true;
    selected = std::min(selected, static_cast<int>(scene.bodies.size()) - 1);
    Refresh();
    return true;
}

void App::Save(const std::string& path)
{
    Scene saved = SceneForSaving();
    std::string error;
    if (!SaveScene(saved, path, error))
    {
        SetStatus(error, true);
        return;
    }
    scene = std::move(saved);
    file = path;
    readOnly = false;
    dirty = false;
    Remember(path);
    SetStatus("Saved " + path, false);
}

void App::AddBody(Shape shape, const std::string& stem)
{
    BeginEdit();
    Body body;
    body.name = UniqueName(scene, stem);
    body.shape = std::move(shape);
    body.position = camera.center;
    scene.bodies.push_back(std::move(body));
    selected = static_cast<int>(scene.bodies.size()) - 1;
    CommitEdit();
    Refresh();
    SetStatus("Added " + scene.bodies.back().name + ": drag it into place", false);
}

void App::DeleteSelected()
{
    if (selected < 0 || selected >= static_cast<int>(scene.bodies.size()))
    {
        SetStatus("Select a body first (click it)", true);
        return;
    }
    if (scene.bodies.size() <= 2)
    {
        SetStatus("The scene keeps at least two bodies: add one before deleting this one", true);
        return;
    }
    BeginEdit();
    const std::string name = scene.bodies[static_cast<size_t>(selected)].name;
    scene.bodies.erase(scene.bodies.begin() + selected);
    selected = -1;
    CommitEdit();
    Refresh();
    SetStatus("Deleted " + name, false);
}

void App::Remember(const std::string& path)
{
    if (!options_.updateRecent)
    {
        return;
    }
    std::error_code code;
    const std::string absolute = std::filesystem::absolute(path, code).string();
    recent.erase(std::remove(recent.begin(), recent.end(), absolute), recent.end());
    recent.insert(recent.begin(), absolute);
    if (recent.size() > 8)
    {
        recent.resize(8);
    }
    SaveRecent();
}

void App::LoadRecent()
{
    if (options_.recentFile.empty())
    {
        return;
    }
    std::ifstream in(options_.recentFile);
    for (std::string line; std::getline(in, line) && recent.size() < 8;)
    {
        if (!line.empty())
        {
            recent.push_back(line);
        }
    }
}

void App::SaveRecent() const
{
    if (options_.recentFile.empty())
    {
        return;
    }
    std::error_code code;
    std::filesystem::create_directories(std::filesystem::path(options_.recentFile).parent_path(), code);
    const std::string temporary = options_.recentFile + ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        for (const std::string& path : recent)
        {
            out << path << '\n';
        }
        if (!out)
        {
            return;
        }
    }
    std::filesystem::rename(temporary, options_.recentFile, code);
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

void App::Frame()
{
    PollStudy();
    Shortcuts();
    if (playing)
    {
        playClock_ += ImGui::GetIO().DeltaTime;
        if (playClock_ >= kPlayInterval)
        {
            playClock_ = 0.0;
            if (step < setup.study.VerdictStep())
            {
                ++step;
                ShowStep();
            }
            playing = step < setup.study.VerdictStep();
        }
    }
    MenuBar();
    CanvasWindow();
    SidePanel();
    StatusBar();
    Popups();
    if (showHelp)
    {
        HelpOverlay();
    }
    if (showLesson)
    {
        LessonWindow();
    }
}

void App::LessonsMenu()
{
    if (!ImGui::BeginMenu("Lessons", !lessons_.empty()))
    {
        return;
    }
    for (size_t i = 0; i < lessons_.size(); ++i)
    {
        if (ImGui::MenuItem(lessons_[i].title.c_str(), nullptr, static_cast<int>(i) == lesson_ && showLesson))
        {
            OpenLesson(static_cast<int>(i));
        }
    }
    ImGui::EndMenu();
}

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
    showLesson = true;
    lessonScrollTop_ = true;
    if (!lesson.scenes.empty() && lesson.scenes.front() != file)
    {
        RequestOpen(lesson.scenes.front());
    }
    return true;
}

// The lesson beside the canvas: its text from the Markdown (md4c), buttons for its scenes, previous and next.
void App::LessonWindow()
{
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x, viewport->Pos.y + top));
    ImGui::SetNextWindowSize(ImVec2(kLessonWidth, viewport->Size.y - 2.0f * top));
    const Lesson& lesson = lessons_[static_cast<size_t>(lesson_)];
    if (!ImGui::Begin("Lesson###lesson", &showLesson,
                      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                          ImGuiWindowFlags_NoSavedSettings))
    {
        ImGui::End();
        return;
    }
    int go = lesson_;
    ImGui::BeginDisabled(lesson_ <= 0);
    if (ImGui::Button("< Previous"))
    {
        go = lesson_ - 1;
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(lesson_ + 1 >= static_cast<int>(lessons_.size()));
    if (ImGui::Button("Next >"))
    {
        go = lesson_ + 1;
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled("lesson %d of %d", lesson_ + 1, static_cast<int>(lessons_.size()));
    if (!lesson.scenes.empty())
    {
        ImGui::TextUnformatted("Scenes:");
        for (const std::string& scene : lesson.scenes)
        {
            ImGui::SameLine();
            const std::string name = std::filesystem::path(scene).stem().string();
            if (ImGui::SmallButton(name.c_str()))
            {
                RequestOpen(scene);
            }
        }
    }
    ImGui::Separator();
    ImGui::BeginChild("##lesson-text");
    if (lessonScrollTop_)
    {
        ImGui::SetScrollY(0.0f);
        lessonScrollTop_ = false;
    }
    for (const LessonBlock& block : lessonBlocks_)
    {
        switch (block.kind)
        {
        case LessonBlock::Kind::Heading:
            ImGui::Spacing();
            ImGui::PushFont(fonts_.heading);
            ImGui::TextWrapped("%s", block.text.c_str());
            ImGui::PopFont();
            break;
        case LessonBlock::Kind::Paragraph:
            ImGui::TextWrapped("%s", block.text.c_str());
            ImGui::Spacing();
            break;
        case LessonBlock::Kind::Item:
            ImGui::Indent(static_cast<float>(block.level - 1) * 14.0f);
            ImGui::Bullet();
            ImGui::TextWrapped("%s", block.text.c_str());
            ImGui::Unindent(static_cast<float>(block.level - 1) * 14.0f);
            break;
        case LessonBlock::Kind::Code:
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            ImGui::TextUnformatted(block.text.c_str());
            ImGui::PopStyleColor();
            ImGui::Spacing();
            break;
        case LessonBlock::Kind::Figure:
        {
            // The figure is the canvas: a figure of a scene opens that scene there.
            ImGui::TextDisabled("Figure: %s", block.text.c_str());
            const std::string stem = SceneOfFigure(block.target);
            const std::string scene =
                (std::filesystem::path(options_.lessonsDir) / "scenes" / (stem + ".json")).string();
            if (std::filesystem::exists(scene))
            {
                ImGui::PushID(&block);
                if (ImGui::SmallButton(("show " + stem).c_str()))
                {
                    RequestOpen(scene);
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
    ImGui::EndChild();
    ImGui::End();
    if (go != lesson_)
    {
        OpenLesson(go);
    }
}

void App::Shortcuts()
{
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput)
    {
        return;
    }
    const AppKeys& k = options_.keys;
    if (Ctrl())
    {
        if (PressedNamed(ImGuiKey_Z))
        {
            if (!Undo())
            {
                SetStatus("Nothing to undo", false);
            }
        }
        if (PressedNamed(ImGuiKey_Y))
        {
            if (!Redo())
            {
                SetStatus("Nothing to redo", false);
            }
        }
        if (Pressed(k.s))
        {
            if (file.empty() || readOnly)
            {
                askSaveAs_ = true;
            }
            else
            {
                Save(file);
            }
        }
        if (Pressed(k.o))
        {
            askOpen_ = true;
        }
        if (Pressed(k.e))
        {
            exportRequested_ = true;
            std::filesystem::path target = options_.exportPath;
            if (target.empty())
            {
                const std::filesystem::path base = file.empty() ? "satviz.json" : file;
                target = base.parent_path() / (base.stem().string() + "-step" + std::to_string(step + 1) + ".png");
            }
            exportPath_ = target.string();
        }
        if (Pressed(k.q))
        {
            RequestQuit();
        }
        return;
    }
    if (PressedNamed(ImGuiKey_Space))
    {
        playing = !playing;
        playClock_ = 0.0;
        if (playing && step >= setup.study.VerdictStep())
        {
            step = 0;
            ShowStep();
        }
    }
    if (PressedNamed(ImGuiKey_RightArrow) && step < setup.study.VerdictStep())
    {
        ++step;
        ShowStep();
    }
    if (PressedNamed(ImGuiKey_LeftArrow) && step > 0)
    {
        --step;
        ShowStep();
    }
    if (PressedNamed(ImGuiKey_Delete))
    {
        DeleteSelected();
    }
    if (Pressed(k.f1))
    {
        showHelp = !showHelp;
    }
    if (Pressed(k.f))
    {
        cameraFit = true;
        Refresh();
    }
    if (PressedNamed(ImGuiKey_Escape))
    {
        showHelp = false;
    }
}

void App::MenuBar()
{
    if (!ImGui::BeginMainMenuBar())
    {
        return;
    }
    if (ImGui::BeginMenu("File"))
    {
        if (ImGui::MenuItem("Open...", "Ctrl+O"))
        {
            askOpen_ = true;
        }
        if (ImGui::BeginMenu("Bundled scenes"))
        {
            for (const std::string& path : BundledScenes())
            {
                if (ImGui::MenuItem(std::filesystem::path(path).stem().string().c_str()))
                {
                    RequestOpen(path);
                }
            }
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("Recent", !recent.empty()))
        {
            for (const std::string& path : std::vector<std::string>(recent))
            {
                if (ImGui::MenuItem(path.c_str()))
                {
                    RequestOpen(path);
                }
            }
            ImGui::EndMenu();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Save", "Ctrl+S"))
        {
            if (file.empty() || readOnly)
            {
                askSaveAs_ = true;
            }
            else
            {
                Save(file);
            }
        }
        if (ImGui::MenuItem("Save as..."))
        {
            askSaveAs_ = true;
        }
        if (ImGui::MenuItem("Export PNG", "Ctrl+E"))
        {
            exportRequested_ = true;
            const std::filesystem::path base = file.empty() ? "satviz.json" : file;
            exportPath_ =
                options_.exportPath.empty()
                    ? (base.parent_path() / (base.stem().string() + "-step" + std::to_string(step + 1) + ".png"))
                          .string()
                    : options_.exportPath;
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q"))
        {
            RequestQuit();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit"))
    {
        if (ImGui::MenuItem("Undo", "Ctrl+Z", false, !undo_.empty()))
        {
            Undo();
        }
        if (ImGui::MenuItem("Redo", "Ctrl+Y", false, !redo_.empty()))
        {
            Redo();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Add box"))
        {
            AddBody(MakeShape(MakeBox(0.5, 0.5).polygon), "box");
        }
        if (ImGui::MenuItem("Add triangle"))
        {
            AddBody(MakeShape(MakeRegularPolygon(3, 0.6).polygon), "triangle");
        }
        if (ImGui::MenuItem("Add regular polygon"))
        {
            AddBody(MakeShape(MakeRegularPolygon(newSides_, 0.6).polygon), "polygon");
        }
        ImGui::SetNextItemWidth(120.0f);
        if (ImGui::InputInt("sides", &newSides_))
        {
            newSides_ = std::clamp(newSides_, 3, 4096);
        }
        if (ImGui::MenuItem("Add circle"))
        {
            AddBody(MakeShape(Circle{{0.0, 0.0}, 0.5}), "circle");
        }
        if (ImGui::MenuItem("Delete selected", "Del", false, selected >= 0))
        {
            DeleteSelected();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View"))
    {
        if (ImGui::MenuItem("Fit the pair", "F"))
        {
            cameraFit = true;
            Refresh();
        }
        ImGui::Separator();
        LayerToggles();
        ImGui::Separator();
        ImGui::MenuItem("Help", "F1", &showHelp);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help"))
    {
        ImGui::MenuItem("Controls and conventions", "F1", &showHelp);
        LessonsMenu();
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

// One switch per row of the layer table, with its description as the tooltip.
void App::LayerToggles()
{
    for (const LayerInfo& layer : kLayerTable)
    {
        bool on = (layers & layer.bit) != 0;
        if (ImGui::Checkbox(std::string(layer.name).c_str(), &on))
        {
            layers = on ? (layers | layer.bit) : (layers & ~layer.bit);
            Refresh();
        }
        if (ImGui::IsItemHovered())
        {
            ImGui::SetTooltip("%.*s", static_cast<int>(layer.description.size()), layer.description.data());
        }
    }
}

void App::SidePanel()
{
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x - kPanelWidth, viewport->Pos.y + top));
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, viewport->Size.y - 2.0f * top));
    ImGui::Begin("##panel", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    const std::string title =
        (file.empty() ? std::string("untitled") : std::filesystem::path(file).filename().string()) +
        (dirty ? " (modified)" : "");
    ImGui::TextUnformatted(title.c_str());
    if (!scene.description.empty())
    {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", scene.description.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::Separator();
    if (setup.Ok())
    {
        StepControls();
        Inspector();
    }
    if (ImGui::CollapsingHeader("Layers"))
    {
        LayerToggles();
    }
    ImGui::End();
}

void App::StepControls()
{
    const PairStudy& study = setup.study;
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
                (std::string(s == 0 ? "A: " : "B: ") + studied_.bodies[static_cast<size_t>(current)].name).c_str()))
        {
            for (size_t i = 0; i < studied_.bodies.size(); ++i)
            {
                const int other = s == 0 ? study.bodyB : study.bodyA;
                if (static_cast<int>(i) == other)
                {
                    continue;
                }
                if (ImGui::Selectable(studied_.bodies[i].name.c_str(), static_cast<int>(i) == current))
                {
                    scene.view.bodyA = studied_.bodies[static_cast<size_t>(s == 0 ? static_cast<int>(i) : other)].name;
                    scene.view.bodyB = studied_.bodies[static_cast<size_t>(s == 0 ? other : static_cast<int>(i))].name;
                    dirty = true;
                    Refresh();
                }
            }
            ImGui::EndCombo();
        }
    }
    int query = static_cast<int>(scene.view.query);
    const char* queries[] = {"automatic (sweep when moving)", "static test (Collide)", "swept test (Sweep)"};
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::Combo("##query", &query, queries, 3))
    {
        scene.view.query = static_cast<ViewQuery>(query);
        dirty = true;
        Refresh();
    }
    int steps = scene.view.steps == StepView::Faces ? 1 : 0;
    const char* views[] = {"textbook SAT: both intervals per axis", "face tests, as the fast path runs them"};
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::Combo("##steps", &steps, views, 2))
    {
        scene.view.steps = steps == 1 ? StepView::Faces : StepView::Textbook;
        dirty = true;
        Refresh();
    }
    if (ImGui::IsItemHovered())
    {
        ImGui::SetTooltip("The textbook test projects both shapes on each distinct axis and compares the intervals.\n"
                          "The fast queries test faces instead: does the other shape lie wholly beyond this face?\n"
                          "Each axis is two face tests, one per side; both give the same verdict and MTV.");
    }
    // A classic mistake beside the right answer: the library never takes it, the view shows what it would do.
    int pitfall = static_cast<int>(scene.view.pitfall);
    const char* pitfalls[] = {"no pitfall",
                              "pitfall: axes not normalised",
                              "pitfall: push direction not checked",
                              "pitfall: only A's axes tested",
                              "pitfall: motion sampled, not swept",
                              "pitfall: float on world coordinates"};
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::Combo("##pitfall", &pitfall, pitfalls, static_cast<int>(std::size(pitfalls))))
    {
        scene.view.pitfall = static_cast<Pitfall>(pitfall);
        dirty = true;
        Refresh();
    }
    if (ImGui::IsItemHovered())
    {
        ImGui::SetTooltip(
            "Shows what a classic SAT mistake would answer, beside the right answer, on the verdict step\n"
            "(a dashed arrow and a sentence). The library's queries never make it.");
    }

    ImGui::Separator();
    const int last = study.VerdictStep();
    ImGui::BeginDisabled(step <= 0);
    if (ImGui::ArrowButton("##previous", ImGuiDir_Left))
    {
        --step;
        ShowStep();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(step >= last);
    if (ImGui::ArrowButton("##next", ImGuiDir_Right))
    {
        ++step;
        ShowStep();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button(playing ? "Pause" : "Play"))
    {
        playing = !playing;
        playClock_ = 0.0;
        if (playing && step >= last)
        {
            step = 0;
            ShowStep();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Verdict"))
    {
        step = last;
        ShowStep();
    }
    ImGui::SameLine();
    ImGui::Text("step %d of %d", step + 1, study.StepCount());
    ImGui::SetNextItemWidth(-1.0f);
    int shown = step;
    const std::string sliderText = step == last ? "verdict" : "axis " + std::to_string(step + 1);
    if (ImGui::SliderInt("##step", &shown, 0, last, sliderText.c_str()) && shown != step)
    {
        step = shown;
        ShowStep();
    }
    ImGui::TextWrapped("%s", DescribeStep(studied_, study, step).c_str());

    ImGui::Separator();
    ImGui::TextUnformatted(study.Textbook() ? "Axes tested (click one)" : "Face tests run (click one)");
    HelpMarker(study.Textbook()
                   ? "Each row is one axis: the overlap of the two intervals on it (the shorter push that separates "
                     "them) or the gap between them. The test stops at the first axis with a gap (a separating axis)."
                   : "Each row is one face test: how far the other shape reaches behind the face, or how far beyond "
                     "it it lies. The test stops at the first face with the other shape wholly beyond it.");
    const float rows = std::min<float>(static_cast<float>(study.StepCount()), 9.0f);
    if (ImGui::BeginChild("##axes", ImVec2(0.0f, rows * ImGui::GetTextLineHeightWithSpacing() + 8.0f), true))
    {
        // Only the rows in sight are built: a polygon of 100 000 vertices has as many steps.
        const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
        if (ImGui::IsWindowAppearing())
        {
            ImGui::SetScrollY(std::max(0.0f, (static_cast<float>(step) - 4.0f) * rowHeight));
        }
        ImGuiListClipper clipper;
        clipper.Begin(study.StepCount(), rowHeight);
        while (clipper.Step())
        {
            for (int k = clipper.DisplayStart; k < clipper.DisplayEnd; ++k)
            {
                if (ImGui::Selectable(StepTitle(studied_, study, k).c_str(), k == step))
                {
                    step = k;
                    ShowStep();
                }
            }
        }
    }
    ImGui::EndChild();

    if (study.sweep)
    {
        bool showTime = scene.view.time >= 0.0;
        if (ImGui::Checkbox("bodies at time", &showTime))
        {
            scene.view.time = showTime ? 0.5 : -1.0;
            ShowStep();
        }
        ImGui::SameLine();
        float t = static_cast<float>(std::max(scene.view.time, 0.0));
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::BeginDisabled(!showTime);
        if (ImGui::SliderFloat("##time", &t, 0.0f, 1.0f, "t = %.3f"))
        {
            scene.view.time = t;
            ShowStep();
        }
        ImGui::EndDisabled();
    }
}

void App::Inspector()
{
    if (!ImGui::CollapsingHeader("Numbers", ImGuiTreeNodeFlags_DefaultOpen))
    {
        return;
    }
    bool single = scene.view.singlePrecision;
    if (ImGui::Checkbox("single precision (float)", &single))
    {
        scene.view.singlePrecision = single;
        dirty = true;
        Refresh();
    }
    HelpMarker("Runs the float instantiation of the queries on the shapes rounded to float: compare its numbers "
               "with double's to see what the precision costs.");
    const PairStudy& study = setup.study;
    if (single && !study.singlePrecision)
    {
        ImGui::TextWrapped("A polygon is not valid once rounded to float: the numbers are double.");
    }
    // Every number in full, as the shortest decimal that reads back as the same value.
    auto full = [&](double v) {
        return study.singlePrecision ? ShortestDecimal(static_cast<float>(v)) : ShortestDecimal(v);
    };
    auto point = [&](Vec2 p) { return "(" + full(p.x) + ", " + full(p.y) + ")"; };
    const Manifold& m = study.manifold;
    ImGui::Text("overlap: %s", m.overlap ? "yes" : "no");
    // The textbook view shows the MTV its own test found; the contact points come from Collide's clipping.
    const bool textbook = study.Textbook();
    const double depth = textbook ? study.textbookResult.depth : m.depth;
    const double gap = textbook ? study.textbookResult.gap : m.gap;
    const Vec2 normal = textbook ? study.textbookResult.normal : m.normal;
    if (m.overlap)
    {
        ImGui::Text("MTV length (depth): %s", full(depth).c_str());
    }
    else
    {
        ImGui::Text("gap on the separating axis: %s", full(gap).c_str());
    }
    ImGui::Text("%s: %s", m.overlap ? "MTV direction (A to B)" : "separating axis (A to B)", point(normal).c_str());
    for (int i = 0; i < m.contactCount; ++i)
    {
        // In the order the figure labels them c1, c2, and satviz-query lists "contacts".
        ImGui::Text(study.sweep ? "contact c%d at t = 0: %s" : "contact c%d: %s", i + 1,
                    point(m.contacts[i].point).c_str());
    }
    if (study.sweep)
    {
        const SweepResult& r = study.sweepResult;
        if (r.status == SweepStatus::Hit)
        {
            ImGui::Text("time of impact: %s", full(r.toi).c_str());
            ImGui::Text("normal at impact: %s", point(r.normal).c_str());
            // The contacts the figure labels c1, c2 in a sweep (satviz-query's "toi_contacts", in that order).
            for (int i = 0; i < r.contactCount; ++i)
            {
                ImGui::Text("contact c%d at impact: %s", i + 1, point(r.contacts[i].point).c_str());
            }
        }
        else
        {
            ImGui::TextUnformatted("time of impact: none (no hit in this step)");
        }
    }
    else if (study.startsOverlapping)
    {
        ImGui::TextUnformatted("moving, but overlapping at t = 0: no time of impact");
    }
    if (selected >= 0 && selected < static_cast<int>(scene.bodies.size()))
    {
        Body& body = scene.bodies[static_cast<size_t>(selected)];
        ImGui::Separator();
        ImGui::Text("selected: %s", body.name.c_str());
        bool changed = false;
        changed |= ImGui::DragScalarN("position", ImGuiDataType_Double, &body.position.x, 2, 0.01f);
        if (ImGui::IsItemActivated())
        {
            BeginEdit();
        }
        if (ImGui::IsItemDeactivated())
        {
            CommitEdit();
        }
        changed |= ImGui::DragScalar("angle", ImGuiDataType_Double, &body.angle, 0.01f);
        if (ImGui::IsItemActivated())
        {
            BeginEdit();
        }
        if (ImGui::IsItemDeactivated())
        {
            CommitEdit();
        }
        changed |= ImGui::DragScalarN("velocity", ImGuiDataType_Double, &body.velocity.x, 2, 0.01f);
        if (ImGui::IsItemActivated())
        {
            BeginEdit();
        }
        if (ImGui::IsItemDeactivated())
        {
            CommitEdit();
        }
        if (changed)
        {
            Refresh();
        }
    }
}

void App::StatusBar()
{
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float height = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x, viewport->Pos.y + viewport->Size.y - height));
    ImGui::SetNextWindowSize(ImVec2(viewport->Size.x, height));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 3.0f));
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    if (statusIsError)
    {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.2f, 0.05f, 1.0f));
    }
    const std::string studying =
        "Testing the pair (" + std::to_string(PairVertices()) +
        " vertices) on a worker thread: its traced queries take long at this size; the figure follows when done";
    ImGui::TextUnformatted(Studying()       ? studying.c_str()
                           : status.empty() ? "Drag a body to move it, shift-drag to turn it; arrows step through "
                                              "the test; F1 for help"
                                            : status.c_str());
    if (statusIsError)
    {
        ImGui::PopStyleColor();
    }
    ImGui::End();
    ImGui::PopStyleVar();
}

void App::Popups()
{
    if (askOpen_)
    {
        askOpen_ = false;
        pathBuffer_[0] = '\0';
        ImGui::OpenPopup("Open scene");
    }
    if (askSaveAs_)
    {
        askSaveAs_ = false;
        const std::string suggestion =
            file.empty() ? "scene.json" : (std::filesystem::path(file).stem().string() + "-edited.json");
        std::snprintf(pathBuffer_, sizeof(pathBuffer_), "%s", suggestion.c_str());
        ImGui::OpenPopup("Save scene as");
    }
    if (askQuit_)
    {
        askQuit_ = false;
        ImGui::OpenPopup("Unsaved changes");
    }
    if (askOpenUnsaved_)
    {
        askOpenUnsaved_ = false;
        ImGui::OpenPopup("Unsaved changes before opening");
    }
    const ImVec2 center = ImGui::GetMainViewport()->GetCenter();
    if (PathPopup("Open scene", "Scene file (JSON):", "Open", pathBuffer_, sizeof(pathBuffer_)))
    {
        RequestOpen(pathBuffer_);
    }
    const bool saveAsOpen = ImGui::IsPopupOpen("Save scene as");
    if (PathPopup("Save scene as", "Save to (JSON):", "Save", pathBuffer_, sizeof(pathBuffer_)))
    {
        Save(pathBuffer_);
        if (openAfterSaveAs_ && !dirty)
        {
            Open(pendingOpen_);
        }
        openAfterSaveAs_ = false;
    }
    else if (saveAsOpen && !ImGui::IsPopupOpen("Save scene as"))
    {
        openAfterSaveAs_ = false; // cancelled: the scene stays, nothing is opened
    }
    ImGui::SetNextWindowPos(center, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("%s has unsaved changes.", file.empty() ? "The scene" : file.c_str());
        if (ImGui::Button("Save and quit"))
        {
            if (file.empty() || readOnly)
            {
                ImGui::CloseCurrentPopup();
                askSaveAs_ = true;
            }
            else
            {
                Save(file);
                quitConfirmed_ = !dirty;
                ImGui::CloseCurrentPopup();
            }
        }
        ImGui::SameLine();
        if (ImGui::Button("Quit without saving"))
        {
            quitConfirmed_ = true;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel"))
        {
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(center, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes before opening", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("%s has unsaved changes.", file.empty() ? "The scene" : file.c_str());
        ImGui::Text("Open %s?", pendingOpen_.c_str());
        if (ImGui::Button("Save and open"))
        {
            ImGui::CloseCurrentPopup();
            if (file.empty() || readOnly)
            {
                openAfterSaveAs_ = true;
                askSaveAs_ = true;
            }
            else
            {
                Save(file);
                if (!dirty)
                {
                    Open(pendingOpen_);
                }
            }
        }
        ImGui::SameLine();
        if (ImGui::Button("Open without saving"))
        {
            ImGui::CloseCurrentPopup();
            Open(pendingOpen_);
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel"))
        {
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

void App::HelpOverlay()
{
    const ImVec2 center = ImGui::GetMainViewport()->GetCenter();
    ImGui::SetNextWindowPos(center, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(620.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.96f);
    if (ImGui::Begin("Help (F1 or Esc closes)", &showHelp,
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize))
    {
        ImGui::TextWrapped("The Separating Axis Theorem: two convex shapes do not touch if and only if some axis "
                           "exists on which their projections (intervals) do not overlap. For polygons it is "
                           "enough to try the normals of their edges. The test projects both shapes on each axis "
                           "in turn and stops at the first gap. When every axis overlaps, the axis needing the "
                           "smallest push gives the minimum translation vector (MTV).");
        ImGui::Separator();
        ImGui::TextUnformatted("Mouse");
        ImGui::BulletText("drag a body: move it;  shift-drag, or the round handle above it: turn it");
        ImGui::BulletText("drag a vertex handle of the selected polygon: reshape it (it must stay convex)");
        ImGui::BulletText("drag the arrow tip (or the small v handle): set the velocity over one step");
        ImGui::BulletText("drag empty space, or with the right button: pan;  wheel: zoom about the pointer");
        ImGui::TextUnformatted("Keys");
        ImGui::BulletText("left / right: previous / next step;  space: play or pause");
        ImGui::BulletText("ctrl+z / ctrl+y: undo / redo;  del: delete the selected body;  f: fit the pair");
        ImGui::BulletText("ctrl+o: open;  ctrl+s: save;  ctrl+e: export a PNG;  ctrl+q: quit;  F1: this help");
        ImGui::TextUnformatted("Conventions");
        ImGui::BulletText("world y points up; angles are radians, counter-clockwise");
        ImGui::BulletText("polygon vertices go counter-clockwise, the interior on their left");
        ImGui::BulletText("the normal points from A to B: moving B by depth x normal separates the pair");
        ImGui::BulletText("a velocity is the displacement over one step; t runs from 0 to 1");
    }
    ImGui::End();
}

} // namespace satviz
