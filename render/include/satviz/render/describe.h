// SPDX-License-Identifier: MIT
// satviz render: the words of a figure: what each step of a trace found, with its numbers.
#pragma once

#include <satviz/render/study.h>

#include <string>

namespace satviz
{

/// A number as figures show it: two decimals for ordinary magnitudes, three significant digits otherwise.
std::string FormatNumber(double value);

/// The shortest decimal that reads back as the same double (0.4825, not 0.48249999999999998): for the panels that
/// show a number in full.
std::string ShortestDecimal(double value);

/// The shortest decimal that reads back as the same float.
std::string ShortestDecimal(float value);

/// Where an axis comes from, in words: "normal of B's edge 1", "from pentagon's vertex 2 to ball's centre".
std::string DescribeAxis(const Scene& scene, const PairStudy& study, const AxisRef& axis);

/// The caption of a step, one or two plain sentences with the step's numbers, e.g. "Axis 3 of 8: normal of B's
/// edge 1. Intervals [0.10, 1.32] and [1.20, 2.05] overlap by 0.12."
std::string DescribeStep(const Scene& scene, const PairStudy& study, int step);

/// A short title of a step for lists: "3: B edge 1, overlap 0.12", or "verdict: collide, depth 0.12".
std::string StepTitle(const Scene& scene, const PairStudy& study, int step);

} // namespace satviz
