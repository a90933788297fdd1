// SPDX-License-Identifier: MIT
#include <satviz/collide.h>
#include <satviz/render/describe.h>
#include <satviz/render/pitfall.h>
#include <satviz/sweep.h>
#include <satviz/textbook.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace satviz
{

namespace
{

// A polygon's vertices in the world.
std::vector<Vec2> World(const Body& body)
{
    std::vector<Vec2> out;
    for (const Vec2& v : body.shape.polygon.Vertices())
    {
        out.push_back(TransformPoint(body.Xf(), v));
    }
    return out;
}

void Project(const std::vector<Vec2>& points, Vec2 axis, double& lo, double& hi)
{
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const Vec2& p : points)
    {
        lo = std::min(lo, Dot(axis, p));
        hi = std::max(hi, Dot(axis, p));
    }
}

std::string AxisName(const Scene& scene, int body, int edge)
{
    return scene.bodies[static_cast<size_t>(body)].name + "'s edge " + std::to_string(edge);
}

// The mistake: overlaps on edge normals that are not unit length, compared as if they were.
PitfallResult Unnormalised(const Scene& scene, int a, int b, const TextbookResult& right)
{
    PitfallResult out;
    out.ran = true;
    const std::vector<Vec2> pa = World(scene.bodies[static_cast<size_t>(a)]);
    const std::vector<Vec2> pb = World(scene.bodies[static_cast<size_t>(b)]);
    double smallest = std::numeric_limits<double>::infinity();
    int chosenBody = -1;
    int chosenEdge = -1;
    double length = 1.0;
    out.overlap = true;
    for (int side = 0; side < 2 && out.overlap; ++side)
    {
        const std::vector<Vec2>& own = side == 0 ? pa : pb;
        for (size_t i = 0; i < own.size() && out.overlap; ++i)
        {
            const Vec2 n = RightPerp(own[(i + 1) % own.size()] - own[i]); // length: the edge's
            double minA = 0.0, maxA = 0.0, minB = 0.0, maxB = 0.0;
            Project(pa, n, minA, maxA);
            Project(pb, n, minB, maxB);
            if (minB > maxA || minA > maxB)
            {
                out.overlap = false;
                break;
            }
            const double along = maxA - minB;
            const double against = maxB - minA;
            const double overlap = std::min(along, against);
            if (overlap < smallest)
            {
                smallest = overlap;
                chosenBody = side == 0 ? a : b;
                chosenEdge = static_cast<int>(i);
                length = Length(n);
                out.normal = (along <= against ? 1.0 : -1.0) * Normalize(n);
            }
        }
    }
    if (!out.overlap)
    {
        out.verdict = "Pitfall (unnormalised axes): a gap has the same sign on any axis length, so this mistake "
                      "still finds the separating axis.";
        return out;
    }
    out.depth = smallest;
    out.verdict = "Pitfall (unnormalised axes): comparing overlaps on edge normals as long as their edges picks " +
                  AxisName(scene, chosenBody, chosenEdge) + " (normal " + FormatNumber(length) +
                  " long) and a 'depth' of " + FormatNumber(smallest) + " = " + FormatNumber(smallest / length) +
                  " x " + FormatNumber(length) + "; on unit axes the MTV is " + FormatNumber(right.depth) + ".";
    return out;
}

// The mistake: every face normal of both shapes tried in turn, each as the polygon lists it (A's first), the overlap
// taken as the intervals' common part, and B pushed along the normal of the first face with the smallest one,
// whichever way that normal points. The faces are the shapes' own, not the test's axes: the test points each axis
// along the face turned towards the other shape, which is the very check this mistake leaves out.
PitfallResult Unchecked(const Scene& scene, int a, int b, const TextbookResult& right)
{
    PitfallResult out;
    out.ran = true;
    out.overlap = right.overlap;
    if (!out.overlap)
    {
        out.verdict = "Pitfall (unchecked direction): the shapes are apart, so there is no push to get wrong.";
        return out;
    }
    const std::vector<Vec2> pa = World(scene.bodies[static_cast<size_t>(a)]);
    const std::vector<Vec2> pb = World(scene.bodies[static_cast<size_t>(b)]);
    double smallest = std::numeric_limits<double>::infinity();
    int chosenBody = -1;
    int chosenEdge = -1;
    for (int side = 0; side < 2; ++side)
    {
        const std::vector<Vec2>& own = side == 0 ? pa : pb;
        for (size_t i = 0; i < own.size(); ++i)
        {
            const Vec2 n = Normalize(RightPerp(own[(i + 1) % own.size()] - own[i]));
            double minA = 0.0, maxA = 0.0, minB = 0.0, maxB = 0.0;
            Project(pa, n, minA, maxA);
            Project(pb, n, minB, maxB);
            const double common = std::min(maxA, maxB) - std::max(minA, minB);
            if (common < smallest)
            {
                smallest = common;
                out.normal = n;
                chosenBody = side == 0 ? a : b;
                chosenEdge = static_cast<int>(i);
            }
        }
    }
    out.depth = smallest;
    const bool inward = Dot(out.normal, right.normal) < 0.0;
    const std::string& nameA = scene.bodies[static_cast<size_t>(a)].name;
    const std::string& nameB = scene.bodies[static_cast<size_t>(b)].name;
    out.verdict = "Pitfall (unchecked direction): taking the intervals' common part, " + FormatNumber(smallest) +
                  ", and pushing " + nameB + " along the normal of " + AxisName(scene, chosenBody, chosenEdge) +
                  " as it points, (" + FormatNumber(out.normal.x) + ", " + FormatNumber(out.normal.y) + "), " +
                  (inward ? "drives " + nameB + " into " + nameA + " instead of out of it"
                          : std::string("happens to push the right way here, by luck")) +
                  "; the MTV moves " + nameB + " " + FormatNumber(right.depth) + " along (" + FormatNumber(right.normal.x) + ", " +
                  FormatNumber(right.normal.y) + ").";
    return out;
}

// The mistake: only A's face normals tested.
PitfallResult OneShape(const Scene& scene, int a, int b, const TextbookTrace& right)
{
    PitfallResult out;
    out.ran = true;
    const std::vector<Vec2> pa = World(scene.bodies[static_cast<size_t>(a)]);
    const std::vector<Vec2> pb = World(scene.bodies[static_cast<size_t>(b)]);
    out.overlap = true;
    double smallest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < pa.size(); ++i)
    {
        const Vec2 n = Normalize(RightPerp(pa[(i + 1) % pa.size()] - pa[i]));
        double minA = 0.0, maxA = 0.0, minB = 0.0, maxB = 0.0;
        Project(pa, n, minA, maxA);
        Project(pb, n, minB, maxB);
        if (minB > maxA || minA > maxB)
        {
            out.overlap = false;
            break;
        }
        const double along = maxA - minB;
        const double against = maxB - minA;
        if (std::min(along, against) < smallest)
        {
            smallest = std::min(along, against);
            out.normal = (along <= against ? 1.0 : -1.0) * n;
        }
    }
    out.depth = out.overlap ? smallest : 0.0;
    const std::string nameA = scene.bodies[static_cast<size_t>(a)].name;
    if (out.overlap && !right.result.overlap)
    {
        out.verdict = "Pitfall (only " + nameA + "'s axes): no face normal of " + nameA +
                      " shows a gap, so it says the shapes collide; the separating axis is a face normal of the other "
                      "shape.";
    }
    else if (out.overlap)
    {
        out.verdict = "Pitfall (only " + nameA + "'s axes): it finds the collision, with a 'depth' of " +
                      FormatNumber(smallest) + " where the MTV is " + FormatNumber(right.result.depth) + ".";
    }
    else
    {
        out.verdict = "Pitfall (only " + nameA + "'s axes): here one of " + nameA +
                      "'s face normals separates, so the mistake goes unnoticed.";
    }
    return out;
}

// The mistake: a moving pair tested where it is at the start and at the end of the step.
PitfallResult Sampled(const Scene& scene, int a, int b)
{
    PitfallResult out;
    const Body& ba = scene.bodies[static_cast<size_t>(a)];
    const Body& bb = scene.bodies[static_cast<size_t>(b)];
    if (ba.velocity == bb.velocity)
    {
        out.verdict = "Pitfall (sampled motion): nothing moves relative to the other, so there is nothing to sample.";
        return out;
    }
    out.ran = true;
    auto at = [](const Body& body, double t) { return MakeTransform(body.position + t * body.velocity, body.angle); };
    const bool start = Overlap(ba.shape, at(ba, 0.0), bb.shape, at(bb, 0.0));
    const bool end = Overlap(ba.shape, at(ba, 1.0), bb.shape, at(bb, 1.0));
    out.overlap = start || end;
    const SweepResult swept = Sweep(ba.shape, ba.Xf(), ba.velocity, bb.shape, bb.Xf(), bb.velocity);
    const std::string samples = std::string("at t = 0 the shapes ") + (start ? "overlap" : "are apart") +
                                ", at t = 1 they " + (end ? "overlap" : "are apart");
    if (!out.overlap && swept.status == SweepStatus::Hit)
    {
        out.verdict = "Pitfall (sampled motion): " + samples +
                      ", so it sees no collision: the shapes tunnel "
                      "through each other. The swept test finds first contact at t = " +
                      FormatNumber(swept.toi) + ".";
    }
    else
    {
        out.verdict = "Pitfall (sampled motion): " + samples +
                      "; here the samples catch the contact, but only by the "
                      "luck of where the step ends.";
    }
    return out;
}

// The mistake: the world coordinates in float, where far from the origin they keep only a few decimals.
PitfallResult FloatWorld(const Scene& scene, int a, int b, const TextbookResult& right)
{
    PitfallResult out;
    out.ran = true;
    auto world = [&](const Body& body) {
        const RotT<float> q = MakeRot(static_cast<float>(body.angle));
        const Vec2T<float> p = ConvertVec<float>(body.position);
        std::vector<Vec2T<float>> points;
        for (const Vec2& v : body.shape.polygon.Vertices())
        {
            points.push_back(Rotate(q, ConvertVec<float>(v)) + p);
        }
        return points;
    };
    const std::vector<Vec2T<float>> pa = world(scene.bodies[static_cast<size_t>(a)]);
    const std::vector<Vec2T<float>> pb = world(scene.bodies[static_cast<size_t>(b)]);
    auto project = [](const std::vector<Vec2T<float>>& points, Vec2T<float> n, float& lo, float& hi) {
        lo = std::numeric_limits<float>::infinity();
        hi = -lo;
        for (const Vec2T<float>& p : points)
        {
            lo = std::min(lo, Dot(n, p));
            hi = std::max(hi, Dot(n, p));
        }
    };
    out.overlap = true;
    float smallest = std::numeric_limits<float>::infinity();
    for (int side = 0; side < 2 && out.overlap; ++side)
    {
        const std::vector<Vec2T<float>>& own = side == 0 ? pa : pb;
        for (size_t i = 0; i < own.size(); ++i)
        {
            const Vec2T<float> n = Normalize(RightPerp(own[(i + 1) % own.size()] - own[i]));
            float minA = 0.0f, maxA = 0.0f, minB = 0.0f, maxB = 0.0f;
            project(pa, n, minA, maxA);
            project(pb, n, minB, maxB);
            if (minB > maxA || minA > maxB)
            {
                out.overlap = false;
                break;
            }
            const float along = maxA - minB;
            const float against = maxB - minA;
            if (std::min(along, against) < smallest)
            {
                smallest = std::min(along, against);
                out.normal = ConvertVec<double>((along <= against ? 1.0f : -1.0f) * n);
            }
        }
    }
    out.depth = out.overlap ? static_cast<double>(smallest) : 0.0;
    const Body& body = scene.bodies[static_cast<size_t>(a)];
    const float far = static_cast<float>(std::max(std::abs(body.position.x), std::abs(body.position.y)));
    const std::string step = ShortestDecimal(std::nextafter(far, INFINITY) - far);
    const std::string said = out.overlap ? "a depth of " + FormatNumber(out.depth) : std::string("no collision");
    out.verdict = "Pitfall (float on world coordinates): at " + FormatNumber(far) +
                  " from the origin a float coordinate moves in steps of " + step + ", so it finds " + said +
                  ", where double in A's frame finds " +
                  (right.overlap ? "a depth of " + FormatNumber(right.depth) : std::string("no collision")) + ".";
    return out;
}

} // namespace

PitfallResult RunPitfall(Pitfall pitfall, const Scene& scene, int a, int b)
{
    const Body& ba = scene.bodies[static_cast<size_t>(a)];
    const Body& bb = scene.bodies[static_cast<size_t>(b)];
    if (pitfall == Pitfall::None)
    {
        return {};
    }
    if (pitfall == Pitfall::SampledMotion)
    {
        return Sampled(scene, a, b);
    }
    if (ba.shape.type != ShapeType::Polygon || bb.shape.type != ShapeType::Polygon)
    {
        PitfallResult none;
        none.verdict = "(This pitfall is shown for two polygons.)";
        return none;
    }
    TextbookTrace trace;
    TextbookCollide(ba.shape, ba.Xf(), bb.shape, bb.Xf(), &trace);
    switch (pitfall)
    {
    case Pitfall::UnnormalisedAxes:
        return Unnormalised(scene, a, b, trace.result);
    case Pitfall::UncheckedDirection:
        return Unchecked(scene, a, b, trace.result);
    case Pitfall::OneShapesAxes:
        return OneShape(scene, a, b, trace);
    case Pitfall::FloatWorld:
        return FloatWorld(scene, a, b, trace.result);
    default:
        break;
    }
    return {};
}

} // namespace satviz
