// SPDX-License-Identifier: MIT
// Concave shapes in the queries: against an exact test of the concave outline itself, notches and teeth, and
// seams that must not catch a sliding shape.

#include "support/random_concave.h"

#include <satviz/collide.h>
#include <satviz/concave.h>

#include <catch2/catch.hpp>

using namespace satviz;
using namespace satviz::testing;

namespace
{

Concave ConcaveOf(const std::vector<Vec2>& outline, DecomposeMethod method = DecomposeMethod::Fast)
{
    const Decomposition d = Decompose(outline, method);
    REQUIRE(d.Ok());
    return MakeConcave(d.pieces);
}

std::vector<Vec2> Placed(const std::vector<Vec2>& points, const Transform& xf)
{
    std::vector<Vec2> out;
    for (const Vec2& p : points)
    {
        out.push_back(TransformPoint(xf, p));
    }
    return out;
}

bool SegmentsTouch(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
    const int o1 = TurnSign(a, b, c);
    const int o2 = TurnSign(a, b, d);
    const int o3 = TurnSign(c, d, a);
    const int o4 = TurnSign(c, d, b);
    return o1 * o2 <= 0 && o3 * o4 <= 0 && !(o1 == 0 && o2 == 0);
}

// The oracle: two outlines (world) intersect when some pair of edges meets or a vertex of one is inside the other.
bool OutlinesOverlap(const std::vector<Vec2>& p, const std::vector<Vec2>& q)
{
    for (size_t i = 0; i < p.size(); ++i)
    {
        for (size_t j = 0; j < q.size(); ++j)
        {
            if (SegmentsTouch(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()]))
            {
                return true;
            }
        }
    }
    return InsideOutline(p, q[0]) || InsideOutline(q, p[0]);
}

Shape Box(double halfWidth, double halfHeight)
{
    return MakeShape(MakeBox(halfWidth, halfHeight).polygon);
}

} // namespace

TEST_CASE("Concave Overlap and Collide agree with an exact test of the concave outline", "[concave]")
{
    Rng rng(21);
    int overlaps = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const std::vector<Vec2> outline = RandomStarPolygon(rng, rng.Int(5, 30), 2.0, 0.2);
        const Concave concave = ConcaveOf(outline, trial % 2 == 0 ? DecomposeMethod::Fast : DecomposeMethod::Fewest);
        const Polygon convex = RandomPolygon(rng, rng.Int(3, 8), rng.Uniform(0.1, 1.0), rng.Uniform(0.2, 1.0));
        const Transform xfA = MakeTransform(Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(0, 2 * kPi));
        const Transform xfB = MakeTransform(Vec2{rng.Uniform(-3, 3), rng.Uniform(-3, 3)}, rng.Uniform(0, 2 * kPi));
        const Shape b = MakeShape(convex);
        const bool expected =
            OutlinesOverlap(Placed(outline, xfA), Placed({convex.Vertices().begin(), convex.Vertices().end()}, xfB));
        INFO("trial " << trial);
        REQUIRE(Overlap(concave, xfA, b, xfB) == expected);
        REQUIRE(Overlap(b, xfB, concave, xfA) == expected);
        const ConcaveManifold m = Collide(concave, xfA, b, xfB);
        REQUIRE(m.manifold.overlap == expected);
        overlaps += expected;
        if (expected)
        {
            // Moving B by the MTV clears the deciding piece (it is that piece's own MTV, not a sum).
            Transform moved = xfB;
            moved.p = moved.p + (m.manifold.depth + 1e-9) * m.manifold.normal;
            REQUIRE(m.pieceA >= 0);
            CHECK(!Overlap(concave.parts[m.pieceA].shape, xfA, b, moved));
            REQUIRE(m.manifold.contactCount >= 1);
            // Swapped: the same depth (the deciding piece may differ where two pairs are equally deep).
            const ConcaveManifold swapped = Collide(b, xfB, concave, xfA);
            CHECK(swapped.manifold.depth == Approx(m.manifold.depth).margin(1e-12));
        }
        else
        {
            CHECK(m.manifold.gap > 0);
        }
    }
    CHECK(overlaps > 500);
    CHECK(overlaps < 2500);
}

TEST_CASE("Two concave shapes overlap exactly when their outlines do", "[concave]")
{
    Rng rng(22);
    for (int trial = 0; trial < 1000; ++trial)
    {
        const std::vector<Vec2> p = RandomStarPolygon(rng, rng.Int(5, 20), 1.0, 0.2);
        const std::vector<Vec2> q = RandomUntangledPolygon(rng, rng.Int(4, 12), 1.5);
        const Transform xfA = MakeTransform(Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(0, 2 * kPi));
        const Transform xfB = MakeTransform(Vec2{rng.Uniform(-2, 2), rng.Uniform(-2, 2)}, rng.Uniform(0, 2 * kPi));
        const bool expected = OutlinesOverlap(Placed(p, xfA), Placed(q, xfB));
        INFO("trial " << trial);
        REQUIRE(Overlap(ConcaveOf(p), xfA, ConcaveOf(q), xfB) == expected);
        REQUIRE(Collide(ConcaveOf(p), xfA, ConcaveOf(q), xfB).manifold.overlap == expected);
    }
}

TEST_CASE("A box in an L's notch or between a comb's teeth does not collide, though the convex hull would", "[concave]")
{
    const std::vector<Vec2> ell{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
    // Teeth over [0, 1], [2, 3], ..., [8, 9] standing on a spine [0, 9] x [0, 1].
    const std::vector<Vec2> comb{{0, 0}, {9, 0}, {9, 4}, {8, 4}, {8, 1}, {7, 1}, {7, 4}, {6, 4}, {6, 1}, {5, 1},
                                 {5, 4}, {4, 4}, {4, 1}, {3, 1}, {3, 4}, {2, 4}, {2, 1}, {1, 1}, {1, 4}, {0, 4}};
    const Shape box = Box(0.4, 0.4);
    struct Case
    {
        const std::vector<Vec2>* outline;
        Vec2 where;
    };
    for (const Case& c : {Case{&ell, {2.5, 2.5}}, Case{&comb, {1.5, 2.5}}, Case{&comb, {7.5, 2.0}}})
    {
        for (DecomposeMethod method : {DecomposeMethod::Fast, DecomposeMethod::Fewest})
        {
            const Concave concave = ConcaveOf(*c.outline, method);
            const Transform xfBox = MakeTransform(c.where, 0.0);
            CHECK(!Overlap(concave, Transform{}, box, xfBox));
            CHECK(!Collide(concave, Transform{}, box, xfBox).manifold.overlap);
            CHECK(Overlap(MakeShape(ComputeHull(*c.outline).polygon), Transform{}, box, xfBox));
            // Dropped onto the notch's floor, it hits the floor (normal up), not the hull's top.
            const ConcaveSweepResult hit = Sweep(concave, Transform{}, Vec2{}, box, xfBox, Vec2{0, -3});
            REQUIRE(hit.result.status == SweepStatus::Hit);
            CHECK(hit.result.normal.y == Approx(1.0));
            CHECK(hit.result.toi == Approx((c.where.y - 0.4 - 1.0) / 3.0));
            // A ray down the notch meets its floor.
            const ConcaveRayHit ray = RayCast(concave, Transform{}, c.where, c.where - Vec2{0, 5});
            REQUIRE(ray.hit.hit);
            CHECK(ray.hit.point.y == Approx(1.0));
        }
    }
}

TEST_CASE("A box sliding across a floor of pieces does not catch on the seams", "[concave]")
{
    const Concave floor = TileFloor(10);
    int seamPairsDropped = 0;
    // Pressed in a little (box and circle), and deeper than the box's half width (a box across a seam then
    // overlaps each tile less sideways than downwards: each pair alone would push it out sideways).
    for (const auto& [shape, depth] : {std::pair{Box(0.25, 0.25), 0.01}, std::pair{Box(0.25, 0.25), 0.3},
                                       std::pair{MakeShape(Circle{{0, 0}, 0.3}), 0.01}})
    {
        const double bottom = shape.type == ShapeType::Polygon ? 0.25 : 0.3;
        for (double x = 0.4; x <= 9.6; x += 0.0037)
        {
            const Transform xf = MakeTransform(Vec2{x, bottom - depth}, 0.0);
            const ConcaveManifold m = Collide(floor, Transform{}, shape, xf);
            INFO("x " << x << ", depth " << depth);
            REQUIRE(m.manifold.overlap);
            CHECK(m.manifold.normal.x == Approx(0.0).margin(1e-12));
            CHECK(m.manifold.normal.y == Approx(1.0));
            CHECK(m.manifold.depth == Approx(depth).margin(1e-12));
            seamPairsDropped += m.pairsSeam;
            if (shape.type == ShapeType::Polygon)
            {
                // The box's two bottom corners, as on a floor of one piece; a corner that reaches past a seam by
                // less than the depth is met only by the dropped pair, and the contact stays at the seam.
                REQUIRE(m.manifold.contactCount == 2);
                const double x0 = std::min(m.manifold.contacts[0].point.x, m.manifold.contacts[1].point.x);
                const double x1 = std::max(m.manifold.contacts[0].point.x, m.manifold.contacts[1].point.x);
                CHECK(x0 >= x - 0.25 - 1e-12);
                CHECK(x0 <= x - 0.25 + depth);
                CHECK(x1 <= x + 0.25 + 1e-12);
                CHECK(x1 >= x + 0.25 - depth);
            }
            // The same from the other side: the floor as B.
            const ConcaveManifold swapped = Collide(shape, xf, floor, Transform{});
            CHECK(swapped.manifold.normal.y == Approx(-1.0));
            CHECK(swapped.manifold.depth == Approx(depth).margin(1e-12));
        }
    }
    // Seams were there to catch on: pairs whose own normal was sideways were met and dropped.
    CHECK(seamPairsDropped > 0);

    // Swept along the floor's surface, pressed in: the box overlaps from the start, with the surface's normal.
    const Shape box = Box(0.25, 0.25);
    const double depth = 0.01;
    const ConcaveSweepResult swept =
        Sweep(floor, Transform{}, Vec2{}, box, MakeTransform(Vec2{0.5, 0.25 - depth}, 0.0), Vec2{8, 0});
    CHECK(swept.result.status == SweepStatus::Overlapping);
    CHECK(swept.result.initial.normal.y == Approx(1.0));
    // Falling onto a seam: a hit with the surface's normal.
    const ConcaveSweepResult fall =
        Sweep(floor, Transform{}, Vec2{}, box, MakeTransform(Vec2{3.0, 2.0}, 0.0), Vec2{0.5, -4});
    REQUIRE(fall.result.status == SweepStatus::Hit);
    CHECK(fall.result.normal.y == Approx(1.0));
    CHECK(fall.result.toi == Approx(1.75 / 4));
}

TEST_CASE("A segment cast at a concave shape stops where it first meets the outline", "[concave]")
{
    Rng rng(23);
    int hits = 0;
    for (int trial = 0; trial < 2000; ++trial)
    {
        const std::vector<Vec2> outline = RandomStarPolygon(rng, rng.Int(5, 30), 1.0, 0.2);
        const Concave concave = ConcaveOf(outline);
        const Transform xf = MakeTransform(Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(0, 2 * kPi));
        const Vec2 p1{rng.Uniform(-3, 3), rng.Uniform(-3, 3)};
        const Vec2 p2{rng.Uniform(-3, 3), rng.Uniform(-3, 3)};
        const std::vector<Vec2> placed = Placed(outline, xf);
        const ConcaveRayHit hit = RayCast(concave, xf, p1, p2);
        INFO("trial " << trial);
        if (InsideOutline(placed, p1))
        {
            CHECK(hit.hit.startsInside);
            continue;
        }
        // Oracle: the least parameter at which the segment crosses an edge of the outline.
        double first = 2;
        const Vec2 d = p2 - p1;
        for (size_t i = 0; i < placed.size(); ++i)
        {
            const Vec2 a = placed[i];
            const Vec2 e = placed[(i + 1) % placed.size()] - a;
            const double denom = Cross(d, e);
            if (denom == 0)
            {
                continue;
            }
            const double t = Cross(a - p1, e) / denom;
            const double u = Cross(a - p1, d) / denom;
            if (t >= 0 && t <= 1 && u >= 0 && u <= 1)
            {
                first = std::min(first, t);
            }
        }
        REQUIRE(hit.hit.hit == (first <= 1));
        if (first <= 1)
        {
            ++hits;
            CHECK(hit.hit.fraction == Approx(first).margin(1e-9));
            REQUIRE(hit.piece >= 0);
            CHECK(!concave.parts[hit.piece].internal[hit.hit.edge]);
        }
    }
    CHECK(hits > 300);
}

TEST_CASE("Speculative contacts of a concave shape: the nearest surface, across seams, within the margin",
          "[concave]")
{
    const Concave floor = TileFloor(4);
    const Shape box = Box(0.5, 0.25);
    for (const double x : {0.5, 1.0, 1.3, 2.0})
    {
        for (const double gap : {0.01, 0.1, 0.3})
        {
            // The box hovers `gap` above the floor's top (y = 0); its bottom runs from x - 0.5 to x + 0.5, across
            // the seam at the integer between when x is not a half.
            const Transform xf = MakeTransform(Vec2{x, 0.25 + gap}, 0.0);
            INFO("x " << x << ", gap " << gap);
            const ConcaveManifold near = CollideWithin(floor, Transform{}, box, xf, 0.2);
            if (gap > 0.2)
            {
                CHECK(near.manifold.contactCount == 0);
                CHECK(near.manifold.gap > 0.2 - 1e-12);
                continue;
            }
            REQUIRE(near.manifold.contactCount == 2);
            CHECK(!near.manifold.overlap);
            CHECK(near.manifold.normal.x == Approx(0.0).margin(1e-12));
            CHECK(near.manifold.normal.y == Approx(1.0));
            CHECK(near.manifold.gap == Approx(gap));
            // The two points are the box's bottom corners, whichever tiles they lie over.
            const double xs[2] = {near.manifold.contacts[0].point.x, near.manifold.contacts[1].point.x};
            CHECK(std::min(xs[0], xs[1]) == Approx(x - 0.5));
            CHECK(std::max(xs[0], xs[1]) == Approx(x + 0.5));
            for (const ContactPoint& c : near.manifold.contacts)
            {
                CHECK(c.separation == Approx(gap));
            }
            // Swapped, the normal turns round.
            const ConcaveManifold swapped = CollideWithin(box, xf, floor, Transform{}, 0.2);
            REQUIRE(swapped.manifold.contactCount == 2);
            CHECK(swapped.manifold.normal.y == Approx(-1.0));
        }
    }
    // Overlapping, it is the merged manifold of Collide.
    const Transform sunk = MakeTransform(Vec2{1.0, 0.2}, 0.0);
    const ConcaveManifold deep = CollideWithin(floor, Transform{}, box, sunk, 0.2);
    const ConcaveManifold merged = Collide(floor, Transform{}, box, sunk);
    CHECK(deep.manifold.overlap);
    CHECK(deep.manifold.depth == merged.manifold.depth);
    CHECK(deep.manifold.contactCount == merged.manifold.contactCount);
}

TEST_CASE("The broadphase over pieces boxes each piece as placed, by its own corners, however the body is turned",
          "[concave]")
{
    // An L turned by 45 degrees: each piece's box in the body frame, turned and boxed again, grows well past the
    // piece (the upright piece's box reaches 0.7 beyond its corners). A pair is tested only when the boxes of the
    // pieces as placed overlap: worked out here from each piece's corners, transformed one by one.
    const Concave l = ConcaveOf({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}});
    REQUIRE(l.parts.size() == 2);
    const Transform xf = MakeTransform(Vec2{0.0, 0.0}, 0.7853981633974483);
    int probes = 0;
    int looser = 0;
    for (double x = -3.0; x <= 3.0; x += 0.05)
    {
        for (double y = -0.5; y <= 4.0; y += 0.05)
        {
            const Shape probe = MakeShape(
                MakePolygon(std::vector<Vec2>{{-0.01, -0.01}, {0.01, -0.01}, {0.01, 0.01}, {-0.01, 0.01}}).polygon);
            const Transform at = MakeTransform(Vec2{x, y}, 0.0);
            int overlapping = 0;
            bool inLooseBox = false;
            for (const ConcavePart& part : l.parts)
            {
                Vec2 low{INFINITY, INFINITY};
                Vec2 high{-INFINITY, -INFINITY};
                for (const Vec2& v : Placed({part.shape.polygon.Vertices().begin(), part.shape.polygon.Vertices().end()},
                                            xf))
                {
                    low = {std::min(low.x, v.x), std::min(low.y, v.y)};
                    high = {std::max(high.x, v.x), std::max(high.y, v.y)};
                }
                overlapping += x - 0.01 <= high.x && x + 0.01 >= low.x && y - 0.01 <= high.y && y + 0.01 >= low.y;
                Vec2 loose{INFINITY, INFINITY};
                Vec2 looseHigh{-INFINITY, -INFINITY};
                for (const Vec2& c : Placed({part.bounds.min, {part.bounds.max.x, part.bounds.min.y}, part.bounds.max,
                                             {part.bounds.min.x, part.bounds.max.y}},
                                            xf))
                {
                    loose = {std::min(loose.x, c.x), std::min(loose.y, c.y)};
                    looseHigh = {std::max(looseHigh.x, c.x), std::max(looseHigh.y, c.y)};
                }
                inLooseBox = inLooseBox || (x > loose.x && x < looseHigh.x && y > loose.y && y < looseHigh.y);
            }
            const ConcaveManifold m = Collide(l, xf, probe, at);
            INFO("probe at " << x << ", " << y);
            CHECK(m.pairsTested == overlapping);
            ++probes;
            looser += inLooseBox && overlapping == 0 ? 1 : 0;
        }
    }
    CHECK(probes > 5000);
    // Many probes lie in a piece's box turned with the body but in no piece's own box: they test no pair.
    CHECK(looser > 100);
}
