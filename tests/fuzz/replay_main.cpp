// SPDX-License-Identifier: MIT
// Runs a fuzz target over files, without libFuzzer: the committed corpus becomes a regression test in every
// build (and under the sanitizers). Usage: PROGRAM FILE_OR_DIRECTORY...
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv)
{
    int files = 0;
    for (int i = 1; i < argc; ++i)
    {
        std::vector<std::filesystem::path> paths;
        if (std::filesystem::is_directory(argv[i]))
        {
            for (const auto& entry : std::filesystem::directory_iterator(argv[i]))
            {
                paths.push_back(entry.path());
            }
        }
        else
        {
            paths.push_back(argv[i]);
        }
        for (const auto& path : paths)
        {
            std::ifstream in(path, std::ios::binary);
            const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
            ++files;
        }
    }
    std::printf("replayed %d inputs\n", files);
    return files > 0 ? 0 : 1;
}
