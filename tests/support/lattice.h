// SPDX-License-Identifier: MIT
// Pairs whose geometry is exact in binary: polygons on a coarse dyadic lattice, placed by quarter turns (Rot{0, 1},
// not MakeRot(pi / 2), whose cosine is 6e-17) and lattice translations. Every coordinate of one shape mapped into
// the other's frame, every raw edge normal (RightPerp of an edge) and every product and sum the queries form from
// them is exact in double and in float, so a pair built here touches, stands apart or interpenetrates exactly as
// built: the boundary cases that random pairs almost never meet.
#pragma once

#include "random_shapes.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace satviz::testing
{

/// The lattice step, 2^-3. Lattice coordinates stay within a few hundred steps, so products of two of them and
/// their sums need at most 20 significant bits: exact in float's 24.
constexpr double kLatticeStep = 0.125;

/// A lattice coordinate: k steps, k uniform in [lo, hi].
inline double LatticeCoordinate(Rng& rng, int lo, int hi)
{
    return rng.Int(lo, hi) * kLatticeStep;
}

/// A lattice point with both coordinates in [lo, hi] steps.
inline Vec2 LatticePoint(Rng& rng, int lo, int hi)
{
    return {LatticeCoordinate(rng, lo, hi), LatticeCoordinate(rng, lo, hi)};
}

/// The rotation by k quarter turns, exactly: its cosine and sine are 0 and +-1.
inline Rot QuarterTurn(int k)
{
    switch (k & 3)
    {
    case 0:
        return {1.0, 0.0};
    case 1:
        return {0.0, 1.0};
    case 2:
        return {-1.0, 0.0};
    default:
        return {0.0, -1.0};
    }
}

/// Both components of a unit normal are 0 or +-1: the queries' unit normals, and so Collide's separations and the
/// sweeps' times on such a face, are exact.
inline bool AxisAligned(Vec2 n)
{
    return n.x == 0.0 || n.y == 0.0;
}

/// The convex hull of lattice points, which must span an area.
inline Polygon LatticeHull(const std::vector<Vec2>& points)
{
    PolygonResult result = ComputeHull(points);
    REQUIRE(result.Ok());
    return result.polygon;
}

/// A box of w by h steps from `corner`, each corner cut off now and then (by a 45-degree face or a steeper one):
/// 4 to 8 faces, the axis-aligned ones exact for Collide too.
inline Polygon LatticeBox(Rng& rng, Vec2 corner, int w, int h, double cutChance)
{
    const double s = kLatticeStep;
    const auto cut = [&](int limit) { return rng.Chance(cutChance) && limit >= 2 ? rng.Int(1, limit / 2) : 0; };
    std::vector<Vec2> points;
    // Corners counter-clockwise from the lower left; a cut corner becomes two points, each `c` steps along its edges.
    const Vec2 corners[4] = {corner, corner + Vec2{w * s, 0.0}, corner + Vec2{w * s, h * s}, corner + Vec2{0.0, h * s}};
    const Vec2 along[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}}; // direction of the edge leaving each corner
    for (int k = 0; k < 4; ++k)
    {
        const int cx = cut(std::min(w, h));
        const int cy = cx > 0 && rng.Chance(0.5) ? rng.Int(1, std::min(w, h) / 2) : cx;
        if (cx == 0)
        {
            points.push_back(corners[k]);
            continue;
        }
        const Vec2 entering = along[(k + 3) % 4];
        points.push_back(corners[k] - (cx * s) * entering);
        points.push_back(corners[k] + (cy * s) * along[k]);
    }
    return LatticeHull(points);
}

/// A random lattice polygon: a box with corners cut (axis-aligned faces, 4 to 8 vertices), the hull of a few
/// random points (3 to about 10 vertices, faces at any lattice angle), or the hull of the lattice points on an
/// ellipse (17 to 40 vertices: the queries walk such polygons instead of scanning them).
inline Polygon LatticePolygon(Rng& rng)
{
    const double s = kLatticeStep;
    switch (rng.Int(0, 3))
    {
    case 0:
    case 1:
    {
        const int w = rng.Int(2, 16);
        const int h = rng.Int(2, 16);
        return LatticeBox(rng, Vec2{-(w / 2) * s, -(h / 2) * s} + LatticePoint(rng, -2, 2), w, h, 0.4);
    }
    case 2:
    {
        for (;;)
        {
            std::vector<Vec2> points;
            const int count = rng.Int(3, 12);
            for (int i = 0; i < count; ++i)
            {
                points.push_back(LatticePoint(rng, -12, 12));
            }
            PolygonResult result = ComputeHull(points);
            if (result.Ok())
            {
                return result.polygon;
            }
        }
    }
    default:
    {
        // The highest and lowest lattice point of each column of an ellipse.
        for (;;)
        {
            const int a = rng.Int(12, 40);
            const int b = rng.Int(12, 40);
            std::vector<Vec2> points;
            for (int i = -a; i <= a; ++i)
            {
                const double u = static_cast<double>(i) / a;
                const int j = static_cast<int>(std::floor(b * std::sqrt(std::max(0.0, 1.0 - u * u))));
                points.push_back({i * s, j * s});
                points.push_back({i * s, -j * s});
            }
            PolygonResult result = ComputeHull(points);
            if (result.Ok() && result.polygon.Count() > 16)
            {
                return result.polygon;
            }
        }
    }
    }
}

/// A polygon from points given in the frame of the other shape of a pair (`xfOther`), as the body-frame polygon
/// of a shape placed at `xf`: each point mapped by xf^-1 xfOther, exactly (quarter turns, lattice translations).
inline Polygon InFrame(const std::vector<Vec2>& points, const Transform& xfOther, const Transform& xf)
{
    std::vector<Vec2> body;
    for (const Vec2& p : points)
    {
        body.push_back(InvTransformPoint(xf, TransformPoint(xfOther, p)));
        // The mapping must be exact for the pair to be what it was built as.
        REQUIRE(TransformPoint(xf, body.back()) == TransformPoint(xfOther, p));
    }
    PolygonResult result = MakePolygon(body);
    REQUIRE(result.Ok());
    return result.polygon;
}

/// A lattice placement: a position within 32 steps of the origin and a quarter turn. (Farther out, the body
/// coordinates of one shape mapped into the other's frame would need more bits than float's products keep.)
inline Transform LatticePlacement(Rng& rng)
{
    return {LatticePoint(rng, -32, 32), QuarterTurn(rng.Int(0, 3))};
}

/// The shortest lattice vector along v, a nonzero lattice vector: v divided by the greatest common divisor of its
/// components counted in steps.
inline Vec2 Primitive(Vec2 v)
{
    int x = static_cast<int>(std::lround(std::fabs(v.x) / kLatticeStep));
    int y = static_cast<int>(std::lround(std::fabs(v.y) / kLatticeStep));
    while (y != 0)
    {
        const int r = x % y;
        x = y;
        y = r;
    }
    return (1.0 / x) * v;
}

/// How a lattice pair is built against face `face` of A.
enum class Contact
{
    Touching,         ///< B lies in the closed outer half-plane of the face's line and meets the face
    Apart,            ///< then moved out by 1/8 of the shortest lattice vector along the face's normal
    Interpenetrating, ///< then moved in by as much
};

/// A pair of lattice polygons in contact across face `face` of A (A's frame), each placed by LatticePlacement.
struct LatticePair
{
    Polygon a;
    Transform xfA;
    Polygon b;
    Transform xfB;
    int face = 0;        ///< the face of A that B was placed against
    Vec2 normal{};       ///< its raw outward normal RightPerp(edge), in A's frame
    bool edgeOn = false; ///< B was built with an edge along the face's line (else by its deepest vertex)
    Contact contact = Contact::Touching;
    Vec2 offset{}; ///< B's offset from touching, in A's frame: 0, or 1/8 of the shortest lattice vector along +-normal
};

/// An uncut box of 2 to 16 steps a side, near the origin: every face axis-aligned, so that every query, the sweeps
/// included, computes exactly.
inline Polygon UncutLatticeBox(Rng& rng)
{
    const int w = rng.Int(2, 16);
    const int h = rng.Int(2, 16);
    return LatticeBox(rng, Vec2{-(w / 2) * kLatticeStep, -(h / 2) * kLatticeStep} + LatticePoint(rng, -2, 2), w, h,
                      0.0);
}

/// A lattice pair: A random (LatticePolygon, or with `boxes` an uncut box), B touching one of A's faces by the vertex
/// of B deepest along the face's inward normal (B random or a box too), set on a lattice point of the face (one of
/// its ends now and then; strictly inside it when interpenetrating), or by an edge laid along the face's line that
/// shares a stretch of the face; then moved by `contact`.
inline LatticePair TouchingLatticePair(Rng& rng, Contact contact, bool boxes = false)
{
    LatticePair pair;
    pair.a = boxes ? UncutLatticeBox(rng) : LatticePolygon(rng);
    pair.xfA = LatticePlacement(rng);
    pair.xfB = LatticePlacement(rng);
    pair.contact = contact;
    const Polygon& a = pair.a;
    pair.face = rng.Int(0, a.Count() - 1);
    const Vec2 p = a.Vertices()[pair.face];
    const Vec2 e = a.Edge(pair.face);
    const Vec2 n = RightPerp(e);
    pair.normal = n;
    // B's outline in A's frame.
    std::vector<Vec2> outline;
    pair.edgeOn = !boxes && rng.Chance(0.3);
    if (pair.edgeOn)
    {
        // Two points on the face's line at multiples of 1/8 of the edge (points of the finer lattice of 1/64, still
        // exact), from < 1 and to > 0 so that they share a stretch of the face, and the rest strictly outside.
        const int from = rng.Int(-8, 7);
        const int to = rng.Int(std::max(from, 0) + 1, from + 9);
        outline = {p + (from / 8.0) * e, p + (to / 8.0) * e};
        const int extra = rng.Int(1, 3);
        for (int i = 0; i < extra; ++i)
        {
            outline.push_back(p + (rng.Int(-8, 16) / 8.0) * e + (rng.Int(1, 8) / 8.0) * n);
        }
        const Polygon hull = LatticeHull(outline);
        outline.assign(hull.Vertices().begin(), hull.Vertices().end());
    }
    else
    {
        const Polygon b = boxes ? UncutLatticeBox(rng) : LatticePolygon(rng);
        const Rot turn = QuarterTurn(rng.Int(0, 3));
        int deepest = 0;
        for (int k = 1; k < b.Count(); ++k)
        {
            deepest = Dot(n, Rotate(turn, b.Vertices()[k])) < Dot(n, Rotate(turn, b.Vertices()[deepest])) ? k : deepest;
        }
        const bool end = contact != Contact::Interpenetrating && rng.Chance(0.2);
        const int eighth = end ? (rng.Chance(0.5) ? 0 : 8) : rng.Int(1, 7);
        const Vec2 target = p + (eighth / 8.0) * e;
        for (const Vec2& v : b.Vertices())
        {
            outline.push_back(Rotate(turn, v) - Rotate(turn, b.Vertices()[deepest]) + target);
        }
    }
    // Moved by 1/8 of a lattice vector: B's points stay on the lattice of 1/64.
    const double sign = contact == Contact::Touching ? 0.0 : (contact == Contact::Apart ? 0.125 : -0.125);
    pair.offset = sign * Primitive(n);
    for (Vec2& v : outline)
    {
        v = v + pair.offset;
    }
    pair.b = InFrame(outline, pair.xfA, pair.xfB);
    return pair;
}

} // namespace satviz::testing
