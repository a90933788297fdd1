// SPDX-License-Identifier: MIT
#include <satviz/render/describe.h>

#include <cmath>
#include <cstdio>

namespace satviz
{

namespace
{

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
    return "(" + FormatNumber(x) + ", " + FormatNumber(y) + ")";
}

std::string Interval(double low, double high)
{
    return "[" + FormatNumber(low) + ", " + FormatNumber(high) + "]";
}

// Number of axes the full test could try: every face normal of a polygon, one axis per circle pair.
int CandidateCount(const Scene& scene, const PairStudy& study)
{
    const Shape& a = scene.bodies[static_cast<size_t>(study.bodyA)].shape;
    const Shape& b = scene.bodies[static_cast<size_t>(study.bodyB)].shape;
    const int faces =
        (a.type == ShapeType::Polygon ? a.polygon.Count() : 0) + (b.type == ShapeType::Polygon ? b.polygon.Count() : 0);
    return (a.type == ShapeType::Circle || b.type == ShapeType::Circle) ? faces + 1 : faces;
}

std::string OverlapOrGap(double separation)
{
    return separation > 0.0 ? "are " + FormatNumber(separation) + " apart"
                            : "overlap: a push of " + FormatNumber(-separation) + " along this axis separates them";
}

std::string Time(double t)
{
    return std::isinf(t) ? "never" : "t = " + FormatNumber(t);
}

std::string SweepExitReason(SweepExit exit)
{
    switch (exit)
    {
    case SweepExit::NotMoving:
        return "nothing moves, so the static test decides";
    case SweepExit::NeverCloses:
        return "on this axis the gap never closes, so the shapes cannot meet";
    case SweepExit::EntryAfterStep:
        return "the intervals would only meet after the step ends";
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

std::string StaticAxisStep(const Scene& scene, const PairStudy& study, int step)
{
    const AxisTest& test = study.trace.axes[static_cast<size_t>(step)];
    std::string text = "Axis " + std::to_string(step + 1) + " of " + std::to_string(CandidateCount(scene, study)) +
                       ": " + DescribeAxis(scene, study, test.axis) + ".";
    if (test.skipped)
    {
        return text + " It is parallel to axis " + std::to_string(test.duplicateOf + 1) +
               ", already tested, so it is skipped.";
    }
    text += " Intervals " + Interval(test.minA, test.maxA) + " and " + Interval(test.minB, test.maxB) + " " +
            OverlapOrGap(test.separation) + ".";
    if (test.separating)
    {
        text += " A separating axis: the shapes do not collide, and the test stops here.";
    }
    else if (test.pruned)
    {
        text += " Pruned: a single point of the other shape shows this face cannot separate or win.";
    }
    return text;
}

std::string StaticVerdict(const Scene& scene, const PairStudy& study)
{
    const Manifold& m = study.manifold;
    const std::string& nameB = NameOf(scene, study, 1);
    const int tested = static_cast<int>(study.trace.axes.size());
    if (!m.overlap)
    {
        return "Verdict: " + DescribeAxis(scene, study, m.axis) + " separates the shapes by " + FormatNumber(m.gap) +
               ", so they do not collide. The test stopped after " + std::to_string(tested) + " of " +
               std::to_string(CandidateCount(scene, study)) + " axes.";
    }
    std::string text = study.startsOverlapping ? "The shapes already overlap at t = 0, so there is no time of "
                                                 "impact. "
                                               : "";
    text += "Verdict: every axis overlaps, so the shapes collide. The smallest push is along " +
            DescribeAxis(scene, study, m.axis) + ": moving " + nameB + " by " + FormatNumber(m.depth) + " along " +
            Pair(m.normal.x, m.normal.y) + " separates them (the MTV).";
    text += m.contactCount == 1 ? " 1 contact point." : " " + std::to_string(m.contactCount) + " contact points.";
    return text;
}

std::string SweepAxisStep(const Scene& scene, const PairStudy& study, int step)
{
    const SweepAxis& axis = study.sweepTrace.axes[static_cast<size_t>(step)];
    std::string text =
        "Axis " + std::to_string(step + 1) + ": " + DescribeAxis(scene, study, axis.axis) +
        ". At t = 0 the intervals " +
        (axis.separation > 0.0 ? "are " + FormatNumber(axis.separation) + " apart"
                               : "overlap (a push of " + FormatNumber(-axis.separation) + " would separate them)");
    if (axis.rate == 0.0)
    {
        text += " and stay so (no motion along this axis).";
    }
    else if (axis.separation > 0.0 && axis.rate > 0.0)
    {
        text += " and move apart.";
    }
    else
    {
        text += "; they meet at " + Time(axis.entry) + " and part at " + Time(axis.exit) + ".";
    }
    if (axis.endsTest)
    {
        text += " This ends the test: " + SweepExitReason(study.sweepTrace.exit) + ".";
    }
    else if (axis.latestEntry >= 0 && axis.earliestExit >= 0)
    {
        const SweepAxis& entry = study.sweepTrace.axes[static_cast<size_t>(axis.latestEntry)];
        const SweepAxis& exit = study.sweepTrace.axes[static_cast<size_t>(axis.earliestExit)];
        text += " So far: latest entry " + Time(entry.entry) + ", earliest exit " + Time(exit.exit) + ".";
    }
    return text;
}

std::string SweepVerdict(const Scene& scene, const PairStudy& study)
{
    const SweepResult& r = study.sweepResult;
    switch (r.status)
    {
    case SweepStatus::Hit:
    {
        std::string text = "Verdict: first contact at t = " + FormatNumber(r.toi) + " on " +
                           DescribeAxis(scene, study, r.axis) + ", normal " + Pair(r.normal.x, r.normal.y) + ".";
        text += r.contactCount == 1 ? " 1 contact point." : " " + std::to_string(r.contactCount) + " contact points.";
        return text;
    }
    case SweepStatus::Overlapping:
        return "Verdict: the shapes already overlap at t = 0 (depth " + FormatNumber(r.initial.depth) +
               "): the static test's minimum translation vector applies.";
    case SweepStatus::Miss:
        break;
    }
    return "Verdict: no hit during the step: " + SweepExitReason(study.sweepTrace.exit) + ".";
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
        return "0";
    }
    if (magnitude >= 0.01 && magnitude < 1e5)
    {
        std::snprintf(buffer, sizeof(buffer), "%.2f", value);
    }
    else
    {
        std::snprintf(buffer, sizeof(buffer), "%.3g", value);
    }
    return buffer;
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

std::string DescribeStep(const Scene& scene, const PairStudy& study, int step)
{
    if (step < 0 || step >= study.StepCount())
    {
        return "";
    }
    if (step == study.VerdictStep())
    {
        return study.sweep ? SweepVerdict(scene, study) : StaticVerdict(scene, study);
    }
    return study.sweep ? SweepAxisStep(scene, study, step) : StaticAxisStep(scene, study, step);
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
            const SweepResult& r = study.sweepResult;
            return r.status == SweepStatus::Hit           ? "verdict: hit at t = " + FormatNumber(r.toi)
                   : r.status == SweepStatus::Overlapping ? "verdict: overlapping at t = 0"
                                                          : "verdict: no hit";
        }
        return study.manifold.overlap ? "verdict: collide, depth " + FormatNumber(study.manifold.depth)
                                      : "verdict: apart, gap " + FormatNumber(study.manifold.gap);
    }
    const AxisRef axis = study.sweep ? study.sweepTrace.axes[static_cast<size_t>(step)].axis
                                     : study.trace.axes[static_cast<size_t>(step)].axis;
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
    if (study.sweep)
    {
        const SweepAxis& s = study.sweepTrace.axes[static_cast<size_t>(step)];
        return title + ", entry " + (std::isinf(s.entry) ? "never" : FormatNumber(s.entry)) + ", exit " +
               (std::isinf(s.exit) ? "never" : FormatNumber(s.exit));
    }
    const AxisTest& test = study.trace.axes[static_cast<size_t>(step)];
    if (test.skipped)
    {
        return title + ", skipped (parallel)";
    }
    title +=
        test.separation > 0.0 ? ", gap " + FormatNumber(test.separation) : ", push " + FormatNumber(-test.separation);
    return test.separating ? title + " (separates)" : title;
}

} // namespace satviz
