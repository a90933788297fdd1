// SPDX-License-Identifier: MIT
// The textbook test (intervals on each distinct axis) against the fast queries and the quadruple-precision
// reference: the same verdicts, depths and times, and a trace that holds what a learner checks by hand.

#include "support/builders.h"
#include "support/lattice.h"
#include "support/random_shapes.h"
#include "support/reference.h"
#include "support/same_bits.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

using namespace satviz;
using namespace satviz::testing;

namespace
{

// A random pair small enough for the O((n + m)^2) textbook test: at most 40 vertices between them.
RandomPair SmallPair(Rng& rng, double circleChance)
{
    for (;;)
    {
        RandomPair pair = RandomShapePair(rng, circleChance);
        auto count = [](const Shape& s) { return s.type == ShapeType::Polygon ? s.polygon.Count() : 1; };
        if (count(pair.a) + count(pair.b) <= 40)
        {
            return pair;
        }
    }
}

double Scale(const RandomPair& pair)
{
    auto radius = [](const Shape& s) { return s.type == ShapeType::Polygon ? Radius(s.polygon) : s.circle.radius; };
    return std::max({radius(pair.a), radius(pair.b), 1.0});
}

// Quad-precision extent of a shape along a world direction.
void QExtent(const Shape& shape, const Transform& xf, QVec u, Quad& lo, Quad& hi)
{
    if (shape.type == ShapeType::Circle)
    {
        const Quad c = QDot(u, QTransform(xf, shape.circle.center));
        lo = c - shape.circle.radius;
        hi = c + shape.circle.radius;
        return;
    }
    lo = 1e300;
    hi = -1e300;
    for (const QVec& p : QWorld(shape.polygon, xf))
    {
        lo = std::min(lo, QDot(u, p));
        hi = std::max(hi, QDot(u, p));
    }
}

bool SameAxisRef(const AxisRef& a, const AxisRef& b)
{
    return a.kind == b.kind && a.shape == b.shape && a.index == b.index;
}

} // namespace

TEST_CASE("The textbook test gives Overlap's verdict and Collide's depth, and its MTV separates",
          "[textbook][properties]")
{
    Rng rng(20261125);
    int decided = 0;
    int overlapping = 0;
    int sameNormal = 0;
    for (int i = 0; i < 30000; ++i)
    {
        const RandomPair pair = SmallPair(rng, 0.25);
        const TextbookResult t = TextbookCollide(pair.a, pair.xfA, pair.b, pair.xfB);
        const Reference ref = ReferenceCollide(pair.a, pair.xfA, pair.b, pair.xfB);
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        const double scale = Scale(pair);
        const double refSeparation = static_cast<double>(ref.separation);
        INFO("pair " << i << ": reference separation " << refSeparation);
        if (std::abs(refSeparation) > 1e-12 * scale)
        {
            REQUIRE(t.overlap == ref.overlap);
            REQUIRE(t.overlap == Overlap(pair.a, pair.xfA, pair.b, pair.xfB));
            ++decided;
        }
        REQUIRE(t.axesTested >= 1);
        REQUIRE(t.axesTested <= t.axisCount);
        REQUIRE(std::abs(Length(t.normal) - 1.0) <= 1e-14);
        if (!t.overlap || !ref.overlap || !m.overlap)
        {
            continue;
        }
        ++overlapping;
        REQUIRE(t.axesTested == t.axisCount);
        REQUIRE(std::abs(t.depth + refSeparation) <= 1e-13 * scale);
        REQUIRE(std::abs(t.depth - m.depth) <= 1e-13 * scale);
        // Independent of ties: along the textbook normal, B must move exactly the depth to leave A (quad).
        const QVec u{t.normal.x, t.normal.y};
        Quad loA = 0, hiA = 0, loB = 0, hiB = 0;
        QExtent(pair.a, pair.xfA, u, loA, hiA);
        QExtent(pair.b, pair.xfB, u, loB, hiB);
        REQUIRE(std::abs(static_cast<double>(hiA - loB) - t.depth) <= 1e-13 * scale);
        sameNormal += Length(t.normal - m.normal) <= 1e-9 ? 1 : 0;
    }
    WARN(decided << " verdicts compared, " << overlapping << " depths, " << sameNormal
                 << " with Collide's very normal (the rest tie)");
    CHECK(decided > 29000);
    CHECK(overlapping > 10000);
    CHECK(sameNormal > overlapping * 99 / 100);
}

TEST_CASE("Textbook traces are bit-identical to the untraced test and hold checkable intervals", "[textbook][trace]")
{
    Rng rng(77);
    for (int i = 0; i < 5000; ++i)
    {
        const RandomPair pair = SmallPair(rng, 0.25);
        TextbookTrace trace;
        const TextbookResult traced = TextbookCollide(pair.a, pair.xfA, pair.b, pair.xfB, &trace);
        const TextbookResult plain = TextbookCollide(pair.a, pair.xfA, pair.b, pair.xfB);
        INFO("pair " << i);
        REQUIRE(traced.overlap == plain.overlap);
        REQUIRE(SameBits(traced.depth, plain.depth));
        REQUIRE(SameBits(traced.gap, plain.gap));
        REQUIRE(SameBits(traced.normal, plain.normal));
        REQUIRE(traced.axis == plain.axis);
        REQUIRE(static_cast<int>(trace.axes.size()) == traced.axesTested);
        for (size_t k = 0; k < trace.axes.size(); ++k)
        {
            const TextbookAxis& axis = trace.axes[k];
            // The intervals are the shapes' projections on the axis (quad precision, world space).
            Quad loA = 0, hiA = 0, loB = 0, hiB = 0;
            const QVec u{axis.direction.x, axis.direction.y};
            QExtent(pair.a, pair.xfA, u, loA, hiA);
            QExtent(pair.b, pair.xfB, u, loB, hiB);
            const double tolerance = 1e-13 * (Scale(pair) + 4.0);
            REQUIRE(std::abs(static_cast<double>(loA) - axis.minA) <= tolerance);
            REQUIRE(std::abs(static_cast<double>(hiA) - axis.maxA) <= tolerance);
            REQUIRE(std::abs(static_cast<double>(loB) - axis.minB) <= tolerance);
            REQUIRE(std::abs(static_cast<double>(hiB) - axis.maxB) <= tolerance);
            // What the step says follows from its two intervals, as a learner would check it.
            const double along = axis.minB - axis.maxA;
            const double against = axis.minA - axis.maxB;
            REQUIRE(axis.separating == (k + 1 == trace.axes.size() && !traced.overlap));
            if (axis.separating)
            {
                REQUIRE(std::abs(axis.gap - std::max(along, against)) <= tolerance);
                REQUIRE(axis.gap > 0.0);
            }
            else
            {
                REQUIRE(std::abs(axis.overlap - std::min(-along, -against)) <= tolerance);
                REQUIRE(axis.overlap >= 0.0);
                REQUIRE(std::abs(axis.overlap - (axis.pushSign > 0 ? -along : -against)) <= tolerance);
            }
            // Merged faces lie on the axis's line, and no two axes share a line.
            for (int f = 0; f < axis.faceCount; ++f)
            {
                REQUIRE(axis.faces[f].kind != AxisKind::None);
            }
            for (size_t j = 0; j < k; ++j)
            {
                REQUIRE(std::abs(Cross(trace.axes[j].direction, axis.direction)) > 1e-15);
            }
        }
    }
}

TEST_CASE("Two boxes have two axes when aligned, four when turned, and a gap on the first axis ends the test",
          "[textbook]")
{
    const Shape floor = MakeShape(MakeBox(2.0, 0.25).polygon);
    const Shape box = MakeShape(MakeBox(0.3, 0.3).polygon);
    // A box resting 0.45 above a floor: the first axis (vertical) already shows the gap.
    TextbookTrace trace;
    const TextbookResult above =
        TextbookCollide(floor, MakeTransform(Vec2{0.0, 0.0}, 0.0), box, MakeTransform(Vec2{-1.2, 1.0}, 0.0), &trace);
    CHECK_FALSE(above.overlap);
    CHECK(above.axisCount == 2);
    CHECK(above.axesTested <= 2);
    const TextbookAxis& last = trace.axes.back();
    CHECK(last.separating);
    CHECK(last.faceCount == 4); // both boxes' faces on that line
    CHECK(above.gap == Approx(0.45).margin(1e-15));
    CHECK(above.normal.y == Approx(1.0));

    const TextbookResult turned =
        TextbookCollide(floor, MakeTransform(Vec2{0.0, 0.0}, 0.0), box, MakeTransform(Vec2{0.5, 0.4}, 0.3));
    CHECK(turned.overlap);
    CHECK(turned.axisCount == 4);
    CHECK(turned.axesTested == 4);
}

TEST_CASE("Textbook MTV on the two mirrored triangles that tie on their diagonals", "[textbook]")
{
    const Shape a = MakeShape(MakePolygon<double>({{0, 0}, {2, 0}, {0, 2}}).polygon);
    const Shape b = MakeShape(MakePolygon<double>({{1, 0}, {3, 0}, {3, 2}}).polygon);
    const Transform at = MakeTransform(Vec2{0.0, 0.0}, 0.0);
    TextbookTrace trace;
    const TextbookResult t = TextbookCollide(a, at, b, at, &trace);
    REQUIRE(t.overlap);
    // The diagonals x + y = 2 and x - y = 1 are distinct axes; the base y = 0 is shared: 4 axes in all.
    CHECK(t.axisCount == 4);
    const Manifold m = Collide(a.polygon, at, b.polygon, at);
    CHECK(t.depth == Approx(m.depth).margin(1e-15));
    // The diagonals tie; the first of them in the test order decides, A's, as A's face is Collide's reference face.
    const TextbookAxis& best = trace.axes[static_cast<size_t>(t.axis)];
    CHECK(best.faces[0].shape == 0);
    CHECK(best.faces[0].index == 1);
    CHECK(t.normal == m.normal);
    // The push of B by depth * normal leaves the triangles touching, and a hair more separates them.
    const Transform pushed = MakeTransform(t.depth * t.normal, 0.0);
    const Reference touching = ReferenceCollide(a, at, b, pushed);
    CHECK(std::abs(static_cast<double>(touching.separation)) <= 1e-15);
    CHECK(!ReferenceCollide(a, at, b, MakeTransform((t.depth + 1e-12) * t.normal, 0.0)).overlap);
}

TEST_CASE("The textbook swept test gives Sweep's status and time of impact on random moving pairs",
          "[textbook][sweep][properties]")
{
    Rng rng(4343);
    int compared = 0;
    int hits = 0;
    double maxError = 0.0;
    for (int i = 0; i < 30000; ++i)
    {
        const RandomPair pair = SmallPair(rng, 0.0);
        const Vec2 toward = pair.xfA.p - pair.xfB.p;
        const double k = rng.Uniform(0.2, 1.5) * rng.LogUniform(-1.0, 3.0);
        const double s = rng.Uniform(-0.5, 0.5);
        const Vec2 v = k * toward + (s * k) * LeftPerp(toward);
        const Vec2 vA = rng.Chance(0.5) ? Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)} : Vec2{};
        TextbookSweepTrace trace;
        const TextbookSweepResult t = TextbookSweep(pair.a, pair.xfA, vA, pair.b, pair.xfB, vA + v, &trace);
        const TextbookSweepResult plain = TextbookSweep(pair.a, pair.xfA, vA, pair.b, pair.xfB, vA + v);
        INFO("pair " << i);
        REQUIRE(t.status == plain.status);
        REQUIRE(SameBits(t.toi, plain.toi));
        REQUIRE(SameBits(t.normal, plain.normal));
        const SweepReference ref = ReferenceSweep(pair.a.polygon, pair.xfA, pair.b.polygon, pair.xfB, v);
        const double enter = static_cast<double>(ref.enter);
        if (std::abs(static_cast<double>(ref.startSeparation)) < 1e-12 || std::abs(enter - 1.0) < 1e-12 ||
            std::abs(static_cast<double>(ref.leave - ref.enter)) < 1e-12)
        {
            continue;
        }
        ++compared;
        const SweepResult fast = Sweep(pair.a, pair.xfA, vA, pair.b, pair.xfB, vA + v);
        REQUIRE(t.status == fast.status);
        if (ref.insideAtStart)
        {
            REQUIRE(t.status == SweepStatus::Overlapping);
            continue;
        }
        const bool hit = ref.crosses && ref.enter <= 1 && ref.leave > 0;
        REQUIRE((t.status == SweepStatus::Hit) == hit);
        if (hit)
        {
            ++hits;
            const double expected = std::max(0.0, enter);
            maxError = std::max(maxError, std::abs(t.toi - expected));
            REQUIRE(std::abs(t.toi - expected) <= 1e-12);
            REQUIRE(Length(t.normal - fast.normal) <= 1e-9);
            // The trace's windows: the hit is the latest entry, before the earliest exit.
            const TextbookSweepAxis& lastAxis = trace.axes.back();
            REQUIRE(trace.axes[static_cast<size_t>(lastAxis.latestEntry)].entry == t.toi);
            REQUIRE(trace.axes[static_cast<size_t>(lastAxis.earliestExit)].exit > t.toi);
        }
    }
    WARN("compared " << compared << " sweeps, " << hits << " hits, max |t error| " << maxError);
    CHECK(compared > 29000);
    CHECK(hits > 5000);
}

TEST_CASE("Textbook sweeps of circle pairs test the fixed axes, then cast against the rounded outline",
          "[textbook][sweep][circle]")
{
    Rng rng(99);
    int proved = 0;
    for (int i = 0; i < 20000; ++i)
    {
        RandomPair pair = SmallPair(rng, 0.6);
        if (pair.a.type == ShapeType::Polygon && pair.b.type == ShapeType::Polygon)
        {
            continue;
        }
        const Vec2 v = rng.Uniform(0.5, 3.0) * (pair.xfA.p - pair.xfB.p) + Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)};
        TextbookSweepTrace trace;
        const TextbookSweepResult t = TextbookSweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, v, &trace);
        const SweepResult fast = Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, v);
        INFO("pair " << i);
        // A miss proved on a fixed axis is a true miss; otherwise the cast's answer, bit for bit.
        if (trace.exit != SweepExit::RoundedOutline)
        {
            ++proved;
            REQUIRE(t.status == SweepStatus::Miss);
            REQUIRE(fast.status != SweepStatus::Hit);
            continue;
        }
        REQUIRE(t.status == fast.status);
        if (t.status == SweepStatus::Hit)
        {
            REQUIRE(SameBits(t.toi, fast.toi));
            REQUIRE(SameBits(t.normal, fast.normal));
            REQUIRE((t.corner.kind == AxisKind::None) == (fast.axis.kind == AxisKind::FaceNormal));
            if (t.axis >= 0)
            {
                bool found = false;
                for (int f = 0; f < trace.axes[static_cast<size_t>(t.axis)].faceCount; ++f)
                {
                    found = found || SameAxisRef(trace.axes[static_cast<size_t>(t.axis)].faces[f], fast.axis);
                }
                REQUIRE(found);
            }
        }
    }
    CHECK(proved > 100);
}

TEST_CASE("Lattice boxes that touch exactly overlap with depth 0 in the textbook test, a fraction apart they do not",
          "[textbook][touching]")
{
    // Shapes are closed sets: touching shapes overlap, with depth 0. Uncut lattice boxes, one set against a face of
    // the other (support/lattice.h), have axis-aligned faces only, so every projection is exact and the gap on the
    // deciding axis is exactly 0; the exact reference says whether the pair as built touches.
    Rng rng(20261127);
    int touching = 0;
    for (int i = 0; i < 3000; ++i)
    {
        const Contact contact = static_cast<Contact>(i % 3);
        const LatticePair pair = TouchingLatticePair(rng, contact, true);
        const Shape a = MakeShape(pair.a);
        const Shape b = MakeShape(pair.b);
        const Reference ref = ReferenceCollide(a, pair.xfA, b, pair.xfB);
        INFO("pair " << i << ", contact " << static_cast<int>(contact) << ", face " << pair.face);
        REQUIRE(ref.overlap == (contact != Contact::Apart));
        // The offset out or in is 1/8 of a lattice step along an axis-aligned normal.
        const double offset = Length(pair.offset);
        for (int order = 0; order < 2; ++order)
        {
            const TextbookResult t = order == 0 ? TextbookCollide(a, pair.xfA, b, pair.xfB)
                                                : TextbookCollide(b, pair.xfB, a, pair.xfA);
            REQUIRE(t.overlap == ref.overlap);
            if (contact == Contact::Touching)
            {
                REQUIRE(t.depth == 0.0);
                REQUIRE(t.axesTested == t.axisCount);
            }
            else if (contact == Contact::Apart)
            {
                REQUIRE(t.gap == offset);
            }
            else
            {
                REQUIRE(t.depth <= offset);
            }
        }
        touching += contact == Contact::Touching ? 1 : 0;
    }
    REQUIRE(touching == 1000);
}

TEST_CASE("Circles touching each other or a box's face overlap with depth 0 in the textbook test",
          "[textbook][touching]")
{
    // Radii and centres in whole units: the centres lie exactly the sum of the radii apart, on an axis, so the
    // intervals meet end to end. Moved apart by 1/8 they are separated by exactly 1/8; moved in, they overlap by it.
    for (int radiusA = 1; radiusA <= 4; ++radiusA)
    {
        for (int radiusB = 1; radiusB <= 4; ++radiusB)
        {
            for (int axis = 0; axis < 4; ++axis)
            {
                const Vec2 along = axis == 0 ? Vec2{1, 0} : axis == 1 ? Vec2{0, 1} : axis == 2 ? Vec2{-1, 0} : Vec2{0, -1};
                for (int shift = -1; shift <= 1; ++shift)
                {
                    const double distance = radiusA + radiusB + shift / 8.0;
                    INFO("radii " << radiusA << " and " << radiusB << ", axis " << axis << ", shift " << shift);
                    // Two discs.
                    const Shape discA = DiscShape(radiusA);
                    const Shape discB = DiscShape(radiusB);
                    const Transform xfA = At(3, -2);
                    const Transform xfB = At(3 + distance * along.x, -2 + distance * along.y);
                    TextbookResult t = TextbookCollide(discA, xfA, discB, xfB);
                    REQUIRE(t.overlap == (shift <= 0));
                    REQUIRE((t.overlap ? -t.depth : t.gap) == shift / 8.0);
                    // A disc against the face of a box of half-width radiusA: the face at radiusA from its centre.
                    const Shape box = BoxShape(radiusA, radiusA);
                    t = TextbookCollide(box, xfA, discB, xfB);
                    REQUIRE(t.overlap == (shift <= 0));
                    REQUIRE((t.overlap ? -t.depth : t.gap) == shift / 8.0);
                    t = TextbookCollide(discB, xfB, box, xfA);
                    REQUIRE(t.overlap == (shift <= 0));
                    REQUIRE((t.overlap ? -t.depth : t.gap) == shift / 8.0);
                }
            }
        }
    }
}

TEST_CASE("Boxes passing corner to corner graze in the textbook sweep: a miss, and a 64th closer a hit",
          "[textbook][sweep]")
{
    // A is the square [-1, 1]^2. B, the same square, starts centred at (-4, y0) and moves by (4, 4) over the step. On
    // x the intervals overlap for t in (1/2, 3/2); on y, with y0 = 0, for t in (-1/2, 1/2): they share the instant
    // t = 1/2 only, when B's lower right corner is A's upper left corner. With y0 = -1/64 the y overlap lasts until
    // t = 1/2 + 1/256: a hit at t = 1/2. Every number is a sum of powers of 2, exact. The scene is turned by each
    // quarter turn, which maps the lattice to itself exactly.
    const Shape box = BoxShape(1.0, 1.0);
    for (int turn = 0; turn < 4; ++turn)
    {
        const Rot q = QuarterTurn(turn);
        for (int closer = 0; closer < 2; ++closer)
        {
            const Vec2 start{-4.0, closer == 0 ? 0.0 : -1.0 / 64.0};
            const Vec2 v = Rotate(q, Vec2{4.0, 4.0});
            const Transform xfA{Vec2{}, q};
            const Transform xfB{Rotate(q, start), q};
            INFO("quarter turns " << turn << (closer == 0 ? ", grazing" : ", a 64th closer"));
            const TextbookSweepResult t = TextbookSweep(box, xfA, Vec2{}, box, xfB, v);
            REQUIRE(t.status == (closer == 0 ? SweepStatus::Miss : SweepStatus::Hit));
            if (closer == 1)
            {
                REQUIRE(t.toi == 0.5);
            }
            // B standing still and A moving the other way is the same motion.
            const TextbookSweepResult back = TextbookSweep(box, xfB, Vec2{}, box, xfA, -v);
            REQUIRE(back.status == t.status);
        }
    }
}
