// SPDX-License-Identifier: MIT
// An independent reference for the SAT queries, in quadruple precision (__float128, 113-bit significand) from the
// exact double inputs. It shares no code with the library:
//   - yes/no: two convex outlines intersect iff an edge of one crosses or touches an edge of the other, or one
//     contains a vertex of the other (orientation predicates);
//   - depth and normal: the minimum over the unit edge normals of both polygons of the projection overlap
//     min(maxA - minB, maxB - minA), the interval formulation of the tutorials (for convex polygons this is the
//     penetration depth of the Minkowski difference);
//   - circles: the distance from the centre to the outline.
#pragma once

#include <satviz/sat.h>

#include <algorithm>
#include <cmath>
#include <quadmath.h>
#include <vector>

namespace satviz::testing
{

using Quad = __float128;

/// A point in quadruple precision.
struct QVec
{
    Quad x = 0;
    Quad y = 0;
};

inline QVec operator-(QVec a, QVec b)
{
    return {a.x - b.x, a.y - b.y};
}
inline Quad QDot(QVec a, QVec b)
{
    return a.x * b.x + a.y * b.y;
}
inline Quad QCross(QVec a, QVec b)
{
    return a.x * b.y - a.y * b.x;
}

/// World position of a body-frame point: the products of two doubles are exact in quad precision.
inline QVec QTransform(const Transform& xf, Vec2 v)
{
    const Quad c = xf.q.c, s = xf.q.s, x = v.x, y = v.y;
    return {c * x - s * y + Quad(xf.p.x), s * x + c * y + Quad(xf.p.y)};
}

inline std::vector<QVec> QWorld(const Polygon& polygon, const Transform& xf)
{
    std::vector<QVec> out;
    for (const Vec2& v : polygon.vertices)
    {
        out.push_back(QTransform(xf, v));
    }
    return out;
}

/// The reference answer for a pair.
struct Reference
{
    bool overlap = false; ///< closed shapes intersect
    /// Signed separation: > 0 the gap on the best separating axis (polygons) or the distance (circles); <= 0 minus
    /// the penetration depth.
    Quad separation = 0;
    double normalX = 0, normalY = 0; ///< unit normal from A to B on the deciding axis
};

inline int Sign(Quad v)
{
    return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

inline bool SegmentsIntersect(QVec p1, QVec p2, QVec q1, QVec q2)
{
    const int d1 = Sign(QCross(q2 - q1, p1 - q1));
    const int d2 = Sign(QCross(q2 - q1, p2 - q1));
    const int d3 = Sign(QCross(p2 - p1, q1 - p1));
    const int d4 = Sign(QCross(p2 - p1, q2 - p1));
    if (d1 * d2 < 0 && d3 * d4 < 0)
    {
        return true;
    }
    auto onSegment = [](QVec a, QVec b, QVec p) { return QCross(b - a, p - a) == 0 && QDot(p - a, p - b) <= 0; };
    return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2)) ||
           (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
}

/// Point inside or on a counter-clockwise convex outline.
inline bool ContainsPoint(const std::vector<QVec>& outline, QVec p)
{
    const size_t n = outline.size();
    for (size_t i = 0; i < n; ++i)
    {
        if (QCross(outline[(i + 1) % n] - outline[i], p - outline[i]) < 0)
        {
            return false;
        }
    }
    return true;
}

/// How far `point` lies outside a polygon (vertices mapped by `xf` in double, as the library maps them): the
/// largest signed distance from the lines of its edges, in long double; <= 0 inside. Cheaper than SignedDistance
/// (no quadruple-precision square root) where only the sign and a band around 0 matter.
inline long double DepthOutside(const Polygon& polygon, const Transform& xf, Vec2 point)
{
    long double worst = -1e300L;
    for (int k = 0; k < polygon.Count(); ++k)
    {
        const Vec2 v1 = TransformPoint(xf, polygon.vertices[k]);
        const Vec2 v2 = TransformPoint(xf, polygon.vertices[(k + 1) % polygon.Count()]);
        const long double ex = static_cast<long double>(v2.x) - v1.x;
        const long double ey = static_cast<long double>(v2.y) - v1.y;
        const long double cross =
            ex * (static_cast<long double>(point.y) - v1.y) - ey * (static_cast<long double>(point.x) - v1.x);
        worst = std::max(worst, -cross / std::sqrt(ex * ex + ey * ey));
    }
    return worst;
}

/// Yes/no by edge crossings and containment.
inline bool ReferenceOverlap(const std::vector<QVec>& a, const std::vector<QVec>& b)
{
    for (size_t i = 0; i < a.size(); ++i)
    {
        for (size_t j = 0; j < b.size(); ++j)
        {
            if (SegmentsIntersect(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]))
            {
                return true;
            }
        }
    }
    return ContainsPoint(a, b[0]) || ContainsPoint(b, a[0]);
}

/// Separation by projection intervals on every unit edge normal of both polygons.
inline void ReferenceDepth(const std::vector<QVec>& a, const std::vector<QVec>& b, Reference& out)
{
    Quad best = -1e300Q;
    bool first = true;
    for (int side = 0; side < 2; ++side)
    {
        const std::vector<QVec>& owner = side == 0 ? a : b;
        for (size_t i = 0; i < owner.size(); ++i)
        {
            const QVec e = owner[(i + 1) % owner.size()] - owner[i];
            const Quad length = sqrtq(QDot(e, e));
            const QVec axis{e.y / length, -e.x / length};
            Quad minA = 1e300Q, maxA = -1e300Q, minB = 1e300Q, maxB = -1e300Q;
            for (const QVec& v : a)
            {
                const Quad d = QDot(axis, v);
                minA = d < minA ? d : minA;
                maxA = d > maxA ? d : maxA;
            }
            for (const QVec& v : b)
            {
                const Quad d = QDot(axis, v);
                minB = d < minB ? d : minB;
                maxB = d > maxB ? d : maxB;
            }
            // Moving B along +axis by (maxA - minB), or along -axis by (maxB - minA), separates on this axis.
            const Quad forward = minB - maxA;
            const Quad backward = minA - maxB;
            const Quad separation = forward > backward ? forward : backward;
            if (first || separation > best)
            {
                first = false;
                best = separation;
                const double sign = forward > backward ? 1.0 : -1.0;
                out.normalX = sign * static_cast<double>(axis.x);
                out.normalY = sign * static_cast<double>(axis.y);
            }
        }
    }
    out.separation = best;
}

/// Distance from a point to a segment.
inline Quad SegmentDistance(QVec p, QVec a, QVec b)
{
    const QVec ab = b - a;
    Quad t = QDot(p - a, ab) / QDot(ab, ab);
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const QVec closest{a.x + t * ab.x, a.y + t * ab.y};
    const QVec d = p - closest;
    return sqrtq(QDot(d, d));
}

/// Signed distance from a point to a convex outline: negative inside.
inline Quad SignedDistance(const std::vector<QVec>& outline, QVec p)
{
    Quad distance = 1e300Q;
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const Quad d = SegmentDistance(p, outline[i], outline[(i + 1) % outline.size()]);
        distance = d < distance ? d : distance;
    }
    return ContainsPoint(outline, p) ? -distance : distance;
}

/// The reference for any pair of shapes.
inline Reference ReferenceCollide(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB)
{
    Reference out;
    if (a.type == ShapeType::Polygon && b.type == ShapeType::Polygon)
    {
        const std::vector<QVec> wa = QWorld(a.polygon, xfA);
        const std::vector<QVec> wb = QWorld(b.polygon, xfB);
        out.overlap = ReferenceOverlap(wa, wb);
        ReferenceDepth(wa, wb, out);
        return out;
    }
    if (a.type == ShapeType::Circle && b.type == ShapeType::Circle)
    {
        const QVec ca = QTransform(xfA, a.circle.center);
        const QVec cb = QTransform(xfB, b.circle.center);
        const QVec d = cb - ca;
        const Quad distance = sqrtq(QDot(d, d));
        out.separation = distance - Quad(a.circle.radius) - Quad(b.circle.radius);
        out.overlap = out.separation <= 0;
        out.normalX = static_cast<double>(d.x / distance);
        out.normalY = static_cast<double>(d.y / distance);
        return out;
    }
    const bool polygonFirst = a.type == ShapeType::Polygon;
    const Polygon& polygon = polygonFirst ? a.polygon : b.polygon;
    const Circle& circle = polygonFirst ? b.circle : a.circle;
    const std::vector<QVec> outline = QWorld(polygon, polygonFirst ? xfA : xfB);
    const QVec center = QTransform(polygonFirst ? xfB : xfA, circle.center);
    out.separation = SignedDistance(outline, center) - Quad(circle.radius);
    out.overlap = out.separation <= 0;
    return out;
}

/// The reference for a sweep of two translating polygons: B moves by v relative to A. B(t) meets A exactly when
/// t v lies in the Minkowski difference A - B, built here as the convex hull of every vertex difference (Andrew's
/// monotone chain, quad precision), and the ray t v is clipped against its faces (Cyrus-Beck).
struct SweepReference
{
    bool insideAtStart = false; ///< the origin is strictly inside A - B: interpenetrating at t = 0
    Quad enter = 0;             ///< first time t v is in A - B (may be negative: already inside)
    Quad leave = 0;             ///< last time
    bool crosses = false;       ///< the ray meets A - B with enter < leave (not only tangent)
    Quad startSeparation = 0;   ///< signed distance of the origin from A - B at t = 0 (< 0: inside)
};

inline SweepReference ReferenceSweep(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                                     Vec2 velocity)
{
    std::vector<QVec> points;
    for (const QVec& p : QWorld(a, xfA))
    {
        for (const QVec& q : QWorld(b, xfB))
        {
            points.push_back(p - q);
        }
    }
    std::sort(points.begin(), points.end(), [](QVec l, QVec r) { return l.x < r.x || (l.x == r.x && l.y < r.y); });
    std::vector<QVec> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i)
    {
        while (k >= 2 && QCross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0)
        {
            --k;
        }
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && QCross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0)
        {
            --k;
        }
        hull[k++] = points[i];
    }
    hull.resize(k - 1);

    SweepReference out;
    out.enter = -1e300Q;
    out.leave = 1e300Q;
    out.insideAtStart = true;
    const QVec v{velocity.x, velocity.y};
    for (size_t i = 0; i < hull.size(); ++i)
    {
        const QVec e = hull[(i + 1) % hull.size()] - hull[i];
        const QVec n{e.y, -e.x}; // outward for a counter-clockwise hull
        // Inside this face's half-plane while Dot(n, t v - q) <= 0.
        const Quad offset = -QDot(n, hull[i]);
        const Quad rate = QDot(n, v);
        out.insideAtStart = out.insideAtStart && offset < 0;
        const Quad distance = offset / sqrtq(QDot(n, n));
        out.startSeparation = i == 0 || distance > out.startSeparation ? distance : out.startSeparation;
        if (rate == 0)
        {
            if (offset >= 0)
            {
                out.enter = 1e300Q; // parallel and outside (or on) the face: never strictly inside
            }
            continue;
        }
        const Quad t = -offset / rate;
        if (rate < 0)
        {
            out.enter = t > out.enter ? t : out.enter;
        }
        else
        {
            out.leave = t < out.leave ? t : out.leave;
        }
    }
    out.crosses = out.enter < out.leave;
    return out;
}

} // namespace satviz::testing
