// SPDX-License-Identifier: MIT
#include <satviz/collide.h>
#include <satviz/render/study.h>

namespace satviz
{

Transform BodyTransformAt(const Body& body, double t)
{
    return MakeTransform(body.position + t * body.velocity, body.angle);
}

namespace
{

template <typename T, typename S>
ContactPointT<T> Widen(const ContactPointT<S>& c)
{
    return {ConvertVec<T>(c.point), static_cast<T>(c.separation)};
}

template <typename T, typename S>
ManifoldT<T> Widen(const ManifoldT<S>& m)
{
    ManifoldT<T> out;
    out.overlap = m.overlap;
    out.depth = static_cast<T>(m.depth);
    out.gap = static_cast<T>(m.gap);
    out.normal = ConvertVec<T>(m.normal);
    for (int i = 0; i < 2; ++i)
    {
        out.contacts[i] = Widen<T>(m.contacts[i]);
    }
    out.contactCount = m.contactCount;
    out.axis = m.axis;
    out.incidentEdge = m.incidentEdge;
    return out;
}

template <typename T, typename S>
TraceT<T> Widen(const TraceT<S>& trace)
{
    TraceT<T> out;
    for (const AxisTestT<S>& a : trace.axes)
    {
        AxisTestT<T> b;
        b.axis = a.axis;
        b.direction = ConvertVec<T>(a.direction);
        b.minA = a.minA;
        b.maxA = a.maxA;
        b.minB = a.minB;
        b.maxB = a.maxB;
        b.separation = a.separation;
        b.supportA = a.supportA;
        b.supportB = a.supportB;
        b.separating = a.separating;
        b.skipped = a.skipped;
        b.duplicateOf = a.duplicateOf;
        b.pruned = a.pruned;
        b.bound = a.bound;
        b.best = a.best;
        out.axes.push_back(b);
    }
    out.hasClip = trace.hasClip;
    const ClipTraceT<S>& c = trace.clip;
    ClipTraceT<T>& d = out.clip;
    d.reference = c.reference;
    d.referenceV1 = ConvertVec<T>(c.referenceV1);
    d.referenceV2 = ConvertVec<T>(c.referenceV2);
    d.referenceNormal = ConvertVec<T>(c.referenceNormal);
    d.incidentShape = c.incidentShape;
    d.incidentEdge = c.incidentEdge;
    d.incidentV1 = ConvertVec<T>(c.incidentV1);
    d.incidentV2 = ConvertVec<T>(c.incidentV2);
    for (int i = 0; i < 2; ++i)
    {
        d.sideClip1[i] = ConvertVec<T>(c.sideClip1[i]);
        d.sideClip2[i] = ConvertVec<T>(c.sideClip2[i]);
        d.clippedSeparation[i] = c.clippedSeparation[i];
        d.kept[i] = c.kept[i];
    }
    d.sideClip1Count = c.sideClip1Count;
    d.sideClip2Count = c.sideClip2Count;
    d.usedFallback = c.usedFallback;
    out.exit = trace.exit;
    out.result = Widen<T>(trace.result);
    return out;
}

template <typename T, typename S>
SweepTraceT<T> Widen(const SweepTraceT<S>& trace)
{
    SweepTraceT<T> out;
    for (const SweepAxisT<S>& a : trace.axes)
    {
        SweepAxisT<T> b;
        b.axis = a.axis;
        b.direction = ConvertVec<T>(a.direction);
        b.minA = a.minA;
        b.maxA = a.maxA;
        b.minB = a.minB;
        b.maxB = a.maxB;
        b.sweptMinB = a.sweptMinB;
        b.sweptMaxB = a.sweptMaxB;
        b.separation = a.separation;
        b.rate = a.rate;
        b.entry = a.entry;
        b.exit = a.exit;
        b.latestEntry = a.latestEntry;
        b.earliestExit = a.earliestExit;
        b.endsTest = a.endsTest;
        out.axes.push_back(b);
    }
    out.exit = trace.exit;
    return out;
}

template <typename T, typename S>
SweepResultT<T> Widen(const SweepResultT<S>& r)
{
    SweepResultT<T> out;
    out.status = r.status;
    out.toi = r.toi;
    out.normal = ConvertVec<T>(r.normal);
    for (int i = 0; i < 2; ++i)
    {
        out.contacts[i] = Widen<T>(r.contacts[i]);
    }
    out.contactCount = r.contactCount;
    out.axis = r.axis;
    out.initial = Widen<T>(r.initial);
    return out;
}

// The shape rounded to float; false when rounding breaks the polygon.
bool ToFloat(const Shape& shape, ShapeT<float>& out)
{
    if (shape.type == ShapeType::Circle)
    {
        out =
            MakeShape(CircleT<float>{ConvertVec<float>(shape.circle.center), static_cast<float>(shape.circle.radius)});
        return true;
    }
    PolygonResultT<float> polygon = ConvertPolygon<float>(shape.polygon);
    if (!polygon.Ok())
    {
        return false;
    }
    out = MakeShape(std::move(polygon.polygon));
    return true;
}

// The single-precision queries; false when a shape does not survive rounding to float.
bool StudyInFloat(const Body& bodyA, const Body& bodyB, PairStudy& study)
{
    ShapeT<float> a;
    ShapeT<float> b;
    if (!ToFloat(bodyA.shape, a) || !ToFloat(bodyB.shape, b))
    {
        return false;
    }
    const TransformT<float> xfA = MakeTransform(ConvertVec<float>(bodyA.position), static_cast<float>(bodyA.angle));
    const TransformT<float> xfB = MakeTransform(ConvertVec<float>(bodyB.position), static_cast<float>(bodyB.angle));
    TraceT<float> trace;
    study.manifold = Widen<double>(Collide(a, xfA, b, xfB, &trace));
    study.trace = Widen<double>(trace);
    if (study.sweep)
    {
        SweepTraceT<float> sweepTrace;
        study.sweepResult = Widen<double>(
            Sweep(a, xfA, ConvertVec<float>(bodyA.velocity), b, xfB, ConvertVec<float>(bodyB.velocity), &sweepTrace));
        study.sweepTrace = Widen<double>(sweepTrace);
    }
    return true;
}

} // namespace

PairStudy StudyPair(const Scene& scene, int a, int b, ViewQuery query, bool singlePrecision)
{
    PairStudy study;
    study.bodyA = a;
    study.bodyB = b;
    const Body& bodyA = scene.bodies[static_cast<size_t>(a)];
    const Body& bodyB = scene.bodies[static_cast<size_t>(b)];
    const Transform xfA = bodyA.Xf();
    const Transform xfB = bodyB.Xf();
    const bool moving = bodyA.velocity != bodyB.velocity;
    study.sweep = query == ViewQuery::Sweep || (query == ViewQuery::Automatic && moving);
    study.singlePrecision = singlePrecision && StudyInFloat(bodyA, bodyB, study);
    if (!study.singlePrecision)
    {
        study.manifold = Collide(bodyA.shape, xfA, bodyB.shape, xfB, &study.trace);
        if (study.sweep)
        {
            study.sweepResult =
                Sweep(bodyA.shape, xfA, bodyA.velocity, bodyB.shape, xfB, bodyB.velocity, &study.sweepTrace);
        }
    }
    if (study.sweep)
    {
        if (study.sweepResult.status == SweepStatus::Overlapping)
        {
            study.sweep = false;
            study.startsOverlapping = true;
        }
    }
    return study;
}

} // namespace satviz
