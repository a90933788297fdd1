// SPDX-License-Identifier: MIT
// Numerical stress tests, for both precisions: shapes far from the origin, tiny and huge shapes, slivers,
// near-parallel edges, tiny gaps, nearly collinear vertices, repeated moves to contact. Each case states the bound
// it holds and asserts it against the quadruple-precision reference, computed on the exact inputs the queries see
// (for float: the shapes, transforms, velocities and segments rounded to float). Overlap and Collide are scored in
// every case; Sweep and RayCast as well far from the origin, for tiny and huge shapes and for slivers. No pair is
// dropped silently: an outline that does not survive rounding to a precision is counted, and each case states
// whether that may happen and with which error.
#include "support/random_shapes.h"
#include "support/reference.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// What each precision promises, relative to the size of the shapes.
template <typename S>
struct Bounds;

template <>
struct Bounds<double>
{
    static constexpr double kBand = 1e-12;     ///< yes/no answers are exact outside this band
    static constexpr double kClose = 1e-9;     ///< pairs outside the band but this close to touching are close calls
    static constexpr double kDepth = 1e-14;    ///< penetration depth error (and gap overstatement)
    static constexpr double kToi = 5e-14;      ///< time of impact error along the path, of the size plus the path
    static constexpr double kFraction = 5e-15; ///< cast error across the face entered, of the size plus the segment
    /// The smallest push of a vertex off its neighbours' line (in units of the edge) of the levels tried that
    /// survives construction in this precision; the smaller levels are rejected as collinear.
    static constexpr double kKeptPush = 1e-15;
    /// How far a MoveAndSlide step may end inside the skin it keeps from a surface it meets, in skins.
    static constexpr double kDip = 1e-6;
    static constexpr const char* kName = "double";
};

template <>
struct Bounds<float>
{
    static constexpr double kBand = 1e-5;
    static constexpr double kClose = 1e-4;
    static constexpr double kDepth = 1e-5;
    static constexpr double kToi = 1e-5;
    static constexpr double kFraction = 5e-6;
    static constexpr double kKeptPush = 1e-6;
    static constexpr double kDip = 0.125;
    static constexpr const char* kName = "float";
};

/// Worst errors seen over a set of pairs.
struct Tally
{
    int attempts = 0; ///< pairs tried: each is scored or counted as not built, none dropped
    int pairs = 0;
    int wrong = 0;         ///< wrong yes/no answers outside the band
    int inBand = 0;        ///< pairs within the band (either answer accepted)
    int nearMisses = 0;    ///< pairs apart by more than the band but less than kClose
    int nearHits = 0;      ///< pairs overlapping by more than the band but less than kClose
    double depthError = 0; ///< worst |depth error| / scale, and worst gap beyond the reference separation
    int collinear = 0;     ///< pairs not built: a polygon rounded to this precision has a collinear vertex
    int malformed = 0;     ///< pairs not built for any other reason
};

/// Worst errors of the swept test over a set of moving pairs.
struct SweepTally
{
    int pairs = 0;
    int wrong = 0;  ///< wrong status outside the band
    int inBand = 0; ///< touching at the start, grazing or reaching at t = 1, within the band
    int hits = 0;   ///< reference outcomes of the pairs outside the band
    int misses = 0;
    int overlapping = 0;
    double toiError = 0; ///< worst |toi error| |v| / (scale + |v|): as a distance along the path
};

/// Worst errors of segment casts.
struct RayTally
{
    int rays = 0;
    int wrong = 0;  ///< wrong hit or starts-inside answers outside the band
    int inBand = 0; ///< starting on the surface, grazing or ending on it, within the band
    int hits = 0;   ///< reference outcomes of the segments outside the band
    int misses = 0;
    int inside = 0;
    double fractionError = 0; ///< worst |fraction error| |Dot(n, p2 - p1)| / (scale + |p2 - p1|), n the face entered
};

/// A pair rounded to precision S, with the double view of exactly those values for the reference.
template <typename S>
struct Rounded
{
    ShapeT<S> a, b;
    TransformT<S> xfA, xfB;
    Shape da, db; ///< the same shapes, widened back to double (exact)
    Transform dxfA, dxfB;
    PolygonError error = PolygonError::None; ///< why a polygon did not survive rounding, if one did not
};

/// x rounded to precision S. The rounding goes through a volatile, which the optimiser cannot see through: GCC 12's
/// SLP vectoriser (-O2 and up) drops the rounding of a vector's two coordinates converted to float and back to
/// double, which would hand the reference other values than the queries see.
template <typename S>
S Narrow(double x)
{
    volatile S rounded = static_cast<S>(x);
    return rounded;
}

template <typename S>
Vec2T<S> Narrow(Vec2 v)
{
    return {Narrow<S>(v.x), Narrow<S>(v.y)};
}

/// A validated polygon: the builders must accept the outline.
template <typename S>
PolygonT<S> Built(PolygonResultT<S> result)
{
    INFO(DescribePolygonError(result.error, result.vertex));
    REQUIRE(result.Ok());
    return std::move(result.polygon);
}

template <typename S>
PolygonError Round(const Shape& in, ShapeT<S>& out, Shape& back)
{
    if (in.type == ShapeType::Circle)
    {
        out = MakeShape(CircleT<S>{Narrow<S>(in.circle.center), Narrow<S>(in.circle.radius)});
        back = MakeShape(Circle{ConvertVec<double>(out.circle.center), static_cast<double>(out.circle.radius)});
        return PolygonError::None;
    }
    PolygonResultT<S> polygon = ConvertPolygon<S>(in.polygon);
    if (!polygon.Ok())
    {
        return polygon.error;
    }
    PolygonResult widened = ConvertPolygon<double>(polygon.polygon);
    if (!widened.Ok())
    {
        return widened.error;
    }
    out = MakeShape(std::move(polygon.polygon));
    back = MakeShape(std::move(widened.polygon));
    return PolygonError::None;
}

template <typename S>
TransformT<S> RoundTransform(const Transform& xf)
{
    return {Narrow<S>(xf.p), {Narrow<S>(xf.q.c), Narrow<S>(xf.q.s)}};
}

template <typename S>
Transform Widen(const TransformT<S>& xf)
{
    return {ConvertVec<double>(xf.p), {static_cast<double>(xf.q.c), static_cast<double>(xf.q.s)}};
}

/// A vector rounded to precision S and widened back: the value the queries of precision S see.
template <typename S>
Vec2 Seen(Vec2 v)
{
    return ConvertVec<double>(Narrow<S>(v));
}

template <typename S>
Rounded<S> RoundPair(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB)
{
    Rounded<S> r;
    r.error = Round<S>(a, r.a, r.da);
    if (r.error == PolygonError::None)
    {
        r.error = Round<S>(b, r.b, r.db);
    }
    r.xfA = RoundTransform<S>(xfA);
    r.xfB = RoundTransform<S>(xfB);
    r.dxfA = Widen(r.xfA);
    r.dxfB = Widen(r.xfB);
    return r;
}

/// Counts a pair that did not survive rounding; true when it did.
bool Kept(Tally& tally, PolygonError error)
{
    if (error == PolygonError::None)
    {
        return true;
    }
    (error == PolygonError::CollinearVertex ? tally.collinear : tally.malformed) += 1;
    return false;
}

double Scale(const Shape& s)
{
    return s.type == ShapeType::Circle ? s.circle.radius : Radius(s.polygon);
}

/// Scores Overlap and Collide on a rounded pair against the reference.
template <typename S>
void ScoreRounded(Tally& tally, const Rounded<S>& r)
{
    const Reference ref = ReferenceCollide(r.da, r.dxfA, r.db, r.dxfB);
    const double scale = std::max(Scale(r.da), Scale(r.db));
    const double separation = static_cast<double>(ref.separation);
    const double margin = std::abs(separation) / scale;
    const bool overlap = Overlap(r.a, r.xfA, r.b, r.xfB);
    const ManifoldT<S> m = Collide(r.a, r.xfA, r.b, r.xfB);
    tally.pairs += 1;
    if (margin <= Bounds<S>::kBand)
    {
        tally.inBand += 1;
    }
    else
    {
        tally.wrong += (overlap != ref.overlap) + (m.overlap != ref.overlap);
        if (margin <= Bounds<S>::kClose)
        {
            (ref.overlap ? tally.nearHits : tally.nearMisses) += 1;
        }
    }
    // An overlap found carries the true depth (0 for a pair apart within the band); a gap found is never more
    // than the reference's best separation (the gap is on one axis, the separation the best of them).
    if (m.overlap)
    {
        tally.depthError =
            std::max(tally.depthError, std::abs(static_cast<double>(m.depth) - std::max(0.0, -separation)) / scale);
    }
    else
    {
        tally.depthError = std::max(tally.depthError, (static_cast<double>(m.gap) - std::max(0.0, separation)) / scale);
    }
}

/// Runs Overlap and Collide in precision S on a pair and scores them against the reference.
template <typename S>
void Score(Tally& tally, const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB)
{
    tally.attempts += 1;
    const Rounded<S> r = RoundPair<S>(a, xfA, b, xfB);
    if (Kept(tally, r.error))
    {
        ScoreRounded(tally, r);
    }
}

/// Scores Sweep in precision S, B moving by `velocity` and A still, against the Minkowski-difference cast; returns
/// the reference.
template <typename S>
SweepReference ScoreSweep(SweepTally& tally, const Rounded<S>& r, Vec2 velocity)
{
    const Vec2 v = Seen<S>(velocity);
    const SweepResultT<S> got = Sweep(r.a, r.xfA, Vec2T<S>{}, r.b, r.xfB, ConvertVec<S>(v));
    const SweepReference ref = ReferenceSweep(r.da.polygon, r.dxfA, r.db.polygon, r.dxfB, v);
    const double scale = std::max(Scale(r.da), Scale(r.db));
    const double speed = Length(v) / scale;
    const double enter = static_cast<double>(ref.enter);
    const bool hit = !ref.insideAtStart && ref.crosses && ref.enter <= 1 && ref.leave > 0;
    tally.pairs += 1;
    // Touching at the start, grazing (a short chord through A - B) or reaching A at the end of the step: either.
    if (std::abs(static_cast<double>(ref.startSeparation)) / scale <= Bounds<S>::kBand ||
        std::abs(enter - 1.0) * speed <= Bounds<S>::kBand ||
        std::abs(static_cast<double>(ref.leave - ref.enter)) * speed <= Bounds<S>::kBand)
    {
        tally.inBand += 1;
    }
    else
    {
        const SweepStatus expected =
            ref.insideAtStart ? SweepStatus::Overlapping : (hit ? SweepStatus::Hit : SweepStatus::Miss);
        tally.wrong += got.status != expected;
        (expected == SweepStatus::Hit ? tally.hits
                                      : (expected == SweepStatus::Miss ? tally.misses : tally.overlapping)) += 1;
    }
    if (got.status == SweepStatus::Hit && hit)
    {
        tally.toiError = std::max(tally.toiError, std::abs(static_cast<double>(got.toi) - std::max(0.0, enter)) *
                                                      speed / (1.0 + speed));
    }
    return ref;
}

/// The reference for a segment cast: Cyrus-Beck clipping of the segment against the polygon's faces, in quadruple
/// precision from the exact inputs, and how far the segment is from a change of answer, measured across the faces
/// that decide it (along the segment, a face crossed at a shallow angle magnifies any error of its position).
struct SegmentReference
{
    bool inside = false; ///< p1 inside the polygon or on its boundary
    bool hit = false;    ///< the segment meets the polygon
    Quad enter = 0;      ///< entry fraction, when it enters from outside
    Quad rate = 0;       ///< Dot(unit normal of the face entered, p2 - p1): how steeply the segment enters
    /// Distance from a change of answer: p1 from the nearest face line (starting on a face), the chord through the
    /// polygon or the gap before it times the smaller |Dot(n, p2 - p1)| of the faces that bound it (grazing), p2
    /// from the face entered (ending on it).
    Quad margin = 0;
};

SegmentReference ReferenceSegment(const Polygon& polygon, const Transform& xf, Vec2 p1, Vec2 p2)
{
    const std::vector<QVec> w = QWorld(polygon, xf);
    const QVec q{p1.x, p1.y};
    const QVec d{Quad(p2.x) - Quad(p1.x), Quad(p2.y) - Quad(p1.y)};
    Quad enter = -1e300Q;
    Quad leave = 1e300Q;
    Quad leaveRate = 0;
    Quad nearest = 1e300Q;
    SegmentReference out;
    out.inside = true;
    for (size_t i = 0; i < w.size(); ++i)
    {
        const QVec e = w[(i + 1) % w.size()] - w[i];
        const QVec n{e.y, -e.x};
        const Quad length = sqrtq(QDot(n, n));
        const Quad s = QDot(n, q - w[i]) / length; // signed distance of p1 from the face's line
        const Quad rate = QDot(n, d) / length;
        out.inside = out.inside && s <= 0;
        nearest = fabsq(s) < nearest ? fabsq(s) : nearest;
        if (rate == 0)
        {
            enter = s > 0 ? 1e300Q : enter;
            continue;
        }
        const Quad t = -s / rate;
        if (rate < 0)
        {
            if (t > enter)
            {
                enter = t;
                out.rate = rate;
            }
        }
        else if (t < leave)
        {
            leave = t;
            leaveRate = rate;
        }
    }
    out.hit = out.inside || (enter <= leave && enter >= 0 && enter <= 1);
    out.enter = enter;
    const Quad steepness = std::min(fabsq(out.rate), fabsq(leaveRate));
    out.margin = std::min({nearest, fabsq(leave - enter) * steepness, fabsq(1 - enter) * fabsq(out.rate)});
    return out;
}

/// Scores RayCast in precision S of the segment from p1 to p2 against A.
template <typename S>
void ScoreRay(RayTally& tally, const Rounded<S>& r, Vec2 p1, Vec2 p2)
{
    const Vec2 q1 = Seen<S>(p1);
    const Vec2 q2 = Seen<S>(p2);
    const RayHitT<S> got = RayCast(r.a, r.xfA, ConvertVec<S>(q1), ConvertVec<S>(q2));
    const SegmentReference ref = ReferenceSegment(r.da.polygon, r.dxfA, q1, q2);
    const double scale = Scale(r.da);
    tally.rays += 1;
    if (static_cast<double>(ref.margin) <= Bounds<S>::kBand * scale)
    {
        tally.inBand += 1;
    }
    else
    {
        tally.wrong += got.hit != ref.hit || got.startsInside != ref.inside;
        (ref.inside ? tally.inside : (ref.hit ? tally.hits : tally.misses)) += 1;
    }
    // The entry point's error across the face entered, relative to the size of the shape and the segment (a
    // fraction in precision S cannot tell points closer than eps of the segment's length apart): along the segment,
    // a shallow entry magnifies any error of the face's position by 1 / cos of the angle, which no precision avoids.
    if (got.hit && !got.startsInside && ref.hit && !ref.inside)
    {
        const double error = std::abs(static_cast<double>(got.fraction) - static_cast<double>(ref.enter));
        tally.fractionError =
            std::max(tally.fractionError, error * std::abs(static_cast<double>(ref.rate)) / (scale + Length(q2 - q1)));
    }
}

/// Scores a moving pair: Overlap and Collide, Sweep with B moving by `velocity`, and RayCast of the segment from
/// p1 to p2 against A. A sweep that hits is scored again at the speed that reaches A at 1 + late of the step
/// (late from -1e-2 to 1e-2), so that hits just before the end of the step and misses just after it are tested.
template <typename S>
void ScoreMoving(Tally& tally, SweepTally& sweeps, RayTally& rays, const Shape& a, const Transform& xfA, const Shape& b,
                 const Transform& xfB, Vec2 velocity, double late, Vec2 p1, Vec2 p2)
{
    tally.attempts += 1;
    const Rounded<S> r = RoundPair<S>(a, xfA, b, xfB);
    if (!Kept(tally, r.error))
    {
        return;
    }
    ScoreRounded(tally, r);
    const SweepReference ref = ScoreSweep(sweeps, r, velocity);
    if (!ref.insideAtStart && ref.crosses && ref.enter > 0 && ref.enter <= 1)
    {
        ScoreSweep(sweeps, r, static_cast<double>(ref.enter) / (1.0 + late) * Seen<S>(velocity));
    }
    ScoreRay(rays, r, p1, p2);
}

std::string Short(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

/// What a set of pairs must show beyond the bounds.
struct Expect
{
    int nearContact = 0;      ///< at least this many near misses and as many near hits (pairs placed in contact)
    bool collinearOk = false; ///< rounding to this precision may turn a vertex straight (counted, never dropped)
};

template <typename S>
void Require(const Tally& tally, const std::string& what, Expect expect = {})
{
    INFO(what << " (" << Bounds<S>::kName << "): " << tally.pairs << " pairs, " << tally.inBand << " within the band, "
              << tally.nearMisses << " near misses and " << tally.nearHits << " near hits outside it, " << tally.wrong
              << " wrong, worst depth error " << tally.depthError << " of the shape size; not built: "
              << tally.collinear << " collinear, " << tally.malformed << " otherwise");
    CHECK(tally.pairs > 0);
    CHECK(tally.pairs + tally.collinear + tally.malformed == tally.attempts);
    CHECK(tally.wrong == 0);
    CHECK(tally.depthError <= Bounds<S>::kDepth);
    CHECK(tally.nearMisses >= expect.nearContact);
    CHECK(tally.nearHits >= expect.nearContact);
    CHECK(tally.malformed == 0);
    if (!expect.collinearOk)
    {
        CHECK(tally.collinear == 0);
    }
}

/// `everyOutcome`: hits, misses and pairs overlapping at the start must all occur outside the band.
template <typename S>
void RequireSweeps(const SweepTally& tally, const std::string& what, bool everyOutcome = true)
{
    INFO(what << " (" << Bounds<S>::kName << "), sweeps: " << tally.pairs << " pairs, " << tally.inBand
              << " within the band, " << tally.hits << " hits, " << tally.misses << " misses, " << tally.overlapping
              << " overlapping outside it, " << tally.wrong << " wrong, worst time of impact error " << tally.toiError
              << " (along the path, of the shape size plus the path)");
    CHECK(tally.wrong == 0);
    CHECK(tally.hits + tally.misses + tally.overlapping > 0);
    if (everyOutcome)
    {
        CHECK(tally.hits > 0);
        CHECK(tally.misses > 0);
        CHECK(tally.overlapping > 0);
    }
    CHECK(tally.toiError <= Bounds<S>::kToi);
}

template <typename S>
void RequireRays(const RayTally& tally, const std::string& what)
{
    INFO(what << " (" << Bounds<S>::kName << "), segment casts: " << tally.rays << " segments, " << tally.inBand
              << " within the band, " << tally.hits << " hits, " << tally.misses << " misses, " << tally.inside
              << " starting inside outside it, " << tally.wrong << " wrong, worst fraction error "
              << tally.fractionError << " (across the face entered, of the shape size plus the segment)");
    CHECK(tally.wrong == 0);
    CHECK(tally.hits > 0);
    CHECK(tally.misses > 0);
    CHECK(tally.inside > 0);
    CHECK(tally.fractionError <= Bounds<S>::kFraction);
}

/// A velocity for B that closes on A: `toward` (from B to A) scaled by 0.2 to 150, turned aside by up to half of
/// it, so that some pairs hit early, some late and some pass by.
Vec2 Closing(Rng& rng, Vec2 toward)
{
    const double k = rng.Uniform(0.2, 1.5) * rng.LogUniform(-1.0, 2.0);
    return k * toward + (k * rng.Uniform(-0.5, 0.5)) * LeftPerp(toward);
}

/// A segment from p1 to p2.
struct Segment
{
    Vec2 p1, p2;
};

/// A segment towards A (at `xf`, of size `scale`): from up to three times `reach` away (a fifth of them from within
/// `scale`), aimed at a random point of A's bounding square or at one of its vertices, and stopping before, at or
/// beyond it.
Segment CastAt(Rng& rng, const Polygon& a, const Transform& xf, double scale, double reach)
{
    const double direction = rng.Uniform(0.0, 2.0 * kPi);
    const double from = rng.Chance(0.2) ? scale * rng.Uniform(0.0, 1.0) : reach * rng.Uniform(0.0, 3.0);
    const Vec2 p1 = xf.p + Vec2{from * std::cos(direction), from * std::sin(direction)};
    const Vec2 aim = rng.Chance(0.3) ? TransformPoint(xf, a.Vertices()[rng.Int(0, a.Count() - 1)])
                                     : xf.p + scale * Vec2{rng.Uniform(-1.5, 1.5), rng.Uniform(-1.5, 1.5)};
    return {p1, p1 + rng.Uniform(0.2, 2.0) * (aim - p1)};
}

/// How far before (< 0) or after the end of the step a re-timed sweep reaches A: 1e-12 to 1e-2 of the step,
/// log-uniform, either sign.
double Late(Rng& rng)
{
    return rng.LogUniform(-12.0, -2.0) * (rng.Chance(0.5) ? 1.0 : -1.0);
}

/// A signed gap from 1e-15 to 1e-3 of `scale`, log-uniform, either sign (< 0: pushed in).
double SignedGap(Rng& rng, double scale)
{
    return scale * rng.LogUniform(-15.0, -3.0) * (rng.Chance(0.5) ? 1.0 : -1.0);
}

/// B placed against A at the point `along` (0 to 1) of A's edge `edge`: B's support vertex on it, or a third of
/// the time one of B's edges turned anti-parallel to A's edge and starting there; then moved by `gap` along the
/// edge's outward normal (< 0: into A). A is at `xfA`.
RandomPair Against(Rng& rng, const Polygon& a, const Transform& xfA, const Polygon& b, int edge, double along,
                   double gap)
{
    const Vec2 point = a.Vertices()[edge] + along * a.Edge(edge);
    const Vec2 normal = a.Normal(edge);
    double angleB = rng.Uniform(-kPi, kPi);
    int touching = 0;
    if (rng.Chance(1.0 / 3.0))
    {
        touching = rng.Int(0, b.Count() - 1);
        const Vec2 nb = b.Normal(touching);
        angleB = std::atan2(-normal.y, -normal.x) - std::atan2(nb.y, nb.x);
    }
    else
    {
        const Rot q = MakeRot(angleB);
        double lowest = INFINITY;
        for (int k = 0; k < b.Count(); ++k)
        {
            const double d = Dot(normal, Rotate(q, b.Vertices()[k]));
            if (d < lowest)
            {
                lowest = d;
                touching = k;
            }
        }
    }
    const Vec2 positionInA = point - Rotate(MakeRot(angleB), b.Vertices()[touching]) + gap * normal;
    const double angleA = std::atan2(xfA.q.s, xfA.q.c);
    return {MakeShape(a), xfA, MakeShape(b), MakeTransform(TransformPoint(xfA, positionInA), angleA + angleB)};
}

/// Against, at a random point of a random edge of A, by a random signed gap relative to the larger shape.
RandomPair AgainstAnywhere(Rng& rng, const Polygon& a, const Transform& xfA, const Polygon& b)
{
    const double scale = std::max(Radius(a), Radius(b));
    return Against(rng, a, xfA, b, rng.Int(0, a.Count() - 1), rng.Uniform(0.0, 1.0), SignedGap(rng, scale));
}

template <typename S>
void FarFromOrigin()
{
    // Contact pairs, moved far away together; each also swept (B closing on A) and cast at (a segment at A). In
    // float, positions out there lie on a grid (8 units apart at 1e8): B closes on A as the grid places them, and
    // the segments reach over a few grid steps, so that they are not rounded to nothing.
    Rng rng(101);
    for (double offset : {1e3, 1e4, 1e5, 1e6, 1e7, 1e8})
    {
        Tally tally;
        SweepTally sweeps;
        RayTally rays;
        const double grid = offset * std::numeric_limits<S>::epsilon();
        for (int i = 0; i < 1500; ++i)
        {
            RandomPair p = ContactPair(rng, rng.Int(3, 12), static_cast<PairCategory>(rng.Int(0, 2)));
            const Vec2 offsetBToA = p.xfA.p - p.xfB.p;
            const Vec2 shift{offset * (rng.Chance(0.5) ? 1.0 : -1.0), offset * (rng.Chance(0.5) ? 1.0 : -1.0)};
            p.xfA.p = p.xfA.p + shift;
            p.xfB.p = p.xfB.p + shift;
            const Vec2 rounded = Seen<S>(p.xfA.p) - Seen<S>(p.xfB.p);
            const Vec2 velocity = Closing(rng, rounded == Vec2{} ? offsetBToA : rounded);
            const double scale = Radius(p.a.polygon);
            const Segment s = CastAt(rng, p.a.polygon, p.xfA, scale, std::max(scale, 4.0 * grid));
            ScoreMoving<S>(tally, sweeps, rays, p.a, p.xfA, p.b, p.xfB, velocity, Late(rng), s.p1, s.p2);
        }
        const std::string what = "far from the origin, offset " + Short(offset);
        Require<S>(tally, what);
        // Where the grid is coarser than the shapes (float at 1e8: 12 units against at most 1.5), the two shapes
        // of a pair round to one position: every sweep starts overlapping.
        RequireSweeps<S>(sweeps, what, grid < 1.5);
        RequireRays<S>(rays, what);
    }
}

template <typename S>
void TinyAndHuge()
{
    // Contact pairs scaled as a whole (shapes, positions, velocities and segments).
    Rng rng(202);
    for (double size : {1e-6, 1e-3, 1.0, 1e3, 1e6})
    {
        Tally tally;
        SweepTally sweeps;
        RayTally rays;
        for (int i = 0; i < 1500; ++i)
        {
            const RandomPair p = ContactPair(rng, rng.Int(3, 12), static_cast<PairCategory>(rng.Int(0, 2)));
            auto scaled = [&](const Shape& s) {
                std::vector<Vec2> points;
                for (const Vec2& v : s.polygon.Vertices())
                {
                    points.push_back(size * v);
                }
                return MakeShape(Built(MakePolygon(points)));
            };
            const Transform xfA{size * p.xfA.p, p.xfA.q};
            const Transform xfB{size * p.xfB.p, p.xfB.q};
            const Shape a = scaled(p.a);
            const Vec2 velocity = size * Closing(rng, p.xfA.p - p.xfB.p);
            const Segment s = CastAt(rng, a.polygon, xfA, Radius(a.polygon), Radius(a.polygon));
            ScoreMoving<S>(tally, sweeps, rays, a, xfA, scaled(p.b), xfB, velocity, Late(rng), s.p1, s.p2);
        }
        const std::string what = "shapes of size " + Short(size);
        Require<S>(tally, what);
        RequireSweeps<S>(sweeps, what);
        RequireRays<S>(rays, what);
    }
}

template <typename S>
void Slivers()
{
    // Slivers against ordinary polygons, both ways round, per decade of aspect: at random places (swept and cast
    // at), and placed against each other on a random edge with a signed gap from 1e-15 to 1e-3, so that answers
    // near touching are tested. In float, slivers thinner than 1e-5 may round to a straight turn: counted, and
    // only as CollinearVertex.
    Rng rng(303);
    for (int decade = -6; decade <= -3; ++decade)
    {
        Tally tally;
        SweepTally sweeps;
        RayTally rays;
        for (int i = 0; i < 750; ++i)
        {
            const double aspect = rng.LogUniform(decade, decade + 1);
            const Polygon sliver = RandomPolygon(rng, rng.Int(3, 8), rng.Uniform(0.5, 1.5), aspect);
            const Polygon other = RandomPolygon(rng, rng.Int(3, 8), rng.Uniform(0.5, 1.5), rng.Uniform(0.3, 1.0));
            const Transform xfA = MakeTransform(Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(-kPi, kPi));
            const Transform xfB = MakeTransform(Vec2{rng.Uniform(-2, 2), rng.Uniform(-2, 2)}, rng.Uniform(-kPi, kPi));
            const Shape a = MakeShape(sliver);
            const Shape b = MakeShape(other);
            const Segment toSliver = CastAt(rng, sliver, xfA, Radius(sliver), Radius(sliver));
            const Segment toOther = CastAt(rng, other, xfB, Radius(other), Radius(other));
            ScoreMoving<S>(tally, sweeps, rays, a, xfA, b, xfB, Closing(rng, xfA.p - xfB.p), Late(rng), toSliver.p1,
                           toSliver.p2);
            ScoreMoving<S>(tally, sweeps, rays, b, xfB, a, xfA, Closing(rng, xfB.p - xfA.p), Late(rng), toOther.p1,
                           toOther.p2);
            const RandomPair onSliver = AgainstAnywhere(rng, sliver, xfA, other);
            Score<S>(tally, onSliver.a, onSliver.xfA, onSliver.b, onSliver.xfB);
            const RandomPair onOther = AgainstAnywhere(rng, other, xfB, sliver);
            Score<S>(tally, onOther.a, onOther.xfA, onOther.b, onOther.xfB);
        }
        const std::string what = "slivers of aspect 1e" + std::to_string(decade);
        const bool straightens = std::is_same<S, float>::value && decade < -5;
        Require<S>(tally, what, {20, straightens});
        RequireSweeps<S>(sweeps, what);
        RequireRays<S>(rays, what);
    }
}

template <typename S>
void NearParallelEdges()
{
    // B's bottom edge over A's top face, turned by a tiny angle: pushed in by a depth from 1e-9 to 0.1, or with its
    // lowest corner at a signed gap from 1e-15 to 1e-3 of the size, just apart or just touching.
    Rng rng(404);
    const Shape a = MakeShape(Built(MakeBox(2.0, 0.5)));
    const Shape b = MakeShape(Built(MakeBox(0.7, 0.3)));
    const double scale = Radius(a.polygon);
    for (double angle : {1e-12, 1e-9, 1e-6, 1e-3})
    {
        Tally deep;
        Tally touching;
        for (int i = 0; i < 400; ++i)
        {
            const double turn = angle * (rng.Chance(0.5) ? 1.0 : -1.0);
            const double x = rng.Uniform(-1.0, 1.0);
            // The lowest corner of the turned box is this far below its centre.
            const double lowest = 0.3 * std::cos(turn) + 0.7 * std::abs(std::sin(turn));
            const double depth = rng.LogUniform(-9.0, -1.0);
            Score<S>(deep, a, Transform{{0.0, 0.0}, {1.0, 0.0}}, b, MakeTransform(Vec2{x, 0.5 + lowest - depth}, turn));
            const double gap = SignedGap(rng, scale);
            Score<S>(touching, a, Transform{{0.0, 0.0}, {1.0, 0.0}}, b,
                     MakeTransform(Vec2{x, 0.5 + lowest + gap}, turn));
        }
        Require<S>(deep, "near-parallel edges pushed in, angle " + Short(angle));
        Require<S>(touching, "near-parallel edges at a signed gap of 1e-15 to 1e-3, angle " + Short(angle), {5});
    }
}

template <typename S>
void TinyGaps()
{
    // A hexagon above a box, its lowest vertex at a signed gap from 1e-15 to 1e-3 over the box's top face.
    Rng rng(505);
    const Shape a = MakeShape(Built(MakeBox(1.5, 0.5)));
    const Shape b = MakeShape(Built(MakeRegularPolygon(6, 0.4, 0.25)));
    Tally tally;
    for (int e = -15; e <= -3; ++e)
    {
        for (int i = 0; i < 100; ++i)
        {
            const double gap = std::pow(10.0, e) * rng.Uniform(1.0, 9.99) * (rng.Chance(0.5) ? 1.0 : -1.0);
            const double angle = rng.Uniform(-0.2, 0.2);
            const Transform xfB0 = MakeTransform(Vec2{rng.Uniform(-1.0, 1.0), 0.0}, angle);
            double lowest = INFINITY;
            for (const Vec2& v : b.polygon.Vertices())
            {
                lowest = std::min(lowest, TransformPoint(xfB0, v).y);
            }
            const Transform xfB = MakeTransform(Vec2{xfB0.p.x, 0.5 - lowest + gap}, angle);
            Score<S>(tally, a, Transform{{0.0, 0.0}, {1.0, 0.0}}, b, xfB);
        }
    }
    Require<S>(tally, "gaps from 1e-15 to 1e-3", {20});
}

template <typename S>
void NearlyCollinear()
{
    // A hexagon with one edge's midpoint pushed out by eps, built in precision S from its vertices rounded to S.
    // Pushes of at least kKeptPush keep the vertex: every outline is built, and placed at random and against a
    // random polygon (on the bent edge or the pushed vertex half the time, with a signed gap from 1e-15 to 1e-3),
    // the queries keep their bounds. Smaller pushes vanish in the rounding: every outline is rejected, and only
    // as CollinearVertex.
    Rng rng(606);
    for (double eps : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15, 1e-17})
    {
        Tally tally;
        int rejected = 0;
        constexpr int kOutlines = 300;
        for (int i = 0; i < kOutlines; ++i)
        {
            const Polygon hex = Built(MakeRegularPolygon(6, 1.0, rng.Uniform(0.0, 1.0)));
            std::vector<Vec2> points(hex.Vertices().begin(), hex.Vertices().end());
            const Vec2 mid = 0.5 * (points[0] + points[1]);
            points.insert(points.begin() + 1, mid + eps * hex.Normal(0));
            std::vector<Vec2T<S>> rounded;
            for (const Vec2& p : points)
            {
                rounded.push_back(Narrow<S>(p));
            }
            const PolygonResultT<S> result = MakePolygon(rounded);
            if (!result.Ok())
            {
                INFO("eps " << eps << ": " << DescribePolygonError(result.error, result.vertex));
                CHECK(result.error == PolygonError::CollinearVertex);
                ++rejected;
                continue;
            }
            const Polygon bent = Built(ConvertPolygon<double>(result.polygon));
            const RandomPair p = ContactPair(rng, 5, static_cast<PairCategory>(rng.Int(0, 2)));
            Score<S>(tally, MakeShape(bent), p.xfA, p.b, p.xfB);
            const Polygon other = RandomPolygon(rng, rng.Int(3, 8), rng.Uniform(0.5, 1.5), rng.Uniform(0.35, 1.0));
            const Transform xfA = MakeTransform(Vec2{rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(-kPi, kPi));
            // The pushed vertex is vertex 1, between edges 0 and 1.
            const bool atBend = rng.Chance(0.5);
            const int edge = atBend ? rng.Int(0, 1) : rng.Int(0, bent.Count() - 1);
            const double along =
                atBend ? (edge == 0 ? rng.Uniform(0.5, 1.0) : rng.Uniform(0.0, 0.5)) : rng.Uniform(0.0, 1.0);
            const RandomPair placed =
                Against(rng, bent, xfA, other, edge, along, SignedGap(rng, std::max(Radius(bent), Radius(other))));
            Score<S>(tally, placed.a, placed.xfA, placed.b, placed.xfB);
        }
        INFO(Bounds<S>::kName << ", eps " << eps << ": " << rejected << " of " << kOutlines << " outlines rejected");
        if (eps >= Bounds<S>::kKeptPush)
        {
            CHECK(rejected == 0);
            Require<S>(tally, "nearly collinear vertices, eps " + Short(eps), {5});
        }
        else
        {
            CHECK(rejected == kOutlines);
            CHECK(tally.pairs == 0);
        }
    }
}

/// A mover for MoveAndSlide in precision S, and the same shape in double for the reference.
template <typename S>
struct Mover
{
    ShapeT<S> shape;
    Shape wide;
    std::string name;
};

/// Polygons of 3 to 40 vertices (above 16 the sweeps walk the outline instead of scanning it) at random rotations,
/// an axis-aligned box, and a circle whose centre is off its body origin.
template <typename S>
std::vector<Mover<S>> Movers(Rng& rng)
{
    std::vector<Shape> shapes;
    std::vector<std::string> names;
    for (int n : {3, 5, 6, 8, 12, 40})
    {
        shapes.push_back(MakeShape(RandomPolygon(rng, n, rng.Uniform(0.2, 0.5), rng.Uniform(0.4, 1.0))));
        names.push_back(std::to_string(n) + "-gon");
    }
    shapes.push_back(MakeShape(Built(MakeBox(0.25, 0.25))));
    names.push_back("box");
    shapes.push_back(MakeShape(Circle{{0.05, -0.03}, 0.3}));
    names.push_back("circle");
    std::vector<Mover<S>> movers;
    for (size_t i = 0; i < shapes.size(); ++i)
    {
        Mover<S> mover;
        REQUIRE(Round<S>(shapes[i], mover.shape, mover.wide) == PolygonError::None);
        mover.name = names[i];
        movers.push_back(std::move(mover));
    }
    return movers;
}

/// Distance between the mover and an obstacle by the reference: > 0 apart, minus the depth when overlapping.
template <typename S>
double Clearance(const Mover<S>& mover, const TransformT<S>& xf, const Shape& obstacle, const Transform& at)
{
    return static_cast<double>(ReferenceCollide(mover.wide, Widen(xf), obstacle, at).separation);
}

/// How far the mover reaches below its origin along -up, when turned by q.
double Lowest(const Shape& shape, Rot q, Vec2 up)
{
    if (shape.type == ShapeType::Circle)
    {
        return Dot(up, Rotate(q, shape.circle.center)) - shape.circle.radius;
    }
    double lowest = INFINITY;
    for (const Vec2& v : shape.polygon.Vertices())
    {
        lowest = std::min(lowest, Dot(up, Rotate(q, v)));
    }
    return lowest;
}

/// A slab obstacle in precision S, its double twin and the world normal of its face that looks most along `out`.
template <typename S>
struct Slab
{
    ShapeT<S> shape;
    TransformT<S> xf;
    Shape wide;
    Transform dxf;
    Vec2 normal; ///< the face's unit normal as rounded in precision S
};

template <typename S>
Slab<S> MakeSlab(double hx, double hy, Vec2 center, double angle, Vec2 out)
{
    Slab<S> slab;
    REQUIRE(Round<S>(MakeShape(Built(MakeBox(hx, hy))), slab.shape, slab.wide) == PolygonError::None);
    slab.xf = RoundTransform<S>(MakeTransform(center, angle));
    slab.dxf = Widen(slab.xf);
    double best = -INFINITY;
    for (int i = 0; i < slab.wide.polygon.Count(); ++i)
    {
        const Vec2 n = Rotate(slab.dxf.q, slab.wide.polygon.Normal(i));
        if (Dot(n, out) > best)
        {
            best = Dot(n, out);
            slab.normal = Normalize(n);
        }
    }
    return slab;
}

/// Worst values over a sequence of MoveAndSlide steps, relative to the skin of each step (DefaultSkin at its start).
struct SlideTally
{
    int steps = 0;
    int contacts = 0;        ///< steps that met a surface
    int atWall = 0;          ///< steps that met the wall
    double least = INFINITY; ///< least clearance from any surface after any step (absolute): > 0, no penetration
    double dip = 0;   ///< worst (min(clearance before, skin) - clearance after) / skin from a surface met: no sinking
    double hover = 0; ///< worst clearance / skin from the surface last met in a step: not stopped short
    double slip = 0;  ///< worst |tangential displacement - requested| in rounding units: no sticking
    int stopped = 0;  ///< floor-only steps that ran out of contacts with displacement left
};

/// Bounds of MoveAndSlide. No step leaves the mover touching or inside any surface (clearance > 0). A step stops
/// `skin` short of a surface it meets, and keeps a mover already closer where it is: it never ends closer to a
/// surface it met than that by more than Bounds::kDip of the skin (in float, the skin is 64 ulps of the position
/// and the rounding of a step a few of them), and ends within the skin of the last surface it met (plus kDip): it
/// does not stop short. (Free motion may end anywhere short of a surface it does not meet, the skin included.) A
/// step that does not meet the wall keeps the requested displacement along the floor, within kSlip rounding units
/// of the position and the displacement (eps (|p| + |push|)): it does not stick.
constexpr double kSlip = 4.0;

template <typename S>
void RequireSlide(const SlideTally& tally, const std::string& what)
{
    INFO(what << " (" << Bounds<S>::kName << "): " << tally.steps << " steps, " << tally.contacts
              << " meeting a surface, " << tally.atWall << " the wall; least clearance " << tally.least
              << ", worst dip into the skin " << tally.dip << " and clearance from the last surface met " << tally.hover
              << " of the skin; worst tangential slip " << tally.slip << " rounding units; " << tally.stopped
              << " steps stopped short");
    CHECK(tally.contacts > tally.steps / 2);
    CHECK(tally.least > 0.0);
    CHECK(tally.dip <= Bounds<S>::kDip);
    CHECK(tally.hover <= 1.0 + Bounds<S>::kDip);
    CHECK(tally.slip <= kSlip);
    CHECK(tally.stopped == 0);
}

/// Drives a mover along a floor tilted by `slope`, pressing into it, and with a wall, into the corner where a wall
/// leaning back by `lean` (< 0: overhanging) meets the floor 3 units ahead. Checks every step against the bounds
/// above (the displacement along the floor on the steps that do not meet the wall).
template <typename S>
void SlideSteps(Rng& rng, const Mover<S>& mover, double slope, bool withWall, double lean, SlideTally& tally)
{
    const Vec2 up{-std::sin(slope), std::cos(slope)};
    const Slab<S> floor = MakeSlab<S>(200.0, 1.0, Vec2{0.0, 0.0}, slope, up);
    const Vec2 n = floor.normal;
    const Vec2 t = RightPerp(n);
    const Vec2 wallNormal = -std::cos(lean) * t + std::sin(lean) * n;
    const Vec2 corner = 3.0 * t + 1.0 * n;
    const Slab<S> wall =
        MakeSlab<S>(0.5, 20.0, corner - 0.5 * wallNormal, std::atan2(wallNormal.y, wallNormal.x) - kPi, wallNormal);
    const ObstacleT<S> obstacles[2] = {{&floor.shape, floor.xf}, {&wall.shape, wall.xf}};
    const Slab<S>* slabs[2] = {&floor, &wall};
    const int count = withWall ? 2 : 1;

    const double angle = rng.Uniform(-kPi, kPi);
    const Vec2 start = (1.0 - Lowest(mover.wide, MakeRot(angle), n) + 0.01) * n;
    TransformT<S> xf = RoundTransform<S>(MakeTransform(start, angle));
    double clearance[2] = {Clearance(mover, xf, floor.wide, floor.dxf), Clearance(mover, xf, wall.wide, wall.dxf)};
    const double eps = std::numeric_limits<S>::epsilon();
    for (int step = 0; step < (withWall ? 120 : 300); ++step)
    {
        const double along = withWall ? rng.Uniform(0.01, 0.2) : rng.Uniform(-0.05, 0.2);
        const double press = withWall ? along * rng.Uniform(0.5, 1.5) : rng.Uniform(0.0, 0.1);
        const Vec2T<S> push = Narrow<S>(along * t - press * n);
        const Vec2 p0 = Widen(xf).p;
        const double skin = static_cast<double>(DefaultSkin(mover.shape, xf));
        const SlideResultT<S> result = MoveAndSlide(mover.shape, xf, push, obstacles, count);
        xf = result.xf;
        tally.steps += 1;
        bool met[2] = {false, false};
        for (int k = 0; k < result.contactCount; ++k)
        {
            met[result.obstacles[k]] = true;
        }
        const bool metWall = met[1];
        for (int k = 0; k < count; ++k)
        {
            const double after = Clearance(mover, xf, slabs[k]->wide, slabs[k]->dxf);
            tally.least = std::min(tally.least, after);
            if (met[k])
            {
                tally.dip = std::max(tally.dip, (std::min(clearance[k], skin) - after) / skin);
            }
            clearance[k] = after;
        }
        if (result.contactCount > 0)
        {
            tally.contacts += 1;
            tally.hover = std::max(tally.hover, clearance[result.obstacles[result.contactCount - 1]] / skin);
        }
        tally.atWall += metWall;
        if (!metWall)
        {
            tally.stopped += result.remaining != Vec2T<S>{};
            const double requested = Dot(ConvertVec<double>(push), t);
            const double unit = eps * (Length(p0) + Length(ConvertVec<double>(push)));
            tally.slip = std::max(tally.slip, std::abs(Dot(Widen(xf).p - p0, t) - requested) / unit);
        }
    }
}

template <typename S>
void SlidingAlongSlopes()
{
    Rng rng(808);
    const std::vector<Mover<S>> movers = Movers<S>(rng);
    for (double slope : {0.0, 0.35, -0.8, 1.2})
    {
        for (const Mover<S>& mover : movers)
        {
            SlideTally tally;
            SlideSteps(rng, mover, slope, false, 0.0, tally);
            RequireSlide<S>(tally, "a " + mover.name + " sliding along a floor at slope " + Short(slope));
        }
    }
}

template <typename S>
void RepeatedMovesToContact()
{
    Rng rng(707);
    const std::vector<Mover<S>> movers = Movers<S>(rng);
    for (double slope : {0.0, 0.35, -0.8})
    {
        for (double lean : {0.0, 0.3, -0.4})
        {
            for (const Mover<S>& mover : movers)
            {
                SlideTally tally;
                SlideSteps(rng, mover, slope, true, lean, tally);
                const std::string what = "a " + mover.name + " driven into the corner of a floor at slope " +
                                         Short(slope) + " and a wall leaning " + Short(lean);
                RequireSlide<S>(tally, what);
                INFO(what);
                CHECK(tally.atWall > 0);
            }
        }
    }
}

} // namespace

TEMPLATE_TEST_CASE("Stress: far from the origin, offsets 1e3 to 1e8", "[stress]", double, float)
{
    FarFromOrigin<TestType>();
}

TEMPLATE_TEST_CASE("Stress: tiny and huge shapes, sizes 1e-6 to 1e6", "[stress]", double, float)
{
    TinyAndHuge<TestType>();
}

TEMPLATE_TEST_CASE("Stress: slivers down to aspect 1e-6", "[stress]", double, float)
{
    Slivers<TestType>();
}

TEMPLATE_TEST_CASE("Stress: near-parallel edges, angles down to 1e-12", "[stress]", double, float)
{
    NearParallelEdges<TestType>();
}

TEMPLATE_TEST_CASE("Stress: gaps from 1e-15 to 1e-3", "[stress]", double, float)
{
    TinyGaps<TestType>();
}

TEMPLATE_TEST_CASE("Stress: nearly collinear vertices", "[stress]", double, float)
{
    NearlyCollinear<TestType>();
}

TEMPLATE_TEST_CASE("Stress: sliding along floors at any slope neither sticks nor sinks", "[stress]", double, float)
{
    SlidingAlongSlopes<TestType>();
}

TEMPLATE_TEST_CASE("Stress: repeated moves to contact neither stick nor sink", "[stress]", double, float)
{
    RepeatedMovesToContact<TestType>();
}
