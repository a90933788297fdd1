// SPDX-License-Identifier: MIT
// satviz app: the recently opened files (File > Recent), kept in a small text file between runs.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace satviz
{

/// The files last opened or saved, newest first, read from and written to a file of one path a line.
class RecentFiles
{
  public:
    /// The list remembered in `file` (empty: nothing is read or written). With `update` false the list is shown but
    /// neither it nor its file changes (a --measure-fps run).
    RecentFiles(std::string file, bool update);

    /// The files, as absolute paths, newest first.
    const std::vector<std::string>& List() const { return m_files; }
    /// Puts `path` (made absolute) first, drops the oldest beyond kMaxFiles, and writes the list's file atomically.
    void Remember(const std::string& path);

    /// Most files the list keeps.
    static constexpr size_t kMaxFiles = 8;

  private:
    void Write() const;

    std::string m_file;
    bool m_update = true;
    std::vector<std::string> m_files;
};

} // namespace satviz
