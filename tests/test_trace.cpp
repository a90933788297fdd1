// SPDX-License-Identifier: MIT
// The step trace: complete, consistent with the result, and describing what the algorithm did.

#include "support/random_shapes.h"
#include "support/reference.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

using namespace satviz;
using namespace satviz::testing;
using Catch::Matchers::WithinAbs;

TEST_CASE("The trace of a separated pair ends at the separating axis", "[trace]")
{
    const Polygon a = MakeBox(1.0, 1.0).polygon;
    const Polygon b = MakeBox(0.5, 0.5).polygon;
    Trace trace;
    // B is right of A: A's faces are tested in order bottom (0), right (1): the right face separates.
    const Manifold m = Collide(a, MakeTransform(Vec2{2.0, 0.0}, 0.0), b, MakeTransform(Vec2{3.7, 0.1}, 0.0), &trace);
    REQUIRE_FALSE(m.overlap);
    REQUIRE(trace.exit == TraceExit::SeparatingAxis);
    REQUIRE(trace.axes.size() == 2);
    const AxisTest& first = trace.axes[0];
    CHECK_FALSE(first.separating);
    CHECK(first.direction == Vec2{0.0, -1.0});
    // On the axis (0, -1): A spans [-1, 1], B spans [-0.6, 0.4].
    CHECK_THAT(first.minA, WithinAbs(-1.0, 1e-15));
    CHECK_THAT(first.maxA, WithinAbs(1.0, 1e-15));
    CHECK_THAT(first.minB, WithinAbs(-0.6, 1e-15));
    CHECK_THAT(first.maxB, WithinAbs(0.4, 1e-15));
    CHECK_THAT(first.separation, WithinAbs(-1.6, 1e-15));
    const AxisTest& last = trace.axes[1];
    CHECK(last.separating);
    CHECK(last.axis.index == 1);
    CHECK_THAT(last.separation, WithinAbs(0.2, 1e-15));
    CHECK_THAT(last.minB - last.maxA, WithinAbs(0.2, 1e-15));
    CHECK(last.best == 1);
    CHECK_FALSE(trace.hasClip);
}

TEST_CASE("Trace invariants hold on random pairs", "[trace][properties]")
{
    Rng rng(99);
    Trace trace;
    for (int i = 0; i < 20000; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB, &trace);
        INFO("pair " << i);
        REQUIRE_FALSE(trace.axes.empty());
        REQUIRE(trace.exit == (m.overlap ? TraceExit::AllAxesOverlap : TraceExit::SeparatingAxis));
        // Only the last axis may separate, and it does exactly when the pair is separated.
        for (size_t k = 0; k + 1 < trace.axes.size(); ++k)
        {
            REQUIRE_FALSE(trace.axes[k].separating);
        }
        REQUIRE(trace.axes.back().separating == !m.overlap);
        const double tolerance = 1e-12 * 4.0;
        double best = -1e300;
        for (size_t k = 0; k < trace.axes.size(); ++k)
        {
            const AxisTest& t = trace.axes[k];
            REQUIRE(std::abs(Length(t.direction) - 1.0) < 1e-14);
            REQUIRE(t.minA <= t.maxA);
            REQUIRE(t.minB <= t.maxB);
            if (t.pruned)
            {
                // The bound is an upper bound of the separation, and it could not separate the shapes.
                REQUIRE(t.separation <= t.bound + tolerance);
                REQUIRE_FALSE(t.separating);
            }
            if (!t.skipped)
            {
                best = std::max(best, t.separation);
            }
            REQUIRE(trace.axes[t.best].separation == best);
            // The recorded separation is the gap between the intervals the trace shows: an axis of B points from B
            // towards A, the others from A towards B.
            const double fromIntervals = t.axis.shape == 1 ? t.minA - t.maxB : t.minB - t.maxA;
            REQUIRE(std::abs(fromIntervals - t.separation) < tolerance);
        }
        // The deciding axis of an overlapping pair is the best one, with separation -depth.
        if (m.overlap)
        {
            REQUIRE(std::abs(trace.axes[trace.axes.back().best].separation + m.depth) < tolerance);
        }
        if (m.overlap && pair.a.type == ShapeType::Polygon && pair.b.type == ShapeType::Polygon)
        {
            REQUIRE(trace.hasClip);
            REQUIRE(trace.clip.reference.kind == AxisKind::FaceNormal);
            REQUIRE(trace.clip.reference.shape == m.axis.shape);
            REQUIRE(trace.clip.incidentShape == 1 - m.axis.shape);
            int kept = 0;
            for (int k = 0; k < trace.clip.sideClip2Count; ++k)
            {
                kept += trace.clip.kept[k] ? 1 : 0;
            }
            REQUIRE((trace.clip.usedFallback ? 1 : kept) == m.contactCount);
        }
    }
}

TEST_CASE("Overlap of polygons above 8 vertices stops when a vertex of B lies inside A, and only then skips B's faces, "
          "smaller pairs test both polygons' faces in blocks",
          "[trace][properties]")
{
    Rng rng(2024);
    Trace trace;
    int shortcuts = 0;
    int overlapping = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const int n = rng.Int(3, 20);
        const RandomPair pair = ContactPair(rng, n, static_cast<PairCategory>(rng.Int(0, 2)));
        const Polygon& a = pair.a.polygon;
        const Polygon& b = pair.b.polygon;
        const bool overlap = Overlap(a, pair.xfA, b, pair.xfB, &trace);
        INFO("pair " << i << ", " << n << " vertices");
        REQUIRE(overlap == Collide(a, pair.xfA, b, pair.xfB).overlap);
        // How far outside A each vertex of B lies (<= 0 inside).
        auto depthOutside = [&](int j) { return DepthOutside(a, pair.xfA, TransformPoint(pair.xfB, b.Vertices()[j])); };
        if (!overlap)
        {
            REQUIRE(trace.exit == TraceExit::SeparatingAxis);
            continue;
        }
        if (n <= 8)
        {
            // Both polygons' faces in blocks, none separating (B's anti-parallel ones skipped), no shortcut.
            REQUIRE(trace.exit == TraceExit::AllAxesOverlap);
            size_t facesOfA = 0;
            for (const AxisTest& t : trace.axes)
            {
                REQUIRE_FALSE(t.separating);
                facesOfA += t.axis.shape == 0 ? 1 : 0;
            }
            REQUIRE(facesOfA == static_cast<size_t>(a.Count()));
            REQUIRE(trace.axes.size() == static_cast<size_t>(a.Count() + b.Count()));
            continue;
        }
        ++overlapping;
        if (trace.exit == TraceExit::VertexInside)
        {
            ++shortcuts;
            REQUIRE(trace.containedShape == 1);
            REQUIRE(trace.containedVertex >= 0);
            REQUIRE(trace.containedVertex < b.Count());
            REQUIRE(depthOutside(trace.containedVertex) <= 1e-12L);
            // Only A's faces were tested, none separating.
            REQUIRE(trace.axes.size() == static_cast<size_t>(a.Count()));
            for (const AxisTest& t : trace.axes)
            {
                REQUIRE(t.axis.shape == 0);
                REQUIRE_FALSE(t.separating);
            }
        }
        else
        {
            // The shortcut is not missed: no vertex of B lies clearly inside A (a scanned B: all of its vertices
            // are candidates; a walked one offers a single candidate).
            REQUIRE(trace.exit == TraceExit::AllAxesOverlap);
            for (int j = 0; n <= 16 && j < b.Count(); ++j)
            {
                REQUIRE(depthOutside(j) > -1e-12L);
            }
        }
    }
    // Most overlapping contact pairs have a corner of B inside A.
    CHECK(shortcuts > overlapping / 2);
}
