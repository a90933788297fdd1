// SPDX-License-Identifier: MIT
#include <satviz/collide.h>
#include <satviz/render/study.h>

#include <algorithm>

namespace satviz
{

Transform BodyTransformAt(const Body& body, double t)
{
    return MakeTransform(body.position + t * body.velocity, body.angle);
}

namespace
{

// Every kind of axis record (the face tests', the sweep's, the textbook test's) carries the axis and both shapes'
// intervals on it under the same names; the widening of those is one.
template <typename From, typename To>
void WidenIntervals(const From& a, To& b)
{
    using T = decltype(b.minA);
    b.direction = ConvertVec<T>(a.direction);
    b.minA = a.minA;
    b.maxA = a.maxA;
    b.minB = a.minB;
    b.maxB = a.maxB;
}

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
        WidenIntervals(a, b);
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
        WidenIntervals(a, b);
        b.sweptMinB = a.sweptMinB;
        b.sweptMaxB = a.sweptMaxB;
        b.separation = a.separation;
        b.rate = a.rate;
        b.entry = a.entry;
        b.exit = a.exit;
        b.latestEntry = a.latestEntry;
        b.earliestExit = a.earliestExit;
        b.endsTest = a.endsTest;
        b.bounded = a.bounded;
        b.bound = a.bound;
        b.boundTime = a.boundTime;
        b.knownEntry = a.knownEntry;
        b.exitPass = a.exitPass;
        b.skipped = a.skipped;
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

// The faces a textbook axis stands for, and its intervals.
template <typename From, typename To>
void WidenTextbookAxis(const From& a, To& b)
{
    std::copy(a.faces, a.faces + kMaxFacesPerAxis, b.faces);
    b.faceCount = a.faceCount;
    WidenIntervals(a, b);
}

TextbookResult Widen(const TextbookResultT<float>& r)
{
    TextbookResult out;
    out.overlap = r.overlap;
    out.depth = r.depth;
    out.gap = r.gap;
    out.normal = ConvertVec<double>(r.normal);
    out.axis = r.axis;
    out.axesTested = r.axesTested;
    out.axisCount = r.axisCount;
    return out;
}

TextbookTrace Widen(const TextbookTraceT<float>& trace)
{
    TextbookTrace out;
    for (const TextbookAxisT<float>& a : trace.axes)
    {
        TextbookAxis b;
        WidenTextbookAxis(a, b);
        b.separating = a.separating;
        b.gap = a.gap;
        b.overlap = a.overlap;
        b.pushSign = a.pushSign;
        b.best = a.best;
        out.axes.push_back(b);
    }
    out.result = Widen(trace.result);
    return out;
}

TextbookSweepResult Widen(const TextbookSweepResultT<float>& r)
{
    TextbookSweepResult out;
    out.status = r.status;
    out.toi = r.toi;
    out.normal = ConvertVec<double>(r.normal);
    out.axis = r.axis;
    out.corner = r.corner;
    return out;
}

TextbookSweepTrace Widen(const TextbookSweepTraceT<float>& trace)
{
    TextbookSweepTrace out;
    for (const TextbookSweepAxisT<float>& a : trace.axes)
    {
        TextbookSweepAxis b;
        WidenTextbookAxis(a, b);
        b.rate = a.rate;
        b.entry = a.entry;
        b.exit = a.exit;
        b.never = a.never;
        b.latestEntry = a.latestEntry;
        b.earliestExit = a.earliestExit;
        b.endsTest = a.endsTest;
        out.axes.push_back(b);
    }
    out.exit = trace.exit;
    out.result = Widen(trace.result);
    return out;
}

// The textbook test's work for a pair: every vertex projected on every axis.
long long TextbookWork(const Shape& a, const Shape& b)
{
    auto count = [](const Shape& s) { return s.type == ShapeType::Polygon ? s.polygon.Count() : 1LL; };
    const long long n = count(a) + count(b);
    return n * n;
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
    const Vec2T<float> vA = ConvertVec<float>(bodyA.velocity);
    const Vec2T<float> vB = ConvertVec<float>(bodyB.velocity);
    if (study.sweep)
    {
        SweepTraceT<float> sweepTrace;
        study.sweepResult = Widen<double>(Sweep(a, xfA, vA, b, xfB, vB, &sweepTrace));
        study.sweepTrace = Widen<double>(sweepTrace);
    }
    if (study.Textbook())
    {
        TextbookTraceT<float> textbook;
        study.textbookResult = Widen(TextbookCollide(a, xfA, b, xfB, &textbook));
        study.textbook = Widen(textbook);
        if (study.sweep)
        {
            TextbookSweepTraceT<float> textbookSweep;
            study.textbookSweepResult = Widen(TextbookSweep(a, xfA, vA, b, xfB, vB, &textbookSweep));
            study.textbookSweep = Widen(textbookSweep);
        }
    }
    return true;
}

// Where the shapes meet, the contact's reference face is the face the verdict's picture marks. When it lies on a
// textbook axis it names that axis, which then points along its outward normal (the test names an axis after A's
// face turned towards B, which the reference face is but for rounding; here the two cannot differ).
void NameByReferenceFace(const Scene& scene, PairStudy& study)
{
    const AxisRef& reference = study.trace.clip.reference;
    if (!study.trace.hasClip || reference.kind != AxisKind::FaceNormal)
    {
        return;
    }
    const Body& body = scene.bodies[static_cast<size_t>(reference.shape == 0 ? study.bodyA : study.bodyB)];
    const Vec2 normal = Rotate(body.Xf().q, body.shape.polygon.Normal(reference.index));
    for (TextbookAxis& t : study.textbook.axes)
    {
        for (int f = 1; f < t.faceCount; ++f)
        {
            const AxisRef face = t.faces[f];
            if (face.kind != reference.kind || face.shape != reference.shape || face.index != reference.index)
            {
                continue;
            }
            std::copy_backward(t.faces, t.faces + f, t.faces + f + 1);
            t.faces[0] = face;
            if (Dot(normal, t.direction) < 0.0)
            {
                t.direction = -t.direction;
                const double minA = t.minA;
                const double minB = t.minB;
                t.minA = -t.maxA;
                t.maxA = -minA;
                t.minB = -t.maxB;
                t.maxB = -minB;
                t.pushSign = -t.pushSign;
            }
        }
    }
}

} // namespace

PairStudy StudyPair(const Scene& scene, int a, int b, ViewQuery query, bool singlePrecision, StepView steps)
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
    study.steps = steps;
    if (steps == StepView::Textbook && TextbookWork(bodyA.shape, bodyB.shape) > kTextbookBudget)
    {
        study.steps = StepView::Faces;
        study.textbookTooLarge = true;
    }
    study.singlePrecision = singlePrecision && StudyInFloat(bodyA, bodyB, study);
    if (!study.singlePrecision)
    {
        study.manifold = Collide(bodyA.shape, xfA, bodyB.shape, xfB, &study.trace);
        if (study.sweep)
        {
            study.sweepResult =
                Sweep(bodyA.shape, xfA, bodyA.velocity, bodyB.shape, xfB, bodyB.velocity, &study.sweepTrace);
        }
        if (study.Textbook())
        {
            study.textbookResult = TextbookCollide(bodyA.shape, xfA, bodyB.shape, xfB, &study.textbook);
            if (study.sweep)
            {
                study.textbookSweepResult = TextbookSweep(bodyA.shape, xfA, bodyA.velocity, bodyB.shape, xfB,
                                                          bodyB.velocity, &study.textbookSweep);
            }
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
    if (study.Textbook() && !study.sweep)
    {
        NameByReferenceFace(scene, study);
    }
    return study;
}

} // namespace satviz
