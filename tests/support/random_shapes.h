// SPDX-License-Identifier: MIT
// Seeded random convex polygons, circles and placements, shared by the tests and the benchmarks.
#pragma once

#include <satviz/sat.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace satviz::testing
{

constexpr double kPi = 3.14159265358979323846;

/// A seeded random source with the few distributions the generators need.
struct Rng
{
    std::mt19937_64 engine;
    explicit Rng(uint64_t seed) : engine(seed) {}
    /// Uniform in [lo, hi).
    double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
    /// Uniform integer in [lo, hi].
    int Int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }
    /// True with probability p.
    bool Chance(double p) { return Uniform(0.0, 1.0) < p; }
    /// 10^Uniform(lo, hi).
    double LogUniform(double lo, double hi) { return std::pow(10.0, Uniform(lo, hi)); }
};

/// n points on a randomly rotated ellipse (radius `radius`, axis ratio `aspect`) at jittered, strictly increasing
/// angles: strictly convex and counter-clockwise. Retries until MakePolygon accepts the outline.
inline Polygon RandomPolygon(Rng& rng, int n, double radius, double aspect)
{
    for (;;)
    {
        const double rotation = rng.Uniform(0.0, 2.0 * kPi);
        const double c = std::cos(rotation);
        const double s = std::sin(rotation);
        const double start = rng.Uniform(0.0, 2.0 * kPi);
        std::vector<Vec2> points(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i)
        {
            const double angle = start + 2.0 * kPi * (i + rng.Uniform(0.05, 0.95)) / n;
            const double x = radius * std::cos(angle);
            const double y = radius * aspect * std::sin(angle);
            points[static_cast<size_t>(i)] = {c * x - s * y, c * y + s * x};
        }
        PolygonResult result = MakePolygon(points);
        if (result.Ok())
        {
            return result.polygon;
        }
    }
}

/// Largest distance of a polygon's vertex from its body origin.
inline double Radius(const Polygon& polygon)
{
    double radius = 0.0;
    for (const Vec2& v : polygon.Vertices())
    {
        radius = std::max(radius, Length(v));
    }
    return radius;
}

/// A random pair of shapes with transforms.
struct RandomPair
{
    Shape a;
    Transform xfA;
    Shape b;
    Transform xfB;
};

/// A random vertex count, mostly small, sometimes large.
inline int RandomVertexCount(Rng& rng)
{
    const double u = rng.Uniform(0.0, 1.0);
    if (u < 0.85)
    {
        return rng.Int(3, 12);
    }
    if (u < 0.98)
    {
        return rng.Int(13, 64);
    }
    return rng.Int(65, 300);
}

/// A random shape: a polygon (a sliver now and then) or, with probability `circleChance`, a circle.
inline Shape RandomShape(Rng& rng, double circleChance)
{
    const double radius = rng.Uniform(0.3, 1.5);
    if (rng.Chance(circleChance))
    {
        Circle circle;
        circle.radius = radius;
        circle.center = {rng.Uniform(-0.3, 0.3), rng.Uniform(-0.3, 0.3)};
        return MakeShape(circle);
    }
    const double aspect = rng.Chance(0.1) ? rng.LogUniform(-3.0, -1.0) : rng.Uniform(0.35, 1.0);
    return MakeShape(RandomPolygon(rng, RandomVertexCount(rng), radius, aspect));
}

/// Two random shapes placed so that about half of the pairs overlap, some contained in the other.
inline RandomPair RandomShapePair(Rng& rng, double circleChance)
{
    RandomPair pair;
    pair.a = RandomShape(rng, circleChance);
    pair.b = RandomShape(rng, circleChance);
    pair.xfA = MakeTransform(Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}, rng.Uniform(-kPi, kPi));
    const double direction = rng.Uniform(0.0, 2.0 * kPi);
    const double distance = rng.Uniform(0.0, 2.6);
    const Vec2 offset{distance * std::cos(direction), distance * std::sin(direction)};
    pair.xfB = MakeTransform(pair.xfA.p + offset, rng.Uniform(-kPi, kPi));
    return pair;
}

/// How a contact pair is placed.
enum class PairCategory
{
    Overlap,   ///< pushed into each other by 1e-4 to 0.5 of the smaller width
    Touch,     ///< within 1e-9 of touching, either side
    Separated, ///< apart by 1e-4 to 0.5
};

/// Two n-gons in contact: B's support vertex (or, 30% of the time, one of B's edges turned anti-parallel) is placed
/// on a random boundary point P of A, then B is pushed by a signed distance along A's outward normal at P. A
/// negative push overlaps, a positive one separates: the line through P then separates the pair.
inline RandomPair ContactPair(Rng& rng, int n, PairCategory category, double slivers = 0.0)
{
    RandomPair pair;
    const double aspectA = rng.Chance(slivers) ? rng.LogUniform(-4.0, -2.0) : rng.Uniform(0.35, 1.0);
    const double aspectB = rng.Chance(slivers * 0.5) ? rng.LogUniform(-4.0, -2.0) : rng.Uniform(0.35, 1.0);
    const double radiusA = rng.Uniform(0.5, 1.5);
    const double radiusB = rng.Uniform(0.5, 1.5);
    const Polygon a = RandomPolygon(rng, n, radiusA, aspectA);
    const Polygon b = RandomPolygon(rng, n, radiusB, aspectB);
    const double width = 2.0 * std::min(radiusA * aspectA, radiusB * aspectB);

    // A boundary point of A, on an edge chosen by length.
    double perimeter = 0.0;
    for (int i = 0; i < a.Count(); ++i)
    {
        perimeter += Length(a.Edge(i));
    }
    double pick = rng.Uniform(0.0, perimeter);
    int edge = 0;
    while (edge + 1 < a.Count() && pick > Length(a.Edge(edge)))
    {
        pick -= Length(a.Edge(edge));
        ++edge;
    }
    const Vec2 point = a.Vertices()[edge] + rng.Uniform(0.1, 0.9) * a.Edge(edge);
    const Vec2 normal = a.Normal(edge);

    // B's rotation relative to A, and the vertex of B that touches the point.
    double angleB = rng.Uniform(-kPi, kPi);
    int touching = 0;
    if (rng.Chance(0.3))
    {
        // Edge against edge: turn B so that its edge j faces A's edge.
        const int j = rng.Int(0, n - 1);
        const Vec2 nb = b.Normal(j);
        angleB = std::atan2(-normal.y, -normal.x) - std::atan2(nb.y, nb.x);
        touching = j;
    }
    else
    {
        const Rot q = MakeRot(angleB);
        double lowest = 1e300;
        for (int k = 0; k < n; ++k)
        {
            const double d = Dot(normal, Rotate(q, b.Vertices()[k]));
            if (d < lowest)
            {
                lowest = d;
                touching = k;
            }
        }
    }
    double delta = 0.0;
    switch (category)
    {
    case PairCategory::Overlap:
        delta = -width * rng.LogUniform(-4.0, -0.3);
        break;
    case PairCategory::Touch:
        delta = rng.Uniform(-1e-9, 1e-9);
        break;
    case PairCategory::Separated:
        delta = rng.LogUniform(-4.0, -0.3);
        break;
    }
    const Rot qB = MakeRot(angleB);
    const Vec2 positionInA = point - Rotate(qB, b.Vertices()[touching]) + delta * normal;

    const double angleA = rng.Uniform(-kPi, kPi);
    pair.a = MakeShape(a);
    pair.b = MakeShape(b);
    pair.xfA = MakeTransform(Vec2{rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)}, angleA);
    pair.xfB = MakeTransform(TransformPoint(pair.xfA, positionInA), angleA + angleB);
    return pair;
}

} // namespace satviz::testing
