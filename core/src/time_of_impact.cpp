// SPDX-License-Identifier: MIT
// satviz: the world's positions stage with time-ordered hits.

#include "time_of_impact.h"

#include "body_queries.h"
#include "world_lookup.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace satviz::detail
{

namespace
{

// The step's contact of the pair (a, b), a < b, if it has one (a guard is not a contact).
const WorldContact* ContactOf(const std::vector<WorldContact>& contacts, int a, int b)
{
    const WorldContact* contact = FindContact(contacts, a, b);
    return contact != nullptr && !contact->guard ? contact : nullptr;
}

bool SkipSlowPair(const void* context, int i, int j)
{
    const std::vector<uint8_t>& fast = *static_cast<const std::vector<uint8_t>*>(context);
    return !fast[i] && !fast[j];
}

// Most passes of conservative advancement for one pair; a pair still apart after them counts as a miss.
constexpr int kMaxAdvances = 64;

} // namespace

// Speeds by std::sqrt rather than Length's std::hypot: these only decide which pairs to sweep, and run for every
// candidate pair of every step.
bool OutrunsBody(const WorldSettings& settings, const RigidBody& body, Vec2 v, double w, double span)
{
    return (std::sqrt(LengthSquared(v)) + std::fabs(w) * body.turnRadius) * span >
           settings.sweepFraction * body.innerRadius;
}

bool OutrunsPair(const WorldSettings& settings, const RigidBody& a, Vec2 va, double wa, const RigidBody& b, Vec2 vb,
                 double wb, double span)
{
    const double relative =
        (std::sqrt(LengthSquared(vb - va)) + std::fabs(wa) * a.turnRadius + std::fabs(wb) * b.turnRadius) * span;
    const double size = std::min(a.type == BodyType::Dynamic ? a.innerRadius : INFINITY,
                                 b.type == BodyType::Dynamic ? b.innerRadius : INFINITY);
    return relative > settings.sweepFraction * size;
}

TimeOfImpactStage::TimeOfImpactStage(World& world, double dt, const std::vector<Transform>& xfs,
                                     const std::vector<Vec2>& centers, const std::vector<SolverBody>& solverBodies)
    : m_world(world), m_dt(dt), m_xfs(xfs)
{
    const int n = static_cast<int>(world.bodies.size());
    m_motion.resize(n);
    for (int i = 0; i < n; ++i)
    {
        const RigidBody& body = world.bodies[i];
        Motion& m = m_motion[i];
        m.center = centers[i];
        m.angle = body.angle;
        if (IsAwakeDynamic(body))
        {
            m.moves = true;
            m.v = solverBodies[i].v;
            m.w = solverBodies[i].w;
        }
    }
}

Vec2 TimeOfImpactStage::CenterAt(int i, double t) const
{
    const Motion& m = m_motion[i];
    return m.center + ((t - m.t) * m_dt) * m.v;
}

Transform TimeOfImpactStage::PoseAt(int i, double t) const
{
    const Motion& m = m_motion[i];
    const RigidBody& body = m_world.bodies[i];
    if (!m.moves)
    {
        return m_xfs[i];
    }
    if (t == m.t && t == 0.0)
    {
        return m_xfs[i];
    }
    if (t == m.t)
    {
        Transform xf{};
        xf.q = MakeRot(m.angle);
        xf.p = m.center - Rotate(xf.q, body.localCenter);
        return xf;
    }
    Transform xf{};
    xf.q = MakeRot(m.angle + (t - m.t) * m_dt * m.w);
    xf.p = CenterAt(i, t) - Rotate(xf.q, body.localCenter);
    return xf;
}

Aabb TimeOfImpactStage::PathBox(int i, double t) const
{
    const Motion& m = m_motion[i];
    const RigidBody& body = m_world.bodies[i];
    if (!m.moves)
    {
        return ComputeAabb(body.shape, PoseAt(i, t));
    }
    const Vec2 c0 = CenterAt(i, t), c1 = CenterAt(i, 1.0);
    const double r = body.outerRadius;
    return {{std::min(c0.x, c1.x) - r, std::min(c0.y, c1.y) - r}, {std::max(c0.x, c1.x) + r, std::max(c0.y, c1.y) + r}};
}

double TimeOfImpactStage::Speed(int i) const
{
    const Motion& m = m_motion[i];
    return Length(m.v) + std::fabs(m.w) * m_world.bodies[i].turnRadius;
}

bool TimeOfImpactStage::IsFast(int i) const
{
    if (!m_motion[i].moves)
    {
        return false;
    }
    if (!m_world.settings.sweepOnlyFast)
    {
        return Speed(i) > 0.0;
    }
    return OutrunsBody(m_world.settings, m_world.bodies[i], m_motion[i].v, m_motion[i].w, m_dt);
}

bool TimeOfImpactStage::TurnsFast(int i) const
{
    return m_world.bodies[i].turnRadius > 0.0 && std::fabs(m_motion[i].w) * m_dt > m_world.settings.speculativeTurn;
}

Aabb TimeOfImpactStage::Reach(int i, double speed) const
{
    const Motion& m = m_motion[i];
    const RigidBody& body = m_world.bodies[i];
    if (!m.moves)
    {
        return ComputeAabb(body.shape, PoseAt(i, m.t));
    }
    const double r = speed * (1.0 - m.t) * m_dt + body.outerRadius;
    return {{m.center.x - r, m.center.y - r}, {m.center.x + r, m.center.y + r}};
}

bool TimeOfImpactStage::Approaching(int i, int j, double t, Vec2 normal, const Vec2* points, int count,
                                    double minSpeed, const double* gaps) const
{
    const Vec2 ci = CenterAt(i, t), cj = CenterAt(j, t);
    const Motion& mi = m_motion[i];
    const Motion& mj = m_motion[j];
    const double scale = Speed(i) + Speed(j);
    // A circle's spin moves no point of its outline along the normal; counted, the round-off of the point's
    // offset times a fast spin would pass for an approach or a parting.
    const double wi = m_world.bodies[i].turnRadius > 0.0 ? mi.w : 0.0;
    const double wj = m_world.bodies[j].turnRadius > 0.0 ? mj.w : 0.0;
    for (int k = 0; k < count; ++k)
    {
        const Vec2 vi = mi.v + wi * LeftPerp(points[k] - ci);
        const Vec2 vj = mj.v + wj * LeftPerp(points[k] - cj);
        // Round-off of the solve leaves a resolved pair approaching by a few ulps of the speeds: that is not an
        // approach, and sweeping it again would find the same hit at the same time. A point with a gap (a
        // speculative contact) may close by the gap within the rest of the step: the contact allows that much.
        const double allowed = gaps != nullptr ? minSpeed + std::max(0.0, gaps[k]) / (std::max(1.0 - t, 1e-12) * m_dt)
                                               : minSpeed;
        if (Dot(vj - vi, normal) < -(1e-9 * scale + allowed))
        {
            return true;
        }
    }
    return false;
}

void TimeOfImpactStage::Connect(int i, int j)
{
    if (std::find(m_near[i].begin(), m_near[i].end(), j) == m_near[i].end())
    {
        m_near[i].push_back(j);
        m_near[j].push_back(i);
    }
}

// The approach speed below which a pair within the slop is left to the next step's contact: slower, it cannot
// overlap by more than the slop before the step ends. A pair pressed together by turning would otherwise take a
// string of tiny hits.
double TimeOfImpactStage::CloseSpeed(double t) const
{
    return m_world.settings.linearSlop / (std::max(1.0 - t, 1e-12) * m_dt);
}

// Conservative advancement of a pair whose turning matters, from t0: see the outline in the header.
bool TimeOfImpactStage::Advance(int i, int j, double t0, Event& event)
{
    const RigidBody& a = m_world.bodies[i];
    const RigidBody& b = m_world.bodies[j];
    const Motion& mi = m_motion[i];
    const Motion& mj = m_motion[j];
    const double approach = Length(mj.v - mi.v) + std::fabs(mi.w) * a.turnRadius + std::fabs(mj.w) * b.turnRadius;
    if (!(approach > 0.0))
    {
        return false;
    }
    // How fast the shapes can close along a fixed direction n (from A to B): along it a point of B gains on a
    // point of A at most at their relative speed along it plus what turning adds (a point at the turn radius moves
    // at the angular speed times it, in any direction). The gap of Collide is the separation along its normal.
    // A pair with a concave body: its gap is the least over its piece pairs, each on its own axis, so the normal
    // of the least one does not bound how fast the others close; the whole relative speed does.
    const bool concavePair = AnyConcave(a, b);
    const auto closingAlong = [&](Vec2 n) {
        const double along = concavePair ? Length(mj.v - mi.v) : std::max(0.0, -Dot(mj.v - mi.v, n));
        return along + std::fabs(mi.w) * a.turnRadius + std::fabs(mj.w) * b.turnRadius;
    };
    const double tolerance = m_world.settings.linearSlop;
    double t = t0;
    for (int pass = 0; pass < kMaxAdvances && t < 1.0; ++pass)
    {
        const Transform xi = PoseAt(i, t);
        const Transform xj = PoseAt(j, t);
        const Manifold m = CollidePair(a, xi, b, xj).manifold;
        Vec2 points[2];
        if (m.overlap)
        {
            for (int k = 0; k < m.contactCount; ++k)
            {
                points[k] = m.contacts[k].point;
            }
            if (m.contactCount > 0 && Approaching(i, j, t, m.normal, points, m.contactCount, CloseSpeed(t)))
            {
                event = {t, i, j, m_stamp[i], m_stamp[j], m.normal, {points[0], points[1]}, m.contactCount};
                return true;
            }
            // Parting where they touch (a hit just resolved): turning, another point of one can still meet the
            // other within the step. Advance by a time in which the overlap along the normal cannot grow by more
            // than the slop, so a new approach is caught before it does.
            const double closing = closingAlong(m.normal);
            if (!(closing > 0.0))
            {
                return false;
            }
            t += tolerance / (closing * m_dt);
            continue;
        }
        if (m.gap <= tolerance)
        {
            // Close enough: the contact points where the shapes would touch, B moved onto A along the normal.
            Transform touching = xj;
            const double shift = m.gap + 0.5 * tolerance;
            touching.p = xj.p - shift * m.normal;
            const Manifold close = CollidePair(a, xi, b, touching).manifold;
            if (close.overlap && close.contactCount > 0)
            {
                for (int k = 0; k < close.contactCount; ++k)
                {
                    points[k] = close.contacts[k].point + (0.5 * shift) * close.normal;
                }
                if (Approaching(i, j, t, close.normal, points, close.contactCount, CloseSpeed(t)))
                {
                    event = {t, i, j, m_stamp[i], m_stamp[j], close.normal, {points[0], points[1]}, close.contactCount};
                    return true;
                }
            }
        }
        // Bodies sliding past each other close slowly along the normal however fast they move, and a pair that
        // cannot close along it stays apart to the step's end.
        const double closing = closingAlong(m.normal);
        if (!(closing > 0.0))
        {
            return false;
        }
        t += (m.gap <= tolerance ? tolerance : m.gap - 0.5 * tolerance) / (closing * m_dt);
    }
    if (t < 1.0)
    {
        // Out of passes before the end of the step and still short of the contact (a body spinning so fast that
        // each pass gains little): the pair stops where it is, which never lets it pass through.
        event = {t, i, j, m_stamp[i], m_stamp[j], {}, {}, 0};
        return true;
    }
    return false;
}

void TimeOfImpactStage::SweepPair(int i, int j, bool anySpeed)
{
    if (!anySpeed && !m_fast[i] && !m_fast[j])
    {
        return;
    }
    const double t0 = std::max(m_motion[i].t, m_motion[j].t);
    if (t0 >= 1.0)
    {
        return;
    }
    if (i > j)
    {
        std::swap(i, j);
    }
    const RigidBody& a = m_world.bodies[i];
    const RigidBody& b = m_world.bodies[j];
    const Motion& mi = m_motion[i];
    const Motion& mj = m_motion[j];
    const double span = (1.0 - t0) * m_dt;
    const double turning = (std::fabs(mi.w) * a.turnRadius + std::fabs(mj.w) * b.turnRadius) * span;
    // Bodies that move together (a pile falling as one) are not swept against each other: what counts is how far
    // a point of one can move relative to the other within the rest of the step.
    if (!anySpeed && m_world.settings.sweepOnlyFast &&
        !OutrunsPair(m_world.settings, a, mi.v, mi.w, b, mj.v, mj.w, span))
    {
        return;
    }
    // Where each body can be over the rest of the step: the box of its outer circle along the path of its centre
    // (a body at rest, its own box). The swept broadphase drew its boxes about the centre at the start, grown by the
    // whole step's speed in every direction; these follow the path from now, and most pairs of a body just hit
    // are apart by them.
    if (!AabbOverlap(PathBox(i, t0), PathBox(j, t0)))
    {
        return;
    }
    ++m_world.counts.swept;
    Event event;
    if (turning <= 0.25 * m_world.settings.linearSlop)
    {
        const Transform xi = PoseAt(i, t0);
        const Transform xj = PoseAt(j, t0);
        // A concave body is swept piece by piece: the earliest piece's hit is the pair's.
        const SweepResult r = AnyConcave(a, b) ? SweepBodies(a, xi, span * mi.v, b, xj, span * mj.v).result
                                               : Sweep(a.shape, xi, span * mi.v, b.shape, xj, span * mj.v);
        if (r.status == SweepStatus::Hit && r.contactCount > 0)
        {
            event = {t0 + r.toi * (1.0 - t0), i, j, m_stamp[i], m_stamp[j], r.normal, {}, r.contactCount};
            for (int k = 0; k < r.contactCount; ++k)
            {
                event.points[k] = r.contacts[k].point;
            }
        }
        else if (r.status == SweepStatus::Overlapping && r.initial.contactCount > 0)
        {
            event = {t0, i, j, m_stamp[i], m_stamp[j], r.initial.normal, {}, r.initial.contactCount};
            for (int k = 0; k < r.initial.contactCount; ++k)
            {
                event.points[k] = r.initial.contacts[k].point;
            }
            // Already touching (a contact of the step, or a pair just parted by a hit): a hit only if it closes
            // faster than the contact could hold within the slop to the step's end; slower, the next step's
            // contact takes it, and a resting pile does not turn into a string of tiny hits.
            if (!Approaching(i, j, t0, event.normal, event.points, event.count, CloseSpeed(t0)))
            {
                return;
            }
        }
        else
        {
            return;
        }
    }
    else if (!Advance(i, j, t0, event))
    {
        return;
    }
    m_queue.push(event);
}

void TimeOfImpactStage::Resolve(const std::vector<Event>& group)
{
    World& world = m_world;
    // Each hit's lever arms, from the centres of mass at the time of that hit. Hits taken together are at times a
    // little apart, and a body's centre at the latest of them, seen from an earlier hit's point, would be off by
    // how far it moved in between: for a ball spinning fast, enough to turn its spin into a false speed along the
    // normal, which the solver would cancel instead of the ball's real approach.
    std::vector<std::array<Vec2, 4>> arms(group.size());
    for (size_t e = 0; e < group.size(); ++e)
    {
        const Event& event = group[e];
        const Vec2 ci = CenterAt(event.i, event.t), cj = CenterAt(event.j, event.t);
        for (int k = 0; k < event.count; ++k)
        {
            arms[e][2 * k] = event.points[k] - ci;
            arms[e][2 * k + 1] = event.points[k] - cj;
        }
    }
    // The bodies of the hits move to the time of their hit; a sleeping body that is hit wakes.
    std::vector<int> bodies;
    for (const Event& event : group)
    {
        for (const int k : {event.i, event.j})
        {
            Motion& m = m_motion[k];
            RigidBody& body = world.bodies[k];
            if (body.type == BodyType::Dynamic && !body.awake)
            {
                body.awake = true;
                body.sleepTime = 0.0;
                m.moves = true;
            }
            if (m.moves && m.t < event.t)
            {
                m.center = CenterAt(k, event.t);
                m.angle += (event.t - m.t) * m_dt * m.w;
                m.t = event.t;
            }
            if (std::find(bodies.begin(), bodies.end(), k) == bodies.end())
            {
                bodies.push_back(k);
            }
        }
    }
    // Hits at the same time are solved together, as the contacts of one step are: a plank landing flat on two
    // supports takes both hits at once and does not start to spin.
    std::vector<SolverBody> solver(bodies.size());
    for (size_t s = 0; s < bodies.size(); ++s)
    {
        const RigidBody& body = world.bodies[bodies[s]];
        if (body.type == BodyType::Dynamic)
        {
            solver[s] = {body.velocity, body.angularVelocity, body.invMass, body.invInertia};
        }
    }
    std::vector<double> energyBefore(bodies.size());
    for (size_t s = 0; s < bodies.size(); ++s)
    {
        energyBefore[s] = Energy(solver[s]);
    }
    auto slot = [&](int k) { return static_cast<int>(std::find(bodies.begin(), bodies.end(), k) - bodies.begin()); };
    // The record of the hits (World::stepTrace): the pair, lower index first, posed at the time of its hit, with the
    // velocities it hit with; those it leaves with are added after the solve.
    StepTrace* stepTrace = world.stepTrace;
    const size_t firstRecord = stepTrace != nullptr ? stepTrace->hits.size() : 0;
    if (stepTrace != nullptr)
    {
        for (const Event& event : group)
        {
            StepHit hit;
            const bool swap = event.j < event.i;
            const int order[2] = {swap ? event.j : event.i, swap ? event.i : event.j};
            hit.time = event.t;
            hit.a = order[0];
            hit.b = order[1];
            hit.normal = swap ? -1.0 * event.normal : event.normal;
            hit.pointCount = event.count;
            for (int k = 0; k < event.count; ++k)
            {
                hit.points[k] = event.points[k];
            }
            for (int side = 0; side < 2; ++side)
            {
                const Transform xf = PoseAt(order[side], event.t);
                hit.position[side] = xf.p;
                hit.angle[side] = std::atan2(xf.q.s, xf.q.c);
                hit.velocityBefore[side] = solver[static_cast<size_t>(slot(order[side]))].v;
                hit.spinBefore[side] = solver[static_cast<size_t>(slot(order[side]))].w;
            }
            stepTrace->hits.push_back(hit);
        }
    }
    std::vector<SolverContact> contacts;
    std::vector<uint8_t> stopped(bodies.size(), 0);
    ContactSolveTrace* trace = world.trace;
    std::vector<int> contactOf(group.size(), -1);
    for (size_t e = 0; e < group.size(); ++e)
    {
        const Event& event = group[e];
        const int i = event.i, j = event.j;
        if (event.count == 0)
        {
            // Conservative advancement ran out of passes short of the contact: both bodies stop there.
            stopped[slot(i)] = 1;
            stopped[slot(j)] = 1;
            continue;
        }
        SolverContact c;
        c.a = slot(i);
        c.b = slot(j);
        c.normal = event.normal;
        c.count = event.count;
        c.material = CombineMaterials(world.bodies[i].material, world.bodies[j].material);
        double approach[2] = {0.0, 0.0};
        for (int k = 0; k < c.count; ++k)
        {
            c.points[k].rA = arms[e][2 * k];
            c.points[k].rB = arms[e][2 * k + 1];
            approach[k] = Dot(RelativeVelocity(solver[c.a], solver[c.b], c.points[k].rA, c.points[k].rB), c.normal);
        }
        // A hit within the step is taken at the surface (no overlap) with the velocities of the move.
        PrepareContact(c, solver[c.a], solver[c.b], approach, 0.0, m_dt, world.settings.restitutionThreshold);
        c.traced =
            trace != nullptr && ((trace->bodyA == i && trace->bodyB == j) || (trace->bodyA == j && trace->bodyB == i));
        if (c.traced)
        {
            if (trace->hits == 0)
            {
                trace->hitTime = event.t;
            }
            ++trace->hits;
        }
        contactOf[e] = static_cast<int>(contacts.size());
        contacts.push_back(c);
        ++world.counts.hits;
    }
    NullSolveRecorder quiet;
    TraceSolveRecorder loud{trace};
    for (int pass = 0; pass < world.settings.velocityIterations; ++pass)
    {
        for (SolverContact& c : contacts)
        {
            if (c.traced)
            {
                SolveContactVelocity(c, solver[c.a], solver[c.b], -1, loud);
            }
            else
            {
                SolveContactVelocity(c, solver[c.a], solver[c.b], -1, quiet);
            }
        }
    }
    ApplyRestitution(contacts, solver, energyBefore, world.settings.velocityIterations);
    // Whether each hit still approaches after the solve, measured at its own points and lever arms. Round-off of
    // the solve leaves a resolved pair approaching by a few ulps of the speeds: that is not an approach.
    std::vector<uint8_t> approaching(group.size(), 0);
    for (size_t e = 0; e < group.size(); ++e)
    {
        if (contactOf[e] < 0)
        {
            continue;
        }
        const SolverContact& c = contacts[static_cast<size_t>(contactOf[e])];
        const SolverBody& sa = solver[static_cast<size_t>(c.a)];
        const SolverBody& sb = solver[static_cast<size_t>(c.b)];
        // The speeds the hit began with set the scale of its round-off: a plank stopped dead is left with speeds
        // of 1e-251, not an approach.
        const double scale = Speed(group[e].i) + Speed(group[e].j);
        for (int k = 0; k < c.count; ++k)
        {
            const double vn = Dot(RelativeVelocity(sa, sb, c.points[k].rA, c.points[k].rB), c.normal);
            approaching[e] = approaching[e] || vn < -1e-9 * scale;
        }
    }
    if (stepTrace != nullptr)
    {
        for (size_t e = 0; e < group.size(); ++e)
        {
            StepHit& hit = stepTrace->hits[firstRecord + e];
            for (int side = 0; side < 2; ++side)
            {
                hit.velocityAfter[side] = solver[static_cast<size_t>(slot(side == 0 ? hit.a : hit.b))].v;
                hit.spinAfter[side] = solver[static_cast<size_t>(slot(side == 0 ? hit.a : hit.b))].w;
            }
        }
    }
    for (const SolverContact& c : contacts)
    {
        if (c.traced)
        {
            trace->restitutionFactor[0] = c.points[0].restitutionFactor;
            trace->restitutionFactor[1] = c.points[1].restitutionFactor;
            trace->restitutionImpulse[0] = c.points[0].restitutionImpulse;
            trace->restitutionImpulse[1] = c.points[1].restitutionImpulse;
        }
    }
    for (size_t s = 0; s < bodies.size(); ++s)
    {
        const int k = bodies[s];
        RigidBody& body = world.bodies[k];
        if (body.type != BodyType::Dynamic)
        {
            continue;
        }
        body.velocity = solver[s].v;
        body.angularVelocity = solver[s].w;
        Motion& m = m_motion[k];
        ++m_stamp[k];
        const bool wedged = ++m_hits[k] >= world.settings.maxHitsPerBody;
        if (stopped[s] || wedged)
        {
            // Stops where it is for the rest of the step. Wedged (it took maxHitsPerBody hits), at rest. Short of a
            // contact conservative advancement could not reach in its passes (a fast spinner beside a wall), its
            // clock stops: it keeps its velocity as of now, without the gravity of the rest of the step, for it
            // does not fall for the rest of the step. Either way the energy it is left with is what it had.
            if (wedged)
            {
                body.velocity = {};
                body.angularVelocity = 0.0;
            }
            else
            {
                body.velocity = body.velocity - ((1.0 - m.t) * m_dt) * world.settings.gravity;
            }
            m.v = {};
            m.w = 0.0;
            m_fast[k] = 0;
            continue;
        }
        m.v = body.velocity;
        m.w = body.angularVelocity;
        m_fast[k] = m_fast[k] || IsFast(k);
        const double speed = Speed(k);
        const Aabb reach = Reach(k, speed);
        const Aabb& drawn = m_reach[k];
        if (!m_connected[k] || reach.min.x < drawn.min.x || reach.min.y < drawn.min.y || reach.max.x > drawn.max.x ||
            reach.max.y > drawn.max.y)
        {
            // It can now reach beyond the box its pairs were found with, or it was slow and its pairs with slow
            // bodies were never listed: find every body it can reach now.
            m_reach[k] = AabbUnion(drawn, reach);
            m_connected[k] = 1;
            for (int o = 0; o < static_cast<int>(world.bodies.size()); ++o)
            {
                if (o != k && AabbOverlap(m_reach[k], m_reach[o]))
                {
                    Connect(k, o);
                }
            }
        }
    }
    // The pairs of the bodies that were hit are swept again from now: the solver's contacts held them only at the
    // velocities of the start of the step. A pair that was just resolved is swept only while it still approaches.
    std::vector<std::pair<int, int>> swept;
    for (const int k : bodies)
    {
        if (world.bodies[k].type != BodyType::Dynamic)
        {
            continue;
        }
        for (const int o : m_near[k])
        {
            const std::pair<int, int> pair{std::min(k, o), std::max(k, o)};
            if (std::find(swept.begin(), swept.end(), pair) != swept.end())
            {
                continue;
            }
            swept.push_back(pair);
            bool resolved = false;
            bool stillApproaching = false;
            for (size_t e = 0; e < group.size(); ++e)
            {
                if (group[e].i == pair.first && group[e].j == pair.second)
                {
                    resolved = true;
                    stillApproaching = stillApproaching || approaching[e];
                }
            }
            // A pair that turns can meet again elsewhere within the step even when its contact points part.
            const double turning = (std::fabs(m_motion[pair.first].w) * world.bodies[pair.first].turnRadius +
                                    std::fabs(m_motion[pair.second].w) * world.bodies[pair.second].turnRadius) *
                                   (1.0 - group.front().t) * m_dt;
            if (resolved && !stillApproaching && turning <= 0.25 * world.settings.linearSlop)
            {
                continue;
            }
            // Against a static body, whatever the speeds: the hit may have sent a slow body into the wall it rests
            // on, and nothing else would stop it there. Other pairs are swept only if fast against each other, and
            // not if the step found them in contact: a slow body can sink into another by less than half its size,
            // and the next step's contact undoes that (waking it, if it sleeps), where sweeping every neighbour of a
            // body in a pile would pass each hit on through the whole pile, one pair at a time.
            const bool wall =
                world.bodies[pair.first].type == BodyType::Static || world.bodies[pair.second].type == BodyType::Static;
            if (!wall && !resolved && ContactOf(world.contacts, pair.first, pair.second) != nullptr)
            {
                continue;
            }
            SweepPair(pair.first, pair.second, wall);
        }
    }
}

void TimeOfImpactStage::Run()
{
    World& world = m_world;
    const int n = static_cast<int>(world.bodies.size());
    m_fast.assign(n, 0);
    bool anyFast = false;
    for (int i = 0; i < n; ++i)
    {
        m_fast[i] = IsFast(i) ? 1 : 0;
        anyFast = anyFast || m_fast[i];
    }
    if (anyFast)
    {
        m_reach.resize(n);
        for (int i = 0; i < n; ++i)
        {
            m_reach[i] = Reach(i, m_motion[i].moves ? Speed(i) : 0.0);
        }
        std::vector<std::pair<int, int>> pairs;
        FindPairs(world.sweptBroadphase, m_reach, pairs, SkipSlowPair, &m_fast);
        m_near.assign(n, {});
        for (const auto& [i, j] : pairs)
        {
            m_near[i].push_back(j);
            m_near[j].push_back(i);
        }
        // A fast body's pairs with every body its reach meets are listed; a slow body's only those with fast ones.
        m_connected = m_fast;
        m_stamp.assign(n, 0);
        m_hits.assign(n, 0);
        for (const auto& [i, j] : pairs)
        {
            // A pair the step's contacts hold is left to them until a hit changes one of its bodies' course. They
            // hold it if the solver left its points closing no faster than the slop (and a speculative point's gap)
            // allows to the step's end, and neither body turning faster than a contact follows
            // (WorldSettings::speculativeTurn): a contact found
            // at the start of the step follows a turn only to first order, and the passes do not always bring a
            // small body pressed by a heavy one to a stop against the floor.
            const WorldContact* contact = ContactOf(world.contacts, i, j);
            if (contact != nullptr && !TurnsFast(i) && !TurnsFast(j))
            {
                Vec2 points[2];
                double gaps[2];
                for (int k = 0; k < contact->pointCount; ++k)
                {
                    points[k] = contact->points[k].point;
                    gaps[k] = contact->points[k].separation;
                }
                if (!Approaching(i, j, 0.0, contact->normal, points, contact->pointCount, CloseSpeed(0.0), gaps))
                {
                    continue;
                }
            }
            SweepPair(i, j);
        }
        std::vector<Event> group;
        while (!m_queue.empty())
        {
            const Event event = m_queue.top();
            m_queue.pop();
            if (event.stampI != m_stamp[event.i] || event.stampJ != m_stamp[event.j])
            {
                continue;
            }
            // The hits within a millionth of the step of this one are taken with it, if their bodies cannot move
            // a quarter of the slop in between: a body at 1e5 units a step moves 0.1 in a millionth of it, and
            // taken at the later time, the earlier hit would find it deep in the wall.
            group.assign(1, event);
            const auto near = [&](const Event& e) {
                return (e.t - event.t) * m_dt * (Speed(e.i) + Speed(e.j)) <= 0.25 * world.settings.linearSlop;
            };
            while (!m_queue.empty() && m_queue.top().t <= event.t + 1e-6 && near(m_queue.top()))
            {
                const Event next = m_queue.top();
                m_queue.pop();
                if (next.stampI == m_stamp[next.i] && next.stampJ == m_stamp[next.j])
                {
                    group.push_back(next);
                }
            }
            Resolve(group);
        }
    }
    m_rotation.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
    {
        Motion& m = m_motion[i];
        if (!m.moves)
        {
            m_rotation[static_cast<size_t>(i)] = m_xfs[i].q;
            continue;
        }
        RigidBody& body = world.bodies[i];
        const Vec2 center = CenterAt(i, 1.0);
        body.angle = m.angle + (1.0 - m.t) * m_dt * m.w;
        const Rot q = MakeRot(body.angle);
        m_rotation[static_cast<size_t>(i)] = q;
        body.position = center - Rotate(q, body.localCenter);
    }
}

} // namespace satviz::detail
