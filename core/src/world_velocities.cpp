// SPDX-License-Identifier: MIT
// satviz: the step's velocity stages: the order of the passes, the velocity passes, the limit on the energy they
// gain, and the impulses kept for the next step's warm start.

#include "parallel_for.h"
#include "stepper.h"
#include "world_lookup.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace satviz::detail
{

namespace
{

// Contacts that one piece of parallel work takes at least: fewer cost more to hand to another thread than to prepare
// here.
constexpr int kContactsPerPiece = 64;

} // namespace

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
    // A least-significant-digit radix sort on the heights' bits: stable, as the ties require, and a few passes over
    // the contacts where a comparison sort takes log m of them. Each height becomes an unsigned key that orders as
    // the doubles do, highest first (-0 is read as +0, which it equals).
    if (m < 2)
    {
        return;
    }
    std::vector<uint64_t> keys(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k)
    {
        const SolverContact& c = solverContacts[static_cast<size_t>(k)];
        const double height = Dot(centers[c.a] + c.points[0].rA, up) + 0.0;
        uint64_t bits = 0;
        std::memcpy(&bits, &height, sizeof bits);
        const uint64_t ascending = (bits >> 63) != 0 ? ~bits : bits | (uint64_t{1} << 63);
        keys[static_cast<size_t>(k)] = ~ascending;
    }
    constexpr int kDigits = 8;
    size_t counts[kDigits][256] = {};
    for (const uint64_t key : keys)
    {
        for (int d = 0; d < kDigits; ++d)
        {
            ++counts[d][(key >> (8 * d)) & 0xffu];
        }
    }
    std::vector<int> spare(static_cast<size_t>(m));
    for (int d = 0; d < kDigits; ++d)
    {
        size_t* count = counts[d];
        // A digit that all keys share leaves the order as it is.
        if (count[(keys[0] >> (8 * d)) & 0xffu] == static_cast<size_t>(m))
        {
            continue;
        }
        size_t next = 0;
        for (int digit = 0; digit < 256; ++digit)
        {
            const size_t c = count[digit];
            count[digit] = next;
            next += c;
        }
        for (const int k : solveOrder)
        {
            spare[count[(keys[static_cast<size_t>(k)] >> (8 * d)) & 0xffu]++] = k;
        }
        solveOrder.swap(spare);
    }
}

// The passes visit every contact in their order some 15 to 35 times a step (velocity, energy, position passes),
// and a contact is larger than a cache line five times over: stored in the order found (the order of their pairs),
// a large world's contacts were read from all over memory at each visit. Stored in the passes' order they are read
// in sequence. The restitution and the impulses kept for the next step go in the order found, through foundOrder.
void Stepper::SortContacts()
{
    const size_t m = solverContacts.size();
    foundOrder.resize(m);
    std::vector<SolverContact>& sorted = memory.spareContacts;
    sorted.resize(m);
    for (size_t p = 0; p < m; ++p)
    {
        const int k = solveOrder[p];
        sorted[p] = solverContacts[static_cast<size_t>(k)];
        foundOrder[static_cast<size_t>(k)] = static_cast<int>(p);
    }
    solverContacts.swap(sorted);
}

void Stepper::SolveVelocities()
{
    PrepareContacts();
    if (settings.softStep)
    {
        SolveSoft();
        return;
    }
    ContactSolveTrace* trace = world.trace;
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
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
    SortContacts();
    detail::NullSolveRecorder quiet;
    detail::TraceSolveRecorder loud{trace};
    const auto solveOne = [&](SolverContact& c, int pass) {
        if (c.traced)
        {
            detail::SolveContactVelocity(c, solverBodies[c.a], solverBodies[c.b], pass, loud);
        }
        else
        {
            detail::SolveContactVelocity(c, solverBodies[c.a], solverBodies[c.b], pass, quiet);
        }
    };
    const auto solvePass = [&](const std::vector<int>& order, int pass) {
        for (const int k : order)
        {
            solveOne(solverContacts[static_cast<size_t>(k)], pass);
        }
    };
    for (int pass = 0; pass < settings.velocityIterations; ++pass)
    {
        for (SolverContact& c : solverContacts)
        {
            solveOne(c, pass);
        }
    }
    LimitEnergyGain(unsolved, solvePass);
    detail::ApplyRestitution(solverContacts, foundOrder, solverBodies, energyBefore, settings.velocityIterations);
    RecordAfter();
}

void Stepper::RecordAfter()
{
    ContactSolveTrace* trace = world.trace;
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

void Stepper::PrepareContacts()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    solverBodies.assign(n, SolverBody{});
    centers.resize(n);
    // Whether each body moves, read once in order: a body is several cache lines, read again for each of its
    // contacts below.
    std::vector<uint8_t>& moving = memory.moving;
    moving.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
    {
        const RigidBody& body = bodies[i];
        centers[i] = TransformPoint(xfs[i], body.localCenter);
        moving[static_cast<size_t>(i)] = IsAwakeDynamic(body) ? 1 : 0;
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
    // The normal velocity of each point of a contact before gravity: what decides its bounce.
    const auto approachOf = [&](const SolverContact& c, double approach[2]) {
        for (int i = 0; i < c.count; ++i)
        {
            const detail::SolverPoint& p = c.points[i];
            approach[i] = Dot(detail::RelativeVelocity(solverBodies[c.a], solverBodies[c.b], p.rA, p.rB), c.normal);
        }
    };
    // The contacts are cut into pieces prepared on any thread, each piece's solver contacts and guards appended to
    // lists of its own; the first piece's lists are the step's, and the others follow them in order, as from one
    // pass over the contacts. On one thread there is one piece.
    const int contactCount = static_cast<int>(world.contacts.size());
    const int pieces = PieceCount(world.tasks, contactCount, kContactsPerPiece);
    solverContacts.clear();
    // Grown by at least half again when it must grow: a list grown to the exact count each time a world's contacts
    // grow by a few would be allocated afresh, and its pages touched anew, step after step.
    if (solverContacts.capacity() < world.contacts.size())
    {
        solverContacts.reserve(
            std::max(world.contacts.size(), solverContacts.capacity() + solverContacts.capacity() / 2));
    }
    guards.clear();
    std::vector<std::vector<SolverContact>> laterContacts(static_cast<size_t>(pieces - 1));
    std::vector<std::vector<SolverContact>> laterGuards(static_cast<size_t>(pieces - 1));
    const auto prepare = [&](int piece, int begin, int end) {
        std::vector<SolverContact>& contactsOut =
            piece == 0 ? solverContacts : laterContacts[static_cast<size_t>(piece - 1)];
        std::vector<SolverContact>& guardsOut = piece == 0 ? guards : laterGuards[static_cast<size_t>(piece - 1)];
        for (int k = begin; k < end; ++k)
        {
            const WorldContact& wc = world.contacts[static_cast<size_t>(k)];
            const bool movesA = moving[static_cast<size_t>(wc.a)] != 0;
            const bool movesB = moving[static_cast<size_t>(wc.b)] != 0;
            if (!movesA && !movesB)
            {
                continue;
            }
            // Built in place in its list: a solver contact is several cache lines, not worth building aside and
            // copying.
            SolverContact& c = (wc.guard ? guardsOut : contactsOut).emplace_back();
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
                continue;
            }
            double approach[2] = {0.0, 0.0};
            approachOf(c, approach);
            for (int i = 0; i < c.count; ++i)
            {
                detail::SolverPoint& p = c.points[i];
                p.gapSpeed = std::max(0.0, p.separation) / dt;
                p.approach = approach[i];
                // The soft step warm starts each sub-step from the last sub-step's impulses.
                p.normalImpulse = settings.softStep ? wc.points[i].subStepNormalImpulse : wc.points[i].normalImpulse;
                p.tangentImpulse = settings.softStep ? wc.points[i].subStepTangentImpulse : wc.points[i].tangentImpulse;
            }
            // How fast gravity closes the pair along the normal: it pulls only the awake dynamic bodies.
            const Vec2 gravityA = movesA ? settings.gravity : Vec2{};
            const Vec2 gravityB = movesB ? settings.gravity : Vec2{};
            const double pull = std::max(0.0, -Dot(gravityB - gravityA, c.normal));
            detail::PrepareContact(c, solverBodies[c.a], solverBodies[c.b], approach, pull, dt,
                                   settings.restitutionThreshold);
        }
    };
    ParallelForPieces(world.tasks, contactCount, pieces, prepare);
    for (int piece = 1; piece < pieces; ++piece)
    {
        const std::vector<SolverContact>& more = laterContacts[static_cast<size_t>(piece - 1)];
        solverContacts.insert(solverContacts.end(), more.begin(), more.end());
        const std::vector<SolverContact>& moreGuards = laterGuards[static_cast<size_t>(piece - 1)];
        guards.insert(guards.end(), moreGuards.begin(), moreGuards.end());
    }
    // The traced pair's contact, if any, records what it starts the passes with.
    for (SolverContact& c : solverContacts)
    {
        if (trace == nullptr)
        {
            break;
        }
        if (((trace->bodyA == c.a && trace->bodyB == c.b) || (trace->bodyA == c.b && trace->bodyB == c.a)))
        {
            double approach[2] = {0.0, 0.0};
            approachOf(c, approach);
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
    for (int k = 0; k < static_cast<int>(solverContacts.size()); ++k)
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
    for (const int found : foundOrder)
    {
        const SolverContact& c = solverContacts[static_cast<size_t>(found)];
        while (world.contacts[k].a != c.a || world.contacts[k].b != c.b)
        {
            ++k;
        }
        WorldContact& wc = world.contacts[k];
        for (int i = 0; i < c.count; ++i)
        {
            // A bounce's own impulse is an impact, not a load the point will carry next step: only the compression
            // part is warm started.
            wc.points[i].subStepNormalImpulse = c.points[i].normalImpulse - c.points[i].restitutionImpulse;
            wc.points[i].subStepTangentImpulse = c.points[i].tangentImpulse;
            // The soft step's sub-steps each apply their accumulated impulses: the step's are their sum.
            wc.points[i].normalImpulse = settings.softStep ? c.points[i].normalTotal : wc.points[i].subStepNormalImpulse;
            wc.points[i].tangentImpulse =
                settings.softStep ? c.points[i].tangentTotal : wc.points[i].subStepTangentImpulse;
            wc.points[i].stuck = c.points[i].stuck;
        }
    }
}

} // namespace satviz::detail
