// SPDX-License-Identifier: MIT
// satviz-sim as a program, and the scene library's bridge to the world (MakeWorld, CopyWorldState): JSON lines
// whose numbers are the world's own doubles, --every, --counts, --save, one-line errors.

#include <satviz/mass.h>
#include <satviz/scene.h>
#include <satviz/scene_world.h>
#include <satviz/world.h>

#include "support/run_tool.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace satviz;

namespace
{

/// The files these tests write live in a directory of their own, removed at exit.
struct SimScratch
{
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("satviz-sim-test-" + std::to_string(::getpid()));

    SimScratch() { std::filesystem::create_directories(dir); }

    ~SimScratch()
    {
        std::error_code ignored;
        std::filesystem::remove_all(dir, ignored);
    }

    std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

const SimScratch kSim;

struct SimRun
{
    int exitCode = -1;
    std::vector<std::string> out;
    std::string err;
};

std::string ReadAll(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

SimRun Sim(const std::string& arguments)
{
    const testing::ToolRun run = testing::RunTool(std::string(SATVIZ_SIM_EXE) + " " + arguments);
    return {run.exitCode, testing::SplitLines(run.out), run.err};
}

void WriteFile(const std::string& path, const std::string& text)
{
    std::ofstream(path) << text;
}

size_t LineCount(const std::string& text)
{
    size_t lines = 0;
    for (const char c : text)
    {
        lines += c == '\n' ? 1 : 0;
    }
    return lines;
}

// A ball dropped on the ground beside a spinning box thrown up, in metres and seconds.
const std::string kDrop = R"({
  "description": "drop",
  "bodies": [
    {"name": "ground", "box": [20, 1], "position": [0, -0.5], "static": true, "friction": 0.8},
    {"name": "ball", "circle": {"radius": 0.5}, "position": [0, 2], "restitution": 0.5, "tool:color": "red"},
    {"name": "crate", "box": [1, 0.5], "position": [4, 1], "velocity": [0.5, 3], "angular_velocity": 2,
     "density": 2}
  ],
  "world": {"gravity": [0, -9.81], "dt": 0.0166666}
})";

} // namespace

TEST_CASE("MakeWorld: one world body per scene body, in order, with the scene's gravity and fields", "[sim][world]")
{
    const SceneResult loaded = ParseScene(kDrop, "drop.json");
    REQUIRE(loaded.Ok());
    CHECK(ValidateSceneWorld(loaded.scene).empty());
    const World world = MakeWorld(loaded.scene);
    CHECK(world.settings.gravity == Vec2{0, -9.81});
    REQUIRE(world.bodies.size() == 3);
    const RigidBody& ground = world.bodies[0];
    CHECK(ground.type == BodyType::Static);
    CHECK(ground.invMass == 0.0);
    CHECK(ground.material.friction == 0.8);
    CHECK(ground.material.staticFriction == 0.8);
    CHECK(ground.position == Vec2{0, -0.5});
    const RigidBody& ball = world.bodies[1];
    CHECK(ball.type == BodyType::Dynamic);
    CHECK(ball.material.restitution == 0.5);
    CHECK(ball.mass == Approx(ComputeMass(ball.shape, 1.0).mass));
    const RigidBody& crate = world.bodies[2];
    CHECK(crate.mass == Approx(ComputeMass(crate.shape, 2.0).mass));
    CHECK(crate.mass == Approx(1.0));
    CHECK(crate.position == Vec2{4, 1});
    CHECK(crate.velocity == Vec2{0.5, 3});
    CHECK(crate.angularVelocity == 2.0);

    // A scene built in code can hold what a file cannot: the body is named by its path and name.
    Scene bad = loaded.scene;
    bad.bodies[2].density = 0.0;
    const std::string error = ValidateSceneWorld(bad);
    CHECK(error.rfind("bodies[2] (\"crate\"): ", 0) == 0);
    CHECK(error.find("density") != std::string::npos);
}

TEST_CASE("CopyWorldState: the world's state back into the scene, which saves and loads as that state", "[sim][world]")
{
    SceneResult loaded = ParseScene(kDrop, kSim / "drop.json");
    REQUIRE(loaded.Ok());
    World world = MakeWorld(loaded.scene);
    for (int i = 0; i < 30; ++i)
    {
        Step(world, loaded.scene.world.dt);
    }
    Scene& scene = loaded.scene;
    CopyWorldState(world, scene);
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        CHECK(scene.bodies[i].position == world.bodies[i].position);
        CHECK(scene.bodies[i].angle == world.bodies[i].angle);
        CHECK(scene.bodies[i].velocity == world.bodies[i].velocity);
        CHECK(scene.bodies[i].angularVelocity == world.bodies[i].angularVelocity);
    }
    std::string error;
    REQUIRE(SaveScene(scene, kSim / "copied.json", error));
    const SceneResult again = LoadScene(kSim / "copied.json");
    INFO(again.error);
    REQUIRE(again.Ok());
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        CHECK(again.scene.bodies[i].position == world.bodies[i].position);
        CHECK(again.scene.bodies[i].angle == world.bodies[i].angle);
        CHECK(again.scene.bodies[i].velocity == world.bodies[i].velocity);
        CHECK(again.scene.bodies[i].angularVelocity == world.bodies[i].angularVelocity);
        CHECK(again.scene.bodies[i].isStatic == scene.bodies[i].isStatic);
        CHECK(again.scene.bodies[i].density == scene.bodies[i].density);
    }
    CHECK(again.scene.world.dt == 0.0166666);
}

TEST_CASE("SimulateScene: a falling body drops by g dt^2 N (N + 1) / 2, what sim_steps draws", "[sim][world]")
{
    // Each step adds g dt to the velocity, then moves by the new velocity (semi-implicit Euler): after N steps the
    // body has fallen g dt^2 (1 + 2 + ... + N) = g dt^2 N (N + 1) / 2, and falls at g dt N.
    SceneResult loaded =
        ParseScene(R"({"bodies": [{"name": "ground", "box": [4, 1], "position": [0, -10], "static": true},
        {"name": "ball", "circle": {"radius": 0.25}, "position": [0, 2]}],
        "world": {"gravity": [0, -10], "dt": 0.1}, "view": {"sim_steps": 10}})",
                   "fall.json");
    REQUIRE(loaded.Ok());
    Scene& scene = loaded.scene;
    CHECK(SimulateScene(scene, 0).empty());
    CHECK(scene.bodies[1].position == Vec2{0, 2});
    REQUIRE(SimulateScene(scene, scene.view.simSteps).empty());
    CHECK(scene.bodies[1].position.x == 0.0);
    CHECK(scene.bodies[1].position.y == Approx(2.0 - 10.0 * 0.1 * 0.1 * 10 * 11 / 2).margin(1e-12)); // 2 - 5.5
    CHECK(scene.bodies[1].velocity.y == Approx(-10.0 * 0.1 * 10).margin(1e-12));
    CHECK(scene.bodies[0].position == Vec2{0, -10});

    // Errors leave the scene as it was.
    const Vec2 before = scene.bodies[1].position;
    CHECK(SimulateScene(scene, -1) == "expected a whole number of steps of at least 0, got -1");
    Scene flung = scene;
    flung.bodies[1].velocity = {9e11, 0};
    flung.world.dt = 10.0;
    CHECK(SimulateScene(flung, 1).find("bodies[1] (\"ball\"): after 1 step its state is beyond") == 0);
    CHECK(flung.bodies[1].velocity == Vec2{9e11, 0});
    Scene bad = scene;
    bad.bodies[1].density = 0.0;
    CHECK(SimulateScene(bad, 3).rfind("bodies[1] (\"ball\"): ", 0) == 0);
    CHECK(bad.bodies[1].position == before);
}

TEST_CASE("satviz-sim prints one JSON line per step with the world's own numbers, and a summary", "[sim]")
{
    WriteFile(kSim / "drop.json", kDrop);
    const SimRun run = Sim(kSim / "drop.json --steps 40");
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    REQUIRE(run.out.size() == 40);

    // The same world stepped here gives the same bits: every printed number reads back as the world's double.
    const SceneResult loaded = LoadScene(kSim / "drop.json");
    REQUIRE(loaded.Ok());
    World world = MakeWorld(loaded.scene);
    for (size_t k = 0; k < run.out.size(); ++k)
    {
        Step(world, 0.0166666);
        const nlohmann::ordered_json line = nlohmann::ordered_json::parse(run.out[k]);
        std::vector<std::string> keys;
        for (const auto& item : line.items())
        {
            keys.push_back(item.key());
        }
        CHECK(keys == std::vector<std::string>{"step", "time", "bodies"});
        CHECK(line["step"] == k + 1);
        CHECK(line["time"].get<double>() == world.time);
        REQUIRE(line["bodies"].size() == 3);
        for (size_t i = 0; i < 3; ++i)
        {
            const nlohmann::ordered_json& body = line["bodies"][i];
            const RigidBody& expected = world.bodies[i];
            CHECK(body.begin().key() == "name");
            CHECK(body["name"] == loaded.scene.bodies[i].name);
            CHECK(body["position"][0].get<double>() == expected.position.x);
            CHECK(body["position"][1].get<double>() == expected.position.y);
            CHECK(body["angle"].get<double>() == expected.angle);
            CHECK(body["velocity"][0].get<double>() == expected.velocity.x);
            CHECK(body["velocity"][1].get<double>() == expected.velocity.y);
            CHECK(body["angular_velocity"].get<double>() == expected.angularVelocity);
            CHECK(body.size() == 5);
        }
        CHECK(!line.contains("counts"));
    }
    // The ground stays put; the ball falls under gravity and the crate turns.
    const nlohmann::json last = nlohmann::json::parse(run.out.back());
    CHECK(last["bodies"][0]["position"] == nlohmann::json::array({0, -0.5}));
    CHECK(last["bodies"][1]["position"][1].get<double>() < 2.0);
    CHECK(last["bodies"][2]["angle"].get<double>() > 0.0);
    CHECK(last["time"].get<double>() == Approx(40 * 0.0166666));

    // One summary line on stderr: the steps, the time they took, the last step's contacts, sleep and hits.
    CHECK(LineCount(run.err) == 1);
    CHECK(run.err.find("satviz-sim: " + kSim / "drop.json" + ": 40 steps of 0.0166666 in ") == 0);
    CHECK(run.err.find(" ms; last step: ") != std::string::npos);
    CHECK(run.err.find("contacts") != std::string::npos);
    CHECK(run.err.find("dynamic bodies asleep") != std::string::npos);
    CHECK(run.err.find("time-ordered hits") != std::string::npos);
}

TEST_CASE("satviz-sim --every prints every K-th step and the last, --dt overrides the scene's step", "[sim]")
{
    WriteFile(kSim / "drop.json", kDrop);
    const SimRun run = Sim(kSim / "drop.json --steps 10 --every 3");
    REQUIRE(run.exitCode == 0);
    std::vector<int> steps;
    for (const std::string& line : run.out)
    {
        steps.push_back(nlohmann::json::parse(line)["step"].get<int>());
    }
    CHECK(steps == std::vector<int>{3, 6, 9, 10});
    const SimRun exact = Sim(kSim / "drop.json --steps 10 --every 5");
    CHECK(exact.out.size() == 2);
    const SimRun once = Sim(kSim / "drop.json --steps 3 --every 100");
    REQUIRE(once.out.size() == 1);
    CHECK(nlohmann::json::parse(once.out[0])["step"] == 3);

    // --dt 0.001: ten steps make 0.01 time units whatever the scene says.
    const SimRun fine = Sim(kSim / "drop.json --steps 10 --dt 0.001");
    REQUIRE(fine.exitCode == 0);
    CHECK(nlohmann::json::parse(fine.out.back())["time"].get<double>() == Approx(0.01));
    CHECK(fine.err.find("10 steps of 0.001 in") != std::string::npos);

    // A scene without a world block steps by 1: a velocity is the displacement over one step.
    WriteFile(kSim / "plain.json", R"({"bodies": [{"name": "A", "box": [1, 1], "velocity": [0.25, 0]}]})");
    const SimRun plain = Sim(kSim / "plain.json --steps 4");
    REQUIRE(plain.exitCode == 0);
    const nlohmann::json last = nlohmann::json::parse(plain.out.back());
    CHECK(last["time"].get<double>() == 4.0);
    CHECK(last["bodies"][0]["position"][0].get<double>() == Approx(1.0));
    CHECK(last["bodies"][0]["position"][1].get<double>() == Approx(0.0).margin(1e-12));
}

TEST_CASE("satviz-sim --threads prints the same bytes on 1, 2 and 3 threads, and refuses a bad count", "[sim]")
{
    // A pile that falls, collides and settles, so the world has pairs to split between the threads.
    std::string pile = R"({"world": {"gravity": [0, -9.81], "dt": 0.0166666}, "bodies": [)"
                       R"({"name": "floor", "box": [40, 1], "position": [0, -1], "static": true})";
    for (int k = 0; k < 300; ++k)
    {
        const std::string shape = k % 2 == 0 ? R"("box": [0.6, 0.4])" : R"("circle": {"radius": 0.3})";
        pile += R"(, {"name": "b)" + std::to_string(k) + R"(", )" + shape + R"(, "position": [)" +
                std::to_string(-15.0 + 1.1 * (k % 25)) + ", " + std::to_string(0.5 + 1.1 * (k / 25)) +
                R"(], "angle": )" + std::to_string(0.1 * (k % 7)) + "}";
    }
    pile += "]}";
    WriteFile(kSim / "threads.json", pile);
    const SimRun one = Sim(kSim / "threads.json --steps 120 --every 20");
    INFO(one.err);
    REQUIRE(one.exitCode == 0);
    REQUIRE(one.out.size() == 6);
    for (const char* threads : {"2", "3"})
    {
        const SimRun many = Sim(kSim / "threads.json --steps 120 --every 20 --threads " + threads);
        REQUIRE(many.exitCode == 0);
        CHECK(many.out == one.out);
    }
    for (const char* bad : {"0", "-1", "two", "1000"})
    {
        const SimRun run = Sim(kSim / "threads.json --steps 1 --threads " + bad);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("satviz-sim: --threads: expected a whole number from 1 to 256") == 0);
    }
}

TEST_CASE("satviz-sim --counts adds what each step did with the pairs", "[sim]")
{
    WriteFile(kSim / "drop.json", kDrop);
    const SimRun run = Sim(kSim / "drop.json --steps 5 --every 5 --counts");
    REQUIRE(run.exitCode == 0);
    REQUIRE(run.out.size() == 1);
    const nlohmann::ordered_json line = nlohmann::ordered_json::parse(run.out[0]);
    REQUIRE(line.contains("counts"));
    std::vector<std::string> keys;
    for (const auto& item : line["counts"].items())
    {
        keys.push_back(item.key());
    }
    CHECK(keys == std::vector<std::string>{"pairs", "static_pairs", "sleeping_pairs", "bounds_apart", "tested",
                                           "touching", "speculative", "swept", "hits", "awake", "sleeping"});
    CHECK(line["counts"]["pairs"] == 3);
    CHECK(line["counts"]["awake"].get<int>() + line["counts"]["sleeping"].get<int>() == 2);
}

TEST_CASE("satviz-sim --energy adds the kinetic energy and momentum, computed from the printed bodies", "[sim]")
{
    WriteFile(kSim / "drop.json", kDrop);
    const SimRun plain = Sim(kSim / "drop.json --steps 30 --every 10");
    const SimRun energy = Sim(kSim / "drop.json --steps 30 --every 10 --energy");
    REQUIRE(plain.exitCode == 0);
    REQUIRE(energy.exitCode == 0);
    REQUIRE(plain.out.size() == 3);
    REQUIRE(energy.out.size() == plain.out.size());
    // The scene's bodies, for their masses and inertias.
    const SceneResult loaded = ParseScene(kDrop, "drop.json");
    REQUIRE(loaded.Ok());
    const World world = MakeWorld(loaded.scene);
    bool moving = false;
    for (size_t k = 0; k < plain.out.size(); ++k)
    {
        // Without the flag the line is what it was; with it, the same line and two more fields.
        CHECK(plain.out[k].find("kinetic_energy") == std::string::npos);
        nlohmann::ordered_json line = nlohmann::ordered_json::parse(energy.out[k]);
        REQUIRE(line.contains("kinetic_energy"));
        REQUIRE(line.contains("momentum"));
        double kinetic = 0.0, px = 0.0, py = 0.0;
        for (size_t i = 0; i < world.bodies.size(); ++i)
        {
            const RigidBody& body = world.bodies[i];
            if (body.type != BodyType::Dynamic)
            {
                continue;
            }
            const auto& b = line["bodies"][i];
            const double vx = b["velocity"][0], vy = b["velocity"][1], w = b["angular_velocity"];
            kinetic += 0.5 * body.mass * (vx * vx + vy * vy) + 0.5 * body.inertia * w * w;
            px += body.mass * vx;
            py += body.mass * vy;
            moving = moving || vx != 0.0 || vy != 0.0;
        }
        CHECK(line["kinetic_energy"].get<double>() == Approx(kinetic).epsilon(1e-12));
        CHECK(line["momentum"][0].get<double>() == Approx(px).margin(1e-12));
        CHECK(line["momentum"][1].get<double>() == Approx(py).epsilon(1e-12));
        line.erase("kinetic_energy");
        line.erase("momentum");
        CHECK(line.dump() == nlohmann::ordered_json::parse(plain.out[k]).dump());
    }
    CHECK(moving);
}

TEST_CASE("satviz-sim --save writes the last printed state as a scene that loads, in the file's form", "[sim]")
{
    WriteFile(kSim / "drop.json", kDrop);
    const std::string saved = kSim / "saved.json";
    const SimRun run = Sim(kSim / "drop.json --steps 50 --every 7 --save " + saved);
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const SceneResult again = LoadScene(saved);
    INFO(again.error);
    REQUIRE(again.Ok());
    const nlohmann::json last = nlohmann::json::parse(run.out.back());
    CHECK(last["step"] == 50);
    REQUIRE(again.scene.bodies.size() == last["bodies"].size());
    for (size_t i = 0; i < again.scene.bodies.size(); ++i)
    {
        const Body& body = again.scene.bodies[i];
        const nlohmann::json& printed = last["bodies"][i];
        CHECK(body.name == printed["name"]);
        CHECK(body.position.x == printed["position"][0].get<double>());
        CHECK(body.position.y == printed["position"][1].get<double>());
        CHECK(body.angle == printed["angle"].get<double>());
        CHECK(body.velocity.x == printed["velocity"][0].get<double>());
        CHECK(body.velocity.y == printed["velocity"][1].get<double>());
        CHECK(body.angularVelocity == printed["angular_velocity"].get<double>());
    }
    // The file keeps its form: its description, world block, namespaced fields and physical fields.
    const nlohmann::ordered_json json = nlohmann::ordered_json::parse(ReadAll(saved));
    CHECK(json["description"] == "drop");
    CHECK(json["world"].dump() == R"({"gravity":[0,-9.81],"dt":0.0166666})");
    CHECK(json["bodies"][0]["box"].dump() == "[20,1]");
    CHECK(json["bodies"][0]["static"] == true);
    CHECK(json["bodies"][1]["tool:color"] == "red");
    CHECK(json["bodies"][2]["density"] == 2);
    // No temporary file is left beside it.
    for (const auto& entry : std::filesystem::directory_iterator(kSim.dir))
    {
        CHECK(entry.path().filename().string().find(".tmp.") == std::string::npos);
    }

    // The saved scene steps on.
    const SimRun more = Sim(saved + " --steps 5");
    CHECK(more.exitCode == 0);
    CHECK(more.out.size() == 5);

    // A directory that does not exist: an error naming the file, after the run.
    const SimRun bad = Sim(kSim / "drop.json --steps 2 --save " + kSim / "missing/out.json");
    CHECK(bad.exitCode == 1);
    CHECK(bad.err.find("satviz-sim: " + kSim / "missing/out.json" + ": cannot write") != std::string::npos);
}

TEST_CASE("satviz-sim refuses bad arguments and scenes with one line naming the option, file or field", "[sim]")
{
    WriteFile(kSim / "drop.json", kDrop);
    const std::string scene = kSim / "drop.json";
    const struct
    {
        std::string arguments;
        std::string error;
        int exitCode;
    } cases[] = {
        {scene + " --steps 0", "satviz-sim: --steps: expected a whole number of steps of at least 1, got \"0\"", 2},
        {scene + " --steps -3", "satviz-sim: --steps: expected a whole number of steps of at least 1, got \"-3\"", 2},
        {scene + " --steps ten", "satviz-sim: --steps: expected a whole number of steps of at least 1, got \"ten\"", 2},
        {scene + " --steps 2.5", "satviz-sim: --steps: expected a whole number of steps of at least 1, got \"2.5\"", 2},
        {scene + " --steps 5 --every 0", "satviz-sim: --every: expected a whole number of at least 1, got \"0\"", 2},
        {scene + " --steps 5 --dt 0",
         "satviz-sim: --dt: expected a finite step length greater than 0 (at most 1e12), got \"0\"", 2},
        {scene + " --steps 5 --dt -0.1",
         "satviz-sim: --dt: expected a finite step length greater than 0 (at most 1e12), got \"-0.1\"", 2},
        {scene + " --steps 5 --dt nan",
         "satviz-sim: --dt: expected a finite step length greater than 0 (at most 1e12), got \"nan\"", 2},
        {scene + " --steps 5 --dt inf",
         "satviz-sim: --dt: expected a finite step length greater than 0 (at most 1e12), got \"inf\"", 2},
        {scene + " --steps 5 --dt 1e-3x",
         "satviz-sim: --dt: expected a finite step length greater than 0 (at most 1e12), got \"1e-3x\"", 2},
        {kSim / "missing.json --steps 5",
         "satviz-sim: " + kSim / "missing.json" + ": cannot open: No such file or directory", 1},
    };
    for (const auto& c : cases)
    {
        INFO(c.arguments);
        const SimRun run = Sim(c.arguments);
        CHECK(run.exitCode == c.exitCode);
        CHECK(run.out.empty());
        CHECK(run.err == c.error + "\n");
    }

    WriteFile(kSim / "bad.json", R"({"bodies": [{"name": "A", "box": [1, 1], "density": 0}]})");
    const SimRun bad = Sim(kSim / "bad.json --steps 5");
    CHECK(bad.exitCode == 1);
    CHECK(bad.out.empty());
    CHECK(bad.err == "satviz-sim: " + kSim / "bad.json" + ": bodies[0].density: must be greater than 0\n");
    WriteFile(kSim / "bad_dt.json", R"({"bodies": [], "world": {"dt": -1}})");
    CHECK(Sim(kSim / "bad_dt.json --steps 5").err ==
          "satviz-sim: " + kSim / "bad_dt.json" + ": world.dt: must be greater than 0\n");

    // A final state the scene format cannot hold is refused before anything is written: a body flung past 1e12.
    WriteFile(kSim / "fling.json", R"({"bodies": [{"name": "flung", "box": [2, 0.1], "velocity": [1e12, 0]}]})");
    const SimRun flung = Sim(kSim / "fling.json --steps 2 --save " + kSim / "flung.json");
    CHECK(flung.exitCode == 1);
    CHECK(flung.out.size() == 2);
    INFO(flung.err);
    CHECK(flung.err.find("satviz-sim: " + kSim / "flung.json" + ": bodies[0].position") != std::string::npos);
    CHECK(flung.err.find("(the final state; nothing was written)\n") != std::string::npos);
    CHECK(!std::filesystem::exists(kSim / "flung.json"));

    // A body wound through many turns saves with its orientation, the angle turned into [-pi, pi].
    WriteFile(kSim / "spin.json", R"({"bodies": [{"name": "spinner", "box": [2, 0.1], "angular_velocity": 1e6}]})");
    const SimRun spun = Sim(kSim / "spin.json --steps 2 --save " + kSim / "spun.json");
    INFO(spun.err);
    CHECK(spun.exitCode == 0);
    const double wound = nlohmann::json::parse(spun.out.back())["bodies"][0]["angle"].get<double>();
    CHECK(wound == 2e6);
    const SceneResult spunScene = LoadScene(kSim / "spun.json");
    REQUIRE(spunScene.Ok());
    const double saved = spunScene.scene.bodies[0].angle;
    CHECK(std::abs(saved) <= 3.14159265358979323846);
    CHECK(std::cos(saved) == Approx(std::cos(wound)).margin(1e-9));
    CHECK(std::sin(saved) == Approx(std::sin(wound)).margin(1e-9));

    // Without a scene or --steps: CLI11's usage error, and a non-zero exit.
    CHECK(Sim("--steps 5").exitCode != 0);
    CHECK(Sim(scene).exitCode != 0);
}

TEST_CASE("satviz-sim: the example line of docs/programs.md is what the program prints", "[sim]")
{
    WriteFile(kSim / "ball.json", R"({"bodies": [{"name": "ball", "circle": {"radius": 0.5}, "position": [0, 2],
        "angular_velocity": 1}], "world": {"gravity": [0, -9.81], "dt": 0.0166666}})");
    const SimRun run = Sim(kSim / "ball.json --steps 1");
    REQUIRE(run.exitCode == 0);
    REQUIRE(run.out.size() == 1);
    std::istringstream readme(ReadAll(SATVIZ_SOURCE_DIR "/docs/programs.md"));
    std::string example;
    for (std::string line; std::getline(readme, line);)
    {
        if (line.rfind(R"({"step":1,)", 0) == 0)
        {
            example = line;
        }
    }
    CHECK(example == run.out[0]);
}

TEST_CASE("satviz-sim --version prints its name and the project version", "[sim]")
{
    const SimRun run = Sim("--version");
    CHECK(run.exitCode == 0);
    REQUIRE(run.out.size() == 1);
    CHECK(run.out[0] == std::string("satviz-sim ") + SATVIZ_VERSION);
    CHECK(run.err.empty());
}

TEST_CASE("satviz-sim steps a concave body, and --save writes its outline back", "[sim][concave]")
{
    // An L (outline y from 0 to 3) dropped flat from 1 unit above the ground's top (y = 0).
    WriteFile(kSim / "ell.json", R"({
  "bodies": [
    {"name": "ground", "box": [20, 1], "position": [0, -0.5], "static": true},
    {"name": "L", "polygon": [[0,0],[3,0],[3,1],[1,1],[1,3],[0,3]], "decompose": "fewest", "position": [0, 1]}
  ],
  "world": {"gravity": [0, -9.81], "dt": 0.0166666}
})");
    const std::string saved = kSim / "ell_saved.json";
    const SimRun run = Sim(kSim / "ell.json --steps 120 --every 120 --save " + saved);
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const nlohmann::json last = nlohmann::json::parse(run.out.back());
    const nlohmann::json& ell = last["bodies"][1];
    // At rest on the ground: its outline's bottom (y = 0 in its frame) on the ground's top, within the slop.
    CHECK(ell["position"][1].get<double>() == Approx(0.0).margin(0.01));
    CHECK(ell["position"][0].get<double>() == Approx(0.0).margin(1e-6));
    CHECK(std::abs(ell["velocity"][1].get<double>()) < 0.05);

    // The saved file keeps the outline as written and how it was cut, not the hull that bounds it.
    const nlohmann::ordered_json json = nlohmann::ordered_json::parse(ReadAll(saved));
    CHECK(json["bodies"][1]["polygon"].dump() == "[[0,0],[3,0],[3,1],[1,1],[1,3],[0,3]]");
    CHECK(json["bodies"][1]["decompose"] == "fewest");
    SceneOptions options;
    options.concave = true;
    const SceneResult again = LoadScene(saved, options);
    INFO(again.error);
    REQUIRE(again.Ok());
    REQUIRE(again.scene.bodies[1].IsConcave());
    CHECK(again.scene.bodies[1].position.y == ell["position"][1].get<double>());
}

TEST_CASE("SceneToJson writes a concave body built in code as its outline, which reads back the same", "[sim][concave]")
{
    SceneOptions options;
    options.concave = true;
    const SceneResult read = ParseScene(
        R"({"bodies": [{"name": "U", "polygon": [[0,0],[3,0],[3,2],[2,2],[2,1],[1,1],[1,2],[0,2]]}]})", "u.json",
        options);
    REQUIRE(read.Ok());
    // The same body in a scene of its own, with no source file behind it, cut the other way.
    Scene scene;
    Body body = read.scene.bodies[0];
    const Decomposition fewest = Decompose(body.outline, DecomposeMethod::Fewest);
    REQUIRE(fewest.Ok());
    body.concave = MakeConcave(fewest.pieces);
    body.decompose = DecomposeMethod::Fewest;
    body.position = {1.5, -2};
    scene.bodies.push_back(body);
    const std::string text = SceneToJson(scene);
    const SceneResult back = ParseScene(text, "back.json", options);
    INFO(text << back.error);
    REQUIRE(back.Ok());
    const Body& u = back.scene.bodies[0];
    REQUIRE(u.IsConcave());
    CHECK(u.outline == body.outline);
    CHECK(u.decompose == DecomposeMethod::Fewest);
    CHECK(u.concave.parts.size() == body.concave.parts.size());
    CHECK(u.position == body.position);
    // The world makes the same body of both: the same mass and inertia.
    World a, b;
    AddBody(a, MakeBodyDef(body));
    AddBody(b, MakeBodyDef(u));
    CHECK(a.bodies[0].mass == b.bodies[0].mass);
    CHECK(a.bodies[0].inertia == b.bodies[0].inertia);
    CHECK(a.bodies[0].IsConcave());
}
