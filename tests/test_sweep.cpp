// SPDX-License-Identifier: MIT
// The swept test: no tunnelling at any speed, exact times of impact, grazing and sliding are not hits.

#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/reference.h"
#include "support/same_bits.h"
#include "support/sweep_oracle.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

using namespace satviz;
using namespace satviz::testing;
using Catch::Matchers::WithinAbs;

namespace
{

const Vec2 kStill{0.0, 0.0};

} // namespace

TEST_CASE("A projectile never tunnels through a thin wall, at any speed and angle", "[sweep]")
{
    // The wall is 1e-3 thick and 20 tall; the projectile a 0.01 box. Each shot is aimed to reach the wall at a
    // random time in the step; the analytic time comes from the leading face's distance over the closing speed.
    const Shape wall = BoxShape(5e-4, 10.0);
    const Shape bullet = BoxShape(0.005, 0.005);
    Rng rng(31);
    for (double speed = 1.0; speed <= 1e6; speed *= 10.0)
    {
        for (int k = 0; k < 2000; ++k)
        {
            const double angle = rng.Uniform(-1.4, 1.4); // up to 80 degrees off the wall's normal
            const Vec2 v{speed * std::cos(angle), speed * std::sin(angle)};
            const double hitTime = rng.Uniform(0.001, 0.999);
            const double yAtHit = rng.Uniform(-5.0, 5.0);
            const Vec2 start{-5e-4 - 0.005 - hitTime * v.x, yAtHit - hitTime * v.y};
            // The analytic time for the start position as rounded to doubles, in quad precision.
            const Quad expected = (Quad(-5e-4) - Quad(0.005) - Quad(start.x)) / Quad(v.x);
            INFO("speed " << speed << ", angle " << angle << ", start " << start.x << ", " << start.y);
            const SweepResult r = Sweep(wall, At(0, 0), kStill, bullet, At(start.x, start.y), v);
            REQUIRE(r.status == SweepStatus::Hit);
            REQUIRE(std::abs(r.toi - static_cast<double>(expected)) <= 1e-12 * static_cast<double>(expected));
            REQUIRE(r.normal == Vec2{-1.0, 0.0});
            REQUIRE(r.contactCount >= 1);
            // Either way round: the wall moving onto a resting bullet, in the bullet's terms.
            const SweepResult reverse = Sweep(bullet, At(start.x, start.y), kStill, wall, At(0, 0), -v);
            REQUIRE(reverse.status == SweepStatus::Hit);
            REQUIRE(std::abs(reverse.toi - r.toi) <= 1e-12 * r.toi);
        }
    }
}

TEST_CASE("A fast circle hits a thin wall at the analytic time", "[sweep][circle]")
{
    const Shape wall = BoxShape(5e-4, 10.0);
    const Shape ball = DiscShape(0.005);
    for (double speed : {1.0, 1e3, 1e6})
    {
        const Vec2 v{speed, 0.0};
        const double start = -5e-4 - 0.005 - 0.25 * speed;
        const SweepResult r = Sweep(wall, At(0, 0), kStill, ball, At(start, 0.3), v);
        REQUIRE(r.status == SweepStatus::Hit);
        CHECK_THAT(r.toi, WithinAbs(0.25, 1e-12));
        CHECK(r.normal == Vec2{-1.0, 0.0});
    }
}

TEST_CASE("Grazing a corner and sliding along a face are not hits", "[sweep]")
{
    const Shape a = BoxShape(1.0, 1.0);
    const Shape b = BoxShape(0.5, 0.5);
    // B's lower right corner passes exactly through A's upper left corner (-1, 1), moving up and right.
    const SweepResult graze = Sweep(a, At(0, 0), kStill, b, At(-2.5, 0.5), Vec2{2.0, 2.0});
    CHECK(graze.status == SweepStatus::Miss);
    // A little lower, the corner cuts in: it first touches A's left face when it reaches x = -1.
    const SweepResult cut = Sweep(a, At(0, 0), kStill, b, At(-2.5, 0.5 - 1e-6), Vec2{2.0, 2.0});
    CHECK(cut.status == SweepStatus::Hit);
    CHECK_THAT(cut.toi, WithinAbs(0.5, 1e-15));
    CHECK(cut.normal == Vec2{-1.0, 0.0});
    // Resting on A's top face and sliding along it.
    const SweepResult slide = Sweep(a, At(0, 0), kStill, b, At(-0.5, 1.5), Vec2{3.0, 0.0});
    CHECK(slide.status == SweepStatus::Miss);
    // Touching and moving in is a hit at t = 0; touching and moving away is not.
    const SweepResult in = Sweep(a, At(0, 0), kStill, b, At(0.0, 1.5), Vec2{0.0, -1.0});
    CHECK(in.status == SweepStatus::Hit);
    CHECK(in.toi == 0.0);
    CHECK(Sweep(a, At(0, 0), kStill, b, At(0.0, 1.5), Vec2{0.0, 1.0}).status == SweepStatus::Miss);
    // A ball grazing the rounded corner of a box along a tangent.
    const SweepResult tangent = Sweep(a, At(0, 0), kStill, DiscShape(0.5), At(-3.0, 1.5), Vec2{6.0, 0.0});
    CHECK(tangent.status == SweepStatus::Miss);
}

TEST_CASE("Without motion the static test decides, overlapping shapes report their MTV", "[sweep]")
{
    const Shape a = BoxShape(1.0, 1.0);
    const Shape b = BoxShape(0.5, 0.5);
    SweepTrace trace;
    const SweepResult still = Sweep(a, At(0, 0), Vec2{1.0, 1.0}, b, At(1.3, 0.2), Vec2{1.0, 1.0}, &trace);
    CHECK(still.status == SweepStatus::Overlapping);
    CHECK(trace.exit == SweepExit::NotMoving);
    CHECK(trace.axes.empty());
    CHECK_THAT(still.initial.depth, WithinAbs(0.2, 1e-15));
    CHECK(still.normal == Vec2{1.0, 0.0});
    CHECK(Sweep(a, At(0, 0), kStill, b, At(3.0, 0.0), kStill).status == SweepStatus::Miss);
    // Overlapping at the start while moving: still reported as overlapping, not as a hit.
    const SweepResult moving = Sweep(a, At(0, 0), kStill, b, At(1.3, 0.2), Vec2{-5.0, 0.0});
    CHECK(moving.status == SweepStatus::Overlapping);
    CHECK(moving.toi == 0.0);
}

TEST_CASE("Circle sweeps against circles and rounded corners", "[sweep][circle]")
{
    // Two discs closing head on: radii 1 and 0.5, centres 4 apart, closing at 5 per step: contact at t = 0.5.
    const SweepResult head =
        Sweep(DiscShape(1.0), At(0, 0), Vec2{2.0, 0.0}, DiscShape(0.5), At(4.0, 0.0), Vec2{-3.0, 0.0});
    REQUIRE(head.status == SweepStatus::Hit);
    CHECK_THAT(head.toi, WithinAbs(0.5, 1e-15));
    CHECK(head.normal == Vec2{1.0, 0.0});
    CHECK_THAT(head.contacts[0].point.x, WithinAbs(2.0, 1e-15));

    // A disc of radius 0.5 moving left at height 1.3 meets the box's rounded corner at (1, 1): its centre is then
    // 0.5 from the corner, at x = 1 + sqrt(0.25 - 0.09) = 1.4.
    const Shape box = BoxShape(1.0, 1.0);
    const SweepResult corner = Sweep(box, At(0, 0), kStill, DiscShape(0.5), At(3.0, 1.3), Vec2{-4.0, 0.0});
    REQUIRE(corner.status == SweepStatus::Hit);
    CHECK_THAT(corner.toi, WithinAbs((3.0 - 1.4) / 4.0, 1e-15));
    CHECK(corner.axis.kind == AxisKind::VertexToCenter);
    CHECK_THAT(corner.normal.x, WithinAbs(0.8, 1e-15));
    CHECK_THAT(corner.normal.y, WithinAbs(0.6, 1e-15));
    // The same with the disc as A: the normal points from the disc to the box.
    const SweepResult swapped = Sweep(DiscShape(0.5), At(3.0, 1.3), Vec2{-4.0, 0.0}, box, At(0, 0), kStill);
    REQUIRE(swapped.status == SweepStatus::Hit);
    CHECK(swapped.toi == corner.toi);
    CHECK(swapped.normal == -corner.normal);
    // Passing the corner diagonally 0.55 from it: a miss, though the face planes pushed out by the radius (a
    // sharp corner at (1.5, 1.5)) would call it a hit.
    const double d = 0.55 / std::sqrt(2.0);
    const SweepResult past = Sweep(box, At(0, 0), kStill, DiscShape(0.5), At(2.0 + d, d), Vec2{-2.0, 2.0});
    CHECK(past.status == SweepStatus::Miss);
    const SweepResult closer = Sweep(box, At(0, 0), kStill, DiscShape(0.5), At(1.9 + d, d - 0.1), Vec2{-2.0, 2.0});
    CHECK(closer.status == SweepStatus::Hit);
}

TEST_CASE("Sweep agrees with the Minkowski-difference cast on random moving pairs", "[sweep][properties]")
{
    Rng rng(4242);
    int hits = 0;
    int compared = 0;
    double maxError = 0.0;
    double maxContactOff = 0.0;
    for (int i = 0; i < 100000; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.0);
        const Vec2 toward = pair.xfA.p - pair.xfB.p;
        const double k = rng.Uniform(0.2, 1.5) * rng.LogUniform(-1.0, 3.0);
        const double s = rng.Uniform(-0.5, 0.5);
        const Vec2 v = k * toward + (s * k) * LeftPerp(toward);
        const Vec2 vA = rng.Chance(0.5) ? Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)} : kStill;
        const SweepResult r = Sweep(pair.a, pair.xfA, vA, pair.b, pair.xfB, vA + v);
        const SweepReference ref = ReferenceSweep(pair.a.polygon, pair.xfA, pair.b.polygon, pair.xfB, v);
        INFO("pair " << i);
        // Pairs within 1e-12 of a boundary case (touching at the start, grazing, hitting at t = 1) may go either way.
        const double startMargin = static_cast<double>(ref.startSeparation);
        const double enter = static_cast<double>(ref.enter);
        const double span = static_cast<double>(ref.leave - ref.enter);
        if (std::abs(startMargin) < 1e-12 || std::abs(enter - 1.0) < 1e-12 || std::abs(span) < 1e-12)
        {
            continue;
        }
        ++compared;
        if (ref.insideAtStart)
        {
            REQUIRE(r.status == SweepStatus::Overlapping);
            continue;
        }
        const bool hit = ref.crosses && ref.enter <= 1 && ref.leave > 0;
        REQUIRE((r.status == SweepStatus::Hit) == hit);
        if (hit)
        {
            ++hits;
            const double expected = std::max(0.0, enter);
            maxError = std::max(maxError, std::abs(r.toi - expected));
            REQUIRE(std::abs(r.toi - expected) <= 1e-12);
            // Every contact point lies on both outlines at the time of impact, up to the error of t times the
            // speed, and the rounding of the coordinates.
            REQUIRE(r.contactCount >= 1);
            const Transform atA{pair.xfA.p + r.toi * vA, pair.xfA.q};
            const Transform atB{pair.xfB.p + r.toi * (vA + v), pair.xfB.q};
            const std::vector<QVec> outlineA = QWorld(pair.a.polygon, atA);
            const std::vector<QVec> outlineB = QWorld(pair.b.polygon, atB);
            const double tolerance = 1e-12 * (1.0 + Length(v) + Length(vA) + Length(pair.xfB.p - pair.xfA.p));
            for (int c = 0; c < r.contactCount; ++c)
            {
                const QVec point{r.contacts[c].point.x, r.contacts[c].point.y};
                const double offA = std::abs(static_cast<double>(SignedDistance(outlineA, point)));
                const double offB = std::abs(static_cast<double>(SignedDistance(outlineB, point)));
                maxContactOff = std::max({maxContactOff, offA / tolerance, offB / tolerance});
                REQUIRE(offA <= tolerance);
                REQUIRE(offB <= tolerance);
            }
        }
    }
    WARN("compared " << compared << " pairs, " << hits << " hits, max |t error| " << maxError
                     << ", contacts off the outlines by at most " << maxContactOff << " of the tolerance");
    CHECK(compared > 99000);
    CHECK(hits > 20000);
}

TEST_CASE("Traced and untraced sweeps are bit-identical, the trace follows the entries and exits", "[sweep][trace]")
{
    Rng rng(77);
    SweepTrace trace;
    for (int i = 0; i < 20000; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.0);
        const Vec2 v = rng.Uniform(0.2, 3.0) * (pair.xfA.p - pair.xfB.p);
        const SweepResult plain = Sweep(pair.a, pair.xfA, kStill, pair.b, pair.xfB, v);
        const SweepResult traced = Sweep(pair.a, pair.xfA, kStill, pair.b, pair.xfB, v, &trace);
        INFO("pair " << i);
        REQUIRE(plain.status == traced.status);
        REQUIRE(std::memcmp(&plain.toi, &traced.toi, sizeof plain.toi) == 0);
        REQUIRE(plain.normal == traced.normal);
        REQUIRE(plain.contactCount == traced.contactCount);
        REQUIRE_FALSE(trace.axes.empty());
        const SweepAxis& last = trace.axes.back();
        if (plain.status == SweepStatus::Hit)
        {
            REQUIRE(trace.exit == SweepExit::AllAxesOverlap);
            REQUIRE(trace.axes[last.latestEntry].entry == plain.toi);
            REQUIRE(trace.axes[last.latestEntry].axis.index == plain.axis.index);
        }
        if (plain.status == SweepStatus::Miss)
        {
            // One face ends the test; against a large polygon, faces evaluated with it or decided without
            // evaluation may follow it.
            REQUIRE(std::count_if(trace.axes.begin(), trace.axes.end(),
                                  [](const SweepAxis& a) { return a.endsTest; }) == 1);
        }
        for (const SweepAxis& axis : trace.axes)
        {
            REQUIRE(axis.sweptMinB <= axis.minB);
            REQUIRE(axis.sweptMaxB >= axis.maxB);
            REQUIRE(std::abs((axis.minB - axis.maxA) - axis.separation) < 1e-12);
        }
    }
}

TEST_CASE("SweepTime answers as Sweep, bit for bit, without contact points", "[sweep][properties]")
{
    Rng rng(91);
    SweepTrace full;
    SweepTrace timeOnly;
    int hits = 0;
    for (int i = 0; i < 50000; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.2);
        const Vec2 v =
            rng.Uniform(0.2, 3.0) * (pair.xfA.p - pair.xfB.p) + rng.Uniform(-0.5, 0.5) * LeftPerp(pair.xfA.p);
        const Vec2 vA = rng.Chance(0.5) ? Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)} : kStill;
        const bool traced = rng.Chance(0.2);
        const SweepResult sweep = Sweep(pair.a, pair.xfA, vA, pair.b, pair.xfB, vA + v, traced ? &full : nullptr);
        const SweepResult time =
            SweepTime(pair.a, pair.xfA, vA, pair.b, pair.xfB, vA + v, traced ? &timeOnly : nullptr);
        INFO("pair " << i);
        REQUIRE(time.status == sweep.status);
        REQUIRE(std::memcmp(&time.toi, &sweep.toi, sizeof time.toi) == 0);
        REQUIRE(std::memcmp(&time.normal, &sweep.normal, sizeof time.normal) == 0);
        REQUIRE(time.axis.kind == sweep.axis.kind);
        REQUIRE(time.axis.shape == sweep.axis.shape);
        REQUIRE(time.axis.index == sweep.axis.index);
        if (sweep.status == SweepStatus::Hit)
        {
            ++hits;
            REQUIRE(sweep.contactCount > 0);
            REQUIRE(time.contactCount == 0);
        }
        if (sweep.status == SweepStatus::Overlapping)
        {
            // The static manifold's depth and normal, without its contact points.
            REQUIRE(std::memcmp(&time.initial.depth, &sweep.initial.depth, sizeof time.initial.depth) == 0);
            REQUIRE(std::memcmp(&time.initial.normal, &sweep.initial.normal, sizeof time.initial.normal) == 0);
            REQUIRE(sweep.initial.contactCount > 0);
            REQUIRE(time.initial.contactCount == 0);
            REQUIRE(time.initial.incidentEdge == -1);
        }
        if (traced)
        {
            REQUIRE(timeOnly.exit == full.exit);
            REQUIRE(timeOnly.axes.size() == full.axes.size());
        }
        // The float instantiation agrees with its own Sweep too.
        const ShapeT<float> af = ToFloat(pair.a);
        const ShapeT<float> bf = ToFloat(pair.b);
        if ((af.type == ShapeType::Polygon && af.polygon.Count() == 0) ||
            (bf.type == ShapeType::Polygon && bf.polygon.Count() == 0))
        {
            continue;
        }
        const Vec2T<float> vAf = ConvertVec<float>(vA);
        const Vec2T<float> vBf = ConvertVec<float>(vA + v);
        const SweepResultT<float> sweepF = Sweep(af, ToFloat(pair.xfA), vAf, bf, ToFloat(pair.xfB), vBf);
        const SweepResultT<float> timeF = SweepTime(af, ToFloat(pair.xfA), vAf, bf, ToFloat(pair.xfB), vBf);
        REQUIRE(timeF.status == sweepF.status);
        REQUIRE(std::memcmp(&timeF.toi, &sweepF.toi, sizeof timeF.toi) == 0);
        REQUIRE(std::memcmp(&timeF.normal, &sweepF.normal, sizeof timeF.normal) == 0);
    }
    CHECK(hits > 10000);
}

TEST_CASE("An interpenetrating start reports Collide's manifold, bit for bit, SweepTime without contacts",
          "[sweep][properties]")
{
    // The sweep builds the static manifold from the separations its own face loops computed; Collide computes them
    // again. SweepTime's carries no contact points. Random overlapping contact pairs of every scanned size and a few
    // walked ones, and exact pairs: boxes turned by multiples of 90 degrees (faces anti-parallel, which Collide's
    // second pass skips) and the mirrored right triangles whose diagonals tie exactly.
    Rng rng(20261126);
    const auto check = [](const RandomPair& pair, Vec2 v) {
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        if (!(m.overlap && m.depth > 0.0))
        {
            return false;
        }
        Manifold withoutContacts = m;
        withoutContacts.contacts[0] = {};
        withoutContacts.contacts[1] = {};
        withoutContacts.contactCount = 0;
        withoutContacts.incidentEdge = -1;
        SweepTrace trace;
        for (const bool traced : {false, true})
        {
            INFO((traced ? "traced" : "untraced"));
            const SweepResult sweep = Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, v, traced ? &trace : nullptr);
            const SweepResult time =
                SweepTime(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, v, traced ? &trace : nullptr);
            REQUIRE(SameBits(sweep.initial, m));
            REQUIRE(SameBits(time.initial, withoutContacts));
            for (const SweepResult& r : {sweep, time})
            {
                REQUIRE(r.status == SweepStatus::Overlapping);
                REQUIRE(SameBits(r.normal, m.normal));
                REQUIRE(r.axis.shape == m.axis.shape);
                REQUIRE(r.axis.index == m.axis.index);
            }
        }
        return true;
    };
    int checked = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const int counts[] = {3, 4, 5, 6, 7, 8, 11, 16, 24};
        const RandomPair pair = ContactPair(rng, counts[rng.Int(0, 8)], PairCategory::Overlap, 0.05);
        const Vec2 v{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)};
        INFO("pair " << i);
        checked += check(pair, v) ? 1 : 0;
    }
    for (int i = 0; i < 2000; ++i)
    {
        RandomPair pair;
        pair.a = BoxShape(rng.Uniform(0.2, 1.5), rng.Uniform(0.2, 1.5));
        pair.b = BoxShape(rng.Uniform(0.2, 1.5), rng.Uniform(0.2, 1.5));
        const double quarter = 0.5 * kPi;
        pair.xfA = At(rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0), quarter * rng.Int(0, 3));
        pair.xfB =
            At(pair.xfA.p.x + rng.Uniform(-1.0, 1.0), pair.xfA.p.y + rng.Uniform(-1.0, 1.0), quarter * rng.Int(0, 3));
        INFO("box pair " << i);
        checked += check(pair, Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}) ? 1 : 0;
    }
    RandomPair triangles;
    triangles.a = MakeShape(MakePolygon(std::vector<Vec2>{{0, 0}, {2, 0}, {0, 2}}).polygon);
    triangles.b = MakeShape(MakePolygon(std::vector<Vec2>{{1, 0}, {3, 0}, {3, 2}}).polygon);
    triangles.xfA = At(0, 0);
    triangles.xfB = At(0, 0);
    REQUIRE(check(triangles, Vec2{0.5, 0.25}));
    CHECK(checked > 15000);
}

TEST_CASE("Circle sweeps are traced axis by axis", "[sweep][circle][trace]")
{
    const Shape box = BoxShape(1.0, 1.0);
    SweepTrace trace;
    const SweepResult corner = Sweep(box, At(0, 0), kStill, DiscShape(0.5), At(3.0, 1.3), Vec2{-4.0, 0.0}, &trace);
    REQUIRE(corner.status == SweepStatus::Hit);
    CHECK(trace.exit == SweepExit::RoundedOutline);
    // The four faces of the box, then the corner's vertex axis that decided.
    REQUIRE(trace.axes.size() == 5);
    CHECK(trace.axes[4].axis.kind == AxisKind::VertexToCenter);
    CHECK(trace.axes[4].direction == corner.normal);
    // The right face's interval entry is earlier than the hit: the sharp corner is met before the rounded one.
    const SweepAxis& right = trace.axes[1];
    CHECK(right.direction == Vec2{1.0, 0.0});
    CHECK_THAT(right.entry, WithinAbs((3.0 - 1.5) / 4.0, 1e-15));
    CHECK(right.entry < corner.toi);

    const SweepResult discs =
        Sweep(DiscShape(1.0), At(0, 0), kStill, DiscShape(0.5), At(4.0, 0.0), Vec2{-5.0, 0.0}, &trace);
    REQUIRE(discs.status == SweepStatus::Hit);
    REQUIRE(trace.axes.size() == 1);
    CHECK(trace.axes[0].axis.kind == AxisKind::CenterToCenter);
    CHECK_THAT(trace.axes[0].entry, WithinAbs(discs.toi, 1e-15));
}

namespace
{

// Tallies of the large-polygon sweeps checked against the full face loop.
struct LargeSweepTally
{
    int hits = 0;
    int misses = 0;
    int casts = 0;
    long evaluated = 0;    // steps of faces evaluated by a walked or bisected loop
    long bitwise = 0;      // of those, with the full loop's separation to the bit
    long bounded[3] = {};  // steps of faces not walked to: overlapping at t = 0, entry bounded, exit bounded
    long skipped = 0;      // steps of faces the bisection ruled out
    long scanned = 0;      // steps of faces of a scanned loop
    double worstTie = 0.0; // the largest difference from the full loop's separation, in units of its tolerance
    int ties = 0;          // pairs whose verdict or latest entry the separations the sweep took change
};

// A pair for the large-polygon sweeps: A of `n` vertices near B (a random polygon of `nB` vertices in half of the
// pairs, else as ContactPair made it), B pulled back from A and sent towards it (sometimes past it) or in any
// direction, at speeds from a tenth of the gap to 1000 times it; one motion in ten runs along a face of either
// polygon (a face whose rate rounds to 0, which never closes when the other polygon is beyond it), and in one pair
// in ten B slides along a face of A, placed on its line or just beyond it (a gap of up to 1e-9) or just inside it:
// then `sliding` (whether the motion's line meets A - B can then rest on rounding, which the cast does not model).
RandomPair LargeSweepPair(Rng& rng, int n, int nB, Vec2& v, bool& sliding)
{
    RandomPair pair = ContactPair(rng, n, static_cast<PairCategory>(rng.Int(0, 2)), 0.1);
    if (rng.Chance(0.5))
    {
        pair.b =
            MakeShape(RandomPolygon(rng, nB, rng.Uniform(0.05, 1.5), rng.Chance(0.2) ? 0.05 : rng.Uniform(0.35, 1.0)));
    }
    const Vec2 toward =
        TransformPoint(pair.xfA, pair.a.polygon.Centroid()) - TransformPoint(pair.xfB, pair.b.polygon.Centroid());
    pair.xfB.p = pair.xfB.p - rng.Uniform(0.0, 2.0) * toward;
    const double k = rng.Uniform(0.5, 3.0) * rng.LogUniform(-1.0, 3.0);
    const double angle = rng.Uniform(-kPi, kPi);
    v = rng.Chance(0.3) ? k * toward + (rng.Uniform(-0.5, 0.5) * k) * LeftPerp(toward)
                        : k * Length(toward) * Vec2{std::cos(angle), std::sin(angle)};
    if (rng.Chance(0.1))
    {
        const bool onA = rng.Chance(0.5);
        const Polygon& along = onA ? pair.a.polygon : pair.b.polygon;
        const Vec2 edge = Rotate((onA ? pair.xfA : pair.xfB).q, along.Edge(rng.Int(0, along.Count() - 1)));
        v = (rng.Chance(0.5) ? k : -k) * (Length(toward) / Length(edge)) * edge;
    }
    sliding = rng.Chance(0.1);
    if (sliding)
    {
        // B's lowest vertex towards face f of A put on the face's line (offset along it from before its start to
        // past its end), then moved off it by the gap; the motion runs along the face, over it or away from it.
        const Polygon& a = pair.a.polygon;
        const Polygon& b = pair.b.polygon;
        const int f = rng.Int(0, a.Count() - 1);
        const Vec2 n = Rotate(pair.xfA.q, a.Normal(f));
        const Vec2 edge = Rotate(pair.xfA.q, a.Edge(f));
        int lowest = 0;
        for (int j = 1; j < b.Count(); ++j)
        {
            if (Dot(n, Rotate(pair.xfB.q, b.Vertices()[j])) < Dot(n, Rotate(pair.xfB.q, b.Vertices()[lowest])))
            {
                lowest = j;
            }
        }
        const double gap = rng.Chance(0.3) ? 0.0 : rng.Uniform(-1e-9, 1e-9);
        const Vec2 on = TransformPoint(pair.xfA, a.Vertices()[f]) + rng.Uniform(-2.0, 1.0) * edge + gap * n;
        pair.xfB.p = on - Rotate(pair.xfB.q, b.Vertices()[lowest]);
        v = rng.Uniform(0.5, 3.0) * (rng.Chance(0.5) ? 1.0 : -1.0) * edge;
    }
    return pair;
}

// The pair with A and B swapped half of the time, `v` (B's motion relative to A) turned with it, so that either
// polygon may be the large one.
RandomPair EitherWay(Rng& rng, RandomPair pair, Vec2& v)
{
    if (rng.Chance(0.5))
    {
        std::swap(pair.a, pair.b);
        std::swap(pair.xfA, pair.xfB);
        v = -v;
    }
    return pair;
}

// Which face loop takes the faces of `ref` against `inc`: scanned (both small), walked (inc above 16 vertices), or
// bisected (ref above 256 faces).
enum class FaceLoop
{
    Scanned,
    Walked,
    Bisected,
};

FaceLoop LoopOf(const Polygon& ref, const Polygon& inc)
{
    return ref.Count() > 256 ? FaceLoop::Bisected : inc.Count() > 16 ? FaceLoop::Walked : FaceLoop::Scanned;
}

bool SameBits(double x, double y)
{
    return std::memcmp(&x, &y, sizeof x) == 0;
}

// The trace of a polygon sweep against the full face loop (support/sweep_oracle.h), step by step:
//   - every step is a face, with the full loop's rate to the bit, and its entry and exit as its separation and rate
//     give them (to the bit). A scanned face has the full loop's separation to the bit. A face evaluated by a walked
//     or bisected loop (and the numbers computed for the view of a flagged one) has the separation of one vertex of
//     the other polygon, never below the full loop's least one and within 8 eps of the coordinates' scale above it
//     (two vertices that tie on the normal up to rounding);
//   - a face flagged bounded was not walked to: its bound is no less than its separation (to the bit: the bound is
//     the same expression for one vertex), and what the bound showed holds: in the first pass, that it overlaps at
//     t = 0, or that its entry is at most the entry bound, which is before an entry known then, itself no later than
//     the latest entry; in the second pass, that it recedes and its exit is at least the exit bound, after the
//     latest entry. A face flagged skipped was not evaluated: on a hit, its entry is not after the time of impact,
//     nor its exit before the earliest exit the evaluated faces give;
//   - the first pass shows each face once at most, and on a hit every face of either polygon; on a hit the second
//     pass of a walked loop shows each face that recedes, once, and no other;
//   - the latest entry and the earliest exit point at faces evaluated; on a hit, the last step's latest entry is the
//     result's face at the time of impact, which are the full loop's; on a miss, one face evaluated ended the test
//     and the full loop misses for the reason the trace gives. Where two vertices tie on a face's normal the sweep
//     may take the other one: the verdict is that of the full loop with the separations the sweep took for the
//     faces it evaluated (`decided`), which are within the tolerance of the least ones (checked above), and to the
//     bit the same in all but a few faces (counted).
void CheckTraceAgainstOracle(const RandomPair& pair, Vec2 v, const SweepResult& result, const SweepTrace& trace,
                             LargeSweepTally& tally)
{
    const Polygon& a = pair.a.polygon;
    const Polygon& b = pair.b.polygon;
    const SweepOracle oracle = OracleSweep(a, pair.xfA, kStill, b, pair.xfB, v);
    SweepOracle decided = oracle;
    const int countA = a.Count();
    const bool hit = result.status == SweepStatus::Hit;
    const double infinity = std::numeric_limits<double>::infinity();
    std::vector<int> firstPass(oracle.faces.size(), 0);
    std::vector<int> exitPass(oracle.faces.size(), 0);
    int ends = 0;
    const SweepAxis& last = trace.axes.back();
    const double earliestExit = last.earliestExit >= 0 ? trace.axes[last.earliestExit].exit : infinity;
    for (size_t k = 0; k < trace.axes.size(); ++k)
    {
        const SweepAxis& step = trace.axes[k];
        INFO("step " << k << ": face " << step.axis.index << " of " << (step.axis.shape == 0 ? "A" : "B")
                     << (step.bounded ? ", bounded" : "") << (step.skipped ? ", skipped" : "")
                     << (step.exitPass ? ", second pass" : ""));
        REQUIRE(step.axis.kind == AxisKind::FaceNormal);
        const int side = step.axis.shape;
        const OracleFace& f = oracle.Face(side, step.axis.index, countA);
        const size_t index = static_cast<size_t>(side == 0 ? step.axis.index : countA + step.axis.index);
        const FaceLoop loop = side == 0 ? LoopOf(a, b) : LoopOf(b, a);
        const bool flagged = step.bounded || step.skipped;
        INFO("separation " << step.separation << ", full loop " << f.separation << ", rate " << f.rate << ", bound "
                           << step.bound << ", bound time " << step.boundTime << ", known entry " << step.knownEntry);
        REQUIRE_FALSE((step.bounded && step.skipped));
        REQUIRE((!step.bounded || loop == FaceLoop::Walked));
        REQUIRE((!step.exitPass || loop == FaceLoop::Walked));
        REQUIRE((!step.skipped || loop == FaceLoop::Bisected));
        REQUIRE((!flagged || !step.endsTest));
        // The numbers of the step.
        const double tolerance = 8.0 * std::numeric_limits<double>::epsilon() * f.scale;
        REQUIRE(SameBits(step.rate, f.rate));
        if (loop == FaceLoop::Scanned)
        {
            REQUIRE(SameBits(step.separation, f.separation));
            ++tally.scanned;
        }
        else
        {
            REQUIRE(step.separation >= f.separation);
            REQUIRE(step.separation - f.separation <= tolerance);
            tally.worstTie = std::max(tally.worstTie, (step.separation - f.separation) / tolerance);
            if (!flagged)
            {
                ++tally.evaluated;
                tally.bitwise += SameBits(step.separation, f.separation) ? 1 : 0;
                OracleFace& taken = decided.faces[index];
                taken.separation = step.separation;
                OracleTimes(taken.separation, taken.rate, taken.still, taken.entry, taken.exit, taken.never);
            }
        }
        double entry;
        double exit;
        bool never;
        OracleTimes(step.separation, step.rate, f.still, entry, exit, never);
        REQUIRE(SameBits(step.entry, never ? 0.0 : std::max(entry, 0.0)));
        REQUIRE(SameBits(step.exit, never ? infinity : exit));
        // What a flag says.
        if (step.bounded)
        {
            ++tally.bounded[step.exitPass ? 2 : step.bound < 0.0 ? 0 : 1];
            REQUIRE(step.bound >= f.separation);
            if (!step.exitPass && step.bound < 0.0)
            {
                REQUIRE(f.separation < 0.0);
                REQUIRE(step.boundTime == 0.0);
            }
            else if (!step.exitPass)
            {
                REQUIRE(f.rate < -f.still);
                REQUIRE(SameBits(step.boundTime, step.bound / -f.rate));
                REQUIRE(f.entry <= step.boundTime);
                REQUIRE(step.boundTime < step.knownEntry);
                if (hit)
                {
                    REQUIRE(step.knownEntry <= result.toi);
                }
            }
            else
            {
                REQUIRE(f.rate > f.still);
                REQUIRE(SameBits(step.boundTime, -step.bound / f.rate));
                REQUIRE(f.exit >= step.boundTime);
                REQUIRE(step.boundTime > step.knownEntry);
                if (hit)
                {
                    REQUIRE(step.knownEntry == result.toi);
                }
            }
        }
        if (step.skipped)
        {
            ++tally.skipped;
            if (hit)
            {
                REQUIRE(f.entry <= result.toi);
                REQUIRE(f.exit >= earliestExit);
            }
        }
        (step.exitPass ? exitPass : firstPass)[index] += 1;
        ends += step.endsTest ? 1 : 0;
        // The latest entry and earliest exit so far are faces evaluated.
        REQUIRE(step.latestEntry < static_cast<int>(k + 1));
        REQUIRE(step.earliestExit < static_cast<int>(k + 1));
        REQUIRE((step.latestEntry >= 0) == (step.earliestExit >= 0));
        if (step.latestEntry >= 0)
        {
            REQUIRE_FALSE(trace.axes[step.latestEntry].bounded);
            REQUIRE_FALSE(trace.axes[step.latestEntry].skipped);
            REQUIRE_FALSE(trace.axes[step.earliestExit].bounded);
            REQUIRE_FALSE(trace.axes[step.earliestExit].skipped);
        }
    }
    // Every face once in the first pass (all of them on a hit); the receding faces of a walked loop in the second.
    for (size_t i = 0; i < oracle.faces.size(); ++i)
    {
        const OracleFace& f = oracle.faces[i];
        INFO("face " << f.face << " of " << (f.side == 0 ? "A" : "B"));
        REQUIRE(firstPass[i] <= 1);
        REQUIRE(exitPass[i] <= 1);
        if (hit)
        {
            REQUIRE(firstPass[i] == 1);
            const bool walked = f.side == 0 ? LoopOf(a, b) == FaceLoop::Walked : LoopOf(b, a) == FaceLoop::Walked;
            REQUIRE(exitPass[i] == (walked && f.rate > f.still ? 1 : 0));
        }
    }
    // The verdict, and why.
    decided.Decide();
    const bool tie = decided.Hit() != oracle.Hit() || decided.firstFace != oracle.firstFace ||
                     !SameBits(decided.first, oracle.first) || decided.anyNever != oracle.anyNever;
    tally.ties += tie ? 1 : 0;
    INFO("full loop: latest entry " << oracle.first << " (face " << oracle.firstFace << "), earliest exit "
                                    << oracle.last << ", never " << oracle.anyNever
                                    << "; with the separations taken: " << decided.first << " (face "
                                    << decided.firstFace << "), " << decided.last << ", never " << decided.anyNever);
    REQUIRE(last.latestEntry >= 0);
    if (hit)
    {
        ++tally.hits;
        REQUIRE(trace.exit == SweepExit::AllAxesOverlap);
        REQUIRE(ends == 0);
        REQUIRE(decided.Hit());
        const OracleFace& first = decided.faces[static_cast<size_t>(decided.firstFace)];
        REQUIRE(SameBits(result.toi, decided.first + 0.0));
        REQUIRE(result.axis.shape == first.side);
        REQUIRE(result.axis.index == first.face);
        const SweepAxis& latest = trace.axes[last.latestEntry];
        REQUIRE(SameBits(latest.entry, result.toi));
        REQUIRE(latest.axis.shape == result.axis.shape);
        REQUIRE(latest.axis.index == result.axis.index);
        return;
    }
    if (trace.exit == SweepExit::AllAxesOverlap)
    {
        // Every face overlaps at t = 0, and the static test found the shapes touching at most: no hit.
        REQUIRE(decided.inside);
        REQUIRE(ends == 0);
        return;
    }
    ++tally.misses;
    INFO("exit " << static_cast<int>(trace.exit) << ", steps " << trace.axes.size());
    REQUIRE(ends == 1);
    REQUIRE_FALSE(decided.Hit());
    switch (trace.exit)
    {
    case SweepExit::NeverCloses:
        REQUIRE(decided.anyNever);
        break;
    case SweepExit::EntryAfterStep:
        REQUIRE(decided.first > 1.0);
        break;
    case SweepExit::EntryAfterExit:
        REQUIRE(decided.first >= decided.last);
        break;
    default:
        FAIL("a miss ends for a reason of its own");
    }
}

// The sweep of a pair: traced and untraced alike to the bit, the trace against the full face loop, and with `cast`
// the Minkowski-difference cast.
void CheckLargeSweep(const RandomPair& pair, Vec2 v, bool cast, SweepTrace& trace, LargeSweepTally& tally)
{
    const SweepResult plain = Sweep(pair.a, pair.xfA, kStill, pair.b, pair.xfB, v);
    const SweepResult traced = Sweep(pair.a, pair.xfA, kStill, pair.b, pair.xfB, v, &trace);
    INFO(pair.a.polygon.Count() << " and " << pair.b.polygon.Count() << " vertices");
    REQUIRE(plain.status == traced.status);
    REQUIRE(std::memcmp(&plain.toi, &traced.toi, sizeof plain.toi) == 0);
    REQUIRE(plain.normal == traced.normal);
    REQUIRE(plain.contactCount == traced.contactCount);
    if (plain.status == SweepStatus::Overlapping)
    {
        return;
    }
    REQUIRE_FALSE(trace.axes.empty());
    CheckTraceAgainstOracle(pair, v, plain, trace, tally);
    if (!cast)
    {
        return;
    }
    const SweepReference ref = ReferenceSweep(pair.a.polygon, pair.xfA, pair.b.polygon, pair.xfB, v);
    const double enter = static_cast<double>(ref.enter);
    if (std::abs(static_cast<double>(ref.startSeparation)) < 1e-12 || std::abs(enter - 1.0) < 1e-12 ||
        std::abs(static_cast<double>(ref.leave - ref.enter)) < 1e-12)
    {
        return;
    }
    ++tally.casts;
    INFO("toi " << plain.toi << ", reference: enter " << enter << ", leave " << static_cast<double>(ref.leave)
                << ", crosses " << ref.crosses << ", start separation " << static_cast<double>(ref.startSeparation));
    const bool hit = ref.crosses && ref.enter <= 1 && ref.leave > 0;
    REQUIRE((plain.status == SweepStatus::Hit) == hit);
    if (hit)
    {
        REQUIRE(std::abs(plain.toi - std::max(0.0, enter)) <= 1e-12);
    }
}

} // namespace

TEST_CASE("Sweeps of large polygons walk only the faces that can decide, and decide as every face would",
          "[sweep][properties]")
{
    // Above kScanLimit vertices the face loops walk only to the faces whose bounds leave them a say (the latest
    // entry, an axis that never closes, an exit before the latest entry); above 256 faces they bisect to the faces
    // beside the entry and the exit of the line of the motion through the Minkowski difference, and take the faces
    // along the motion. Mostly moderate sizes, where many pairs fit in the test's time: an exit that a witness
    // hides from one pass but not the other shows up about once in 5000 pairs.
    Rng rng(5150);
    SweepTrace trace;
    LargeSweepTally tally;
    for (int i = 0; i < 20000; ++i)
    {
        const bool large = i % 40 == 0;
        Vec2 v;
        bool sliding = false;
        const RandomPair pair =
            LargeSweepPair(rng, large ? rng.Int(17, 1500) : rng.Int(17, 48), rng.Int(3, large ? 400 : 48), v, sliding);
        INFO("pair " << i);
        CheckLargeSweep(pair, v, i % 20 == 1 && !sliding, trace, tally);
    }
    CHECK(tally.hits > 2000);
    CHECK(tally.misses > 2000);
    CHECK(tally.casts > 500);
}

TEST_CASE("Sweeps of polygons above 256 faces bisect to the faces that decide, and decide as every face would",
          "[sweep][properties]")
{
    // Each polygon above 256 faces has its faces bisected, whatever the other: against one of the same size (also
    // bisected), one of up to 256 faces (bounded face by face) or one of up to 16 (scanned).
    Rng rng(4099);
    SweepTrace trace;
    LargeSweepTally tally;
    for (int i = 0; i < 1500; ++i)
    {
        const int kind = i % 3;
        const int nB = kind == 0 ? rng.Int(257, 500) : kind == 1 ? rng.Int(17, 256) : rng.Int(3, 16);
        Vec2 v;
        bool sliding = false;
        const RandomPair pair = EitherWay(rng, LargeSweepPair(rng, rng.Int(257, 500), nB, v, sliding), v);
        INFO("pair " << i);
        CheckLargeSweep(pair, v, false, trace, tally);
    }
    CHECK(tally.hits > 300);
    CHECK(tally.misses > 300);
}

TEST_CASE(
    "The trace of a large-polygon sweep shows the faces it evaluates and bounds the others as every face has them",
    "[sweep][trace][properties]")
{
    // A of 17 to 4096 vertices, log-uniform (walked faces against a large B up to 256, bisected above), against B of
    // 3 to 4096; either polygon may be the large one. The trace against the full face loop (CheckTraceAgainstOracle).
    Rng rng(2718);
    SweepTrace trace;
    LargeSweepTally tally;
    for (int i = 0; i < 1500; ++i)
    {
        const int n = static_cast<int>(rng.LogUniform(std::log10(17.0), std::log10(4097.0)));
        const int nB = static_cast<int>(rng.LogUniform(std::log10(3.0), std::log10(4097.0)));
        Vec2 v;
        bool sliding = false;
        const RandomPair pair = EitherWay(rng, LargeSweepPair(rng, n, nB, v, sliding), v);
        INFO("pair " << i);
        CheckLargeSweep(pair, v, false, trace, tally);
    }
    WARN(tally.hits << " hits, " << tally.misses << " misses; steps: " << tally.evaluated
                    << " faces evaluated by walked or bisected loops (" << tally.bitwise
                    << " with the full loop's separation to the bit), bounded: " << tally.bounded[0]
                    << " overlapping at t = 0, " << tally.bounded[1] << " by their entry, " << tally.bounded[2]
                    << " by their exit; " << tally.skipped << " skipped, " << tally.scanned
                    << " scanned; the largest tie " << tally.worstTie << " of the tolerance; in " << tally.ties
                    << " pairs these ties change the verdict or the latest entry");
    CHECK(tally.hits > 300);
    CHECK(tally.misses > 300);
    CHECK(tally.bounded[0] > 1000);
    CHECK(tally.bounded[1] > 1000);
    CHECK(tally.bounded[2] > 1000);
    CHECK(tally.skipped > 10000);
}

namespace
{

// A polygon for the touching tests: a box a third of the time, else a random convex polygon (a sliver now and then).
Polygon TouchPolygon(Rng& rng)
{
    if (rng.Chance(0.35))
    {
        return MakeBox(rng.Uniform(0.05, 1.5), rng.Uniform(0.05, 1.5)).polygon;
    }
    const double aspect = rng.Chance(0.1) ? rng.LogUniform(-2.0, -1.0) : rng.Uniform(0.35, 1.0);
    return RandomPolygon(rng, rng.Int(3, 12), rng.Uniform(0.3, 1.5), aspect);
}

// An angle: a multiple of a right angle now and then (where rounding often leaves separations of exactly 0), else
// any.
double TouchAngle(Rng& rng)
{
    return rng.Chance(0.2) ? rng.Int(-2, 2) * (kPi / 2.0) : rng.Uniform(-kPi, kPi);
}

// A disc of random radius, its centre on the body origin or off it.
Shape TouchDisc(Rng& rng)
{
    Circle circle;
    circle.radius = rng.Uniform(0.05, 1.5);
    if (rng.Chance(0.3))
    {
        circle.center = {rng.Uniform(-0.3, 0.3), rng.Uniform(-0.3, 0.3)};
    }
    return MakeShape(circle);
}

// Two shapes that touch at t = 0, up to the rounding of their world coordinates.
struct Touching
{
    Shape a;
    Transform xfA;
    Shape b;
    Transform xfB;
    Vec2 normal;      ///< unit normal of the touching surface, world, from A to B
    Vec2 tangent;     ///< unit tangent of the touching surface, world
    int face = -1;    ///< OnFace: the face of A touched
    double along = 0; ///< OnFace: where on it, as a fraction of its length
};

// B placed on a point of a face of polygon A, 10% to 90% along it: a circle on its rim, a polygon by the vertex
// lowest towards the face or (faceToFace) by an edge turned anti-parallel to the face.
Touching OnFace(Rng& rng, const Polygon& a, const Shape& b, bool faceToFace)
{
    Touching out;
    out.a = MakeShape(a);
    out.b = b;
    const int face = rng.Int(0, a.Count() - 1);
    const double angleA = TouchAngle(rng);
    out.xfA = MakeTransform(Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}, angleA);
    const Vec2 n = a.Normal(face);
    out.face = face;
    out.along = rng.Uniform(0.1, 0.9);
    const Vec2 point = a.Vertices()[face] + out.along * a.Edge(face);
    double angleB = TouchAngle(rng);
    Vec2 origin; // B's body origin relative to the touching point, in A's frame
    if (b.type == ShapeType::Circle)
    {
        origin = b.circle.radius * n - Rotate(MakeRot(angleB), b.circle.center);
    }
    else
    {
        const Polygon& pb = b.polygon;
        int touching = 0;
        if (faceToFace)
        {
            touching = rng.Int(0, pb.Count() - 1);
            const Vec2 nb = pb.Normal(touching);
            angleB = std::atan2(-n.y, -n.x) - std::atan2(nb.y, nb.x);
        }
        else
        {
            for (int k = 1; k < pb.Count(); ++k)
            {
                if (Dot(n, Rotate(MakeRot(angleB), pb.Vertices()[k])) <
                    Dot(n, Rotate(MakeRot(angleB), pb.Vertices()[touching])))
                {
                    touching = k;
                }
            }
        }
        origin = -Rotate(MakeRot(angleB), pb.Vertices()[touching]);
    }
    out.xfB = MakeTransform(TransformPoint(out.xfA, point + origin), angleA + angleB);
    out.normal = Rotate(out.xfA.q, n);
    out.tangent = Rotate(out.xfA.q, Normalize(a.Edge(face)));
    return out;
}

// A circle B on a vertex of polygon A, its centre the radius away from the vertex in a direction between the
// normals of the vertex's two faces.
Touching OnVertex(Rng& rng, const Polygon& a, const Shape& disc)
{
    Touching out;
    out.a = MakeShape(a);
    out.b = disc;
    const int k = rng.Int(0, a.Count() - 1);
    const double angleA = TouchAngle(rng);
    out.xfA = MakeTransform(Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}, angleA);
    const Vec2 before = a.Normal((k + a.Count() - 1) % a.Count());
    const Vec2 after = a.Normal(k);
    // The normals turn counter-clockwise from the face before the vertex to the face after it.
    const double from = std::atan2(before.y, before.x);
    const double turn = std::remainder(std::atan2(after.y, after.x) - from, 2.0 * kPi);
    const double angle = from + rng.Uniform(0.0, 1.0) * (turn < 0.0 ? turn + 2.0 * kPi : turn);
    const Vec2 direction{std::cos(angle), std::sin(angle)};
    const double angleB = TouchAngle(rng);
    const Vec2 origin = disc.circle.radius * direction - Rotate(MakeRot(angleB), disc.circle.center);
    out.xfB = MakeTransform(TransformPoint(out.xfA, a.Vertices()[k] + origin), angleA + angleB);
    out.normal = Rotate(out.xfA.q, direction);
    out.tangent = LeftPerp(out.normal);
    return out;
}

// Two circles touching: B's centre the sum of the radii from A's in a random direction.
Touching CirclesTouching(Rng& rng)
{
    Touching out;
    out.a = TouchDisc(rng);
    out.b = TouchDisc(rng);
    out.xfA = MakeTransform(Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}, TouchAngle(rng));
    const double direction = rng.Uniform(-kPi, kPi);
    out.normal = {std::cos(direction), std::sin(direction)};
    out.tangent = LeftPerp(out.normal);
    const Vec2 centerB =
        TransformPoint(out.xfA, out.a.circle.center) + (out.a.circle.radius + out.b.circle.radius) * out.normal;
    const Rot qB = MakeRot(TouchAngle(rng));
    out.xfB = Transform{centerB - Rotate(qB, out.b.circle.center), qB};
    return out;
}

// Size of the coordinates of a pair: positions and the shapes' extents.
double PairScale(const Touching& pair)
{
    auto extent = [](const Shape& shape) {
        return shape.type == ShapeType::Circle ? shape.circle.radius + Length(shape.circle.center)
                                               : Radius(shape.polygon);
    };
    return 1.0 + Length(pair.xfA.p) + Length(pair.xfB.p) + extent(pair.a) + extent(pair.b);
}

// How far a world point lies from a shape's outline, in quadruple precision.
double OffOutline(const Shape& shape, const Transform& xf, Vec2 point)
{
    const QVec p{point.x, point.y};
    if (shape.type == ShapeType::Circle)
    {
        const QVec d = p - QTransform(xf, shape.circle.center);
        return std::abs(static_cast<double>(sqrtq(QDot(d, d)) - Quad(shape.circle.radius)));
    }
    return std::abs(static_cast<double>(SignedDistance(QWorld(shape.polygon, xf), p)));
}

// The relative motion of a touching pair, into the contact: at `speed` along -normal, turned up to 80 degrees
// towards the tangent (head on a fifth of the time).
Vec2 IntoContact(Rng& rng, const Touching& pair, double speed)
{
    const double angle = rng.Chance(0.2) ? 0.0 : rng.Uniform(-1.4, 1.4);
    return speed * (std::sin(angle) * pair.tangent - std::cos(angle) * pair.normal);
}

// A's own motion: none half of the time, else up to the relative speed.
Vec2 OwnMotion(Rng& rng, Vec2 relative)
{
    const double speed = Length(relative);
    return rng.Chance(0.5) ? kStill : Vec2{rng.Uniform(-speed, speed), rng.Uniform(-speed, speed)};
}

// Statuses seen by the touching tests.
struct Tally
{
    int hits = 0;
    int overlapping = 0;
    int misses = 0;
    void Add(SweepStatus status)
    {
        hits += status == SweepStatus::Hit;
        overlapping += status == SweepStatus::Overlapping;
        misses += status == SweepStatus::Miss;
    }
};

// The shapes touch at t = 0 and B moves into A: a hit at once (B moves at most 1e-12 of the scale along the normal
// before it), on the normal of the touching surface, with the contacts on both outlines; or, when the static test
// finds them interpenetrating by rounding (depth > 0, at most 1e-12 of the scale), overlapping along that normal.
// Never a miss. Sweep and SweepTime agree.
void RequireHitAtOnce(const Shape& a, const Transform& xfA, Vec2 vA, const Shape& b, const Transform& xfB, Vec2 vB,
                      Vec2 normal, double scale, Tally& tally)
{
    const SweepResult r = Sweep(a, xfA, vA, b, xfB, vB);
    const SweepResult time = SweepTime(a, xfA, vA, b, xfB, vB);
    INFO("status " << static_cast<int>(r.status) << ", toi " << r.toi << ", normal " << r.normal.x << ", " << r.normal.y
                   << ", expected normal " << normal.x << ", " << normal.y);
    tally.Add(r.status);
    REQUIRE(time.status == r.status);
    REQUIRE(r.status != SweepStatus::Miss);
    if (r.status == SweepStatus::Overlapping)
    {
        const Manifold m = Collide(a, xfA, b, xfB);
        REQUIRE(m.overlap);
        REQUIRE(m.depth > 0.0);
        REQUIRE(m.depth <= 1e-12 * scale);
        REQUIRE(Dot(r.normal, normal) >= 1.0 - 1e-12);
        return;
    }
    REQUIRE(time.toi == r.toi);
    REQUIRE(r.toi >= 0.0);
    REQUIRE(r.toi * -Dot(vB - vA, normal) <= 1e-12 * scale);
    REQUIRE(Dot(r.normal, normal) >= 1.0 - 1e-12);
    REQUIRE(Dot(time.normal, normal) >= 1.0 - 1e-12);
    REQUIRE(r.contactCount >= 1);
    const Transform atA{xfA.p + r.toi * vA, xfA.q};
    const Transform atB{xfB.p + r.toi * vB, xfB.q};
    for (int c = 0; c < r.contactCount; ++c)
    {
        INFO("contact " << c << " at " << r.contacts[c].point.x << ", " << r.contacts[c].point.y);
        REQUIRE(OffOutline(a, atA, r.contacts[c].point) <= 1e-12 * scale);
        REQUIRE(OffOutline(b, atB, r.contacts[c].point) <= 1e-12 * scale);
    }
}

// The shapes touch at t = 0 and slide along the touching surface: not a hit. A miss, or overlapping when the
// static test finds them interpenetrating by rounding (depth > 0, at most 1e-12 of the scale).
void RequireNoHitSliding(const Shape& a, const Transform& xfA, Vec2 vA, const Shape& b, const Transform& xfB, Vec2 vB,
                         double scale, Tally& tally)
{
    const SweepResult r = Sweep(a, xfA, vA, b, xfB, vB);
    INFO("status " << static_cast<int>(r.status) << ", toi " << r.toi << ", normal " << r.normal.x << ", "
                   << r.normal.y);
    tally.Add(r.status);
    REQUIRE(r.status != SweepStatus::Hit);
    REQUIRE(SweepTime(a, xfA, vA, b, xfB, vB).status == r.status);
    if (r.status == SweepStatus::Overlapping)
    {
        const Manifold m = Collide(a, xfA, b, xfB);
        REQUIRE(m.overlap);
        REQUIRE(m.depth > 0.0);
        REQUIRE(m.depth <= 1e-12 * scale);
    }
}

// One component of v moved by an ulp a third of the time, each way: still parallel within rounding.
Vec2 Nudged(Rng& rng, Vec2 v)
{
    const double u = rng.Uniform(0.0, 1.0);
    if (u < 1.0 / 3.0)
    {
        const double to = rng.Chance(0.5) ? HUGE_VAL : -HUGE_VAL;
        return rng.Chance(0.5) ? Vec2{std::nextafter(v.x, to), v.y} : Vec2{v.x, std::nextafter(v.y, to)};
    }
    return v;
}

} // namespace

TEST_CASE("Polygons that start touching and move into each other hit at once, on the touching face", "[sweep]")
{
    // Random rotated boxes and convex polygons, B on any face of A by a vertex or edge to edge, moving in from
    // straight on to 80 degrees off, at speeds from 1e-3 to 1e6, either shape moving, both orders. Catches the
    // sweep that took a face touching at t = 0 for one that overlaps and reported A's face 0 (its normal, axis
    // and contacts) whatever the geometry.
    Rng rng(6101);
    Tally byVertex;
    Tally faceToFaceTally;
    for (int i = 0; i < 20000; ++i)
    {
        const bool faceToFace = rng.Chance(0.3);
        Tally& tally = faceToFace ? faceToFaceTally : byVertex;
        const Polygon a = TouchPolygon(rng);
        const Touching pair = OnFace(rng, a, MakeShape(TouchPolygon(rng)), faceToFace);
        const Vec2 v = IntoContact(rng, pair, rng.LogUniform(-3.0, 6.0));
        const Vec2 vA = OwnMotion(rng, v);
        const Vec2 vB = vA + v;
        const double scale = PairScale(pair);
        INFO("pair " << i << (faceToFace ? ", edge to edge" : ", vertex on face") << ", v " << v.x << ", " << v.y);
        RequireHitAtOnce(pair.a, pair.xfA, vA, pair.b, pair.xfB, vB, pair.normal, scale, tally);
        RequireHitAtOnce(pair.b, pair.xfB, vB, pair.a, pair.xfA, vA, -pair.normal, scale, tally);
    }
    WARN("by a vertex " << byVertex.hits << " hits, " << byVertex.overlapping
                        << " overlapping by rounding; edge to edge " << faceToFaceTally.hits << " hits, "
                        << faceToFaceTally.overlapping << " overlapping by rounding");
    // Rounding may start a pair just inside the other (overlapping): most must still be real hits at t = 0.
    CHECK(byVertex.hits > 15000);
    CHECK(faceToFaceTally.hits > 5000);
}

TEST_CASE("Axis-aligned boxes that start touching and move in hit at once from every side", "[sweep]")
{
    // The exact cases: a unit box A and a half box B on each of its faces, separation exactly 0.
    const Shape a = BoxShape(1.0, 1.0);
    const Shape b = BoxShape(0.5, 0.5);
    struct Case
    {
        Vec2 position;
        Vec2 normal;
    };
    const Case cases[] = {
        {{0.0, 1.5}, {0.0, 1.0}}, {{1.5, 0.2}, {1.0, 0.0}}, {{-1.5, 0.0}, {-1.0, 0.0}}, {{0.3, -1.5}, {0.0, -1.0}}};
    for (const Case& c : cases)
    {
        for (const Vec2 along : {Vec2{0.0, 0.0}, LeftPerp(c.normal), -LeftPerp(c.normal)})
        {
            const Vec2 v = 0.5 * along - c.normal;
            INFO("B at " << c.position.x << ", " << c.position.y << ", moving " << v.x << ", " << v.y);
            const SweepResult r = Sweep(a, At(0, 0), kStill, b, At(c.position.x, c.position.y), v);
            REQUIRE(r.status == SweepStatus::Hit);
            CHECK(r.toi == 0.0);
            CHECK(r.normal == c.normal);
            CHECK(r.axis.kind == AxisKind::FaceNormal);
            // The contacts lie on the touching face: their distance along the normal is A's half width.
            REQUIRE(r.contactCount >= 1);
            for (int k = 0; k < r.contactCount; ++k)
            {
                CHECK_THAT(Dot(r.contacts[k].point, c.normal), WithinAbs(1.0, 1e-15));
            }
        }
    }
}

TEST_CASE("A polygon landing on a face touches it at its lowest vertex or along the overlap of its lowest edge",
          "[sweep]")
{
    // B placed on a face of A by its lowest vertex or by an edge turned anti-parallel to the face (OnFace), then set
    // back along a motion into the face (head on to 80 degrees off, speeds 1e-3 to 1e3, either shape moving) so
    // that it lands there at t = tau. The oracle, from the placement itself: B's vertices on the face's line (one,
    // or the two ends of an edge: the edge-to-edge pairs, and boxes at right angles by a vertex), and the overlap of
    // that edge with the face along it. Either of two parallel faces may be the reference: the contacts are the same.
    Rng rng(6331);
    int flat = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const bool faceToFace = rng.Chance(0.5);
        const Polygon a = TouchPolygon(rng);
        const Touching pair = OnFace(rng, a, MakeShape(TouchPolygon(rng)), faceToFace);
        const Polygon& b = pair.b.polygon;
        const Vec2 v = IntoContact(rng, pair, rng.LogUniform(-3.0, 3.0));
        const Vec2 vA = OwnMotion(rng, v);
        const Vec2 vB = vA + v;
        const double tau = rng.Uniform(0.1, 0.9);
        const Transform startA{pair.xfA.p - tau * vA, pair.xfA.q};
        const Transform startB{pair.xfB.p - tau * vB, pair.xfB.q};
        const double scale = PairScale(pair) + Length(v);
        INFO("pair " << i << (faceToFace ? ", edge to edge" : ", vertex on face") << ", v " << v.x << ", " << v.y);
        const SweepResult r = Sweep(pair.a, startA, vA, pair.b, startB, vB);
        REQUIRE(r.status == SweepStatus::Hit);
        REQUIRE(std::abs(r.toi - tau) <= 1e-12 * scale / Length(v));
        // The face from its first vertex, and B's vertices on its line at the placement, along it.
        const Vec2 start = TransformPoint(pair.xfA, a.Vertices()[pair.face]);
        const auto along = [&](Vec2 world) { return Dot(world - start, pair.tangent); };
        const double faceEnd = along(TransformPoint(pair.xfA, a.Vertices()[(pair.face + 1) % a.Count()]));
        double low = faceEnd;
        double high = 0.0;
        int onLine = 0;
        for (int k = 0; k < b.Count(); ++k)
        {
            const Vec2 w = TransformPoint(pair.xfB, b.Vertices()[k]);
            if (Dot(w - start, pair.normal) <= 1e-12 * scale)
            {
                ++onLine;
                low = std::min(low, along(w));
                high = std::max(high, along(w));
            }
        }
        REQUIRE((onLine == 1 || onLine == 2));
        // The contacts, moved back to the placement (A moved by (toi - tau) vA), on the face's line.
        double contactAlong[2];
        for (int k = 0; k < r.contactCount; ++k)
        {
            const Vec2 point = r.contacts[k].point - (r.toi - tau) * vA;
            REQUIRE(std::abs(Dot(point - start, pair.normal)) <= 1e-12 * scale);
            contactAlong[k] = along(point);
        }
        REQUIRE(r.contactCount == onLine);
        if (onLine == 1)
        {
            CHECK_THAT(contactAlong[0], WithinAbs(low, 1e-12 * scale));
            continue;
        }
        ++flat;
        CHECK_THAT(std::min(contactAlong[0], contactAlong[1]), WithinAbs(std::max(low, 0.0), 1e-12 * scale));
        CHECK_THAT(std::max(contactAlong[0], contactAlong[1]), WithinAbs(std::min(high, faceEnd), 1e-12 * scale));
    }
    CHECK(flat > 8000);
}

TEST_CASE("Circles that start touching and move in hit at once, never tunnel", "[sweep][circle]")
{
    // Circle against circle, circle on a polygon's face and on a polygon's vertex (rotated boxes and random
    // polygons), moving in head on or up to 80 degrees off, at speeds from 1e-3 to 1e6, both orders. Catches the
    // circle sweep that, from touching (rounded to just inside), found no entry into the other shape's outline
    // and reported a miss: the circles passed through each other.
    Rng rng(6202);
    Tally circles;
    Tally faces;
    Tally vertices;
    for (int i = 0; i < 30000; ++i)
    {
        const int kind = i % 3;
        const Touching pair = kind == 0   ? CirclesTouching(rng)
                              : kind == 1 ? OnFace(rng, TouchPolygon(rng), TouchDisc(rng), false)
                                          : OnVertex(rng, TouchPolygon(rng), TouchDisc(rng));
        const Vec2 v = IntoContact(rng, pair, rng.LogUniform(-3.0, 6.0));
        const Vec2 vA = OwnMotion(rng, v);
        const Vec2 vB = vA + v;
        const double scale = PairScale(pair);
        Tally& tally = kind == 0 ? circles : kind == 1 ? faces : vertices;
        INFO("pair " << i
                     << (kind == 0   ? ", circles"
                         : kind == 1 ? ", circle on a face"
                                     : ", circle on a vertex")
                     << ", v " << v.x << ", " << v.y);
        RequireHitAtOnce(pair.a, pair.xfA, vA, pair.b, pair.xfB, vB, pair.normal, scale, tally);
        RequireHitAtOnce(pair.b, pair.xfB, vB, pair.a, pair.xfA, vA, -pair.normal, scale, tally);
    }
    WARN("hits and overlapping by rounding: circles " << circles.hits << ", " << circles.overlapping << "; faces "
                                                      << faces.hits << ", " << faces.overlapping << "; vertices "
                                                      << vertices.hits << ", " << vertices.overlapping);
    CHECK(circles.hits > 5000);
    CHECK(faces.hits > 5000);
    CHECK(vertices.hits > 5000);
}

TEST_CASE("Touching and sliding along a tilted face is not a hit", "[sweep]")
{
    // B touches a face of A (turned any way) and moves along it, as parallel as doubles express it (or an ulp off
    // in one component): a tilted box on a tilted floor, random polygons by a vertex or edge to edge, at speeds
    // from 1e-3 to 1e6, and circles on faces moving along the face or past its end. As sweep.h has it, sliding at
    // zero distance is a miss; a pair the static test finds interpenetrating by rounding may be overlapping. Catches
    // the sweep that divided a separation of about 0 by a rate of about 0 and reported a hit at any time in the
    // step (or at t = 0 on A's face 0).
    Rng rng(6303);
    Tally boxes;
    Tally polygons;
    Tally discs;
    for (int i = 0; i < 30000; ++i)
    {
        const int kind = i % 3;
        Touching pair;
        Vec2 v;
        if (kind == 0)
        {
            // A box on a long tilted floor, turned like it (or by a right angle more), or by a corner.
            const Polygon floor = MakeBox(rng.Uniform(2.0, 10.0), rng.Uniform(0.1, 1.0)).polygon;
            pair = OnFace(rng, floor, BoxShape(rng.Uniform(0.05, 1.0), rng.Uniform(0.05, 1.0)), rng.Chance(0.7));
            v = rng.LogUniform(-3.0, 6.0) * pair.tangent;
        }
        else if (kind == 1)
        {
            pair = OnFace(rng, TouchPolygon(rng), MakeShape(TouchPolygon(rng)), rng.Chance(0.5));
            v = rng.LogUniform(-3.0, 6.0) * pair.tangent;
        }
        else
        {
            // The circle's centre moves from its point 10% to 90% along the face to 5% to 95% along, or past the
            // face's end (from 5% to 3 face lengths beyond it), over the vertex there, whose disc it only touches.
            const Polygon a = TouchPolygon(rng);
            pair = OnFace(rng, a, TouchDisc(rng), false);
            const double u = rng.Uniform(0.0, 1.0);
            const double to = u < 0.5 ? rng.Uniform(0.05, 0.95)
                                      : (u < 0.75 ? 1.0 + rng.LogUniform(-1.3, 0.5) : -rng.LogUniform(-1.3, 0.5));
            v = ((to - pair.along) * Length(a.Edge(pair.face))) * pair.tangent;
        }
        v = Nudged(rng, rng.Chance(0.5) || kind == 2 ? v : -v);
        // B moves, or A the other way: the relative motion is v exactly.
        const bool bMoves = rng.Chance(0.5);
        const Vec2 vA = bMoves ? kStill : -v;
        const Vec2 vB = bMoves ? v : kStill;
        const double scale = PairScale(pair);
        Tally& tally = kind == 0 ? boxes : kind == 1 ? polygons : discs;
        INFO("pair " << i << ", v " << v.x << ", " << v.y << ", normal " << pair.normal.x << ", " << pair.normal.y);
        RequireNoHitSliding(pair.a, pair.xfA, vA, pair.b, pair.xfB, vB, scale, tally);
        RequireNoHitSliding(pair.b, pair.xfB, vB, pair.a, pair.xfA, vA, scale, tally);
    }
    WARN("misses and overlapping by rounding: boxes " << boxes.misses << ", " << boxes.overlapping << "; polygons "
                                                      << polygons.misses << ", " << polygons.overlapping << "; circles "
                                                      << discs.misses << ", " << discs.overlapping);
    CHECK(boxes.misses > 5000);
    CHECK(polygons.misses > 5000);
    CHECK(discs.misses > 5000);
}

namespace
{

// The outcome of a circle sweep by the reference.
enum class CircleVerdict
{
    Overlapping, ///< the centre starts strictly inside the grown shape
    Hit,         ///< it starts outside and enters by t = 1
    Miss,
};

// An independent reference for circle sweeps, in quadruple precision from the exact double inputs: the circle's
// centre p(t) = p0 + t v (relative to the other shape, which stays put) against the other shape grown by the radius.
// A disc grows to a disc. A polygon grows to the union of its interior and the capsules around its edges (not the
// library's outline of pushed-out faces and corner arcs): each capsule is a rectangle, which clips the path
// (Cyrus-Beck), and the discs at its ends, so the first entry is the earliest entry into any of them.
class CircleSweepReference
{
  public:
    CircleSweepReference(const Shape& circle, const Transform& xfCircle, Vec2 vCircle, const Shape& other,
                         const Transform& xfOther, Vec2 vOther)
        : m_radius(circle.circle.radius),
          m_p0(QTransform(xfCircle, circle.circle.center)), m_v{Quad(vCircle.x) - Quad(vOther.x),
                                                                Quad(vCircle.y) - Quad(vOther.y)}
    {
        if (other.type == ShapeType::Circle)
        {
            m_outline.push_back(QTransform(xfOther, other.circle.center));
            m_rim = other.circle.radius;
            m_radius += m_rim;
        }
        else
        {
            m_outline = QWorld(other.polygon, xfOther);
            for (size_t i = 0; i < m_outline.size(); ++i)
            {
                const QVec e = m_outline[(i + 1) % m_outline.size()] - m_outline[i];
                m_lengths.push_back(sqrtq(QDot(e, e)));
            }
        }
    }

    // The verdict for the shape grown by the radius plus `grow`, and for a hit its time.
    CircleVerdict Decide(Quad grow, Quad& toi) const
    {
        const Quad r = m_radius + grow;
        const size_t n = m_outline.size();
        Quad enter = HUGE_VALQ;
        bool inside = false;
        // A piece of the grown shape holds the path over [lo, hi]: the path starts inside it, or enters it at lo.
        auto take = [&](Quad lo, Quad hi) {
            if (lo <= hi && hi >= 0)
            {
                inside = inside || lo < 0;
                enter = lo < enter ? lo : enter;
            }
        };
        for (size_t i = 0; i < n; ++i)
        {
            const QVec a = m_outline[i];
            Quad lo;
            Quad hi;
            DiscTimes(a, r, lo, hi);
            take(lo, hi);
            if (n == 1)
            {
                break;
            }
            const QVec e = m_outline[(i + 1) % n] - a;
            const QVec f = m_p0 - a;
            const Quad length2 = QDot(e, e);
            const Quad width = r * m_lengths[i];
            // The rectangle: 0 <= Dot(p - a, e) <= |e|^2 and |Cross(e, p - a)| <= r |e|, each linear in t.
            lo = -HUGE_VALQ;
            hi = HUGE_VALQ;
            Clip(QDot(f, e), QDot(m_v, e), lo, hi);
            Clip(length2 - QDot(f, e), -QDot(m_v, e), lo, hi);
            Clip(width - QCross(e, f), -QCross(e, m_v), lo, hi);
            Clip(width + QCross(e, f), QCross(e, m_v), lo, hi);
            take(lo, hi);
        }
        // Deep inside a polygon, beyond the capsules: left of every edge (counter-clockwise).
        bool interior = n > 1;
        for (size_t i = 0; i < n && interior; ++i)
        {
            interior = QCross(m_outline[(i + 1) % n] - m_outline[i], m_p0 - m_outline[i]) > 0;
        }
        if (inside || interior)
        {
            return CircleVerdict::Overlapping;
        }
        toi = enter;
        return enter <= 1 ? CircleVerdict::Hit : CircleVerdict::Miss;
    }

    // At time t: the nearest point of the other shape to the centre, and the unit normal from it to the centre.
    void Contact(Quad t, QVec& point, QVec& normal) const
    {
        const QVec p{m_p0.x + t * m_v.x, m_p0.y + t * m_v.y};
        const size_t n = m_outline.size();
        Quad best = HUGE_VALQ;
        for (size_t i = 0; i < n; ++i)
        {
            const QVec a = m_outline[i];
            const QVec e = n == 1 ? QVec{} : m_outline[(i + 1) % n] - a;
            const Quad length2 = QDot(e, e);
            Quad u = length2 > 0 ? QDot(p - a, e) / length2 : 0;
            u = u < 0 ? 0 : (u > 1 ? 1 : u);
            const QVec q{a.x + u * e.x, a.y + u * e.y};
            const QVec d = p - q;
            const Quad distance = sqrtq(QDot(d, d));
            if (distance < best)
            {
                best = distance;
                point = q;
                normal = {d.x / distance, d.y / distance};
            }
        }
        // A disc: the point on its rim.
        point = {point.x + m_rim * normal.x, point.y + m_rim * normal.y};
    }

  private:
    // The times where |p(t) - c| <= r: [lo, hi], empty when lo > hi.
    void DiscTimes(QVec c, Quad r, Quad& lo, Quad& hi) const
    {
        const QVec f = m_p0 - c;
        const Quad a = QDot(m_v, m_v);
        const Quad b = QDot(f, m_v);
        const Quad k = QDot(f, f) - r * r;
        const Quad discriminant = b * b - a * k;
        if (discriminant < 0)
        {
            lo = 1;
            hi = 0;
            return;
        }
        const Quad root = sqrtq(discriminant);
        lo = (-b - root) / a;
        hi = (-b + root) / a;
    }

    // Clips [lo, hi] to the times where g0 + t g1 >= 0.
    static void Clip(Quad g0, Quad g1, Quad& lo, Quad& hi)
    {
        if (g1 == 0)
        {
            if (g0 < 0)
            {
                lo = 1;
                hi = 0;
            }
            return;
        }
        const Quad t = -g0 / g1;
        if (g1 > 0)
        {
            lo = t > lo ? t : lo;
        }
        else
        {
            hi = t < hi ? t : hi;
        }
    }

    Quad m_radius;  // the circle's radius, plus the other's for a disc
    Quad m_rim = 0; // the other's radius for a disc, else 0
    QVec m_p0;
    QVec m_v;
    std::vector<QVec> m_outline; // a polygon's vertices, or a disc's centre
    std::vector<Quad> m_lengths; // a polygon's edge lengths
};

} // namespace

TEST_CASE("Circle sweeps agree with a quadruple-precision reference on random moving pairs", "[sweep][circle]")
{
    // Circle against circle (a quarter) and circle against random convex polygons, either as A, either or both
    // moving, aimed at each other or off to the side, at speeds from a tenth of the distance to 1000 times it. Pairs
    // within 1e-12 of the scale of a boundary case (touching at the start, grazing, first touching at t = 1) go
    // either way: the reference decides them with the shape grown and shrunk by that much and skips them unless
    // both agree. Elsewhere: the same verdict, the time within 1e-12, the normal within 1e-9, and the contact within
    // 1e-9 of the scale of the reference's.
    Rng rng(6404);
    int compared = 0;
    int hits = 0;
    int overlapping = 0;
    double maxError = 0.0;
    for (int i = 0; i < 100000; ++i)
    {
        Circle round;
        round.radius = rng.Uniform(0.05, 1.5);
        round.center = rng.Chance(0.5) ? Vec2{rng.Uniform(-0.3, 0.3), rng.Uniform(-0.3, 0.3)} : Vec2{};
        const Shape circle = MakeShape(round);
        const bool twoCircles = rng.Chance(0.25);
        const Shape other = twoCircles ? TouchDisc(rng) : MakeShape(TouchPolygon(rng));
        const Transform xfOther = MakeTransform(Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}, TouchAngle(rng));
        const double direction = rng.Uniform(-kPi, kPi);
        const double distance = rng.Uniform(0.3, 5.0);
        const Transform xfCircle = MakeTransform(xfOther.p + distance * Vec2{std::cos(direction), std::sin(direction)},
                                                 rng.Uniform(-kPi, kPi));
        const Vec2 toward = xfOther.p - xfCircle.p;
        const double k = rng.Uniform(0.2, 1.5) * rng.LogUniform(-1.0, 3.0);
        const Vec2 v = k * toward + (rng.Uniform(-0.5, 0.5) * k) * LeftPerp(toward);
        const Vec2 vOther = rng.Chance(0.5) ? Vec2{rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)} : kStill;
        const Vec2 vCircle = vOther + v;
        const bool circleFirst = rng.Chance(0.5);
        const SweepResult r = circleFirst ? Sweep(circle, xfCircle, vCircle, other, xfOther, vOther)
                                          : Sweep(other, xfOther, vOther, circle, xfCircle, vCircle);

        const CircleSweepReference reference(circle, xfCircle, vCircle, other, xfOther, vOther);
        const double scale = 1.0 + std::max({std::abs(xfOther.p.x), std::abs(xfOther.p.y), std::abs(xfCircle.p.x),
                                             std::abs(xfCircle.p.y)});
        const Quad band = 1e-12 * scale;
        Quad toi = 0;
        Quad unused = 0;
        const CircleVerdict verdict = reference.Decide(0, toi);
        if (reference.Decide(band, unused) != verdict || reference.Decide(-band, unused) != verdict)
        {
            continue;
        }
        ++compared;
        INFO("pair " << i << (twoCircles ? ", two circles" : ", circle and polygon")
                     << (circleFirst ? ", circle as A" : ", circle as B") << ", reference verdict "
                     << static_cast<int>(verdict) << ", toi " << static_cast<double>(toi) << "; sweep status "
                     << static_cast<int>(r.status) << ", toi " << r.toi);
        if (verdict == CircleVerdict::Overlapping)
        {
            ++overlapping;
            REQUIRE(r.status == SweepStatus::Overlapping);
            continue;
        }
        REQUIRE((r.status == SweepStatus::Hit) == (verdict == CircleVerdict::Hit));
        if (verdict != CircleVerdict::Hit)
        {
            continue;
        }
        ++hits;
        const double error = std::abs(r.toi - static_cast<double>(toi));
        maxError = std::max(maxError, error);
        INFO("|t error| " << error);
        REQUIRE(error <= 1e-12);
        QVec point;
        QVec normal;
        reference.Contact(toi, point, normal);
        // The normal points from A to B; the reference's from the other shape to the circle.
        const double sign = circleFirst ? -1.0 : 1.0;
        REQUIRE(std::abs(r.normal.x - sign * static_cast<double>(normal.x)) <= 1e-9);
        REQUIRE(std::abs(r.normal.y - sign * static_cast<double>(normal.y)) <= 1e-9);
        // The contact lies on the other shape at the time of impact: the reference's point moved with it.
        REQUIRE(r.contactCount == 1);
        const double tolerance = 1e-9 * (scale + Length(v) + Length(vOther));
        REQUIRE(std::abs(r.contacts[0].point.x - static_cast<double>(point.x + toi * vOther.x)) <= tolerance);
        REQUIRE(std::abs(r.contacts[0].point.y - static_cast<double>(point.y + toi * vOther.y)) <= tolerance);
    }
    WARN("compared " << compared << " circle pairs, " << hits << " hits, " << overlapping
                     << " overlapping, max |t error| " << maxError);
    CHECK(compared > 99000);
    CHECK(hits > 20000);
}

TEST_CASE("Boxes and circles never tunnel through a rotated thin wall", "[sweep][circle]")
{
    // A wall 1e-3 thick and 20 tall, turned and placed anywhere; a projectile 0.01 wide (a box turned any way, or
    // a disc) aimed to reach the wall's face at a random time in the step, up to 80 degrees off its normal, at
    // speeds from 1 to 1e6. The analytic time, from the start as rounded to doubles in quadruple precision: when
    // the projectile's leading point (the disc's rim, the box's first vertex) crosses the plane of the face.
    const Shape wall = BoxShape(5e-4, 10.0);
    const Shape box = BoxShape(0.005, 0.005);
    const Shape disc = DiscShape(0.005);
    Rng rng(6505);
    int shots = 0;
    double worst = 0.0;
    for (double speed = 1.0; speed <= 1e6; speed *= 10.0)
    {
        for (int k = 0; k < 3000; ++k)
        {
            const bool round = k % 2 == 1;
            const Shape& projectile = round ? disc : box;
            const Transform xfWall =
                MakeTransform(Vec2{rng.Uniform(-5.0, 5.0), rng.Uniform(-5.0, 5.0)}, rng.Uniform(-kPi, kPi));
            // The face at local x = -5e-4, its outward normal (-1, 0) in the wall's frame.
            const Vec2 outward = Rotate(xfWall.q, Vec2{-1.0, 0.0});
            const Vec2 v = speed * Rotate(MakeRot(rng.Uniform(-1.4, 1.4)), -outward);
            const Vec2 onFace = TransformPoint(xfWall, Vec2{-5e-4, rng.Uniform(-5.0, 5.0)});
            const Rot q = MakeRot(rng.Uniform(-kPi, kPi));
            // The projectile's origin when its leading point is on the face.
            Vec2 lead = round ? -0.005 * outward : Rotate(q, box.polygon.Vertices()[0]);
            if (!round)
            {
                for (const Vec2& vertex : box.polygon.Vertices())
                {
                    lead = Dot(Rotate(q, vertex), outward) < Dot(lead, outward) ? Rotate(q, vertex) : lead;
                }
            }
            const double hitTime = rng.Uniform(0.001, 0.999);
            const Transform start{onFace - lead - hitTime * v, q};
            // In the wall's frame (unrotated by q without rounding), the face is at x = -5e-4 (c^2 + s^2).
            const Quad c = xfWall.q.c;
            const Quad s = xfWall.q.s;
            auto localX = [&](QVec p) { return c * (p.x - Quad(xfWall.p.x)) + s * (p.y - Quad(xfWall.p.y)); };
            const Quad rate = c * Quad(v.x) + s * Quad(v.y);
            const Quad face = Quad(-5e-4) * (c * c + s * s);
            Quad expected = HUGE_VALQ;
            if (round)
            {
                expected = (face - Quad(0.005) * sqrtq(c * c + s * s) - localX(QTransform(start, Vec2{}))) / rate;
            }
            else
            {
                for (const Vec2& vertex : box.polygon.Vertices())
                {
                    const Quad t = (face - localX(QTransform(start, vertex))) / rate;
                    expected = t < expected ? t : expected;
                }
            }
            const double analytic = static_cast<double>(expected);
            INFO("speed " << speed << (round ? ", disc" : ", box") << ", analytic time " << analytic);
            const SweepResult r = Sweep(wall, xfWall, kStill, projectile, start, v);
            REQUIRE(r.status == SweepStatus::Hit);
            worst = std::max(worst, std::abs(r.toi - analytic) / analytic);
            INFO("relative error of the time " << std::abs(r.toi - analytic) / analytic);
            REQUIRE(std::abs(r.toi - analytic) <= 1e-12 * analytic);
            REQUIRE(Dot(r.normal, outward) >= 1.0 - 1e-12);
            // The other way round: the wall moving onto the resting projectile.
            const SweepResult reverse = Sweep(projectile, start, kStill, wall, xfWall, -v);
            REQUIRE(reverse.status == SweepStatus::Hit);
            REQUIRE(std::abs(reverse.toi - analytic) <= 1e-12 * analytic);
            ++shots;
        }
    }
    WARN(shots << " shots, worst relative error of the time " << worst);
}
