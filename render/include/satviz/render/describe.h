// SPDX-License-Identifier: MIT
// satviz render: the words of a figure: what each step of a trace found, with its numbers.
#pragma once

#include <satviz/render/study.h>

#include <string>
#include <utility>
#include <vector>

namespace satviz
{

/// A number as figures show it: three decimals (two when the third is 0) for magnitudes from 0.01 to 1e9, three
/// significant digits otherwise, exponents as written (1.41e6), never -0, and an exact 0 as 0.00; a whole number of
/// five digits or more in groups of three without decimals, as the lessons write it ("100 000", not "100000.00").
std::string FormatNumber(double value);

/// FormatNumber with at least `significant` (up to 3) significant digits: from 0.01 to 0.1, where its three
/// decimals give fewer (0.0102 shows as 0.01), four decimals, so that a sentence that multiplies small numbers can
/// be checked by hand from the numbers it prints (0.50 x 0.0102 = 0.0051). Otherwise the same as FormatNumber(value).
std::string FormatNumber(double value, int significant);

/// A number a label shows (a speed beside its arrow): FormatNumber, so that a label, a sentence and a panel write a
/// number alike.
std::string FormatLabelNumber(double value);

/// Two numbers as FormatNumber shows them, written side by side with as many decimals each: "(-0.342, 0.940)", not
/// "(-0.342, 0.94)". Only the trailing 0 FormatNumber drops is put back, so the values read the same.
std::string FormatPair(double x, double y, const char* open = "(", const char* close = ")");

/// Numbers that are read together (the ends of the intervals on one number line) as FormatNumber shows them, each
/// written with as many decimals as the one with most: 0.000, 2.080, 3.051, not 0.00, 2.08, 3.051. Only the
/// trailing zeros FormatNumber drops are put back, so the values read the same; numbers with an exponent are left
/// as they are. A whole number FormatNumber groups (999 999) is written as the others when they have decimals
/// (999999.00 beside 1000000.90), not in a form of its own.
std::vector<std::string> FormatAlike(const std::vector<double>& values);

/// Two times read together, an entry and an exit, written as FormatAlike writes them when both are finite: "0.610"
/// and "2.253", not "0.61" and "2.253". An infinite one is left as FormatNumber writes it ("inf", "-inf"), for the
/// caller to word ("the start", "never"), and the other as FormatNumber writes it alone.
std::pair<std::string, std::string> FormatTimes(double entry, double exit);

/// hi - lo computed from the two values as FormatNumber shows them, so that a reader subtracting the printed ends
/// gets the printed difference. Where the ends are too small or too large for that (beyond 1e5, their own rounding
/// dominates), `exact` is shown instead: the value the algorithm computed (NaN: hi - lo).
std::string ShownDifference(double hi, double lo, double exact);

/// Whether a face test measures from B: its axis is a face (or a vertex's axis) of B, so the band on its number line
/// runs from B's far end to A's near end. Every other test, the line of centres included, measures from A.
bool MeasuredFromB(const AxisRef& axis);

/// The band between two intervals as the figures print it, from the shown ends: from `lead`, the far end of the
/// shape measured from, to `other`, the other shape's near end, whose difference is `separation` (a gap when
/// positive, else an overlap, or a depth behind a face, of -separation). The number line, the caption and the step
/// list all give this number.
std::string ShownBand(double lead, double other, double separation);

/// A textbook axis's overlap as the figures print it: the shorter push, from the shown interval ends.
std::string ShownOverlap(const TextbookAxis& axis);

/// A textbook axis's gap as the figures print it, from the shown interval ends.
std::string ShownGap(const TextbookAxis& axis);

/// The depth (shapes that overlap) or the gap (apart) of a static test's verdict as its sentence and the step list
/// print it: the difference of the deciding axis's shown interval ends, so that a panel listing it agrees with them.
std::string ShownVerdictAmount(const PairStudy& study);

/// True when a static test's verdict amount (the depth of shapes that overlap, the gap of shapes apart) is not 0
/// but of the size of round-off (within 1e-12 of the coordinates on the deciding axis): shapes that touch on paper
/// and that the stored numbers leave 1e-17 apart or overlapping. The words call them touching, as the verdict
/// calls touching shapes (overlapping with depth 0), and give the amount as the numbers have it.
bool RoundOffVerdict(const PairStudy& study);

/// The shortest decimal that reads back as the same double (0.4825, not 0.48249999999999998): for the panels that
/// show a number in full.
std::string ShortestDecimal(double value);

/// The shortest decimal that reads back as the same float.
std::string ShortestDecimal(float value);

/// A number in full for a panel: ShortestDecimal with at least two decimals, as the figures and the lessons write
/// them (0.80, -1.10, 0.00, and 0.20000000000000018 as it is), so that a panel's number reads as the lesson's; a
/// number written with an exponent stays as ShortestDecimal writes it. Reads back as the same double.
std::string FullDecimal(double value);

/// The same for a float: reads back as the same float.
std::string FullDecimal(float value);

/// Where an axis comes from, in words: "normal of B's edge 1", "from pentagon's vertex 2 to ball's centre".
std::string DescribeAxis(const Scene& scene, const PairStudy& study, const AxisRef& axis);

/// What a step is called, as its caption begins and the app's step controls name it: "Axis 3 of 8" (textbook),
/// "Face test 2 of 8" or "Test 9 of 9" (a circle's axis, along no face) in the face tests, without the count in a
/// sweep, "Verdict" for the verdict; empty for a step that does not exist.
std::string StepName(const Scene& scene, const PairStudy& study, int step);

/// What a sweep's t from 0 to 1 covers in `scene`, as the verdicts name it: "the step" (a scene without a world,
/// where a velocity is the displacement over a step, or a world that counts time in steps, dt = 1), else "the swept
/// second" (a world's velocities are per second, and its figures sweep them over one second, many steps of dt).
std::string SweptSpan(const Scene& scene);

/// The caption of a step, one or two plain sentences with the step's numbers, e.g. "Axis 3 of 8: normal of B's
/// edge 1. Intervals [0.10, 1.32] and [1.20, 2.05] overlap by 0.12." With countContacts false the verdict leaves out
/// its count of contact points, for a picture that does not draw them.
std::string DescribeStep(const Scene& scene, const PairStudy& study, int step, bool countContacts = true);

/// A short title of a step for lists: "3: B edge 1, overlap 0.12", or "verdict: collide, MTV 0.12" ("verdict:
/// touching, MTV zero" for shapes in contact that do not overlap, as the verdict's sentence says).
std::string StepTitle(const Scene& scene, const PairStudy& study, int step);

} // namespace satviz
