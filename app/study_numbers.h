// SPDX-License-Identifier: MIT
// satviz app: the numbers of the static test that the Numbers panel lists, in the words and the decimals of the
// figures, the step sentences and the lessons.
#pragma once

#include <satviz/layers.h>
#include <satviz/render/study.h>

#include <string>
#include <vector>

namespace satviz
{

/// One line of the Numbers panel: what the number is, and one value or a point's two coordinates.
struct NumberRow
{
    std::string label;              ///< "deciding axis 4, the normal of B's edge 3"
    std::vector<std::string> parts; ///< one value, or a point's x and y, as the sentences print them (FormatNumber)
};

/// A number of the panel: as the sentences and the figures print it (FormatNumber), or with `allDigits` as the
/// shortest decimal that reads back as the same value (FullDecimal; as a float in a single-precision study), for a
/// student comparing digits far down (lesson 11).
std::string PanelNumber(double value, const PairStudy& study, bool allDigits);

/// A point's two coordinates: as the sentences print a pair (FormatPair: "-0.342" and "0.940", not "0.94"), or with
/// `allDigits` each as PanelNumber gives it.
std::vector<std::string> PanelPair(Vec2 p, const PairStudy& study, bool allDigits);

/// The static test's numbers, as the sentences and the figures print them (FormatNumber, FormatPair, the verdict's
/// ShownVerdictAmount), so that a number in the panel and the same number in the step's sentence read alike: overlap or
/// not, the depth or the gap, the deciding axis as the figure draws it and the lessons' tables list it (the outward
/// normal of the face that names it, the direction satviz-query's trace gives), the normal from A to B (satviz-query's
/// "normal"; against the axis when that is a face of B), and the contact points c1, c2. With `allDigits`, every number
/// as PanelNumber gives it with all its digits. The contact points are listed only when `layers` has the contacts
/// layer, which draws them, and not beside a sweep, whose figure draws its contacts at the time of impact (c1, c2)
/// and none at t = 0: the panel lists no point the picture leaves out.
std::vector<NumberRow> StaticTestNumbers(const Scene& scene, const PairStudy& study, bool allDigits = false,
                                         LayerMask layers = kAllLayers);

/// The heading of the static test's numbers when they stand alone (no sweep): they are the verdict's, the test's
/// answer, at whichever step the list shows, so that "overlap: yes" or a gap is not read as the axis stepped to.
std::string StaticHeading();

/// The heading of a sweep's numbers, naming what t from 0 to 1 covers as the verdict does (SweptSpan): the step, or
/// in a world's scene one second, whose velocities are per second, not one step of the world.
std::string SweepHeading(const Scene& scene);

/// The line of a sweep's numbers when nothing is hit: "no hit during the step" or "during the swept second", as the
/// verdict says it.
std::string SweepMissLine(const Scene& scene);

} // namespace satviz
