// SPDX-License-Identifier: MIT
// An independent reference for the SAT queries, in quadruple precision (__float128, 113-bit significand) from the
// exact double inputs, with exact rational tie-breaking. It shares no code with the library:
//   - yes/no: two convex outlines intersect iff an edge of one crosses or touches an edge of the other, or one
//     contains a vertex of the other (orientation predicates);
//   - depth and normal: the minimum over the unit edge normals of both polygons of the projection overlap
//     min(maxA - minB, maxB - minA), the interval formulation of the tutorials (for convex polygons this is the
//     penetration depth of the Minkowski difference);
//   - circles: the distance from the centre to the outline.
//
// Exact tie-breaking. The true geometry is the rational numbers the double inputs denote, each transform applied
// without rounding (support/exact.h). Every sign that decides a yes/no answer (overlap, and a sweep's hit or miss)
// is taken from the quad value where that lies farther from 0 than a rigorous bound on its error, and is computed
// exactly with floating-point expansions otherwise: touching shapes (separation exactly 0) overlap, as in the
// library, whatever the rounding of their world coordinates. Only near-ties take the exact path.
//
// The error bounds, with u = 2^-113 the unit roundoff of quad precision:
//   - QTransform forms c x and s y exactly and rounds twice (their difference, then the sum with p): a world
//     coordinate is within (2u + u^2)(|c x| + |s y| + |p|) of the exact one. TransformError takes 3u times that.
//   - A predicate on points (orientation, the dot product of an on-segment test, a sweep's offset and rate) is
//     d1 d2 -+ d3 d4, each d a coordinate difference of two points of a set whose coordinates are within E of the
//     exact ones and whose bounding box has sides of at most W. Evaluated from the rounded points, each d, each
//     product and the result round once: an error below ((1 + u)^4 - 1) 2 W^2 (1 + u)^2 < 8.01 u W^2. Rounded
//     rather than exact points move each d by at most 2E, so the value by at most 4 W 2E + 2 (2E)^2. The filter
//     (FilterBound) takes twice the total, 16 u W^2 + 16 W E + 16 E^2, which also covers the rounding of its own
//     evaluation; it is computed once per pair from the coordinate magnitudes, so the inner loops pay one comparison.
//   - The predicates of higher degree (circles, the order of a sweep's crossing times) carry a bound through each
//     operation instead (QBounded, running error analysis).
#pragma once

#include "exact.h"

#include <satviz/sat.h>

#include <algorithm>
#include <cmath>
#include <quadmath.h>
#include <utility>
#include <vector>

namespace satviz::testing
{

/// Quadruple precision: 113-bit significand, unit roundoff 2^-113.
using Quad = __float128;

/// A point in quadruple precision.
struct QVec
{
    Quad x = 0; ///< x coordinate
    Quad y = 0; ///< y coordinate
};

/// Component-wise difference.
inline QVec operator-(QVec a, QVec b)
{
    return {a.x - b.x, a.y - b.y};
}
/// Dot product.
inline Quad QDot(QVec a, QVec b)
{
    return a.x * b.x + a.y * b.y;
}
/// Cross product a.x b.y - a.y b.x.
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

/// World positions of a polygon's vertices (QTransform).
inline std::vector<QVec> QWorld(const Polygon& polygon, const Transform& xf)
{
    std::vector<QVec> out;
    for (const Vec2& v : polygon.Vertices())
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
    /// Polygons: the unit normals (from A to B) of every axis whose separation is within kTieBand of the best,
    /// the deciding one included: co-minimal axes, any of which is a right answer.
    std::vector<Vec2> ties;
};

/// Axes whose separations differ by less than this are co-minimal (Reference::ties).
constexpr double kTieBand = 1e-9;

/// The unit roundoff of quad precision, 2^-113: a rounded operation is within this fraction of its exact result.
constexpr Quad kQuadRoundoff = FLT128_EPSILON / 2;

/// A bound on the error of either coordinate of QTransform(xf, v) (see the top of the file).
inline Quad TransformError(const Transform& xf, Vec2 v)
{
    const Quad c = xf.q.c, s = xf.q.s, x = v.x, y = v.y;
    const Quad mx = fabsq(c * x) + fabsq(s * y) + fabsq(Quad(xf.p.x));
    const Quad my = fabsq(s * x) + fabsq(c * y) + fabsq(Quad(xf.p.y));
    return 3 * kQuadRoundoff * (mx > my ? mx : my);
}

/// A world point of the reference: its quad position, the bound on that position's error, and the exact inputs it
/// is the image of.
struct WorldPoint
{
    QVec q;       ///< QTransform(xf, local)
    Quad error;   ///< TransformError(xf, local)
    Vec2 local;   ///< the body-frame point
    Transform xf; ///< the body's transform
};

/// The world point of the body-frame point v.
inline WorldPoint MakeWorldPoint(const Transform& xf, Vec2 v)
{
    return {QTransform(xf, v), TransformError(xf, v), v, xf};
}

/// The world points of a polygon's vertices.
inline std::vector<WorldPoint> WorldPoints(const Polygon& polygon, const Transform& xf)
{
    std::vector<WorldPoint> out;
    out.reserve(polygon.Vertices().size());
    for (const Vec2& v : polygon.Vertices())
    {
        out.push_back(MakeWorldPoint(xf, v));
    }
    return out;
}

/// The exact position of a world point.
inline ExactPoint Exact(const WorldPoint& w)
{
    return ExactTransform(w.xf, w.local);
}

/// What the filter bound of a set of points depends on: their largest coordinate error and their bounding box.
struct PointSpread
{
    Quad error = 0;         ///< largest error of a coordinate
    Quad minX = HUGE_VALQ;  ///< bounding box of the quad positions
    Quad maxX = -HUGE_VALQ; ///< bounding box of the quad positions
    Quad minY = HUGE_VALQ;  ///< bounding box of the quad positions
    Quad maxY = -HUGE_VALQ; ///< bounding box of the quad positions
};

/// Adds a point with quad position q and coordinate error `error` to a spread.
inline void Include(PointSpread& spread, QVec q, Quad error)
{
    spread.error = error > spread.error ? error : spread.error;
    spread.minX = q.x < spread.minX ? q.x : spread.minX;
    spread.maxX = q.x > spread.maxX ? q.x : spread.maxX;
    spread.minY = q.y < spread.minY ? q.y : spread.minY;
    spread.maxY = q.y > spread.maxY ? q.y : spread.maxY;
}

/// Adds world points to a spread.
inline void Include(PointSpread& spread, const std::vector<WorldPoint>& points)
{
    for (const WorldPoint& w : points)
    {
        Include(spread, w.q, w.error);
    }
}

/// The spread of the differences p - q, p from a set of spread `a` and q from one of spread `b`, each rounded once:
/// the difference of the boxes (rounding is monotonic), and the errors of both plus that rounding.
inline PointSpread DifferenceSpread(const PointSpread& a, const PointSpread& b)
{
    PointSpread out;
    out.minX = a.minX - b.maxX;
    out.maxX = a.maxX - b.minX;
    out.minY = a.minY - b.maxY;
    out.maxY = a.maxY - b.minY;
    const Quad largest = std::max({fabsq(out.minX), fabsq(out.maxX), fabsq(out.minY), fabsq(out.maxY)});
    out.error = a.error + b.error + 2 * kQuadRoundoff * largest;
    return out;
}

/// The bound on the error of a predicate d1 d2 -+ d3 d4 over differences of the points of a spread: 16 u W^2 +
/// 16 W E + 16 E^2 (see the top of the file).
inline Quad FilterBound(const PointSpread& spread)
{
    const Quad w = std::max(spread.maxX - spread.minX, spread.maxY - spread.minY);
    const Quad e = spread.error;
    return 16 * kQuadRoundoff * w * w + 16 * w * e + 16 * e * e;
}

/// The sign (-1, 0 or +1) of an exact quantity from its quad value, within `bound` of it: the quad value's sign
/// where it lies beyond the bound, else the sign of `exact()`, the quantity as an Expansion. A bound of 0 says that
/// the quad value is exact.
template <typename ExactValue>
int FilteredSign(Quad value, Quad bound, ExactValue exact)
{
    if (value > bound)
    {
        return 1;
    }
    if (value < -bound)
    {
        return -1;
    }
    if (bound == 0)
    {
        return 0;
    }
    return ExpansionSign(exact());
}

/// Orient2d of three points (WorldPoint, or any point with a quad position q and an Exact overload): the sign of
/// Cross(b - a, c - a) of their exact positions, +1 counter-clockwise, 0 collinear; `bound` from FilterBound.
template <typename Point>
int Orient2d(const Point& a, const Point& b, const Point& c, Quad bound)
{
    return FilteredSign(QCross(b.q - a.q, c.q - a.q), bound, [&] {
        const ExactPoint ea = Exact(a);
        return ExactCross(ExactDifference(Exact(b), ea), ExactDifference(Exact(c), ea));
    });
}

/// The sign of Dot(c - a, c - b) of the exact positions: for c collinear with a and b, <= 0 iff c lies on the
/// closed segment a b.
inline int BetweenSign(const WorldPoint& a, const WorldPoint& b, const WorldPoint& c, Quad bound)
{
    return FilteredSign(QDot(c.q - a.q, c.q - b.q), bound, [&] {
        const ExactPoint ec = Exact(c);
        return ExactDot(ExactDifference(ec, Exact(a)), ExactDifference(ec, Exact(b)));
    });
}

/// The closed segments p1 p2 and q1 q2 meet (touching counts): the textbook test (Cormen et al.) on exact
/// orientations.
inline bool SegmentsIntersect(const WorldPoint& p1, const WorldPoint& p2, const WorldPoint& q1, const WorldPoint& q2,
                              Quad bound)
{
    const int d1 = Orient2d(q1, q2, p1, bound);
    const int d2 = Orient2d(q1, q2, p2, bound);
    if (d1 * d2 > 0)
    {
        return false; // p1 p2 strictly on one side of the line through q1 q2
    }
    const int d3 = Orient2d(p1, p2, q1, bound);
    const int d4 = Orient2d(p1, p2, q2, bound);
    if (d1 * d2 < 0 && d3 * d4 < 0)
    {
        return true;
    }
    auto onSegment = [bound](const WorldPoint& a, const WorldPoint& b, const WorldPoint& p) {
        return BetweenSign(a, b, p, bound) <= 0;
    };
    return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2)) ||
           (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
}

/// Point inside or on a counter-clockwise convex outline, exactly.
inline bool ContainsPoint(const std::vector<WorldPoint>& outline, const WorldPoint& p, Quad bound)
{
    const size_t n = outline.size();
    for (size_t i = 0; i < n; ++i)
    {
        if (Orient2d(outline[i], outline[(i + 1) % n], p, bound) < 0)
        {
            return false;
        }
    }
    return true;
}

/// Point inside or on a counter-clockwise convex outline, by the signs of quad values: for SignedDistance, whose
/// sign near 0 is rounding anyway. The yes/no answers use the exact overload above.
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
        const Vec2 v1 = TransformPoint(xf, polygon.Vertices()[k]);
        const Vec2 v2 = TransformPoint(xf, polygon.Vertices()[(k + 1) % polygon.Count()]);
        const long double ex = static_cast<long double>(v2.x) - v1.x;
        const long double ey = static_cast<long double>(v2.y) - v1.y;
        const long double cross =
            ex * (static_cast<long double>(point.y) - v1.y) - ey * (static_cast<long double>(point.x) - v1.x);
        worst = std::max(worst, -cross / std::sqrt(ex * ex + ey * ey));
    }
    return worst;
}

/// Yes/no by edge crossings and containment, every sign filtered by `bound`: FilterBound of both outlines, or
/// HUGE_VALQ to decide every sign with expansions.
inline bool ReferenceOverlap(const std::vector<WorldPoint>& a, const std::vector<WorldPoint>& b, Quad bound)
{
    for (size_t i = 0; i < a.size(); ++i)
    {
        for (size_t j = 0; j < b.size(); ++j)
        {
            if (SegmentsIntersect(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()], bound))
            {
                return true;
            }
        }
    }
    return ContainsPoint(a, b[0], bound) || ContainsPoint(b, a[0], bound);
}

/// Yes/no for two counter-clockwise convex outlines, exact.
inline bool ReferenceOverlap(const std::vector<WorldPoint>& a, const std::vector<WorldPoint>& b)
{
    PointSpread spread;
    Include(spread, a);
    Include(spread, b);
    return ReferenceOverlap(a, b, FilterBound(spread));
}

/// A quad value and a bound on its distance from the exact value it stands for, carried through each operation
/// (running error analysis): for the predicates of degree 4.
struct QBounded
{
    Quad value = 0; ///< the quad value
    Quad error = 0; ///< |value - exact| <= error
};

/// The bounded value of a world coordinate.
inline QBounded Bounded(Quad value, Quad error)
{
    return {value, error};
}

/// Sum: the errors add, plus the rounding (at most u |exact| <= 2u |value|).
inline QBounded operator+(QBounded a, QBounded b)
{
    const Quad v = a.value + b.value;
    return {v, a.error + b.error + 2 * kQuadRoundoff * fabsq(v)};
}

/// Difference, as the sum.
inline QBounded operator-(QBounded a, QBounded b)
{
    const Quad v = a.value - b.value;
    return {v, a.error + b.error + 2 * kQuadRoundoff * fabsq(v)};
}

/// Product: |a b - a* b*| <= |a| e_b + |b| e_a + e_a e_b, plus the rounding.
inline QBounded operator*(QBounded a, QBounded b)
{
    const Quad v = a.value * b.value;
    return {v, fabsq(a.value) * b.error + fabsq(b.value) * a.error + a.error * b.error + 2 * kQuadRoundoff * fabsq(v)};
}

/// The sign of an exact quantity from its bounded quad value; twice the carried bound covers the rounding of the
/// bound's own evaluation.
template <typename ExactValue>
int FilteredSign(QBounded value, ExactValue exact)
{
    return FilteredSign(value.value, 2 * value.error, exact);
}

/// A vector of bounded coordinates.
struct QBoundedVec
{
    QBounded x; ///< x coordinate
    QBounded y; ///< y coordinate
};

/// b - a for two world points, bounded.
inline QBoundedVec BoundedDifference(const WorldPoint& b, const WorldPoint& a)
{
    return {Bounded(b.q.x, b.error) - Bounded(a.q.x, a.error), Bounded(b.q.y, b.error) - Bounded(a.q.y, a.error)};
}

/// Dot product, bounded.
inline QBounded BoundedDot(const QBoundedVec& u, const QBoundedVec& v)
{
    return u.x * v.x + u.y * v.y;
}

/// Cross product, bounded.
inline QBounded BoundedCross(const QBoundedVec& u, const QBoundedVec& v)
{
    return u.x * v.y - u.y * v.x;
}

/// Two closed discs meet, exactly: |cb - ca|^2 <= (ra + rb)^2.
inline bool CirclesOverlap(const WorldPoint& ca, double ra, const WorldPoint& cb, double rb)
{
    const QBoundedVec d = BoundedDifference(cb, ca);
    const QBounded r = Bounded(ra, 0) + Bounded(rb, 0);
    const int sign = FilteredSign(BoundedDot(d, d) - r * r, [&] {
        const ExactPoint e = ExactDifference(Exact(cb), Exact(ca));
        const Expansion sum = ExpansionSum(MakeExpansion(ra), MakeExpansion(rb));
        return ExpansionDifference(ExactDot(e, e), ExpansionProduct(sum, sum));
    });
    return sign <= 0;
}

/// A closed convex polygon (counter-clockwise outline) and a closed disc meet, exactly: the centre is inside, or
/// within the radius of a vertex, or of the inside of an edge (it projects strictly inside the edge and
/// Cross(e, p - a)^2 <= r^2 |e|^2).
inline bool PolygonCircleOverlap(const std::vector<WorldPoint>& outline, const WorldPoint& center, double radius)
{
    PointSpread spread;
    Include(spread, outline);
    Include(spread, center.q, center.error);
    if (ContainsPoint(outline, center, FilterBound(spread)))
    {
        return true;
    }
    const QBounded r2 = Bounded(Quad(radius) * Quad(radius), 0); // exact: a product of two doubles
    auto exactR2 = [radius] { return MakeExpansion(TwoProduct(radius, radius)); };
    for (const WorldPoint& a : outline)
    {
        const QBoundedVec d = BoundedDifference(center, a);
        const int sign = FilteredSign(BoundedDot(d, d) - r2, [&] {
            const ExactPoint e = ExactDifference(Exact(center), Exact(a));
            return ExpansionDifference(ExactDot(e, e), exactR2());
        });
        if (sign <= 0)
        {
            return true;
        }
    }
    const size_t n = outline.size();
    for (size_t i = 0; i < n; ++i)
    {
        const WorldPoint& a = outline[i];
        const WorldPoint& b = outline[(i + 1) % n];
        const QBoundedVec e = BoundedDifference(b, a);
        const QBoundedVec pa = BoundedDifference(center, a);
        const QBoundedVec pb = BoundedDifference(center, b);
        auto exactEdge = [&] { return ExactDifference(Exact(b), Exact(a)); };
        if (FilteredSign(BoundedDot(pa, e),
                         [&] { return ExactDot(ExactDifference(Exact(center), Exact(a)), exactEdge()); }) <= 0 ||
            FilteredSign(BoundedDot(pb, e),
                         [&] { return ExactDot(ExactDifference(Exact(center), Exact(b)), exactEdge()); }) >= 0)
        {
            continue; // the nearest point of the edge is a vertex
        }
        const QBounded cross = BoundedCross(e, pa);
        const int sign = FilteredSign(cross * cross - r2 * BoundedDot(e, e), [&] {
            const ExactPoint edge = exactEdge();
            const Expansion c = ExactCross(edge, ExactDifference(Exact(center), Exact(a)));
            return ExpansionDifference(ExpansionProduct(c, c), ExpansionProduct(exactR2(), ExactDot(edge, edge)));
        });
        if (sign <= 0)
        {
            return true;
        }
    }
    return false;
}

/// Separation by projection intervals on every unit edge normal of both polygons.
inline void ReferenceDepth(const std::vector<QVec>& a, const std::vector<QVec>& b, Reference& out)
{
    std::vector<std::pair<Quad, Vec2>> candidates;
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
            const double sign = forward > backward ? 1.0 : -1.0;
            const Vec2 normal{sign * static_cast<double>(axis.x), sign * static_cast<double>(axis.y)};
            candidates.push_back({separation, normal});
            if (first || separation > best)
            {
                first = false;
                best = separation;
                out.normalX = normal.x;
                out.normalY = normal.y;
            }
        }
    }
    out.separation = best;
    out.ties.clear();
    for (const auto& [separation, normal] : candidates)
    {
        if (best - separation < kTieBand)
        {
            out.ties.push_back(normal);
        }
    }
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
        out.overlap = ReferenceOverlap(WorldPoints(a.polygon, xfA), WorldPoints(b.polygon, xfB));
        ReferenceDepth(QWorld(a.polygon, xfA), QWorld(b.polygon, xfB), out);
        return out;
    }
    if (a.type == ShapeType::Circle && b.type == ShapeType::Circle)
    {
        const QVec ca = QTransform(xfA, a.circle.center);
        const QVec cb = QTransform(xfB, b.circle.center);
        const QVec d = cb - ca;
        const Quad distance = sqrtq(QDot(d, d));
        out.separation = distance - Quad(a.circle.radius) - Quad(b.circle.radius);
        out.overlap = CirclesOverlap(MakeWorldPoint(xfA, a.circle.center), a.circle.radius,
                                     MakeWorldPoint(xfB, b.circle.center), b.circle.radius);
        out.normalX = static_cast<double>(d.x / distance);
        out.normalY = static_cast<double>(d.y / distance);
        return out;
    }
    const bool polygonFirst = a.type == ShapeType::Polygon;
    const Polygon& polygon = polygonFirst ? a.polygon : b.polygon;
    const Circle& circle = polygonFirst ? b.circle : a.circle;
    const Transform& xfPolygon = polygonFirst ? xfA : xfB;
    const Transform& xfCircle = polygonFirst ? xfB : xfA;
    out.separation =
        SignedDistance(QWorld(polygon, xfPolygon), QTransform(xfCircle, circle.center)) - Quad(circle.radius);
    out.overlap =
        PolygonCircleOverlap(WorldPoints(polygon, xfPolygon), MakeWorldPoint(xfCircle, circle.center), circle.radius);
    return out;
}

/// The reference for a sweep of two translating polygons: B moves by v relative to A. B(t) meets A exactly when
/// t v lies in the Minkowski difference A - B, built here as the convex hull of every vertex difference (Andrew's
/// monotone chain), and the ray t v is clipped against its faces (Cyrus-Beck). The order of the points, the hull's
/// turns, the signs of each face's offset and rate, the order of the crossing times and their comparison with 0 and
/// 1 are exact (filtered as above): insideAtStart and crosses, and enter <= 1 and leave > 0, are the exact answers.
/// enter and leave are quad times, moved by no more than their error where that puts them on the exact side of 0,
/// of 1 and of each other.
struct SweepReference
{
    bool insideAtStart = false; ///< the origin is strictly inside A - B: interpenetrating at t = 0
    Quad enter = 0;             ///< first time t v is in A - B (may be negative: already inside)
    Quad leave = 0;             ///< last time
    bool crosses = false;       ///< the ray meets A - B with enter < leave (not only tangent)
    Quad startSeparation = 0;   ///< signed distance of the origin from A - B at t = 0 (< 0: inside)
};

/// A point of the Minkowski difference A - B: a vertex of A minus a vertex of B.
struct MinkowskiPoint
{
    QVec q;                            ///< from->q - minus->q, rounded
    const WorldPoint* from = nullptr;  ///< the vertex of A
    const WorldPoint* minus = nullptr; ///< the vertex of B
};

/// The exact position of a point of the Minkowski difference.
inline ExactPoint Exact(const MinkowskiPoint& m)
{
    return ExactDifference(Exact(*m.from), Exact(*m.minus));
}

/// A face of the Minkowski difference for the sweep: with e the face's edge vector and h its first vertex,
/// offset = Cross(e, h) (< 0 where the origin is inside the face's half-plane) and rate = Cross(v, e) (the outward
/// normal (e.y, -e.x) dotted with v). The ray t v crosses the face's line at t = -offset / rate.
struct SweepFace
{
    Quad offset = 0;    ///< quad value, within the filter bound of the exact one
    Quad rate = 0;      ///< quad value, within the filter bound of the exact one
    int offsetSign = 0; ///< exact sign of offset
    int rateSign = 0;   ///< exact sign of rate: < 0 the ray enters the half-plane, > 0 it leaves
};

/// t moved onto `to` or just past it to the side `sign` gives (the exact sign of t - to), when it is not there.
inline Quad Snapped(Quad t, Quad to, int sign)
{
    if (sign == 0)
    {
        return to;
    }
    if (sign < 0 && t >= to)
    {
        return nextafterq(to, -HUGE_VALQ);
    }
    if (sign > 0 && t <= to)
    {
        return nextafterq(to, HUGE_VALQ);
    }
    return t;
}

/// The reference for the sweep of polygon B (at xfB, moving by `velocity`) against polygon A (at xfA, still).
inline SweepReference ReferenceSweep(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                                     Vec2 velocity)
{
    const std::vector<WorldPoint> worldA = WorldPoints(a, xfA);
    const std::vector<WorldPoint> worldB = WorldPoints(b, xfB);
    const QVec v{velocity.x, velocity.y};
    std::vector<MinkowskiPoint> points;
    points.reserve(worldA.size() * worldB.size());
    for (const WorldPoint& p : worldA)
    {
        for (const WorldPoint& q : worldB)
        {
            points.push_back({p.q - q.q, &p, &q});
        }
    }
    // Every predicate below is a product difference of coordinate differences of the vertex differences, the
    // origin and v.
    PointSpread spreadA, spreadB;
    Include(spreadA, worldA);
    Include(spreadB, worldB);
    PointSpread spread = DifferenceSpread(spreadA, spreadB);
    Include(spread, QVec{}, 0);
    Include(spread, v, 0);
    const Quad bound = FilterBound(spread);
    // Sorted by the quad coordinates, then by the exact ones: two coordinates are each within E of the exact ones,
    // so a rounded difference beyond 4E has the exact sign, and only near-ties move in the insertion sort.
    std::sort(points.begin(), points.end(), [](const MinkowskiPoint& l, const MinkowskiPoint& r) {
        return l.q.x < r.q.x || (l.q.x == r.q.x && l.q.y < r.q.y);
    });
    const Quad coordinateBound = 4 * spread.error;
    auto before = [coordinateBound](const MinkowskiPoint& l, const MinkowskiPoint& r) {
        const int x =
            FilteredSign(l.q.x - r.q.x, coordinateBound, [&] { return ExpansionDifference(Exact(l).x, Exact(r).x); });
        if (x != 0)
        {
            return x < 0;
        }
        return FilteredSign(l.q.y - r.q.y, coordinateBound,
                            [&] { return ExpansionDifference(Exact(l).y, Exact(r).y); }) < 0;
    };
    for (size_t i = 1; i < points.size(); ++i)
    {
        for (size_t j = i; j > 0 && before(points[j], points[j - 1]); --j)
        {
            std::swap(points[j], points[j - 1]);
        }
    }
    std::vector<MinkowskiPoint> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i)
    {
        while (k >= 2 && Orient2d(hull[k - 2], hull[k - 1], points[i], bound) <= 0)
        {
            --k;
        }
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && Orient2d(hull[k - 2], hull[k - 1], points[i], bound) <= 0)
        {
            --k;
        }
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    const size_t h = hull.size();

    const ExactPoint exactV = MakeExactPoint(velocity);
    auto exactEdge = [&hull, h](size_t i) { return ExactDifference(Exact(hull[(i + 1) % h]), Exact(hull[i])); };
    auto exactOffset = [&](size_t i) { return ExactCross(exactEdge(i), Exact(hull[i])); };
    auto exactRate = [&](size_t i) { return ExactCross(exactV, exactEdge(i)); };
    std::vector<SweepFace> faces(h);
    // The sign of t_f - t_g, t = -offset / rate: that of (offset_g rate_f - offset_f rate_g) / (rate_f rate_g).
    auto timeOrder = [&](size_t f, size_t g) {
        const QBounded offsetF = Bounded(faces[f].offset, bound), rateF = Bounded(faces[f].rate, bound);
        const QBounded offsetG = Bounded(faces[g].offset, bound), rateG = Bounded(faces[g].rate, bound);
        const int sign = FilteredSign(offsetG * rateF - offsetF * rateG, [&] {
            return ExpansionDifference(ExpansionProduct(exactOffset(g), exactRate(f)),
                                       ExpansionProduct(exactOffset(f), exactRate(g)));
        });
        return sign * faces[f].rateSign * faces[g].rateSign;
    };

    SweepReference out;
    out.insideAtStart = true;
    bool parallelOutside = false;
    size_t enterFace = h; // the entering face crossed last, h when none
    size_t leaveFace = h; // the leaving face crossed first
    for (size_t i = 0; i < h; ++i)
    {
        const QVec e = hull[(i + 1) % h].q - hull[i].q;
        SweepFace& face = faces[i];
        face.offset = QCross(e, hull[i].q);
        face.rate = QCross(v, e);
        face.offsetSign = FilteredSign(face.offset, bound, [&] { return exactOffset(i); });
        face.rateSign = FilteredSign(face.rate, bound, [&] { return exactRate(i); });
        out.insideAtStart = out.insideAtStart && face.offsetSign < 0;
        const Quad distance = face.offset / sqrtq(QDot(e, e));
        out.startSeparation = i == 0 || distance > out.startSeparation ? distance : out.startSeparation;
        if (face.rateSign == 0)
        {
            // Parallel: outside (or on) the face's line, never strictly inside.
            parallelOutside = parallelOutside || face.offsetSign >= 0;
        }
        else if (face.rateSign < 0)
        {
            enterFace = enterFace == h || timeOrder(i, enterFace) > 0 ? i : enterFace;
        }
        else
        {
            leaveFace = leaveFace == h || timeOrder(i, leaveFace) < 0 ? i : leaveFace;
        }
    }
    auto time = [&faces](size_t i) { return faces[i].offsetSign == 0 ? Quad(0) : -faces[i].offset / faces[i].rate; };
    out.enter = -1e300Q;
    out.leave = 1e300Q;
    if (enterFace < h)
    {
        // t - 1 has the sign of offset + rate = Cross(e, h - v), rate being negative.
        const QVec e = hull[(enterFace + 1) % h].q - hull[enterFace].q;
        const int beyondOne = FilteredSign(QCross(e, hull[enterFace].q - v), bound, [&] {
            return ExactCross(exactEdge(enterFace), ExactDifference(Exact(hull[enterFace]), exactV));
        });
        out.enter = Snapped(Snapped(time(enterFace), 0, faces[enterFace].offsetSign), 1, beyondOne);
    }
    if (leaveFace < h)
    {
        out.leave = Snapped(time(leaveFace), 0, -faces[leaveFace].offsetSign);
    }
    const int order = enterFace < h && leaveFace < h ? timeOrder(enterFace, leaveFace) : -1;
    if (order == 0)
    {
        out.leave = out.enter;
    }
    else if (order < 0 && out.enter >= out.leave)
    {
        out.leave = nextafterq(out.enter, HUGE_VALQ);
    }
    if (parallelOutside)
    {
        out.enter = 1e300Q;
    }
    out.crosses = !parallelOutside && order < 0;
    return out;
}

} // namespace satviz::testing
