// SPDX-License-Identifier: MIT
// The swept test: no tunnelling at any speed, exact times of impact, grazing and sliding are not hits.

#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/reference.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <cstring>

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
    int shots = 0;
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
            ++shots;
        }
    }
    CHECK(shots == 14000);
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
            REQUIRE(last.endsTest);
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

TEST_CASE("Sweeps of large polygons walk only the faces that can decide, and decide as every face would",
          "[sweep][properties]")
{
    // Above kScanLimit vertices the face loops walk only to the faces whose bounds leave them a say (the latest
    // entry, an axis that never closes, an exit before the latest entry). The oracles: the trace, which replays
    // every face in order with its exact separation, and for moderate sizes the Minkowski-difference cast.
    Rng rng(5150);
    SweepTrace trace;
    int hits = 0;
    int misses = 0;
    int casts = 0;
    // Mostly moderate sizes, where many pairs fit in the test's time: an exit that a witness hides from one pass
    // but not the other shows up about once in 5000 pairs.
    for (int i = 0; i < 20000; ++i)
    {
        const bool large = i % 40 == 0;
        const bool cast = i % 20 == 1;
        const int n = large ? rng.Int(17, 1500) : rng.Int(17, 48);
        RandomPair pair = ContactPair(rng, n, static_cast<PairCategory>(rng.Int(0, 2)), 0.1);
        if (rng.Chance(0.5))
        {
            pair.b = MakeShape(RandomPolygon(rng, rng.Int(3, large ? 400 : 48), rng.Uniform(0.05, 1.5),
                                             rng.Chance(0.2) ? 0.05 : rng.Uniform(0.35, 1.0)));
        }
        // B pulled back from A and sent towards it (sometimes past it) or in any direction, at speeds from a
        // tenth of the gap to 1000 times it.
        const Vec2 toward =
            TransformPoint(pair.xfA, pair.a.polygon.centroid) - TransformPoint(pair.xfB, pair.b.polygon.centroid);
        pair.xfB.p = pair.xfB.p - rng.Uniform(0.0, 2.0) * toward;
        const double k = rng.Uniform(0.5, 3.0) * rng.LogUniform(-1.0, 3.0);
        const double angle = rng.Uniform(-kPi, kPi);
        const Vec2 v = rng.Chance(0.3) ? k * toward + (rng.Uniform(-0.5, 0.5) * k) * LeftPerp(toward)
                                       : k * Length(toward) * Vec2{std::cos(angle), std::sin(angle)};
        const SweepResult plain = Sweep(pair.a, pair.xfA, kStill, pair.b, pair.xfB, v);
        const SweepResult traced = Sweep(pair.a, pair.xfA, kStill, pair.b, pair.xfB, v, &trace);
        INFO("pair " << i << ": " << pair.a.polygon.Count() << " and " << pair.b.polygon.Count() << " vertices");
        REQUIRE(plain.status == traced.status);
        REQUIRE(std::memcmp(&plain.toi, &traced.toi, sizeof plain.toi) == 0);
        REQUIRE(plain.normal == traced.normal);
        REQUIRE(plain.contactCount == traced.contactCount);
        if (plain.status == SweepStatus::Overlapping)
        {
            continue;
        }
        REQUIRE_FALSE(trace.axes.empty());
        const SweepAxis& last = trace.axes.back();
        if (plain.status == SweepStatus::Hit)
        {
            ++hits;
            REQUIRE(trace.exit == SweepExit::AllAxesOverlap);
            REQUIRE(trace.axes[last.latestEntry].entry == plain.toi);
            REQUIRE(trace.axes[last.latestEntry].axis.shape == plain.axis.shape);
            REQUIRE(trace.axes[last.latestEntry].axis.index == plain.axis.index);
        }
        else
        {
            ++misses;
            REQUIRE(last.endsTest);
        }
        if (cast)
        {
            const SweepReference ref = ReferenceSweep(pair.a.polygon, pair.xfA, pair.b.polygon, pair.xfB, v);
            const double enter = static_cast<double>(ref.enter);
            if (std::abs(static_cast<double>(ref.startSeparation)) < 1e-12 || std::abs(enter - 1.0) < 1e-12 ||
                std::abs(static_cast<double>(ref.leave - ref.enter)) < 1e-12)
            {
                continue;
            }
            ++casts;
            const bool hit = ref.crosses && ref.enter <= 1 && ref.leave > 0;
            REQUIRE((plain.status == SweepStatus::Hit) == hit);
            if (hit)
            {
                REQUIRE(std::abs(plain.toi - std::max(0.0, enter)) <= 1e-12);
            }
        }
    }
    CHECK(hits > 2000);
    CHECK(misses > 2000);
    CHECK(casts > 500);
}
