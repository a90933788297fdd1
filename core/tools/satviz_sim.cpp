// SPDX-License-Identifier: MIT
// satviz-sim: steps a scene as a rigid-body world and prints the bodies' state as JSON lines. No graphics.

#include <satviz/scene.h>
#include <satviz/scene_world.h>
#include <satviz/tasks.h>
#include <satviz/world.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{

using Json = nlohmann::ordered_json;

// Names quote the input, which may hold bytes that are not UTF-8: print them replaced, never throw.
constexpr auto kReplace = Json::error_handler_t::replace;

// A whole number of at least 1 from an option's text, else false.
bool ParseCount(const std::string& text, long long& value)
{
    if (text.empty() || text.find_first_not_of("0123456789+") != std::string::npos)
    {
        return false;
    }
    errno = 0;
    char* end = nullptr;
    value = std::strtoll(text.c_str(), &end, 10);
    return errno == 0 && end != nullptr && *end == '\0' && value >= 1;
}

// Most threads --threads takes: more than a machine has only slows the step down.
constexpr int kMaxThreads = 256;

// -0 prints as 0.
Json Pair(satviz::Vec2 v)
{
    return Json::array({v.x + 0.0, v.y + 0.0});
}

// One printed step: the time and every body's state, numbers in the shortest form that reads back as the same
// double (nlohmann-json's); with `withCounts`, what the step did with the pairs.
Json StateJson(const satviz::World& world, const satviz::Scene& scene, long long step, bool withCounts, bool withEnergy)
{
    Json bodies = Json::array();
    for (size_t i = 0; i < world.bodies.size(); ++i)
    {
        const satviz::RigidBody& body = world.bodies[i];
        bodies.push_back({{"name", scene.bodies[i].name},
                          {"position", Pair(body.position)},
                          {"angle", body.angle + 0.0},
                          {"velocity", Pair(body.velocity)},
                          {"angular_velocity", body.angularVelocity + 0.0}});
    }
    Json line = {{"step", step}, {"time", world.time + 0.0}, {"bodies", std::move(bodies)}};
    if (withEnergy)
    {
        // The dynamic bodies' totals, what the lessons check a hit against: energy kept or lost, momentum kept.
        line["kinetic_energy"] = satviz::KineticEnergy(world) + 0.0;
        line["momentum"] = Pair(satviz::LinearMomentum(world));
    }
    if (withCounts)
    {
        const satviz::StepCounts& c = world.counts;
        line["counts"] = {{"pairs", c.pairs},
                          {"static_pairs", c.staticPairs},
                          {"sleeping_pairs", c.sleepingPairs},
                          {"bounds_apart", c.boundsApart},
                          {"tested", c.tested},
                          {"touching", c.touching},
                          {"speculative", c.speculative},
                          {"swept", c.swept},
                          {"hits", c.hits},
                          {"awake", c.awakeBodies},
                          {"sleeping", c.sleepingBodies}};
    }
    return line;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"Step a scene as a rigid-body world; print the bodies' state as one JSON line per printed step."};
    app.set_version_flag("--version", std::string("satviz-sim ") + SATVIZ_VERSION);
    std::string file;
    std::string stepsText;
    std::string dtText;
    std::string everyText = "1";
    std::string threadsText = "1";
    std::string savePath;
    bool withCounts = false;
    app.add_option("scene", file, "Scene file (JSON)")->required()->type_name("SCENE.json");
    app.add_option("--steps", stepsText, "Number of steps, at least 1")->required()->type_name("N");
    app.add_option("--dt", dtText, "Step length in time units, > 0 (default: the scene's world.dt, else 1)")
        ->type_name("S");
    app.add_option("--every", everyText, "Print every K-th step (default 1), and always the last")->type_name("K");
    app.add_option("--threads", threadsText,
                   "Threads the world steps on, the caller's included (default 1); the results are the same bits for "
                   "any number")
        ->type_name("T");
    app.add_option("--save", savePath, "Write the final state as a scene file (atomically)")->type_name("OUT.json");
    bool withEnergy = false;
    app.add_flag("--energy", withEnergy,
                 "Add each printed step's totals over the dynamic bodies: kinetic_energy (translation and rotation) "
                 "and momentum");
    app.add_flag("--counts", withCounts,
                 "Add each printed step's counts: pairs, static_pairs, sleeping_pairs, bounds_apart, tested, "
                 "touching, swept, hits, awake, sleeping");
    bool softStep = false;
    app.add_flag("--soft-step", softStep,
                 "Step with the soft step (sub-steps of soft contacts, WorldSettings::softStep) in place of the "
                 "velocity and position passes");
    CLI11_PARSE(app, argc, argv);

    long long steps = 0;
    if (!ParseCount(stepsText, steps))
    {
        std::fprintf(stderr, "satviz-sim: --steps: expected a whole number of steps of at least 1, got \"%s\"\n",
                     stepsText.c_str());
        return 2;
    }
    long long every = 0;
    if (!ParseCount(everyText, every))
    {
        std::fprintf(stderr, "satviz-sim: --every: expected a whole number of at least 1, got \"%s\"\n",
                     everyText.c_str());
        return 2;
    }
    long long threads = 0;
    if (!ParseCount(threadsText, threads) || threads > kMaxThreads)
    {
        std::fprintf(stderr, "satviz-sim: --threads: expected a whole number from 1 to %d, got \"%s\"\n", kMaxThreads,
                     threadsText.c_str());
        return 2;
    }
    double dt = 0.0;
    if (!dtText.empty())
    {
        char* end = nullptr;
        dt = std::strtod(dtText.c_str(), &end);
        if (end == dtText.c_str() || *end != '\0' || !std::isfinite(dt) || dt <= 0.0 || dt > satviz::kMaxSceneValue)
        {
            std::fprintf(stderr,
                         "satviz-sim: --dt: expected a finite step length greater than 0 (at most 1e12), got "
                         "\"%s\"\n",
                         dtText.c_str());
            return 2;
        }
    }

    // A polygon may be concave: the world steps it as one body made of its convex pieces.
    satviz::SceneOptions options;
    options.concave = true;
    satviz::SceneResult loaded = satviz::LoadScene(file, options);
    if (!loaded.Ok())
    {
        std::cerr << "satviz-sim: " << loaded.error << "\n";
        return 1;
    }
    satviz::Scene& scene = loaded.scene;
    if (const std::string error = satviz::ValidateSceneWorld(scene); !error.empty())
    {
        std::cerr << "satviz-sim: " << file << ": " << error << "\n";
        return 1;
    }
    if (dtText.empty())
    {
        dt = scene.world.dt;
    }

    std::ios::sync_with_stdio(false);
    satviz::World world = satviz::MakeWorld(scene);
    world.settings.softStep = softStep;
    satviz::ThreadPool pool(static_cast<int>(threads));
    world.tasks = satviz::PoolTasks(pool);
    long long hits = 0;
    const auto start = std::chrono::steady_clock::now();
    for (long long step = 1; step <= steps; ++step)
    {
        satviz::Step(world, dt);
        hits += world.counts.hits;
        if (step % every == 0 || step == steps)
        {
            std::cout << StateJson(world, scene, step, withCounts, withEnergy).dump(-1, ' ', false, kReplace) << '\n';
        }
    }
    std::cout.flush();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    int dynamic = 0;
    for (const satviz::RigidBody& body : world.bodies)
    {
        dynamic += body.type == satviz::BodyType::Dynamic ? 1 : 0;
    }
    std::fprintf(stderr,
                 "satviz-sim: %s: %lld step%s of %g in %.3f ms; last step: %zu contacts; %d of %d dynamic bodies "
                 "asleep; %lld time-ordered hits\n",
                 file.c_str(), steps, steps == 1 ? "" : "s", dt, ms, world.contacts.size(), world.counts.sleepingBodies,
                 dynamic, hits);

    if (!savePath.empty())
    {
        satviz::CopyWorldState(world, scene);
        // A state the scene format cannot hold (a body flung beyond 1e12) is
        // refused before anything is written.
        const satviz::SceneResult check = satviz::ParseScene(satviz::SceneToJson(scene), savePath, options);
        if (!check.Ok())
        {
            std::cerr << "satviz-sim: " << check.error << " (the final state; nothing was written)\n";
            return 1;
        }
        std::string error;
        if (!satviz::SaveScene(scene, savePath, error))
        {
            std::cerr << "satviz-sim: " << error << "\n";
            return 1;
        }
    }
    return std::cout ? 0 : 1;
}
