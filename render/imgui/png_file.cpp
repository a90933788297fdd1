// SPDX-License-Identifier: MIT
#include <satviz/render/png_file.h>

#include <stb_image_write.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace satviz
{

namespace
{

void Append(void* context, void* data, int size)
{
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

} // namespace

std::vector<unsigned char> EncodePng(const std::vector<unsigned char>& rgb, int width, int height, bool bottomUp)
{
    std::vector<unsigned char> png;
    // Figures are mostly flat colour: without a row filter they compress as small as with the best one, and
    // skipping the per-row filter search plus the lowest compression level halves the encoding time. Neither
    // changes a pixel.
    stbi_write_png_compression_level = 1;
    stbi_write_force_png_filter = 0;
    stbi_flip_vertically_on_write(bottomUp ? 1 : 0);
    stbi_write_png_to_func(Append, &png, width, height, 3, rgb.data(), width * 3);
    stbi_flip_vertically_on_write(0);
    return png;
}

bool WritePngFile(const std::string& path, const std::vector<unsigned char>& rgb, int width, int height, bool bottomUp,
                  std::string& error)
{
    const std::vector<unsigned char> png = EncodePng(rgb, width, height, bottomUp);
    if (png.empty())
    {
        error = path + ": PNG encoding failed";
        return false;
    }
    const std::string temporary = path + ".tmp." + std::to_string(::getpid());
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr)
    {
        error = path + ": cannot write (" + std::strerror(errno) + ")";
        return false;
    }
    const bool written = std::fwrite(png.data(), 1, png.size(), file) == png.size();
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
