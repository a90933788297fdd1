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

// A polygon's vertices in the world, placed in precision S.
template <typename S>
std::vector<Vec2T<S>> World(const Body& body)
{
    const TransformT<S> xf = MakeTransform(ConvertVec<S>(body.position), static_cast<S>(body.angle));
    std::vector<Vec2T<S>> out;
    for (const Vec2& v : body.shape.polygon.Vertices())
    {
        out.push_back(TransformPoint(xf, ConvertVec<S>(v)));
    }
    return out;
}

template <typename S>
void Project(const std::vector<Vec2T<S>>& points, Vec2T<S> axis, S& lo, S& hi)
{
    lo = std::numeric_limits<S>::infinity();
    hi = -lo;
    for (const Vec2T<S>& p : points)
    {
        lo = std::min(lo, Dot(axis, p));
        hi = std::max(hi, Dot(axis, p));
    }
}

// What a scan of face normals found: whether every face showed an overlap, and the smallest overlap with the face
// that gave it and the unit normal that pushes B out along it.
template <typename S>
struct FaceScan
{
    bool overlap = true;
    S smallest = std::numeric_limits<S>::infinity();
    Vec2T<S> normal{};
    int side = -1; ///< 0: a face of A, 1: of B
    int edge = -1;
    S length = 1; ///< the length of the normal the overlap was measured on
};

// The textbook test's loop, which most mistakes keep: the face normals of A (and of B when `sides` is 2) in turn,
// both shapes projected on each, a gap ending the scan, else the smaller push of the two ways kept when it is the
// smallest so far. `unitNormals` false measures on the edge's perpendicular, as long as the edge.
template <typename S>
FaceScan<S> ScanFaces(const Scene& scene, int a, int b, int sides, bool unitNormals)
{
    const std::vector<Vec2T<S>> pa = World<S>(scene.bodies[static_cast<size_t>(a)]);
    const std::vector<Vec2T<S>> pb = World<S>(scene.bodies[static_cast<size_t>(b)]);
    FaceScan<S> scan;
    for (int side = 0; side < sides && scan.overlap; ++side)
    {
        const std::vector<Vec2T<S>>& own = side == 0 ? pa : pb;
        for (size_t i = 0; i < own.size(); ++i)
        {
            const Vec2T<S> perp = RightPerp(own[(i + 1) % own.size()] - own[i]);
            const Vec2T<S> unit = Normalize(perp);
            const Vec2T<S> n = unitNormals ? unit : perp;
            S minA{}, maxA{}, minB{}, maxB{};
            Project(pa, n, minA, maxA);
            Project(pb, n, minB, maxB);
            if (minB > maxA || minA > maxB)
            {
                scan.overlap = false;
                break;
            }
            const S along = maxA - minB;
            const S against = maxB - minA;
            if (std::min(along, against) < scan.smallest)
            {
                scan.smallest = std::min(along, against);
                scan.side = side;
                scan.edge = static_cast<int>(i);
                scan.length = Length(n);
                scan.normal = (along <= against ? S(1) : S(-1)) * unit;
            }
        }
    }
    return scan;
}

// A mistake's answer as its scan found it, in double.
template <typename S>
PitfallResult Answer(const FaceScan<S>& scan)
{
    PitfallResult out;
    out.ran = true;
    out.overlap = scan.overlap;
    out.depth = scan.overlap ? static_cast<double>(scan.smallest) : 0.0;
    out.normal = ConvertVec<double>(scan.normal);
    return out;
}

std::string AxisName(const Scene& scene, int body, int edge)
{
    return scene.bodies[static_cast<size_t>(body)].name + "'s edge " + std::to_string(edge);
}

// The mistake: overlaps on edge normals that are not unit length, compared as if they were.
PitfallResult Unnormalised(const Scene& scene, int a, int b, const TextbookResult& right)
{
    const FaceScan<double> scan = ScanFaces<double>(scene, a, b, 2, false);
    PitfallResult out = Answer(scan);
    if (!out.overlap)
    {
        out.verdict = "Pitfall (unnormalised axes): a gap has the same sign on any axis length, so this mistake "
                      "still finds the separating axis.";
        return out;
    }
    const double smallest = scan.smallest;
    const int chosenBody = scan.side == 0 ? a : b;
    const int chosenEdge = scan.edge;
    const double length = scan.length;
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
    const std::vector<Vec2> pa = World<double>(scene.bodies[static_cast<size_t>(a)]);
    const std::vector<Vec2> pb = World<double>(scene.bodies[static_cast<size_t>(b)]);
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
    const FaceScan<double> scan = ScanFaces<double>(scene, a, b, 1, true);
    PitfallResult out = Answer(scan);
    const double smallest = scan.smallest;
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
    PitfallResult out = Answer(ScanFaces<float>(scene, a, b, 2, true));
    const Body& body = scene.bodies[static_cast<size_t>(a)];
    const float far = static_cast<float>(std::max(std::abs(body.position.x), std::abs(body.position.y)));
    const std::string step = ShortestDecimal(std::nextafter(far, INFINITY) - far);
    const std::string said = out.overlap ? "a depth of " + FormatNumber(out.depth) : std::string("no collision");
    // In one form with the pair's largest coordinate, which the verdict's precision note gives just before
    // (1000000.00 beside 1000001.47, not 1 000 000).
    const Body& other = scene.bodies[static_cast<size_t>(b)];
    const double largest = std::max({std::abs(body.position.x), std::abs(body.position.y), std::abs(other.position.x),
                                     std::abs(other.position.y)});
    const std::string farText = FormatAlike({static_cast<double>(far), largest})[0];
    out.verdict = "Pitfall (float on world coordinates): a float coordinate as large as A's (" + farText +
                  ") moves in steps of " + step + ", so it finds " + said +
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
