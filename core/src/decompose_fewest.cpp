// SPDX-License-Identifier: MIT
// satviz: the fewest convex pieces of a simple polygon, step 5 of the outline in decompose.cpp.
#include "decompose_fewest.h"

#include "decompose_predicates.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace satviz::decompose_detail
{
namespace
{

// Segment a-b (a, b vertices of the counter-clockwise polygon, not neighbours) is a diagonal: it leaves a into the
// interior and meets no edge other than at its ends.
template <typename S>
bool IsDiagonal(const std::vector<Vec2T<S>>& v, int a, int b)
{
    const int n = static_cast<int>(v.size());
    const Vec2T<S>& pa = v[a];
    const Vec2T<S>& pb = v[b];
    // Inside the cone at each end (between the edge to its successor and the edge from its predecessor):
    // O'Rourke's InCone.
    auto inCone = [&](int from, int to) {
        const Vec2T<S>& p = v[from];
        const Vec2T<S>& q = v[to];
        const Vec2T<S>& before = v[(from + n - 1) % n];
        const Vec2T<S>& after = v[(from + 1) % n];
        if (Orientation(before, p, after) > 0)
        {
            return Orientation(p, q, before) > 0 && Orientation(q, p, after) > 0;
        }
        return !(Orientation(p, q, after) >= 0 && Orientation(q, p, before) >= 0);
    };
    if (!inCone(a, b) || !inCone(b, a))
    {
        return false;
    }
    for (int e = 0; e < n; ++e)
    {
        const int f = (e + 1) % n;
        if (e == a || f == a || e == b || f == b)
        {
            // Edges at a or b meet the segment at its end; they can still hold the other end's line only through a
            // vertex, which the edges not at a or b test.
            continue;
        }
        if (SegmentsMeet(pa, pb, v[e], v[f]))
        {
            return false;
        }
    }
    // A vertex on the open segment whose two edges were both skipped above would be a neighbour of both a and b,
    // straight between them: such vertices were dropped before.
    return true;
}

} // namespace

template <typename S>
std::vector<std::vector<int>> Fewest(const std::vector<Vec2T<S>>& v)
{
    const int n = static_cast<int>(v.size());
    const int kInf = std::numeric_limits<int>::max() / 4;
    auto at = [n](int i, int j) { return static_cast<size_t>(i) * n + j; };
    // valid(i, j), i < j: edge or diagonal.
    std::vector<char> valid(static_cast<size_t>(n) * n, 0);
    for (int i = 0; i < n; ++i)
    {
        for (int j = i + 1; j < n; ++j)
        {
            valid[at(i, j)] = (j == i + 1 || (i == 0 && j == n - 1)) ? 1 : IsDiagonal(v, i, j);
        }
    }
    std::vector<int> best(static_cast<size_t>(n) * n, kInf);
    std::vector<std::vector<int>> chain(static_cast<size_t>(n) * n);
    for (int i = 0; i + 1 < n; ++i)
    {
        best[at(i, i + 1)] = 0;
    }
    std::vector<int> f(static_cast<size_t>(n) * n);
    std::vector<int> from(static_cast<size_t>(n) * n);
    for (int length = 2; length < n; ++length)
    {
        for (int i = 0; i + length < n; ++i)
        {
            const int j = i + length;
            if (!valid[at(i, j)])
            {
                continue;
            }
            // f(a, b): least sum of best over a left-turning chain i = v0, ..., a, b (i <= a < b <= j).
            for (int a = i; a <= j; ++a)
            {
                for (int b = a + 1; b <= j; ++b)
                {
                    f[at(a, b)] = kInf;
                }
            }
            for (int b = i + 1; b < j; ++b)
            {
                if (valid[at(i, b)] && best[at(i, b)] < kInf && TurnsLeft(v[j], v[i], v[b]))
                {
                    f[at(i, b)] = best[at(i, b)];
                    from[at(i, b)] = -1;
                }
            }
            for (int a = i + 1; a < j; ++a)
            {
                for (int b = a + 1; b <= j; ++b)
                {
                    if (!valid[at(a, b)] || best[at(a, b)] >= kInf)
                    {
                        continue;
                    }
                    int least = kInf;
                    int arg = -1;
                    for (int p = i; p < a; ++p)
                    {
                        if (f[at(p, a)] < least && TurnsLeft(v[p], v[a], v[b]))
                        {
                            least = f[at(p, a)];
                            arg = p;
                        }
                    }
                    if (arg >= 0)
                    {
                        f[at(a, b)] = least + best[at(a, b)];
                        from[at(a, b)] = arg;
                    }
                }
            }
            int least = kInf;
            int arg = -1;
            for (int a = i + 1; a < j; ++a)
            {
                if (f[at(a, j)] < least && TurnsLeft(v[a], v[j], v[i]))
                {
                    least = f[at(a, j)];
                    arg = a;
                }
            }
            if (arg < 0)
            {
                continue;
            }
            best[at(i, j)] = 1 + least;
            std::vector<int>& corners = chain[at(i, j)];
            int b = j;
            int a = arg;
            while (a >= 0)
            {
                corners.push_back(b);
                const int p = from[at(a, b)];
                b = a;
                a = p;
            }
            corners.push_back(i);
            std::reverse(corners.begin(), corners.end());
        }
    }
    std::vector<std::vector<int>> pieces;
    if (best[at(0, n - 1)] >= kInf)
    {
        return pieces;
    }
    std::vector<std::pair<int, int>> todo{{0, n - 1}};
    while (!todo.empty())
    {
        const auto [i, j] = todo.back();
        todo.pop_back();
        const std::vector<int>& corners = chain[at(i, j)];
        pieces.push_back(corners);
        for (size_t t = 0; t + 1 < corners.size(); ++t)
        {
            if (corners[t + 1] > corners[t] + 1)
            {
                todo.push_back({corners[t], corners[t + 1]});
            }
        }
    }
    return pieces;
}

template std::vector<std::vector<int>> Fewest(const std::vector<Vec2T<double>>&);
template std::vector<std::vector<int>> Fewest(const std::vector<Vec2T<float>>&);

} // namespace satviz::decompose_detail
