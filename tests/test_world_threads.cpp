// SPDX-License-Identifier: MIT
// The world on several threads: the task pool covers every index once, and random worlds (piles, rain, fast bodies,
// concave bodies) step to the same bits with 1, 2 and 3 workers, and with a caller's runner that takes the pieces
// in a scrambled order, as on the calling thread alone.

#include "support/random_concave.h"
#include "support/random_shapes.h"
#include "support/world_scenes.h"

#include <satviz/concave.h>
#include <satviz/decompose.h>
#include <satviz/tasks.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

// Counts, per index, how often a task was called on it.
struct Tally
{
    std::vector<std::atomic<int>> calls;
    explicit Tally(int n) : calls(static_cast<size_t>(n)) {}
};

void CountCalls(void* context, int begin, int end)
{
    Tally& tally = *static_cast<Tally*>(context);
    for (int i = begin; i < end; ++i)
    {
        tally.calls[static_cast<size_t>(i)].fetch_add(1);
    }
}

// A caller's runner on the calling thread that hands out the range in pieces of random sizes, last piece first: the
// world must not depend on how its work is split nor in which order the pieces run.
struct ScrambledRunner
{
    Rng rng{7};

    static void Run(void* context, int count, TaskFunction task, void* taskContext)
    {
        ScrambledRunner& self = *static_cast<ScrambledRunner*>(context);
        std::vector<std::pair<int, int>> pieces;
        for (int begin = 0; begin < count;)
        {
            const int end = std::min(count, begin + self.rng.Int(1, 40));
            pieces.emplace_back(begin, end);
            begin = end;
        }
        for (auto piece = pieces.rbegin(); piece != pieces.rend(); ++piece)
        {
            task(taskContext, piece->first, piece->second);
        }
    }
};

// A box, a disc or a random convex polygon of 3 to 8 vertices, about 0.25 to 0.5 across its radius.
Shape RandomBody(Rng& rng)
{
    const double radius = rng.Uniform(0.25, 0.5);
    switch (rng.Int(0, 2))
    {
    case 0:
        return BoxShape(radius * rng.Uniform(0.5, 1.0), radius * rng.Uniform(0.5, 1.0));
    case 1:
        return DiscShape(radius);
    default:
        return MakeShape(RandomPolygon(rng, rng.Int(3, 8), radius, rng.Uniform(0.6, 1.0)));
    }
}

// A concave body from a random star-shaped outline, or none when its decomposition has a single piece.
bool RandomConcave(Rng& rng, Concave& concave)
{
    const Decomposition d = Decompose(RandomStarPolygon(rng, rng.Int(5, 9), 0.6, 0.35), DecomposeMethod::Fast);
    if (!d.Ok() || d.pieces.size() < 2)
    {
        return false;
    }
    concave = MakeConcave(d.pieces);
    return true;
}

enum class Kind
{
    Pile,  // a heap dropped from rest onto the ground
    Rain,  // bodies falling from far up at different heights, spinning
    Fast,  // a pile with bullets fired into it (swept hits)
    Mixed, // a pile with concave bodies and a few bullets
};

// A random world of `count` dynamic bodies between two walls, of the given kind.
World RandomWorld(Kind kind, uint64_t seed, int count)
{
    Rng rng(seed);
    World world = WorldWithGravity(kGravity);
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    const double width = 1.1 * columns;
    AddGround(world, 0.5 * width + 1.0);
    const double height = kind == Kind::Rain ? 40.0 : 1.1 * (count / columns + 2);
    AddStatic(world, BoxShape(0.5, 0.5 * height + 1.0), {-0.5 * width - 0.5, 0.5 * height});
    AddStatic(world, BoxShape(0.5, 0.5 * height + 1.0), {0.5 * width + 0.5, 0.5 * height});
    for (int k = 0; k < count; ++k)
    {
        const Vec2 p{-0.5 * width + 1.1 * (k % columns + 0.5) + rng.Uniform(-0.05, 0.05),
                     0.6 + (kind == Kind::Rain ? rng.Uniform(0.0, height) : 1.1 * (k / columns))};
        const double angle = rng.Uniform(-3.0, 3.0);
        const Vec2 v = kind == Kind::Rain ? Vec2{rng.Uniform(-1.0, 1.0), rng.Uniform(-5.0, 0.0)} : Vec2{};
        const double w = kind == Kind::Rain ? rng.Uniform(-3.0, 3.0) : 0.0;
        Concave concave;
        if (kind == Kind::Mixed && rng.Chance(0.3) && RandomConcave(rng, concave))
        {
            BodyDef def;
            def.concave = concave;
            def.position = p;
            def.angle = angle;
            AddBody(world, def);
            continue;
        }
        AddDynamic(world, RandomBody(rng), p, angle, v, w);
    }
    if (kind == Kind::Fast || kind == Kind::Mixed)
    {
        const int bullets = kind == Kind::Fast ? count / 4 : 8;
        for (int k = 0; k < bullets; ++k)
        {
            // Fired down and sideways into the pile, from above it: each crosses several bodies' sizes in a step.
            const Vec2 p{rng.Uniform(-0.5 * width, 0.5 * width), height + rng.Uniform(1.0, 6.0)};
            const Vec2 v{rng.Uniform(-60.0, 60.0), rng.Uniform(-250.0, -80.0)};
            AddDynamic(world, DiscShape(rng.Uniform(0.05, 0.15)), p, 0.0, v, rng.Uniform(-50.0, 50.0));
        }
    }
    return world;
}

std::string KindName(Kind kind)
{
    switch (kind)
    {
    case Kind::Pile:
        return "pile";
    case Kind::Rain:
        return "rain";
    case Kind::Fast:
        return "fast";
    default:
        return "mixed";
    }
}

} // namespace

TEST_CASE("The task pool runs every index of a range exactly once, for any count and number of workers", "[tasks]")
{
    for (const int workers : {1, 2, 3, 5})
    {
        ThreadPool pool(workers);
        CHECK(pool.Workers() == workers);
        const TaskRunner runner = PoolTasks(pool);
        CHECK(runner.workers == workers);
        for (const int count : {0, 1, 2, 7, 64, 1000, 4099})
        {
            // Many runs in a row, as a step hands them: a thread late for one run must not take a piece of the next.
            for (int round = 0; round < 50; ++round)
            {
                Tally tally(count);
                runner.run(runner.context, count, CountCalls, &tally);
                int wrong = 0;
                for (const std::atomic<int>& calls : tally.calls)
                {
                    wrong += calls.load() != 1;
                }
                INFO(workers << " workers, count " << count << ", round " << round);
                REQUIRE(wrong == 0);
            }
        }
    }
}

TEST_CASE("Random worlds step to the same bits on 1, 2 and 3 threads as on the calling thread alone",
          "[world][tasks][determinism]")
{
    ThreadPool one(1), two(2), three(3);
    ScrambledRunner scrambled;
    TaskRunner custom;
    custom.run = ScrambledRunner::Run;
    custom.context = &scrambled;
    custom.workers = 2;
    const std::vector<TaskRunner> runners = {PoolTasks(one), PoolTasks(two), PoolTasks(three), custom};
    const char* const names[] = {"pool of 1", "pool of 2", "pool of 3", "scrambled"};
    for (const Kind kind : {Kind::Pile, Kind::Rain, Kind::Fast, Kind::Mixed})
    {
        for (const uint64_t seed : {11u, 12u})
        {
            // Enough bodies and pairs that every stage splits its work into several pieces.
            const World start = RandomWorld(kind, seed * 100 + static_cast<uint64_t>(kind), 400);
            World serial = start;
            std::vector<World> threaded(runners.size(), start);
            for (size_t r = 0; r < runners.size(); ++r)
            {
                threaded[r].tasks = runners[r];
            }
            int64_t swept = 0, hits = 0, sleeping = 0;
            for (int step = 0; step < 240; ++step)
            {
                Step(serial, kDt);
                swept += serial.counts.swept;
                hits += serial.counts.hits;
                sleeping += serial.counts.sleepingBodies;
                for (size_t r = 0; r < runners.size(); ++r)
                {
                    Step(threaded[r], kDt);
                    INFO(KindName(kind) << " seed " << seed << ", " << names[r] << ", step " << step);
                    REQUIRE(SameState(serial, threaded[r]));
                    REQUIRE(serial.contacts.size() == threaded[r].contacts.size());
                    REQUIRE(serial.counts.tested == threaded[r].counts.tested);
                    REQUIRE(serial.counts.touching == threaded[r].counts.touching);
                    REQUIRE(serial.counts.speculative == threaded[r].counts.speculative);
                    REQUIRE(serial.counts.swept == threaded[r].counts.swept);
                    REQUIRE(serial.counts.hits == threaded[r].counts.hits);
                }
            }
            // The runs meet what they are meant to: bullets are swept and hit, piles settle and sleep.
            INFO(KindName(kind) << " seed " << seed << ": swept " << swept << ", hits " << hits << ", sleeping "
                                << sleeping);
            if (kind == Kind::Fast || kind == Kind::Mixed)
            {
                CHECK(hits > 0);
            }
            if (kind == Kind::Pile)
            {
                CHECK(sleeping > 0);
            }
        }
    }
}
