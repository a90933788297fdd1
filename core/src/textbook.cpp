// SPDX-License-Identifier: MIT
// satviz: the textbook separating axis test (projection intervals per distinct axis) and its swept form.
#include <satviz/collide.h>
#include <satviz/textbook.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz
{

namespace
{

// A shape placed in A's frame: world = Rotate(xfA.q, local) + xfA.p. Working there keeps a pair far from the
// origin as precise as the same pair at the origin, as in the fast queries.
template <typename S>
struct Placed
{
    const ShapeT<S>* shape = nullptr;
    TransformT<S> xf{}; // the shape's body frame in A's frame

    bool IsPolygon() const { return shape->type == ShapeType::Polygon; }
    const PolygonT<S>& Polygon() const { return shape->polygon; }
    Vec2T<S> Vertex(int i) const { return TransformPoint(xf, Polygon().Vertices()[i]); }
    Vec2T<S> Normal(int i) const { return Rotate(xf.q, Polygon().Normal(i)); }
    Vec2T<S> Center() const { return TransformPoint(xf, IsPolygon() ? Polygon().Centroid() : shape->circle.center); }

    // The projection interval [lo, hi] on u: every vertex's dot product, or the centre's plus and minus the radius.
    void Project(Vec2T<S> u, S& lo, S& hi) const
    {
        if (!IsPolygon())
        {
            const S c = Dot(u, Center());
            lo = c - shape->circle.radius;
            hi = c + shape->circle.radius;
            return;
        }
        lo = std::numeric_limits<S>::infinity();
        hi = -std::numeric_limits<S>::infinity();
        for (int i = 0; i < Polygon().Count(); ++i)
        {
            const S d = Dot(u, Vertex(i));
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    }
};

// One distinct axis in A's frame, with the faces (or vertex, or line of centres) that lie on it.
template <typename S>
struct Candidate
{
    AxisRef faces[kMaxFacesPerAxis]{};
    int faceCount = 0;
    Vec2T<S> u{};
    S slack{}; // how far rounding may have turned u: a few epsilons, more for a short edge far from its origin
};

// Adds direction u from `ref` as a new axis, or to the axis already listed on its line: two directions lie on one
// line when their cross product is within what rounding may have turned them by. A face normal is computed from
// its edge, so its direction carries about eps * R / L for vertices R from the body origin and an edge of length
// L (a fine polygon's opposite faces, parallel in exact arithmetic, differ by that much).
// Of the faces on one line, the one whose world normal points right (or, for a vertical line, up) comes first and
// orients the axis while testing; a trace then names each axis after the face turned towards the other shape
// (NameByFacingFace), which does not change the answer.
template <typename S>
bool PointsRightOrUp(Vec2T<S> world)
{
    const S level = S(64) * std::numeric_limits<S>::epsilon();
    return world.x > level || (std::abs(world.x) <= level && world.y > S(0));
}

template <typename S>
void AddAxis(std::vector<Candidate<S>>& axes, const AxisRef& ref, Vec2T<S> u, S slack, RotT<S> toWorld)
{
    for (Candidate<S>& axis : axes)
    {
        const S tolerance = S(16) * std::numeric_limits<S>::epsilon() + axis.slack + slack;
        if (std::abs(Cross(axis.u, u)) <= tolerance && axis.faceCount < kMaxFacesPerAxis)
        {
            if (!PointsRightOrUp(Rotate(toWorld, axis.u)) && PointsRightOrUp(Rotate(toWorld, u)))
            {
                std::copy_backward(axis.faces, axis.faces + axis.faceCount, axis.faces + axis.faceCount + 1);
                axis.faces[0] = ref;
                axis.u = u;
                ++axis.faceCount;
                return;
            }
            axis.faces[axis.faceCount++] = ref;
            return;
        }
    }
    Candidate<S> axis;
    axis.faces[0] = ref;
    axis.faceCount = 1;
    axis.u = u;
    axis.slack = slack;
    axes.push_back(axis);
}

// The rounding slack of face i's normal (see AddAxis).
template <typename S>
S NormalSlack(const PolygonT<S>& polygon, S reach, int i)
{
    return S(4) * std::numeric_limits<S>::epsilon() * reach / Length(polygon.Edge(i));
}

// The axis from a polygon's vertex nearest to a circle's centre to that centre (Ericson 5.2.6: with the face
// normals, the axes a polygon and a circle need). None when the centre lies on the vertex.
template <typename S>
void AddVertexAxis(std::vector<Candidate<S>>& axes, const Placed<S>& polygon, int side, Vec2T<S> center,
                   RotT<S> toWorld)
{
    int nearest = -1;
    S nearestSquared = std::numeric_limits<S>::infinity();
    for (int i = 0; i < polygon.Polygon().Count(); ++i)
    {
        const S d = LengthSquared(center - polygon.Vertex(i));
        if (d < nearestSquared)
        {
            nearestSquared = d;
            nearest = i;
        }
    }
    if (nearest >= 0 && nearestSquared > S(0))
    {
        AddAxis(axes, {AxisKind::VertexToCenter, side, nearest}, Normalize(center - polygon.Vertex(nearest)), S(0),
                toWorld);
    }
}

// The distinct axes of a pair, in test order: A's face normals, B's, then a circle's axis. With `fixedOnly`, only
// the axes that keep their direction as the shapes translate (a circle's axis turns).
template <typename S>
std::vector<Candidate<S>> DistinctAxes(const Placed<S>& a, const Placed<S>& b, bool fixedOnly, RotT<S> toWorld)
{
    std::vector<Candidate<S>> axes;
    const Placed<S>* shapes[2] = {&a, &b};
    for (int side = 0; side < 2; ++side)
    {
        if (shapes[side]->IsPolygon())
        {
            const PolygonT<S>& polygon = shapes[side]->Polygon();
            S reach = S(0);
            for (const Vec2T<S>& v : polygon.Vertices())
            {
                reach = std::max(reach, Length(v));
            }
            for (int i = 0; i < polygon.Count(); ++i)
            {
                AddAxis(axes, {AxisKind::FaceNormal, side, i}, shapes[side]->Normal(i), NormalSlack(polygon, reach, i),
                        toWorld);
            }
        }
    }
    if (fixedOnly)
    {
        return axes;
    }
    if (a.IsPolygon() != b.IsPolygon())
    {
        const int polygonSide = a.IsPolygon() ? 0 : 1;
        const Placed<S>& polygon = *shapes[polygonSide];
        AddVertexAxis(axes, polygon, polygonSide, shapes[1 - polygonSide]->Center(), toWorld);
    }
    else if (!a.IsPolygon())
    {
        const Vec2T<S> centers = b.Center() - a.Center();
        const Vec2T<S> u = LengthSquared(centers) > S(0) ? Normalize(centers) : Vec2T<S>{S(0), S(1)};
        AddAxis(axes, {AxisKind::CenterToCenter, -1, -1}, u, S(0), toWorld);
    }
    return axes;
}

// Both shapes in A's frame.
template <typename S>
void PlacePair(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
               Placed<S>& pa, Placed<S>& pb)
{
    pa.shape = &a;
    pa.xf = {Vec2T<S>{}, RotT<S>{}};
    pb.shape = &b;
    pb.xf = InvMulTransforms(xfA, xfB);
}

// Both shapes' projection intervals on the axis u: [minA, maxA] and [minB, maxB].
template <typename S>
struct PairIntervals
{
    S minA{};
    S maxA{};
    S minB{};
    S maxB{};
};

template <typename S>
PairIntervals<S> ProjectPair(const Placed<S>& pa, const Placed<S>& pb, Vec2T<S> u)
{
    PairIntervals<S> p;
    pa.Project(u, p.minA, p.maxA);
    pb.Project(u, p.minB, p.maxB);
    return p;
}

// The trace's copy of an axis: world direction and world intervals (A's frame shifted by A's position).
template <typename Axis, typename S>
void ToWorld(const Candidate<S>& c, const TransformT<S>& xfA, S minA, S maxA, S minB, S maxB, Axis& out)
{
    std::copy(c.faces, c.faces + kMaxFacesPerAxis, out.faces);
    out.faceCount = c.faceCount;
    out.direction = Rotate(xfA.q, c.u);
    const S offset = Dot(out.direction, xfA.p);
    out.minA = minA + offset;
    out.maxA = maxA + offset;
    out.minB = minB + offset;
    out.maxB = maxB + offset;
}

// Of the faces on a traced axis, the one a reader looks at names it: A's face turned towards B (`bAhead`: B's
// interval lies along the axis from A's), else B's face turned towards A. The axis then points along that face's
// outward normal, its intervals and B's push (or rate) turned with it, so that the sentence, the number line and
// the picture name one face and measure along its normal. An axis without such a face keeps its first face.
template <typename Axis, typename S>
void NameByFacingFace(Axis& step, const Placed<S>& pa, const Placed<S>& pb, Vec2T<S> u, bool bAhead, int& pushSign,
                      S& rate)
{
    const Placed<S>* shapes[2] = {&pa, &pb};
    for (int side = 0; side < 2; ++side)
    {
        for (int f = 0; f < step.faceCount; ++f)
        {
            const AxisRef face = step.faces[f];
            if (face.kind != AxisKind::FaceNormal || face.shape != side)
            {
                continue;
            }
            const S along = Dot(shapes[side]->Normal(face.index), u);
            // A's face faces B when its normal points the way B lies; B's face when it points back towards A.
            const bool normalAlong = along > S(0);
            if (normalAlong != (bAhead == (side == 0)))
            {
                continue;
            }
            std::copy_backward(step.faces, step.faces + f, step.faces + f + 1);
            step.faces[0] = face;
            if (!normalAlong)
            {
                step.direction = -step.direction;
                const S minA = step.minA;
                const S minB = step.minB;
                step.minA = -step.maxA;
                step.maxA = -minA;
                step.minB = -step.maxB;
                step.maxB = -minB;
                pushSign = -pushSign;
                rate = -rate;
            }
            return;
        }
    }
}

struct NullTracer
{
    static constexpr bool kEnabled = false;
};

struct Recording
{
    static constexpr bool kEnabled = true;
};

// Outline (Ericson, Real-Time Collision Detection, 5.2.1; the MTV as in the classic SAT tutorials):
//   1. list the distinct axes: face normals of both polygons (parallel ones merged), a circle's axis;
//   2. on each axis project both shapes: intervals [minA, maxA] and [minB, maxB];
//   3. disjoint intervals (a gap > 0) prove a separating axis: stop, the shapes do not collide;
//   4. else the overlap is the shorter of the two pushes that separate the intervals, maxA - minB (B along the
//      axis) and maxB - minA (B against it);
//   5. every axis overlapped: the shapes collide, and the axis of the smallest overlap gives the MTV.
template <typename Tracer, typename S>
TextbookResultT<S> TextbookCollideWith(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                                       const TransformT<S>& xfB, TextbookTraceT<S>* trace)
{
    Placed<S> pa;
    Placed<S> pb;
    PlacePair(a, xfA, b, xfB, pa, pb);
    const std::vector<Candidate<S>> axes = DistinctAxes(pa, pb, false, xfA.q);
    const Vec2T<S> centers = pb.Center() - pa.Center();

    TextbookResultT<S> result;
    result.axisCount = static_cast<int>(axes.size());
    S smallest = std::numeric_limits<S>::infinity();
    for (size_t k = 0; k < axes.size(); ++k)
    {
        const Vec2T<S> u = axes[k].u;
        const auto [minA, maxA, minB, maxB] = ProjectPair(pa, pb, u);
        result.axesTested = static_cast<int>(k) + 1;

        const S gapAlong = minB - maxA;   // B beyond A along u
        const S gapAgainst = minA - maxB; // B beyond A against u
        const bool separating = gapAlong > S(0) || gapAgainst > S(0);
        const S pushAlong = maxA - minB;
        const S pushAgainst = maxB - minA;
        int pushSign = 0;
        S overlap{};
        if (!separating)
        {
            // Equal pushes: the one that moves B away from A's centre.
            pushSign = pushAlong < pushAgainst ? 1 : pushAlong > pushAgainst ? -1 : (Dot(u, centers) >= S(0) ? 1 : -1);
            overlap = pushSign > 0 ? pushAlong : pushAgainst;
            if (overlap < smallest)
            {
                smallest = overlap;
                result.axis = static_cast<int>(k);
                result.depth = overlap;
                result.normal = Rotate(xfA.q, S(pushSign) * u);
            }
        }
        if constexpr (Tracer::kEnabled)
        {
            TextbookAxisT<S> step;
            ToWorld(axes[k], xfA, minA, maxA, minB, maxB, step);
            step.separating = separating;
            step.gap = separating ? std::max(gapAlong, gapAgainst) : S(0);
            step.overlap = overlap;
            step.pushSign = pushSign;
            S unused{};
            NameByFacingFace(step, pa, pb, u, separating ? gapAlong > S(0) : pushSign > 0, step.pushSign, unused);
            step.best = result.axis;
            trace->axes.push_back(step);
        }
        if (separating)
        {
            result.overlap = false;
            result.depth = S(0);
            result.gap = std::max(gapAlong, gapAgainst);
            result.normal = Rotate(xfA.q, gapAlong > S(0) ? u : -u);
            result.axis = static_cast<int>(k);
            break;
        }
        result.overlap = true;
    }
    if constexpr (Tracer::kEnabled)
    {
        trace->result = result;
    }
    return result;
}

// The span of t in which B's interval, moving at `rate` relative to A's, overlaps it with positive length.
template <typename S>
void MovingIntervals(S minA, S maxA, S minB, S maxB, S rate, S& entry, S& exit, bool& never)
{
    constexpr S inf = std::numeric_limits<S>::infinity();
    never = false;
    if (rate == S(0))
    {
        const bool overlapping = minB < maxA && maxB > minA;
        never = !overlapping;
        entry = overlapping ? -inf : std::numeric_limits<S>::quiet_NaN();
        exit = overlapping ? inf : std::numeric_limits<S>::quiet_NaN();
        return;
    }
    // B's interval at t: [minB + rate t, maxB + rate t]. It overlaps A's while minB + rate t < maxA and
    // maxB + rate t > minA; each bound is crossed once.
    const S crossFar = (maxA - minB) / rate;  // B's low end passes A's high end
    const S crossNear = (minA - maxB) / rate; // B's high end passes A's low end
    entry = rate < S(0) ? crossFar : crossNear;
    exit = rate < S(0) ? crossNear : crossFar;
}

// Outline (Ericson 5.5.8, intervals moving at a constant rate on each axis):
//   1. on each distinct axis, the intervals at t = 0 and B's rate relative to A;
//   2. they overlap during one span (entry, exit): never (rate 0, disjoint), always (rate 0, overlapping);
//   3. keep the latest entry and the earliest exit; stop with a miss when an axis never overlaps or parts before
//      t = 0, when an entry falls after the step, or when the latest entry is not before the earliest exit;
//   4. otherwise every axis overlaps from the latest entry on: the time of impact (before 0: overlapping already).
template <typename Tracer, typename S>
TextbookSweepResultT<S> TextbookSweepWith(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                                          const TransformT<S>& xfB, Vec2T<S> vB, TextbookSweepTraceT<S>* trace)
{
    TextbookSweepResultT<S> result;
    const Vec2T<S> velocity = vB - vA;
    auto finish = [&](SweepExit exit) {
        if constexpr (Tracer::kEnabled)
        {
            trace->exit = exit;
            trace->result = result;
        }
        return result;
    };
    if (velocity.x == S(0) && velocity.y == S(0))
    {
        const TextbookResultT<S> still = TextbookCollideWith<NullTracer, S>(a, xfA, b, xfB, nullptr);
        result.status = still.overlap && still.depth > S(0) ? SweepStatus::Overlapping : SweepStatus::Miss;
        result.axis = still.axis;
        result.normal = still.normal;
        return finish(SweepExit::NotMoving);
    }

    Placed<S> pa;
    Placed<S> pb;
    PlacePair(a, xfA, b, xfB, pa, pb);
    const bool circles = !pa.IsPolygon() || !pb.IsPolygon();
    const std::vector<Candidate<S>> axes = DistinctAxes(pa, pb, circles, xfA.q);
    const Vec2T<S> v = InvRotate(xfA.q, velocity);
    // Motion along an axis within the rounding of its rate counts as none (as Sweep's StillRate).
    const S still = S(8) * std::numeric_limits<S>::epsilon() * std::max(std::abs(velocity.x), std::abs(velocity.y));

    S latest = -std::numeric_limits<S>::infinity();
    S earliest = std::numeric_limits<S>::infinity();
    int latestAxis = -1;
    int earliestAxis = -1;
    SweepExit exit = SweepExit::AllAxesOverlap;
    for (size_t k = 0; k < axes.size(); ++k)
    {
        const Vec2T<S> u = axes[k].u;
        const auto [minA, maxA, minB, maxB] = ProjectPair(pa, pb, u);
        const S rawRate = Dot(u, v);
        const S rate = std::abs(rawRate) > still ? rawRate : S(0);
        S entry{};
        S leave{};
        bool never = false;
        MovingIntervals(minA, maxA, minB, maxB, rate, entry, leave, never);
        if (!never && (latestAxis < 0 || entry > latest))
        {
            latest = entry;
            latestAxis = static_cast<int>(k);
        }
        if (!never && (earliestAxis < 0 || leave < earliest))
        {
            earliest = leave;
            earliestAxis = static_cast<int>(k);
        }
        // NaN coordinates fail every comparison: such an axis proves nothing and the test goes on.
        const bool ends = never || leave <= S(0) || entry > S(1) || latest >= earliest;
        if (ends)
        {
            exit = never || leave <= S(0) ? SweepExit::NeverCloses
                   : entry > S(1)         ? SweepExit::EntryAfterStep
                                          : SweepExit::EntryAfterExit;
            result.axis = static_cast<int>(k);
        }
        if constexpr (Tracer::kEnabled)
        {
            TextbookSweepAxisT<S> step;
            ToWorld(axes[k], xfA, minA, maxA, minB, maxB, step);
            step.rate = rate;
            int unused = 0;
            // B lies along the axis from A at t = 0 when its interval is the farther one that way (past A's, or
            // overlapping it with the shorter push along the axis).
            NameByFacingFace(step, pa, pb, u, minB - maxA > minA - maxB, unused, step.rate);
            step.entry = entry;
            step.exit = leave;
            step.never = never;
            step.latestEntry = latestAxis;
            step.earliestExit = earliestAxis;
            step.endsTest = ends;
            trace->axes.push_back(step);
        }
        if (ends)
        {
            return finish(exit);
        }
    }

    if (circles)
    {
        // A circle's own axis turns as it moves: the centre's path against the rounded outline decides.
        const SweepResultT<S> cast = Sweep(a, xfA, vA, b, xfB, vB);
        result.status = cast.status;
        result.toi = cast.status == SweepStatus::Hit ? cast.toi : S(0);
        result.normal = cast.status == SweepStatus::Overlapping ? cast.initial.normal : cast.normal;
        result.axis = -1;
        const AxisRef decided = cast.status == SweepStatus::Overlapping ? cast.initial.axis : cast.axis;
        for (size_t k = 0; k < axes.size() && cast.status != SweepStatus::Miss; ++k)
        {
            for (int f = 0; f < axes[k].faceCount; ++f)
            {
                const AxisRef& face = axes[k].faces[f];
                if (face.kind == decided.kind && face.shape == decided.shape && face.index == decided.index)
                {
                    result.axis = static_cast<int>(k);
                }
            }
        }
        if (cast.status != SweepStatus::Miss && decided.kind != AxisKind::FaceNormal)
        {
            result.corner = decided;
        }
        return finish(SweepExit::RoundedOutline);
    }

    result.axis = latestAxis;
    if (latest < S(0))
    {
        result.status = SweepStatus::Overlapping;
        const TextbookResultT<S> initial = TextbookCollideWith<NullTracer, S>(a, xfA, b, xfB, nullptr);
        result.normal = initial.normal;
        result.axis = initial.axis;
        return finish(SweepExit::AllAxesOverlap);
    }
    result.status = SweepStatus::Hit;
    result.toi = latest;
    // B's interval came from the side it moves away from: along the axis when it moves against it.
    const Vec2T<S> u = axes[static_cast<size_t>(latestAxis)].u;
    const S rate = Dot(u, v);
    result.normal = Rotate(xfA.q, rate < S(0) ? u : -u);
    return finish(SweepExit::AllAxesOverlap);
}

} // namespace

template <typename S>
TextbookResultT<S> TextbookCollide(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b,
                                   const TransformT<S>& xfB, TextbookTraceT<S>* trace)
{
    if (trace == nullptr)
    {
        return TextbookCollideWith<NullTracer>(a, xfA, b, xfB, trace);
    }
    trace->Clear();
    return TextbookCollideWith<Recording>(a, xfA, b, xfB, trace);
}

template <typename S>
TextbookSweepResultT<S> TextbookSweep(const ShapeT<S>& a, const TransformT<S>& xfA, Vec2T<S> vA, const ShapeT<S>& b,
                                      const TransformT<S>& xfB, Vec2T<S> vB, TextbookSweepTraceT<S>* trace)
{
    if (trace == nullptr)
    {
        return TextbookSweepWith<NullTracer>(a, xfA, vA, b, xfB, vB, trace);
    }
    trace->Clear();
    return TextbookSweepWith<Recording>(a, xfA, vA, b, xfB, vB, trace);
}

template TextbookResultT<double> TextbookCollide(const ShapeT<double>&, const TransformT<double>&,
                                                 const ShapeT<double>&, const TransformT<double>&,
                                                 TextbookTraceT<double>*);
template TextbookResultT<float> TextbookCollide(const ShapeT<float>&, const TransformT<float>&, const ShapeT<float>&,
                                                const TransformT<float>&, TextbookTraceT<float>*);
template TextbookSweepResultT<double> TextbookSweep(const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                                    const ShapeT<double>&, const TransformT<double>&, Vec2T<double>,
                                                    TextbookSweepTraceT<double>*);
template TextbookSweepResultT<float> TextbookSweep(const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                                   const ShapeT<float>&, const TransformT<float>&, Vec2T<float>,
                                                   TextbookSweepTraceT<float>*);

} // namespace satviz
