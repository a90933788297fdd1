// SPDX-License-Identifier: MIT
// satviz app: a copy of the scene being edited, kept on disk for as long as it has unsaved changes, so that they
// outlive an end of the app that asks no question (a crash, a killed process, a machine turned off). The app drops
// the copy when the scene is saved, undone back to its file, or discarded on a confirmed quit. No ImGui here.
#pragma once

#include <satviz/scene.h>

#include <string>
#include <vector>

namespace satviz
{

/// The copy of one app's unsaved scene: `FOLDER/STEM.unsaved-PID.json`, STEM the document file's stem (or
/// "untitled"), PID this process's, so that two apps at once keep two copies.
class UnsavedCopy
{
  public:
    /// Copies into `folder` (created when missing); empty: keeps no copy.
    explicit UnsavedCopy(std::string folder = {}) : m_folder(std::move(folder)) {}
    UnsavedCopy(const UnsavedCopy&) = delete;
    UnsavedCopy& operator=(const UnsavedCopy&) = delete;
    /// Drops the copy: it ends with a known end (saved, or discarded on purpose).
    ~UnsavedCopy() { Drop(); }

    /// Writes `scene`, edited from `documentFile` (empty for a new scene), atomically as the copy, in place of
    /// the one before (dropped when its name differs). False, with `error` naming the file, when it cannot be
    /// written; the copy before is then kept.
    bool Keep(const Scene& scene, const std::string& documentFile, std::string& error);
    /// Removes the copy, if any.
    void Drop();
    /// The copy's file; empty while there is none.
    const std::string& Path() const { return m_path; }

  private:
    std::string m_folder;
    std::string m_path;
};

/// The copies in `folder` that an app left and no running app keeps (their process is gone), newest first.
std::vector<std::string> LeftUnsavedCopies(const std::string& folder);

} // namespace satviz
