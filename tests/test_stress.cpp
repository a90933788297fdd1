// SPDX-License-Identifier: MIT
// Numerical stress tests, for both precisions: shapes far from the origin, tiny and huge shapes, slivers,
// near-parallel edges, tiny gaps, nearly collinear vertices, repeated moves to contact. Each case states the bound
// it holds and asserts it against the quadruple-precision reference, computed on the exact inputs the queries see
// (for float: the shapes and transforms rounded to float).
#include "support/random_shapes.h"
#include "support/reference.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// What each precision promises, relative to the size of the shapes.
template <typename S>
struct Bounds;

template <>
struct Bounds<double>
{
    static constexpr double kBand = 1e-12;  ///< yes/no answers are exact outside this band
    static constexpr double kDepth = 1e-14; ///< penetration depth error
    static constexpr const char* kName = "double";
};

template <>
struct Bounds<float>
{
    static constexpr double kBand = 1e-5;
    static constexpr double kDepth = 1e-5;
    static constexpr const char* kName = "float";
};

/// Worst errors seen over a set of pairs.
struct Tally
{
    int pairs = 0;
    int wrong = 0;         ///< wrong yes/no answers outside the band
    int inBand = 0;        ///< pairs within the band (either answer accepted)
    double depthError = 0; ///< worst |depth error| / scale
};

/// A pair rounded to precision S, with the double view of exactly those values for the reference.
template <typename S>
struct Rounded
{
    ShapeT<S> a, b;
    TransformT<S> xfA, xfB;
    Shape da, db; ///< the same shapes, widened back to double (exact)
    Transform dxfA, dxfB;
    bool ok = false;
};

template <typename S>
bool Round(const Shape& in, ShapeT<S>& out, Shape& back)
{
    if (in.type == ShapeType::Circle)
    {
        out = MakeShape(CircleT<S>{ConvertVec<S>(in.circle.center), static_cast<S>(in.circle.radius)});
        back = MakeShape(Circle{ConvertVec<double>(out.circle.center), static_cast<double>(out.circle.radius)});
        return true;
    }
    PolygonResultT<S> polygon = ConvertPolygon<S>(in.polygon);
    if (!polygon.Ok())
    {
        return false;
    }
    PolygonResult widened = ConvertPolygon<double>(polygon.polygon);
    if (!widened.Ok())
    {
        return false;
    }
    out = MakeShape(std::move(polygon.polygon));
    back = MakeShape(std::move(widened.polygon));
    return true;
}

template <typename S>
TransformT<S> RoundTransform(const Transform& xf)
{
    return {ConvertVec<S>(xf.p), {static_cast<S>(xf.q.c), static_cast<S>(xf.q.s)}};
}

template <typename S>
Rounded<S> RoundPair(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB)
{
    Rounded<S> r;
    r.ok = Round<S>(a, r.a, r.da) && Round<S>(b, r.b, r.db);
    r.xfA = RoundTransform<S>(xfA);
    r.xfB = RoundTransform<S>(xfB);
    r.dxfA = {ConvertVec<double>(r.xfA.p), {static_cast<double>(r.xfA.q.c), static_cast<double>(r.xfA.q.s)}};
    r.dxfB = {ConvertVec<double>(r.xfB.p), {static_cast<double>(r.xfB.q.c), static_cast<double>(r.xfB.q.s)}};
    return r;
}

double Scale(const Shape& s)
{
    return s.type == ShapeType::Circle ? s.circle.radius : Radius(s.polygon);
}

/// Runs Overlap and Collide in precision S on a pair and scores them against the reference.
template <typename S>
void Score(Tally& tally, const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB)
{
    const Rounded<S> r = RoundPair<S>(a, xfA, b, xfB);
    if (!r.ok)
    {
        return; // a polygon does not survive rounding: not a pair of this precision
    }
    const Reference ref = ReferenceCollide(r.da, r.dxfA, r.db, r.dxfB);
    const double scale = std::max(Scale(r.da), Scale(r.db));
    const double margin = std::abs(static_cast<double>(ref.separation)) / scale;
    const bool overlap = Overlap(r.a, r.xfA, r.b, r.xfB);
    const ManifoldT<S> m = Collide(r.a, r.xfA, r.b, r.xfB);
    tally.pairs += 1;
    if (margin <= Bounds<S>::kBand)
    {
        tally.inBand += 1;
    }
    else
    {
        tally.wrong += (overlap != ref.overlap) + (m.overlap != ref.overlap);
    }
    if (m.overlap && ref.overlap)
    {
        tally.depthError = std::max(
            tally.depthError, std::abs(static_cast<double>(m.depth) + static_cast<double>(ref.separation)) / scale);
    }
}

std::string Short(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

template <typename S>
void Require(const Tally& tally, const std::string& what)
{
    INFO(what << " (" << Bounds<S>::kName << "): " << tally.pairs << " pairs, " << tally.inBand << " within the band, "
              << tally.wrong << " wrong outside it, worst depth error " << tally.depthError << " of the shape size");
    CHECK(tally.pairs > 0);
    CHECK(tally.wrong == 0);
    CHECK(tally.depthError <= Bounds<S>::kDepth);
}

template <typename S>
void FarFromOrigin()
{
    Rng rng(101);
    for (double offset : {1e3, 1e4, 1e5, 1e6, 1e7, 1e8})
    {
        Tally tally;
        for (int i = 0; i < 1500; ++i)
        {
            RandomPair p = ContactPair(rng, rng.Int(3, 12), static_cast<PairCategory>(rng.Int(0, 2)));
            const Vec2 shift{offset * (rng.Chance(0.5) ? 1.0 : -1.0), offset * (rng.Chance(0.5) ? 1.0 : -1.0)};
            p.xfA.p = p.xfA.p + shift;
            p.xfB.p = p.xfB.p + shift;
            Score<S>(tally, p.a, p.xfA, p.b, p.xfB);
        }
        Require<S>(tally, "far from the origin, offset " + Short(offset));
    }
}

template <typename S>
void TinyAndHuge()
{
    Rng rng(202);
    for (double size : {1e-6, 1e-3, 1.0, 1e3, 1e6})
    {
        Tally tally;
        for (int i = 0; i < 1500; ++i)
        {
            const RandomPair p = ContactPair(rng, rng.Int(3, 12), static_cast<PairCategory>(rng.Int(0, 2)));
            auto scaled = [&](const Shape& s) {
                std::vector<Vec2> points;
                for (const Vec2& v : s.polygon.vertices)
                {
                    points.push_back(size * v);
                }
                return MakeShape(MakePolygon(points).polygon);
            };
            const Transform xfA{size * p.xfA.p, p.xfA.q};
            const Transform xfB{size * p.xfB.p, p.xfB.q};
            Score<S>(tally, scaled(p.a), xfA, scaled(p.b), xfB);
        }
        Require<S>(tally, "shapes of size " + Short(size));
    }
}

template <typename S>
void Slivers()
{
    Rng rng(303);
    Tally tally;
    for (int i = 0; i < 3000; ++i)
    {
        const double aspect = rng.LogUniform(-6.0, -2.0);
        const Polygon sliver = RandomPolygon(rng, rng.Int(3, 8), rng.Uniform(0.5, 1.5), aspect);
        const Polygon other = RandomPolygon(rng, rng.Int(3, 8), rng.Uniform(0.5, 1.5), rng.Uniform(0.3, 1.0));
        const Transform xfA = MakeTransform(Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(-kPi, kPi));
        const Transform xfB = MakeTransform(Vec2{rng.Uniform(-2, 2), rng.Uniform(-2, 2)}, rng.Uniform(-kPi, kPi));
        Score<S>(tally, MakeShape(sliver), xfA, MakeShape(other), xfB);
        Score<S>(tally, MakeShape(other), xfB, MakeShape(sliver), xfA);
    }
    Require<S>(tally, "slivers of aspect 1e-6 to 1e-2");
}

template <typename S>
void NearParallelEdges()
{
    // B's bottom edge rests on A's top face, turned by a tiny angle, pushed in by a depth from 1e-9 to 0.1.
    Rng rng(404);
    const Shape a = MakeShape(MakeBox(2.0, 0.5).polygon);
    const Shape b = MakeShape(MakeBox(0.7, 0.3).polygon);
    for (double angle : {1e-12, 1e-9, 1e-6, 1e-3})
    {
        Tally tally;
        for (int i = 0; i < 400; ++i)
        {
            const double turn = angle * (rng.Chance(0.5) ? 1.0 : -1.0);
            const double depth = rng.LogUniform(-9.0, -1.0);
            const double x = rng.Uniform(-1.0, 1.0);
            // The lowest corner of the turned box sits `depth` below A's top face.
            const double lowest = 0.3 * std::cos(turn) + 0.7 * std::abs(std::sin(turn));
            const Transform xfB = MakeTransform(Vec2{x, 0.5 + lowest - depth}, turn);
            Score<S>(tally, a, Transform{{0.0, 0.0}, {1.0, 0.0}}, b, xfB);
        }
        Require<S>(tally, "near-parallel edges, angle " + Short(angle));
    }
}

template <typename S>
void TinyGaps()
{
    // A hexagon above a box, its lowest vertex at a signed gap from 1e-15 to 1e-3 over the box's top face.
    Rng rng(505);
    const Shape a = MakeShape(MakeBox(1.5, 0.5).polygon);
    const Shape b = MakeShape(MakeRegularPolygon(6, 0.4, 0.25).polygon);
    Tally tally;
    for (int e = -15; e <= -3; ++e)
    {
        for (int i = 0; i < 100; ++i)
        {
            const double gap = std::pow(10.0, e) * rng.Uniform(1.0, 9.99) * (rng.Chance(0.5) ? 1.0 : -1.0);
            const double angle = rng.Uniform(-0.2, 0.2);
            const Transform xfB0 = MakeTransform(Vec2{rng.Uniform(-1.0, 1.0), 0.0}, angle);
            double lowest = INFINITY;
            for (const Vec2& v : b.polygon.vertices)
            {
                lowest = std::min(lowest, TransformPoint(xfB0, v).y);
            }
            const Transform xfB = MakeTransform(Vec2{xfB0.p.x, 0.5 - lowest + gap}, angle);
            Score<S>(tally, a, Transform{{0.0, 0.0}, {1.0, 0.0}}, b, xfB);
        }
    }
    Require<S>(tally, "gaps from 1e-15 to 1e-3");
}

template <typename S>
void NearlyCollinear()
{
    // A hexagon with one edge's midpoint pushed out by eps: valid for large eps, rejected as collinear (never as
    // anything else) when eps vanishes in rounding; accepted outlines keep the query bounds.
    Rng rng(606);
    for (double eps : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15})
    {
        Tally tally;
        int rejected = 0;
        for (int i = 0; i < 300; ++i)
        {
            const Polygon hex = MakeRegularPolygon(6, 1.0, rng.Uniform(0.0, 1.0)).polygon;
            std::vector<Vec2> points(hex.vertices.begin(), hex.vertices.end());
            const Vec2 mid = 0.5 * (points[0] + points[1]);
            points.insert(points.begin() + 1, mid + eps * hex.Normal(0));
            const PolygonResult result = MakePolygon(points);
            if (!result.Ok())
            {
                INFO("eps " << eps << ": " << DescribePolygonError(result.error, result.vertex));
                CHECK((result.error == PolygonError::CollinearVertex || result.error == PolygonError::NotConvex));
                ++rejected;
                continue;
            }
            const RandomPair p = ContactPair(rng, 5, static_cast<PairCategory>(rng.Int(0, 2)));
            Score<S>(tally, MakeShape(result.polygon), p.xfA, p.b, p.xfB);
        }
        if (tally.pairs > 0)
        {
            Require<S>(tally, "nearly collinear vertices, eps " + Short(eps));
        }
        if (eps >= 1e-9)
        {
            CHECK(rejected == 0); // clearly convex outlines are accepted
        }
    }
}

template <typename S>
void RepeatedMovesToContact()
{
    // A box driven into a wall and along a floor, step after step: it never sinks in and never stops short.
    Rng rng(707);
    const ShapeT<S> mover = MakeShape(MakeBox(S(0.25), S(0.25)).polygon);
    const ShapeT<S> floor = MakeShape(MakeBox(S(50), S(0.5)).polygon);
    const ShapeT<S> wall = MakeShape(MakeBox(S(0.5), S(5)).polygon);
    const ObstacleT<S> obstacles[2] = {{&floor, TransformT<S>{{S(0), S(0)}, {S(1), S(0)}}},
                                       {&wall, TransformT<S>{{S(10), S(5)}, {S(1), S(0)}}}};
    TransformT<S> xf{{S(0), S(0.75)}, {S(1), S(0)}};
    S lowest = S(10);
    for (int step = 0; step < 2000; ++step)
    {
        const Vec2T<S> push{static_cast<S>(rng.Uniform(0.001, 0.2)), static_cast<S>(-rng.Uniform(0.0, 0.1))};
        const SlideResultT<S> result = MoveAndSlide(mover, xf, push, obstacles, 2);
        xf = result.xf;
        for (const ObstacleT<S>& o : obstacles)
        {
            const ManifoldT<S> m = Collide(mover, xf, *o.shape, o.xf);
            REQUIRE((!m.overlap || m.depth == S(0)));
        }
        lowest = std::min(lowest, xf.p.y);
    }
    INFO(Bounds<S>::kName << ": after 2000 steps the box is at " << xf.p.x << ", " << xf.p.y);
    // Resting on the floor (top at 0.5, half height 0.25) and against the wall (left face at 9.5).
    CHECK(lowest >= S(0.75));
    CHECK(xf.p.y <= S(0.75) + S(1e-3));
    CHECK(xf.p.x >= S(9.25) - S(1e-3));
    CHECK(xf.p.x <= S(9.25));
}

} // namespace

TEMPLATE_TEST_CASE("Stress: far from the origin, offsets 1e3 to 1e8", "[stress]", double, float)
{
    FarFromOrigin<TestType>();
}

TEMPLATE_TEST_CASE("Stress: tiny and huge shapes, sizes 1e-6 to 1e6", "[stress]", double, float)
{
    TinyAndHuge<TestType>();
}

TEMPLATE_TEST_CASE("Stress: slivers down to aspect 1e-6", "[stress]", double, float)
{
    Slivers<TestType>();
}

TEMPLATE_TEST_CASE("Stress: near-parallel edges, angles down to 1e-12", "[stress]", double, float)
{
    NearParallelEdges<TestType>();
}

TEMPLATE_TEST_CASE("Stress: gaps from 1e-15 to 1e-3", "[stress]", double, float)
{
    TinyGaps<TestType>();
}

TEMPLATE_TEST_CASE("Stress: nearly collinear vertices", "[stress]", double, float)
{
    NearlyCollinear<TestType>();
}

TEMPLATE_TEST_CASE("Stress: repeated moves to contact neither stick nor sink", "[stress]", double, float)
{
    RepeatedMovesToContact<TestType>();
}
