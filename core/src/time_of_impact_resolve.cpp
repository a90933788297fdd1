// SPDX-License-Identifier: MIT
// satviz: the world's positions stage: a group of hits at one time resolved together, with the solver's impulses.

#include "time_of_impact.h"
#include "world_lookup.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace satviz::detail
{

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
    std::vector<int> inOrder(contacts.size());
    for (size_t k = 0; k < contacts.size(); ++k)
    {
        inOrder[k] = static_cast<int>(k);
    }
    ApplyRestitution(contacts, inOrder, solver, energyBefore, world.settings.velocityIterations);
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
            // Stopped again later in the step (a fast spinner swept against it), it has no more gravity to give
            // back: taking the rest of the step's off once more would throw it upwards, energy from nowhere.
            if (wedged)
            {
                body.velocity = {};
                body.angularVelocity = 0.0;
            }
            else
            {
                body.velocity = body.velocity - (std::max(0.0, m.fallsUntil - m.t) * m_dt) * world.settings.gravity;
            }
            m.fallsUntil = std::min(m.fallsUntil, m.t);
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
            ConnectReach(k);
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

} // namespace satviz::detail
