// SPDX-License-Identifier: MIT
// A program of the project run from a test as a user runs it, from a shell command line: its exit code and what it
// printed, read back from two files of this process that are then removed. One runner for every test of a program
// (satviz, satviz-bench, satviz-query, satviz-render, satviz-sim), so that each reads a run the same way.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace satviz::testing
{

/// What a program did: its exit code (-1 when it did not exit normally) and what it wrote to stdout and to stderr.
struct ToolRun
{
    int exitCode = -1;
    std::string out;
    std::string err;
};

/// The lines of `text`, without their line breaks.
inline std::vector<std::string> SplitLines(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
    {
        lines.push_back(line);
    }
    return lines;
}

/// Runs `command` through the shell, in the current directory, with stdout and stderr sent to two files in the
/// system's temporary directory named after this process (ctest may run the cases of one test program in parallel
/// processes), which are read back and removed.
inline ToolRun RunTool(const std::string& command)
{
    namespace fs = std::filesystem;
    const std::string stem = (fs::temp_directory_path() / ("satviz-tool-" + std::to_string(::getpid()))).string();
    const std::string out = stem + ".out";
    const std::string err = stem + ".err";
    const int status = std::system((command + " > " + out + " 2> " + err).c_str());
    const auto take = [](const std::string& path) {
        std::string text;
        {
            std::ifstream in(path, std::ios::binary);
            std::ostringstream bytes;
            bytes << in.rdbuf();
            text = bytes.str();
        }
        std::error_code ignored;
        fs::remove(path, ignored);
        return text;
    };
    ToolRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = take(out);
    run.err = take(err);
    return run;
}

} // namespace satviz::testing
