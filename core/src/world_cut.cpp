// SPDX-License-Identifier: MIT
// satviz: cutting a body of the world.
//
// OUTLINE
//   The body's outline (a concave body's traced from its pieces' outline edges) is cut in the body frame by
//   SliceAlongSegment. Each part large enough is decomposed and given to AddBody, which computes its mass, centre
//   and inertia, with the velocity of the rigid motion at its new centre. The first part takes the cut body's
//   slot, the others are appended, so no index held elsewhere (contacts of other pairs, a view's pair) shifts.

#include <satviz/slice.h>
#include <satviz/world_cut.h>

#include <algorithm>
#include <map>
#include <utility>

namespace satviz
{
namespace
{

// The velocity of the rigid motion (v at c, turning at w) at point p.
Vec2 VelocityAt(Vec2 v, double w, Vec2 c, Vec2 p)
{
    const Vec2 r = p - c;
    return v + Vec2{-w * r.y, w * r.x};
}

// A part's body definition: the cut body's type, material, place and density; the part's shape.
bool PartDef(const std::vector<Vec2>& outline, const RigidBody& body, double density, DecomposeMethod method,
             BodyDef& def)
{
    const Decomposition pieces = Decompose(outline, method);
    if (!pieces.Ok() || pieces.pieces.empty())
    {
        return false;
    }
    def = BodyDef{};
    if (pieces.pieces.size() == 1)
    {
        def.shape = MakeShape(pieces.pieces[0].polygon);
    }
    else
    {
        def.concave = MakeConcave(pieces.pieces);
    }
    def.type = body.type;
    def.density = density;
    def.material = body.material;
    def.position = body.position;
    def.angle = body.angle;
    return ValidateBodyDef(def).empty();
}

// Area, centroid and second moment about the centroid of a simple outline of unit density (the shoelace sums,
// about the outline's first vertex so that a part far from the body origin loses no digits). A sliver may be too
// thin to decompose, but it still has these.
MassProperties OutlineMass(const std::vector<Vec2>& outline)
{
    MassProperties m;
    const Vec2 o = outline.front();
    double area2 = 0.0;
    Vec2 first{};
    double second = 0.0;
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const Vec2 p = outline[i] - o;
        const Vec2 q = outline[(i + 1) % outline.size()] - o;
        const double cross = Cross(p, q);
        area2 += cross;
        first = first + cross * (p + q);
        second += cross * (Dot(p, p) + Dot(p, q) + Dot(q, q));
    }
    m.mass = 0.5 * area2;
    if (m.mass == 0.0)
    {
        m.center = o;
        return m;
    }
    const Vec2 centroid = (1.0 / (3.0 * area2)) * first;
    m.center = o + centroid;
    m.inertia = second / 12.0 - m.mass * Dot(centroid, centroid);
    return m;
}

} // namespace

std::vector<Vec2> BodyOutline(const RigidBody& body)
{
    if (!body.IsConcave())
    {
        if (body.shape.type != ShapeType::Polygon)
        {
            return {};
        }
        const Vec2Span<double> vertices = body.shape.polygon.Vertices();
        return std::vector<Vec2>(vertices.begin(), vertices.end());
    }
    // Each outline edge is an edge of exactly one piece, not internal, from and to vertices of the outline (the
    // pieces' corners are the outline's own points, copied exactly), and each outline vertex starts one of them.
    std::map<std::pair<double, double>, Vec2> next;
    size_t edges = 0;
    for (const ConcavePart& part : body.concave.parts)
    {
        const Vec2Span<double> v = part.shape.polygon.Vertices();
        const int n = part.shape.polygon.Count();
        for (int i = 0; i < n; ++i)
        {
            if (!part.internal[static_cast<size_t>(i)])
            {
                next[{v[i].x, v[i].y}] = v[(i + 1) % n];
                ++edges;
            }
        }
    }
    if (next.size() != edges || edges < 3)
    {
        return {};
    }
    std::vector<Vec2> outline;
    Vec2 p{next.begin()->first.first, next.begin()->first.second};
    for (size_t k = 0; k < edges; ++k)
    {
        outline.push_back(p);
        const auto it = next.find({p.x, p.y});
        if (it == next.end())
        {
            return {};
        }
        p = it->second;
    }
    // The walk must close after visiting every edge once.
    if (!(p == outline.front()))
    {
        return {};
    }
    return outline;
}

BodyCut CutBody(World& world, int index, Vec2 a, Vec2 b, const CutOptions& options)
{
    BodyCut result;
    if (index < 0 || index >= static_cast<int>(world.bodies.size()))
    {
        result.reason = "no body " + std::to_string(index);
        return result;
    }
    const RigidBody body = world.bodies[static_cast<size_t>(index)];
    const std::vector<Vec2> outline = BodyOutline(body);
    if (outline.empty())
    {
        result.reason = body.shape.type == ShapeType::Circle ? "a circle cannot be cut"
                                                               : "the body's outline could not be traced";
        return result;
    }
    const Transform xf = body.Xf();
    const std::vector<std::vector<Vec2>> parts =
        SliceAlongSegment(outline, InvTransformPoint(xf, a), InvTransformPoint(xf, b), 0.0);

    // The density, from the mass the body has and the area its outline has (a static body has no mass).
    const MassProperties unit = body.IsConcave() ? ComputeMass(body.concave, 1.0) : ComputeMass(body.shape, 1.0);
    const double density = body.type == BodyType::Dynamic && unit.mass > 0.0 ? body.mass / unit.mass : 1.0;

    std::vector<BodyDef> kept;
    std::vector<std::vector<Vec2>> keptOutlines;
    std::vector<const std::vector<Vec2>*> slivers;
    for (const std::vector<Vec2>& part : parts)
    {
        BodyDef def;
        if (0.5 * SignedArea2(part) >= options.minArea && PartDef(part, body, density, options.method, def))
        {
            kept.push_back(def);
            keptOutlines.push_back(part);
        }
        else
        {
            slivers.push_back(&part);
        }
    }
    if (kept.size() < 2)
    {
        result.reason = parts.size() < 2 ? "the segment does not cut the body from side to side"
                                         : "the cut leaves fewer than two parts larger than a sliver";
        return result;
    }

    const Vec2 c = body.WorldCenter();
    const bool dynamic = body.type == BodyType::Dynamic;
    for (const std::vector<Vec2>* part : slivers)
    {
        ++result.slivers;
        if (!dynamic)
        {
            continue; // a static body has no mass to lose
        }
        const MassProperties m = OutlineMass(*part);
        const double mass = density * m.mass;
        const Vec2 r = TransformPoint(xf, m.center) - c;
        const Vec2 v = VelocityAt(body.velocity, body.angularVelocity, c, TransformPoint(xf, m.center));
        result.sliverMass += mass;
        result.sliverMomentum = result.sliverMomentum + mass * v;
        result.sliverSpin += density * m.inertia * body.angularVelocity + mass * Cross(r, v);
    }

    // The new bodies: the first in the cut body's slot, the others appended.
    const size_t first = world.bodies.size();
    for (BodyDef& def : kept)
    {
        if (dynamic)
        {
            // The part's centre of mass in the world, from its own mass properties.
            const MassProperties m =
                def.concave.parts.empty() ? ComputeMass(def.shape, 1.0) : ComputeMass(def.concave, 1.0);
            def.velocity = VelocityAt(body.velocity, body.angularVelocity, c, TransformPoint(xf, m.center));
            def.angularVelocity = body.angularVelocity;
        }
        AddBody(world, def);
    }
    world.bodies[static_cast<size_t>(index)] = std::move(world.bodies[first]);
    world.bodies.erase(world.bodies.begin() + static_cast<std::ptrdiff_t>(first));
    result.bodies.push_back(index);
    for (size_t k = 1; k < kept.size(); ++k)
    {
        result.bodies.push_back(static_cast<int>(first + k - 1));
    }
    result.outlines = std::move(keptOutlines);
    result.cut = true;

    // The body's contacts go; what they touched wakes (it may have rested on the body).
    std::vector<WorldContact> contacts;
    contacts.reserve(world.contacts.size());
    for (WorldContact& contact : world.contacts)
    {
        if (contact.a == index || contact.b == index)
        {
            for (int other : {contact.a, contact.b})
            {
                RigidBody& touched = world.bodies[static_cast<size_t>(other)];
                if (touched.type == BodyType::Dynamic)
                {
                    touched.awake = true;
                    touched.sleepTime = 0.0;
                }
            }
        }
        else
        {
            contacts.push_back(std::move(contact));
        }
    }
    world.contacts = std::move(contacts);
    return result;
}

} // namespace satviz
