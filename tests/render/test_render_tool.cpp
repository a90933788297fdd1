// SPDX-License-Identifier: MIT
// satviz-render as a program: a batch survives a bad scene, errors are one line naming the file and the field,
// output is written atomically, and the same input gives the same bytes.

#include "support/run_tool.h"
#include "support/xml_check.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace
{

struct Run
{
    int exitCode = -1;
    std::vector<std::string> outLines;
    std::vector<std::string> errLines;
};

// Where this process writes: a folder of its own under the system's temporary folder, never the folder the tests
// are run from (a run from a source tree would leave its files among the sources), and never shared with another
// process (ctest may run the cases of this file in parallel).
// Removed when the process ends.
fs::path WorkDirectory()
{
    struct Owned
    {
        fs::path dir = fs::temp_directory_path() / ("satviz-render-tool-" + std::to_string(::getpid()));
        ~Owned()
        {
            std::error_code ignored;
            fs::remove_all(dir, ignored);
        }
    };
    static const Owned owned;
    fs::create_directories(owned.dir);
    return owned.dir;
}

Run Render(const std::string& arguments)
{
    const satviz::testing::ToolRun run = satviz::testing::RunTool(std::string(SATVIZ_RENDER_EXE) + " " + arguments);
    return {run.exitCode, satviz::testing::SplitLines(run.out), satviz::testing::SplitLines(run.err)};
}

std::string Scene(const std::string& name)
{
    return std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + name;
}

std::string Bytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

fs::path FreshDirectory(const std::string& name)
{
    const fs::path dir = WorkDirectory() / name;
    fs::remove_all(dir);
    return dir;
}

std::string Joined(const std::vector<std::string>& lines)
{
    std::string text;
    for (const std::string& line : lines)
    {
        text += line + "\n";
    }
    return text;
}

} // namespace

TEST_CASE("satviz-render: a bad scene gets one error line and the rest of the batch is rendered", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-batch");
    fs::create_directories(dir);
    // A polygon that crosses itself (a concave one would be cut into pieces and drawn).
    std::ofstream(dir / "broken.json") << R"({"bodies": [{"polygon": [[0, 0], [2, 0], [0, 2], [2, 2]]}]})";
    std::ofstream(dir / "badview.json")
        << R"({"bodies": [{"box": [1, 1]}, {"box": [1, 1]}], "view": {"layers": ["shapes", "mvt"]}})";
    const Run run = Render(Scene("overlapping_boxes.json") + " " + (dir / "broken.json").string() + " " +
                           (dir / "badview.json").string() + " " + (dir / "missing.json").string() + " " +
                           Scene("two_circles.json") + " -q -o " + (dir / "out").string());
    INFO(Joined(run.errLines));
    CHECK(run.exitCode == 1);
    CHECK(fs::exists(dir / "out" / "overlapping_boxes.png"));
    CHECK(fs::exists(dir / "out" / "two_circles.png"));
    CHECK(!fs::exists(dir / "out" / "broken.png"));
    REQUIRE(run.errLines.size() == 4); // three errors and the summary
    CHECK(run.errLines[0].find("broken.json") != std::string::npos);
    CHECK(run.errLines[0].find("bodies[0].polygon") != std::string::npos);
    CHECK(run.errLines[1].find("badview.json") != std::string::npos);
    CHECK(run.errLines[1].find("view.layers[1]") != std::string::npos);
    CHECK(run.errLines[2].find("missing.json") != std::string::npos);
    CHECK(run.errLines[3].find("2 figures written") != std::string::npos);
    CHECK(run.errLines[3].find("3 of 5 scenes failed") != std::string::npos);
}

TEST_CASE("satviz-render: one figure per step, and a step that does not exist is named", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-steps");
    const Run run = Render(Scene("separated_triangle.json") + " --all-steps -q -o " + dir.string());
    CHECK(run.exitCode == 0);
    // Steps count from 1 in file names, as in every view: the first axis separates, then the verdict.
    CHECK(!fs::exists(dir / "separated_triangle-step0.png"));
    CHECK(fs::exists(dir / "separated_triangle-step1.png"));
    CHECK(fs::exists(dir / "separated_triangle-step2.png"));
    CHECK(!fs::exists(dir / "separated_triangle-step3.png"));

    const Run beyond = Render(Scene("separated_triangle.json") + " --step 7 -o " + (dir / "x.png").string());
    CHECK(beyond.exitCode == 1);
    REQUIRE(!beyond.errLines.empty());
    CHECK(beyond.errLines[0].find("--step") != std::string::npos);
    CHECK(beyond.errLines[0].find("1 to 2") != std::string::npos);
    CHECK(!fs::exists(dir / "x.png"));

    for (const char* step : {"0", "-1"})
    {
        const Run below =
            Render(Scene("separated_triangle.json") + " --step " + step + " -o " + (dir / "x.png").string());
        INFO("--step " << step);
        CHECK(below.exitCode == 2);
        REQUIRE(below.errLines.size() == 1);
        CHECK(below.errLines[0].find("--step: steps count from 1") != std::string::npos);
    }
    const Run badView = Render(Scene("separated_triangle.json") + " --view edges -o " + (dir / "x.png").string());
    CHECK(badView.exitCode == 2);
    CHECK(!fs::exists(dir / "x.png"));
}

TEST_CASE("satviz-render: usage errors exit with 2 and a one-line reason", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-usage");
    const Run two =
        Render(Scene("two_circles.json") + " " + Scene("fly_by.json") + " -o " + (dir / "one.png").string());
    CHECK(two.exitCode == 2);
    REQUIRE(two.errLines.size() == 1);
    CHECK(two.errLines[0].find(".png output takes exactly one figure") != std::string::npos);

    const Run size = Render(Scene("two_circles.json") + " --size 800by600 -o " + dir.string());
    CHECK(size.exitCode == 2);
    REQUIRE(size.errLines.size() == 1);
    CHECK(size.errLines[0].find("--size") != std::string::npos);

    const Run layers = Render(Scene("two_circles.json") + " --layers shapes,mvt -o " + dir.string());
    CHECK(layers.exitCode == 2);
    REQUIRE(layers.errLines.size() == 1);
    CHECK(layers.errLines[0].find("\"mvt\"") != std::string::npos);
}

TEST_CASE("satviz-render: output is atomic and never half-written", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-atomic");
    fs::create_directories(dir);
    // An existing image that cannot be replaced (its directory is read-only) survives a failed write intact.
    const fs::path locked = dir / "locked";
    fs::create_directories(locked);
    std::ofstream(locked / "two_circles.png") << "previous figure";
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    const Run run = Render(Scene("two_circles.json") + " -o " + (locked / "two_circles.png").string());
    fs::permissions(locked, fs::perms::owner_all);
    if (::geteuid() != 0) // root ignores the permission bits
    {
        CHECK(run.exitCode == 1);
        REQUIRE(!run.errLines.empty());
        CHECK(run.errLines[0].find("two_circles.png") != std::string::npos);
        CHECK(Bytes(locked / "two_circles.png") == "previous figure");
    }
    // No temporary file is left behind by a successful batch.
    const Run ok = Render(Scene("two_circles.json") + " " + Scene("fly_by.json") + " -q -o " + dir.string());
    CHECK(ok.exitCode == 0);
    for (const auto& entry : fs::directory_iterator(dir))
    {
        CHECK(entry.path().string().find(".tmp") == std::string::npos);
    }
}

TEST_CASE("satviz-render: the same scene gives byte-identical PNGs, alone or in a batch", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-determinism");
    REQUIRE(Render(Scene("circle_and_polygon.json") + " -q -o " + (dir / "alone.png").string()).exitCode == 0);
    REQUIRE(Render(Scene("overlapping_boxes.json") + " " + Scene("circle_and_polygon.json") + " --size 800x600 -q -o " +
                   (dir / "batch").string())
                .exitCode == 0);
    const std::string alone = Bytes(dir / "alone.png");
    CHECK(alone.size() > 1000);
    CHECK(alone == Bytes(dir / "batch" / "circle_and_polygon.png"));
    CHECK(alone.substr(1, 3) == "PNG");
}

TEST_CASE("satviz-render: two scenes of one file name are refused, naming both, before any figure", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-same-name");
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    fs::copy_file(Scene("two_circles.json"), dir / "a" / "x.json");
    fs::copy_file(Scene("overlapping_boxes.json"), dir / "b" / "x.json");
    const std::string a = (dir / "a" / "x.json").string();
    const std::string b = (dir / "b" / "x.json").string();

    const Run run = Render(Scene("fly_by.json") + " " + a + " " + b + " -q -o " + (dir / "out").string());
    CHECK(run.exitCode == 2);
    REQUIRE(run.errLines.size() == 1);
    CHECK(run.errLines[0].find("satviz-render: ") == 0);
    CHECK(run.errLines[0].find(a) != std::string::npos);
    CHECK(run.errLines[0].find(b) != std::string::npos);
    CHECK(run.errLines[0].find("x.png") != std::string::npos);
    CHECK(!fs::exists(dir / "out" / "x.png"));
    CHECK(!fs::exists(dir / "out" / "fly_by.png"));

    // The same with one figure per step, and with one file given twice.
    const Run steps = Render(a + " " + b + " --all-steps -q -o " + (dir / "out").string());
    CHECK(steps.exitCode == 2);
    REQUIRE(steps.errLines.size() == 1);
    CHECK(steps.errLines[0].find("x-stepN.png") != std::string::npos);
    const Run twice = Render(a + " " + a + " -q -o " + (dir / "out").string());
    CHECK(twice.exitCode == 2);
    REQUIRE(twice.errLines.size() == 1);
    CHECK(twice.errLines[0].find(a + " and " + a) != std::string::npos);

    // Scenes of different file names in one batch are still fine.
    const Run distinct = Render(a + " " + Scene("fly_by.json") + " -q -o " + (dir / "out").string());
    CHECK(distinct.exitCode == 0);
    CHECK(fs::exists(dir / "out" / "x.png"));
    CHECK(fs::exists(dir / "out" / "fly_by.png"));
}

TEST_CASE("satviz-render: -o with .png in any case is a file, not a directory", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-png-case");
    for (const char* name : {"Figure.PNG", "figure.Png"})
    {
        INFO(name);
        const Run run = Render(Scene("two_circles.json") + " -q -o " + (dir / name).string());
        CHECK(run.exitCode == 0);
        CHECK(fs::is_regular_file(dir / name));
        CHECK(Bytes(dir / name).substr(1, 3) == "PNG");
    }
    const Run two =
        Render(Scene("two_circles.json") + " " + Scene("fly_by.json") + " -o " + (dir / "two.PNG").string());
    CHECK(two.exitCode == 2);
    REQUIRE(two.errLines.size() == 1);
    CHECK(two.errLines[0].find(".png output takes exactly one figure") != std::string::npos);
    CHECK(!fs::exists(dir / "two.PNG"));
}

TEST_CASE("satviz-render: -o FIG.svg writes the figure as well-formed SVG, the committed bytes", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-svg");
    const Run run = Render(Scene("l14_head_on.json") + " -q -o " + (dir / "Head_On.SVG").string());
    INFO(Joined(run.errLines));
    REQUIRE(run.exitCode == 0);
    const std::string svg = Bytes(dir / "Head_On.SVG");
    const auto parsed = satviz::test::ParseXml(svg);
    INFO(parsed.error);
    REQUIRE(parsed.root != nullptr);
    CHECK(parsed.root->name == "svg");
    // The caption is text, in the figure's font: selectable, searchable.
    std::vector<const satviz::test::XmlElement*> elements;
    satviz::test::CollectElements(*parsed.root, elements);
    bool caption = false;
    for (const auto* element : elements)
    {
        caption = caption || (element->name == "text" && element->text.find("Before: A (mass 1.571)") == 0);
    }
    CHECK(caption);
    const fs::path golden = fs::path(SATVIZ_SOURCE_DIR) / "tests/render/golden/l14_head_on.svg";
    INFO("a changed figure: compare " << (dir / "Head_On.SVG").string() << " with " << golden.string()
                                      << ", and copy it over when the change is meant");
    CHECK(svg == Bytes(golden));

    // A directory takes --format svg; the same scene again gives the same bytes.
    const Run batch = Render(Scene("l14_head_on.json") + " -q --format svg -o " + dir.string());
    REQUIRE(batch.exitCode == 0);
    CHECK(Bytes(dir / "l14_head_on.svg") == svg);

    // A format the file name contradicts, or an unknown one, is refused in one line.
    const Run contradiction = Render(Scene("l14_head_on.json") + " --format png -o " + (dir / "x.svg").string());
    CHECK(contradiction.exitCode == 2);
    REQUIRE(contradiction.errLines.size() == 1);
    CHECK(contradiction.errLines[0].find("--format png") != std::string::npos);
    const Run unknown = Render(Scene("l14_head_on.json") + " --format pdf -o " + dir.string());
    CHECK(unknown.exitCode == 2);
    REQUIRE(unknown.errLines.size() == 1);
    CHECK(unknown.errLines[0].find("expected png or svg") != std::string::npos);
    CHECK(!fs::exists(dir / "x.svg"));
}

TEST_CASE("satviz-render --sim-every writes a strip of figures named by step, each the state --sim-steps draws",
          "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-strip");
    const Run run = Render(Scene("l14_head_on.json") + " -q --sim-steps 25 --sim-every 10 --layers shapes,plots -o " +
                           dir.string());
    INFO(Joined(run.errLines));
    REQUIRE(run.exitCode == 0);
    for (const char* name : {"l14_head_on-sim00.png", "l14_head_on-sim10.png", "l14_head_on-sim20.png",
                             "l14_head_on-sim25.png"})
    {
        CHECK(fs::is_regular_file(dir / name));
    }
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 4);
    // A figure of the strip is the figure of its step alone.
    REQUIRE(Render(Scene("l14_head_on.json") + " -q --sim-steps 20 --layers shapes,plots -o " +
                   (dir / "alone.png").string())
                .exitCode == 0);
    CHECK(Bytes(dir / "alone.png") == Bytes(dir / "l14_head_on-sim20.png"));
    const Run bad = Render(Scene("l14_head_on.json") + " --sim-steps 5 --sim-every 0 -o " + dir.string());
    CHECK(bad.exitCode == 2);
    REQUIRE(bad.errLines.size() == 1);
    CHECK(bad.errLines[0].find("--sim-every") != std::string::npos);
}

TEST_CASE("satviz-render --version prints its name and the project version", "[render-tool]")
{
    const Run run = Render("--version");
    CHECK(run.exitCode == 0);
    REQUIRE(run.outLines.size() == 1);
    CHECK(run.outLines[0] == std::string("satviz-render ") + SATVIZ_VERSION);
    CHECK(run.errLines.empty());
}

TEST_CASE("satviz-render --sim-steps draws a falling body where N steps leave it, g dt^2 N (N + 1) / 2 lower",
          "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-sim");
    fs::create_directories(dir);
    // A ball at y = 2 under gravity 10 with dt 0.1: each step adds g dt to its speed, then moves it, so after 10
    // steps it has fallen 10 * 0.1^2 * (1 + 2 + ... + 10) = 5.5, to y = -3.5 (the continuous g t^2 / 2 says 5).
    auto scene = [](const std::string& ball, const std::string& extra) {
        return R"({"bodies": [{"name": "ground", "box": [4, 1], "position": [0, -10], "static": true},
            {"name": "ball", "circle": {"radius": 0.25}, )" +
               ball + R"(}], "world": {"gravity": [0, -10], "dt": 0.1},
            "view": {"zoom": 40, "center": [0, -1], "size": [200, 400], "query": "collide", "layers": ["shapes"])" +
               extra + "}}";
    };
    std::ofstream(dir / "fall.json") << scene(R"("position": [0, 2])", "");
    std::ofstream(dir / "fall_view.json") << scene(R"("position": [0, 2])", R"(, "sim_steps": 10)");
    std::ofstream(dir / "closed_form.json") << scene(R"("position": [0, -3.5])", "");
    std::ofstream(dir / "continuous.json") << scene(R"("position": [0, -3])", "");

    const Run run = Render((dir / "fall.json").string() + " --sim-steps 10 -q -o " + (dir / "fall.png").string());
    INFO(Joined(run.errLines));
    REQUIRE(run.exitCode == 0);
    REQUIRE(Render((dir / "closed_form.json").string() + " -q -o " + (dir / "closed_form.png").string()).exitCode == 0);
    REQUIRE(Render((dir / "continuous.json").string() + " -q -o " + (dir / "continuous.png").string()).exitCode == 0);
    REQUIRE(Render((dir / "fall.json").string() + " -q -o " + (dir / "start.png").string()).exitCode == 0);
    const std::string stepped = Bytes(dir / "fall.png");
    CHECK(stepped == Bytes(dir / "closed_form.png"));
    CHECK(stepped != Bytes(dir / "continuous.png"));
    CHECK(stepped != Bytes(dir / "start.png"));

    // The scene's view.sim_steps does the same; --sim-steps overrides it, 0 drawing the scene as written.
    REQUIRE(Render((dir / "fall_view.json").string() + " -q -o " + (dir / "view.png").string()).exitCode == 0);
    CHECK(Bytes(dir / "view.png") == stepped);
    REQUIRE(
        Render((dir / "fall_view.json").string() + " --sim-steps 0 -q -o " + (dir / "zero.png").string()).exitCode ==
        0);
    CHECK(Bytes(dir / "zero.png") == Bytes(dir / "start.png"));

    // A negative count is refused before anything is drawn, with one line.
    const Run negative =
        Render((dir / "fall.json").string() + " --sim-steps -1 -q -o " + (dir / "negative.png").string());
    CHECK(negative.exitCode == 2);
    REQUIRE(negative.errLines.size() == 1);
    CHECK(negative.errLines[0] ==
          "satviz-render: --sim-steps: expected a whole number of steps from 0 to 1000000, got -1");
    CHECK(!fs::exists(dir / "negative.png"));
}

TEST_CASE("satviz-render --size shows what the scene's own view frames, scaled to fit the new size", "[render-tool]")
{
    const fs::path dir = FreshDirectory("render-size");
    fs::create_directories(dir);
    // Two unit squares 16 apart, framed for 800 x 600 at 40 pixels a unit: at x = 80 and x = 720 in the scene's
    // own figure, 640 pixels apart, at mid-height. Only the shapes are drawn, so the whole image is the scene area.
    std::ofstream(dir / "apart.json")
        << R"({"bodies": [{"name": "a", "box": [1, 1], "position": [-8, 0]},
                          {"name": "b", "box": [1, 1], "position": [8, 0]}],
              "view": {"zoom": 40, "center": [0, 0], "size": [800, 600], "layers": ["shapes"]}})";
    // The squares' centres as drawn: the mean of each filled polygon's corners, in the order the bodies are drawn.
    auto centres = [&](const std::string& size) {
        const fs::path out = dir / ("apart-" + size + ".svg");
        const Run run = Render((dir / "apart.json").string() + " --size " + size + " -q -o " + out.string());
        INFO(Joined(run.errLines));
        REQUIRE(run.exitCode == 0);
        const auto parsed = satviz::test::ParseXml(Bytes(out));
        REQUIRE(parsed.root != nullptr);
        std::vector<const satviz::test::XmlElement*> elements;
        satviz::test::CollectElements(*parsed.root, elements);
        std::vector<std::pair<double, double>> found;
        for (const auto* element : elements)
        {
            const auto fill = element->attributes.find("fill");
            if (element->name != "polygon" || fill == element->attributes.end() || fill->second == "none")
            {
                continue;
            }
            std::istringstream points(element->attributes.at("points"));
            double sx = 0.0;
            double sy = 0.0;
            int n = 0;
            for (std::string pair; points >> pair; ++n)
            {
                const size_t comma = pair.find(',');
                sx += std::stod(pair.substr(0, comma));
                sy += std::stod(pair.substr(comma + 1));
            }
            found.push_back({sx / n, sy / n});
        }
        return found;
    };
    struct Expected
    {
        std::string size;
        double scale;  // the world rectangle of 800 x 600 pixels fits the new image: the smaller ratio of sides
        double middleX;
        double middleY;
    };
    for (const Expected& expected : {Expected{"800x600", 1.0, 400.0, 300.0}, Expected{"400x600", 0.5, 200.0, 300.0},
                                     Expected{"1600x600", 1.0, 800.0, 300.0}, Expected{"800x300", 0.5, 400.0, 150.0},
                                     Expected{"200x150", 0.25, 100.0, 75.0}})
    {
        INFO("--size " << expected.size);
        const std::vector<std::pair<double, double>> found = centres(expected.size);
        REQUIRE(found.size() == 2);
        // Centred where the view's centre goes, the middle of the image, and as far apart as the scale makes 640.
        CHECK(found[0].first == Approx(expected.middleX - 320.0 * expected.scale).margin(0.6));
        CHECK(found[1].first == Approx(expected.middleX + 320.0 * expected.scale).margin(0.6));
        CHECK(found[0].second == Approx(expected.middleY).margin(0.6));
        CHECK(found[1].second == Approx(expected.middleY).margin(0.6));
    }
}
