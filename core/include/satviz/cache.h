// SPDX-License-Identifier: MIT
// satviz: frame coherence. Shapes that move a little per frame are usually separated by the same axis as in the
// previous frame; a pair keeps that axis in a cache and tests it first, and the query ends there most of the time.
#pragma once

#include <satviz/manifold.h>
#include <satviz/polygon.h>

namespace satviz
{

/// What a polygon pair's previous Overlap learnt: the face that separated it, or none. Keep one per pair of
/// bodies (in the broadphase's pair record) and pass the same one frame after frame; a default-constructed cache
/// is empty. A cache describes its pair only: do not share it between pairs or swap A and B.
struct SatCache
{
    AxisRef axis{};   ///< the separating face found last time (kind None: nothing cached)
    int support = -1; ///< the other polygon's support vertex for that face, where the next search starts
};

/// Overlap of two polygons, with frame coherence: first the cached separating face alone, its support point found
/// by climbing from the cached one (a step or two when the pair moved a little, whatever the vertex count); if it
/// still separates, the answer is "no" at once. Otherwise the full query runs, and the cache keeps the separating
/// face it finds (or is emptied when the polygons overlap). A face the cache reports separating separates the
/// shapes, so the answer is Overlap's, except that shapes touching within rounding may get either answer.
/// Cost: when the cached face still separates, one face and the climb of its support point, O(1) for a pair that
/// moved a little; otherwise that plus Overlap's cost.
template <typename S>
bool Overlap(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
             SatCache& cache);

} // namespace satviz
