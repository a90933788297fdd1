// SPDX-License-Identifier: MIT
// satviz (private), chapter 2: the incident polygon. A face query tests the faces of one polygon, the reference
// polygon, against the other, the incident polygon, in the reference polygon's frame. A small incident polygon is
// mapped into that frame once, so that each face then costs one pass over its vertices (face_query.h); a large one
// is only given its transform, and its support points are walked to.
#pragma once

#include "support.h"
#include "tracer.h"

#include <satviz/polygon.h>

#include <cstdint>

namespace satviz::detail
{

/// Polygons with at most this many vertices are scanned whole for each face instead of walked: for small
/// counts a branch-free scan of a few projections beats the data-dependent branches of the walk.
constexpr int kScanLimit = AlgorithmChoices::kScanLimit;

/// Maps a polygon's vertices by a transform into arrays x and y, one vertex at a time, as TransformPoint does.
struct MapOneByOne
{
    /// Writes the vertices of `p` mapped by `xf` to x[0 .. count) and y[0 .. count).
    template <typename S>
    void operator()(const PolygonT<S>& p, const TransformT<S>& xf, S* x, S* y) const
    {
        const Vec2T<S>* vertices = p.Vertices().data;
        for (int j = 0; j < p.Count(); ++j)
        {
            const Vec2T<S> w = TransformPoint(xf, vertices[j]);
            x[j] = w.x;
            y[j] = w.y;
        }
    }
};

/// The incident polygon of a face query: the polygon, its transform into the reference frame, and, when it is
/// small enough to scan, its vertices mapped into that frame as a structure of arrays on the stack, followed by
/// vertex 0 again up to the next multiple of 4 entries past the last vertex: scans read whole blocks of 4, and
/// entry `count` closes the outline, so edge j runs from entry j to entry j + 1.
template <typename S>
struct IncidentPolygon
{
    static constexpr int kCapacity = kScanLimit + 4;
    const PolygonT<S>& polygon; ///< the incident polygon
    TransformT<S> xf;           ///< its frame relative to the reference polygon
    bool scan;                  ///< small: mapped below, scanned
    Vec2T<S> centroid;          ///< the polygon's centroid in the reference frame
    int padded = 0; ///< entries a scan reads, a multiple of 4 (entries from the vertex count to this one hold vertex 0)
    alignas(32) S x[kCapacity];
    alignas(32) S y[kCapacity];

    /// `p` with transform `xfInc` against a reference polygon with transform `xfRef`. `scanLimit` (at most
    /// kScanLimit) is the largest vertex count that is scanned. `map` maps the vertices of a scanned polygon into the
    /// reference frame: one at a time as the textbook does (MapOneByOne), or four at a time in lanes with the same
    /// bits (MapInLanes, face_kernel.h), which the scans of the face loops then read whole. The relative transform
    /// is computed into the member itself: built elsewhere and copied in, its scalar stores were read back as pairs,
    /// which stalled store forwarding.
    template <typename Map = MapOneByOne>
    IncidentPolygon(const PolygonT<S>& p, const TransformT<S>& xfRef, const TransformT<S>& xfInc,
                    int scanLimit = kScanLimit, Map map = {})
        : polygon(p), xf(InvMulTransforms(xfRef, xfInc)), scan(p.Count() > 0 && p.Count() <= scanLimit),
          centroid(TransformPoint(xf, p.Centroid()))
    {
        if (!scan)
        {
            return;
        }
        const int count = polygon.Count();
        padded = (count + 3) & ~3;
        map(polygon, xf, x, y);
        // Vertex 0 again in the four entries after the last vertex (at most kScanLimit + 3 < kCapacity): those up to
        // `padded`, which the scans read, and one more. A fixed count, so no loop and no branch.
        for (int k = 0; k < 4; ++k)
        {
            x[count + k] = x[0];
            y[count + k] = y[0];
        }
    }

    /// `p`, whose vertices `xfInc` (its frame relative to the reference polygon) has already mapped: `store(x, y)`
    /// writes them, then vertex 0 again up to entry count + 3, as the constructor above lays them out. For the
    /// 512-bit face loops, which hold the mapped vertices in registers (collide512.h).
    template <typename Store>
    IncidentPolygon(const PolygonT<S>& p, const TransformT<S>& xfInc, Store&& store)
        : polygon(p), xf(xfInc), scan(true), centroid(TransformPoint(xf, p.Centroid())), padded((p.Count() + 3) & ~3)
    {
        store(x, y);
    }

    /// The separation of a reference face from this polygon's vertex `support`, its support point.
    S Separation(Vec2T<S> normal, Vec2T<S> v, int support) const
    {
        return Dot(normal, TransformPoint(xf, polygon.Vertices()[support]) - v);
    }

    /// The first vertex whose projection on `normal` (reference frame) is the smallest: the support point in
    /// direction -normal. Off the fast path (the face loops need only the smallest projection): for the trace, which
    /// shows each face's support point, and the rare step that wants the vertex itself.
    int Support(Vec2T<S> normal) const
    {
        if (!scan)
        {
            return BisectSupport(polygon, InvRotate(xf.q, -normal));
        }
        int support = 0;
        S low = normal.x * x[0] + normal.y * y[0];
        for (int j = 1; j < polygon.Count(); ++j)
        {
            const S projection = normal.x * x[j] + normal.y * y[j];
            if (projection < low)
            {
                low = projection;
                support = j;
            }
        }
        return support;
    }
};

} // namespace satviz::detail
