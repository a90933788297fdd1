// SPDX-License-Identifier: MIT
// satviz: the world's positions stage with time-ordered hits.

#include "time_of_impact.h"

#include "body_queries.h"
#include "parallel_for.h"
#include "world_lookup.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <cmath>

namespace satviz::detail
{

namespace
{

bool SkipSlowPair(const void* context, int i, int j)
{
    const std::vector<uint8_t>& fast = *static_cast<const std::vector<uint8_t>*>(context);
    return !fast[i] && !fast[j];
}

// Most passes of conservative advancement for one pair; a pair still apart after them counts as a miss.
constexpr int kMaxAdvances = 64;

// Bodies that one piece of parallel work takes at least: fewer cost more to hand to another thread than to move here.
constexpr int kBodiesPerPiece = 128;
constexpr int kPairsPerPiece = 32; // the same for pairs to sweep

} // namespace

// Speeds by std::sqrt rather than Length's std::hypot: these only decide which pairs to sweep, and run for every
// candidate pair of every step.
bool OutrunsBody(const WorldSettings& settings, const RigidBody& body, Vec2 v, double w, double span)
{
    return (std::sqrt(LengthSquared(v)) + std::fabs(w) * body.turnRadius) * span >
           settings.sweepFraction * body.innerRadius;
}

bool TurnsBeyondContacts(const WorldSettings& settings, const RigidBody& body, double w, double span)
{
    return body.turnRadius > 0.0 && std::fabs(w) * span > settings.speculativeTurn;
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
                                     const std::vector<Vec2>& centers, const std::vector<SolverBody>& solverBodies,
                                     std::vector<std::vector<int>>& near)
    : m_world(world), m_dt(dt), m_xfs(xfs), m_near(near)
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
            m.fallsUntil = 1.0;
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
    return TurnsBeyondContacts(m_world.settings, m_world.bodies[i], m_motion[i].w, m_dt);
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

// Connects body k with every body whose reach meets k's, in ascending order of the bodies, as a pass over all of
// them would; the search reads a grid of the reaches rather than every body. Body k's reach has just grown: the
// grid reads it whole from now on.
void TimeOfImpactStage::ConnectReach(int k)
{
    if (!m_reachFiled)
    {
        m_reachGrid.Make(m_reach);
        m_reachFiled = true;
    }
    m_reachGrid.Meeting(m_reach, m_reach[static_cast<size_t>(k)], k, m_met);
    for (const int o : m_met)
    {
        Connect(k, o);
    }
    m_reachGrid.Unfile(k);
}

// The approach speed below which a pair within the slop is left to the next step's contact: slower, it cannot
// overlap by more than the slop before the step ends. A pair pressed together by turning would otherwise take a
// string of tiny hits.
double TimeOfImpactStage::CloseSpeed(double t) const
{
    return m_world.settings.linearSlop / (std::max(1.0 - t, 1e-12) * m_dt);
}

// Conservative advancement of a pair whose turning matters, from t0: see the outline in the header.
bool TimeOfImpactStage::Advance(int i, int j, double t0, Event& event) const
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
    Event event;
    const SweepOutcome outcome = SweepPairEvent(i, j, anySpeed, event);
    if (outcome != SweepOutcome::Skipped)
    {
        ++m_world.counts.swept;
    }
    if (outcome == SweepOutcome::Hit)
    {
        m_queue.push(event);
    }
}

TimeOfImpactStage::SweepOutcome TimeOfImpactStage::SweepPairEvent(int i, int j, bool anySpeed, Event& event) const
{
    if (!anySpeed && !m_fast[i] && !m_fast[j])
    {
        return SweepOutcome::Skipped;
    }
    const double t0 = std::max(m_motion[i].t, m_motion[j].t);
    if (t0 >= 1.0)
    {
        return SweepOutcome::Skipped;
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
        return SweepOutcome::Skipped;
    }
    // Where each body can be over the rest of the step: the box of its outer circle along the path of its centre
    // (a body at rest, its own box). The swept broadphase drew its boxes about the centre at the start, grown by the
    // whole step's speed in every direction; these follow the path from now, and most pairs of a body just hit
    // are apart by them.
    if (!AabbOverlap(PathBox(i, t0), PathBox(j, t0)))
    {
        return SweepOutcome::Skipped;
    }
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
                return SweepOutcome::Missed;
            }
        }
        else
        {
            return SweepOutcome::Missed;
        }
    }
    else if (!Advance(i, j, t0, event))
    {
        return SweepOutcome::Missed;
    }
    return SweepOutcome::Hit;
}

// A pair the step's contacts hold is left to them until a hit changes one of its bodies' course. They hold it if the
// solver left its points closing no faster than the slop (and a speculative point's gap) allows to the step's end,
// and neither body turning faster than a contact follows (WorldSettings::speculativeTurn): a contact found at the
// start of the step follows a turn only to first order, and the passes do not always bring a small body pressed by
// a heavy one to a stop against the floor.
bool TimeOfImpactStage::HeldByContact(int i, int j) const
{
    const WorldContact* contact = ContactOf(m_world.contacts, i, j);
    if (contact == nullptr || TurnsFast(i) || TurnsFast(j))
    {
        return false;
    }
    Vec2 points[2];
    double gaps[2];
    for (int k = 0; k < contact->pointCount; ++k)
    {
        points[k] = contact->points[k].point;
        gaps[k] = contact->points[k].separation;
    }
    return !Approaching(i, j, 0.0, contact->normal, points, contact->pointCount, CloseSpeed(0.0), gaps);
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
        // Emptied, not freed: a list keeps the memory of the steps before.
        m_near.resize(static_cast<size_t>(n));
        for (std::vector<int>& list : m_near)
        {
            list.clear();
        }
        for (const auto& [i, j] : pairs)
        {
            m_near[i].push_back(j);
            m_near[j].push_back(i);
        }
        // A fast body's pairs with every body its reach meets are listed; a slow body's only those with fast ones.
        m_connected = m_fast;
        m_stamp.assign(n, 0);
        m_hits.assign(n, 0);
        // The first sweeps: before any hit, each pair's depends on the start of the step alone, so each goes into
        // its own slot on any thread, and the events are queued in the pairs' order.
        const int pairCount = static_cast<int>(pairs.size());
        std::vector<Event> events(pairs.size());
        std::vector<SweepOutcome> outcomes(pairs.size(), SweepOutcome::Skipped);
        const auto sweep = [&](int begin, int end) {
            for (int k = begin; k < end; ++k)
            {
                const auto [i, j] = pairs[static_cast<size_t>(k)];
                if (!HeldByContact(i, j))
                {
                    outcomes[static_cast<size_t>(k)] = SweepPairEvent(i, j, false, events[static_cast<size_t>(k)]);
                }
            }
        };
        ParallelFor(world.tasks, pairCount, kPairsPerPiece, sweep);
        for (int k = 0; k < pairCount; ++k)
        {
            const SweepOutcome outcome = outcomes[static_cast<size_t>(k)];
            world.counts.swept += outcome != SweepOutcome::Skipped;
            if (outcome == SweepOutcome::Hit)
            {
                m_queue.push(events[static_cast<size_t>(k)]);
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
    // Every body moves on to the end of the step, body by body on any thread.
    m_rotation.resize(static_cast<size_t>(n));
    const auto finish = [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
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
    };
    ParallelFor(world.tasks, n, kBodiesPerPiece, finish);
}

} // namespace satviz::detail
