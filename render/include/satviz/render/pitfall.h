// SPDX-License-Identifier: MIT
// satviz render: the classic SAT mistakes, run beside the right answer so that a view can show what goes wrong.
// Each is a documented variant computed here for the picture; the library's queries never take it.
#pragma once

#include <satviz/scene.h>

#include <string>
#include <string_view>

namespace satviz
{

/// What the mistaken algorithm answers for a pair.
struct PitfallResult
{
    bool ran = false;     ///< the pitfall applies to this pair (polygons; sampling: a moving pair)
    bool overlap = false; ///< its yes or no
    double depth = 0.0;   ///< its MTV length (when overlap)
    Vec2 normal{};        ///< its MTV direction (when overlap): the way it would push B
    std::string verdict;  ///< one sentence: what it answers and how that differs from the right answer
};

/// Runs the mistaken algorithm on bodies a and b of the scene. Polygons only (circles: ran is false), except
/// sampling, which takes any moving pair.
PitfallResult RunPitfall(Pitfall pitfall, const Scene& scene, int a, int b);

} // namespace satviz
