// SPDX-License-Identifier: MIT
#include <satviz/render/atomic_file.h>
#include <satviz/render/png_file.h>

#include <stb_image_write.h>


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
    return WriteFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()), error);
}

} // namespace satviz
