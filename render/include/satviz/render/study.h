// SPDX-License-Identifier: MIT
// satviz render: the queries run on the pictured pair, with their step traces.
#pragma once

#include <satviz/scene.h>
#include <satviz/sweep.h>
#include <satviz/trace.h>

namespace satviz
{

/// The pictured pair of a scene and what the SAT queries recorded for it. The static test is always run; the
/// swept test only when the view shows it (nothing is swept when nothing moves).
struct PairStudy
{
    int bodyA = -1;     ///< index of body A in the scene
    int bodyB = -1;     ///< index of body B in the scene
    bool sweep = false; ///< the figure shows the swept test (else the static test)
    /// The pair moves but already overlaps at t = 0: there is no time of impact, so the static test is shown.
    bool startsOverlapping = false;
    /// The queries ran in single precision (float), their results widened to double for drawing.
    bool singlePrecision = false;
    Manifold manifold;       ///< Collide(A, B)
    Trace trace;             ///< its step trace
    SweepResult sweepResult; ///< Sweep(A, B), when sweep
    SweepTrace sweepTrace;   ///< its step trace, when sweep

    /// Number of axis steps of the shown test.
    int AxisCount() const { return static_cast<int>(sweep ? sweepTrace.axes.size() : trace.axes.size()); }
    /// Number of steps: one per axis, then the verdict.
    int StepCount() const { return AxisCount() + 1; }
    /// The step that shows the verdict.
    int VerdictStep() const { return AxisCount(); }
};

/// Runs the queries on bodies a and b of the scene (indices). `query` Automatic sweeps when the pair moves
/// relative to each other. A sweep that finds the pair overlapping at t = 0 shows the static test instead.
/// With `singlePrecision`, the shapes are rounded to float and the float instantiation of the queries runs (a
/// polygon that rounding makes invalid falls back to double, and singlePrecision stays false).
PairStudy StudyPair(const Scene& scene, int a, int b, ViewQuery query, bool singlePrecision = false);

/// The world transform of a body at time t of the step (its velocity is the displacement over the step).
Transform BodyTransformAt(const Body& body, double t);

} // namespace satviz
