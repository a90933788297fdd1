// SPDX-License-Identifier: MIT
// satviz-v3-profile: steps the bodies of a scene file (as satviz-bench --world --write-scenes writes them) in Box2D
// v3, as satviz-bench --world does (density 1, friction 0.6, restitution 0.1, gravity 10, 4 sub-steps), and prints
// v3's own profile (b2World_GetProfile), each stage's mean ms per step: where v3's time goes on the same scene as
// satviz's. Built only with SATVIZ_BOX2D_V3_ROOT, beside satviz-bench.
#include "box2d_v3.h"

#include <satviz/scene.h>
#include <satviz/scene_world.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 4)
    {
        std::fprintf(stderr, "usage: satviz-v3-profile SCENE.json [STEPS (default 600)] [WORKERS (default 1)]\n");
        return 2;
    }
    const int steps = argc > 2 ? std::atoi(argv[2]) : 600;
    const int workers = argc > 3 ? std::atoi(argv[3]) : 1;
    if (steps < 1 || workers < 1)
    {
        std::fprintf(stderr, "satviz-v3-profile: STEPS and WORKERS must be at least 1\n");
        return 2;
    }
    const satviz::SceneResult loaded = satviz::LoadScene(argv[1]);
    if (!loaded.Ok())
    {
        std::fprintf(stderr, "satviz-v3-profile: %s\n", loaded.error.c_str());
        return 1;
    }
    const satviz::World scene = satviz::MakeWorld(loaded.scene);
    std::vector<satviz::bench::V3Body> bodies;
    for (const satviz::RigidBody& body : scene.bodies)
    {
        satviz::bench::V3Body b;
        b.shape = body.shape;
        b.dynamic = body.type == satviz::BodyType::Dynamic;
        b.position = body.position;
        b.angle = body.angle;
        b.velocity = body.velocity;
        b.angularVelocity = body.angularVelocity;
        bodies.push_back(b);
    }
    satviz::bench::V3Settings settings; // the benchmark's materials, gravity, step and sub-steps
    settings.workers = workers;
    satviz::bench::Box2DV3World world(bodies, settings);
    std::vector<std::pair<std::string, double>> sum;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k)
    {
        world.Step();
        const std::vector<std::pair<std::string, double>> stages = world.LastStepProfile();
        sum.resize(stages.size());
        for (size_t i = 0; i < stages.size(); ++i)
        {
            sum[i].first = stages[i].first;
            sum[i].second += stages[i].second;
        }
    }
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %d steps, %d worker(s), %.1f ms by the wall clock (%.3f ms per step)\n", argv[1], steps, workers,
                wall, wall / steps);
    for (const auto& [name, ms] : sum)
    {
        std::printf("%-20s %8.3f ms/step %6.1f %%\n", name.c_str(), ms / steps, 100.0 * ms / sum.front().second);
    }
    return 0;
}
