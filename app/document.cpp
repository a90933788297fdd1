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
    m_dirty = SceneContent(m_scene) != m_savedContent;
    ++m_revision;
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
    m_scene = std::move(result.scene);
    m_file = path;
    std::error_code code;
    const auto canonical = std::filesystem::weakly_canonical(path, code);
    const auto bundled = std::filesystem::weakly_canonical(bundledDir, code);
    // The bundled scenes' folder and its folders (tutorials/scenes/concave...).
    const std::filesystem::path within = canonical.lexically_relative(bundled);
    m_readOnly = !bundledDir.empty() && !within.empty() && *within.begin() != "..";
    m_savedContent = SceneContent(m_scene);
    m_dirty = false;
    ++m_revision;
    m_undo.clear();
    m_redo.clear();
    m_editOpen = false;
    opened.ok = true;
    return opened;
}

bool Document::Save(Scene saved, const std::string& path, std::string& error)
{
    if (!SaveScene(saved, path, error))
    {
        return false;
    }
    m_scene = std::move(saved);
    m_file = path;
    m_readOnly = false;
    m_savedContent = SceneContent(m_scene);
    m_dirty = false;
    ++m_revision;
    return true;
}

void Document::BeginEdit(const ViewChoices& choices)
{
    if (m_editOpen)
    {
        return;
    }
    m_editStart = {m_scene, choices};
    m_editOpen = true;
    m_editTouched = false;
}

void Document::AddBody(Body body)
{
    m_editTouched = true;
    m_scene.bodies.push_back(std::move(body));
}

void Document::RemoveBody(size_t index)
{
    m_editTouched = true;
    m_scene.bodies.erase(m_scene.bodies.begin() + static_cast<std::ptrdiff_t>(index));
}

void Document::SetWorld(const SceneWorld& world)
{
    m_editTouched = true;
    m_scene.hasWorld = true;
    m_scene.world = world;
}

bool Document::CommitEdit()
{
    if (!m_editOpen)
    {
        return false;
    }
    m_editOpen = false;
    if (SceneToJson(m_editStart.scene) == SceneToJson(m_scene))
    {
        return false; // a click without a change is not an edit
    }
    m_undo.push_back(std::move(m_editStart));
    m_redo.clear();
    Measure(); // a drag back to where the file has the body is no change
    return true;
}

void Document::RecordChoices(const ViewChoices& before)
{
    m_undo.push_back({m_scene, before});
    m_redo.clear();
}

bool Document::Undo(ViewChoices& choices)
{
    if (m_undo.empty() || m_editOpen)
    {
        return false;
    }
    m_redo.push_back({std::move(m_scene), choices});
    m_scene = std::move(m_undo.back().scene);
    choices = std::move(m_undo.back().choices);
    m_undo.pop_back();
    Measure();
    return true;
}

bool Document::Redo(ViewChoices& choices)
{
    if (m_redo.empty() || m_editOpen)
    {
        return false;
    }
    m_undo.push_back({std::move(m_scene), choices});
    m_scene = std::move(m_redo.back().scene);
    choices = std::move(m_redo.back().choices);
    m_redo.pop_back();
    Measure();
    return true;
}

} // namespace satviz
