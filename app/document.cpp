// SPDX-License-Identifier: MIT
#include "document.h"

#include <satviz/scene_world.h>

#include <filesystem>
#include <utility>

namespace satviz
{

namespace
{

// What a change of the scene is measured on: the scene as its file would hold it, without the view block.
std::string SceneContent(Scene scene)
{
    scene.hasView = false;
    scene.view = SceneView{};
    return SceneToJson(scene);
}

} // namespace

void Document::Measure()
{
    dirty_ = SceneContent(scene_) != savedContent_;
}

OpenResult Document::Open(const std::string& path, const std::string& bundledDir)
{
    OpenResult opened;
    // A polygon may be concave: decomposed on load, as satviz-render and satviz-sim read it.
    SceneOptions options;
    options.concave = true;
    SceneResult result = LoadScene(path, options);
    if (!result.Ok())
    {
        opened.error = result.error;
        return opened;
    }
    // A figure of one body (a decomposition, a slice) tests no pair: its scene may hold that body alone, as
    // satviz-render draws it. Any other figure tests a pair.
    const FigureKind figure = result.scene.view.figure;
    const bool ofOneBody = figure == FigureKind::Decomposition || figure == FigureKind::Slice;
    if (result.scene.bodies.empty() || (result.scene.bodies.size() < 2 && !ofOneBody))
    {
        opened.error = path + ": bodies: the app needs at least two bodies to test, or one for a view.figure of "
                              "one body (\"decomposition\", \"slice\")";
        return opened;
    }
    // A view that asks for rigid-body steps is shown where they leave the bodies, as satviz-render draws it: the
    // app's simulation takes them from the scene as written, which the document keeps. A state they would leave
    // beyond what a scene holds is refused here, as satviz-render refuses it.
    opened.simSteps = result.scene.view.simSteps;
    if (opened.simSteps > 0)
    {
        Scene stepped = result.scene;
        if (const std::string error = SimulateScene(stepped, opened.simSteps); !error.empty())
        {
            opened.error = path + ": " + error;
            return opened;
        }
    }
    scene_ = std::move(result.scene);
    file_ = path;
    std::error_code code;
    const auto canonical = std::filesystem::weakly_canonical(path, code);
    const auto bundled = std::filesystem::weakly_canonical(bundledDir, code);
    // The bundled scenes' folder and its folders (tutorials/scenes/concave...).
    const std::filesystem::path within = canonical.lexically_relative(bundled);
    readOnly_ = !bundledDir.empty() && !within.empty() && *within.begin() != "..";
    savedContent_ = SceneContent(scene_);
    dirty_ = false;
    undo_.clear();
    redo_.clear();
    editOpen_ = false;
    opened.ok = true;
    return opened;
}

bool Document::Save(Scene saved, const std::string& path, std::string& error)
{
    if (!SaveScene(saved, path, error))
    {
        return false;
    }
    scene_ = std::move(saved);
    file_ = path;
    readOnly_ = false;
    savedContent_ = SceneContent(scene_);
    dirty_ = false;
    return true;
}

void Document::BeginEdit(const ViewChoices& choices)
{
    if (editOpen_)
    {
        return;
    }
    editStart_ = {scene_, choices};
    editOpen_ = true;
    editTouched_ = false;
}

void Document::AddBody(Body body)
{
    editTouched_ = true;
    scene_.bodies.push_back(std::move(body));
}

void Document::RemoveBody(size_t index)
{
    editTouched_ = true;
    scene_.bodies.erase(scene_.bodies.begin() + static_cast<std::ptrdiff_t>(index));
}

bool Document::CommitEdit()
{
    if (!editOpen_)
    {
        return false;
    }
    editOpen_ = false;
    if (SceneToJson(editStart_.scene) == SceneToJson(scene_))
    {
        return false; // a click without a change is not an edit
    }
    undo_.push_back(std::move(editStart_));
    redo_.clear();
    Measure(); // a drag back to where the file has the body is no change
    return true;
}

void Document::RecordChoices(const ViewChoices& before)
{
    undo_.push_back({scene_, before});
    redo_.clear();
}

bool Document::Undo(ViewChoices& choices)
{
    if (undo_.empty() || editOpen_)
    {
        return false;
    }
    redo_.push_back({std::move(scene_), choices});
    scene_ = std::move(undo_.back().scene);
    choices = std::move(undo_.back().choices);
    undo_.pop_back();
    Measure();
    return true;
}

bool Document::Redo(ViewChoices& choices)
{
    if (redo_.empty() || editOpen_)
    {
        return false;
    }
    undo_.push_back({std::move(scene_), choices});
    scene_ = std::move(redo_.back().scene);
    choices = std::move(redo_.back().choices);
    redo_.pop_back();
    Measure();
    return true;
}

} // namespace satviz
