// SPDX-License-Identifier: MIT
// The wide scans (AVX2, chosen at run time) against the baseline instructions: the same bits for every query.

#include "sat_impl.h"
#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/same_bits.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

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

Answers Ask(const RandomPair& pair, Vec2 velocity, const ShapeT<float>& fa, const ShapeT<float>& fb)
{
    Answers out;
    out.overlap = Overlap(pair.a, pair.xfA, pair.b, pair.xfB);
    out.manifold = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
    out.sweep = Sweep(pair.a, pair.xfA, Vec2{}, pair.b, pair.xfB, velocity);
    const TransformT<float> xfA{ConvertVec<float>(pair.xfA.p),
                                {static_cast<float>(pair.xfA.q.c), static_cast<float>(pair.xfA.q.s)}};
    const TransformT<float> xfB{ConvertVec<float>(pair.xfB.p),
                                {static_cast<float>(pair.xfB.q.c), static_cast<float>(pair.xfB.q.s)}};
    out.floatOverlap = Overlap(fa, xfA, fb, xfB);
    out.floatManifold = Collide(fa, xfA, fb, xfB);
    out.floatSweep = Sweep(fa, xfA, Vec2T<float>{}, fb, xfB, ConvertVec<float>(velocity));
    return out;
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

TEST_CASE("Wide scans, 512-bit face loops and baseline scans give the same bits", "[properties][wide]")
{
    bool& wide = detail::WideVectorsEnabled();
    bool& wide512 = detail::Wide512Enabled();
    const bool available = wide;
    const bool available512 = wide512;
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
        wide = false;
        const Answers baseline = Ask(pair, velocity, fa, fb);
        // The widest the processor has (512-bit face loops where it has AVX-512), then 256-bit vectors alone.
        for (const bool with512 : {true, false})
        {
            wide = available;
            wide512 = available512 && with512;
            const Answers first = Ask(pair, velocity, fa, fb);
            INFO("pair " << i << (with512 ? ", widest vectors" : ", 256-bit vectors"));
            REQUIRE(first.overlap == baseline.overlap);
            REQUIRE(SameBits(first.manifold, baseline.manifold));
            REQUIRE(SameBits(first.sweep, baseline.sweep));
            REQUIRE(first.floatOverlap == baseline.floatOverlap);
            REQUIRE(SameBits(first.floatManifold, baseline.floatManifold));
            REQUIRE(SameBits(first.floatSweep, baseline.floatSweep));
        }
        wide = available;
        wide512 = available512;
        ++pairs;
    }
    REQUIRE(pairs > 25000);
}
