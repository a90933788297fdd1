// SPDX-License-Identifier: MIT
// The wide scans (AVX2, chosen at run time) and the 512-bit face loops (AVX-512F) against the baseline instructions:
// the same bits for every query. A processor without them reports those cases skipped to ctest (support/skip.h).

#include "sat/cpu_dispatch.h"
#include "sat/face_blocks.h"
#include "sat/face_query.h"
#include "sat/face_query_dispatch.h"
#include "sat/incident_polygon.h"
#include "sat/lanes.h"
#include "sat/lanes2.h"
#include "sat/select.h"
#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/same_bits.h"
#include "support/skip.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

using namespace satviz;
using namespace satviz::testing;

namespace
{

struct Answers
{
    bool overlap = false;
    Manifold manifold;
    SweepResult sweep;
    bool floatOverlap = false;
    ManifoldT<float> floatManifold;
    SweepResultT<float> floatSweep;
};

// The answers of every query to a pair, in double and in float; with `traced`, through the recording instantiations.
Answers Ask(const RandomPair& pair, Vec2 velocity, const ShapeT<float>& fa, const ShapeT<float>& fb,
            bool traced = false)
{
    Trace trace;
    SweepTrace sweepTrace;
    TraceT<float> floatTrace;
    SweepTraceT<float> floatSweepTrace;
    Answers out;
    out.overlap = Overlap(pair.a, pair.xfA, pair.b, pair.xfB, traced ? &trace : nullptr);
    out.manifold = Collide(pair.a, pair.xfA, pair.b, pair.xfB, traced ? &trace : nullptr);
    out.sweep = Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, velocity, traced ? &sweepTrace : nullptr);
    const TransformT<float> xfA{ConvertVec<float>(pair.xfA.p),
                                {static_cast<float>(pair.xfA.q.c), static_cast<float>(pair.xfA.q.s)}};
    const TransformT<float> xfB{ConvertVec<float>(pair.xfB.p),
                                {static_cast<float>(pair.xfB.q.c), static_cast<float>(pair.xfB.q.s)}};
    out.floatOverlap = Overlap(fa, xfA, fb, xfB, traced ? &floatTrace : nullptr);
    out.floatManifold = Collide(fa, xfA, fb, xfB, traced ? &floatTrace : nullptr);
    out.floatSweep =
        Sweep(fa, xfA, Vec2T<float>{}, fb, xfB, ConvertVec<float>(velocity), traced ? &floatSweepTrace : nullptr);
    return out;
}

void RequireSameAnswers(const Answers& a, const Answers& b)
{
    REQUIRE(a.overlap == b.overlap);
    REQUIRE(SameBits(a.manifold, b.manifold));
    REQUIRE(SameBits(a.sweep, b.sweep));
    REQUIRE(a.floatOverlap == b.floatOverlap);
    REQUIRE(SameBits(a.floatManifold, b.floatManifold));
    REQUIRE(SameBits(a.floatSweep, b.floatSweep));
}

} // namespace

namespace
{

// The reductions the lanes promise: std::max(std::max(v0, v1), std::max(v2, v3)), and the same with std::min.
double ScalarMax(const double* v)
{
    return std::max(std::max(v[0], v[1]), std::max(v[2], v[3]));
}

double ScalarMin(const double* v)
{
    return std::min(std::min(v[0], v[1]), std::min(v[2], v[3]));
}

#if SATVIZ_LANES_AVX2
[[gnu::target("avx2"), gnu::noinline]] void WideReductions(const double* v, double& largest, double& smallest)
{
    const detail::Lanes<double, true> lanes = detail::Lanes<double, true>::Set(v[0], v[1], v[2], v[3]);
    largest = lanes.MaxLane();
    smallest = lanes.MinLane();
}
#endif

} // namespace

TEST_CASE("Lane reductions give the values of std::max and std::min, NaN and signed zeros included", "[wide]")
{
    const double kNaN = std::numeric_limits<double>::quiet_NaN();
    const double kInf = std::numeric_limits<double>::infinity();
    const double values[] = {0.0, -0.0, 1.0, -1.0, 0.5, kInf, -kInf, kNaN, 1e-300, -2.5};
    Rng rng(5);
    for (int i = 0; i < 20000; ++i)
    {
        double v[4];
        for (double& x : v)
        {
            x = values[rng.Int(0, 9)];
        }
        INFO(v[0] << " " << v[1] << " " << v[2] << " " << v[3]);
        const detail::Lanes<double, false> lanes = detail::Lanes<double, false>::Set(v[0], v[1], v[2], v[3]);
        REQUIRE(SameBits(lanes.MaxLane(), ScalarMax(v)));
        REQUIRE(SameBits(lanes.MinLane(), ScalarMin(v)));
        const float f[4] = {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]),
                            static_cast<float>(v[3])};
        const detail::Lanes<float, false> floats = detail::Lanes<float, false>::Set(f[0], f[1], f[2], f[3]);
        REQUIRE(SameBits(floats.MaxLane(), std::max(std::max(f[0], f[1]), std::max(f[2], f[3]))));
        REQUIRE(SameBits(floats.MinLane(), std::min(std::min(f[0], f[1]), std::min(f[2], f[3]))));
        // The face scans' reduction, in the order cheapest for the registers: the same number (== takes +0 and -0
        // as equal), NaN aside.
        if (!std::isnan(v[0]) && !std::isnan(v[1]) && !std::isnan(v[2]) && !std::isnan(v[3]))
        {
            REQUIRE(lanes.MinLaneAnyOrder() == ScalarMin(v));
            REQUIRE(floats.MinLaneAnyOrder() == floats.MinLane());
            const detail::Lanes2<double> low = detail::Lanes2<double>::Set(v[0], v[1]);
            REQUIRE(low.MinLaneAnyOrder() == std::min(v[0], v[1]));
        }
#if SATVIZ_LANES_AVX2
        if (detail::HasWideVectors())
        {
            double largest = 0.0;
            double smallest = 0.0;
            WideReductions(v, largest, smallest);
            REQUIRE(SameBits(largest, ScalarMax(v)));
            REQUIRE(SameBits(smallest, ScalarMin(v)));
        }
#endif
    }
}

TEST_CASE("Select by mask returns one of its operands bit for bit, NaN, infinities and signed zeros included", "[wide]")
{
    const double kNaN = std::numeric_limits<double>::quiet_NaN();
    const double kInf = std::numeric_limits<double>::infinity();
    const double values[] = {0.0, -0.0, 1.0, -1.0, 0.5, kInf, -kInf, kNaN, -kNaN, 1e-310, -2.5, 1e300};
    Rng rng(6);
    for (int i = 0; i < 20000; ++i)
    {
        const double a = values[rng.Int(0, 11)];
        const double b = i % 3 == 0 ? rng.Uniform(-1e6, 1e6) : values[rng.Int(0, 11)];
        const bool c = rng.Int(0, 1) == 1;
        INFO(c << " " << a << " " << b);
        REQUIRE(SameBits(detail::Select(c, a, b), c ? a : b));
        const float fa = static_cast<float>(a);
        const float fb = static_cast<float>(b);
        REQUIRE(SameBits(detail::Select(c, fa, fb), c ? fa : fb));
        REQUIRE(SameBits(detail::SelectBits<uint64_t>(c, a, b), c ? a : b));
        REQUIRE(SameBits(detail::SelectBits<uint32_t>(c, fa, fb), c ? fa : fb));
        const Vec2 p{a, b};
        const Vec2 q{b, -a};
        const Vec2 chosen = detail::Select(c, p, q);
        REQUIRE(SameBits(chosen.x, c ? p.x : q.x));
        REQUIRE(SameBits(chosen.y, c ? p.y : q.y));
    }
}

namespace
{

// The kinds of code a query can run, each checked against the baseline instructions.
enum class Kind
{
    Traced,  // the traced queries, which take the baseline scans with a recorder
    Wide256, // 256-bit vectors, on a processor with AVX2
    Wide512, // 512-bit face loops on top of them, on a processor with AVX-512F
};

// Asks each of many pairs with the baseline instructions, then through `kind`: both must give the same bits.
void CheckAgainstBaseline(Kind kind)
{
    bool& wide = detail::WideVectorsEnabled();
    bool& wide512 = detail::Wide512Enabled();
    const bool flag = wide;
    const bool flag512 = wide512;
    Rng rng(20261123);
    int pairs = 0;
    for (int i = 0; i < 30000; ++i)
    {
        // Contact pairs of every scanned size and a few walked ones, and random shapes with circles.
        const int counts[] = {3, 4, 5, 7, 8, 9, 12, 16, 17, 40};
        const RandomPair pair =
            i % 4 == 3 ? RandomShapePair(rng, 0.15)
                       : ContactPair(rng, counts[rng.Int(0, 9)], static_cast<PairCategory>(rng.Int(0, 2)), 0.1);
        const Vec2 toward = pair.xfA.p - pair.xfB.p;
        const Vec2 velocity = rng.Uniform(0.2, 1.5) * toward + rng.Uniform(-0.5, 0.5) * LeftPerp(toward);
        const ShapeT<float> fa = ToFloat(pair.a);
        const ShapeT<float> fb = ToFloat(pair.b);
        if ((fa.type == ShapeType::Polygon && fa.polygon.Count() == 0) ||
            (fb.type == ShapeType::Polygon && fb.polygon.Count() == 0))
        {
            continue;
        }
        INFO("pair " << i);
        wide = false;
        wide512 = false;
        const Answers baseline = Ask(pair, velocity, fa, fb);
        wide = kind != Kind::Traced;
        wide512 = kind == Kind::Wide512;
        const Answers other = Ask(pair, velocity, fa, fb, kind == Kind::Traced);
        wide = flag;
        wide512 = flag512;
        RequireSameAnswers(other, baseline);
        ++pairs;
    }
    // Float rounding makes some outlines invalid (collinear or duplicate vertices): only a few are skipped.
    REQUIRE(pairs > 25000);
}

} // namespace

TEST_CASE("The incident polygon mapped in lanes has the textbook's vertices to the bit", "[properties][wide]")
{
    // MapInLanes (four vertices at a time) against MapOneByOne (TransformPoint per vertex), in double and float,
    // for every vertex count a scan takes, polygons kept inline and not.
    Rng rng(5151);
    for (int k = 0; k < 4000; ++k)
    {
        const int count = rng.Int(3, detail::kScanLimit);
        const Polygon p = RandomPolygon(rng, count, rng.Uniform(0.01, 100.0), rng.Uniform(0.3, 1.0));
        const Transform xfRef = MakeTransform({rng.Uniform(-1e3, 1e3), rng.Uniform(-1e3, 1e3)}, rng.Uniform(-4.0, 4.0));
        const Transform xfInc = MakeTransform({rng.Uniform(-1e3, 1e3), rng.Uniform(-1e3, 1e3)}, rng.Uniform(-4.0, 4.0));
        const detail::IncidentPolygon<double> textbook(p, xfRef, xfInc);
        const detail::IncidentPolygon<double> lanes(p, xfRef, xfInc, detail::kScanLimit, detail::MapInLanes<false>{});
        INFO("polygon " << k << ", " << p.Count() << " vertices");
        REQUIRE(textbook.scan);
        REQUIRE(textbook.padded == lanes.padded);
        for (int j = 0; j < textbook.padded; ++j)
        {
            REQUIRE(SameBits(textbook.x[j], lanes.x[j]));
            REQUIRE(SameBits(textbook.y[j], lanes.y[j]));
            const Vec2 w = TransformPoint(textbook.xf, p.Vertices()[j < p.Count() ? j : 0]);
            REQUIRE(SameBits(textbook.x[j], w.x));
            REQUIRE(SameBits(textbook.y[j], w.y));
        }
        const ShapeT<float> shapeF = ToFloat(MakeShape(p));
        if (shapeF.polygon.Count() == 0)
        {
            continue; // rounding to float made the polygon invalid
        }
        const PolygonT<float>& pf = shapeF.polygon;
        const TransformT<float> fRef = ToFloat(xfRef), fInc = ToFloat(xfInc);
        const detail::IncidentPolygon<float> textbookF(pf, fRef, fInc);
        const detail::IncidentPolygon<float> lanesF(pf, fRef, fInc, detail::kScanLimit, detail::MapInLanes<false>{});
        for (int j = 0; j < textbookF.padded; ++j)
        {
            REQUIRE(SameBits(textbookF.x[j], lanesF.x[j]));
            REQUIRE(SameBits(textbookF.y[j], lanesF.y[j]));
        }
    }
}

TEST_CASE("A trace says which instructions the same query runs on untraced", "[wide]")
{
    // The oracle: the processor's features (cpu_dispatch.h) and the rule that 512-bit face loops take two polygons
    // of up to 8 vertices each, in double.
    const auto expected = [](bool small) {
        if (detail::WideVectorsEnabled() && detail::Wide512Enabled() && small)
        {
            return InstructionPath::Avx512;
        }
        return detail::WideVectorsEnabled() ? InstructionPath::Avx2 : InstructionPath::Baseline;
    };
    Rng rng(5152);
    int small = 0, large = 0;
    for (int k = 0; k < 400; ++k)
    {
        RandomPair pair = ContactPair(rng, rng.Int(3, 20), static_cast<PairCategory>(rng.Int(0, 2)));
        const bool isSmall = pair.a.polygon.Count() <= 8 && pair.b.polygon.Count() <= 8;
        small += isSmall;
        large += !isSmall;
        Trace trace;
        trace.untracedPath = InstructionPath::Avx512; // a leftover the query must overwrite
        Collide(pair.a.polygon, pair.xfA, pair.b.polygon, pair.xfB, &trace);
        INFO("pair " << k << ": " << pair.a.polygon.Count() << " and " << pair.b.polygon.Count() << " vertices");
        CHECK(trace.untracedPath == expected(isSmall));
        SweepTrace sweep;
        Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, Vec2{0.5, -0.25}, &sweep);
        CHECK(sweep.untracedPath == expected(isSmall));
    }
    CHECK(small > 50);
    CHECK(large > 50);
    // With the wide scans turned off, as a processor without AVX2 runs: the baseline.
    const bool wide = detail::WideVectorsEnabled();
    detail::WideVectorsEnabled() = false;
    RandomPair pair = ContactPair(rng, 5, PairCategory::Overlap);
    Trace trace;
    Collide(pair.a.polygon, pair.xfA, pair.b.polygon, pair.xfB, &trace);
    detail::WideVectorsEnabled() = wide;
    CHECK(trace.untracedPath == InstructionPath::Baseline);
}

TEST_CASE("Traced queries and baseline scans give the same bits", "[properties][wide]")
{
    CheckAgainstBaseline(Kind::Traced);
}

// A processor without AVX2 or AVX-512F cannot run those kinds: their test cases report themselves skipped to ctest
// (skip.h) rather than passing unchecked.
TEST_CASE("Wide scans (AVX2) and baseline scans give the same bits", "[properties][wide]")
{
    if (!detail::WideVectorsEnabled())
    {
        SkipTestCase("this processor has no AVX2: the wide scans were not checked");
        return;
    }
    CheckAgainstBaseline(Kind::Wide256);
}

TEST_CASE("512-bit face loops (AVX-512F) and baseline scans give the same bits", "[properties][wide]")
{
    if (!detail::WideVectorsEnabled() || !detail::Wide512Enabled())
    {
        SkipTestCase("this processor has no AVX-512F: the 512-bit face loops were not checked");
        return;
    }
    CheckAgainstBaseline(Kind::Wide512);
}

namespace
{

// A polygon turned half a turn in its own frame (every vertex negated, exactly): face i of it is exactly
// anti-parallel to face i of `p`.
Polygon HalfTurned(const Polygon& p)
{
    std::vector<Vec2> points;
    for (const Vec2& v : p.Vertices())
    {
        points.push_back(-v);
    }
    PolygonResult result = MakePolygon(points);
    REQUIRE(result.Ok());
    return result.polygon;
}

} // namespace

TEST_CASE("The face loops in lanes give the textbook face loop's answer, skipped anti-parallel faces included",
          "[properties][wide]")
{
    // The face query of both polygons of each pair in both passes, by the loop the queries run for its sizes (four
    // faces at a time in lanes, or all the faces of a small polygon at once), against the textbook loop (face_query.h):
    // the same verdict, face and separation to the bit. Half the pairs are a polygon and itself turned half a turn, at
    // the same rotation in the world or a quarter turn apart: then every face of B is exactly anti-parallel to a
    // face of A and the second pass skips it, the last face included, which the lanes past it repeat.
    Rng rng(20261128);
    const int counts[] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    int skipping = 0;
    for (int i = 0; i < 4000; ++i)
    {
        RandomPair pair = ContactPair(rng, counts[rng.Int(0, 13)], static_cast<PairCategory>(rng.Int(0, 2)));
        if (i % 2 == 1)
        {
            pair.a = MakeShape(HalfTurned(pair.b.polygon));
            const Rot q = pair.xfB.q;
            pair.xfA = {pair.xfB.p + Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)},
                        rng.Chance(0.5) ? q : Rot{-q.s, q.c}};
        }
        const Polygon& a = pair.a.polygon;
        const Polygon& b = pair.b.polygon;
        INFO("pair " << i << ": " << a.Count() << " and " << b.Count() << " vertices");
        detail::NullTracer tracer;
        const detail::IncidentPolygon<double> incB(b, pair.xfA, pair.xfB, detail::kScanLimit);
        const detail::IncidentPolygon<double> incA(a, pair.xfB, pair.xfA, detail::kScanLimit);
        REQUIRE((incA.scan && incB.scan));
        for (const bool second : {false, true})
        {
            const Polygon& ref = second ? b : a;
            const detail::IncidentPolygon<double>& inc = second ? incA : incB;
            const int side = second ? 1 : 0;
            INFO((second ? "B's faces" : "A's faces"));
            const detail::FaceQuery<double> textbook = detail::TextbookFaceQuery<true>(ref, inc, side, second, tracer);
            const detail::FaceQuery<double> lanes =
                detail::QueryFaces<true>(ref, inc, side, second, -std::numeric_limits<double>::infinity(), tracer);
            REQUIRE(lanes.separated == textbook.separated);
            REQUIRE(lanes.face == textbook.face);
            REQUIRE(SameBits(lanes.separation, textbook.separation));
            skipping += second && detail::SecondPassSkips<true>(ref, inc, true) != 0 ? 1 : 0;
            // Overlap's face query: small polygons all faces at once, larger ones a face at a time.
            const bool separates = detail::TextbookFaceQuery<false>(ref, inc, side, second, tracer).separated;
            if (a.Count() <= 8 && b.Count() <= 8)
            {
                REQUIRE(detail::SmallFacesSeparate(ref, inc, side, second, tracer) == separates);
            }
            else
            {
                REQUIRE(detail::QueryFaces<false>(ref, inc, side, second, 0.0, tracer).separated == separates);
                // The face scan also keeps each vertex's largest separation (a vertex inside ref), as the textbook
                // loop does: the same numbers (== takes the two zeros for one, as the test <= 0 does).
                alignas(32) double lanesInside[detail::IncidentPolygon<double>::kCapacity];
                double textbookInside[detail::IncidentPolygon<double>::kCapacity];
                std::fill(std::begin(lanesInside), std::end(lanesInside), -std::numeric_limits<double>::infinity());
                std::fill(std::begin(textbookInside), std::end(textbookInside),
                          -std::numeric_limits<double>::infinity());
                detail::QueryFaces<false, true>(ref, inc, side, second, 0.0, tracer, lanesInside);
                detail::TextbookFaceQuery<false, true>(ref, inc, side, second, tracer, textbookInside);
                for (int j = 0; j < inc.polygon.Count(); ++j)
                {
                    REQUIRE(lanesInside[j] == textbookInside[j]);
                }
            }
        }
    }
    // Most of the half-turned pairs skip faces (the rest are those a rotation by a quarter turn leaves inexact).
    REQUIRE(skipping > 1000);
}
