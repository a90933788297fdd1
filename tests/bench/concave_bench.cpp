// SPDX-License-Identifier: MIT
// satviz-bench --concave: decomposition and concave pair queries.
//
// Method. Outlines: random star-shaped polygons (tests/support/random_concave.h, radii from 0.3 to 1 of the
// largest), about half of whose vertices are reflex. Per vertex count, `outlines` of them, the same for both
// methods. A round decomposes every outline once per method, repeated until the round has taken at least 20 ms;
// the figure is the median over the rounds of the time per decomposition. The growth exponent between two counts is
// the slope of log time against log n.
// Pairs: two star outlines of n vertices each cut by Fast, B placed around A at a random distance (from half to
// twice A's radius) and angle, so that some pairs overlap and some are apart. Each round times Collide on the
// concave pair (a broadphase on the pieces' boxes, then the pairs whose boxes overlap, merged by its rule) and the
// same pieces collided all against all with the convex Collide, every pair of pieces, the deepest kept: what a
// concave body costs without the broadphase over its pieces.

#include "concave_bench.h"

#include "support/random_concave.h"

#include <satviz/concave.h>
#include <satviz/decompose.h>
#include <satviz/sat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace satviz::bench
{
namespace
{

using Clock = std::chrono::steady_clock;
using testing::kPi;
using testing::Rng;

// Below this, a decomposition happens within one frame of an app at 60 frames a second: it can follow a dragged
// vertex.
constexpr double kInteractiveMs = 1000.0 / 60.0;

double MedianOf(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

double Ms(Clock::duration d)
{
    return std::chrono::duration<double, std::milli>(d).count();
}

// Keeps a result alive, so that the timed calls are not optimised away.
volatile double g_sink = 0.0;

struct DecomposeRow
{
    int n = 0;
    double ms = 0.0;       // median time per decomposition
    double pieces = 0.0;   // mean piece count over the outlines
    int minPieces = 0;     // least piece count over the outlines
    int maxPieces = 0;     // most
    double reflex = 0.0;   // mean reflex vertices (a lower bound of the pieces is reflex / 2 + 1)
    double exponent = 0.0; // slope of log ms against log n from the row before; 0 for the first
};

// Reflex vertices of a counter-clockwise outline.
int ReflexCount(const std::vector<Vec2>& p)
{
    int count = 0;
    const size_t n = p.size();
    for (size_t i = 0; i < n; ++i)
    {
        if (testing::TurnSign(p[(i + n - 1) % n], p[i], p[(i + 1) % n]) < 0)
        {
            ++count;
        }
    }
    return count;
}

DecomposeRow TimeDecompose(const ConcaveBenchSettings& s, int n, DecomposeMethod method)
{
    Rng rng(s.seed + static_cast<uint64_t>(n));
    std::vector<std::vector<Vec2>> outlines;
    for (int i = 0; i < s.outlines; ++i)
    {
        outlines.push_back(testing::RandomStarPolygon(rng, n, 1.0, 0.3));
    }
    DecomposeRow row;
    row.n = n;
    row.minPieces = 1 << 30;
    for (const std::vector<Vec2>& outline : outlines)
    {
        const Decomposition d = Decompose(outline, method);
        const int pieces = static_cast<int>(d.pieces.size());
        row.pieces += pieces;
        row.minPieces = std::min(row.minPieces, pieces);
        row.maxPieces = std::max(row.maxPieces, pieces);
        row.reflex += ReflexCount(outline);
    }
    row.pieces /= s.outlines;
    row.reflex /= s.outlines;
    std::vector<double> perCall;
    for (int round = 0; round < s.rounds; ++round)
    {
        int calls = 0;
        const Clock::time_point start = Clock::now();
        do
        {
            for (const std::vector<Vec2>& outline : outlines)
            {
                g_sink = g_sink + static_cast<double>(Decompose(outline, method).pieces.size());
                ++calls;
            }
        } while (Ms(Clock::now() - start) < 20.0);
        perCall.push_back(Ms(Clock::now() - start) / calls);
    }
    row.ms = MedianOf(perCall);
    return row;
}

void PrintDecompose(const char* name, std::vector<DecomposeRow>& rows)
{
    std::printf("%s\n", name);
    std::printf("%8s %12s %10s %12s %10s %10s\n", "n", "ms", "exponent", "pieces", "min-max", "reflex");
    for (size_t i = 0; i < rows.size(); ++i)
    {
        DecomposeRow& r = rows[i];
        char exponent[32] = "-";
        if (i > 0 && rows[i - 1].ms > 0.0)
        {
            r.exponent = std::log(r.ms / rows[i - 1].ms) / std::log(static_cast<double>(r.n) / rows[i - 1].n);
            std::snprintf(exponent, sizeof exponent, "%.2f", r.exponent);
        }
        char range[32];
        std::snprintf(range, sizeof range, "%d-%d", r.minPieces, r.maxPieces);
        std::printf("%8d %12.4f %10s %12.1f %10s %10.1f\n", r.n, r.ms, exponent, r.pieces, range, r.reflex);
    }
    int last = 0;
    for (const DecomposeRow& r : rows)
    {
        if (r.ms <= kInteractiveMs)
        {
            last = r.n;
        }
    }
    if (last > 0)
    {
        std::printf("interactive (at most %.1f ms, one frame at 60 Hz) up to n = %d of these counts\n\n",
                    kInteractiveMs, last);
    }
    else
    {
        std::printf("no count here decomposes within %.1f ms (one frame at 60 Hz)\n\n", kInteractiveMs);
    }
}

struct PairCase
{
    Concave a;
    Concave b;
    Transform xfA;
    Transform xfB;
};

// The deepest manifold of every pair of pieces, without a broadphase: the naive way to collide compounds.
double AllAgainstAll(const PairCase& c)
{
    double deepest = -1.0;
    for (const ConcavePart& pa : c.a.parts)
    {
        for (const ConcavePart& pb : c.b.parts)
        {
            const Manifold m = Collide(pa.shape, c.xfA, pb.shape, c.xfB);
            if (m.overlap)
            {
                deepest = std::max(deepest, m.depth);
            }
        }
    }
    return deepest;
}

void TimePairs(const ConcaveBenchSettings& s)
{
    std::printf("concave pairs: two star outlines of n vertices each, cut by Fast; us per query, median of %d "
                "rounds over %d pairs\n",
                s.rounds, s.pairs);
    std::printf("%8s %8s %9s %9s %10s %12s %14s %8s\n", "n", "pieces", "all pairs", "boxes hit", "overlap %",
                "Collide us", "all-vs-all us", "ratio");
    for (const int n : s.pairVertices)
    {
        Rng rng(s.seed * 3 + static_cast<uint64_t>(n));
        std::vector<PairCase> cases;
        double pieces = 0.0;
        double allPairs = 0.0;
        double tested = 0.0;
        int overlapping = 0;
        for (int i = 0; i < s.pairs; ++i)
        {
            PairCase c;
            c.a = MakeConcave(Decompose(testing::RandomStarPolygon(rng, n, 1.0, 0.3), DecomposeMethod::Fast).pieces);
            c.b = MakeConcave(Decompose(testing::RandomStarPolygon(rng, n, 1.0, 0.3), DecomposeMethod::Fast).pieces);
            const double distance = rng.Uniform(0.5, 2.0);
            const double angle = rng.Uniform(0.0, 2.0 * kPi);
            c.xfA = MakeTransform(Vec2{0.0, 0.0}, rng.Uniform(0.0, 2.0 * kPi));
            c.xfB = MakeTransform(Vec2{distance * std::cos(angle), distance * std::sin(angle)},
                                  rng.Uniform(0.0, 2.0 * kPi));
            const ConcaveManifold m = Collide(c.a, c.xfA, c.b, c.xfB);
            pieces += 0.5 * static_cast<double>(c.a.parts.size() + c.b.parts.size());
            allPairs += static_cast<double>(c.a.parts.size() * c.b.parts.size());
            tested += m.pairsTested;
            overlapping += m.manifold.overlap ? 1 : 0;
            cases.push_back(std::move(c));
        }
        std::vector<double> concaveUs;
        std::vector<double> naiveUs;
        for (int round = 0; round < s.rounds; ++round)
        {
            Clock::time_point start = Clock::now();
            int calls = 0;
            do
            {
                for (const PairCase& c : cases)
                {
                    g_sink = g_sink + Collide(c.a, c.xfA, c.b, c.xfB).manifold.depth;
                    ++calls;
                }
            } while (Ms(Clock::now() - start) < 20.0);
            concaveUs.push_back(1e3 * Ms(Clock::now() - start) / calls);
            start = Clock::now();
            calls = 0;
            do
            {
                for (const PairCase& c : cases)
                {
                    g_sink = g_sink + AllAgainstAll(c);
                    ++calls;
                }
            } while (Ms(Clock::now() - start) < 20.0);
            naiveUs.push_back(1e3 * Ms(Clock::now() - start) / calls);
        }
        const double concave = MedianOf(concaveUs);
        const double naive = MedianOf(naiveUs);
        std::printf("%8d %8.1f %9.1f %9.1f %10.1f %12.3f %14.3f %8.2f\n", n, pieces / s.pairs, allPairs / s.pairs,
                    tested / s.pairs, 100.0 * overlapping / s.pairs, concave, naive, naive / concave);
        std::fflush(stdout);
    }
    std::printf("(pieces: per outline; all pairs: piece pairs the all-against-all loop collides; boxes hit: those "
                "whose boxes overlap, which the concave Collide collides; ratio: all-vs-all over Collide)\n");
}

} // namespace

std::string CheckConcaveBenchSettings(const ConcaveBenchSettings& s)
{
    for (const int n : s.fastVertices)
    {
        if (n < 3)
        {
            return "--concave: vertex counts must be at least 3";
        }
    }
    for (const int n : s.fewestVertices)
    {
        if (n < 3 || n > kFewestMaxVertices)
        {
            return "--concave: Fewest's vertex counts must be from 3 to " + std::to_string(kFewestMaxVertices);
        }
    }
    if (s.rounds < 1 || s.outlines < 1 || s.pairs < 1)
    {
        return "--rounds: at least 1";
    }
    return "";
}

ConcaveBenchSettings QuickConcaveBenchSettings(ConcaveBenchSettings s)
{
    s.fastVertices = {10, 50};
    s.fewestVertices = {10, 20};
    s.pairVertices = {10, 30};
    s.outlines = 2;
    s.pairs = 10;
    s.rounds = 1;
    s.quick = true;
    return s;
}

void RunConcaveBench(const ConcaveBenchSettings& s)
{
    std::printf("satviz-bench --concave: decomposition of random star outlines (radii 0.3 to 1), %d outlines per "
                "count, ms per decomposition (median of %d rounds); exponent: slope of log ms against log n from "
                "the row above; pieces: mean over the outlines\n\n",
                s.outlines, s.rounds);
    std::vector<DecomposeRow> fast;
    for (const int n : s.fastVertices)
    {
        std::fprintf(stderr, "satviz-bench: Fast, n = %d\n", n);
        fast.push_back(TimeDecompose(s, n, DecomposeMethod::Fast));
    }
    PrintDecompose("Fast (ear clipping, then Hertel-Mehlhorn)", fast);
    std::vector<DecomposeRow> fewest;
    for (const int n : s.fewestVertices)
    {
        std::fprintf(stderr, "satviz-bench: Fewest, n = %d\n", n);
        fewest.push_back(TimeDecompose(s, n, DecomposeMethod::Fewest));
    }
    PrintDecompose("Fewest (the exact programme; above kFewestMaxVertices it gives Fast's result)", fewest);
    std::fflush(stdout);
    TimePairs(s);
}

} // namespace satviz::bench
