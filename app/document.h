// SPDX-License-Identifier: MIT
// satviz app: the document, the scene being edited with its file and the history of its edits. Each state of the
// history holds the scene and the viewer's choices (pair, query, layers, precision...) of that moment, so that undo
// and redo restore both. No ImGui here.
#pragma once

#include "view_choices.h"

#include <satviz/scene.h>

#include <cstddef>
#include <string>
#include <vector>

namespace satviz
{

/// What opening a scene file gave.
struct OpenResult
{
    bool ok = false;   ///< the scene is open
    std::string error; ///< why not: one line naming the file and the field
    int simSteps = 0;  ///< the rigid-body steps its view block asks for, which the simulation takes on opening
};

/// The scene being edited, its file, whether it has unsaved changes, and its undo and redo history.
class Document
{
  public:
    /// Opens the scene file `path`, as written (its view's sim_steps are checked: they must leave a state a scene
    /// holds). It needs two bodies, or one when its view's figure is of one body (a decomposition, a slice). A file
    /// in `bundledDir` (the bundled scenes) or a folder of it opens read-only: saving asks for another file. On
    /// failure the document stays as it was.
    OpenResult Open(const std::string& path, const std::string& bundledDir);
    /// Writes `saved` (the scene with the view block of the moment) to `path` atomically; from then on the document
    /// holds it, from that file, without unsaved changes. False, with `error` set, when it cannot be written.
    bool Save(Scene saved, const std::string& path, std::string& error);

    /// The scene being edited.
    const Scene& GetScene() const { return m_scene; }
    /// Its file; empty for a scene not read from a file.
    const std::string& File() const { return m_file; }
    /// True for a bundled scene: saving asks for another file.
    bool ReadOnly() const { return m_readOnly; }
    /// Makes saving ask for another file, as for a bundled scene (a copy of unsaved changes kept aside).
    void AskForAnotherFile() { m_readOnly = true; }
    /// True when the scene differs from its file: its bodies, description or world, measured against the scene as
    /// it was opened or last saved (undoing back to it is no change). The view block (pair, query, layers,
    /// camera, step...) is how the scene is looked at, not a change of it. During an edit, true once the edit has
    /// touched a body.
    bool Dirty() const { return m_dirty || (m_editOpen && m_editTouched); }
    /// A count that changes whenever the scene may have changed outside an open edit (an edit committed, an undo or
    /// a redo, a file opened or saved): what watches the scene compares it instead of the scene.
    size_t Revision() const { return m_revision; }

    /// Starts an edit of the bodies (a drag, a number being dragged): the scene now and the viewer's `choices` are
    /// kept until CommitEdit, so that the whole edit is undone in one step. Does nothing while an edit is open.
    void BeginEdit(const ViewChoices& choices);
    /// True between BeginEdit and CommitEdit.
    bool EditOpen() const { return m_editOpen; }
    /// Body `index`, to change in place while an edit is open.
    Body& EditBody(size_t index)
    {
        m_editTouched = true;
        return m_scene.bodies[index];
    }
    /// Adds `body` after the others, while an edit is open.
    void AddBody(Body body);
    /// Removes body `index`, while an edit is open.
    void RemoveBody(size_t index);
    /// Gives the scene the world block `world`, while an edit is open.
    void SetWorld(const SceneWorld& world);
    /// Ends the edit: the state it began from goes on the undo stack, unless the scene did not change (a click is
    /// not an edit). True when it did.
    bool CommitEdit();

    /// Records a change of the viewer's choices about to be made: the scene with the choices `before` it goes on
    /// the undo stack, and the redo stack is cleared.
    void RecordChoices(const ViewChoices& before);
    /// Undoes the last edit. `choices` gives the viewer's current choices (kept for Redo) and receives those of the
    /// restored state. False when there is nothing to undo or an edit is open.
    bool Undo(ViewChoices& choices);
    /// Redoes the last undone edit, as Undo does. False when there is nothing to redo or an edit is open.
    bool Redo(ViewChoices& choices);
    /// Number of edits that can be undone.
    size_t UndoDepth() const { return m_undo.size(); }
    /// Number of undone edits that can be redone.
    size_t RedoDepth() const { return m_redo.size(); }

  private:
    /// One state of the history: the scene and the viewer's choices of that moment.
    struct State
    {
        Scene scene;
        ViewChoices choices;
    };

    // Measures m_dirty: the scene against m_savedContent.
    void Measure();

    Scene m_scene;
    std::string m_file;
    bool m_readOnly = false;
    std::string m_savedContent; // the scene as opened or last saved, without its view block (SceneContent)
    bool m_dirty = false;
    size_t m_revision = 0;
    bool m_editTouched = false;
    std::vector<State> m_undo;
    std::vector<State> m_redo;
    bool m_editOpen = false;
    State m_editStart;
};

} // namespace satviz
