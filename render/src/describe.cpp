// SPDX-License-Identifier: MIT
#include <satviz/render/describe.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace satviz
{

namespace
{

// Interval ends up to this magnitude are subtracted as shown; beyond it, their rounding dominates (see
// ShownDifference).
constexpr double kShownEnds = 1e5;

const std::string& NameOf(const Scene& scene, const PairStudy& study, int shape)
{
    return scene.bodies[static_cast<size_t>(shape == 0 ? study.bodyA : study.bodyB)].name;
}

std::string Possessive(const std::string& name)
{
    return name + "'s";
}

std::string Pair(double x, double y)
{
    return FormatPair(x, y);
}

// Number of face tests the fast test could run: every face of a polygon, one axis per circle pair.
int CandidateCount(const Scene& scene, const PairStudy& study)
{
    const Shape& a = scene.bodies[static_cast<size_t>(study.bodyA)].shape;
    const Shape& b = scene.bodies[static_cast<size_t>(study.bodyB)].shape;
    const int faces =
        (a.type == ShapeType::Polygon ? a.polygon.Count() : 0) + (b.type == ShapeType::Polygon ? b.polygon.Count() : 0);
    return (a.type == ShapeType::Circle || b.type == ShapeType::Circle) ? faces + 1 : faces;
}

// A value as the figures print it, rounded to what they show, so that differences of shown numbers add up.
double Shown(double value)
{
    const std::string text = FormatNumber(value);
    return std::strtod(text.c_str(), nullptr);
}

} // namespace

std::string ShownDifference(double hi, double lo, double exact)
{
    const double a = Shown(hi);
    const double b = Shown(lo);
    // Far from the origin the ends carry the rounding of their magnitude (float: steps of 0.0625 at 1e6), and their
    // difference is no longer the algorithm's: there the value it computed, in A's frame, is shown.
    auto fixed = [](double v) { return v == 0.0 || (std::fabs(v) >= 0.01 && std::fabs(v) < kShownEnds); };
    const bool sameBand = std::isfinite(a) && std::isfinite(b) && fixed(hi) && fixed(lo) && std::fabs(a - b) >= 0.01;
    return FormatNumber(sameBand ? a - b : (std::isnan(exact) ? hi - lo : exact));
}

bool MeasuredFromB(const AxisRef& axis)
{
    return axis.shape == 1 && axis.kind != AxisKind::CenterToCenter;
}

std::string ShownBand(double lead, double other, double separation)
{
    return separation > 0.0 ? ShownDifference(other, lead, separation) : ShownDifference(lead, other, -separation);
}

namespace
{

std::string Difference(double hi, double lo)
{
    return ShownDifference(hi, lo, hi - lo);
}

// How far the other shape lies beyond or behind a face test's face, as the band on its number line shows it: the
// difference of the interval ends as printed (the face's shape's far end, the other shape's near end), so that a
// reader subtracting the printed ends gets this number, and the sentence says what the band says.
std::string ShownSeparation(const AxisTest& t)
{
    const bool fromB = MeasuredFromB(t.axis);
    return ShownBand(fromB ? t.maxB : t.maxA, fromB ? t.minA : t.minB, t.separation);
}

// The face test a static verdict rests on: the separating one (the last tested), or the one whose separation is the
// MTV's depth; null when there is none to show.
const AxisTest* VerdictTest(const PairStudy& study)
{
    const std::vector<AxisTest>& axes = study.trace.axes;
    const Manifold& m = study.manifold;
    if (!m.overlap)
    {
        return !axes.empty() && axes.back().separating ? &axes.back() : nullptr;
    }
    for (const AxisTest& t : axes)
    {
        if (!t.skipped && t.axis.kind == m.axis.kind && t.axis.shape == m.axis.shape && t.axis.index == m.axis.index &&
            t.separation == -m.depth)
        {
            return &t;
        }
    }
    return nullptr;
}

// The gap or the depth of a static verdict as the figure shows it: its face test's band, else the value itself.
std::string VerdictAmount(const PairStudy& study)
{
    const AxisTest* t = VerdictTest(study);
    if (t != nullptr)
    {
        return ShownSeparation(*t);
    }
    return FormatNumber(study.manifold.overlap ? study.manifold.depth : study.manifold.gap);
}

} // namespace

std::string ShownVerdictAmount(const PairStudy& study)
{
    if (study.Textbook() && study.textbookResult.axis >= 0 &&
        static_cast<size_t>(study.textbookResult.axis) < study.textbook.axes.size())
    {
        const TextbookAxis& t = study.textbook.axes[static_cast<size_t>(study.textbookResult.axis)];
        return study.textbookResult.overlap ? ShownOverlap(t) : ShownGap(t);
    }
    if (study.manifold.overlap && study.manifold.depth == 0.0)
    {
        return FormatNumber(0.0);
    }
    return VerdictAmount(study);
}

bool RoundOffVerdict(const PairStudy& study)
{
    if (study.sweep)
    {
        return false;
    }
    double amount = study.manifold.overlap ? study.manifold.depth : study.manifold.gap;
    double scale = 1.0;
    if (study.Textbook() && study.textbookResult.axis >= 0 &&
        static_cast<size_t>(study.textbookResult.axis) < study.textbook.axes.size())
    {
        const TextbookAxis& t = study.textbook.axes[static_cast<size_t>(study.textbookResult.axis)];
        amount = study.textbookResult.overlap ? study.textbookResult.depth : study.textbookResult.gap;
        scale = std::max({scale, std::fabs(t.minA), std::fabs(t.maxA), std::fabs(t.minB), std::fabs(t.maxB)});
    }
    else if (!study.Textbook() && !study.trace.axes.empty())
    {
        // The face view measures against the same size: the projections on the deciding face's normal (the best
        // face tested, or the one that separated).
        const AxisTest& last = study.trace.axes.back();
        const AxisTest& t = last.separating || last.best < 0 || static_cast<size_t>(last.best) >= study.trace.axes.size()
                                ? last
                                : study.trace.axes[static_cast<size_t>(last.best)];
        scale = std::max({scale, std::fabs(t.minA), std::fabs(t.maxA), std::fabs(t.minB), std::fabs(t.maxB)});
    }
    return amount != 0.0 && std::fabs(amount) <= 1e-12 * scale;
}

// After a verdict whose amount is round-off (RoundOffVerdict): the shapes touch, in words, and the amount is the
// stored numbers'.
static std::string RoundOffNote(const PairStudy& study)
{
    if (!RoundOffVerdict(study))
    {
        return "";
    }
    const bool overlap = study.Textbook() ? study.textbookResult.overlap : study.manifold.overlap;
    const std::string amount = ShownVerdictAmount(study);
    return overlap ? " An overlap of " + amount + " is round-off in size: the shapes touch (touching counts as "
                                                  "overlapping with depth 0), and the stored numbers overlap by that "
                                                  "much."
                   : " A gap of " + amount + " is round-off in size: the shapes touch (touching counts as overlapping "
                                             "with depth 0), though the stored numbers keep them that far apart.";
}

namespace
{

std::string Time(double t)
{
    return std::isinf(t) ? (t > 0 ? "never" : "always") : "t = " + FormatNumber(t);
}

// Two times a sentence gives together ("from t = 0.610 until t = 2.253"), with as many decimals each as its row
// and its time bar write them (FormatTimes); an infinite one as Time words it.
std::pair<std::string, std::string> Times(double a, double b)
{
    const auto [x, y] = FormatTimes(a, b);
    return {std::isinf(a) ? Time(a) : "t = " + x, std::isinf(b) ? Time(b) : "t = " + y};
}

// The span a sweep covers, t from 0 to 1: one step of a scene without a world, where a velocity is the displacement
// over a step; one second of a world's scene, whose velocities are in units per second and whose figures sweep them
// over a second (many steps of dt). A world that counts time in steps (dt = 1) says "step", as its lesson does.
bool SweepsSteps(const Scene& scene)
{
    return !scene.hasWorld || scene.world.dt == 1.0;
}

} // namespace

std::string SweptSpan(const Scene& scene)
{
    return SweepsSteps(scene) ? "the step" : "the swept second";
}

namespace
{

// How far an interval moves over the swept span, in the same words.
std::string PerSpan(const Scene& scene)
{
    return SweepsSteps(scene) ? "per step" : "per second";
}

// What the static test at t = 0 found, for a sweep it decides (nothing moves): the gap or the depth as the Numbers
// panel and the static verdict print them.
std::string StaticAtStart(const PairStudy& study)
{
    const bool overlap = study.Textbook() ? study.textbookResult.overlap : study.manifold.overlap;
    const std::string amount = ShownVerdictAmount(study);
    if (!overlap)
    {
        return "it finds them apart, with a gap of " + amount + " that nothing closes";
    }
    return amount == FormatNumber(0.0) ? "it finds them touching without overlapping, and touching is not a hit"
                                       : "it finds them overlapping by " + amount;
}

std::string SweepExitReason(const Scene& scene, const PairStudy& study, SweepExit exit)
{
    switch (exit)
    {
    case SweepExit::NotMoving:
        return "nothing moves relative to the other, so the static test at t = 0 decides: " + StaticAtStart(study);
    case SweepExit::NeverCloses:
        return "on this axis the intervals never overlap during " + SweptSpan(scene) + ", so the shapes cannot interpenetrate";
    case SweepExit::EntryAfterStep:
        return "the intervals would only meet after " + SweptSpan(scene) + " ends";
    case SweepExit::EntryAfterExit:
        return "one axis parts before another meets, so they never overlap on all axes at once";
    case SweepExit::AllAxesOverlap:
        return "every axis overlaps during a common span of time";
    case SweepExit::RoundedOutline:
        return "the circle's centre was cast against the other shape's rounded outline";
    case SweepExit::None:
        break;
    }
    return "the test ended";
}

// What precision the numbers carry, said where it matters: a pair far from the origin, or the float queries.
std::string PrecisionNote(const Scene& scene, const PairStudy& study)
{
    const Body& a = scene.bodies[static_cast<size_t>(study.bodyA)];
    const Body& b = scene.bodies[static_cast<size_t>(study.bodyB)];
    const double distance = std::max(Length(a.position), Length(b.position));
    const double coordinate =
        std::max({std::fabs(a.position.x), std::fabs(a.position.y), std::fabs(b.position.x), std::fabs(b.position.y)});
    const float far = static_cast<float>(coordinate);
    const std::string floatStep = ShortestDecimal(std::nextafter(far, INFINITY) - far);
    if (study.singlePrecision)
    {
        std::string text = " These numbers come from the float queries (about 7 significant digits)";
        return distance >= 1e4 ? text + ": a float coordinate as large as " + FormatNumber(coordinate) +
                                     " moves in steps of " + floatStep + "."
                               : text + ".";
    }
    if (distance < 1e4)
    {
        return "";
    }
    return " The pair lies " + FormatNumber(distance) + " from the origin. The queries run in double (about 16 " +
           "significant digits) in A's frame, so they decide as they would at the origin; in float, coordinates " +
           "this large (" + FormatNumber(coordinate) + ") move in steps of " + floatStep + ".";
}

// The view's pitfall, said after the right verdict.
std::string PitfallNote(const PairStudy& study)
{
    return study.pitfall.verdict.empty() ? "" : " " + study.pitfall.verdict;
}

// "the normal of floor's edge 2 (floor's edge 0 and box's edges 0 and 2 are parallel to that edge)": one axis, many
// faces.
std::string DescribeFaces(const Scene& scene, const PairStudy& study, const AxisRef* faces, int count)
{
    std::string text = DescribeAxis(scene, study, faces[0]);
    if (count <= 1)
    {
        return text;
    }
    // The other faces on the line, grouped by shape: "floor's edge 2", "box's edges 0 and 2".
    std::string others;
    for (int shape = 0; shape < 2; ++shape)
    {
        std::vector<int> edges;
        for (int f = 1; f < count; ++f)
        {
            if (faces[f].kind == AxisKind::FaceNormal && faces[f].shape == shape)
            {
                edges.push_back(faces[f].index);
            }
        }
        if (edges.empty())
        {
            continue;
        }
        std::string list;
        for (size_t e = 0; e < edges.size(); ++e)
        {
            list += (e == 0 ? "" : e + 1 == edges.size() ? " and " : ", ") + std::to_string(edges[e]);
        }
        others += (others.empty() ? "" : " and ") + Possessive(NameOf(scene, study, shape)) +
                  (edges.size() == 1 ? " edge " : " edges ") + list;
    }
    // Parallel to the face that names the axis, so their normals share its line.
    const std::string relation =
        faces[0].kind == AxisKind::FaceNormal ? " parallel to that edge)" : " on the same line)";
    return others.empty() ? text : text + " (" + others + (count == 2 ? " is" : " are") + relation;
}

std::string TextbookAxisStep(const Scene& scene, const PairStudy& study, int step)
{
    const TextbookAxis& t = study.textbook.axes[static_cast<size_t>(step)];
    const std::string& nameA = NameOf(scene, study, 0);
    const std::string& nameB = NameOf(scene, study, 1);
    // A's name begins a sentence here: capitalised, as a textbook would ("... edge 2. Floor projects to ...").
    std::string sentenceA = nameA;
    if (!sentenceA.empty() && sentenceA[0] >= 'a' && sentenceA[0] <= 'z')
    {
        sentenceA[0] = static_cast<char>(sentenceA[0] - 'a' + 'A');
    }
    // The four ends as the number line writes them, read together with as many decimals each (FormatAlike).
    const std::vector<std::string> ends = FormatAlike({t.minA, t.maxA, t.minB, t.maxB});
    std::string text = StepName(scene, study, step) + ": " + DescribeFaces(scene, study, t.faces, t.faceCount) +
                       ". " + sentenceA + " projects to [" + ends[0] + ", " + ends[1] + "], " + nameB + " to [" +
                       ends[2] + ", " + ends[3] + "]. ";
    if (t.separating)
    {
        return text + "Gap " + ShownGap(t) +
               " between them: this axis separates the shapes, so they do not collide and the test stops here.";
    }
    const std::string along = Difference(t.maxA, t.minB);
    const std::string against = Difference(t.maxB, t.minA);
    return text + "They overlap: " + nameB + " would have to move " + along + " along the axis or " + against +
           " against it to clear " + nameA + "; the overlap is the smaller, " + (t.pushSign > 0 ? along : against) +
           ".";
}

// The face that names a textbook axis (faces[0]: the reference face where the shapes meet, else the face turned
// towards the other shape, as StudyPair and the test choose it), when it is turned towards the other shape
// (`towardB`: from A's interval to B's on the axis). Kind None when no face on the axis is (a circle's axis).
AxisRef FacingFace(const Scene& scene, const PairStudy& study, const AxisRef* faces, int count, Vec2 towardB)
{
    if (count < 1 || faces[0].kind != AxisKind::FaceNormal)
    {
        return AxisRef{};
    }
    const AxisRef& face = faces[0];
    const Body& body = scene.bodies[static_cast<size_t>(face.shape == 0 ? study.bodyA : study.bodyB)];
    const double facing = Dot(Rotate(body.Xf().q, body.shape.polygon.Normal(face.index)), towardB);
    return (face.shape == 0 ? facing > 0.0 : facing < 0.0) ? face : AxisRef{};
}

// "floor's edge 3"
std::string FaceName(const Scene& scene, const PairStudy& study, const AxisRef& face)
{
    return Possessive(NameOf(scene, study, face.shape)) + " edge " + std::to_string(face.index);
}

std::string TextbookVerdict(const Scene& scene, const PairStudy& study, bool countContacts)
{
    const TextbookResult& r = study.textbookResult;
    const std::string& nameA = NameOf(scene, study, 0);
    const std::string& nameB = NameOf(scene, study, 1);
    if (r.axis < 0)
    {
        return "Verdict: no axis could be tested.";
    }
    const TextbookAxis& t = study.textbook.axes[static_cast<size_t>(r.axis)];
    const std::string axis = "axis " + std::to_string(r.axis + 1);
    // The face named is the one the picture marks and the number line is measured along: where the shapes meet
    // (the reference face), or, apart, the face turned towards the other shape.
    const bool bAhead = t.separating ? t.minB - t.maxA > 0.0 : t.pushSign > 0;
    const AxisRef face = FacingFace(scene, study, t.faces, t.faceCount, bAhead ? t.direction : -t.direction);
    const bool named = face.kind == AxisKind::FaceNormal;
    if (!r.overlap)
    {
        if (named)
        {
            const std::string& other = face.shape == 0 ? nameB : nameA;
            return "Verdict: " + axis + " separates the shapes: " + other + " lies " + ShownGap(t) + " beyond " +
                   FaceName(scene, study, face) + ", so they do not collide. The test stopped after " +
                   std::to_string(r.axesTested) + " of " + std::to_string(r.axisCount) + " axes.";
        }
        return "Verdict: " + axis + " (" + DescribeAxis(scene, study, t.faces[0]) +
               ") separates the shapes with a gap of " + ShownGap(t) + ", so they do not collide. The test stopped "
               "after " +
               std::to_string(r.axesTested) + " of " + std::to_string(r.axisCount) + " axes.";
    }
    std::string text = study.startsOverlapping ? "The shapes already overlap at t = 0, so there is no time of "
                                                 "impact. "
                                               : "";
    const std::string where = named ? axis + ", at " + FaceName(scene, study, face)
                                    : axis + " (" + DescribeAxis(scene, study, t.faces[0]) + ")";
    // B moves along A's face's outward normal, or against B's own face's.
    const std::string way = named ? (face.shape == 0 ? "along" : "against") : (t.pushSign > 0 ? "along" : "against");
    const std::string depth = ShownOverlap(t);
    const std::string that = named ? "that face's normal" : "that axis";
    if (depth == "0.00")
    {
        // Touching: no move of 0 separates anything; the intervals meet end to end on the deciding axis.
        text += "Verdict: no axis has a gap, so the shapes are in contact. The smallest overlap is " + depth + ", on " +
                where +
                ": there the intervals meet end to end. The shapes touch without overlapping: the MTV is zero, "
                "direction " +
                Pair(r.normal.x, r.normal.y) + ".";
    }
    else
    {
        text += "Verdict: " +
                (r.axisCount == 1   ? std::string("the only axis overlaps")
                 : r.axisCount == 2 ? std::string("both axes overlap")
                                    : "all " + std::to_string(r.axisCount) + " axes overlap") +
                ", so the shapes collide. The smallest overlap is " + depth + ", on " + where + ": moving " + nameB +
                " " + depth + " " + way + " " + that + ", direction " + Pair(r.normal.x, r.normal.y) +
                ", separates them. That is the minimum translation vector (MTV).";
    }
    if (!countContacts)
    {
        return text;
    }
    const int contacts = study.manifold.contactCount;
    text += contacts == 1 ? " 1 contact point" : " " + std::to_string(contacts) + " contact points";
    const std::string halfway = contacts == 1 ? "halfway" : "each halfway";
    text += study.trace.hasClip ? ", clipped from the incident edge against the reference face, " + halfway +
                                      " between the two surfaces."
                                : ", " + halfway + " between the two surfaces.";
    return text;
}

// Why a textbook sweep's axis rules out a hit when the intervals never close: they stay apart (or only touch) and
// do not move, or their overlap lies wholly before the step and they move apart during it.
std::string NeverClosesReason(const Scene& scene, const TextbookSweepAxis& t)
{
    if (t.never)
    {
        const bool touching = std::max(t.minB - t.maxA, t.minA - t.maxB) == 0.0;
        return touching ? "on this axis the intervals only touch and do not move (touching is not a hit), so the "
                          "shapes cannot interpenetrate"
                        : "on this axis the intervals are apart and do not move, so the shapes cannot interpenetrate";
    }
    const auto [from, until] = Times(t.entry, t.exit);
    return "on this axis the intervals overlap only before " + SweptSpan(scene) + " (from " + from + " until " +
           until + ") and move apart during it, so the shapes cannot interpenetrate";
}

// Why a face of a face-test sweep rules out a hit: the other shape is beyond it or on it at t = 0 and does not
// approach. Only a shape on the face (separation 0) touches it; one beyond it and moving away was behind it only
// before the step.
std::string FaceNeverClosesReason(const Scene& scene, const std::string& other, const std::string& face,
                                  const SweepAxis& axis)
{
    const std::string span = SweptSpan(scene);
    const std::string cannot = ", so the shapes cannot interpenetrate";
    if (axis.separation > 0.0)
    {
        if (axis.rate > 0.0)
        {
            return other + " is beyond " + face + " at t = 0 and moves away from it (it was behind it only before " + span +
                   ", until " + Time(-axis.separation / axis.rate) +
                   "): the face separates the shapes during the whole of " + span +
                   cannot;
        }
        return other + " is beyond " + face + " and stays so: the face separates the shapes during the whole of " + span +
               cannot;
    }
    return other + (axis.rate > 0.0 ? " touches " + face + " at t = 0 and moves away from it"
                                    : " only touches " + face + " and does not move along its normal") +
           " (touching is not a hit)" + cannot;
}

// The reason a textbook sweep ended on axis `t`.
std::string TextbookExitReason(const Scene& scene, const PairStudy& study, const TextbookSweepAxis& t)
{
    const TextbookSweepTrace& trace = study.textbookSweep;
    return trace.exit == SweepExit::NeverCloses ? NeverClosesReason(scene, t) : SweepExitReason(scene, study, trace.exit);
}

std::string TextbookSweepAxisStep(const Scene& scene, const PairStudy& study, int step)
{
    const TextbookSweepAxis& t = study.textbookSweep.axes[static_cast<size_t>(step)];
    const std::string& nameA = NameOf(scene, study, 0);
    const std::string& nameB = NameOf(scene, study, 1);
    const std::vector<std::string> ends = FormatAlike({t.minA, t.maxA, t.minB, t.maxB});
    std::string text = StepName(scene, study, step) + ": " + DescribeFaces(scene, study, t.faces, t.faceCount) +
                       ". At t = 0 " + nameA + " projects to [" + ends[0] + ", " + ends[1] + "], " + nameB + " to [" +
                       ends[2] + ", " + ends[3] + "]; ";
    if (t.never)
    {
        const bool touching = std::max(t.minB - t.maxA, t.minA - t.maxB) == 0.0;
        text += nameB + "'s interval does not move along this axis and " +
                (touching ? "only touches " + nameA + "'s: they never overlap by more than " + FormatNumber(0.0) +
                                "."
                          : "never overlaps " + nameA + "'s.");
    }
    else if (t.rate == 0.0)
    {
        text += nameB + "'s interval does not move along this axis and overlaps " + nameA + "'s throughout.";
    }
    else
    {
        text += nameB + "'s interval moves " + FormatNumber(std::fabs(t.rate)) + " " + PerSpan(scene) + " " +
                (t.rate > 0.0 ? "along" : "against") + " the axis, so they overlap ";
        const auto [from, until] = Times(t.entry, t.exit);
        if (t.entry < 0.0 && t.exit > 0.0)
        {
            // The time bar marks that entry off its left end, "(before)": the sentence gives the same time.
            text += "from before the start (" + from + ") until " + until + ".";
        }
        else
        {
            text += "from " + from + " until " + until + ".";
        }
    }
    if (t.endsTest)
    {
        return text + " This ends the test: " + TextbookExitReason(scene, study, t) + ".";
    }
    if (t.latestEntry >= 0 && t.earliestExit >= 0 && step > 0)
    {
        const TextbookSweepAxis& entry = study.textbookSweep.axes[static_cast<size_t>(t.latestEntry)];
        const TextbookSweepAxis& exit = study.textbookSweep.axes[static_cast<size_t>(t.earliestExit)];
        const auto [from, until] = Times(entry.entry, exit.exit);
        text += " So far every axis overlaps from " + (std::isinf(entry.entry) ? std::string("the start") : from) +
                " until " + (std::isinf(exit.exit) ? std::string("the end") : until) + ".";
    }
    return text;
}

std::string TextbookSweepVerdict(const Scene& scene, const PairStudy& study)
{
    const TextbookSweepResult& r = study.textbookSweepResult;
    if (study.textbookSweep.exit == SweepExit::RoundedOutline)
    {
        // A circle's own axis (from the nearest vertex, or the other centre, to its centre) turns as it moves, so
        // fixed axes cannot time a hit on a corner: the exact test moves the centre against the other shape grown
        // by the radius.
        const std::string fixed =
            study.textbookSweep.axes.empty()
                ? "Two circles have no fixed axis: the line of centres turns as they move. So the test follows "
                  "the centre of one along its path against the other grown by its radius: "
                : "No fixed axis rules out a hit. The circle's own axis, from the polygon's nearest vertex to its "
                  "centre, turns as it moves, so the test follows the centre along its path against the polygon "
                  "grown by the radius (faces pushed out, corners rounded): ";
        if (r.status == SweepStatus::Hit)
        {
            std::string where;
            if (r.corner.kind == AxisKind::VertexToCenter)
            {
                where = " on the rounded corner at " + Possessive(NameOf(scene, study, r.corner.shape)) + " vertex " +
                        std::to_string(r.corner.index) + " (later than every fixed axis's entry: a corner delays it)";
            }
            else if (r.axis >= 0)
            {
                where = ", when it reaches a pushed-out face: axis " + std::to_string(r.axis + 1) + "'s entry time";
            }
            return "Verdict: " + fixed + "first contact at t = " + FormatNumber(r.toi) + where + ", normal " +
                   Pair(r.normal.x, r.normal.y) + ", from " + NameOf(scene, study, 0) + " to " +
                   NameOf(scene, study, 1) + ".";
        }
        return "Verdict: " + fixed +
               (r.status == SweepStatus::Overlapping ? "the shapes already overlap at t = 0."
                                                     : "the path misses it, so there is no hit during " + SweptSpan(scene) + ".");
    }
    if (r.status == SweepStatus::Hit)
    {
        const TextbookSweepAxis& last = study.textbookSweep.axes.back();
        const TextbookSweepAxis& exit = study.textbookSweep.axes[static_cast<size_t>(last.earliestExit)];
        return "Verdict: every axis overlaps from t = " + FormatNumber(r.toi) + " (the latest entry, axis " +
               std::to_string(r.axis + 1) + ") until " +
               (std::isinf(exit.exit) ? std::string("the end") : Time(exit.exit)) +
               " (the earliest exit): first contact at t = " + FormatNumber(r.toi) + ", normal " +
               Pair(r.normal.x, r.normal.y) + ", from " + NameOf(scene, study, 0) + " to " + NameOf(scene, study, 1) +
               ".";
    }
    if (r.status == SweepStatus::Overlapping)
    {
        return "Verdict: every axis overlaps already at t = 0: the shapes start interpenetrating.";
    }
    const TextbookSweepTrace& trace = study.textbookSweep;
    if (trace.exit == SweepExit::EntryAfterExit && !trace.axes.empty())
    {
        // Which axes: the one that parts, and the one that meets too late.
        const TextbookSweepAxis& last = trace.axes.back();
        if (last.latestEntry >= 0 && last.earliestExit >= 0)
        {
            const TextbookSweepAxis& entry = trace.axes[static_cast<size_t>(last.latestEntry)];
            const TextbookSweepAxis& exit = trace.axes[static_cast<size_t>(last.earliestExit)];
            const auto [meet, part] = Times(entry.entry, exit.exit);
            return "Verdict: no hit during " + SweptSpan(scene) + ": on axis " + std::to_string(last.earliestExit + 1) +
                   " the intervals part at " + part + ", before those of axis " +
                   std::to_string(last.latestEntry + 1) + " meet at " + meet +
                   ", so the shapes never overlap on all axes at once.";
        }
    }
    if (trace.exit == SweepExit::NeverCloses && trace.result.axis >= 0)
    {
        // "on this axis" names the axis: the verdict comes after every axis step.
        const std::string reason = NeverClosesReason(scene, trace.axes[static_cast<size_t>(trace.result.axis)]);
        return "Verdict: no hit during " + SweptSpan(scene) + ": on axis " + std::to_string(trace.result.axis + 1) +
               reason.substr(std::string("on this axis").size()) + ".";
    }
    return "Verdict: no hit during " + SweptSpan(scene) + ": " + SweepExitReason(scene, study, trace.exit) + ".";
}

// Where the count of FaceTestStep's "Face test 1 of N" comes from, in words that add up to it: one test per edge,
// each asking about one side of its edge, where the textbook test checks both sides of an axis at once (two boxes
// have 2 distinct axes and 8 face tests).
std::string FaceTestsCounted(const Scene& scene, const PairStudy& study)
{
    const Shape& a = scene.bodies[static_cast<size_t>(study.bodyA)].shape;
    const Shape& b = scene.bodies[static_cast<size_t>(study.bodyB)].shape;
    const std::string total = std::to_string(CandidateCount(scene, study));
    const std::string side = "a face test asks about one side of its edge only, where the textbook test checks both "
                             "sides of an axis at once";
    if (a.type == ShapeType::Circle && b.type == ShapeType::Circle)
    {
        return "Two circles have 1 test, along the line between their centres.";
    }
    if (a.type == ShapeType::Circle || b.type == ShapeType::Circle)
    {
        const int edges = a.type == ShapeType::Polygon ? a.polygon.Count() : b.polygon.Count();
        return "One face test per edge of the polygon, and one from its nearest vertex to the circle's centre: " +
               std::to_string(edges) + " + 1 = " + total + "; " + side + ".";
    }
    return "One face test per edge of both shapes: " + std::to_string(a.polygon.Count()) + " + " +
           std::to_string(b.polygon.Count()) + " = " + total + "; " + side +
           ". The face normals of both shapes are enough, since the MTV lies along one of them.";
}

std::string FaceTestStep(const Scene& scene, const PairStudy& study, int step)
{
    const AxisTest& test = study.trace.axes[static_cast<size_t>(step)];
    const bool face = test.axis.kind == AxisKind::FaceNormal;
    std::string text = StepName(scene, study, step) + ": ";
    const int owner = face ? test.axis.shape : 0;
    const std::string& own = NameOf(scene, study, owner);
    const std::string& other = NameOf(scene, study, 1 - owner);
    if (face)
    {
        text += "does " + other + " lie wholly beyond " + Possessive(own) + " edge " + std::to_string(test.axis.index) +
                "?";
    }
    else
    {
        text += DescribeAxis(scene, study, test.axis) + ": are the shapes apart along it?";
    }
    if (test.skipped)
    {
        return text + " This face is anti-parallel to face test " + std::to_string(test.duplicateOf + 1) +
               "'s face: the same axis, already decided, so it is skipped.";
    }
    if (test.separation > 0.0)
    {
        text += " Yes: " + ShownSeparation(test) + " beyond it, so this face's normal is a separating axis " +
                "and the test stops here.";
    }
    else
    {
        text += " No: " + (face ? Possessive(other) + " deepest point is " : std::string("they overlap by ")) +
                ShownSeparation(test) + (face ? " behind it." : ".");
    }
    if (test.pruned)
    {
        text += " Decided early: one vertex of the other shape already lies deeper behind this face than the best face "
                "so far, so it can neither separate the shapes nor give the MTV (its depth is shown for reference).";
    }
    if (step == 0)
    {
        text += " (" + FaceTestsCounted(scene, study) + ")";
    }
    return text;
}

std::string FaceTestVerdict(const Scene& scene, const PairStudy& study, bool countContacts)
{
    const Manifold& m = study.manifold;
    const std::string& nameB = NameOf(scene, study, 1);
    const int tested = static_cast<int>(study.trace.axes.size());
    std::string text = study.textbookTooLarge ? "(The textbook test would project every vertex on every axis, too "
                                                "many for a view of this pair: the face tests are shown.) "
                                              : "";
    if (!m.overlap)
    {
        // The gap as the number line shows it: the other shape's near end minus the face's shape's far end.
        const std::string gap = VerdictAmount(study);
        return text + "Verdict: " + DescribeAxis(scene, study, m.axis) + " separates the shapes by " + gap +
               ", so they do not collide. The test stopped after " + std::to_string(tested) + " of " +
               std::to_string(CandidateCount(scene, study)) + " face tests.";
    }
    if (study.startsOverlapping)
    {
        text += "The shapes already overlap at t = 0, so there is no time of impact. ";
    }
    const bool face = m.axis.kind == AxisKind::FaceNormal;
    const std::string way = face && m.axis.shape == 1 ? "against" : "along";
    // The depth as the deciding face test's band shows it; touching is a depth of exactly 0.
    const std::string depth = m.depth == 0.0 ? FormatNumber(m.depth) : VerdictAmount(study);
    if (m.depth == 0.0)
    {
        // Touching: the other shape reaches the face and not behind it.
        text += "Verdict: no face test separates, so the shapes are in contact. The face the other shape reaches "
                "least far behind is " +
                (face ? FaceName(scene, study, m.axis) : DescribeAxis(scene, study, m.axis)) +
                ", and only just: " + depth +
                " behind it. The shapes touch without overlapping: the MTV is zero, direction " +
                Pair(m.normal.x, m.normal.y) + ".";
    }
    else
    {
        // A face is named as a face (the picture marks it as the reference face), its normal as its normal.
        text += "Verdict: no face test separates, so the shapes collide. The face the other shape reaches least far "
                "behind is " +
                (face ? FaceName(scene, study, m.axis) : DescribeAxis(scene, study, m.axis)) + ": moving " + nameB +
                " by " + depth + " " + way + (face ? " its normal" : " it") + ", direction " +
                Pair(m.normal.x, m.normal.y) + ", separates them (the MTV).";
    }
    if (countContacts)
    {
        text += m.contactCount == 1 ? " 1 contact point." : " " + std::to_string(m.contactCount) + " contact points.";
    }
    return text;
}

// Where the other shape lies from a face at t = 0: "0.25 beyond this face", "0.1 behind this face".
std::string BeyondOrBehind(double separation)
{
    return separation > 0.0 ? FormatNumber(separation) + " beyond this face"
                            : FormatNumber(-separation) + " behind this face";
}

// How the other shape moves against a face over the step, from its separation at t = 0, its rate, entry and exit.
std::string SweepTimes(const SweepAxis& axis)
{
    if (axis.rate == 0.0)
    {
        return " and stays so (no motion along its normal).";
    }
    if (axis.separation > 0.0 && axis.rate > 0.0)
    {
        return " and moves away.";
    }
    const auto [from, until] = Times(axis.entry, axis.exit);
    return "; it is behind from " + (std::isinf(axis.entry) ? std::string("the start") : from) + " until " +
           (std::isinf(axis.exit) ? std::string("the end") : until) + ".";
}

// A face of a walked loop not walked to: what the bound of the other shape's vertex showed.
std::string BoundedFace(const std::string& other, const SweepAxis& axis)
{
    // The vertex's distance beyond the face bounds the gap between the projection intervals (or the overlap, from
    // below), so a bound in time follows from the rate.
    const std::string where =
        "a vertex of " + other + " already found lies " + BeyondOrBehind(axis.bound) + ", so " +
        (axis.bound > 0.0
             ? "the gap between the projection intervals on this axis is at most " + FormatNumber(axis.bound)
             : "the projection intervals on this axis overlap by at least " + FormatNumber(-axis.bound));
    const std::string rate = FormatNumber(std::fabs(axis.rate)) + " per step";
    const auto [bound, known] = Times(axis.boundTime, axis.knownEntry);
    if (axis.exitPass)
    {
        return "Second pass, for the exits, once the latest entry is known. Not walked to: " + where +
               ", and they move apart by " + rate + ": they part no earlier than " + bound +
               ", after the latest entry (" + known +
               "), so this face cannot part them before every axis overlaps.";
    }
    if (axis.bound < 0.0)
    {
        return "Not walked to: " + where +
               " from the start: this axis has no entry. Whether they part too early is checked in a second pass, "
               "once the latest entry is known.";
    }
    return "Not walked to: " + where + ", and it closes by " + rate + ", so the intervals meet by " +
           bound + " at the latest, before an entry already found (" + known +
           "): this face's entry cannot be the latest.";
}

// A face of a bisected loop never evaluated: why it cannot decide.
std::string SkippedFace(const SweepAxis& axis)
{
    const std::string text = "Not evaluated: bisection found the faces where the line of the motion enters and leaves "
                             "the Minkowski difference, and this face is not beside either. ";
    if (axis.rate < 0.0)
    {
        return text + "It faces the motion, and along such faces the entry times rise up to where the line enters "
                      "and fall after it, so its entry cannot be the latest.";
    }
    return text + "It faces away from the motion, and along such faces the exit times fall to where the line "
                  "leaves and rise after it, so its exit cannot be the earliest.";
}

std::string FaceSweepStep(const Scene& scene, const PairStudy& study, int step)
{
    const SweepAxis& axis = study.sweepTrace.axes[static_cast<size_t>(step)];
    const bool face = axis.axis.kind == AxisKind::FaceNormal;
    const std::string other = face ? NameOf(scene, study, 1 - axis.axis.shape) : std::string("the other shape");
    std::string text = StepName(scene, study, step) + ": " + DescribeAxis(scene, study, axis.axis) + ". ";
    if (axis.bounded || axis.skipped)
    {
        // The numbers of a face decided without evaluation are the view's own.
        text += axis.bounded ? BoundedFace(other, axis) : SkippedFace(axis);
        const std::string times = SweepTimes(axis);
        return text + " (For this view only: at t = 0 " + other + " is " + BeyondOrBehind(axis.separation) +
               times.substr(0, times.size() - 1) + ".)";
    }
    if (axis.exitPass)
    {
        text += "Second pass, for the exits, once the latest entry is known: this face recedes, and its exit may come "
                "before that entry. ";
    }
    text += "At t = 0 " + other + " is " + BeyondOrBehind(axis.separation) + SweepTimes(axis);
    // A face evaluated after the one that ended the test: the faces are taken in four at a time.
    for (int k = step - 1; k >= 0; --k)
    {
        const SweepAxis& earlier = study.sweepTrace.axes[static_cast<size_t>(k)];
        if (earlier.endsTest)
        {
            return text + " The test had already ended at face test " + std::to_string(k + 1) +
                   ": this face was evaluated with it (the faces are taken in four at a time).";
        }
    }
    if (axis.endsTest)
    {
        const bool never = face && axis.separation >= 0.0 && axis.rate >= 0.0;
        text += " This ends the test: " +
                (never ? FaceNeverClosesReason(scene, other, "this face", axis) : SweepExitReason(scene, study, study.sweepTrace.exit)) + ".";
    }
    else if (axis.latestEntry >= 0 && axis.earliestExit >= 0)
    {
        const SweepAxis& entry = study.sweepTrace.axes[static_cast<size_t>(axis.latestEntry)];
        const SweepAxis& exit = study.sweepTrace.axes[static_cast<size_t>(axis.earliestExit)];
        const auto [latest, earliest] = Times(entry.entry, exit.exit);
        text += " So far: latest entry " + latest + ", earliest exit " + earliest + ".";
    }
    return text;
}

std::string FaceSweepVerdict(const Scene& scene, const PairStudy& study, bool countContacts)
{
    const SweepResult& r = study.sweepResult;
    switch (r.status)
    {
    case SweepStatus::Hit:
    {
        // The face the other shape reaches at that time, which the picture marks; a circle's axis by its name.
        const std::string where = r.axis.kind == AxisKind::FaceNormal ? "at " + FaceName(scene, study, r.axis)
                                                                       : "along " + DescribeAxis(scene, study, r.axis);
        std::string text = "Verdict: first contact at t = " + FormatNumber(r.toi) + ", " + where + ", normal " +
                           Pair(r.normal.x, r.normal.y) + ".";
        if (countContacts)
        {
            text += r.contactCount == 1 ? " 1 contact point."
                                        : " " + std::to_string(r.contactCount) + " contact points.";
        }
        return text;
    }
    case SweepStatus::Overlapping:
        return "Verdict: the shapes already overlap at t = 0 (depth " + FormatNumber(r.initial.depth) +
               "): the static test's minimum translation vector applies.";
    case SweepStatus::Miss:
        break;
    }
    // The face that ended the test, named, when it never closes: what the picture's number line shows.
    for (const SweepAxis& axis : study.sweepTrace.axes)
    {
        if (axis.endsTest && axis.separation >= 0.0 && axis.rate >= 0.0 && axis.axis.kind == AxisKind::FaceNormal)
        {
            const std::string other = NameOf(scene, study, 1 - axis.axis.shape);
            return "Verdict: no hit during " + SweptSpan(scene) + ": " +
                   FaceNeverClosesReason(scene, other, FaceName(scene, study, axis.axis), axis) + ".";
        }
    }
    return "Verdict: no hit during " + SweptSpan(scene) + ": " + SweepExitReason(scene, study, study.sweepTrace.exit) + ".";
}

// Against a polygon above 16 vertices: how many face tests the sweep evaluated, and how many faces it decided without
// evaluating them; nothing for smaller pairs.
std::string DecidedNote(const PairStudy& study)
{
    int evaluated = 0;
    int bounded = 0;
    int skipped = 0;
    for (const SweepAxis& axis : study.sweepTrace.axes)
    {
        evaluated += axis.bounded || axis.skipped ? 0 : 1;
        bounded += axis.bounded ? 1 : 0;
        skipped += axis.skipped ? 1 : 0;
    }
    if (bounded + skipped == 0)
    {
        return "";
    }
    std::string text = " The sweep evaluated " + std::to_string(evaluated) + " face tests";
    if (bounded > 0)
    {
        text += "; " + std::to_string(bounded) +
                " were decided without walking to the face, by a vertex of the other shape that bounds the gap";
    }
    if (skipped > 0)
    {
        text += "; " + std::to_string(skipped) + " faces were never evaluated: bisection ruled them out";
    }
    return text + ".";
}

} // namespace

std::string FormatNumber(double value)
{
    char buffer[48];
    if (std::isnan(value))
    {
        return "nan";
    }
    if (std::isinf(value))
    {
        return value > 0 ? "inf" : "-inf";
    }
    const double magnitude = std::fabs(value);
    if (magnitude == 0.0)
    {
        // Beside other numbers a bare "0" reads as another format: 0.00, like 0.50.
        return "0.00";
    }
    if (magnitude >= 1e4 && magnitude < 1e9 && value == std::round(value))
    {
        // A whole number of five digits or more in groups of three, as a reader writes it: 100 000, not 100000.00,
        // the same in a sentence, a panel and a label beside an arrow.
        const std::string digits = std::to_string(static_cast<long long>(magnitude));
        std::string grouped = value < 0.0 ? "-" : "";
        for (size_t i = 0; i < digits.size(); ++i)
        {
            if (i > 0 && (digits.size() - i) % 3 == 0)
            {
                grouped += ' ';
            }
            grouped += digits[i];
        }
        return grouped;
    }
    if (magnitude >= 0.01 && magnitude < 1e9)
    {
        // Three decimals, the third dropped when it is 0: 0.176, -0.125, 0.45, 1.30.
        std::snprintf(buffer, sizeof(buffer), "%.3f", value);
        std::string fixed = buffer;
        if (fixed.back() == '0')
        {
            fixed.pop_back();
        }
        return fixed == "-0.00" ? "0.00" : fixed;
    }
    else
    {
        std::snprintf(buffer, sizeof(buffer), "%.3g", value);
    }
    std::string text = buffer;
    // Exponents as a reader writes them: 1.41e6 and 2.5e-5, not 1.41e+06 and 2.5e-05.
    const size_t e = text.find('e');
    if (e != std::string::npos)
    {
        std::string exponent = text.substr(e + 1);
        const bool negative = !exponent.empty() && exponent[0] == '-';
        exponent.erase(0, exponent.find_first_not_of("+-"));
        exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
        text = text.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
    }
    return text == "-0.00" ? "0.00" : text;
}

std::string FormatLabelNumber(double value)
{
    return FormatNumber(value);
}

std::string FormatNumber(double value, int significant)
{
    // Only from 0.01 to 0.1 do three decimals give fewer than three significant digits: below, FormatNumber gives
    // three significant digits; above, three decimals are three digits or more.
    const double magnitude = std::fabs(value);
    if (!(magnitude >= 0.01 && magnitude < 0.1))
    {
        return FormatNumber(value);
    }
    const int decimals = 1 + std::clamp(significant, 1, 3);
    if (decimals <= 3)
    {
        return FormatNumber(value);
    }
    char buffer[48];
    std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
    // 0.09999 rounds up to 0.1000: from 0.1 on, three decimals are three digits.
    return std::fabs(std::strtod(buffer, nullptr)) >= 0.1 ? FormatNumber(value) : buffer;
}

std::string FormatPair(double x, double y, const char* open, const char* close)
{
    const std::vector<std::string> alike = FormatAlike({x, y});
    return open + alike[0] + ", " + alike[1] + close;
}

std::vector<std::string> FormatAlike(const std::vector<double>& values)
{
    std::vector<std::string> texts;
    texts.reserve(values.size());
    const auto decimals = [](const std::string& t) {
        const size_t dot = t.find('.');
        return t.find('e') != std::string::npos || dot == std::string::npos ? -1 : static_cast<int>(t.size() - dot - 1);
    };
    int most = -1;
    for (const double value : values)
    {
        texts.push_back(FormatNumber(value));
        most = std::max(most, decimals(texts.back()));
    }
    // FormatNumber drops at most the third decimal's 0: a small number's five decimals (0.00512) are its
    // significant digits, not a width for the others.
    most = std::min(most, 3);
    for (std::string& text : texts)
    {
        // A grouped whole number (no point, no exponent) among numbers with decimals: its digits ungrouped, with
        // as many decimals of zeros.
        if (most > 0 && text.find(' ') != std::string::npos && text.find('.') == std::string::npos &&
            text.find('e') == std::string::npos)
        {
            text.erase(std::remove(text.begin(), text.end(), ' '), text.end());
            text += '.';
        }
        const int own = decimals(text);
        if (own >= 0 && own < most)
        {
            text.append(static_cast<size_t>(most - own), '0');
        }
    }
    return texts;
}

std::pair<std::string, std::string> FormatTimes(double entry, double exit)
{
    if (std::isfinite(entry) && std::isfinite(exit))
    {
        const std::vector<std::string> alike = FormatAlike({entry, exit});
        return {alike[0], alike[1]};
    }
    return {FormatNumber(entry), FormatNumber(exit)};
}

namespace
{

template <typename T>
std::string Shortest(T value)
{
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), value + T(0));
    return std::string(buffer, r.ptr);
}

} // namespace

std::string ShownOverlap(const TextbookAxis& t)
{
    return t.pushSign > 0 ? ShownDifference(t.maxA, t.minB, t.overlap) : ShownDifference(t.maxB, t.minA, t.overlap);
}

std::string ShownGap(const TextbookAxis& t)
{
    return t.minB - t.maxA > 0.0 ? ShownDifference(t.minB, t.maxA, t.gap) : ShownDifference(t.minA, t.maxB, t.gap);
}

std::string ShortestDecimal(double value)
{
    return Shortest(value);
}

std::string ShortestDecimal(float value)
{
    return Shortest(value);
}

namespace
{

// Pads a shortest decimal to two decimals: "0.8" to "0.80", "1" to "1.00"; an exponent form is left alone.
std::string TwoDecimalsAtLeast(std::string text)
{
    if (text.find_first_of("eEni") != std::string::npos) // 1e-05, inf, nan
    {
        return text;
    }
    const size_t point = text.find('.');
    if (point == std::string::npos)
    {
        return text + ".00";
    }
    const size_t decimals = text.size() - point - 1;
    return decimals >= 2 ? text : text + std::string(2 - decimals, '0');
}

} // namespace

std::string FullDecimal(double value)
{
    return TwoDecimalsAtLeast(Shortest(value));
}

std::string FullDecimal(float value)
{
    return TwoDecimalsAtLeast(Shortest(value));
}

std::string DescribeAxis(const Scene& scene, const PairStudy& study, const AxisRef& axis)
{
    switch (axis.kind)
    {
    case AxisKind::FaceNormal:
        return "the normal of " + Possessive(NameOf(scene, study, axis.shape)) + " edge " + std::to_string(axis.index);
    case AxisKind::VertexToCenter:
        return "the axis from " + Possessive(NameOf(scene, study, axis.shape)) + " vertex " +
               std::to_string(axis.index) + " to " + Possessive(NameOf(scene, study, 1 - axis.shape)) + " centre";
    case AxisKind::CenterToCenter:
        return "the line of centres";
    case AxisKind::None:
        break;
    }
    return "no axis";
}

std::string StepName(const Scene& scene, const PairStudy& study, int step)
{
    if (step < 0 || step >= study.StepCount())
    {
        return "";
    }
    if (step == study.VerdictStep())
    {
        return "Verdict";
    }
    const size_t k = static_cast<size_t>(step);
    const std::string number = std::to_string(step + 1);
    if (study.Textbook())
    {
        // The static test counts the distinct axes it would test in all; a sweep's list ends where it is decided.
        return "Axis " + number + (study.sweep ? "" : " of " + std::to_string(study.textbookResult.axisCount));
    }
    const AxisKind kind = study.sweep ? study.sweepTrace.axes[k].axis.kind : study.trace.axes[k].axis.kind;
    const std::string name = (kind == AxisKind::FaceNormal ? "Face test " : "Test ") + number;
    return study.sweep ? name : name + " of " + std::to_string(CandidateCount(scene, study));
}

std::string DescribeStep(const Scene& scene, const PairStudy& study, int step, bool countContacts)
{
    if (step < 0 || step >= study.StepCount())
    {
        return "";
    }
    if (study.Textbook())
    {
        if (step == study.VerdictStep())
        {
            return (study.sweep ? TextbookSweepVerdict(scene, study) : TextbookVerdict(scene, study, countContacts)) +
                   RoundOffNote(study) + PrecisionNote(scene, study) + PitfallNote(study);
        }
        return study.sweep ? TextbookSweepAxisStep(scene, study, step) : TextbookAxisStep(scene, study, step);
    }
    if (step == study.VerdictStep())
    {
        return (study.sweep ? FaceSweepVerdict(scene, study, countContacts) + DecidedNote(study)
                             : FaceTestVerdict(scene, study, countContacts)) +
               RoundOffNote(study) + PrecisionNote(scene, study) + PitfallNote(study);
    }
    return study.sweep ? FaceSweepStep(scene, study, step) : FaceTestStep(scene, study, step);
}

std::string StepTitle(const Scene& scene, const PairStudy& study, int step)
{
    if (step < 0 || step >= study.StepCount())
    {
        return "";
    }
    if (step == study.VerdictStep())
    {
        if (study.sweep)
        {
            const SweepStatus status = study.Textbook() ? study.textbookSweepResult.status : study.sweepResult.status;
            const double toi = study.Textbook() ? study.textbookSweepResult.toi : study.sweepResult.toi;
            return status == SweepStatus::Hit           ? "verdict: hit at t = " + FormatNumber(toi)
                   : status == SweepStatus::Overlapping ? "verdict: overlapping at t = 0"
                                                        : "verdict: no hit";
        }
        if (study.Textbook())
        {
            const TextbookResult& r = study.textbookResult;
            if (r.axis < 0)
            {
                return "verdict";
            }
            const TextbookAxis& t = study.textbook.axes[static_cast<size_t>(r.axis)];
            if (RoundOffVerdict(study))
            {
                return std::string("verdict: touching, round-off ") + (r.overlap ? "overlap " : "gap ") +
                       ShownVerdictAmount(study);
            }
            if (!r.overlap)
            {
                return "verdict: apart, gap " + ShownGap(t);
            }
            // Shapes whose smallest overlap shows as 0.00 touch: the verdict's sentence says so, and so does this.
            const std::string depth = ShownOverlap(t);
            return depth == "0.00" ? "verdict: touching, MTV zero" : "verdict: collide, MTV " + depth;
        }
        if (RoundOffVerdict(study))
        {
            return std::string("verdict: touching, round-off ") + (study.manifold.overlap ? "overlap " : "gap ") +
                   ShownVerdictAmount(study);
        }
        if (!study.manifold.overlap)
        {
            return "verdict: apart, gap " + VerdictAmount(study);
        }
        return study.manifold.depth == 0.0 ? "verdict: touching, MTV zero" : "verdict: collide, MTV " + VerdictAmount(study);
    }
    const size_t k = static_cast<size_t>(step);
    AxisRef axis;
    if (study.Textbook())
    {
        axis = study.sweep ? study.textbookSweep.axes[k].faces[0] : study.textbook.axes[k].faces[0];
    }
    else
    {
        axis = study.sweep ? study.sweepTrace.axes[k].axis : study.trace.axes[k].axis;
    }
    std::string title = std::to_string(step + 1) + ": ";
    switch (axis.kind)
    {
    case AxisKind::FaceNormal:
        title += NameOf(scene, study, axis.shape) + " edge " + std::to_string(axis.index);
        break;
    case AxisKind::VertexToCenter:
        title += NameOf(scene, study, axis.shape) + " vertex " + std::to_string(axis.index);
        break;
    default:
        title += "centres";
        break;
    }
    // The two times of a row read together, with as many decimals each (FormatTimes).
    auto fromTo = [](double entry, double exit) {
        const auto [from, to] = FormatTimes(entry, exit);
        return (std::isinf(entry) ? std::string("the start") : from) + " to " +
               (std::isinf(exit) ? std::string("the end") : to);
    };
    auto times = [&](double entry, double exit) { return ", overlap from " + fromTo(entry, exit); };
    if (study.Textbook())
    {
        if (study.sweep)
        {
            const TextbookSweepAxis& s = study.textbookSweep.axes[k];
            return s.never ? title + ", never overlap" : title + times(s.entry, s.exit);
        }
        const TextbookAxis& t = study.textbook.axes[k];
        return t.separating ? title + ", gap " + ShownGap(t) + " (separates)" : title + ", overlap " + ShownOverlap(t);
    }
    if (study.sweep)
    {
        const SweepAxis& s = study.sweepTrace.axes[k];
        if (s.skipped)
        {
            return title + ", not evaluated (bisection)";
        }
        if (s.bounded)
        {
            return title + (s.exitPass      ? ", not walked to (exit after " + FormatNumber(s.boundTime) + ")"
                            : s.bound < 0.0 ? ", not walked to (overlaps at t = 0)"
                                            : ", not walked to (entry by " + FormatNumber(s.boundTime) + ")");
        }
        return title + (s.exitPass ? ", exits: behind from " : ", behind from ") + fromTo(s.entry, s.exit);
    }
    const AxisTest& test = study.trace.axes[k];
    if (test.skipped)
    {
        return title + ", skipped (anti-parallel)";
    }
    title += ", " + ShownSeparation(test) + (test.separation > 0.0 ? " beyond" : " behind");
    return test.separating ? title + " (separates)" : title;
}

} // namespace satviz
