// SPDX-License-Identifier: MIT
#include "recent_files.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <utility>

namespace satviz
{

RecentFiles::RecentFiles(std::string file, bool update) : m_file(std::move(file)), m_update(update)
{
    if (m_file.empty())
    {
        return;
    }
    std::ifstream in(m_file);
    for (std::string line; std::getline(in, line) && m_files.size() < kMaxFiles;)
    {
        if (!line.empty())
        {
            m_files.push_back(line);
        }
    }
}

void RecentFiles::Remember(const std::string& path)
{
    if (!m_update)
    {
        return;
    }
    std::error_code code;
    const std::string absolute = std::filesystem::absolute(path, code).string();
    m_files.erase(std::remove(m_files.begin(), m_files.end(), absolute), m_files.end());
    m_files.insert(m_files.begin(), absolute);
    if (m_files.size() > kMaxFiles)
    {
        m_files.resize(kMaxFiles);
    }
    Write();
}

void RecentFiles::Write() const
{
    if (m_file.empty())
    {
        return;
    }
    std::error_code code;
    std::filesystem::create_directories(std::filesystem::path(m_file).parent_path(), code);
    const std::string temporary = m_file + ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        for (const std::string& path : m_files)
        {
            out << path << '\n';
        }
        if (!out)
        {
            return;
        }
    }
    std::filesystem::rename(temporary, m_file, code);
}

} // namespace satviz
