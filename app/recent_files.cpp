// SPDX-License-Identifier: MIT
#include "recent_files.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <utility>

namespace satviz
{

RecentFiles::RecentFiles(std::string file, bool update) : file_(std::move(file)), update_(update)
{
    if (file_.empty())
    {
        return;
    }
    std::ifstream in(file_);
    for (std::string line; std::getline(in, line) && files_.size() < kMaxFiles;)
    {
        if (!line.empty())
        {
            files_.push_back(line);
        }
    }
}

void RecentFiles::Remember(const std::string& path)
{
    if (!update_)
    {
        return;
    }
    std::error_code code;
    const std::string absolute = std::filesystem::absolute(path, code).string();
    files_.erase(std::remove(files_.begin(), files_.end(), absolute), files_.end());
    files_.insert(files_.begin(), absolute);
    if (files_.size() > kMaxFiles)
    {
        files_.resize(kMaxFiles);
    }
    Write();
}

void RecentFiles::Write() const
{
    if (file_.empty())
    {
        return;
    }
    std::error_code code;
    std::filesystem::create_directories(std::filesystem::path(file_).parent_path(), code);
    const std::string temporary = file_ + ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        for (const std::string& path : files_)
        {
            out << path << '\n';
        }
        if (!out)
        {
            return;
        }
    }
    std::filesystem::rename(temporary, file_, code);
}

} // namespace satviz
