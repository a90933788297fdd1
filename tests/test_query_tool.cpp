// SPDX-License-Identifier: MIT
// satviz-query as a program: one JSON line per file, errors on stderr, a non-zero exit, the other files answered;
// --touching against a brute-force oracle.

#include <satviz/collide.h>
#include <satviz/concave.h>
#include <satviz/decompose.h>
#include <satviz/polygon.h>
#include <satviz/scene.h>
#include <satviz/sweep.h>

#include "support/random_concave.h"
#include "support/random_shapes.h"
#include "support/run_tool.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace satviz;

namespace
{

struct Run
{
    int exitCode = -1;
    std::vector<std::string> out;
    std::string err;
};

/// The files these tests write live in a directory of their own, removed at exit, never in the directory the tests
/// were started from.
struct ScratchDirectory
{
    std::filesystem::path start = std::filesystem::current_path();
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("satviz-query-test-" + std::to_string(::getpid()));

    ScratchDirectory()
    {
        std::filesystem::create_directories(dir);
        std::filesystem::current_path(dir);
    }

    ~ScratchDirectory()
    {
        std::error_code ignored;
        std::filesystem::current_path(start, ignored);
        std::filesystem::remove_all(dir, ignored);
    }
};

const ScratchDirectory kScratch;

Run Query(const std::string& arguments)
{
    const testing::ToolRun run = testing::RunTool(std::string(SATVIZ_QUERY_EXE) + " " + arguments);
    return {run.exitCode, testing::SplitLines(run.out), run.err};
}

void Write(const std::string& path, const std::string& text)
{
    std::ofstream(path) << text;
}

} // namespace

TEST_CASE("satviz-query answers every pair, in the documented form", "[query]")
{
    const std::string scene = SATVIZ_SOURCE_DIR "/tutorials/scenes/overlapping_boxes.json";
    const Run run = Query(scene);
    REQUIRE(run.exitCode == 0);
    REQUIRE(run.out.size() == 1);
    const nlohmann::json line = nlohmann::json::parse(run.out[0]);
    CHECK(line["scene"] == scene);
    REQUIRE(line["pairs"].size() == 1);
    const nlohmann::json& pair = line["pairs"][0];
    CHECK(pair["a"] == "A");
    CHECK(pair["b"] == "B");

    // The printed numbers read back as the very doubles the library computed.
    const SceneResult loaded = LoadScene(scene);
    REQUIRE(loaded.Ok());
    const Body& a = loaded.scene.bodies[0];
    const Body& b = loaded.scene.bodies[1];
    const Manifold m = Collide(a.shape, a.Xf(), b.shape, b.Xf());
    CHECK(pair["overlap"] == m.overlap);
    CHECK(pair["depth"].get<double>() == m.depth);
    CHECK(pair["normal"][0].get<double>() == m.normal.x);
    CHECK(pair["normal"][1].get<double>() == m.normal.y);
    REQUIRE(pair["contacts"].size() == static_cast<size_t>(m.contactCount));
    CHECK(pair["contacts"][0][0].get<double>() == m.contacts[0].point.x);
    CHECK(pair["axis"]["shape"] == (m.axis.shape == 0 ? "a" : "b"));
    CHECK(pair["axis"]["edge"] == m.axis.index);
    CHECK(!pair.contains("trace"));

    // The default trace is the textbook test's: its view says so, and its MTV is Collide's.
    const Run traced = Query("--trace " + scene);
    REQUIRE(traced.exitCode == 0);
    const nlohmann::json textbook = nlohmann::json::parse(traced.out[0])["pairs"][0]["trace"];
    CHECK(textbook["view"] == "textbook");
    REQUIRE(textbook["axes"].size() >= 2);
    CHECK(textbook["result"]["overlap"] == m.overlap);
    CHECK(std::abs(textbook["result"]["depth"].get<double>() - m.depth) <= 1e-12);
    for (const auto& axis : textbook["axes"])
    {
        const double minA = axis["interval_a"][0], maxA = axis["interval_a"][1];
        const double minB = axis["interval_b"][0], maxB = axis["interval_b"][1];
        REQUIRE(axis.contains("overlap"));
        CHECK(axis["overlap"].get<double>() == std::min(maxA - minB, maxB - minA));
    }

    const Run faces = Query("--trace --view faces " + scene);
    REQUIRE(faces.exitCode == 0);
    const nlohmann::json withTrace = nlohmann::json::parse(faces.out[0])["pairs"][0];
    CHECK(withTrace["trace"]["view"] == "faces");
    CHECK(withTrace["trace"]["axes"].size() >= 4);
    CHECK(withTrace["trace"]["exit"] == "all-axes-overlap");
    // An overlapping pair runs one face test per face of either polygon, and the count says how many ran.
    const int faceCount = a.shape.polygon.Count() + b.shape.polygon.Count();
    CHECK(withTrace["trace"]["faces_tested"] == withTrace["trace"]["axes"].size());
    CHECK(withTrace["trace"]["faces_tested"] == faceCount);
    CHECK(withTrace["trace"].contains("clip"));
    CHECK(Query("--trace --view edges " + scene).exitCode != 0);
}

TEST_CASE("satviz-query: bad files get one error line each, the others are answered", "[query]")
{
    Write("bad_syntax.json", "{\"bodies\": [");
    Write("bad_polygon.json", R"({"bodies": [{"polygon": [[0,0],[2,0],[0,2],[2,2]]}, {"box": [1, 1]}]})");
    const std::string good = SATVIZ_SOURCE_DIR "/tutorials/scenes/containment.json";
    const Run run = Query("bad_syntax.json " + good + " missing.json bad_polygon.json");
    CHECK(run.exitCode == 1);
    REQUIRE(run.out.size() == 4);
    CHECK(nlohmann::json::parse(run.out[0]).contains("error"));
    CHECK(nlohmann::json::parse(run.out[1])["pairs"].size() == 1);
    CHECK(nlohmann::json::parse(run.out[2])["error"] == "missing.json: cannot open: No such file or directory");
    CHECK(
        nlohmann::json::parse(run.out[3])["error"] ==
        "bad_polygon.json: bodies[0].polygon: polygon is not simple: edge 1 (vertex 1 to 2) meets edge 3 (vertex 3 to "
        "0)");
    // Exactly one line on stderr per bad file.
    size_t lines = 0;
    for (char c : run.err)
    {
        lines += c == '\n' ? 1 : 0;
    }
    CHECK(lines == 3);
    CHECK(run.err.find("satviz-query: bad_polygon.json: bodies[0].polygon:") != std::string::npos);
}

TEST_CASE("satviz-query survives junk bytes, invalid UTF-8 and deep nesting", "[query]")
{
    std::string junk;
    for (int i = 0; i < 4096; ++i)
    {
        junk += static_cast<char>((i * 73 + 11) & 0xff);
    }
    Write("junk.json", junk);
    Write("bad_utf8.json", "{\"bodies\": [{\"polygon\": [[0,0],[1,0],[0,1]], \"name\": \"\xff\xfe\"}]}");
    Write("bad_utf8_name.json", "{\"bodies\": [{\"box\": [1, 1], \"name\": \"a\"}], \"x\xff\": 1}");
    // 200 000 levels of nesting: no stack overflow in the parser.
    Write("deep.json", std::string(200000, '[') + std::string(200000, ']'));
    const Run run = Query("junk.json bad_utf8.json bad_utf8_name.json deep.json");
    CHECK(run.exitCode == 1);
    REQUIRE(run.out.size() == 4);
    for (const std::string& line : run.out)
    {
        CHECK(nlohmann::json::parse(line).contains("error"));
    }
}

TEST_CASE("satviz-query without files explains its usage and fails", "[query]")
{
    const Run run = Query("");
    CHECK(run.exitCode != 0);
    CHECK(run.err.find("files") != std::string::npos);
}

TEST_CASE("satviz-query --version prints its name and the project version", "[query]")
{
    const Run run = Query("--version");
    CHECK(run.exitCode == 0);
    REQUIRE(run.out.size() == 1);
    CHECK(run.out[0] == std::string("satviz-query ") + SATVIZ_VERSION);
    CHECK(run.err.empty());
}

TEST_CASE("satviz-query reports times of impact for moving pairs", "[query][sweep]")
{
    Write("moving.json", R"({"bodies": [
        {"name": "wall", "box": [0.001, 20]},
        {"name": "bullet", "box": [0.01, 0.01], "position": [-500, 0.2], "velocity": [1000, 0]},
        {"name": "away", "circle": {"radius": 0.1}, "position": [5, 5], "velocity": [1, 1]},
        {"name": "still", "circle": {"radius": 0.1}, "position": [-5, -5]}]})");
    const Run run = Query("moving.json");
    REQUIRE(run.exitCode == 0);
    const nlohmann::json pairs = nlohmann::json::parse(run.out[0])["pairs"];
    REQUIRE(pairs.size() == 6);
    const SceneResult loaded = LoadScene("moving.json");
    REQUIRE(loaded.Ok());
    const Body& wall = loaded.scene.bodies[0];
    const Body& bullet = loaded.scene.bodies[1];
    const SweepResult expected =
        Sweep(wall.shape, wall.Xf(), wall.velocity, bullet.shape, bullet.Xf(), bullet.velocity);
    REQUIRE(expected.status == SweepStatus::Hit);
    CHECK(pairs[0]["toi"].get<double>() == expected.toi);
    CHECK(pairs[0]["toi_normal"][0].get<double>() == expected.normal.x);
    CHECK(pairs[0]["toi_contacts"].size() == static_cast<size_t>(expected.contactCount));
    CHECK(pairs[0]["toi_status"] == "hit");
    // wall-away: moving apart, a miss, with a null normal and no contacts; wall-still: nothing moves, no sweep
    // fields at all.
    CHECK(pairs[1]["b"] == "away");
    CHECK(pairs[1]["toi"].is_null());
    CHECK(pairs[1]["toi_status"] == "miss");
    CHECK(pairs[1]["toi_normal"].is_null());
    CHECK(pairs[1]["toi_contacts"].empty());
    CHECK(pairs[2]["b"] == "still");
    CHECK_FALSE(pairs[2].contains("toi"));
}

TEST_CASE("satviz-query tells a pair that overlaps at the start from one that hits, for circles too", "[query][sweep]")
{
    // Two discs of radius 1 at x = 0 and x = 5, the second moving by -4: they touch when 5 - 4 t = 2, t = 3/4,
    // at x = 1 on the line of centres. Two boxes 1 wide whose centres are 0.5 apart overlap by 0.5 at the start.
    Write("circles.json", R"({"bodies": [
        {"name": "P", "circle": {"radius": 1}},
        {"name": "Q", "circle": {"radius": 1}, "position": [5, 0], "velocity": [-4, 0]}]})");
    Write("overlapping.json", R"({"bodies": [
        {"name": "A", "box": [1, 1]},
        {"name": "B", "box": [1, 1], "position": [0.5, 0], "velocity": [1, 0]}]})");
    const Run circles = Query("circles.json");
    REQUIRE(circles.exitCode == 0);
    const nlohmann::json hit = nlohmann::json::parse(circles.out[0])["pairs"][0];
    CHECK(hit["toi_status"] == "hit");
    CHECK(hit["toi"].get<double>() == Approx(0.75).margin(1e-15));
    CHECK(hit["toi_normal"][0].get<double>() == Approx(1.0).margin(1e-15));
    CHECK(hit["toi_normal"][1].get<double>() == Approx(0.0).margin(1e-15));
    REQUIRE(hit["toi_contacts"].size() == 1);
    CHECK(hit["toi_contacts"][0][0].get<double>() == Approx(1.0).margin(1e-14));
    const Run overlapping = Query("overlapping.json");
    REQUIRE(overlapping.exitCode == 0);
    const nlohmann::json inside = nlohmann::json::parse(overlapping.out[0])["pairs"][0];
    CHECK(inside["toi_status"] == "overlapping");
    CHECK(inside["toi"].get<double>() == 0.0);
    // The static MTV: out along +x (B is to the right of A), by 0.5.
    CHECK(inside["toi_normal"][0].get<double>() == Approx(1.0).margin(1e-15));
    CHECK(inside["depth"].get<double>() == Approx(0.5).margin(1e-15));
}

TEST_CASE("satviz-query: a long trace says so on stderr, and one too large for the textbook prints the face tests",
          "[query]")
{
    Write("large.json", R"({"bodies": [{"name": "disc", "regular": {"sides": 4200, "radius": 1}},
        {"name": "box", "box": [0.5, 0.5], "position": [1.1, 0.3]}]})");
    const Run large = Query("--trace large.json");
    REQUIRE(large.exitCode == 0);
    CHECK(large.err.find("satviz-query: large.json: tracing disc and box, 4204 vertices") != std::string::npos);
    const nlohmann::json textbook = nlohmann::json::parse(large.out[0])["pairs"][0]["trace"];
    CHECK(textbook["view"] == "textbook");
    CHECK(textbook["result"]["axis_count"] == 2100 + 2);
    CHECK(Query("large.json").err.empty());

    Write("huge.json", R"({"bodies": [{"name": "disc", "regular": {"sides": 20001, "radius": 1}},
        {"name": "box", "box": [0.5, 0.5], "position": [1.1, 0.3]}]})");
    const Run huge = Query("--trace huge.json");
    REQUIRE(huge.exitCode == 0);
    const nlohmann::json faces = nlohmann::json::parse(huge.out[0])["pairs"][0]["trace"];
    CHECK(faces["view"] == "faces");
    CHECK(faces["note"].get<std::string>().find("too many vertices for the textbook trace") == 0);
}

namespace
{

// A scene of grid x grid bodies: circles, boxes and pentagons of random size and turn, each jittered about its
// own cell of a 1.2-unit grid. No body reaches more than 0.72 + 0.15 sqrt 2 < 0.94 from its cell's centre, and
// cells two apart are 2.4 apart, so only bodies of neighbouring cells (8 around) can touch; about one pair of
// neighbours in twelve does.
Scene GridScene(int grid)
{
    uint64_t state = 0x9e3779b97f4a7c15ull;
    auto uniform = [&state](double low, double high) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return low + (high - low) * static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    Scene scene;
    for (int k = 0; k < grid * grid; ++k)
    {
        Body body;
        body.name = "b" + std::to_string(k);
        body.position = {1.2 * (k % grid) + uniform(-0.15, 0.15), 1.2 * (k / grid) + uniform(-0.15, 0.15)};
        body.angle = uniform(-3.0, 3.0);
        if (k % 3 == 0)
        {
            body.shape = MakeShape(Circle{{0.0, 0.0}, uniform(0.4, 0.7)});
        }
        else if (k % 3 == 1)
        {
            body.shape = MakeShape(MakeBox(uniform(0.3, 0.5), uniform(0.3, 0.5)).polygon);
        }
        else
        {
            body.shape = MakeShape(MakeRegularPolygon(5, uniform(0.4, 0.72), 0.0).polygon);
        }
        scene.bodies.push_back(body);
    }
    return scene;
}

using NamePairs = std::vector<std::pair<std::string, std::string>>;

NamePairs TouchingOf(const nlohmann::json& line)
{
    NamePairs pairs;
    for (const auto& pair : line["touching"])
    {
        pairs.emplace_back(pair[0].get<std::string>(), pair[1].get<std::string>());
    }
    return pairs;
}

NamePairs Names(const Scene& scene, const std::vector<std::pair<size_t, size_t>>& pairs)
{
    NamePairs names;
    for (const auto& [i, j] : pairs)
    {
        names.emplace_back(scene.bodies[i].name, scene.bodies[j].name);
    }
    return names;
}

bool Touch(const Body& a, const Body& b)
{
    return Overlap(a.shape, a.Xf(), b.shape, b.Xf());
}

} // namespace

TEST_CASE("satviz-query --touching lists the pairs that touch, in body order", "[query][touching]")
{
    // A and B share an edge (touching counts), C overlaps B, D is far away.
    Write("touch.json", R"({"bodies": [
        {"name": "A", "box": [1, 1]},
        {"name": "B", "box": [1, 1], "position": [1, 0]},
        {"name": "C", "circle": {"radius": 0.5}, "position": [1.75, 0.25]},
        {"name": "D", "circle": {"radius": 0.5}, "position": [10, 0]}]})");
    const Run run = Query("--touching touch.json");
    REQUIRE(run.exitCode == 0);
    REQUIRE(run.out.size() == 1);
    CHECK(run.out[0] == R"({"scene":"touch.json","touching":[["A","B"],["B","C"]],"bodies":4})");
    CHECK(run.err.empty());

    Write("empty.json", R"({"bodies": []})");
    const Run empty = Query("--touching empty.json missing.json");
    CHECK(empty.exitCode == 1);
    REQUIRE(empty.out.size() == 2);
    CHECK(empty.out[0] == R"({"scene":"empty.json","touching":[],"bodies":0})");
    CHECK(nlohmann::json::parse(empty.out[1]).contains("error"));
    CHECK(Query("--touching --trace touch.json").exitCode != 0);
}

TEST_CASE("satviz-query --touching equals the brute-force Overlap of every pair, and answers 10000 bodies",
          "[query][touching]")
{
    // 900 bodies: every one of the 404 550 pairs tested here.
    std::string error;
    REQUIRE(SaveScene(GridScene(30), "grid30.json", error));
    const SceneResult small = LoadScene("grid30.json");
    REQUIRE(small.Ok());
    std::vector<std::pair<size_t, size_t>> expected;
    for (size_t i = 0; i < small.scene.bodies.size(); ++i)
    {
        for (size_t j = i + 1; j < small.scene.bodies.size(); ++j)
        {
            if (Touch(small.scene.bodies[i], small.scene.bodies[j]))
            {
                expected.emplace_back(i, j);
            }
        }
    }
    CHECK(expected.size() > 200);
    const Run run = Query("--touching grid30.json");
    REQUIRE(run.exitCode == 0);
    const nlohmann::json line = nlohmann::json::parse(run.out.at(0));
    CHECK(line["bodies"] == 900);
    CHECK(TouchingOf(line) == Names(small.scene, expected));

    // 10 000 bodies: 50 million pairs, answered through the broadphase. The oracle here tests each body against
    // its neighbouring cells, the only ones it can reach (see GridScene), so it is exact too.
    const int grid = 100;
    REQUIRE(SaveScene(GridScene(grid), "grid100.json", error));
    const SceneResult large = LoadScene("grid100.json");
    REQUIRE(large.Ok());
    std::vector<std::pair<size_t, size_t>> near;
    for (size_t i = 0; i < large.scene.bodies.size(); ++i)
    {
        const int x = static_cast<int>(i) % grid;
        const int y = static_cast<int>(i) / grid;
        for (int dy = -1; dy <= 1; ++dy)
        {
            for (int dx = -1; dx <= 1; ++dx)
            {
                const int nx = x + dx;
                const int ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= grid || ny >= grid)
                {
                    continue;
                }
                const size_t j = static_cast<size_t>(ny * grid + nx);
                if (j > i && Touch(large.scene.bodies[i], large.scene.bodies[j]))
                {
                    near.emplace_back(i, j);
                }
            }
        }
    }
    std::sort(near.begin(), near.end());
    const Run big = Query("--touching grid100.json");
    REQUIRE(big.exitCode == 0);
    const nlohmann::json bigLine = nlohmann::json::parse(big.out.at(0));
    CHECK(bigLine["bodies"] == 10000);
    CHECK(TouchingOf(bigLine) == Names(large.scene, near));
}

TEST_CASE("satviz-query answers for concave bodies with the same fields, the axis naming the piece", "[query]")
{
    // An L, a box in its notch (falling onto the floor of the notch), a box sunk into its foot, and a comb.
    Write("concave.json", R"({"bodies": [
        {"name": "L", "polygon": [[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]]},
        {"name": "notch", "box": [0.8, 0.8], "position": [2.5, 2.5], "velocity": [0, -3]},
        {"name": "sunk", "box": [0.8, 0.8], "position": [2.5, 0.9], "angle": 0.1},
        {"name": "comb", "polygon": [[0,0],[9,0],[9,4],[8,4],[8,1],[7,1],[7,4],[6,4],[6,1],[5,1],[5,4],[4,4],[4,1],
                                     [3,1],[3,4],[2,4],[2,1],[1,1],[1,4],[0,4]],
         "decompose": "fewest", "position": [10, 0]}]})");
    const Run run = Query("concave.json");
    REQUIRE(run.exitCode == 0);
    const nlohmann::json pairs = nlohmann::json::parse(run.out[0])["pairs"];
    SceneOptions options;
    options.concave = true;
    const SceneResult loaded = LoadScene("concave.json", options);
    REQUIRE(loaded.Ok());
    const std::vector<Body>& bodies = loaded.scene.bodies;
    REQUIRE(pairs.size() == 6);
    size_t k = 0;
    for (size_t i = 0; i < bodies.size(); ++i)
    {
        for (size_t j = i + 1; j < bodies.size(); ++j, ++k)
        {
            const Body& a = bodies[i];
            const Body& b = bodies[j];
            const nlohmann::json& pair = pairs[k];
            INFO(a.name << " " << b.name);
            CHECK(pair["a"] == a.name);
            // The library's answer, by the concave queries.
            ConcaveManifold m;
            if (a.IsConcave() && b.IsConcave())
            {
                m = Collide(a.concave, a.Xf(), b.concave, b.Xf());
            }
            else if (a.IsConcave())
            {
                m = Collide(a.concave, a.Xf(), b.shape, b.Xf());
            }
            else if (b.IsConcave())
            {
                m = Collide(a.shape, a.Xf(), b.concave, b.Xf());
            }
            else
            {
                m.manifold = Collide(a.shape, a.Xf(), b.shape, b.Xf());
            }
            CHECK(pair["overlap"] == m.manifold.overlap);
            if (a.IsConcave() || b.IsConcave())
            {
                CHECK(pair["piece_pairs"]["tested"] == m.pairsTested);
                CHECK(pair["piece_pairs"]["overlapping"] == m.pairsOverlap);
                CHECK(pair["piece_pairs"]["seam"] == m.pairsSeam);
            }
            else
            {
                CHECK(!pair.contains("piece_pairs"));
            }
            CHECK(pair["normal"][0].get<double>() == m.manifold.normal.x);
            CHECK(pair["normal"][1].get<double>() == m.manifold.normal.y);
            CHECK(pair["contacts"].size() == static_cast<size_t>(m.manifold.contactCount));
            if (m.manifold.overlap)
            {
                CHECK(pair["depth"].get<double>() == m.manifold.depth);
                const int piece = m.manifold.axis.shape == 0 ? m.pieceA : m.pieceB;
                if (piece >= 0)
                {
                    CHECK(pair["axis"]["piece"] == piece);
                }
            }
        }
    }
    // Each body's pieces, against the decomposition of the outline as written, by the body's method.
    const nlohmann::json listed = nlohmann::json::parse(run.out[0])["bodies"];
    REQUIRE(listed.size() == bodies.size());
    const std::vector<Vec2> ell = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
    std::vector<Vec2> comb = {{0, 0}, {9, 0}};
    for (int tooth = 8; tooth >= 0; tooth -= 2)
    {
        // Teeth at x in [8, 9], [6, 7], ... [0, 1], gaps between them down to y = 1.
        comb.insert(comb.end(), {{tooth + 1.0, 4.0}, {tooth + 0.0, 4.0}});
        if (tooth > 0)
        {
            comb.insert(comb.end(), {{tooth + 0.0, 1.0}, {tooth - 1.0, 1.0}});
        }
    }
    CHECK(listed[0] == nlohmann::json::parse(R"({"name": "L", "pieces": )" +
                                             std::to_string(Decompose(ell, DecomposeMethod::Fast).pieces.size()) +
                                             R"(, "decompose": "fast", "vertices": 6})"));
    CHECK(listed[1] == nlohmann::json::parse(R"({"name": "notch", "pieces": 1})"));
    CHECK(listed[2] == nlohmann::json::parse(R"({"name": "sunk", "pieces": 1})"));
    CHECK(listed[3]["pieces"] == Decompose(comb, DecomposeMethod::Fewest).pieces.size());
    CHECK(listed[3]["decompose"] == "fewest");
    CHECK(listed[3]["vertices"] == 20);
    // By hand: one seam from the L's one reflex corner, two pieces.
    CHECK(listed[0]["pieces"] == 2);
    // The box in the notch is clear of the L (its hull would hold it), and falls onto the notch's floor.
    const nlohmann::json& notch = pairs[0];
    CHECK(notch["overlap"] == false);
    CHECK(notch["toi_status"] == "hit");
    CHECK(notch["toi"].get<double>() == Approx(1.1 / 3));
    CHECK(notch["toi_normal"][1].get<double>() == Approx(1.0));
    // The sunk box is pushed up out of the L's foot, by the piece that holds the foot.
    const nlohmann::json& sunk = pairs[1];
    CHECK(sunk["overlap"] == true);
    CHECK(sunk["normal"][1].get<double>() == Approx(1.0));
    CHECK(sunk["axis"]["kind"] == "face");
    CHECK(sunk["axis"].contains("piece"));
    // --touching: only the sunk box touches the L; the box in the notch is inside the L's hull, not the L.
    const Run touching = Query("--touching concave.json");
    REQUIRE(touching.exitCode == 0);
    CHECK(nlohmann::json::parse(touching.out[0])["touching"] == nlohmann::json::parse(R"([["L", "sunk"]])"));
}

TEST_CASE("satviz-query applies a slice figure's cut: the parts' mass, centre, inertia and motion keep the momenta",
          "[query][cut]")
{
    // By hand: a 2 x 1 bar of density 1 moving at (1, 0) and turning at 1 rad/s, cut along x = 0.5. The right part
    // is [0.5, 1] x [-0.5, 0.5]: mass 0.5, centre (0.75, 0), inertia 0.5 (0.5^2 + 1^2) / 12, velocity
    // (1, 0) + 1 x (0.75, 0) = (1, 0.75). The left part is [-1, 0.5] x [-0.5, 0.5]: mass 1.5, centre (-0.25, 0),
    // inertia 1.5 (1.5^2 + 1^2) / 12, velocity (1, -0.25).
    Write("bar_cut.json", R"({"bodies": [{"name": "bar", "box": [2, 1], "velocity": [1, 0], "angular_velocity": 1}],
        "view": {"figure": "slice", "cut": [[0.5, -1], [0.5, 1]]}})");
    Run run = Query("bar_cut.json");
    REQUIRE(run.exitCode == 0);
    const nlohmann::json cut = nlohmann::json::parse(run.out[0])["cut"];
    REQUIRE(cut["cut"] == true);
    REQUIRE(cut["parts"].size() == 2);
    const nlohmann::json& right = cut["parts"][0];
    const nlohmann::json& left = cut["parts"][1];
    CHECK(right["mass"].get<double>() == Approx(0.5));
    CHECK(right["centroid"][0].get<double>() == Approx(0.75));
    CHECK(right["inertia"].get<double>() == Approx(0.5 * (0.25 + 1.0) / 12.0));
    CHECK(right["velocity"][1].get<double>() == Approx(0.75));
    CHECK(left["mass"].get<double>() == Approx(1.5));
    CHECK(left["centroid"][0].get<double>() == Approx(-0.25));
    CHECK(left["inertia"].get<double>() == Approx(1.5 * (2.25 + 1.0) / 12.0));
    CHECK(left["velocity"][1].get<double>() == Approx(-0.25));
    CHECK(left["angular_velocity"].get<double>() == 1.0);
    // The whole bar: momentum 2 (1, 0), angular momentum about its centre I w = 2 (2^2 + 1^2) / 12.
    CHECK(cut["momentum_before"][0].get<double>() == Approx(2.0));
    CHECK(cut["angular_momentum_before"].get<double>() == Approx(10.0 / 12.0));
    CHECK(cut["angular_momentum_after"].get<double>() == Approx(10.0 / 12.0));

    // Random polygons, convex and concave, moving and turning, cut by random lines: the parts' areas sum to the
    // outline's (shoelace), and both momenta are kept.
    testing::Rng rng(20261128);
    std::string files;
    std::vector<std::vector<Vec2>> outlines;
    for (int i = 0; i < 60; ++i)
    {
        std::vector<Vec2> outline;
        if (i % 2 == 0)
        {
            const Polygon convex = testing::RandomPolygon(rng, rng.Int(3, 12), 2.0, rng.Uniform(0.3, 1.0));
            outline.assign(convex.Vertices().begin(), convex.Vertices().end());
        }
        else
        {
            outline = testing::RandomStarPolygon(rng, rng.Int(5, 14), 2.0, 0.5);
        }
        outlines.push_back(outline);
        std::ostringstream text;
        text.precision(17);
        text << R"({"bodies": [{"name": "p", "polygon": [)";
        for (size_t k = 0; k < outline.size(); ++k)
        {
            text << (k > 0 ? ", " : "") << "[" << outline[k].x << ", " << outline[k].y << "]";
        }
        const double through = rng.Uniform(-0.5, 0.5);
        const double turn = rng.Uniform(0.0, 3.14159);
        const Vec2 d{std::cos(turn), std::sin(turn)};
        const Vec2 a = Vec2{through * -d.y, through * d.x} - 5.0 * d;
        const Vec2 b = a + 10.0 * d;
        text << R"(], "position": [)" << rng.Uniform(-3, 3) << ", " << rng.Uniform(-3, 3) << R"(], "angle": )"
             << rng.Uniform(-3, 3) << R"(, "velocity": [)" << rng.Uniform(-2, 2) << ", " << rng.Uniform(-2, 2)
             << R"(], "angular_velocity": )" << rng.Uniform(-2, 2) << R"(, "density": )" << rng.Uniform(0.5, 3)
             << R"(}], "view": {"figure": "slice", "cut": [[)" << a.x << ", " << a.y << "], [" << b.x << ", " << b.y
             << "]]}}";
        const std::string name = "random_cut_" + std::to_string(i) + ".json";
        Write(name, text.str());
        files += " " + name;
    }
    run = Query(files.substr(1));
    REQUIRE(run.exitCode == 0);
    REQUIRE(run.out.size() == outlines.size());
    int cuts = 0;
    for (size_t i = 0; i < outlines.size(); ++i)
    {
        INFO("random_cut_" << i);
        const nlohmann::json line = nlohmann::json::parse(run.out[i]);
        const nlohmann::json& c = line["cut"];
        if (c["cut"] == false)
        {
            CHECK(!c["reason"].get<std::string>().empty());
            continue;
        }
        ++cuts;
        const double area = std::abs(static_cast<double>(testing::Area2(outlines[i]))) / 2.0;
        double parts = 0.0;
        for (const nlohmann::json& part : c["parts"])
        {
            parts += part["area"].get<double>();
            CHECK(part["area"].get<double>() > 0.0);
        }
        CHECK(parts + 0.0 == Approx(area).epsilon(1e-9));
        CHECK(c["slivers"] == 0);
        const double scale = 1.0 + std::abs(c["momentum_before"][0].get<double>()) +
                             std::abs(c["momentum_before"][1].get<double>());
        CHECK(std::abs(c["momentum_after"][0].get<double>() - c["momentum_before"][0].get<double>()) < 1e-9 * scale);
        CHECK(std::abs(c["momentum_after"][1].get<double>() - c["momentum_before"][1].get<double>()) < 1e-9 * scale);
        CHECK(c["angular_momentum_after"].get<double>() ==
              Approx(c["angular_momentum_before"].get<double>()).margin(1e-9 * scale * 10.0));
        // The parts' kinetic energy, summed from their printed motion, is the body's: a cut neither adds nor takes.
        double energy = 0.0;
        for (const nlohmann::json& part : c["parts"])
        {
            const double vx = part["velocity"][0].get<double>();
            const double vy = part["velocity"][1].get<double>();
            const double w = part["angular_velocity"].get<double>();
            energy += 0.5 * part["mass"].get<double>() * (vx * vx + vy * vy) +
                      0.5 * part["inertia"].get<double>() * w * w;
        }
        const double after = c["kinetic_energy_after"].get<double>();
        CHECK(after == Approx(energy).epsilon(1e-12));
        CHECK(after == Approx(c["kinetic_energy_before"].get<double>()).epsilon(1e-9));
    }
    CHECK(cuts >= 30);
}
