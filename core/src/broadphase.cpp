// SPDX-License-Identifier: MIT
// satviz: bounding boxes and sort and sweep.

#include <satviz/broadphase.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

Aabb ComputeAabb(const Shape& shape, const Transform& xf)
{
    if (shape.type == ShapeType::Circle)
    {
        const Vec2 c = TransformPoint(xf, shape.circle.center);
        const double r = shape.circle.radius;
        return {{c.x - r, c.y - r}, {c.x + r, c.y + r}};
    }
    const Polygon& polygon = shape.polygon;
    Vec2 lo = TransformPoint(xf, polygon.Vertices()[0]);
    Vec2 hi = lo;
    for (int i = 1; i < polygon.Count(); ++i)
    {
        const Vec2 v = TransformPoint(xf, polygon.Vertices()[i]);
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    }
    return {lo, hi};
}

namespace
{

// The axis along which the box centres spread most: 0 for x, 1 for y (Ericson, 7.5.2). The last axis stays
// unless the other spreads the centres a quarter more.
int SweepAxis(const std::vector<Aabb>& boxes, int last)
{
    const size_t n = boxes.size();
    double sum[2] = {0.0, 0.0};
    double sum2[2] = {0.0, 0.0};
    for (const Aabb& box : boxes)
    {
        const double cx = 0.5 * (box.min.x + box.max.x);
        const double cy = 0.5 * (box.min.y + box.max.y);
        sum[0] += cx;
        sum[1] += cy;
        sum2[0] += cx * cx;
        sum2[1] += cy * cy;
    }
    const double varX = sum2[0] - sum[0] * sum[0] / static_cast<double>(n);
    const double varY = sum2[1] - sum[1] * sum[1] / static_cast<double>(n);
    if (last == 0)
    {
        return varY > 1.25 * varX ? 1 : 0;
    }
    if (last == 1)
    {
        return varX > 1.25 * varY ? 0 : 1;
    }
    return varY > varX ? 1 : 0;
}

double Lower(const Aabb& box, int axis)
{
    return axis == 0 ? box.min.x : box.min.y;
}
double Upper(const Aabb& box, int axis)
{
    return axis == 0 ? box.max.x : box.max.y;
}

// Boxes from which the sweep splits the other axis into bands: fewer cost more to split than they save.
constexpr int kBandedFrom = 256;
// A band's height in mean box heights (on the other axis): lower, and more boxes span two bands and are swept
// twice; higher, and each box meets more boxes of other rows.
constexpr double kBandHeight = 2.0;

// Equal bands across the other axis, from the lowest lower bound up; the last takes all above it.
struct Bands
{
    double low = 0.0;     // the lowest lower bound
    double perBand = 0.0; // bands per unit of length
    int count = 1;        // bands

    // The band of position v. Monotone in v, so a box [l, u] spans the bands Of(l) to Of(u) and any v within it
    // falls in one of those.
    int Of(double v) const
    {
        const double t = (v - low) * perBand;
        return t < 1.0 ? 0 : (t < count ? static_cast<int>(t) : count - 1);
    }
};

Bands MakeBands(const std::vector<SortAndSweep::Entry>& sorted)
{
    Bands bands;
    const int n = static_cast<int>(sorted.size());
    if (n < kBandedFrom)
    {
        return bands;
    }
    double low = sorted[0].otherLower;
    double high = sorted[0].otherUpper;
    double heights = 0.0;
    for (const SortAndSweep::Entry& e : sorted)
    {
        low = std::min(low, e.otherLower);
        high = std::max(high, e.otherUpper);
        heights += e.otherUpper - e.otherLower;
    }
    const double height = kBandHeight * heights / n;
    // Boxes with bounds that are not finite (or all flat) are swept in one band, as they come.
    if (!(std::isfinite(high - low) && std::isfinite(height) && height > 0.0))
    {
        return bands;
    }
    const double count = std::min((high - low) / height, n / 8.0);
    if (!(count >= 2.0))
    {
        return bands;
    }
    bands.low = low;
    bands.count = static_cast<int>(count);
    bands.perBand = bands.count / (high - low);
    return bands;
}

} // namespace

// Outline (Baraff, 1992; Ericson, 7.5):
//  1. Pick the axis of largest spread of the box centres.
//  2. Order the boxes by their lower bound on it: an insertion sort of the last order when the count is unchanged
//     (boxes that moved a little swap with few neighbours), else a full sort. Ties go by index, so the order, and
//     with it the work, depends only on the boxes.
//  3. Split the other axis into bands of about two box heights (many boxes only); each box goes to the bands it
//     spans, in the order of step 2.
//  4. Sweep each band: a box meets the boxes after it in the band whose lower bound is within its upper bound; each
//     such pair is checked on the other axis, and kept only in the band where the two boxes' overlap begins.
//  5. Sort the pairs, so the caller sees them in the same order whatever the axis and the bands.
void FindPairs(SortAndSweep& sweep, const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs,
               bool (*skip)(const void* context, int i, int j), const void* context)
{
    pairs.clear();
    sweep.comparisons = 0;
    const int n = static_cast<int>(boxes.size());
    if (n < 2)
    {
        sweep.order.assign(n, 0);
        sweep.axis = -1;
        return;
    }
    const int axis = SweepAxis(boxes, sweep.axis);
    const bool sameAxis = axis == sweep.axis;
    sweep.axis = axis;
    std::vector<int>& order = sweep.order;
    auto before = [&](int i, int j) {
        const double li = Lower(boxes[i], axis);
        const double lj = Lower(boxes[j], axis);
        return li < lj || (li == lj && i < j);
    };
    if (sameAxis && static_cast<int>(order.size()) == n)
    {
        for (int k = 1; k < n; ++k)
        {
            const int item = order[k];
            int m = k - 1;
            while (m >= 0 && before(item, order[m]))
            {
                order[m + 1] = order[m];
                --m;
            }
            order[m + 1] = item;
        }
    }
    else
    {
        order.resize(n);
        for (int i = 0; i < n; ++i)
        {
            order[i] = i;
        }
        std::sort(order.begin(), order.end(), before);
    }

    // The bounds in the sweep's order, side by side: the sweep reads them in sequence instead of through the order,
    // and checks the other axis before it asks `skip`, so a pair apart on either axis costs no call.
    const int other = 1 - axis;
    std::vector<SortAndSweep::Entry>& sorted = sweep.sorted;
    sorted.resize(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k)
    {
        const Aabb& box = boxes[order[k]];
        sorted[k] = {Lower(box, axis), Upper(box, axis), Lower(box, other), Upper(box, other), order[k], 0};
    }
    // Bands across the other axis: each box is swept only with the boxes of the bands it spans, so a box in a
    // tall pile swept across meets the few rows near it, not its whole column.
    const Bands bands = MakeBands(sorted);
    const SortAndSweep::Entry* swept = sorted.data();
    std::vector<int>& bandStart = sweep.bandStart;
    bandStart.assign(static_cast<size_t>(bands.count) + 1, 0);
    if (bands.count > 1)
    {
        for (const SortAndSweep::Entry& e : sorted)
        {
            for (int b = bands.Of(e.otherLower), last = bands.Of(e.otherUpper); b <= last; ++b)
            {
                ++bandStart[static_cast<size_t>(b) + 1];
            }
        }
        for (int b = 0; b < bands.count; ++b)
        {
            bandStart[static_cast<size_t>(b) + 1] += bandStart[static_cast<size_t>(b)];
        }
        std::vector<SortAndSweep::Entry>& banded = sweep.banded;
        banded.resize(static_cast<size_t>(bandStart[static_cast<size_t>(bands.count)]));
        std::vector<int>& fill = sweep.met;
        fill.assign(bandStart.begin(), bandStart.end() - 1);
        for (SortAndSweep::Entry e : sorted)
        {
            e.band = bands.Of(e.otherLower);
            for (int b = e.band, last = bands.Of(e.otherUpper); b <= last; ++b)
            {
                banded[static_cast<size_t>(fill[static_cast<size_t>(b)]++)] = e;
            }
        }
        swept = banded.data();
    }
    else
    {
        bandStart[1] = n;
    }
    // Without a branch on the other axis, whose outcome is as good as random down a column of boxes: each neighbour's
    // place is written, and kept by advancing past it only when the boxes meet.
    std::vector<int>& met = sweep.met;
    met.resize(static_cast<size_t>(n));
    int* const metAt = met.data();
    int64_t comparisons = 0;
    for (int band = 0; band < bands.count; ++band)
    {
        const int end = bandStart[static_cast<size_t>(band) + 1];
        for (int k = bandStart[static_cast<size_t>(band)]; k < end; ++k)
        {
            const SortAndSweep::Entry a = swept[k];
            int count = 0;
            int m = k + 1;
            for (; m < end && !(swept[m].lower > a.upper); ++m)
            {
                const SortAndSweep::Entry& b = swept[m];
                metAt[count] = m;
                count += (a.otherLower <= b.otherUpper) & (b.otherLower <= a.otherUpper);
            }
            comparisons += m - (k + 1);
            for (int q = 0; q < count; ++q)
            {
                const SortAndSweep::Entry& b = swept[metAt[q]];
                // A pair of boxes that both span several bands meets in each band they share: it is kept in the
                // band where their overlap on the other axis begins, which both span. That is the band of the
                // higher lower bound, so the higher of the two boxes' first bands, as a band only grows with its
                // position (the lower bounds of two boxes that meet are numbers). Without bands, both are 0.
                if (std::max(a.band, b.band) != band)
                {
                    continue;
                }
                const int lo = a.index < b.index ? a.index : b.index;
                const int hi = a.index < b.index ? b.index : a.index;
                if (skip == nullptr || !skip(context, lo, hi))
                {
                    pairs.emplace_back(lo, hi);
                }
            }
        }
    }
    sweep.comparisons = comparisons;
    // A counting sort on the first index, then each (short) run sorted on the second: linear in the pairs. The
    // runs hold a box's few neighbours after it, sorted in place; a long one (a box that meets many) by std::sort.
    std::vector<int>& start = sweep.firstStart;
    start.assign(static_cast<size_t>(n) + 1, 0);
    for (const auto& pair : pairs)
    {
        ++start[pair.first + 1];
    }
    for (int i = 0; i < n; ++i)
    {
        start[i + 1] += start[i];
    }
    std::vector<std::pair<int, int>>& byFirst = sweep.byFirst;
    byFirst.resize(pairs.size());
    for (const auto& pair : pairs)
    {
        byFirst[start[pair.first]++] = pair;
    }
    std::pair<int, int>* const run = byFirst.data();
    int begin = 0;
    for (int i = 0; i < n; ++i)
    {
        const int end = start[i];
        if (end - begin > 16)
        {
            std::sort(run + begin, run + end);
        }
        else
        {
            // One first index: the second ones alone decide, and no two are equal.
            for (int k = begin + 1; k < end; ++k)
            {
                const std::pair<int, int> item = run[k];
                int m = k - 1;
                for (; m >= begin && run[m].second > item.second; --m)
                {
                    run[m + 1] = run[m];
                }
                run[m + 1] = item;
            }
        }
        begin = end;
    }
    pairs.swap(byFirst);
}

void FindPairsBruteForce(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>& pairs,
                         bool (*skip)(const void* context, int i, int j), const void* context)
{
    pairs.clear();
    const int n = static_cast<int>(boxes.size());
    for (int i = 0; i < n; ++i)
    {
        for (int j = i + 1; j < n; ++j)
        {
            if (skip != nullptr && skip(context, i, j))
            {
                continue;
            }
            if (AabbOverlap(boxes[i], boxes[j]))
            {
                pairs.emplace_back(i, j);
            }
        }
    }
}

} // namespace satviz
