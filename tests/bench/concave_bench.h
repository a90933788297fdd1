// SPDX-License-Identifier: MIT
// satviz-bench --concave: the convex decomposition's time and piece count per method against the vertex count, and
// the concave pair queries against the same pieces tested all against all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace satviz::bench
{

/// What satviz-bench --concave runs.
struct ConcaveBenchSettings
{
    /// Vertex counts of the outlines decomposed by Fast.
    std::vector<int> fastVertices = {10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000};
    /// Vertex counts decomposed by Fewest (at most kFewestMaxVertices: above it Fewest gives Fast's result).
    std::vector<int> fewestVertices = {10, 20, 30, 50, 70, 100};
    /// Vertex counts of the concave pairs whose queries are timed.
    std::vector<int> pairVertices = {10, 30, 100, 300, 1000};
    int outlines = 8;         ///< random outlines per vertex count (their piece counts are averaged)
    int pairs = 200;          ///< pairs per vertex count for the queries
    int rounds = 5;           ///< timed rounds; a figure is the median over the rounds
    uint64_t seed = 20240601; ///< seed of the outlines and placements
    bool quick = false;       ///< set by QuickConcaveBenchSettings: the figures are no measurement
};

/// Empty when the settings can be run, else a one-line reason naming the option.
std::string CheckConcaveBenchSettings(const ConcaveBenchSettings& settings);

/// The settings of --quick: small outlines, few pairs, one round, so that a run takes a second or two.
ConcaveBenchSettings QuickConcaveBenchSettings(ConcaveBenchSettings settings);

/// Decomposes and queries, and prints the tables to stdout (progress to stderr).
void RunConcaveBench(const ConcaveBenchSettings& settings);

} // namespace satviz::bench
