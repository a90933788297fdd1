// SPDX-License-Identifier: MIT
// The app's command line, checked before any window opens: --version, --measure-fps refused below 1 frame, and the
// options as docs/programs.md lists them. Runs the real program without a display, so a check that came too late would
// fail at the window instead.

#include "support/run_tool.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace
{

struct Run
{
    int exitCode = -1;
    std::string out;
    std::vector<std::string> errLines;
};

/// Runs satviz with `arguments` and no display, found on the PATH as `satviz` (so that its usage line names it
/// so) in `dir`.
Run App(const std::string& arguments, const fs::path& dir = fs::path(SATVIZ_APP_EXE).parent_path())
{
    const satviz::testing::ToolRun run = satviz::testing::RunTool(
        "env -u DISPLAY -u WAYLAND_DISPLAY PATH=\"" + dir.string() + ":$PATH\" satviz " + arguments);
    return {run.exitCode, run.out, satviz::testing::SplitLines(run.err)};
}

} // namespace

TEST_CASE("satviz --version prints its name and the project version", "[app-cli]")
{
    const Run run = App("--version");
    CHECK(run.exitCode == 0);
    CHECK(run.out == std::string("satviz ") + SATVIZ_VERSION + "\n");
    CHECK(run.errLines.empty());
}

TEST_CASE("satviz refuses --measure-fps below 1 frame with one line, before opening a window", "[app-cli]")
{
    for (const char* frames : {"0", "-1", "-250"})
    {
        INFO("--measure-fps " << frames);
        const Run run = App(std::string("--measure-fps ") + frames);
        CHECK(run.exitCode == 2);
        CHECK(run.out.empty());
        REQUIRE(run.errLines.size() == 1);
        CHECK(run.errLines[0] ==
              std::string("satviz: --measure-fps: expected a number of frames of at least 1, got ") + frames);
    }
}

TEST_CASE("docs/programs.md lists the app's options as satviz --help prints them", "[app-cli]")
{
    const Run run = App("--help");
    CHECK(run.exitCode == 0);
    std::ifstream in(std::string(SATVIZ_SOURCE_DIR) + "/docs/programs.md");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string readme = text.str();
    const std::string start = "```text\nsatviz: ";
    const size_t begin = readme.find(start);
    REQUIRE(begin != std::string::npos);
    const size_t end = readme.find("```\n", begin + start.size());
    REQUIRE(end != std::string::npos);
    // CLI11 ends its help with an empty line, which the page leaves out.
    CHECK(readme.substr(begin + 8, end - begin - 8) + "\n" == run.out);
}

TEST_CASE("satviz finds its bundled scenes from its own folder, with no path compiled in", "[app-cli]")
{
    // In the build tree (BUILD/share/satviz links to tutorials/): it gets as far as the window.
    const Run found = App("");
    CHECK(found.exitCode == 1);
    REQUIRE(found.errLines.size() == 1);
    CHECK(found.errLines[0].find("cannot open a window") != std::string::npos);

    // A copy of the program with no data folder beside it and no source tree above it says where it looked.
    const fs::path prefix = fs::temp_directory_path() / ("satviz-app-cli-prefix-" + std::to_string(::getpid()));
    fs::create_directories(prefix / "bin");
    fs::copy_file(SATVIZ_APP_EXE, prefix / "bin" / "satviz", fs::copy_options::overwrite_existing);
    const Run missing = App("", prefix / "bin");
    const Run named = App(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json", prefix / "bin");
    fs::remove_all(prefix);
    CHECK(missing.exitCode == 1);
    REQUIRE(missing.errLines.size() == 1);
    CHECK(missing.errLines[0] == "satviz: no bundled scenes in " + (prefix / "share" / "satviz" / "scenes").string() +
                                     " or a tutorials/scenes above it; name a scene file");
    // A scene named on the command line needs no bundled scenes.
    CHECK(named.exitCode == 1);
    REQUIRE(named.errLines.size() == 1);
    CHECK(named.errLines[0].find("cannot open a window") != std::string::npos);
}

TEST_CASE("satviz --window takes a size smaller than the panels need, to be raised, and refuses a malformed one",
          "[app-cli]")
{
    // The help says a small size is raised to the smallest the panels need: such a size gets as far as the window.
    for (const char* size : {"200x150", "1x1", "319x239"})
    {
        INFO("--window " << size);
        const Run run = App(std::string("--window ") + size);
        CHECK(run.exitCode == 1);
        REQUIRE(run.errLines.size() == 1);
        CHECK(run.errLines[0].find("cannot open a window") != std::string::npos);
    }
    // What is not a size is refused in one line, before any window.
    for (const char* size : {"0x600", "800x-1", "800", "800x600x2", "wide"})
    {
        INFO("--window " << size);
        const Run run = App(std::string("--window ") + size);
        CHECK(run.exitCode == 2);
        REQUIRE(run.errLines.size() == 1);
        CHECK(run.errLines[0] ==
              std::string("satviz: --window: expected WxH, two whole numbers of pixels of at least 1, got \"") + size +
                  "\"");
    }
}
