// SPDX-License-Identifier: MIT
// The scene files of the course, for the tests that go over every one of them.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace satviz::testing
{

/// The .json files of tutorials/scenes, sorted by path; with `subfolders`, those of its subfolders too
/// (tutorials/scenes/concave).
inline std::vector<std::string> TutorialSceneFiles(bool subfolders = false)
{
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(SATVIZ_SOURCE_DIR) / "tutorials" / "scenes";
    std::vector<std::string> files;
    const auto take = [&files](const fs::directory_entry& entry) {
        if (entry.path().extension() == ".json")
        {
            files.push_back(entry.path().string());
        }
    };
    if (subfolders)
    {
        std::for_each(fs::recursive_directory_iterator(folder), fs::recursive_directory_iterator(), take);
    }
    else
    {
        std::for_each(fs::directory_iterator(folder), fs::directory_iterator(), take);
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace satviz::testing
