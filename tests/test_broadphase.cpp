// SPDX-License-Identifier: MIT
// The broadphase against independent computations: FindPairs against every pair of boxes compared, with touching,
// identical and empty boxes, as the boxes move and with pairs skipped; a world's pairs against every pair of its
// grown boxes, step after step; ComputeAabb against the placed shape's extremes; TouchingPairs against Overlap over
// every pair.

#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/world_scenes.h"

#include <satviz/broadphase.h>
#include <satviz/collide.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// Random boxes with corners on a coarse grid, so that many boxes touch exactly; some repeat an earlier box, some
/// have zero width or height or both (a point).
std::vector<Aabb> RandomBoxes(Rng& rng, int n, double extent)
{
    std::vector<Aabb> boxes;
    boxes.reserve(static_cast<size_t>(n));
    const int cells = static_cast<int>(extent * 4.0);
    for (int i = 0; i < n; ++i)
    {
        if (!boxes.empty() && rng.Chance(0.05))
        {
            boxes.push_back(boxes[static_cast<size_t>(rng.Int(0, static_cast<int>(boxes.size()) - 1))]);
            continue;
        }
        Aabb box;
        box.min = {0.25 * rng.Int(-cells, cells), 0.25 * rng.Int(-cells, cells)};
        Vec2 size{0.25 * rng.Int(0, 8), 0.25 * rng.Int(0, 8)};
        if (rng.Chance(0.2))
        {
            size = {rng.Uniform(0.0, 2.0), rng.Uniform(0.0, 2.0)}; // off the grid
        }
        if (rng.Chance(0.05))
        {
            size = {0.0, 0.0}; // a point
        }
        box.max = box.min + size;
        boxes.push_back(box);
    }
    return boxes;
}

bool BoxesOverlap(const Aabb& a, const Aabb& b)
{
    return !(a.max.x < b.min.x || b.max.x < a.min.x || a.max.y < b.min.y || b.max.y < a.min.y);
}

/// Every pair compared, the skipped ones dropped.
std::vector<std::pair<int, int>> AllPairs(const std::vector<Aabb>& boxes, const std::vector<char>* frozen)
{
    std::vector<std::pair<int, int>> pairs;
    const int n = static_cast<int>(boxes.size());
    for (int i = 0; i < n; ++i)
    {
        for (int j = i + 1; j < n; ++j)
        {
            if (frozen != nullptr && (*frozen)[static_cast<size_t>(i)] && (*frozen)[static_cast<size_t>(j)])
            {
                continue;
            }
            if (BoxesOverlap(boxes[static_cast<size_t>(i)], boxes[static_cast<size_t>(j)]))
            {
                pairs.emplace_back(i, j);
            }
        }
    }
    return pairs;
}

/// Skips the pairs of two frozen boxes (as a world skips two static bodies).
bool SkipFrozen(const void* context, int i, int j)
{
    const auto& frozen = *static_cast<const std::vector<char>*>(context);
    return frozen[static_cast<size_t>(i)] && frozen[static_cast<size_t>(j)];
}

/// The order is a permutation of the boxes sorted by their lower bound on x or on y.
bool SortedOnAnAxis(const std::vector<int>& order, const std::vector<Aabb>& boxes)
{
    if (order.size() != boxes.size())
    {
        return false;
    }
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < sorted.size(); ++i)
    {
        if (sorted[i] != static_cast<int>(i))
        {
            return false;
        }
    }
    bool byX = true, byY = true;
    for (size_t i = 1; i < order.size(); ++i)
    {
        const Aabb& p = boxes[static_cast<size_t>(order[i - 1])];
        const Aabb& q = boxes[static_cast<size_t>(order[i])];
        byX = byX && p.min.x <= q.min.x;
        byY = byY && p.min.y <= q.min.y;
    }
    return byX || byY;
}

} // namespace

TEST_CASE("FindPairs finds the same pairs as comparing every box with every other", "[world][broadphase]")
{
    Rng rng(405);
    std::vector<std::pair<int, int>> pairs, brute;
    for (int set = 0; set < 3000; ++set)
    {
        const int n = set < 10 ? set : (rng.Chance(0.02) ? rng.Int(200, 600) : rng.Int(2, 60));
        // Tall, wide and square spreads, so that both sweep axes are taken.
        const std::vector<Aabb> boxes = RandomBoxes(rng, n, rng.Uniform(1.0, 12.0));
        std::vector<Aabb> stretched = boxes;
        const int shape = set % 3;
        for (Aabb& b : stretched)
        {
            if (shape == 1)
            {
                b.min.x *= 6.0;
                b.max.x *= 6.0;
            }
            else if (shape == 2)
            {
                b.min.y *= 6.0;
                b.max.y *= 6.0;
            }
        }
        const std::vector<std::pair<int, int>> expected = AllPairs(stretched, nullptr);
        SortAndSweep sweep;
        FindPairs(sweep, stretched, pairs);
        FindPairsBruteForce(stretched, brute);
        INFO("set " << set << ", " << n << " boxes");
        REQUIRE(pairs == expected);
        REQUIRE(brute == expected);
        REQUIRE(SortedOnAnAxis(sweep.order, stretched));
    }
}

TEST_CASE("FindPairs with touching, identical and zero-size boxes", "[world][broadphase]")
{
    // A row of unit boxes that touch at their sides, each with a copy of itself, and points on their corners.
    std::vector<Aabb> boxes;
    for (int i = 0; i < 10; ++i)
    {
        const Aabb box{{double(i), 0.0}, {double(i + 1), 1.0}};
        boxes.push_back(box);
        boxes.push_back(box);
        boxes.push_back({box.max, box.max});
    }
    boxes.push_back({{3.0, 1.0}, {3.0, 1.0}});   // a second point on a corner
    boxes.push_back({{-5.0, 1.0}, {20.0, 1.0}}); // a segment along the row's top
    std::vector<std::pair<int, int>> pairs, brute;
    SortAndSweep sweep;
    FindPairs(sweep, boxes, pairs);
    FindPairsBruteForce(boxes, brute);
    const std::vector<std::pair<int, int>> expected = AllPairs(boxes, nullptr);
    CHECK(pairs == expected);
    CHECK(brute == expected);
    // Box 0 touches its copy, its corner point, box 1 (sides touch) and its copy, and the segment.
    CHECK(std::count(expected.begin(), expected.end(), std::make_pair(0, 1)) == 1);
    CHECK(std::count(expected.begin(), expected.end(), std::make_pair(0, 3)) == 1);
    CHECK(std::count(expected.begin(), expected.end(), std::make_pair(0, 31)) == 1);
}

TEST_CASE("FindPairs keeps its order between calls as the boxes move", "[world][broadphase]")
{
    Rng rng(406);
    std::vector<std::pair<int, int>> pairs, brute;
    for (int world = 0; world < 20; ++world)
    {
        const int n = rng.Int(50, 300);
        std::vector<Aabb> boxes = RandomBoxes(rng, n, 10.0);
        std::vector<Vec2> drift(boxes.size());
        for (Vec2& d : drift)
        {
            d = {rng.Uniform(-0.1, 0.1), rng.Uniform(-0.1, 0.1)};
        }
        SortAndSweep sweep;
        std::vector<char> frozen(boxes.size());
        for (char& f : frozen)
        {
            f = rng.Chance(0.4);
        }
        for (int frame = 0; frame < 40; ++frame)
        {
            const bool skip = frame % 2 == 1;
            if (skip)
            {
                FindPairs(sweep, boxes, pairs, SkipFrozen, &frozen);
                FindPairsBruteForce(boxes, brute, SkipFrozen, &frozen);
            }
            else
            {
                FindPairs(sweep, boxes, pairs);
                FindPairsBruteForce(boxes, brute);
            }
            const std::vector<std::pair<int, int>> expected = AllPairs(boxes, skip ? &frozen : nullptr);
            INFO("world " << world << ", frame " << frame);
            REQUIRE(pairs == expected);
            REQUIRE(brute == expected);
            REQUIRE(SortedOnAnAxis(sweep.order, boxes));
            // The unfrozen boxes move a little; now and then one jumps across the world.
            for (size_t i = 0; i < boxes.size(); ++i)
            {
                if (frozen[i])
                {
                    continue;
                }
                Vec2 d = drift[i];
                if (rng.Chance(0.01))
                {
                    d = {rng.Uniform(-10.0, 10.0), rng.Uniform(-10.0, 10.0)};
                }
                boxes[i].min = boxes[i].min + d;
                boxes[i].max = boxes[i].max + d;
            }
        }
    }
}

namespace
{

// The world's skip, from the bodies as the step began: both static, or neither awake and dynamic.
struct StartOfStep
{
    std::vector<char> isStatic, moving;
};

bool SkipAtStart(const void* context, int i, int j)
{
    const StartOfStep& start = *static_cast<const StartOfStep*>(context);
    const size_t a = static_cast<size_t>(i), b = static_cast<size_t>(j);
    if (start.isStatic[a] && start.isStatic[b])
    {
        return true;
    }
    return !start.moving[a] && !start.moving[b];
}

} // namespace

TEST_CASE("A world's broadphase pairs are every pair of its grown boxes, step after step", "[world][broadphase]")
{
    Rng rng(4142);
    for (int run = 0; run < 4; ++run)
    {
        World world = WorldWithGravity(kGravity);
        // Bodies fall asleep sooner than by default, so that every run has sleepers to wake, with either step.
        world.settings.sleepLinearSpeed = 0.05;
        world.settings.sleepAngularSpeed = 0.1;
        world.settings.timeToSleep = 0.25;
        AddGround(world, 12.0);
        AddStatic(world, BoxShape(0.25, 4.0), {-12.0, 4.0});
        AddStatic(world, BoxShape(0.25, 4.0), {12.0, 4.0});
        StepTrace trace;
        world.stepTrace = &trace;
        std::vector<std::pair<int, int>> expected;
        const auto addBody = [&](bool fast) {
            const double size = rng.Uniform(0.1, 0.4);
            const Shape shape = rng.Chance(0.5) ? DiscShape(size) : BoxShape(size, rng.Uniform(0.1, 0.4));
            const Vec2 at{rng.Uniform(-11.0, 11.0), rng.Uniform(0.5, 16.0)};
            const Vec2 velocity = fast ? Vec2{rng.Uniform(-80.0, 80.0), rng.Uniform(-120.0, 0.0)}
                                       : Vec2{rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)};
            AddDynamic(world, shape, at, rng.Uniform(-1.0, 1.0), velocity, rng.Uniform(-2.0, 2.0));
        };
        // More bodies than the sweep takes before it cuts the world into bands.
        for (int i = 0; i < 270; ++i)
        {
            addBody(rng.Chance(0.1));
        }
        int sleptOnce = 0;
        for (int step = 0; step < 450; ++step)
        {
            StartOfStep start;
            for (const RigidBody& body : world.bodies)
            {
                start.isStatic.push_back(body.type == BodyType::Static);
                start.moving.push_back(body.type == BodyType::Dynamic && body.awake);
            }
            // The broadphase off for a few steps now and then: the bodies move meanwhile, unseen by it.
            world.settings.broadphase = step % 50 < 40 || step % 50 >= 43;
            Step(world, kDt);
            if (world.settings.broadphase)
            {
                FindPairsBruteForce(trace.bounds, expected, SkipAtStart, &start);
                INFO("run " << run << ", step " << step << ", bodies " << world.bodies.size());
                REQUIRE(trace.candidates == expected);
            }
            for (const RigidBody& body : world.bodies)
            {
                sleptOnce += body.type == BodyType::Dynamic && !body.awake;
            }
            // Bodies dropped in now and then, fast ones among them, after the pile has had time to go to sleep;
            // a body thrown across the world.
            const bool calm = step < 250 || (step >= 320 && step < 400);
            if (!calm && rng.Chance(0.05))
            {
                addBody(rng.Chance(0.5));
            }
            if (!calm && rng.Chance(0.02))
            {
                const int thrown = rng.Int(3, static_cast<int>(world.bodies.size()) - 1);
                RigidBody& body = world.bodies[static_cast<size_t>(thrown)];
                body.position = {rng.Uniform(-11.0, 11.0), rng.Uniform(1.0, 12.0)};
                body.awake = true;
                body.sleepTime = 0.0;
            }
        }
        CHECK(sleptOnce > 0);
    }
}

TEST_CASE("FindPairs in a wide pile finds each pair once and compares a box with the rows near it",
          "[world][broadphase]")
{
    // A pile twice as wide as it is tall, swept across: rows of boxes that touch, overlap and stand on band-sized
    // steps (corners on a 0.25 grid), a few tall boxes over several rows, and a ground and two walls that span it.
    Rng rng(410);
    std::vector<Aabb> boxes;
    const int rows = 30, columns = 60;
    for (int r = 0; r < rows; ++r)
    {
        for (int c = 0; c < columns; ++c)
        {
            const Vec2 low{c + 0.25 * rng.Int(-1, 1), r + 0.25 * rng.Int(-1, 1)};
            Vec2 size{0.25 * rng.Int(2, 6), 0.25 * rng.Int(2, 6)};
            if (rng.Chance(0.3))
            {
                size = {rng.Uniform(0.5, 1.5), rng.Uniform(0.5, 1.5)}; // off the grid
            }
            if (rng.Chance(0.01))
            {
                size.y = rng.Uniform(3.0, 8.0); // over several rows
            }
            boxes.push_back({low, low + size});
        }
    }
    boxes.push_back({{-1.0, -1.0}, {columns + 1.0, 0.0}});
    boxes.push_back({{-1.0, -1.0}, {0.0, rows + 1.0}});
    boxes.push_back({{double(columns), -1.0}, {columns + 1.0, rows + 1.0}});
    std::vector<std::pair<int, int>> pairs;
    SortAndSweep sweep;
    FindPairs(sweep, boxes, pairs);
    CHECK(pairs == AllPairs(boxes, nullptr));
    // The comparisons of a sweep over whole columns: each box with every box whose lower bound on the sweep axis
    // lies within its extent there (ties by index, as the sweep orders them).
    int64_t columnComparisons = 0;
    for (size_t i = 0; i < boxes.size(); ++i)
    {
        for (size_t j = 0; j < boxes.size(); ++j)
        {
            const double li = boxes[i].min.x, lj = boxes[j].min.x;
            columnComparisons += (lj > li || (lj == li && j > i)) && lj <= boxes[i].max.x;
        }
    }
    CHECK(sweep.axis == 0);
    CHECK(sweep.comparisons * 4 < columnComparisons);
}

TEST_CASE("FindPairs with a skip callback drops exactly the skipped pairs", "[world][broadphase]")
{
    Rng rng(407);
    std::vector<std::pair<int, int>> pairs, brute;
    for (int set = 0; set < 1000; ++set)
    {
        const std::vector<Aabb> boxes = RandomBoxes(rng, rng.Int(2, 80), 4.0);
        std::vector<char> frozen(boxes.size());
        const double p = rng.Uniform(0.0, 1.0);
        for (char& f : frozen)
        {
            f = rng.Chance(p);
        }
        SortAndSweep sweep;
        FindPairs(sweep, boxes, pairs, SkipFrozen, &frozen);
        FindPairsBruteForce(boxes, brute, SkipFrozen, &frozen);
        const std::vector<std::pair<int, int>> expected = AllPairs(boxes, &frozen);
        INFO("set " << set);
        REQUIRE(pairs == expected);
        REQUIRE(brute == expected);
    }
}

TEST_CASE("ComputeAabb is the tight box of the placed shape", "[world][broadphase]")
{
    Rng rng(408);
    for (int k = 0; k < 2000; ++k)
    {
        const Shape shape = RandomShape(rng, 0.3);
        const Vec2 position{rng.Uniform(-50.0, 50.0), rng.Uniform(-50.0, 50.0)};
        const Transform xf = MakeTransform(position, rng.Uniform(-kPi, kPi));
        Aabb expected;
        if (shape.type == ShapeType::Circle)
        {
            const Vec2 c = TransformPoint(xf, shape.circle.center);
            const Vec2 r{shape.circle.radius, shape.circle.radius};
            expected = {c - r, c + r};
        }
        else
        {
            expected.min = {1e300, 1e300};
            expected.max = {-1e300, -1e300};
            for (const Vec2& v : shape.polygon.Vertices())
            {
                const Vec2 w = TransformPoint(xf, v);
                expected.min = {std::min(expected.min.x, w.x), std::min(expected.min.y, w.y)};
                expected.max = {std::max(expected.max.x, w.x), std::max(expected.max.y, w.y)};
            }
        }
        const Aabb box = ComputeAabb(shape, xf);
        const double tol = 1e-13 * 100.0;
        INFO("shape " << k);
        REQUIRE(std::abs(box.min.x - expected.min.x) <= tol);
        REQUIRE(std::abs(box.min.y - expected.min.y) <= tol);
        REQUIRE(std::abs(box.max.x - expected.max.x) <= tol);
        REQUIRE(std::abs(box.max.y - expected.max.y) <= tol);
    }
}

TEST_CASE("TouchingPairs equals Overlap over every pair", "[world][broadphase]")
{
    Rng rng(409);
    int touching = 0;
    for (int scene = 0; scene < 150; ++scene)
    {
        const int n = rng.Int(2, 30);
        const double spread = rng.Uniform(2.0, 8.0);
        std::vector<Shape> shapes;
        std::vector<Transform> xfs;
        for (int i = 0; i < n; ++i)
        {
            if (i > 0 && rng.Chance(0.05))
            {
                // An identical copy of the previous body.
                shapes.push_back(shapes.back());
                xfs.push_back(xfs.back());
                continue;
            }
            shapes.push_back(RandomShape(rng, 0.3));
            const Vec2 position{rng.Uniform(-spread, spread), rng.Uniform(-spread, spread)};
            xfs.push_back(MakeTransform(position, rng.Uniform(-kPi, kPi)));
        }
        if (scene % 5 == 0)
        {
            // Two boxes sharing a side exactly: touching counts.
            shapes.push_back(BoxShape(0.5, 0.5));
            xfs.push_back(At(20.0, 20.0));
            shapes.push_back(BoxShape(0.5, 0.5));
            xfs.push_back(At(21.0, 20.0));
        }
        std::vector<std::pair<int, int>> expected;
        for (size_t i = 0; i < shapes.size(); ++i)
        {
            for (size_t j = i + 1; j < shapes.size(); ++j)
            {
                if (Overlap(shapes[i], xfs[i], shapes[j], xfs[j]))
                {
                    expected.emplace_back(static_cast<int>(i), static_cast<int>(j));
                }
            }
        }
        touching += static_cast<int>(expected.size());
        INFO("scene " << scene);
        REQUIRE(TouchingPairs(shapes, xfs) == expected);
    }
    CHECK(touching > 500); // the scenes are dense enough to say something
}
