// SPDX-License-Identifier: MIT
#include <satviz/render/atomic_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace satviz
{

bool WriteFileAtomically(const std::string& path, std::string_view bytes, std::string& error)
{
    const std::string temporary = path + ".tmp." + std::to_string(::getpid());
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr)
    {
        error = path + ": cannot write (" + std::strerror(errno) + ")";
        return false;
    }
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
    const bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed)
    {
        error = path + ": write failed (" + std::strerror(errno) + ")";
        std::remove(temporary.c_str());
        return false;
    }
    std::error_code code;
    std::filesystem::rename(temporary, path, code);
    if (code)
    {
        error = path + ": cannot replace the file (" + code.message() + ")";
        std::remove(temporary.c_str());
        return false;
    }
    return true;
}

} // namespace satviz
