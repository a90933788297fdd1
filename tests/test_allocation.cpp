// SPDX-License-Identifier: MIT
// The untraced queries allocate nothing: every operator new in this test binary is counted.

#include "support/random_shapes.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

namespace
{
std::atomic<long> g_allocations{0};
}

// Every replaceable form goes through malloc and free, so that a sanitizer sees matching pairs.
void* operator new(std::size_t size)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size))
    {
        return p;
    }
    throw std::bad_alloc();
}

void* operator new[](std::size_t size)
{
    return operator new(size);
}

void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size == 0 ? 1 : size);
}

void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept
{
    return operator new(size, tag);
}

void operator delete(void* p) noexcept
{
    std::free(p);
}

void operator delete[](void* p) noexcept
{
    std::free(p);
}

void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete[](void* p, std::size_t) noexcept
{
    std::free(p);
}

using namespace satviz;
using namespace satviz::testing;

TEST_CASE("Overlap, Collide and Sweep allocate nothing, at any vertex count", "[allocation]")
{
    Rng rng(5);
    std::vector<RandomPair> pairs;
    for (int n : {3, 8, 16, 17, 64, 1024, 4096})
    {
        for (int k = 0; k < 20; ++k)
        {
            pairs.push_back(ContactPair(rng, n, static_cast<PairCategory>(k % 3)));
        }
    }
    pairs.push_back(RandomShapePair(rng, 1.0)); // circles
    const long before = g_allocations.load();
    double sink = 0.0;
    for (const RandomPair& p : pairs)
    {
        sink += Overlap(p.a, p.xfA, p.b, p.xfB) ? 1.0 : 0.0;
        sink += Collide(p.a, p.xfA, p.b, p.xfB).depth;
        sink += Sweep(p.a, p.xfA, Vec2{}, p.b, p.xfB, p.xfA.p - p.xfB.p).toi;
    }
    const long during = g_allocations.load() - before;
    CHECK(during == 0);
    CHECK(std::isfinite(sink)); // the results are used, so the queries are not optimised away

    // The traced query does allocate (its trace grows): the counter sees it.
    Trace trace;
    Collide(pairs[0].a, pairs[0].xfA, pairs[0].b, pairs[0].xfB, &trace);
    CHECK(g_allocations.load() - before > 0);
}
