// SPDX-License-Identifier: MIT
#include "unsaved_copy.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>
#include <utility>

#include <signal.h>
#include <unistd.h>

namespace satviz
{

namespace
{

constexpr std::string_view kMark = ".unsaved-";

// The process id in a copy's name (STEM.unsaved-PID.json); -1 when the name is not a copy's.
long ProcessOf(const std::filesystem::path& file)
{
    if (file.extension() != ".json")
    {
        return -1;
    }
    const std::string stem = file.stem().string();
    const size_t mark = stem.rfind(kMark);
    if (mark == std::string::npos || mark + kMark.size() == stem.size())
    {
        return -1;
    }
    long pid = 0;
    for (size_t i = mark + kMark.size(); i < stem.size(); ++i)
    {
        if (stem[i] < '0' || stem[i] > '9' || pid > 100000000)
        {
            return -1;
        }
        pid = pid * 10 + (stem[i] - '0');
    }
    return pid;
}

// True while process `pid` runs and is a satviz (a process id is used again once its process ended).
bool RunningApp(long pid)
{
    if (pid <= 0 || ::kill(static_cast<pid_t>(pid), 0) != 0)
    {
        return false;
    }
    std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
    std::string name;
    return !(comm >> name) || name == "satviz";
}

} // namespace

bool UnsavedCopy::Keep(const Scene& scene, const std::string& documentFile, std::string& error)
{
    if (m_folder.empty())
    {
        return true;
    }
    std::string stem =
        documentFile.empty() ? std::string("untitled") : std::filesystem::path(documentFile).stem().string();
    if (ProcessOf(documentFile) >= 0)
    {
        stem.erase(stem.rfind(kMark)); // a copy taken back and edited again: named after the scene, not the copy
    }
    const std::string path =
        (std::filesystem::path(m_folder) / (stem + std::string(kMark) + std::to_string(::getpid()) + ".json"))
            .string();
    std::error_code code;
    std::filesystem::create_directories(m_folder, code);
    if (code)
    {
        error = m_folder + ": cannot make the folder of unsaved copies: " + code.message();
        return false;
    }
    if (!SaveScene(scene, path, error))
    {
        return false;
    }
    if (!m_path.empty() && m_path != path)
    {
        std::filesystem::remove(m_path, code);
    }
    m_path = path;
    return true;
}

void UnsavedCopy::Drop()
{
    if (m_path.empty())
    {
        return;
    }
    std::error_code code;
    std::filesystem::remove(m_path, code);
    m_path.clear();
}

std::vector<std::string> LeftUnsavedCopies(const std::string& folder)
{
    std::vector<std::pair<std::filesystem::file_time_type, std::string>> found;
    std::error_code code;
    for (const auto& entry : std::filesystem::directory_iterator(folder, code))
    {
        const long pid = ProcessOf(entry.path());
        // A copy whose process still runs is that app's own, kept while it edits.
        if (pid < 0 || pid == ::getpid() || RunningApp(pid))
        {
            continue;
        }
        found.emplace_back(entry.last_write_time(code), entry.path().string());
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<std::string> files;
    for (auto& [time, file] : found)
    {
        files.push_back(std::move(file));
    }
    return files;
}

} // namespace satviz
