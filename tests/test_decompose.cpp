// SPDX-License-Identifier: MIT
// Convex decomposition of simple polygons: properties over random polygons, the hard outlines, bad input.

#include "support/random_concave.h"

#include <satviz/collide.h>
#include <satviz/decompose.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <map>
#include <numeric>

using namespace satviz;
using namespace satviz::testing;

namespace
{

std::vector<Vec2> Corners(const Polygon& polygon)
{
    return {polygon.Vertices().begin(), polygon.Vertices().end()};
}

// The piece scaled about its centroid by 1 - shrink: pieces that only share edges no longer touch.
Polygon Shrunk(const Polygon& polygon, double shrink)
{
    std::vector<Vec2> points;
    const Vec2 c = polygon.Centroid();
    for (const Vec2& v : polygon.Vertices())
    {
        points.push_back(c + (1.0 - shrink) * (v - c));
    }
    return MakePolygon(points).polygon;
}

double DistanceToSegment(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const double t = std::clamp(Dot(p - a, ab) / Dot(ab, ab), 0.0, 1.0);
    return Length(p - (a + t * ab));
}

// Every property a decomposition of `points` must have, checked without the decomposer's own predicates.
void CheckDecomposition(const std::vector<Vec2>& points, const Decomposition& d)
{
    REQUIRE(d.Ok());
    REQUIRE(!d.pieces.empty());
    const int n = static_cast<int>(points.size());
    long double sum = 0;
    double extent = 0;
    for (const Vec2& p : points)
    {
        extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    }
    for (const ConvexPiece& piece : d.pieces)
    {
        const std::vector<Vec2> c = Corners(piece.polygon);
        const int m = static_cast<int>(c.size());
        REQUIRE(piece.source.size() == c.size());
        REQUIRE(piece.internal.size() == c.size());
        // Convex, counter-clockwise.
        for (int k = 0; k < m; ++k)
        {
            REQUIRE(TurnSign(c[k], c[(k + 1) % m], c[(k + 2) % m]) > 0);
        }
        sum += Area2(c);
        for (int k = 0; k < m; ++k)
        {
            // Corners are input vertices, and the source says which.
            REQUIRE(piece.source[k] >= 0);
            REQUIRE(piece.source[k] < n);
            REQUIRE(points[piece.source[k]] == c[k]);
            // A boundary edge joins input vertices that follow each other (either orientation); an internal one
            // is held, reversed, by another piece or at least lies inside the outline.
            const int a = piece.source[k];
            const int b = piece.source[(k + 1) % m];
            const Vec2 mid = 0.5 * (c[k] + c[(k + 1) % m]);
            if (piece.internal[k])
            {
                CHECK(InsideOutline(points, mid));
            }
            else
            {
                bool onOutline = false;
                for (int e = 0; e < n && !onOutline; ++e)
                {
                    onOutline = DistanceToSegment(mid, points[e], points[(e + 1) % n]) <= 1e-12 * extent;
                }
                CHECK(onOutline);
                (void)a;
                (void)b;
            }
        }
    }
    // Areas sum to the outline's.
    const long double area = std::abs(Area2(points));
    REQUIRE(std::abs(static_cast<double>((sum - area) / area)) <= 1e-12);
    // Every input vertex lies on the outline of some piece (a corner, unless it was straight).
    for (const Vec2& p : points)
    {
        bool found = false;
        for (const ConvexPiece& piece : d.pieces)
        {
            const std::vector<Vec2> c = Corners(piece.polygon);
            for (size_t k = 0; k < c.size() && !found; ++k)
            {
                found = DistanceToSegment(p, c[k], c[(k + 1) % c.size()]) <= 1e-12 * extent;
            }
        }
        REQUIRE(found);
    }
    // No two pieces overlap: shrunk a little about their centroids, no pair meets (the library's Overlap).
    std::vector<Polygon> shrunk;
    for (const ConvexPiece& piece : d.pieces)
    {
        shrunk.push_back(Shrunk(piece.polygon, 1e-6));
    }
    for (size_t i = 0; i < shrunk.size(); ++i)
    {
        for (size_t j = i + 1; j < shrunk.size(); ++j)
        {
            REQUIRE(!Overlap(shrunk[i], Transform{}, shrunk[j], Transform{}));
        }
    }
}

// The fewest convex pieces whose corners are vertices, by trying every set of diagonals, smallest first: a set
// works when no two of its diagonals cross and at every vertex the directions of its edges and diagonals leave no
// gap of 180 degrees or more inside the polygon.
int BruteForceFewest(const std::vector<Vec2>& p)
{
    const int n = static_cast<int>(p.size());
    std::vector<std::pair<int, int>> diagonals;
    for (int a = 0; a < n; ++a)
    {
        for (int b = a + 2; b < n; ++b)
        {
            if (a == 0 && b == n - 1)
            {
                continue;
            }
            bool ok = InsideOutline(p, 0.5 * (p[a] + p[b]));
            for (int e = 0; e < n && ok; ++e)
            {
                ok = !ProperlyCross(p[a], p[b], p[e], p[(e + 1) % n]);
            }
            for (int v = 0; v < n && ok; ++v)
            {
                ok = v == a || v == b || DistanceToSegment(p[v], p[a], p[b]) > 1e-12;
            }
            if (ok)
            {
                diagonals.push_back({a, b});
            }
        }
    }
    const int count = static_cast<int>(diagonals.size());
    auto works = [&](const std::vector<int>& set) {
        for (size_t i = 0; i < set.size(); ++i)
        {
            for (size_t j = i + 1; j < set.size(); ++j)
            {
                const auto [a, b] = diagonals[set[i]];
                const auto [c, e] = diagonals[set[j]];
                if (a != c && a != e && b != c && b != e && ProperlyCross(p[a], p[b], p[c], p[e]))
                {
                    return false;
                }
            }
        }
        for (int v = 0; v < n; ++v)
        {
            const Vec2 prev = p[(v + n - 1) % n];
            const Vec2 next = p[(v + 1) % n];
            // Angles measured counter-clockwise from the edge to next; the interior runs up to the edge to prev.
            auto angle = [&](Vec2 q) {
                const Vec2 r = q - p[v];
                const Vec2 e = next - p[v];
                double t = std::atan2(Cross(e, r), Dot(e, r));
                return t < 0 ? t + 2 * kPi : t;
            };
            std::vector<double> rays{0.0, angle(prev)};
            for (int s : set)
            {
                if (diagonals[s].first == v)
                {
                    rays.push_back(angle(p[diagonals[s].second]));
                }
                if (diagonals[s].second == v)
                {
                    rays.push_back(angle(p[diagonals[s].first]));
                }
            }
            std::sort(rays.begin(), rays.end());
            for (size_t k = 0; k + 1 < rays.size(); ++k)
            {
                if (rays[k + 1] - rays[k] >= kPi)
                {
                    return false;
                }
            }
        }
        return true;
    };
    for (int size = 0; size <= count; ++size)
    {
        std::vector<int> set(static_cast<size_t>(size));
        std::iota(set.begin(), set.end(), 0);
        for (;;)
        {
            if (works(set))
            {
                return size + 1;
            }
            int k = size - 1;
            while (k >= 0 && set[k] == count - size + k)
            {
                --k;
            }
            if (k < 0)
            {
                break;
            }
            ++set[k];
            for (int t = k + 1; t < size; ++t)
            {
                set[t] = set[t - 1] + 1;
            }
        }
    }
    return -1;
}

std::vector<Vec2> Reversed(std::vector<Vec2> p)
{
    std::reverse(p.begin(), p.end());
    return p;
}

} // namespace

TEST_CASE("Decompositions of random simple polygons are exact convex partitions", "[decompose]")
{
    Rng rng(42);
    for (int trial = 0; trial < 3000; ++trial)
    {
        const int n = rng.Int(3, 40);
        std::vector<Vec2> points = (trial % 2 == 0) ? RandomStarPolygon(rng, n, rng.LogUniform(-3, 3), 0.1)
                                                    : RandomUntangledPolygon(rng, std::min(n, 25), 10.0);
        if (rng.Chance(0.5))
        {
            points = Reversed(points);
        }
        INFO("trial " << trial);
        const Decomposition fast = Decompose(points, DecomposeMethod::Fast);
        const Decomposition fewest = Decompose(points, DecomposeMethod::Fewest);
        CheckDecomposition(points, fast);
        CheckDecomposition(points, fewest);
        REQUIRE(fewest.pieces.size() <= fast.pieces.size());
    }
}

TEST_CASE("Fewest gives the fewest pieces a brute force over sets of diagonals finds", "[decompose]")
{
    Rng rng(7);
    int fewerThanFast = 0;
    for (int trial = 0; trial < 300; ++trial)
    {
        const int n = rng.Int(4, 9);
        const std::vector<Vec2> points =
            (trial % 2 == 0) ? RandomStarPolygon(rng, n, 1.0, 0.2) : RandomUntangledPolygon(rng, n, 1.0);
        const std::vector<Vec2> ccw = Area2(points) > 0 ? points : Reversed(points);
        INFO("trial " << trial);
        const Decomposition fewest = Decompose(points, DecomposeMethod::Fewest);
        REQUIRE(fewest.Ok());
        REQUIRE(static_cast<int>(fewest.pieces.size()) == BruteForceFewest(ccw));
        fewerThanFast += fewest.pieces.size() < Decompose(points, DecomposeMethod::Fast).pieces.size();
    }
    // The programme earns its cost: on some of these outlines the fast method leaves extra pieces.
    CHECK(fewerThanFast > 0);
}

TEST_CASE("Decomposition of the hard outlines", "[decompose]")
{
    std::map<std::string, std::vector<Vec2>> outlines;
    // A comb: a spine with teeth pointing up.
    {
        std::vector<Vec2> comb{{0, 0}, {20, 0}};
        for (int t = 9; t >= 0; --t)
        {
            comb.push_back({2.0 * t + 1.5, 1});
            comb.push_back({2.0 * t + 1.5, 5});
            comb.push_back({2.0 * t + 0.5, 5});
            comb.push_back({2.0 * t + 0.5, 1});
        }
        comb.push_back({0, 1});
        outlines["comb"] = comb;
    }
    // A star with needle-thin spikes.
    {
        std::vector<Vec2> star;
        for (int k = 0; k < 24; ++k)
        {
            const double a = 2 * kPi * k / 24;
            const double r = k % 2 == 0 ? 1000.0 : 0.01;
            star.push_back({r * std::cos(a), r * std::sin(a)});
        }
        outlines["spikes"] = star;
    }
    // A spiral band, two and a half turns: an inner curve r = 1 + t / 2 out, the outer r = 1.8 + t / 2 back.
    {
        std::vector<Vec2> spiral;
        const int steps = 30;
        for (int k = 0; k <= steps; ++k)
        {
            const double t = 5 * kPi * k / steps;
            spiral.push_back((1.0 + 0.5 * t) * Vec2{std::cos(t), std::sin(t)});
        }
        for (int k = steps; k >= 0; --k)
        {
            const double t = 5 * kPi * k / steps;
            spiral.push_back((1.8 + 0.5 * t) * Vec2{std::cos(t), std::sin(t)});
        }
        outlines["spiral"] = spiral;
    }
    // Near-collinear: a long wavy floor whose bumps are far below its length.
    {
        std::vector<Vec2> floor;
        for (int k = 0; k <= 50; ++k)
        {
            floor.push_back({k * 1.0, (k % 2) * 1e-9});
        }
        floor.push_back({50, -1});
        floor.push_back({0, -1});
        outlines["near-collinear"] = floor;
    }
    // Exactly collinear vertices and repeated ones, clockwise.
    outlines["collinear and repeated"] = {{0, 0}, {0, 2},   {0, 2}, {1, 2},   {2, 2}, {2, 1},
                                          {1, 1}, {1, 0.5}, {1, 0}, {0.5, 0}, {0, 0}};
    // Huge coordinates: an L far from the origin.
    {
        const double f = 1e11;
        const Vec2 o{9e11, -9e11};
        outlines["huge"] = {
            o, o + Vec2{f, 0}, o + Vec2{f, 0.3 * f}, o + Vec2{0.3 * f, 0.3 * f}, o + Vec2{0.3 * f, f}, o + Vec2{0, f}};
    }
    for (const auto& [name, points] : outlines)
    {
        INFO(name);
        const auto start = std::chrono::steady_clock::now();
        const Decomposition fast = Decompose(points, DecomposeMethod::Fast);
        const Decomposition fewest = Decompose(points, DecomposeMethod::Fewest);
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
        CheckDecomposition(points, fast);
        CheckDecomposition(points, fewest);
        CHECK(fewest.pieces.size() <= fast.pieces.size());
    }
    // An L is two pieces.
    CHECK(Decompose(outlines["huge"], DecomposeMethod::Fast).pieces.size() == 2);
}

TEST_CASE("A convex outline is one piece with no internal edge", "[decompose]")
{
    Rng rng(3);
    for (int trial = 0; trial < 50; ++trial)
    {
        const Polygon convex = RandomPolygon(rng, rng.Int(3, 30), 2.0, 0.5);
        for (DecomposeMethod method : {DecomposeMethod::Fast, DecomposeMethod::Fewest})
        {
            const Decomposition d = Decompose(Corners(convex), method);
            REQUIRE(d.pieces.size() == 1);
            for (bool internal : d.pieces[0].internal)
            {
                CHECK(!internal);
            }
        }
    }
}

TEST_CASE("A self-intersecting outline is refused, naming the two edges that cross", "[decompose]")
{
    // A bow tie: edge 1 (1 to 2) crosses edge 3 (3 to 0).
    const std::vector<Vec2> bowTie{{0, 0}, {2, 0}, {0, 2}, {2, 2}};
    const Decomposition d = Decompose(bowTie, DecomposeMethod::Fast);
    REQUIRE(d.error == DecomposeError::SelfIntersecting);
    CHECK(d.edgeA == 1);
    CHECK(d.edgeB == 3);
    CHECK(DescribeDecomposeError(d, bowTie) ==
          "polygon is not simple: edge 1 (vertex 1 to 2) meets edge 3 (vertex 3 to 0)");

    // Random simple polygons with one vertex moved across a far edge: the edges found do meet (an independent
    // test), and the two edges the move created are among the pairs that meet.
    Rng rng(11);
    int refused = 0;
    for (int trial = 0; trial < 500; ++trial)
    {
        std::vector<Vec2> p = RandomStarPolygon(rng, rng.Int(6, 30), 1.0, 0.3);
        const int n = static_cast<int>(p.size());
        const int k = rng.Int(0, n - 1);
        p[k] = -1.5 * p[k];
        const auto start = std::chrono::steady_clock::now();
        const Decomposition bad = Decompose(p, DecomposeMethod::Fewest);
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
        bool crosses = false;
        for (int e = 0; e < n; ++e)
        {
            for (int f = e + 2; f < n; ++f)
            {
                if (!(e == 0 && f == n - 1) && ProperlyCross(p[e], p[e + 1], p[f], p[(f + 1) % n]))
                {
                    crosses = true;
                }
            }
        }
        if (!crosses)
        {
            continue;
        }
        ++refused;
        REQUIRE(bad.error == DecomposeError::SelfIntersecting);
        const int a = bad.edgeA;
        const int b = bad.edgeB;
        REQUIRE(a < b);
        // The first pair in order of the first edge: no pair with a smaller first edge crosses.
        CHECK(ProperlyCross(p[a], p[(a + 1) % n], p[b], p[(b + 1) % n]));
        for (int e = 0; e < a; ++e)
        {
            for (int f = e + 2; f < n; ++f)
            {
                CHECK(!((e != 0 || f != n - 1) && ProperlyCross(p[e], p[e + 1], p[f], p[(f + 1) % n])));
            }
        }
    }
    CHECK(refused > 100);

    // An edge folding back along the one before it, and a vertex touching an edge.
    const std::vector<Vec2> fold{{0, 0}, {2, 0}, {1, 0}, {1, 1}};
    const Decomposition folded = Decompose(fold, DecomposeMethod::Fast);
    CHECK(folded.error == DecomposeError::SelfIntersecting);
    CHECK(folded.edgeA == 0);
    CHECK(folded.edgeB == 1);
    const std::vector<Vec2> touch{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}};
    const Decomposition touching = Decompose(touch, DecomposeMethod::Fast);
    CHECK(touching.error == DecomposeError::SelfIntersecting);
    CHECK(touching.edgeA == 0);
    CHECK(touching.edgeB == 2);
}

TEST_CASE("Decompose refuses degenerate input with a clear error", "[decompose]")
{
    CHECK(Decompose(std::vector<Vec2>{{0, 0}, {1, 0}}, DecomposeMethod::Fast).error == DecomposeError::TooFewVertices);
    CHECK(Decompose(std::vector<Vec2>{{0, 0}, {0, 0}, {1, 1}, {0, 0}}, DecomposeMethod::Fast).error ==
          DecomposeError::TooFewVertices);
    CHECK(Decompose(std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}}, DecomposeMethod::Fast).error ==
          DecomposeError::SelfIntersecting); // folds back from 2 to 0 along 0 to 1
    const std::vector<Vec2> nan{{0, 0}, {1, 0}, {0, std::nan("")}};
    const Decomposition d = Decompose(nan, DecomposeMethod::Fast);
    CHECK(d.error == DecomposeError::NotFinite);
    CHECK(DescribeDecomposeError(d, nan) == "polygon vertex 2 is not a finite number");
    CHECK(Decompose(std::vector<Vec2>{{0, 0}, {2e12, 0}, {0, 1}}, DecomposeMethod::Fast).error ==
          DecomposeError::TooLarge);
}

TEST_CASE("Large outlines decompose in bounded time", "[decompose]")
{
    Rng rng(5);
    const std::vector<Vec2> points = RandomStarPolygon(rng, 2000, 100.0, 0.2);
    const auto start = std::chrono::steady_clock::now();
    const Decomposition fast = Decompose(points, DecomposeMethod::Fast);
    const Decomposition fewest = Decompose(points, DecomposeMethod::Fewest);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
    REQUIRE(fast.Ok());
    CHECK(fewest.pieces.size() == fast.pieces.size()); // beyond kFewestMaxVertices, Fewest is Fast
    long double sum = 0;
    for (const ConvexPiece& piece : fast.pieces)
    {
        sum += Area2(Corners(piece.polygon));
    }
    CHECK(std::abs(static_cast<double>(sum / Area2(points) - 1)) <= 1e-12);
}

TEST_CASE("Vertices on an edge's line are kept in the outline but are corners of no piece", "[decompose][property]")
{
    // Lattice outlines, with points added halfway and a quarter of the way along random edges: exactly on the edge,
    // so the outline is the same region with straight corners. Its decomposition must be the outline's without
    // them (the same pieces: a piece is strictly convex, it has no straight corner), and each added point must lie
    // on an outline edge of a piece.
    Rng rng(20261128);
    int tested = 0;
    for (int trial = 0; trial < 1500; ++trial)
    {
        std::vector<Vec2> lattice;
        for (const Vec2& p : RandomStarPolygon(rng, rng.Int(3, 24), 40.0, 0.2))
        {
            lattice.push_back({std::round(p.x), std::round(p.y)});
        }
        const DecomposeMethod method = trial % 2 == 0 ? DecomposeMethod::Fast : DecomposeMethod::Fewest;
        const Decomposition plain = Decompose(lattice, method);
        if (!plain.Ok())
        {
            continue; // rounding made it cross itself or collapse
        }
        std::vector<Vec2> written;
        std::vector<Vec2> added;
        for (size_t i = 0; i < lattice.size(); ++i)
        {
            const Vec2 a = lattice[i];
            const Vec2 b = lattice[(i + 1) % lattice.size()];
            written.push_back(a);
            if (a != b && rng.Chance(0.4))
            {
                // 4 * integers: the quarter points are exact, and exactly on the edge.
                for (const double t : {0.25, 0.5})
                {
                    if (rng.Chance(0.6))
                    {
                        written.push_back(a + t * (b - a));
                        added.push_back(written.back());
                    }
                }
            }
        }
        if (added.empty())
        {
            continue;
        }
        ++tested;
        INFO("trial " << trial);
        const Decomposition straight = Decompose(written, method);
        CheckDecomposition(written, straight);
        REQUIRE(straight.pieces.size() == plain.pieces.size());
        // The same pieces, corner for corner (the decomposer starts from the same outline either way).
        for (size_t k = 0; k < plain.pieces.size(); ++k)
        {
            CHECK(Corners(straight.pieces[k].polygon) == Corners(plain.pieces[k].polygon));
        }
        for (const Vec2& p : added)
        {
            bool onOutline = false;
            for (const ConvexPiece& piece : straight.pieces)
            {
                const std::vector<Vec2> c = Corners(piece.polygon);
                for (size_t e = 0; e < c.size(); ++e)
                {
                    onOutline = onOutline ||
                                (!piece.internal[e] && DistanceToSegment(p, c[e], c[(e + 1) % c.size()]) < 1e-9);
                }
            }
            CHECK(onOutline);
        }
    }
    CHECK(tested >= 500);
}
