// SPDX-License-Identifier: MIT
// satviz: concave shapes in the queries. Each side of a query is a list of convex parts (a convex shape is one
// part); the pairs of parts whose boxes overlap go to the convex queries, whose answers are merged by the rules
// written in concave.h. The convex queries are called as they are: nothing here touches their fast paths. A side
// and its boxes are in concave_sides.h; the segment cast is in concave_raycast.cpp.

#include "concave_sides.h"

#include <satviz/collide.h>
#include <satviz/concave.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz
{
namespace
{

using namespace concave_detail;

// The normal `outward` (world, pointing out of part i of `side` towards the other shape) points along an internal
// edge of the part: it is that edge's normal, or the axis is a vertex axis at a corner of an internal edge and
// leans to that edge's outer side.
template <typename S>
bool AlongSeam(const Side<S>& side, int i, Vec2T<S> outward, const AxisRef& axis)
{
    const std::vector<bool>* internal = side.Internal(i);
    if (internal == nullptr)
    {
        return false;
    }
    const PolygonT<S>& polygon = side.Part(i).polygon;
    const Vec2T<S> n = InvRotate(side.xf.q, outward);
    const int count = polygon.Count();
    for (int e = 0; e < count; ++e)
    {
        if ((*internal)[e] && Dot(n, polygon.Normal(e)) >= S(1) - S(64) * std::numeric_limits<S>::epsilon())
        {
            return true;
        }
    }
    if (axis.kind == AxisKind::VertexToCenter && axis.shape == side.index)
    {
        const int v = axis.index;
        for (int e : {(v + count - 1) % count, v})
        {
            if ((*internal)[e] && Dot(n, polygon.Normal(e)) > S(0))
            {
                return true;
            }
        }
    }
    return false;
}

template <typename S>
bool PairAlongSeam(const Side<S>& a, int i, const Side<S>& b, int j, Vec2T<S> normal, const AxisRef& axis)
{
    return AlongSeam(a, i, normal, axis) || AlongSeam(b, j, -normal, axis);
}

// A pair whose own normal points along a seam, tested again on the axes that are surfaces: the face normals of both
// polygons except those along an internal edge, each as the direction that pushes B out of A's part. The least
// overlap on them is the pair's depth as part of the whole shape; the contacts are B's deepest points on that axis
// (one, or the two ends of a face of B lying across it), halfway to A's surface. False when no surface axis is
// left or a part is a circle.
template <typename S>
bool SurfaceManifold(const Side<S>& a, int i, const Side<S>& b, int j, ManifoldT<S>& out)
{
    if (a.Part(i).type != ShapeType::Polygon || b.Part(j).type != ShapeType::Polygon)
    {
        return false;
    }
    const PolygonT<S>& pa = a.Part(i).polygon;
    const PolygonT<S>& pb = b.Part(j).polygon;
    // Vertices relative to A's origin, so that the pair keeps its precision far from the world's origin.
    std::vector<Vec2T<S>> va;
    std::vector<Vec2T<S>> vb;
    for (const Vec2T<S>& v : pa.Vertices())
    {
        va.push_back(Rotate(a.xf.q, v));
    }
    const Vec2T<S> offset = b.xf.p - a.xf.p;
    for (const Vec2T<S>& v : pb.Vertices())
    {
        vb.push_back(Rotate(b.xf.q, v) + offset);
    }
    bool found = false;
    S least = std::numeric_limits<S>::infinity();
    auto consider = [&](Vec2T<S> n, AxisRef axis) {
        if (PairAlongSeam(a, i, b, j, n, axis))
        {
            return;
        }
        S maxA = -std::numeric_limits<S>::infinity();
        S minB = std::numeric_limits<S>::infinity();
        for (const Vec2T<S>& v : va)
        {
            maxA = std::max(maxA, Dot(v, n));
        }
        for (const Vec2T<S>& v : vb)
        {
            minB = std::min(minB, Dot(v, n));
        }
        const S overlap = maxA - minB;
        if (overlap < least)
        {
            least = overlap;
            found = true;
            out.normal = n;
            out.axis = axis;
        }
    };
    for (int e = 0; e < pa.Count(); ++e)
    {
        consider(Rotate(a.xf.q, pa.Normal(e)), {AxisKind::FaceNormal, 0, e});
    }
    for (int f = 0; f < pb.Count(); ++f)
    {
        consider(-Rotate(b.xf.q, pb.Normal(f)), {AxisKind::FaceNormal, 1, f});
    }
    if (!found || least < S(0))
    {
        return false;
    }
    const Vec2T<S> n = out.normal;
    S minB = std::numeric_limits<S>::infinity();
    for (const Vec2T<S>& v : vb)
    {
        minB = std::min(minB, Dot(v, n));
    }
    const S scale = std::max(S(1), least);
    const Vec2T<S> tangent = LeftPerp(n);
    int low = -1;
    int high = -1;
    for (int k = 0; k < static_cast<int>(vb.size()); ++k)
    {
        if (Dot(vb[k], n) <= minB + S(64) * std::numeric_limits<S>::epsilon() * scale)
        {
            if (low < 0 || Dot(vb[k], tangent) < Dot(vb[low], tangent))
            {
                low = k;
            }
            if (high < 0 || Dot(vb[k], tangent) > Dot(vb[high], tangent))
            {
                high = k;
            }
        }
    }
    out.depth = least;
    out.incidentEdge = -1;
    out.contactCount = 0;
    for (int k : {low, high})
    {
        if (out.contactCount == 1 && k == low)
        {
            continue;
        }
        ContactPointT<S>& c = out.contacts[out.contactCount++];
        c.point = a.xf.p + vb[k] + (least / S(2)) * n;
        c.separation = -least;
    }
    return true;
}

// The manifold of a concave pair keeps, of the contacts its piece pairs found along the deciding normal, the two
// farthest apart across that normal: the pair that spans the contact, so a body resting on several pieces is held
// at both ends as on one face. Piece pairs whose normal differs (beyond round-off) push another way and give none,
// nor do those the caller leaves out.
template <typename S, typename Candidate, typename LeftOut>
void KeepWidestContacts(const std::vector<Candidate>& candidates, const Candidate& deciding, LeftOut leftOut,
                        ManifoldT<S>& out)
{
    const Vec2T<S> normal = deciding.manifold.normal;
    std::vector<ContactPointT<S>> points;
    for (const Candidate& c : candidates)
    {
        if (leftOut(c) || Dot(c.manifold.normal, normal) < S(1) - S(64) * std::numeric_limits<S>::epsilon())
        {
            continue;
        }
        for (int k = 0; k < c.manifold.contactCount; ++k)
        {
            points.push_back(c.manifold.contacts[k]);
        }
    }
    if (points.empty())
    {
        return;
    }
    const Vec2T<S> tangent = LeftPerp(normal);
    const Vec2T<S> origin = deciding.manifold.contacts[0].point;
    auto along = [&](const ContactPointT<S>& p) { return Dot(p.point - origin, tangent); };
    const auto [low, high] =
        std::minmax_element(points.begin(), points.end(), [&](const auto& p, const auto& q) { return along(p) < along(q); });
    out.contacts[0] = *low;
    out.contactCount = 1;
    if (along(*high) > along(*low))
    {
        out.contacts[1] = *high;
        out.contactCount = 2;
    }
}

template <typename S>
bool OverlapSides(const Side<S>& a, const Side<S>& b)
{
    std::vector<BoundsT<S>> boxesB(static_cast<size_t>(b.Count()));
    for (int j = 0; j < b.Count(); ++j)
    {
        boxesB[j] = WorldBox(b, j);
    }
    for (int i = 0; i < a.Count(); ++i)
    {
        const BoundsT<S> boxA = WorldBox(a, i);
        for (int j = 0; j < b.Count(); ++j)
        {
            if (BoxesOverlap(boxA, boxesB[j]) && Overlap(a.Part(i), a.xf, b.Part(j), b.xf))
            {
                return true;
            }
        }
    }
    return false;
}

template <typename S>
ConcaveManifoldT<S> CollideSides(const Side<S>& a, const Side<S>& b)
{
    struct Candidate
    {
        ManifoldT<S> manifold;
        int i;
        int j;
        bool seam;
    };
    std::vector<Candidate> overlapping;
    ConcaveManifoldT<S> result;
    S leastGap = std::numeric_limits<S>::infinity();
    std::vector<BoundsT<S>> boxesB(static_cast<size_t>(b.Count()));
    for (int j = 0; j < b.Count(); ++j)
    {
        boxesB[j] = WorldBox(b, j);
    }
    for (int i = 0; i < a.Count(); ++i)
    {
        const BoundsT<S> boxA = WorldBox(a, i);
        for (int j = 0; j < b.Count(); ++j)
        {
            const BoundsT<S>& boxB = boxesB[j];
            if (!BoxesOverlap(boxA, boxB))
            {
                // A lower bound of the distance: the gap between the boxes on the axis that parts them most.
                const S right = boxB.min.x - boxA.max.x;
                const S left = boxA.min.x - boxB.max.x;
                const S up = boxB.min.y - boxA.max.y;
                const S down = boxA.min.y - boxB.max.y;
                const S gap = std::max({right, left, up, down});
                if (gap < leastGap)
                {
                    leastGap = gap;
                    result.manifold.gap = gap;
                    result.manifold.normal = gap == right  ? Vec2T<S>{1, 0}
                                             : gap == left ? Vec2T<S>{-1, 0}
                                             : gap == up   ? Vec2T<S>{0, 1}
                                                           : Vec2T<S>{0, -1};
                    result.manifold.axis = {};
                    result.pieceA = a.Piece(i);
                    result.pieceB = b.Piece(j);
                }
                continue;
            }
            ++result.pairsTested;
            const ManifoldT<S> m = Collide(a.Part(i), a.xf, b.Part(j), b.xf);
            if (!m.overlap)
            {
                if (m.gap < leastGap)
                {
                    leastGap = m.gap;
                    result.manifold = m;
                    result.pieceA = a.Piece(i);
                    result.pieceB = b.Piece(j);
                }
                continue;
            }
            Candidate candidate{m, i, j, PairAlongSeam(a, i, b, j, m.normal, m.axis)};
            if (candidate.seam && SurfaceManifold(a, i, b, j, candidate.manifold))
            {
                ++result.pairsSeam;
                candidate.seam = false;
            }
            overlapping.push_back(candidate);
        }
    }
    if (overlapping.empty())
    {
        return result;
    }
    result.pairsOverlap = static_cast<int>(overlapping.size());
    const bool anyOnSurface =
        std::any_of(overlapping.begin(), overlapping.end(), [](const Candidate& c) { return !c.seam; });
    const Candidate* deciding = nullptr;
    for (const Candidate& c : overlapping)
    {
        if (c.seam && anyOnSurface)
        {
            ++result.pairsSeam;
            continue;
        }

        if (deciding == nullptr || c.manifold.depth > deciding->manifold.depth)
        {
            deciding = &c;
        }
    }
    result.manifold = deciding->manifold;
    result.pieceA = a.Piece(deciding->i);
    result.pieceB = b.Piece(deciding->j);
    KeepWidestContacts(overlapping, *deciding, [&](const Candidate& c) { return c.seam && anyOnSurface; },
                       result.manifold);
    return result;
}

// Speculative contacts by pieces: see CollideWithin in concave.h.
template <typename S>
ConcaveManifoldT<S> CollideWithinSides(const Side<S>& a, const Side<S>& b, S margin)
{
    ConcaveManifoldT<S> merged = CollideSides(a, b);
    if (merged.manifold.overlap || merged.manifold.gap > margin)
    {
        return merged;
    }
    struct Candidate
    {
        ManifoldT<S> manifold;
        int i;
        int j;
    };
    std::vector<Candidate> near;
    std::vector<BoundsT<S>> boxesB(static_cast<size_t>(b.Count()));
    for (int j = 0; j < b.Count(); ++j)
    {
        boxesB[j] = WorldBox(b, j);
        boxesB[j].min = boxesB[j].min - Vec2T<S>{margin, margin};
        boxesB[j].max = boxesB[j].max + Vec2T<S>{margin, margin};
    }
    for (int i = 0; i < a.Count(); ++i)
    {
        const BoundsT<S> boxA = WorldBox(a, i);
        for (int j = 0; j < b.Count(); ++j)
        {
            if (!BoxesOverlap(boxA, boxesB[j]))
            {
                continue;
            }
            const ManifoldT<S> m = CollideWithin(a.Part(i), a.xf, b.Part(j), b.xf, margin);
            // A piece pair that overlaps while the whole does not cannot be (CollideSides tested every pair); a pair
            // pushed along a seam is a ghost.
            if (m.overlap || m.contactCount == 0 || PairAlongSeam(a, i, b, j, m.normal, m.axis))
            {
                continue;
            }
            near.push_back({m, i, j});
        }
    }
    if (near.empty())
    {
        return merged;
    }
    const Candidate* deciding = &near.front();
    for (const Candidate& c : near)
    {
        if (c.manifold.gap < deciding->manifold.gap)
        {
            deciding = &c;
        }
    }
    ConcaveManifoldT<S> result = merged;
    result.manifold = deciding->manifold;
    result.pieceA = a.Piece(deciding->i);
    result.pieceB = b.Piece(deciding->j);
    KeepWidestContacts(near, *deciding, [](const Candidate&) { return false; }, result.manifold);
    return result;
}

template <typename S>
ConcaveSweepResultT<S> SweepSides(const Side<S>& a, Vec2T<S> vA, const Side<S>& b, Vec2T<S> vB)
{
    ConcaveSweepResultT<S> out;
    bool bestOnSeam = false;
    const Vec2T<S> relative = vB - vA;
    for (int i = 0; i < a.Count(); ++i)
    {
        const BoundsT<S> boxA = WorldBox(a, i);
        for (int j = 0; j < b.Count(); ++j)
        {
            // B's box swept over the step, relative to A.
            BoundsT<S> boxB = WorldBox(b, j);
            boxB = Grow(Grow(boxB, boxB.min + relative), boxB.max + relative);
            if (!BoxesOverlap(boxA, boxB))
            {
                continue;
            }
            const SweepResultT<S> r = Sweep(a.Part(i), a.xf, vA, b.Part(j), b.xf, vB);
            if (r.status == SweepStatus::Overlapping)
            {
                ConcaveSweepResultT<S> overlapping;
                const ConcaveManifoldT<S> merged = CollideSides(a, b);
                overlapping.result.status = SweepStatus::Overlapping;
                overlapping.result.initial = merged.manifold;
                overlapping.result.normal = merged.manifold.normal;
                overlapping.result.axis = merged.manifold.axis;
                overlapping.pieceA = merged.pieceA;
                overlapping.pieceB = merged.pieceB;
                return overlapping;
            }
            if (r.status != SweepStatus::Hit)
            {
                continue;
            }
            const bool onSeam = PairAlongSeam(a, i, b, j, r.normal, r.axis);
            const bool earlier = out.result.status != SweepStatus::Hit || r.toi < out.result.toi ||
                                 (r.toi == out.result.toi && bestOnSeam && !onSeam);
            if (earlier)
            {
                out.result = r;
                out.pieceA = a.Piece(i);
                out.pieceB = b.Piece(j);
                bestOnSeam = onSeam;
            }
        }
    }
    return out;
}

} // namespace

template <typename S>
ConcaveT<S> MakeConcave(const std::vector<ConvexPieceT<S>>& pieces)
{
    ConcaveT<S> concave;
    for (const ConvexPieceT<S>& piece : pieces)
    {
        ConcavePartT<S> part;
        part.shape = MakeShape(piece.polygon);
        part.internal = piece.internal;
        part.bounds = Empty<S>();
        for (const Vec2T<S>& v : piece.polygon.Vertices())
        {
            part.bounds = Grow(part.bounds, v);
        }
        concave.parts.push_back(std::move(part));
    }
    return concave;
}

template <typename S>
bool Overlap(const ConcaveT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB)
{
    return OverlapSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1));
}

template <typename S>
bool Overlap(const ShapeT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b, const TransformT<S>& xfB)
{
    return OverlapSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1));
}

template <typename S>
bool Overlap(const ConcaveT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b, const TransformT<S>& xfB)
{
    return OverlapSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1));
}

template <typename S>
ConcaveManifoldT<S> Collide(const ConcaveT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                            const TransformT<S>& xfB)
{
    return CollideSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1));
}

template <typename S>
ConcaveManifoldT<S> Collide(const ShapeT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                            const TransformT<S>& xfB)
{
    return CollideSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1));
}

template <typename S>
ConcaveManifoldT<S> Collide(const ConcaveT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                            const TransformT<S>& xfB)
{
    return CollideSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1));
}

template <typename S>
ConcaveManifoldT<S> CollideWithin(const ConcaveT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                                  const TransformT<S>& xfB, S margin)
{
    return CollideWithinSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1), margin);
}

template <typename S>
ConcaveManifoldT<S> CollideWithin(const ShapeT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                                  const TransformT<S>& xfB, S margin)
{
    return CollideWithinSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1), margin);
}

template <typename S>
ConcaveManifoldT<S> CollideWithin(const ConcaveT<S>& a, const TransformT<S>& xfA, const ConcaveT<S>& b,
                                  const TransformT<S>& xfB, S margin)
{
    return CollideWithinSides(SideOf(a, xfA, 0), SideOf(b, xfB, 1), margin);
}

template <typename S>
ConcaveSweepResultT<S> Sweep(const ConcaveT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                             const TransformT<S>& xfB, Vec2T<S> vB)
{
    return SweepSides(SideOf(a, xfA, 0), vA, SideOf(b, xfB, 1), vB);
}

template <typename S>
ConcaveSweepResultT<S> Sweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ConcaveT<S>& b,
                             const TransformT<S>& xfB, Vec2T<S> vB)
{
    return SweepSides(SideOf(a, xfA, 0), vA, SideOf(b, xfB, 1), vB);
}

template <typename S>
ConcaveSweepResultT<S> Sweep(const ConcaveT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ConcaveT<S>& b,
                             const TransformT<S>& xfB, Vec2T<S> vB)
{
    return SweepSides(SideOf(a, xfA, 0), vA, SideOf(b, xfB, 1), vB);
}


#define SATVIZ_CONCAVE_INSTANTIATE(S)                                                                                  \
    template ConcaveT<S> MakeConcave(const std::vector<ConvexPieceT<S>>&);                                             \
    template bool Overlap(const ConcaveT<S>&, const TransformT<S>&, const ShapeT<S>&, const TransformT<S>&);           \
    template bool Overlap(const ShapeT<S>&, const TransformT<S>&, const ConcaveT<S>&, const TransformT<S>&);           \
    template bool Overlap(const ConcaveT<S>&, const TransformT<S>&, const ConcaveT<S>&, const TransformT<S>&);         \
    template ConcaveManifoldT<S> Collide(const ConcaveT<S>&, const TransformT<S>&, const ShapeT<S>&,                   \
                                         const TransformT<S>&);                                                        \
    template ConcaveManifoldT<S> Collide(const ShapeT<S>&, const TransformT<S>&, const ConcaveT<S>&,                   \
                                         const TransformT<S>&);                                                        \
    template ConcaveManifoldT<S> Collide(const ConcaveT<S>&, const TransformT<S>&, const ConcaveT<S>&,                 \
                                         const TransformT<S>&);                                                        \
    template ConcaveManifoldT<S> CollideWithin(const ConcaveT<S>&, const TransformT<S>&, const ShapeT<S>&,             \
                                               const TransformT<S>&, S);                                               \
    template ConcaveManifoldT<S> CollideWithin(const ShapeT<S>&, const TransformT<S>&, const ConcaveT<S>&,             \
                                               const TransformT<S>&, S);                                               \
    template ConcaveManifoldT<S> CollideWithin(const ConcaveT<S>&, const TransformT<S>&, const ConcaveT<S>&,           \
                                               const TransformT<S>&, S);                                               \
    template ConcaveSweepResultT<S> Sweep(const ConcaveT<S>&, const TransformT<S>&, Vec2T<S>, const ShapeT<S>&,        \
                                          const TransformT<S>&, Vec2T<S>);                                             \
    template ConcaveSweepResultT<S> Sweep(const ShapeT<S>&, const TransformT<S>&, Vec2T<S>, const ConcaveT<S>&,        \
                                          const TransformT<S>&, Vec2T<S>);                                             \
    template ConcaveSweepResultT<S> Sweep(const ConcaveT<S>&, const TransformT<S>&, Vec2T<S>, const ConcaveT<S>&,      \
                                          const TransformT<S>&, Vec2T<S>);

SATVIZ_CONCAVE_INSTANTIATE(double)
SATVIZ_CONCAVE_INSTANTIATE(float)

} // namespace satviz
