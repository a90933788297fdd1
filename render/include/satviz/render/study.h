// SPDX-License-Identifier: MIT
// satviz render: the queries run on the pictured pair, with their step traces.
#pragma once

#include <satviz/render/pitfall.h>
#include <satviz/scene.h>
#include <satviz/sweep.h>
#include <satviz/textbook.h>
#include <satviz/trace.h>

namespace satviz
{

/// Largest (n + m)^2 for which the textbook test is run for a view (it projects every vertex on every axis); a
/// larger pair shows the face tests, and its caption says why.
constexpr long long kTextbookBudget = 4000000;

/// The pictured pair of a scene and what the SAT queries recorded for it. The static test is always run; the
/// swept test only when the view shows it (nothing is swept when nothing moves). The fast queries always run (the
/// contact points come from them); the textbook test too when the view shows its steps.
struct PairStudy
{
    int bodyA = -1;     ///< index of body A in the scene
    int bodyB = -1;     ///< index of body B in the scene
    bool sweep = false; ///< the figure shows the swept test (else the static test)
    /// The pair moves but already overlaps at t = 0: there is no time of impact, so the static test is shown.
    bool startsOverlapping = false;
    /// The queries ran in single precision (float), their results widened to double for drawing.
    bool singlePrecision = false;
    /// Which algorithm the steps show: the textbook test, or the face tests of the fast queries.
    StepView steps = StepView::Textbook;
    /// The textbook view was asked for, but the pair has too many vertices for it (kTextbookBudget): the face
    /// tests are shown instead.
    bool textbookTooLarge = false;
    Manifold manifold;                       ///< Collide(A, B)
    Trace trace;                             ///< its step trace
    SweepResult sweepResult;                 ///< Sweep(A, B), when sweep
    SweepTrace sweepTrace;                   ///< its step trace, when sweep
    TextbookResult textbookResult;           ///< TextbookCollide(A, B), in the textbook view
    TextbookTrace textbook;                  ///< its trace
    TextbookSweepResult textbookSweepResult; ///< TextbookSweep(A, B), in the textbook view when sweep
    TextbookSweepTrace textbookSweep;        ///< its trace
    /// The view's pitfall (a classic mistake) run on the pair beside the right answer; ran is false without one.
    PitfallResult pitfall;

    /// The steps are those of the textbook test.
    bool Textbook() const { return steps == StepView::Textbook; }
    /// Number of axis steps of the shown test.
    int AxisCount() const
    {
        if (Textbook())
        {
            return static_cast<int>(sweep ? textbookSweep.axes.size() : textbook.axes.size());
        }
        return static_cast<int>(sweep ? sweepTrace.axes.size() : trace.axes.size());
    }
    /// Number of steps: one per axis, then the verdict.
    int StepCount() const { return AxisCount() + 1; }
    /// The step that shows the verdict.
    int VerdictStep() const { return AxisCount(); }
    /// Step `step` shows a face that the swept test decided without evaluating it (in the face-test view, against a
    /// polygon above 16 vertices: a face not walked to, or one the bisection ruled out).
    bool Decided(int step) const
    {
        if (!sweep || Textbook() || step < 0 || step >= AxisCount())
        {
            return false;
        }
        const SweepAxis& axis = sweepTrace.axes[static_cast<size_t>(step)];
        return axis.bounded || axis.skipped;
    }
    /// The first step after `step` (`direction` 1) or before it (-1) that is not Decided, as the step controls go:
    /// a polygon of 4096 faces has thousands of faces decided without evaluation, and a few evaluated. Forwards
    /// the verdict ends the search; backwards, with none before, `step` itself. NextStep(-1, 1) is the first step.
    int NextStep(int step, int direction) const
    {
        for (int next = step + direction; next >= 0 && next <= VerdictStep(); next += direction)
        {
            if (!Decided(next))
            {
                return next;
            }
        }
        return step < 0 ? 0 : step > VerdictStep() ? VerdictStep() : step;
    }
};

/// Runs the queries on bodies a and b of the scene (indices). `query` Automatic sweeps when the pair moves
/// relative to each other. A sweep that finds the pair overlapping at t = 0 shows the static test instead.
/// With `singlePrecision`, the shapes are rounded to float and the float instantiation of the queries runs (a
/// polygon that rounding makes invalid falls back to double, and singlePrecision stays false).
/// `steps` chooses the algorithm whose steps are recorded for the view (the textbook test by default).
PairStudy StudyPair(const Scene& scene, int a, int b, ViewQuery query, bool singlePrecision = false,
                    StepView steps = StepView::Textbook);

/// The world transform of a body at time t of the step (its velocity is the displacement over the step).
Transform BodyTransformAt(const Body& body, double t);

} // namespace satviz
