// SPDX-License-Identifier: MIT
// satviz: axis-aligned bounding boxes and the sort-and-sweep broadphase that finds the pairs whose boxes overlap.
#pragma once

#include <satviz/shape.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace satviz
{

/// An axis-aligned bounding box. Closed: boxes that touch overlap.
struct Aabb
{
    Vec2 min{}; ///< lower-left corner
    Vec2 max{}; ///< upper-right corner
};

/// True when the boxes overlap (touching counts).
inline bool AabbOverlap(const Aabb& a, const Aabb& b)
{
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

/// The box around two boxes.
inline Aabb AabbUnion(const Aabb& a, const Aabb& b)
{
    return {{a.min.x < b.min.x ? a.min.x : b.min.x, a.min.y < b.min.y ? a.min.y : b.min.y},
            {a.max.x > b.max.x ? a.max.x : b.max.x, a.max.y > b.max.y ? a.max.y : b.max.y}};
}

/// The tight box of a shape placed by `xf`. O(n) for an n-gon.
Aabb ComputeAabb(const Shape& shape, const Transform& xf);

/// Sort and sweep (Baraff's sweep and prune; Ericson, Real-Time Collision Detection, 7.5): the boxes sorted by their
/// lower bound on one axis, each box compared only with those whose lower bound lies within its extent on that axis,
/// then the other axis checked. The axis is the one along which the box centres spread most, so a wide pile is
/// swept across and a tall stack along its height. Keeps the order of the previous call, which an insertion sort
/// repairs in close to linear time when the boxes moved a little.
struct SortAndSweep
{
    /// Box indices in ascending order of their lower bound on the sweep axis; kept between calls.
    std::vector<int> order;
    /// The sweep axis of the last call (0: x, 1: y; -1 before the first). It changes only when the other axis
    /// spreads the centres clearly more, so a square pile does not flip between axes and re-sort from scratch.
    int axis = -1;
    /// Comparisons of a box with a neighbour on the sweep axis in the last call (the work done).
    int64_t comparisons = 0;

    /// One box's bounds as the sweep reads them: on the sweep axis, then on the other, and the box's index.
    struct Entry
    {
        double lower, upper;           ///< bounds on the sweep axis
        double otherLower, otherUpper; ///< bounds on the other axis
        int index;                     ///< the box's index in the caller's list
        int band;                      ///< the band of otherLower when the sweep uses bands, else 0
    };
    /// The boxes' bounds in `order` (working memory of the last call, kept to save its allocation).
    std::vector<Entry> sorted;
    /// The neighbours one box meets (working memory of the last call).
    std::vector<int> met;
    /// The entries of each band across the other axis, band after band, each in `order` (working memory).
    std::vector<Entry> banded;
    /// Where each band's entries begin in `banded`, and where the last ends (working memory).
    std::vector<int> bandStart;
    /// Where each first index's pairs begin in `byFirst`, as the pairs are sorted (working memory).
    std::vector<int> firstStart;
    /// The pairs sorted by their first index (working memory).
    std::vector<std::pair<int, int>> byFirst;
};

/// The pairs (i, j), i < j, of boxes that overlap, sorted by i then j, written to `pairs` (cleared first).
/// `skip(i, j)` is asked of each pair whose boxes overlap and drops it when true (static-static and sleeping pairs in
/// a world); it may be null. Deterministic: the result depends only on the boxes.
/// Cost: O(n log n) for n boxes on the first call or after the axis changes, close to O(n) for the sort when the
/// boxes moved a little since the last call; then O(n + c) for c comparisons on the sweep axis (`comparisons`).
/// With many boxes the other axis is cut into bands of about two box heights, each swept alone, so that c counts
/// a box's neighbours in the rows near it rather than in its whole column.
void FindPairs(SortAndSweep& sweep, const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs,
               bool (*skip)(const void* context, int i, int j) = nullptr, const void* context = nullptr);

/// The same pairs by comparing every box with every other: O(n^2), the oracle of the tests and the world's
/// "broadphase off" setting.
void FindPairsBruteForce(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs,
                         bool (*skip)(const void* context, int i, int j) = nullptr, const void* context = nullptr);

} // namespace satviz
