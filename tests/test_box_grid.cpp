// SPDX-License-Identifier: MIT
// The time of impact's grid of reaches (core/src/box_grid.h) against every box compared: the boxes a box meets, in
// ascending order, as boxes grow after the grid was made.

#include "box_grid.h"
#include "support/random_shapes.h"

#include <catch2/catch.hpp>

#include <limits>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

// Every box but `skip` that meets `box`, in ascending order.
std::vector<int> MeetingAll(const std::vector<Aabb>& boxes, const Aabb& box, int skip)
{
    std::vector<int> met;
    for (int o = 0; o < static_cast<int>(boxes.size()); ++o)
    {
        const Aabb& b = boxes[static_cast<size_t>(o)];
        if (o != skip && box.min.x <= b.max.x && b.min.x <= box.max.x && box.min.y <= b.max.y &&
            b.min.y <= box.max.y)
        {
            met.push_back(o);
        }
    }
    return met;
}

// A crowd of small boxes, corners on a 0.25 grid so that many touch exactly, with some long ones (paths over many
// cells) and points.
std::vector<Aabb> Crowd(Rng& rng, int n, double extent)
{
    std::vector<Aabb> boxes;
    for (int i = 0; i < n; ++i)
    {
        const Vec2 low{0.25 * rng.Int(static_cast<int>(-4 * extent), static_cast<int>(4 * extent)),
                       0.25 * rng.Int(static_cast<int>(-4 * extent), static_cast<int>(4 * extent))};
        Vec2 size{0.25 * rng.Int(0, 4), 0.25 * rng.Int(0, 4)};
        if (rng.Chance(0.05))
        {
            size = {rng.Uniform(0.0, extent), rng.Uniform(0.0, extent)};
        }
        boxes.push_back({low, low + size});
    }
    return boxes;
}

} // namespace

TEST_CASE("The grid of reaches finds the boxes a box meets as comparing every box does, as boxes grow",
          "[world][ccd]")
{
    Rng rng(411);
    std::vector<int> met;
    for (int world = 0; world < 60; ++world)
    {
        const int n = rng.Int(1, 400);
        std::vector<Aabb> boxes = Crowd(rng, n, rng.Uniform(1.0, 30.0));
        detail::BoxGrid grid;
        grid.Make(boxes);
        for (int search = 0; search < 200; ++search)
        {
            const int k = rng.Int(0, n - 1);
            if (rng.Chance(0.3))
            {
                // Box k grows, as a reach does after a hit: by a little, or across the world.
                const double grow = rng.Chance(0.2) ? rng.Uniform(0.0, 40.0) : rng.Uniform(0.0, 1.0);
                Aabb& box = boxes[static_cast<size_t>(k)];
                box.min = box.min - Vec2{rng.Uniform(0.0, grow), rng.Uniform(0.0, grow)};
                box.max = box.max + Vec2{rng.Uniform(0.0, grow), rng.Uniform(0.0, grow)};
                grid.Unfile(k);
            }
            // A box of the list, or any box, in the world or beyond it.
            const bool own = rng.Chance(0.7);
            const Aabb box = own ? boxes[static_cast<size_t>(k)] : Crowd(rng, 1, 40.0)[0];
            const int skip = own ? k : -1;
            grid.Meeting(boxes, box, skip, met);
            INFO("world " << world << ", search " << search);
            REQUIRE(met == MeetingAll(boxes, box, skip));
        }
    }
}

TEST_CASE("The grid of reaches with boxes that are not finite reads every box", "[world][ccd]")
{
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<Aabb> boxes{{{0.0, 0.0}, {1.0, 1.0}}, {{-inf, 0.5}, {inf, 0.6}}, {{2.0, 2.0}, {3.0, 3.0}}};
    detail::BoxGrid grid;
    grid.Make(boxes);
    std::vector<int> met;
    grid.Meeting(boxes, boxes[0], 0, met);
    CHECK(met == std::vector<int>{1});
    grid.Meeting(boxes, {{0.5, 0.0}, {2.5, 2.5}}, -1, met);
    CHECK(met == std::vector<int>{0, 1, 2});
}
