// SPDX-License-Identifier: MIT
// satviz: the rigid-body world: bodies, the step, and what it counts.

#include "body_queries.h"
#include "contact_solver.h"
#include "time_of_impact.h"
#include "world_lookup.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>
#include <satviz/world.h>

#include <algorithm>
#include <cmath>
#include <queue>

namespace satviz
{

namespace
{

using detail::FindContact;
using detail::IsAwakeDynamic;
using detail::SolverBody;
using detail::SolverContact;

bool FiniteNumber(double x)
{
    return std::isfinite(x);
}

// Identifies a contact point from step to step: the deciding axis (kind, shape, index), the incident edge and the
// point's slot. Points whose features persist keep their impulses (warm starting).
uint32_t FeatureKey(const Manifold& m, int slot)
{
    const uint32_t kind = static_cast<uint32_t>(m.axis.kind) & 3u;
    const uint32_t shape = static_cast<uint32_t>(m.axis.shape + 1) & 3u;
    const uint32_t index = static_cast<uint32_t>(m.axis.index + 1) & 0x1fffu;
    const uint32_t incident = static_cast<uint32_t>(m.incidentEdge + 1) & 0x1fffu;
    return kind | shape << 2 | index << 4 | incident << 17 | static_cast<uint32_t>(slot) << 30;
}

// The same for a pair with a concave body: the deciding pieces are folded into the high bits of the index and the
// incident edge (a piece's own edges are few), so that a point on another piece is another point.
uint32_t FeatureKey(const Manifold& m, int pieceA, int pieceB, int slot)
{
    const uint32_t foldA = static_cast<uint32_t>(pieceA + 1) & 0x3fu;
    const uint32_t foldB = static_cast<uint32_t>(pieceB + 1) & 0x3fu;
    return FeatureKey(m, slot) ^ (foldA << 11 | foldB << 24);
}

struct PairFilter
{
    const std::vector<RigidBody>* bodies = nullptr;
    bool skipStatic = true;
};

// A pair is skipped when both bodies are static (if the world skips those) or when neither is awake and dynamic.
bool SkipPair(const void* context, int i, int j)
{
    const PairFilter& filter = *static_cast<const PairFilter*>(context);
    const RigidBody& a = (*filter.bodies)[i];
    const RigidBody& b = (*filter.bodies)[j];
    if (a.type == BodyType::Static && b.type == BodyType::Static)
    {
        return filter.skipStatic;
    }
    return !IsAwakeDynamic(a) && !IsAwakeDynamic(b);
}

// Wakes the sleeping bodies in `seeds` and every sleeping dynamic body joined to them through contacts: an island
// wakes as a whole. Static bodies do not join islands.
void WakeIslands(World& world, std::vector<int>& seeds)
{
    std::vector<RigidBody>& bodies = world.bodies;
    if (seeds.empty())
    {
        return;
    }
    const int n = static_cast<int>(bodies.size());
    std::vector<int> start(n + 1, 0);
    for (const WorldContact& c : world.contacts)
    {
        ++start[c.a + 1];
        ++start[c.b + 1];
    }
    for (int i = 0; i < n; ++i)
    {
        start[i + 1] += start[i];
    }
    std::vector<int> next(start.begin(), start.end() - 1);
    std::vector<int> neighbours(start[n]);
    for (const WorldContact& c : world.contacts)
    {
        neighbours[next[c.a]++] = c.b;
        neighbours[next[c.b]++] = c.a;
    }
    while (!seeds.empty())
    {
        const int i = seeds.back();
        seeds.pop_back();
        RigidBody& body = bodies[i];
        if (body.type != BodyType::Dynamic || body.awake)
        {
            continue;
        }
        body.awake = true;
        body.sleepTime = 0.0;
        for (int k = start[i]; k < start[i + 1]; ++k)
        {
            seeds.push_back(neighbours[k]);
        }
    }
}

// q turned by a small angle: the rotation by (1, angle) normalised, which costs no sine or cosine. The passes use
// it for their anchors; the body's angle is summed exactly and its rotation taken from it at the end.
Rot TurnBy(Rot q, double angle)
{
    const double c = q.c - angle * q.s;
    const double s = q.s + angle * q.c;
    // |(c, s)|^2 = 1 + x with x about angle^2. A pass turns a body by little, and for small x the series
    // 1 - x/2 + 3x^2/8 of 1/sqrt(1 + x) is exact to rounding (its next term, 5x^3/16, is below 1e-16), without a
    // square root or a division.
    const double x = c * c + s * s - 1.0;
    const double inv = std::fabs(x) < 1e-6 ? 1.0 - x * (0.5 - 0.375 * x) : 1.0 / std::sqrt(1.0 + x);
    return {c * inv, s * inv};
}

// Union-find over body indices, for the islands of sleeping.
int FindRoot(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

} // namespace

std::string ValidateBodyDef(const BodyDef& def)
{
    if (!def.concave.parts.empty())
    {
        for (const ConcavePart& part : def.concave.parts)
        {
            if (part.shape.type != ShapeType::Polygon || part.shape.polygon.Count() < 3 ||
                part.internal.size() != static_cast<size_t>(part.shape.polygon.Count()))
            {
                return "shape: each piece of a concave body must be a polygon of at least 3 vertices, with a flag "
                       "per edge";
            }
        }
    }
    else if (def.shape.type == ShapeType::Polygon)
    {
        if (def.shape.polygon.Count() < 3)
        {
            return "shape: a polygon needs at least 3 vertices";
        }
    }
    else if (!(def.shape.circle.radius > 0.0) || !FiniteNumber(def.shape.circle.radius) ||
             !IsFinite(def.shape.circle.center))
    {
        return "shape: a circle needs a finite radius > 0";
    }
    if (!IsFinite(def.position) || !FiniteNumber(def.angle))
    {
        return "position and angle must be finite";
    }
    if (!IsFinite(def.velocity))
    {
        return "velocity must be finite";
    }
    if (!FiniteNumber(def.angularVelocity))
    {
        return "angular_velocity must be finite";
    }
    if (def.type == BodyType::Dynamic && !(def.density > 0.0 && FiniteNumber(def.density)))
    {
        return "density must be finite and > 0 on a dynamic body";
    }
    if (!(def.material.restitution >= 0.0 && def.material.restitution <= 1.0))
    {
        return "restitution must be in [0, 1]";
    }
    if (!(def.material.friction >= 0.0 && FiniteNumber(def.material.friction)))
    {
        return "friction must be finite and >= 0";
    }
    if (!(def.material.staticFriction >= 0.0 && FiniteNumber(def.material.staticFriction)))
    {
        return "static_friction must be finite and >= 0";
    }
    return {};
}

int AddBody(World& world, const BodyDef& def)
{
    RigidBody body;
    const bool concave = !def.concave.parts.empty();
    if (concave)
    {
        body.concave = def.concave;
        std::vector<Vec2> points;
        for (const ConcavePart& part : def.concave.parts)
        {
            const Vec2Span<double> vertices = part.shape.polygon.Vertices();
            points.insert(points.end(), vertices.begin(), vertices.end());
        }
        body.shape = MakeShape(ComputeHull(points).polygon);
    }
    else
    {
        body.shape = def.shape;
    }
    body.type = def.type;
    body.material = def.material;
    body.position = def.position;
    body.angle = def.angle;
    const MassProperties mass = concave ? ComputeMass(def.concave, 1.0) : ComputeMass(def.shape, 1.0);
    body.localCenter = mass.center;
    if (def.type == BodyType::Dynamic)
    {
        body.mass = def.density * mass.mass;
        body.inertia = def.density * mass.inertia;
        body.invMass = body.mass > 0.0 ? 1.0 / body.mass : 0.0;
        body.invInertia = body.inertia > 0.0 ? 1.0 / body.inertia : 0.0;
        body.velocity = def.velocity;
        body.angularVelocity = def.angularVelocity;
    }
    if (concave)
    {
        body.innerRadius = InnerRadius(def.concave);
        body.outerRadius = OuterRadius(def.concave, mass.center);
        body.turnRadius = body.outerRadius;
    }
    else
    {
        body.innerRadius = InnerRadius(def.shape, mass.center);
        body.outerRadius = OuterRadius(def.shape, mass.center);
        body.turnRadius = TurnRadius(def.shape, mass.center);
    }
    world.bodies.push_back(std::move(body));
    world.broadphase.order.clear();
    return static_cast<int>(world.bodies.size()) - 1;
}

double KineticEnergy(const World& world)
{
    double energy = 0.0;
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            energy += 0.5 * body.mass * LengthSquared(body.velocity) +
                      0.5 * body.inertia * body.angularVelocity * body.angularVelocity;
        }
    }
    return energy;
}

Vec2 LinearMomentum(const World& world)
{
    Vec2 p{};
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            p = p + body.mass * body.velocity;
        }
    }
    return p;
}

double AngularMomentum(const World& world, Vec2 origin)
{
    double l = 0.0;
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            l += body.inertia * body.angularVelocity + Cross(body.WorldCenter() - origin, body.mass * body.velocity);
        }
    }
    return l;
}

std::vector<std::pair<int, int>> TouchingPairs(const std::vector<Shape>& shapes, const std::vector<Transform>& xfs)
{
    std::vector<Aabb> boxes(shapes.size());
    for (size_t i = 0; i < shapes.size(); ++i)
    {
        boxes[i] = ComputeAabb(shapes[i], xfs[i]);
    }
    SortAndSweep sweep;
    std::vector<std::pair<int, int>> candidates;
    FindPairs(sweep, boxes, candidates);
    std::vector<std::pair<int, int>> touching;
    for (const auto& [i, j] : candidates)
    {
        if (Overlap(shapes[i], xfs[i], shapes[j], xfs[j]))
        {
            touching.emplace_back(i, j);
        }
    }
    return touching;
}

namespace
{

// The state of one step, shared by its stages.
struct Stepper
{
    World& world;
    double dt;
    const WorldSettings& settings;
    std::vector<SolverBody> solverBodies;
    std::vector<SolverContact> solverContacts;
    std::vector<SolverContact> guards; // the points of swept pairs: for the position passes only
    std::vector<int> solveOrder;       // solverContacts' indices in the order the passes visit them, top down
    std::vector<double> heights;       // per solver contact: how high its first point lies against gravity
    std::vector<double> energyBefore;  // per body, after gravity and before the contacts
    std::vector<Transform> xfs;        // transforms at the start of the step (one sine and cosine per body)
    std::vector<Vec2> centers;         // centres of mass at the start of the step
    std::vector<uint8_t> hit;          // per body: took a time-ordered hit in the step (Move)
    std::vector<uint8_t> bullets;      // per body: moves beyond its reach or turns fast (FindContacts)
    std::vector<double> bodyReach;     // per body: how far FindContacts looked beyond its box
    std::vector<Rot> rotations;        // per body: MakeRot of its angle after Move

    Stepper(World& w, double step) : world(w), dt(step), settings(w.settings) {}

    void FindContacts();
    bool LeftToSweep(int i, int j) const;
    void SolveVelocities();
    template <typename SolvePass>
    void LimitEnergyGain(const std::vector<SolverBody>& unsolved, const SolvePass& solvePass);
    void StoreImpulses();
    void Move();
    void GuardAfterMove(const std::vector<Vec2>& c, const std::vector<Rot>& turn);
    void CorrectPositions();
    void Sleep();
    void OrderTopDown();
};

// Whether the pair (i, j), still apart, is left to the sweep instead of given a speculative contact: one body is
// static, the other a bullet (it moves farther within the step than its reach, speculativeReach outer radii, or
// turns faster than speculativeTurn), and it outruns the static body (detail::OutrunsPair, the sweep's own rule),
// judged from the velocities after the step's gravity. A speculative contact holds its pair at the velocities the
// solver leaves, to first order, from the start of the step: it would bounce a bullet off a wall it has not reached
// yet, far short of where the exact hit would leave it. The sweep finds that hit at its time instead. The points
// are kept as a guard (WorldContact::guard): the velocity passes ignore them, and the position passes, which push
// bodies out of each other, see that a ball skimming a floor is there and do not push it through.
// Two moving bodies keep their speculative contact, bullet or not: it stops their approach at the gap, so they
// cannot pass through each other, and a bullet landing on a pile is solved with the pile's contacts at once
// rather than hit by hit, each hit passed on through the pile (the sweep still takes the pair if a hit changes
// either body's course).
bool Stepper::LeftToSweep(int i, int j) const
{
    if (!bullets[static_cast<size_t>(i)] && !bullets[static_cast<size_t>(j)])
    {
        return false;
    }
    const RigidBody& a = world.bodies[static_cast<size_t>(i)];
    const RigidBody& b = world.bodies[static_cast<size_t>(j)];
    if (a.type != BodyType::Static && b.type != BodyType::Static)
    {
        return false;
    }
    const bool movesA = IsAwakeDynamic(a), movesB = IsAwakeDynamic(b);
    const Vec2 va = movesA ? a.velocity + dt * settings.gravity : Vec2{};
    const Vec2 vb = movesB ? b.velocity + dt * settings.gravity : Vec2{};
    const double wa = movesA ? a.angularVelocity : 0.0;
    const double wb = movesB ? b.angularVelocity : 0.0;
    return detail::OutrunsPair(settings, a, va, wa, b, vb, wb, dt);
}

// Stage 1: bounds, broadphase, narrowphase, warm starting, waking.
void Stepper::FindContacts()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    StepCounts& counts = world.counts;
    counts.pairs = static_cast<int64_t>(n) * (n - 1) / 2;

    int64_t statics = 0, idle = 0;
    std::vector<uint8_t> awakeAtStart(n);
    for (int i = 0; i < n; ++i)
    {
        statics += bodies[i].type == BodyType::Static;
        idle += !IsAwakeDynamic(bodies[i]);
        awakeAtStart[i] = IsAwakeDynamic(bodies[i]);
    }
    counts.staticPairs = settings.skipStaticPairs ? statics * (statics - 1) / 2 : 0;
    const int64_t idlePairs = idle * (idle - 1) / 2 - statics * (statics - 1) / 2;
    counts.sleepingPairs = idlePairs;

    xfs.resize(n);
    for (int i = 0; i < n; ++i)
    {
        xfs[i] = bodies[i].Xf();
    }
    // How far each awake dynamic body can move within the step (its speed after gravity, and the turn of its
    // farthest point), at most speculativeReach outer radii: a body that moves farther is a bullet, and the sweep
    // finds its hits; none for a body turning more than speculativeTurn.
    bodyReach.assign(static_cast<size_t>(n), 0.0);
    bullets.assign(static_cast<size_t>(n), 0);
    if (settings.speculativeContacts)
    {
        const double fall = Length(settings.gravity) * dt;
        for (int i = 0; i < n; ++i)
        {
            const RigidBody& body = bodies[i];
            if (!IsAwakeDynamic(body))
            {
                continue;
            }
            const double move = dt * (Length(body.velocity) + fall + std::fabs(body.angularVelocity) * body.turnRadius);
            const double cap = settings.speculativeReach * body.outerRadius;
            // A body that turns fast is left to the sweep: a contact found at the start of the step follows a
            // turn only to first order.
            const bool turnsFast =
                body.turnRadius > 0.0 && std::fabs(body.angularVelocity) * dt > settings.speculativeTurn;
            bullets[static_cast<size_t>(i)] = turnsFast || move > cap ? 1 : 0;
            if (!turnsFast)
            {
                bodyReach[static_cast<size_t>(i)] = std::min(move, cap);
            }
        }
    }
    // How far a pass of the position correction can move a body at a point (maxCorrection): a body beside a static
    // one within this distance beyond its reach gets a guard, so that the passes, pushing it out of another body,
    // do not push it into the static one. (Several passes can move it farther, but only out of an overlap that
    // deep, which the sweep and the contacts leave rare.)
    const double correctionReach = settings.positionIterations > 0 ? settings.maxCorrection : 0.0;
    PairFilter filter{&bodies, settings.skipStaticPairs};
    std::vector<std::pair<int, int>> candidates;
    StepTrace* stepTrace = world.stepTrace;
    std::vector<Aabb> boxes;
    if (settings.broadphase || stepTrace != nullptr)
    {
        boxes.resize(n);
        if (stepTrace != nullptr)
        {
            stepTrace->grow.resize(n);
        }
        for (int i = 0; i < n; ++i)
        {
            boxes[i] = ComputeAabb(bodies[i].shape, xfs[i]);
            // A body's box grows by the reach of its speculative contacts, so the pairs within it are found; a
            // static body's by how far the position passes can move a body, so its guards are found.
            const double grow =
                bodies[i].type == BodyType::Static ? correctionReach : bodyReach[static_cast<size_t>(i)];
            boxes[i].min = boxes[i].min - Vec2{grow, grow};
            boxes[i].max = boxes[i].max + Vec2{grow, grow};
            if (stepTrace != nullptr)
            {
                stepTrace->grow[i] = grow;
            }
        }
    }
    if (settings.broadphase)
    {
        FindPairs(world.broadphase, boxes, candidates, SkipPair, &filter);
        counts.broadphaseComparisons = world.broadphase.comparisons;
    }
    else
    {
        for (int i = 0; i < n; ++i)
        {
            for (int j = i + 1; j < n; ++j)
            {
                if (!SkipPair(&filter, i, j))
                {
                    candidates.emplace_back(i, j);
                }
            }
        }
    }
    counts.tested = static_cast<int64_t>(candidates.size());
    if (stepTrace != nullptr)
    {
        stepTrace->bounds = std::move(boxes);
        stepTrace->candidates = candidates;
    }
    counts.boundsApart = counts.pairs - counts.staticPairs - counts.sleepingPairs - counts.tested;

    std::vector<int> wake;
    std::vector<WorldContact> previous = std::move(world.contacts);
    std::vector<WorldContact>& contacts = world.contacts;
    contacts.clear();
    int64_t touching = 0, speculative = 0;
    contacts.reserve(previous.size() + 16);
    // The previous contacts are in pair order: those of body a are previous[firstOf[a]] up to firstOf[a + 1], a
    // few to scan for b.
    std::vector<int> firstOf(static_cast<size_t>(n) + 1, 0);
    for (const WorldContact& c : previous)
    {
        ++firstOf[static_cast<size_t>(c.a) + 1];
    }
    for (int i = 0; i < n; ++i)
    {
        firstOf[static_cast<size_t>(i) + 1] += firstOf[static_cast<size_t>(i)];
    }
    const auto previousOf = [&](int a, int b) -> const WorldContact* {
        for (int k = firstOf[static_cast<size_t>(a)]; k < firstOf[static_cast<size_t>(a) + 1]; ++k)
        {
            if (previous[static_cast<size_t>(k)].b == b)
            {
                return &previous[static_cast<size_t>(k)];
            }
        }
        return nullptr;
    };
    for (const auto& pair : candidates)
    {
        const int i = pair.first, j = pair.second;
        RigidBody& a = bodies[i];
        RigidBody& b = bodies[j];
        // A pair with a concave body takes the concave queries (one merged manifold, seams dropped), and the
        // pieces that decided it name its points (CollidePair).
        if (a.type == BodyType::Static && b.type == BodyType::Static)
        {
            detail::CollidePair(a, xfs[i], b, xfs[j]);
            continue;
        }
        // The pair's speculative margin: how far the two can close within the step.
        const double margin = bodyReach[static_cast<size_t>(i)] + bodyReach[static_cast<size_t>(j)];
        ConcaveManifold cm = detail::CollidePair(a, xfs[i], b, xfs[j], margin);
        const Manifold& m = cm.manifold;
        bool guard = false;
        if (m.contactCount == 0)
        {
            // Beyond reach of a static body, but within what the position passes can move it: a guard.
            if (correctionReach > 0.0 && (a.type == BodyType::Static) != (b.type == BodyType::Static))
            {
                cm = detail::CollidePair(a, xfs[i], b, xfs[j], margin + correctionReach);
                guard = m.contactCount > 0 && !m.overlap;
            }
            if (!guard)
            {
                continue;
            }
        }
        WorldContact c;
        // A pair still apart that the sweep takes gets no speculative contact, only a guard (see LeftToSweep).
        c.guard = guard || (!m.overlap && LeftToSweep(i, j));
        touching += m.overlap;
        speculative += !m.overlap && !c.guard;
        c.a = i;
        c.b = j;
        c.normal = m.normal;
        c.normalBody = m.axis.shape == 1 ? 1 : 0;
        c.pointCount = m.contactCount;
        c.material = CombineMaterials(a.material, b.material);
        const WorldContact* old = previousOf(i, j);
        const double reach = 0.25 * std::min(a.type == BodyType::Dynamic ? a.innerRadius : INFINITY,
                                             b.type == BodyType::Dynamic ? b.innerRadius : INFINITY);
        for (int k = 0; k < m.contactCount; ++k)
        {
            WorldContactPoint& p = c.points[k];
            p.point = m.contacts[k].point;
            p.separation = m.contacts[k].separation;
            p.key = FeatureKey(m, cm.pieceA, cm.pieceB, k);
            if (old != nullptr && !c.guard)
            {
                bool matched = false;
                for (int l = 0; l < old->pointCount; ++l)
                {
                    if (old->points[l].key == p.key)
                    {
                        p.normalImpulse = old->points[l].normalImpulse;
                        p.tangentImpulse = old->points[l].tangentImpulse;
                        matched = true;
                    }
                }
                // The reference face can pass from one body to the other between steps when two faces are
                // nearly parallel (a stack of equal boxes): the point is the same, its key is not. Such a point
                // takes the impulses of the old point nearest to it, if close and the normal has not turned.
                if (!matched && Dot(old->normal, c.normal) > 0.95)
                {
                    double nearest = reach * reach;
                    for (int l = 0; l < old->pointCount; ++l)
                    {
                        const double d2 = LengthSquared(old->points[l].point - p.point);
                        if (d2 < nearest)
                        {
                            nearest = d2;
                            p.normalImpulse = old->points[l].normalImpulse;
                            p.tangentImpulse = old->points[l].tangentImpulse;
                            matched = true;
                        }
                    }
                }
            }
        }
        contacts.push_back(c);
        // A body that touches a sleeping one wakes its island.
        if (awakeAtStart[i] != awakeAtStart[j])
        {
            wake.push_back(awakeAtStart[i] ? j : i);
        }
    }
    // The contacts of pairs skipped because neither body was awake are kept as they were: neither body moved. Both
    // lists are in pair order, so a merge keeps the whole in order.
    const size_t found = contacts.size();
    counts.touching = touching;
    counts.speculative = speculative;
    for (const WorldContact& c : previous)
    {
        if (!awakeAtStart[c.a] && !awakeAtStart[c.b])
        {
            contacts.push_back(c);
        }
    }
    std::inplace_merge(
        contacts.begin(), contacts.begin() + static_cast<std::ptrdiff_t>(found), contacts.end(),
        [](const WorldContact& x, const WorldContact& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); });
    WakeIslands(world, wake);
}

// Stage 2: gravity and the velocity passes (with the restitution targets taken before gravity).
// The order of the velocity and position passes: the contacts from the highest to the lowest along gravity, ties
// in the order found (stable, so deterministic); without gravity, the order found. Gauss-Seidel passes carry an
// impulse to the contacts after it in the same pass: top down, the weight of a pile's upper rows reaches its lower
// rows within one pass instead of one row per pass, so the same number of passes leaves a pile less sunk than the
// order found (rows from the bottom up) does.
void Stepper::OrderTopDown()
{
    const int m = static_cast<int>(solverContacts.size());
    solveOrder.resize(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k)
    {
        solveOrder[static_cast<size_t>(k)] = k;
    }
    const double g = Length(settings.gravity);
    if (!(g > 0.0))
    {
        return;
    }
    const Vec2 up = (-1.0 / g) * settings.gravity;
    heights.resize(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k)
    {
        const SolverContact& c = solverContacts[static_cast<size_t>(k)];
        heights[static_cast<size_t>(k)] = Dot(centers[c.a] + c.points[0].rA, up);
    }
    std::stable_sort(solveOrder.begin(), solveOrder.end(), [this](int x, int y) {
        return heights[static_cast<size_t>(x)] > heights[static_cast<size_t>(y)];
    });
}

void Stepper::SolveVelocities()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    solverBodies.assign(n, SolverBody{});
    centers.resize(n);
    for (int i = 0; i < n; ++i)
    {
        const RigidBody& body = bodies[i];
        centers[i] = TransformPoint(xfs[i], body.localCenter);
        if (IsAwakeDynamic(body))
        {
            SolverBody& s = solverBodies[i];
            s.v = body.velocity;
            s.w = body.angularVelocity;
            s.invMass = body.invMass;
            s.invInertia = body.invInertia;
        }
    }

    ContactSolveTrace* trace = world.trace;
    solverContacts.clear();
    solverContacts.reserve(world.contacts.size());
    guards.clear();
    for (size_t k = 0; k < world.contacts.size(); ++k)
    {
        const WorldContact& wc = world.contacts[k];
        if (!IsAwakeDynamic(bodies[wc.a]) && !IsAwakeDynamic(bodies[wc.b]))
        {
            continue;
        }
        SolverContact c;
        c.a = wc.a;
        c.b = wc.b;
        c.normal = wc.normal;
        c.normalBody = wc.normalBody;
        c.count = wc.pointCount;
        c.material = wc.material;
        for (int i = 0; i < c.count; ++i)
        {
            c.points[i].rA = wc.points[i].point - centers[wc.a];
            c.points[i].rB = wc.points[i].point - centers[wc.b];
            c.points[i].separation = wc.points[i].separation;
        }
        if (wc.guard)
        {
            guards.push_back(c);
            continue;
        }
        double approach[2] = {0.0, 0.0};
        for (int i = 0; i < c.count; ++i)
        {
            detail::SolverPoint& p = c.points[i];
            p.gapSpeed = std::max(0.0, p.separation) / dt;
            p.normalImpulse = wc.points[i].normalImpulse;
            p.tangentImpulse = wc.points[i].tangentImpulse;
            approach[i] = Dot(detail::RelativeVelocity(solverBodies[c.a], solverBodies[c.b], p.rA, p.rB), c.normal);
        }
        // How fast gravity closes the pair along the normal: it pulls only the awake dynamic bodies.
        const Vec2 gravityA = IsAwakeDynamic(bodies[c.a]) ? settings.gravity : Vec2{};
        const Vec2 gravityB = IsAwakeDynamic(bodies[c.b]) ? settings.gravity : Vec2{};
        const double pull = std::max(0.0, -Dot(gravityB - gravityA, c.normal));
        detail::PrepareContact(c, solverBodies[c.a], solverBodies[c.b], approach, pull, dt,
                               settings.restitutionThreshold);
        if (trace != nullptr &&
            ((trace->bodyA == c.a && trace->bodyB == c.b) || (trace->bodyA == c.b && trace->bodyB == c.a)))
        {
            c.traced = true;
            trace->found = true;
            trace->normal = c.normal;
            trace->pointCount = c.count;
            trace->restitution = c.material.restitution;
            trace->blockSolved = c.block;
            trace->velocityBefore[0] = solverBodies[c.a].v;
            trace->velocityBefore[1] = solverBodies[c.b].v;
            trace->spinBefore[0] = solverBodies[c.a].w;
            trace->spinBefore[1] = solverBodies[c.b].w;
            for (int i = 0; i < c.count; ++i)
            {
                trace->approachSpeed[i] = approach[i];
                trace->gapSpeed[i] = c.points[i].gapSpeed;
                trace->bounceSpeed[i] = c.points[i].bounce;
                trace->restitutionFactor[i] = c.points[i].restitutionFactor;
                trace->normalMass[i] = c.points[i].normalMass;
                trace->tangentMass[i] = c.points[i].tangentMass;
                trace->warmNormal[i] = c.points[i].normalImpulse;
                trace->warmTangent[i] = c.points[i].tangentImpulse;
            }
        }
        solverContacts.push_back(c);
    }

    for (int i = 0; i < n; ++i)
    {
        if (IsAwakeDynamic(bodies[i]))
        {
            solverBodies[i].v = solverBodies[i].v + dt * settings.gravity;
        }
    }
    energyBefore.resize(n);
    for (int i = 0; i < n; ++i)
    {
        energyBefore[i] = detail::Energy(solverBodies[i]);
    }
    const std::vector<SolverBody> unsolved = solverBodies;
    for (SolverContact& c : solverContacts)
    {
        detail::WarmStart(c, solverBodies[c.a], solverBodies[c.b]);
    }
    OrderTopDown();
    detail::NullSolveRecorder quiet;
    detail::TraceSolveRecorder loud{trace};
    const auto solvePass = [&](const std::vector<int>& order, int pass) {
        for (const int k : order)
        {
            SolverContact& c = solverContacts[static_cast<size_t>(k)];
            if (c.traced)
            {
                detail::SolveContactVelocity(c, solverBodies[c.a], solverBodies[c.b], pass, loud);
            }
            else
            {
                detail::SolveContactVelocity(c, solverBodies[c.a], solverBodies[c.b], pass, quiet);
            }
        }
    };
    for (int pass = 0; pass < settings.velocityIterations; ++pass)
    {
        solvePass(solveOrder, pass);
    }
    LimitEnergyGain(unsolved, solvePass);
    detail::ApplyRestitution(solverContacts, solverBodies, energyBefore, settings.velocityIterations);
    for (const SolverContact& c : solverContacts)
    {
        if (c.traced)
        {
            trace->restitutionImpulse[0] = c.points[0].restitutionImpulse;
            trace->restitutionImpulse[1] = c.points[1].restitutionImpulse;
            trace->velocityAfter[0] = solverBodies[c.a].v;
            trace->velocityAfter[1] = solverBodies[c.b].v;
            trace->spinAfter[0] = solverBodies[c.a].w;
            trace->spinAfter[1] = solverBodies[c.b].w;
        }
    }
}

// Warm starting guesses this step's impulses from the last step's. From zero impulses, each velocity pass over
// inelastic contacts only takes kinetic energy away (projected Gauss-Seidel descends the energy, less what the
// speculative gaps allow); from the guess, passes that have not converged (a light body wedged under a heavy,
// spinning one) can leave more energy than the bodies had before the contacts acted. A group of bodies joined by
// contacts that ends the passes with more kinetic energy than it had, beyond the drift the slop allows, gets more
// passes (as many again at most) while it still gains; if it still does, every impulse of the group is scaled
// down, by the same factor, until its energy is back within the allowance. Momentum is kept; an approach the
// smaller impulses leave is the sweep's and the next step's to stop.
template <typename SolvePass>
void Stepper::LimitEnergyGain(const std::vector<SolverBody>& unsolved, const SolvePass& solvePass)
{
    const int n = static_cast<int>(solverBodies.size());
    if (solverContacts.empty())
    {
        return;
    }
    const auto moves = [&](int i) { return solverBodies[i].invMass > 0.0 || solverBodies[i].invInertia > 0.0; };
    // What a group may gain: the energy of each body moving at the slop per step, the speed at which the contacts
    // let a resting body drift within the slop.
    const double drift = 0.5 * (2.0 * settings.linearSlop / dt) * (2.0 * settings.linearSlop / dt);
    const auto allowance = [&](int i) {
        return energyBefore[i] + (solverBodies[i].invMass > 0.0 ? drift / solverBodies[i].invMass : 0.0);
    };
    // A group gains only if one of its bodies does: when none does, there is nothing to look at (the usual case).
    bool anyBody = false;
    for (int i = 0; i < n && !anyBody; ++i)
    {
        anyBody = moves(i) && detail::Energy(solverBodies[i]) > allowance(i);
    }
    if (!anyBody)
    {
        return;
    }
    std::vector<int> parent(n);
    for (int i = 0; i < n; ++i)
    {
        parent[i] = i;
    }
    for (const SolverContact& c : solverContacts)
    {
        if (moves(c.a) && moves(c.b))
        {
            const int ra = FindRoot(parent, c.a), rb = FindRoot(parent, c.b);
            parent[ra < rb ? rb : ra] = ra < rb ? ra : rb;
        }
    }
    std::vector<double> before(n, 0.0), after(n, 0.0);
    for (int i = 0; i < n; ++i)
    {
        if (moves(i))
        {
            const int r = FindRoot(parent, i);
            before[r] += allowance(i);
            after[r] += detail::Energy(solverBodies[i]);
        }
    }
    std::vector<uint8_t> gained(n, 0);
    bool any = false;
    for (int i = 0; i < n; ++i)
    {
        if (moves(i) && FindRoot(parent, i) == i && after[i] > before[i])
        {
            gained[i] = 1;
            any = true;
        }
    }
    if (!any)
    {
        return;
    }
    // More passes over the groups that gained, as many again at most, while they still gain: the passes converge
    // towards impulses that take energy away.
    std::vector<int> order;
    for (const int k : solveOrder)
    {
        const SolverContact& c = solverContacts[static_cast<size_t>(k)];
        if (gained[FindRoot(parent, moves(c.a) ? c.a : c.b)])
        {
            order.push_back(k);
            if (c.traced)
            {
                world.trace->energyLimited = true;
            }
        }
    }
    for (int pass = 0; pass < settings.velocityIterations && any; ++pass)
    {
        solvePass(order, settings.velocityIterations + pass);
        std::fill(after.begin(), after.end(), 0.0);
        for (int i = 0; i < n; ++i)
        {
            if (moves(i) && gained[FindRoot(parent, i)])
            {
                after[FindRoot(parent, i)] += detail::Energy(solverBodies[i]);
            }
        }
        any = false;
        for (int r = 0; r < n; ++r)
        {
            if (gained[r])
            {
                gained[r] = after[r] > before[r] ? 1 : 0;
                any = any || gained[r];
            }
        }
        // Groups that no longer gain keep their passes; the next pass is only over those that still do.
        order.erase(std::remove_if(order.begin(), order.end(),
                                   [&](int k) {
                                       const SolverContact& c = solverContacts[static_cast<size_t>(k)];
                                       return !gained[FindRoot(parent, moves(c.a) ? c.a : c.b)];
                                   }),
                    order.end());
    }
    if (!any)
    {
        return;
    }
    // Per group: the energy as a function of the scale s of the contacts' impulses, E(s) = e0 + g s + h s^2, with
    // e0 the energy before they acted; s = 1 is the solve as it stands. The largest s in [0, 1] with E(s) within
    // the allowance scales every impulse of the group (momentum is kept, pair by pair).
    std::vector<double> e0(n, 0.0), g(n, 0.0), h(n, 0.0);
    for (int i = 0; i < n; ++i)
    {
        if (!moves(i) || !gained[FindRoot(parent, i)])
        {
            continue;
        }
        const int r = FindRoot(parent, i);
        const SolverBody& u = unsolved[i];
        const SolverBody& v = solverBodies[i];
        const double mass = u.invMass > 0.0 ? 1.0 / u.invMass : 0.0;
        const double inertia = u.invInertia > 0.0 ? 1.0 / u.invInertia : 0.0;
        const Vec2 dv = v.v - u.v;
        const double dw = v.w - u.w;
        e0[r] += detail::Energy(u);
        g[r] += mass * Dot(u.v, dv) + inertia * u.w * dw;
        h[r] += 0.5 * (mass * Dot(dv, dv) + inertia * dw * dw);
    }
    std::vector<double> scale(n, 1.0);
    for (int r = 0; r < n; ++r)
    {
        if (!gained[r])
        {
            continue;
        }
        // E(s) = before[r] at the largest root; E(0) = e0 <= before, E(1) > before, so the root lies in (0, 1).
        const double c = e0[r] - before[r];
        double root = 0.0;
        if (h[r] > 0.0)
        {
            const double disc = std::max(0.0, g[r] * g[r] - 4.0 * h[r] * c);
            root = (-g[r] + std::sqrt(disc)) / (2.0 * h[r]);
        }
        else if (g[r] > 0.0)
        {
            root = -c / g[r];
        }
        scale[r] = std::max(0.0, std::min(1.0, root));
    }
    for (int i = 0; i < n; ++i)
    {
        if (moves(i) && gained[FindRoot(parent, i)])
        {
            const double f = scale[FindRoot(parent, i)];
            const SolverBody& u = unsolved[i];
            SolverBody& v = solverBodies[i];
            v.v = u.v + f * (v.v - u.v);
            v.w = u.w + f * (v.w - u.w);
        }
    }
    for (SolverContact& c : solverContacts)
    {
        const int body = moves(c.a) ? c.a : c.b;
        if (!gained[FindRoot(parent, body)])
        {
            continue;
        }
        const double f = scale[FindRoot(parent, body)];
        for (int i = 0; i < c.count; ++i)
        {
            c.points[i].normalImpulse *= f;
            c.points[i].tangentImpulse *= f;
        }
        if (c.traced)
        {
            world.trace->impulseScale = f;
        }
    }
}

// The accumulated impulses go back to the world's contacts for the next step's warm start.
void Stepper::StoreImpulses()
{
    size_t k = 0;
    for (const SolverContact& c : solverContacts)
    {
        while (world.contacts[k].a != c.a || world.contacts[k].b != c.b)
        {
            ++k;
        }
        WorldContact& wc = world.contacts[k];
        for (int i = 0; i < c.count; ++i)
        {
            // A bounce's own impulse is an impact, not a load the point will carry next step: only the compression
            // part is warm started.
            wc.points[i].normalImpulse = c.points[i].normalImpulse - c.points[i].restitutionImpulse;
            wc.points[i].tangentImpulse = c.points[i].tangentImpulse;
            wc.points[i].stuck = c.points[i].stuck;
        }
    }
}

// Stage 4: positions, with the hits of fast bodies in time order.
void Stepper::Move()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    for (int i = 0; i < n; ++i)
    {
        if (IsAwakeDynamic(bodies[i]))
        {
            bodies[i].velocity = solverBodies[i].v;
            bodies[i].angularVelocity = solverBodies[i].w;
        }
    }
    detail::TimeOfImpactStage stage(world, dt, xfs, centers, solverBodies);
    stage.Run();
    hit.assign(static_cast<size_t>(n), 0);
    rotations.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
    {
        hit[static_cast<size_t>(i)] = stage.TookHit(i) ? 1 : 0;
        rotations[static_cast<size_t>(i)] = stage.Rotation(i);
    }
}

// Guards for where the bodies went. FindContacts gave guards to the static bodies within reach of the position
// passes of where each body could go at its speed at the start of the step; the velocity passes and the hits can
// send a body farther (a light body struck by a heavy one), and the passes, pushing it out of the body that struck
// it, would then push it on into a wall no guard watches. A body that moved beyond the reach it was given gets
// guards with the static bodies within maxCorrection of its path.
// c and turn: each body's centre of mass after the move, and its turn since the start of the step.
void Stepper::GuardAfterMove(const std::vector<Vec2>& c, const std::vector<Rot>& turn)
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    std::vector<int> statics;
    for (int i = 0; i < n; ++i)
    {
        const RigidBody& body = bodies[i];
        if (!IsAwakeDynamic(body))
        {
            continue;
        }
        const double reach = bodyReach[static_cast<size_t>(i)];
        const double d2 = LengthSquared(c[i] - centers[i]);
        if (d2 <= reach * reach && body.turnRadius == 0.0)
        {
            continue;
        }
        const double moved = std::sqrt(d2) + body.turnRadius * std::sqrt(LengthSquared(Vec2{turn[i].c - 1.0, turn[i].s}));
        if (moved <= reach)
        {
            continue;
        }
        if (statics.empty())
        {
            for (int k = 0; k < n; ++k)
            {
                if (bodies[k].type == BodyType::Static)
                {
                    statics.push_back(k);
                }
            }
            if (statics.empty())
            {
                return;
            }
        }
        // The box of every place the body was in the step, grown by what a pass can move it.
        const double margin = moved + settings.maxCorrection;
        Aabb path = ComputeAabb(body.shape, xfs[i]);
        path.min = path.min - Vec2{margin, margin};
        path.max = path.max + Vec2{margin, margin};
        for (const int s : statics)
        {
            if (!AabbOverlap(path, ComputeAabb(bodies[s].shape, xfs[s])))
            {
                continue;
            }
            const int a = std::min(i, s), b = std::max(i, s);
            const WorldContact* existing = FindContact(world.contacts, a, b);
            if (existing != nullptr)
            {
                continue;
            }
            const Manifold m = detail::CollidePair(bodies[a], xfs[a], bodies[b], xfs[b], margin).manifold;
            if (m.contactCount == 0)
            {
                continue;
            }
            SolverContact g;
            g.a = a;
            g.b = b;
            g.material = CombineMaterials(bodies[a].material, bodies[b].material);
            g.normal = m.normal;
            g.normalBody = m.axis.shape == 1 ? 1 : 0;
            g.count = m.contactCount;
            for (int k = 0; k < g.count; ++k)
            {
                g.points[k].rA = m.contacts[k].point - centers[a];
                g.points[k].rB = m.contacts[k].point - centers[b];
                g.points[k].separation = m.contacts[k].separation;
            }
            guards.push_back(g);
        }
    }
}

// Stage 5: overlap removed by moving the positions, not the velocities (nonlinear Gauss-Seidel: Catto, Box2D).
// Each pass measures every point's overlap at the bodies' present positions, from the point's anchors on both bodies
// and the normal turned with the body whose face (or vertex) it is, as Box2D measures it from the reference face,
// and moves the two bodies apart along the normal by correctionFactor times the overlap beyond the slop (at most
// maxCorrection), weighted by their inverse masses and inertias. Passes see the moves of the passes before them, so
// a body that sank during this step's move is lifted in the same step. Speculative points (a gap) are left alone.
void Stepper::CorrectPositions()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    std::vector<Vec2> c(n);
    std::vector<double> angle(n);
    // Each body's turn since the start of the step, as a rotation: the anchors found then turn by it. A circle
    // turning about its centre keeps the identity, for its turning moves no point of its outline (a ball spinning
    // a full turn in a step would otherwise be pushed along a normal turned any which way).
    std::vector<Rot> turn(n);
    std::vector<uint8_t> turns(n); // turning moves the outline: not a circle about its centre
    for (int i = 0; i < n; ++i)
    {
        angle[i] = bodies[i].angle;
        const Rot q = rotations[static_cast<size_t>(i)];
        c[i] = bodies[i].position + Rotate(q, bodies[i].localCenter);
        turns[i] = bodies[i].turnRadius > 0.0 ? 1 : 0;
        turn[i] = turns[i] ? InvMulRot(xfs[i].q, q) : Rot{};
    }
    if (settings.positionIterations > 0)
    {
        GuardAfterMove(c, turn);
    }
    // Body i's transform with its centre of mass at `center`, turned as the passes have turned it so far.
    const auto PoseAt = [&](int i, Vec2 center) {
        Transform xf;
        const Rot q0 = xfs[i].q, d = turn[i];
        xf.q = {q0.c * d.c - q0.s * d.s, q0.s * d.c + q0.c * d.s};
        xf.p = center - Rotate(xf.q, bodies[i].localCenter);
        return xf;
    };
    // Moves bodies a and b apart along n0 at a point with lever arms rA, rB and separation sep, by `factor` of the
    // overlap beyond the slop.
    const auto push = [&](int a, int b, Vec2 n0, Vec2 rA, Vec2 rB, double sep, double factor) {
        const SolverBody& sa = solverBodies[a];
        const SolverBody& sb = solverBodies[b];
        double C = factor * (sep + settings.linearSlop);
        C = std::max(-settings.maxCorrection, std::min(0.0, C));
        const double rnA = Cross(rA, n0), rnB = Cross(rB, n0);
        const double K = sa.invMass + sb.invMass + sa.invInertia * rnA * rnA + sb.invInertia * rnB * rnB;
        if (!(K > 0.0) || C == 0.0)
        {
            return;
        }
        const Vec2 P = (-C / K) * n0;
        const double turnA = -sa.invInertia * Cross(rA, P);
        const double turnB = sb.invInertia * Cross(rB, P);
        c[a] = c[a] - sa.invMass * P;
        angle[a] += turnA;
        c[b] = c[b] + sb.invMass * P;
        angle[b] += turnB;
        if (turns[a])
        {
            turn[a] = TurnBy(turn[a], turnA);
        }
        if (turns[b])
        {
            turn[b] = TurnBy(turn[b], turnB);
        }
    };
    // One contact's points moved apart by `factor` of their overlap beyond the slop.
    const auto correct = [&](const SolverContact& sc, double factor) {
        const int a = sc.a, b = sc.b;
        // A body that took a hit went where the sweep sent it, which may be far from where this contact was
        // found: the contact's anchors and normal no longer describe its surroundings (measured from them, a
        // ball that crossed the room would seem deep in the wall it started beside, and be pushed through the
        // floor). The sweep leaves its bodies apart; the next step finds their contacts afresh.
        if (hit[static_cast<size_t>(a)] || hit[static_cast<size_t>(b)])
        {
            return;
        }
        const SolverBody& sa = solverBodies[a];
        const SolverBody& sb = solverBodies[b];
        // The normal turns with the body that holds it; between two circles it joins their centres.
        Vec2 n0 = Rotate(turn[sc.normalBody == 1 ? b : a], sc.normal);
        if (!turns[a] && !turns[b])
        {
            const Vec2 d = c[b] - c[a];
            const double length = std::sqrt(LengthSquared(d));
            if (length > 0.0)
            {
                n0 = (1.0 / length) * d;
            }
        }
        for (int k = 0; k < sc.count; ++k)
        {
            // Each body's anchor is the point of its own surface: the contact point lies halfway between them, a
            // half separation along the normal from each. Turned with its body, an anchor off the surface would
            // swing by the turn times that offset: a body turning towards the floor across a wide speculative gap
            // would seem to reach it, and be lifted.
            const detail::SolverPoint& p = sc.points[k];
            const Vec2 half = (0.5 * p.separation) * sc.normal;
            const Vec2 rA = Rotate(turn[a], p.rA - half);
            const Vec2 rB = Rotate(turn[b], p.rB + half);
            const double sep = Dot((c[b] + rB) - (c[a] + rA), n0);
            // A bounce that carries the point out of this much overlap within the step is left to do so: the
            // separating speed the velocity passes left at the point, not the one the restitution asked for,
            // which other contacts may have taken back.
            const double C = std::max(-settings.maxCorrection, std::min(0.0, factor * (sep + settings.linearSlop)));
            if (p.bounce > 0.0 && Dot(detail::RelativeVelocity(sa, sb, p.rA, p.rB), sc.normal) * dt >= -C)
            {
                continue;
            }
            push(a, b, n0, rA, rB, sep, factor);
        }
    };
    // A guard's pair may have moved far against each other: anchors found at the start of the step say nothing of
    // where they are now, so its overlap is measured afresh, by Collide at the present positions, once its bodies
    // may have crossed the gap it started with (each point of a body has moved at most the distance of its centre
    // plus the turn radius times the chord of its turn).
    const auto guard = [&](const SolverContact& g, double factor, bool straight) {
        const int a = g.a, b = g.b;
        // The passes leave out a body that took a hit (see correct), but not the last lift out of a static body,
        // measured afresh: a light body pressed into a wall by a heavy one takes a hit in every step, and the sweep
        // lets it creep in by less than the slop each time.
        const bool tookHit = hit[static_cast<size_t>(a)] || hit[static_cast<size_t>(b)];
        if (tookHit && !straight)
        {
            return;
        }
        // The chord of a turn by `turn` is |turn - 1| (a circle's turn is kept as the identity, and its turn radius
        // is 0 anyway).
        const auto moved = [&](int i) {
            return std::sqrt(LengthSquared(c[i] - centers[i])) +
                   bodies[i].turnRadius * std::sqrt(LengthSquared(Vec2{turn[i].c - 1.0, turn[i].s}));
        };
        const double gap = std::min(g.points[0].separation, g.count > 1 ? g.points[1].separation : INFINITY);
        if (gap - moved(a) - moved(b) > -settings.linearSlop)
        {
            return;
        }
        const auto pose = [&](int i) { return PoseAt(i, c[i]); };
        // Along n (from the static body to the moving one): the static body's (piece's) extent, `top`, and the
        // moving one's deepest point and its height, `bottom`.
        const auto extents = [&](int fixedBody, int fixedPiece, int moving, int movingPiece, Vec2 n, double& top,
                                 double& bottom, Vec2& deepest) {
            const Transform xs = pose(fixedBody), xm = pose(moving);
            const Shape& shapeS = detail::PieceShape(bodies[fixedBody], fixedPiece);
            const Shape& shapeM = detail::PieceShape(bodies[moving], movingPiece);
            top = -INFINITY;
            if (shapeS.type == ShapeType::Circle)
            {
                top = Dot(n, TransformPoint(xs, shapeS.circle.center)) + shapeS.circle.radius;
            }
            else
            {
                for (const Vec2& v : shapeS.polygon.Vertices())
                {
                    top = std::max(top, Dot(n, TransformPoint(xs, v)));
                }
            }
            bottom = INFINITY;
            if (shapeM.type == ShapeType::Circle)
            {
                deepest = TransformPoint(xm, shapeM.circle.center) - shapeM.circle.radius * n;
                bottom = Dot(n, deepest);
            }
            else
            {
                for (const Vec2& v : shapeM.polygon.Vertices())
                {
                    const Vec2 w = TransformPoint(xm, v);
                    if (Dot(n, w) < bottom)
                    {
                        bottom = Dot(n, w);
                        deepest = w;
                    }
                }
            }
        };
        const int fixedBody = bodies[a].type == BodyType::Static ? a : (bodies[b].type == BodyType::Static ? b : -1);
        // The last lift of a convex body along a static body's own face, fixed: when the body is within the slop
        // of it along that face's normal there is nothing to lift, whatever Collide would say, so Collide is not
        // asked (a resting pile's contacts with the floor, every step).
        if (straight && fixedBody >= 0 && !tookHit && (g.normalBody == 1 ? b : a) == fixedBody &&
            !detail::AnyConcave(bodies[a], bodies[b]))
        {
            const int moving = fixedBody == a ? b : a;
            const Vec2 n = fixedBody == a ? g.normal : -1.0 * g.normal;
            double top = 0.0, bottom = 0.0;
            Vec2 deepest{};
            extents(fixedBody, -1, moving, -1, n, top, bottom, deepest);
            if (bottom - top + settings.linearSlop >= 0.0)
            {
                return;
            }
        }
        // Beside a static body, once Collide finds them overlapping, the axis is the guard's normal, fixed as the
        // static body is: the moving body's deepest point along it against the static body's extent. Measured so,
        // a body pushed past the middle of a thin wall is still pushed back the way it came; Collide's own normal
        // would push it on through.
        // A concave body's part in the overlap is the piece that decided it: its vertices bound the push below.
        const ConcaveManifold cm = detail::CollidePair(bodies[a], pose(a), bodies[b], pose(b));
        const Manifold& m = cm.manifold;
        const int pieceA = cm.pieceA, pieceB = cm.pieceB;
        if (!m.overlap)
        {
            return;
        }
        if (fixedBody >= 0)
        {
            const int moving = fixedBody == a ? b : a;
            // The axis turns with the body whose face it is: fixed if the static body's, as found now if the moving
            // body's (a plank's face turning on a peg).
            const int owner = g.normalBody == 1 ? b : a;
            // A body that took a hit may be far from where the guard was found: its overlap is the one Collide
            // finds now, shallow (the sweep left it touching), along Collide's normal.
            const Vec2 axis = owner == fixedBody && !tookHit ? g.normal : m.normal;
            const Vec2 n = fixedBody == a ? axis : -1.0 * axis; // from the static body to the moving one
            double top = 0.0, bottom = 0.0;
            Vec2 deepest{};
            extents(fixedBody, fixedBody == a ? pieceA : pieceB, moving, moving == a ? pieceA : pieceB, n, top, bottom,
                    deepest);
            const Vec2 normal = fixedBody == a ? n : -1.0 * n;
            if (straight)
            {
                // Straight out, without turning: every point of the body rises by the same amount, so the deepest
                // one comes out and no other goes in (pushed at one corner, a sliver lying in the floor would turn
                // its other end down).
                const double C = std::max(-settings.maxCorrection, std::min(0.0, bottom - top + settings.linearSlop));
                c[moving] = c[moving] - C * n;
                RigidBody& body = bodies[moving];
                if (C < 0.0 && IsAwakeDynamic(body))
                {
                    // The body sank into the static one beyond the slop: the step's contacts and sweep missed it (a
                    // corner brought down by a turn that a contact follows only to first order). Its approach at
                    // the deepest point is taken as a hit would take it, with the pair's restitution, so that the
                    // lift does not leave it moving on into the wall, to be lifted again: lifted while still
                    // falling, it would gain the height for nothing.
                    const Vec2 r = deepest - c[moving];
                    const double vn = Dot(body.velocity + body.angularVelocity * LeftPerp(r), n);
                    if (vn < 0.0)
                    {
                        const double rn = Cross(r, n);
                        const double K = body.invMass + body.invInertia * rn * rn;
                        const double j = -(1.0 + g.material.restitution) * vn / K;
                        body.velocity = body.velocity + (j * body.invMass) * n;
                        body.angularVelocity += body.invInertia * j * rn;
                    }
                }
                return;
            }
            push(a, b, normal, deepest - c[a], deepest - c[b], bottom - top, factor);
            return;
        }
        for (int k = 0; k < m.contactCount; ++k)
        {
            const Vec2 point = m.contacts[k].point;
            push(a, b, m.normal, point - c[a], point - c[b], m.contacts[k].separation, factor);
        }
    };
    const std::vector<Vec2> afterMove = c; // where the move left the centres, before the passes
    for (int pass = 0; pass < settings.positionIterations; ++pass)
    {
        for (const int k : solveOrder)
        {
            correct(solverContacts[static_cast<size_t>(k)], settings.correctionFactor);
        }
        for (const SolverContact& g : guards)
        {
            guard(g, settings.correctionFactor, false);
        }
    }
    // The passes move bodies too: pressed by a heavy body, a light one can be pushed right through a thin static
    // body within them, and the lift below finds no overlap with a body already past it. A body the passes moved
    // is swept, without turning, from where the move left it to where the passes put it, against each static body
    // it has a contact or a guard with, and stops where it would touch it.
    const auto stopAtStatic = [&](const SolverContact& sc) {
        const bool staticA = bodies[sc.a].type == BodyType::Static;
        if (staticA == (bodies[sc.b].type == BodyType::Static))
        {
            return;
        }
        const int s = staticA ? sc.a : sc.b, i = staticA ? sc.b : sc.a;
        const Vec2 d = c[i] - afterMove[i];
        if (!IsAwakeDynamic(bodies[i]) || LengthSquared(d) <= settings.linearSlop * settings.linearSlop)
        {
            return;
        }
        const SweepResult r =
            detail::AnyConcave(bodies[s], bodies[i])
                ? detail::SweepBodies(bodies[s], xfs[s], Vec2{}, bodies[i], PoseAt(i, afterMove[i]), d).result
                : Sweep(bodies[s].shape, xfs[s], Vec2{}, bodies[i].shape, PoseAt(i, afterMove[i]), d);
        if (r.status == SweepStatus::Overlapping)
        {
            // Already touching it (a body resting on the floor overlaps it by up to the slop): the sweep cannot
            // say when it would go in, for it is in. The passes may slide it along the static body and lift it
            // out, never take it deeper: the part of the displacement into the static body, along the normal of
            // their overlap, is taken out.
            const Vec2 out = r.initial.normal; // from the static body (A of the sweep) to the moving one
            const double into = Dot(d, out);
            if (into < 0.0)
            {
                c[i] = c[i] - into * out;
            }
        }
        else if (r.status == SweepStatus::Hit)
        {
            c[i] = afterMove[i] + r.toi * d;
        }
    };
    if (settings.positionIterations > 0)
    {
        for (const int k : solveOrder)
        {
            stopAtStatic(solverContacts[static_cast<size_t>(k)]);
        }
        for (const SolverContact& g : guards)
        {
            stopAtStatic(g);
        }
    }
    // Last, the contacts with bodies that do not move (static or asleep) take out their whole overlap beyond the
    // slop. The passes share each overlap between the bodies by their masses: a heavy body landing on a light
    // sliver that lies on the floor pushes the sliver down as far as the floor pushes it up, and under enough
    // weight it sinks into the floor, and through a thin one. Nothing can push back a static body, so its overlap
    // is the one that must go.
    const auto fixed = [&](const SolverContact& sc) {
        const SolverBody& sa = solverBodies[sc.a];
        const SolverBody& sb = solverBodies[sc.b];
        return (sa.invMass == 0.0 && sa.invInertia == 0.0) || (sb.invMass == 0.0 && sb.invInertia == 0.0);
    };
    if (settings.positionIterations > 0)
    {
        for (const int k : solveOrder)
        {
            const SolverContact& sc = solverContacts[static_cast<size_t>(k)];
            if (!fixed(sc))
            {
                continue;
            }
            // Against a static body, measured afresh as a guard is, and lifted straight out: a contact's anchors see
            // only the points found at the start of the step, and a sliver that turned can poke another corner into
            // the wall.
            if (bodies[sc.a].type == BodyType::Static || bodies[sc.b].type == BodyType::Static)
            {
                guard(sc, 1.0, true);
            }
            else
            {
                correct(sc, 1.0);
            }
        }
        for (const SolverContact& g : guards)
        {
            if (fixed(g))
            {
                guard(g, 1.0, true);
            }
        }
    }
    for (int i = 0; i < n; ++i)
    {
        if (IsAwakeDynamic(bodies[i]))
        {
            // The passes turned few bodies: the others keep the rotation Move computed for their angle.
            const Rot q = angle[i] == bodies[i].angle ? rotations[static_cast<size_t>(i)] : MakeRot(angle[i]);
            bodies[i].angle = angle[i];
            bodies[i].position = c[i] - Rotate(q, bodies[i].localCenter);
        }
    }
}

// Stage 6: islands of touching dynamic bodies sleep together once all have rested long enough.
void Stepper::Sleep()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    StepCounts& counts = world.counts;
    if (!settings.sleeping)
    {
        for (RigidBody& body : bodies)
        {
            if (body.type == BodyType::Dynamic)
            {
                body.awake = true;
                body.sleepTime = 0.0;
            }
        }
    }
    else
    {
        const double linear2 = settings.sleepLinearSpeed * settings.sleepLinearSpeed;
        for (RigidBody& body : bodies)
        {
            if (!IsAwakeDynamic(body))
            {
                continue;
            }
            const bool resting = LengthSquared(body.velocity) <= linear2 &&
                                 std::fabs(body.angularVelocity) <= settings.sleepAngularSpeed;
            body.sleepTime = resting ? body.sleepTime + dt : 0.0;
        }
        std::vector<int> parent(n);
        for (int i = 0; i < n; ++i)
        {
            parent[i] = i;
        }
        for (const WorldContact& c : world.contacts)
        {
            if (bodies[c.a].type == BodyType::Dynamic && bodies[c.b].type == BodyType::Dynamic)
            {
                const int ra = FindRoot(parent, c.a), rb = FindRoot(parent, c.b);
                if (ra != rb)
                {
                    parent[ra > rb ? ra : rb] = ra < rb ? ra : rb;
                }
            }
        }
        // The shortest rest in each island, and whether any body of it is awake.
        std::vector<double> shortest(n, INFINITY);
        std::vector<uint8_t> anyAwake(n, 0);
        for (int i = 0; i < n; ++i)
        {
            if (bodies[i].type != BodyType::Dynamic)
            {
                continue;
            }
            const int root = FindRoot(parent, i);
            shortest[root] = std::min(shortest[root], bodies[i].awake ? bodies[i].sleepTime : INFINITY);
            anyAwake[root] |= bodies[i].awake ? 1 : 0;
        }
        for (int i = 0; i < n; ++i)
        {
            RigidBody& body = bodies[i];
            if (body.type != BodyType::Dynamic || !body.awake)
            {
                continue;
            }
            const int root = FindRoot(parent, i);
            if (anyAwake[root] && shortest[root] >= settings.timeToSleep)
            {
                body.awake = false;
                body.velocity = {};
                body.angularVelocity = 0.0;
            }
        }
    }
    counts.awakeBodies = 0;
    counts.sleepingBodies = 0;
    for (const RigidBody& body : bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            (body.awake ? counts.awakeBodies : counts.sleepingBodies) += 1;
        }
    }
}

} // namespace

void Step(World& world, double dt)
{
    world.counts = StepCounts();
    if (world.trace != nullptr)
    {
        world.trace->Clear();
    }
    if (world.stepTrace != nullptr)
    {
        world.stepTrace->Clear();
    }
    Stepper stepper(world, dt);
    stepper.FindContacts();
    stepper.SolveVelocities();
    stepper.StoreImpulses();
    stepper.Move();
    stepper.CorrectPositions();
    stepper.Sleep();
    world.time += dt;
}

} // namespace satviz
