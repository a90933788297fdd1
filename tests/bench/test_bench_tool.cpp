// SPDX-License-Identifier: MIT
// satviz-bench as a program: settings it cannot run and a --csv directory it cannot write are refused with one line
// before the run starts, --quick says that its figures are not measurements (--world --quick too), --help names the
// peers, --world --write-scenes writes its scenes and --world --threads says what satviz steps on.

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

/// The files of these tests live in a directory of their own, removed at exit.
struct ScratchDirectory
{
    fs::path dir = fs::temp_directory_path() / ("satviz-bench-test-" + std::to_string(::getpid()));

    ScratchDirectory() { fs::create_directories(dir); }
    ~ScratchDirectory()
    {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
};

const ScratchDirectory kScratch;

Run Bench(const std::string& arguments)
{
    const satviz::testing::ToolRun run = satviz::testing::RunTool(std::string(SATVIZ_BENCH_EXE) + " " + arguments);
    return {run.exitCode, run.out, satviz::testing::SplitLines(run.err)};
}

/// A refused run: exit code 2, one line on stderr that holds every one of `words`, and nothing run (no output).
void CheckRefused(const std::string& arguments, const std::vector<std::string>& words)
{
    INFO("satviz-bench " << arguments);
    const Run run = Bench(arguments);
    CHECK(run.exitCode == 2);
    CHECK(run.out.empty());
    REQUIRE(run.errLines.size() == 1);
    INFO(run.errLines[0]);
    CHECK(run.errLines[0].find("satviz-bench: ") == 0);
    for (const std::string& word : words)
    {
        CHECK(run.errLines[0].find(word) != std::string::npos);
    }
}

} // namespace

// The timeout of this file's tests (CMakeLists.txt) catches the hang these runs used to be.
TEST_CASE("satviz-bench refuses vertex counts below 3, no pairs and no rounds", "[bench-tool]")
{
    CheckRefused("--counts 2", {"--counts", "at least 3 vertices", "got 2"});
    CheckRefused("--counts 8 0", {"--counts", "got 0"});
    CheckRefused("--counts -4", {"--counts", "got -4"});
    CheckRefused("--pairs 0", {"--pairs", "got 0"});
    CheckRefused("--pairs -3", {"--pairs", "got -3"});
    CheckRefused("--rounds 0", {"--rounds", "got 0"});
    CheckRefused("--near-counts 3 2", {"--near-counts", "at least 3 vertices", "got 2"});
    CheckRefused("--near-pairs 2", {"--near-pairs", "got 2"});
    CheckRefused("--near-rounds 0", {"--near-rounds", "got 0"});
    CheckRefused("--near-placement sideways", {"--near-placement", "sideways"});
    // Checked before --quick sets its own pool sizes.
    CheckRefused("--quick --pairs 0", {"--pairs", "got 0"});
}

TEST_CASE("satviz-bench checks the --csv directory before the run", "[bench-tool]")
{
    // Under a regular file no directory can be made (root too); without the quick flag, a run would take minutes.
    const fs::path file = kScratch.dir / "a-file";
    std::ofstream(file) << "not a directory";
    CheckRefused("--csv " + (file / "results").string(), {"--csv", (file / "results").string(), "cannot create"});
    CheckRefused("--csv " + file.string(), {"--csv", file.string()});
    CHECK(!fs::exists(file / "results"));
}

TEST_CASE("satviz-bench --quick says its figures are not measurements, and writes the CSV files", "[bench-tool]")
{
    const fs::path csv = kScratch.dir / "new" / "csv";
    const Run run = Bench("--quick --counts 3 8 --csv " + csv.string());
    CHECK(run.exitCode == 0);
    CHECK(run.out.find("--quick: tiny pools and one round: these figures only show that the benchmark runs; they are "
                       "not measurements\n") != std::string::npos);
    CHECK(fs::is_regular_file(csv / "timing.csv"));
    CHECK(fs::is_regular_file(csv / "accuracy.csv"));
    CHECK(fs::is_regular_file(csv / "accuracy_by_category.csv"));
    CHECK(fs::is_regular_file(csv / "timing_near.csv"));
    // The near-contact table, with a figure for every query it names at the first count and its goals.
    CHECK(run.out.find("near-contact pairs, placed along a random direction") != std::string::npos);
    CHECK(run.out.find("Overlap / textbook Overlap") != std::string::npos);
    // The probe file of the check before the run is gone.
    int files = 0;
    for (const auto& entry : fs::directory_iterator(csv))
    {
        CHECK(entry.path().filename().string().find("probe") == std::string::npos);
        ++files;
    }
    CHECK(files == 4);
}

TEST_CASE("satviz-bench --world refuses no bodies, too few steps, no rounds and unknown scenes", "[bench-tool]")
{
    CheckRefused("--world --bodies 0", {"--bodies", "got 0"});
    CheckRefused("--world --bodies 100 -5", {"--bodies", "got -5"});
    CheckRefused("--world --steps 3", {"--steps", "got 3"});
    CheckRefused("--world --rounds 0", {"--rounds", "got 0"});
    CheckRefused("--world --quick --steps 0", {"--steps", "got 0"});
    CheckRefused("--world --scenes pile drizzle", {"--scenes", "got drizzle"});
    CheckRefused("--world --threads 0", {"--threads", "got 0"});
    CheckRefused("--world --threads 257", {"--threads", "got 257"});
}

TEST_CASE("satviz-bench --world --write-scenes writes each scene at each size as a scene file, and runs nothing",
          "[bench-tool]")
{
    const fs::path dir = kScratch.dir / "scenes";
    const Run run = Bench("--world --bodies 30 7 --write-scenes " + dir.string());
    REQUIRE(run.exitCode == 0);
    CHECK(run.out.empty());
    for (const char* name : {"pile-30.json", "pile-7.json", "rain-30.json", "rain-7.json"})
    {
        INFO(name);
        REQUIRE(fs::is_regular_file(dir / name));
        std::ifstream file(dir / name);
        std::ostringstream text;
        text << file.rdbuf();
        const std::string json = text.str();
        // The dynamic bodies and the ground and two walls, with the benchmark's gravity and step.
        const int bodies = std::string(name).find("-30") != std::string::npos ? 30 : 7;
        size_t names = 0;
        for (size_t at = json.find("\"name\""); at != std::string::npos; at = json.find("\"name\"", at + 1))
        {
            ++names;
        }
        CHECK(names == static_cast<size_t>(bodies + 3));
        CHECK(json.find("\"gravity\":[0.0,-10.0]") != std::string::npos);
    }
}

TEST_CASE("satviz-bench --world --threads 2 steps satviz on two threads and says so", "[bench-tool]")
{
    const Run run = Bench("--world --quick --threads 2");
    CHECK(run.exitCode == 0);
    CHECK(run.out.find("satviz steps on 2 threads (--threads): its ms per step are the wall clock's") !=
          std::string::npos);
}

TEST_CASE("satviz-bench --world --quick says its figures are not measurements, and writes world.csv", "[bench-tool]")
{
    const fs::path csv = kScratch.dir / "world" / "csv";
    const Run run = Bench("--world --quick --csv " + csv.string());
    CHECK(run.exitCode == 0);
    CHECK(run.out.find("--quick: tiny scenes, few steps and one round: these figures only show that the benchmark "
                       "runs; they are not measurements\n") != std::string::npos);
    for (const char* table : {"ms per step", "what each saving saves", "quality", "targets"})
    {
        INFO(table);
        CHECK(run.out.find(table) != std::string::npos);
    }
    REQUIRE(fs::is_regular_file(csv / "world.csv"));
    std::ifstream file(csv / "world.csv");
    std::string header;
    std::getline(file, header);
    CHECK(header.find("scene,bodies,configuration,") == 0);
    int rows = 0;
    for (std::string line; std::getline(file, line);)
    {
        ++rows;
    }
    // Two scenes of two sizes, each in satviz's five configurations (broadphase off included at these sizes) and,
    // when the build has them, Box2D (one row) and Box2D v3 (two: 1 and 2 workers).
    const bool box2d = run.out.find("peers: Box2D ") != std::string::npos;
    const bool v3 = run.out.find(", Box2D v3 ") != std::string::npos;
    CHECK(rows == 4 * (5 + (box2d ? 1 : 0) + (v3 ? 2 : 0)));
    if (v3)
    {
        CHECK(run.out.find("beside Box2D v3") != std::string::npos);
    }
    else
    {
        CHECK(run.out.find("built without Box2D v3") != std::string::npos);
    }
}

TEST_CASE("satviz-bench --help names every peer it compares with", "[bench-tool]")
{
    const Run run = Bench("--help");
    CHECK(run.exitCode == 0);
    for (const char* peer :
         {"Box2D", "b2TestOverlap", "b2CollidePolygons", "b2PolygonShape::RayCast", "b2TimeOfImpact",
          "b2TimeOfImpact + b2CollidePolygons at t", "Chipmunk", "cpShapesCollide", "textbook SAT loop", "__float128",
          "Box2D v3", "SATVIZ_BOX2D_V3_ROOT"})
    {
        INFO(peer);
        CHECK(run.out.find(peer) != std::string::npos);
    }
    CHECK(run.out.find("This build: ") != std::string::npos);
}

TEST_CASE("satviz-bench --version prints its name and the project version", "[bench-tool]")
{
    const Run run = Bench("--version");
    CHECK(run.exitCode == 0);
    CHECK(run.out == std::string("satviz-bench ") + SATVIZ_VERSION + "\n");
    CHECK(run.errLines.empty());
}
