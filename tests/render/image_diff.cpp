// SPDX-License-Identifier: MIT
// satviz-image-diff ACTUAL EXPECTED DIFF: pixel comparison of two PNG files for the golden-image tests. On a mismatch
// it writes DIFF (differing pixels red over a pale copy of EXPECTED), names the three files and exits 1.
#include <satviz/render/png_file.h>

#include <stb_image.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

/// Mesa's software rasteriser rounds anti-aliased edges differently on hosts with different vector units (AVX2
/// against AVX-512): a channel may move by one or two levels there. Anything larger is a real difference.
constexpr int kChannelTolerance = 2;
/// And it may place an edge pixel of a faint anti-aliased line (a dashed projection line) a step over on one host and
/// not on another: a few stray pixels. A real change (a label moved, a mark added or gone) changes far more.
constexpr size_t kStrayPixels = 8;

struct Image
{
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgb;
};

bool Load(const char* path, Image& image)
{
    int channels = 0;
    unsigned char* data = stbi_load(path, &image.width, &image.height, &channels, 3);
    if (data == nullptr)
    {
        std::printf("%s: cannot read the PNG (%s)\n", path, stbi_failure_reason());
        return false;
    }
    image.rgb.assign(data, data + static_cast<size_t>(image.width) * image.height * 3);
    stbi_image_free(data);
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 4)
    {
        std::printf("usage: satviz-image-diff ACTUAL EXPECTED DIFF\n");
        return 2;
    }
    Image actual;
    Image expected;
    if (!Load(argv[1], actual) || !Load(argv[2], expected))
    {
        return 2;
    }
    if (actual.width != expected.width || actual.height != expected.height)
    {
        std::printf("%s is %dx%d but %s is %dx%d\n", argv[1], actual.width, actual.height, argv[2], expected.width,
                    expected.height);
        return 1;
    }
    std::vector<unsigned char> diff(expected.rgb.size());
    size_t differing = 0;
    int largest = 0;
    for (size_t i = 0; i < expected.rgb.size(); i += 3)
    {
        int delta = 0;
        for (size_t c = 0; c < 3; ++c)
        {
            delta = std::max(delta, std::abs(actual.rgb[i + c] - expected.rgb[i + c]));
        }
        if (delta > kChannelTolerance)
        {
            ++differing;
            largest = std::max(largest, delta);
            diff[i] = 255;
            diff[i + 1] = 0;
            diff[i + 2] = 0;
        }
        else
        {
            const int grey = (expected.rgb[i] + expected.rgb[i + 1] + expected.rgb[i + 2]) / 3;
            const auto pale = static_cast<unsigned char>(255 - (255 - grey) / 4);
            diff[i] = diff[i + 1] = diff[i + 2] = pale;
        }
    }
    if (differing <= kStrayPixels)
    {
        return 0;
    }
    std::string error;
    const bool written = satviz::WritePngFile(argv[3], diff, expected.width, expected.height, false, error);
    std::printf("%s differs from %s in %zu of %d pixels (largest channel difference %d, tolerance %d, %zu stray pixels "
                "allowed); %s%s\n",
                argv[1], argv[2], differing, expected.width * expected.height, largest, kChannelTolerance, kStrayPixels,
                written ? "difference image: " : "", written ? argv[3] : error.c_str());
    return 1;
}
