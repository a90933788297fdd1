// SPDX-License-Identifier: MIT
// satviz-bench --world: milliseconds per step of satviz's rigid-body world beside Box2D 2.4.1's b2World on the same
// scenes in the same process, what each of the world's savings saves, and the penetration and energy drift of both.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace satviz::bench
{

/// What satviz-bench --world runs.
struct WorldBenchSettings
{
    std::vector<std::string> scenes = {"pile", "rain"}; ///< which scenes run: "pile", "rain"
    std::vector<int> bodies = {100, 1000, 10000};       ///< dynamic bodies of each scene (each scene at each size)
    int steps = 600;                                    ///< steps of 1/60 per run; the last quarter is the settled tail
    int rounds = 5;                                     ///< timed rounds; a figure is the median over the rounds
    uint64_t seed = 20240601;                           ///< seed of the scenes' shapes and placements
    /// Threads satviz's world steps on (its default task pool, satviz/tasks.h), the caller's included. Above 1,
    /// satviz's figures are by the wall clock, the processor time of one thread no longer being its cost.
    int threads = 1;
    /// satviz steps with the soft step (WorldSettings::softStep) in every configuration, timed and measured.
    bool softStep = false;
    bool quick = false;       ///< set by QuickWorldBenchSettings: the figures are no measurement
    std::string csvDirectory; ///< where world.csv is written; empty: nowhere
};

/// Above this many bodies the world is not timed with its broadphase off, nor with every moving body swept: the
/// first gives every pair to the narrowphase, n (n - 1) / 2 of them per step (5e7 at 10 000 bodies); the second
/// sweeps every moving body against its neighbours again after each of their hits, and already takes about 100
/// times the default's step at 1000 bodies. Both run in the first round only: their ratios are far from 1.
constexpr int kWorldCostlyLimit = 1000;

/// Empty when the settings can be run, else a one-line reason naming the option ("--bodies: ...").
std::string CheckWorldBenchSettings(const WorldBenchSettings& settings);

/// The settings of --quick: two small scenes, few steps, one round, so that a run takes a second or two.
WorldBenchSettings QuickWorldBenchSettings(WorldBenchSettings settings);

/// Writes each scene of the settings (each scene at each size, settings.seed) as a scene file DIR/SCENE-N.json that
/// satviz-sim steps as the benchmark does (its bodies, materials, gravity and dt), for timing a whole process.
/// Returns false with a one-line error naming the file when one cannot be written.
bool WriteWorldScenes(const WorldBenchSettings& settings, const std::string& directory, std::string& error);

/// Builds the scenes, runs them and prints the tables to stdout (progress to stderr), and writes world.csv into
/// settings.csvDirectory when it is set. Returns false when the CSV file could not be written.
bool RunWorldBench(const WorldBenchSettings& settings);

} // namespace satviz::bench
