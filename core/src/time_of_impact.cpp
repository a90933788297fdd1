// SPDX-License-Identifier: MIT
// satviz: the world's positions stage with time-ordered hits.

#include "time_of_impact.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <cmath>

namespace satviz::detail
{

namespace
{

bool IsAwakeDynamic(const RigidBody& body)
{
    return body.type == BodyType::Dynamic && body.awake;
}

bool InContact(const std::vector<WorldContact>& contacts, int a, int b)
{
    auto it = std::lower_bound(contacts.begin(), contacts.end(), std::make_pair(a, b),
                               [](const WorldContact& c, const std::pair<int, int>& key) {
                                   return c.a < key.first || (c.a == key.first && c.b < key.second);
                               });
    return it != contacts.end() && it->a == a && it->b == b;
}

bool SkipSlowPair(const void* context, int i, int j)
{
    const std::vector<uint8_t>& fast = *static_cast<const std::vector<uint8_t>*>(context);
    return !fast[i] && !fast[j];
}

// Most passes of conservative advancement for one pair; a pair still apart after them counts as a miss.
constexpr int kMaxAdvances = 64;

} // namespace

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

double TimeOfImpactStage::Speed(int i) const
{
    const Motion& m = m_motion[i];
    return Length(m.v) + std::fabs(m.w) * m_world.bodies[i].outerRadius;
}

bool TimeOfImpactStage::IsFast(int i) const
{
    if (!m_motion[i].moves)
    {
        return false;
    }
    const double travel = Speed(i) * m_dt;
    if (!m_world.settings.sweepOnlyFast)
    {
        return travel > 0.0;
    }
    return travel > m_world.settings.sweepFraction * m_world.bodies[i].innerRadius;
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
                                    double minSpeed) const
{
    const Vec2 ci = CenterAt(i, t), cj = CenterAt(j, t);
    const Motion& mi = m_motion[i];
    const Motion& mj = m_motion[j];
    const double scale = Speed(i) + Speed(j);
    for (int k = 0; k < count; ++k)
    {
        const Vec2 vi = mi.v + mi.w * LeftPerp(points[k] - ci);
        const Vec2 vj = mj.v + mj.w * LeftPerp(points[k] - cj);
        // Round-off of the solve leaves a resolved pair approaching by a few ulps of the speeds: that is not an
        // approach, and sweeping it again would find the same hit at the same time.
        if (Dot(vj - vi, normal) < -(1e-9 * scale + minSpeed))
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
    const double approach = Length(mj.v - mi.v) + std::fabs(mi.w) * a.outerRadius + std::fabs(mj.w) * b.outerRadius;
    if (!(approach > 0.0))
    {
        return false;
    }
    const double tolerance = m_world.settings.linearSlop;
    double t = t0;
    for (int pass = 0; pass < kMaxAdvances && t < 1.0; ++pass)
    {
        const Transform xi = PoseAt(i, t);
        const Transform xj = PoseAt(j, t);
        const Manifold m = Collide(a.shape, xi, b.shape, xj);
        Vec2 points[2];
        if (m.overlap)
        {
            for (int k = 0; k < m.contactCount; ++k)
            {
                points[k] = m.contacts[k].point;
            }
            if (m.contactCount == 0 || !Approaching(i, j, t, m.normal, points, m.contactCount, CloseSpeed(t)))
            {
                return false;
            }
            event = {t, i, j, m_stamp[i], m_stamp[j], m.normal, {points[0], points[1]}, m.contactCount};
            return true;
        }
        if (m.gap <= tolerance)
        {
            // Close enough: the contact points where the shapes would touch, B moved onto A along the normal.
            Transform touching = xj;
            const double shift = m.gap + 0.5 * tolerance;
            touching.p = xj.p - shift * m.normal;
            const Manifold close = Collide(a.shape, xi, b.shape, touching);
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
            t += tolerance / (approach * m_dt);
            continue;
        }
        t += (m.gap - 0.5 * tolerance) / (approach * m_dt);
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

void TimeOfImpactStage::SweepPair(int i, int j)
{
    if (!m_fast[i] && !m_fast[j])
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
    const double turning = (std::fabs(mi.w) * a.outerRadius + std::fabs(mj.w) * b.outerRadius) * span;
    // Bodies that move together (a pile falling as one) are not swept against each other: what counts is how far
    // a point of one can move relative to the other within the rest of the step.
    if (m_world.settings.sweepOnlyFast)
    {
        const double relative = Length(mj.v - mi.v) * span + turning;
        const double size = std::min(a.type == BodyType::Dynamic ? a.innerRadius : INFINITY,
                                     b.type == BodyType::Dynamic ? b.innerRadius : INFINITY);
        if (!(relative > m_world.settings.sweepFraction * size))
        {
            return;
        }
    }
    ++m_world.counts.swept;
    Event event;
    if (turning <= 0.25 * m_world.settings.linearSlop)
    {
        const Transform xi = PoseAt(i, t0);
        const Transform xj = PoseAt(j, t0);
        const SweepResult r = Sweep(a.shape, xi, span * mi.v, b.shape, xj, span * mj.v);
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
            if (!Approaching(i, j, t0, event.normal, event.points, event.count))
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
    std::vector<SolverContact> contacts;
    std::vector<uint8_t> stopped(bodies.size(), 0);
    ContactSolveTrace* trace = world.trace;
    for (const Event& event : group)
    {
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
            c.points[k].rA = event.points[k] - m_motion[i].center;
            c.points[k].rB = event.points[k] - m_motion[j].center;
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
        if (stopped[s] || ++m_hits[k] >= world.settings.maxHitsPerBody)
        {
            // Stops where it is for the rest of the step.
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
        if (reach.min.x < drawn.min.x || reach.min.y < drawn.min.y || reach.max.x > drawn.max.x ||
            reach.max.y > drawn.max.y)
        {
            // It can now reach beyond the box its pairs were found with: find the bodies it can reach now.
            m_reach[k] = AabbUnion(drawn, reach);
            for (int o = 0; o < static_cast<int>(world.bodies.size()); ++o)
            {
                if (o != k && AabbOverlap(m_reach[k], m_reach[o]) &&
                    !InContact(world.contacts, std::min(k, o), std::max(k, o)))
                {
                    Connect(k, o);
                }
            }
        }
    }
    // The pairs of the bodies that were hit are swept again from now. A pair that was just resolved is swept only
    // while it still approaches.
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
            bool approaching = false;
            for (const Event& event : group)
            {
                if (event.i == pair.first && event.j == pair.second)
                {
                    resolved = true;
                    approaching = approaching ||
                                  (event.count > 0 &&
                                   Approaching(event.i, event.j, event.t, event.normal, event.points, event.count));
                }
            }
            // A pair that turns can meet again elsewhere within the step even when its contact points part.
            const double turning = (std::fabs(m_motion[pair.first].w) * world.bodies[pair.first].outerRadius +
                                    std::fabs(m_motion[pair.second].w) * world.bodies[pair.second].outerRadius) *
                                   (1.0 - group.front().t) * m_dt;
            if (resolved && !approaching && turning <= 0.25 * world.settings.linearSlop)
            {
                continue;
            }
            SweepPair(pair.first, pair.second);
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
            if (!InContact(world.contacts, i, j))
            {
                m_near[i].push_back(j);
                m_near[j].push_back(i);
            }
        }
        m_stamp.assign(n, 0);
        m_hits.assign(n, 0);
        for (const auto& [i, j] : pairs)
        {
            if (!InContact(world.contacts, i, j))
            {
                SweepPair(i, j);
            }
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
            // The hits within a millionth of the step of this one are taken with it.
            group.assign(1, event);
            while (!m_queue.empty() && m_queue.top().t <= event.t + 1e-6)
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
    for (int i = 0; i < n; ++i)
    {
        Motion& m = m_motion[i];
        if (!m.moves)
        {
            continue;
        }
        RigidBody& body = world.bodies[i];
        const Vec2 center = CenterAt(i, 1.0);
        body.angle = m.angle + (1.0 - m.t) * m_dt * m.w;
        body.position = center - Rotate(MakeRot(body.angle), body.localCenter);
    }
}

} // namespace satviz::detail
