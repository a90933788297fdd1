// SPDX-License-Identifier: MIT
// satviz: the soft step (WorldSettings::softStep): sub-steps of soft contacts in place of the velocity passes, the
// restitution's push-only passes and the position passes.

#include "stepper.h"
#include "world_lookup.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace satviz::detail
{

namespace
{

// q turned further by the small angle `angle`: q + angle * perp(q), normalised. A sub-step turns a body by little,
// and this rotation only carries the anchors (the body's angle is summed exactly), so the difference from the exact
// turn, of the order of angle^3, is not worth a sine and a cosine per body and sub-step.
Rot TurnBy(Rot q, double angle)
{
    const double c = q.c - angle * q.s;
    const double s = q.s + angle * q.c;
    const double inv = 1.0 / std::sqrt(c * c + s * s);
    return {c * inv, s * inv};
}

// Passes of the restitution over the bouncing contacts: enough for a few contacts that land together to agree.
constexpr int kRestitutionPasses = 4;

bool Fixed(const SolverBody& s)
{
    return s.invMass == 0.0 && s.invInertia == 0.0;
}

} // namespace

void MakeSoftContact(SoftContact& s, const SolverContact& c, const SolverBody& sa, const SolverBody& sb)
{
    s.a = c.a;
    s.b = c.b;
    s.count = static_cast<uint8_t>(c.count);
    s.block = c.block;
    s.stiff = Fixed(sa) || Fixed(sb);
    s.traced = c.traced;
    s.normal = c.normal;
    s.friction = c.material.friction;
    s.staticFriction = c.material.staticFriction;
    s.invMassA = sa.invMass;
    s.invInertiaA = sa.invInertia;
    s.invMassB = sb.invMass;
    s.invInertiaB = sb.invInertia;
    s.k11 = c.k11;
    s.k12 = c.k12;
    s.k22 = c.k22;
    s.bounces = false;
    for (int i = 0; i < c.count; ++i)
    {
        const SolverPoint& p = c.points[i];
        SoftPoint& q = s.points[i];
        q.rnA = Cross(p.rA, c.normal);
        q.rnB = Cross(p.rB, c.normal);
        q.rtA = Cross(p.rA, RightPerp(c.normal));
        q.rtB = Cross(p.rB, RightPerp(c.normal));
        q.separation = p.separation;
        q.normalMass = p.normalMass;
        q.tangentMass = p.tangentMass;
        q.normalImpulse = p.normalImpulse;
        q.tangentImpulse = p.tangentImpulse;
        q.maxNormalImpulse = 0.0;
        s.bounces = s.bounces || p.bounce > 0.0;
    }
}

bool SoftBounceTargets(SolverContact& solved, const SoftContact& c, const SoftBody& a, const SoftBody& b, double pull,
                       double h, double dt)
{
    bool any = false;
    const double e = solved.material.restitution;
    for (int i = 0; i < solved.count; ++i)
    {
        SolverPoint& p = solved.points[i];
        p.restitutionImpulse = 0.0;
        if (!(p.bounce > 0.0) || c.points[i].maxNormalImpulse == 0.0)
        {
            p.bounce = 0.0;
            continue;
        }
        const double v = p.approach;
        const double d = p.separation < 0.0 ? std::min(-p.separation, -v * dt) : -p.separation;
        const double down = v - 0.5 * pull * h;
        const double u2 = std::max(0.0, down * down - 2.0 * pull * d);
        const double s = SeparationNow(c.points[i], Dot(b.position - a.position, c.normal), a.rotation, b.rotation);
        p.bounce = 0.5 * pull * h + std::sqrt(std::max(0.0, e * e * u2 - 2.0 * pull * s));
        any = true;
    }
    return any;
}

void ApplySoftRestitution(SolverContact& solved, SoftContact& c, SoftBody& a, SoftBody& b)
{
    if (c.block && solved.points[0].bounce > 0.0 && solved.points[1].bounce > 0.0)
    {
        const double target[2] = {solved.points[0].bounce, solved.points[1].bounce};
        double applied[2] = {0.0, 0.0};
        SoftPair v = LoadPair(a, b);
        SolveNormalBlock(c, v, target, applied);
        StorePair(v, a, b);
        solved.points[0].restitutionImpulse += applied[0];
        solved.points[1].restitutionImpulse += applied[1];
        return;
    }
    for (int i = 0; i < c.count; ++i)
    {
        SoftPoint& p = c.points[i];
        const double bounce = solved.points[i].bounce;
        if (!(bounce > 0.0))
        {
            continue;
        }
        SoftPair v = LoadPair(a, b);
        const double vn = SpeedAlong(v, c.normal, p.rnA, p.rnB);
        const double next = std::max(0.0, p.normalImpulse - p.normalMass * (vn - bounce));
        const double applied = next - p.normalImpulse;
        p.normalImpulse = next;
        solved.points[i].restitutionImpulse += applied;
        ApplyImpulse(c, v, c.normal, p.rnA, p.rnB, applied);
        StorePair(v, a, b);
    }
}

// Catto's soft step ("Solver2D", 2024; Box2D v3). The contacts were prepared once (PrepareContacts); each sub-step
// then integrates gravity, warm starts, solves with the soft push, moves the bodies and relaxes. Compared with the
// velocity passes and the position passes it replaces: the overlap is taken out by velocities within the sub-steps,
// so there is no separate position stage measuring each contact again, and a small time step makes a few passes
// as good as many (the error of an unconverged pass shrinks with h).
void Stepper::SolveSoft()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    const int subSteps = std::max(1, settings.subSteps);
    const double h = dt / subSteps;
    const double invH = 1.0 / h;
    // As in the velocity passes: top down, so that a pile's weight reaches its lower rows within one pass.
    OrderTopDown();
    const int m = static_cast<int>(solverContacts.size());
    // The colours (after Box2D v3's graph colouring, here by levels): each contact, taken top down, gets the first
    // colour after those of the contacts before it that share a body the passes move, the largest of its moving
    // bodies' next free colours. Two contacts that share such a body are then visited in the top-down order (the
    // higher has the lower colour), and two that do not commute: visiting the colours in turn gives the same bits
    // as visiting the contacts top down one at a time, and a colour's contacts may be visited side by side. Static
    // and sleeping bodies do not count: with no inverse mass, a visit leaves their velocities as they are.
    std::vector<int>& level = memory.softLevels;
    level.assign(static_cast<size_t>(n), 0);
    std::vector<int>& keys = memory.softKeys;
    keys.resize(static_cast<size_t>(m));
    int colours = 0;
    for (int k = 0; k < m; ++k)
    {
        const SolverContact& c = solverContacts[static_cast<size_t>(solveOrder[static_cast<size_t>(k)])];
        const bool movesA = IsAwakeDynamic(bodies[c.a]);
        const bool movesB = IsAwakeDynamic(bodies[c.b]);
        const int colour = std::max(movesA ? level[static_cast<size_t>(c.a)] : 0,
                                    movesB ? level[static_cast<size_t>(c.b)] : 0);
        if (movesA)
        {
            level[static_cast<size_t>(c.a)] = colour + 1;
        }
        if (movesB)
        {
            level[static_cast<size_t>(c.b)] = colour + 1;
        }
        keys[static_cast<size_t>(k)] = colour;
        colours = std::max(colours, colour + 1);
    }
    // The contacts by colour, stable (a counting sort), and the passes' order with them.
    std::vector<int>& starts = level;
    starts.assign(static_cast<size_t>(colours + 1), 0);
    for (const int key : keys)
    {
        ++starts[static_cast<size_t>(key) + 1];
    }
    for (size_t key = 1; key < starts.size(); ++key)
    {
        starts[key] += starts[key - 1];
    }
    std::vector<int>& order = memory.softOrder;
    order.resize(static_cast<size_t>(m));
    foundOrder.resize(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k)
    {
        const size_t key = static_cast<size_t>(keys[static_cast<size_t>(k)]);
        order[static_cast<size_t>(starts[key]++)] = solveOrder[static_cast<size_t>(k)];
    }
    solveOrder.swap(order);
    // Each contact is copied once into the small record the passes read, stored in that order so that each pass
    // reads them in sequence; the solver contacts stay in the order found.
    std::vector<SoftContact>& contacts = memory.softContacts;
    contacts.resize(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k)
    {
        foundOrder[static_cast<size_t>(k)] = k;
        const int found = solveOrder[static_cast<size_t>(k)];
        const SolverContact& c = solverContacts[static_cast<size_t>(found)];
        MakeSoftContact(contacts[static_cast<size_t>(k)], c, solverBodies[c.a], solverBodies[c.b]);
    }
    const auto solvedAt = [&](int k) -> SolverContact& {
        return solverContacts[static_cast<size_t>(solveOrder[static_cast<size_t>(k)])];
    };
    std::vector<SoftBody>& states = memory.softBodies;
    states.assign(static_cast<size_t>(n), SoftBody{});
    std::vector<int>& awake = memory.softAwake;
    awake.clear();
    for (int i = 0; i < n; ++i)
    {
        states[static_cast<size_t>(i)].v = solverBodies[i].v;
        states[static_cast<size_t>(i)].w = solverBodies[i].w;
        if (IsAwakeDynamic(bodies[i]))
        {
            // A body whose turn moves no point of its outline (a circle about its centre) keeps its anchors
            // unturned (the normal between two circles joins their centres, whatever they turn): stored as -1 - i.
            awake.push_back(bodies[i].turnRadius > 0.0 ? i : -1 - i);
        }
    }
    // A spring faster than a quarter of the sub-step rate is not resolved by the sub-step: it would only add
    // stiffness that the implicit step turns into damping. Against a body that cannot give way (static, asleep) the
    // spring is twice as stiff: a body in a pile pressed into the ground by the weight above must not sink.
    const double hertz = std::min(settings.contactHertz, 0.25 * invH);
    const Softness soft = hertz > 0.0 ? MakeSoftness(hertz, settings.contactDampingRatio, h) : Softness{};
    const Softness stiff = hertz > 0.0 ? MakeSoftness(2.0 * hertz, settings.contactDampingRatio, h) : Softness{};
    NullSolveRecorder quiet;
    TraceSolveRecorder loud{world.trace};
    // A pass visits the contacts colour by colour (the order of the records).
    const auto pass = [&](auto useBias, int number) {
        constexpr bool kUseBias = decltype(useBias)::value;
        for (SoftContact& c : contacts)
        {
            SoftBody& a = states[static_cast<size_t>(c.a)];
            SoftBody& b = states[static_cast<size_t>(c.b)];
            const Softness& softness = c.stiff ? stiff : soft;
            if (c.traced)
            {
                SolveSoftContact<kUseBias>(c, a, b, softness, invH, settings.maxPushSpeed, number, loud);
            }
            else
            {
                SolveSoftContact<kUseBias>(c, a, b, softness, invH, settings.maxPushSpeed, number, quiet);
            }
        }
    };
    for (int sub = 0; sub < subSteps; ++sub)
    {
        for (const int code : awake)
        {
            SoftBody& s = states[static_cast<size_t>(code >= 0 ? code : -1 - code)];
            s.v = s.v + h * settings.gravity;
        }
        for (SoftContact& c : contacts)
        {
            WarmStart(c, states[static_cast<size_t>(c.a)], states[static_cast<size_t>(c.b)]);
        }
        pass(std::true_type{}, 2 * sub);
        for (const int code : awake)
        {
            SoftBody& s = states[static_cast<size_t>(code >= 0 ? code : -1 - code)];
            s.position = s.position + h * s.v;
            s.angle += h * s.w;
            if (code >= 0)
            {
                s.rotation = TurnBy(s.rotation, h * s.w);
            }
        }
        pass(std::false_type{}, 2 * sub + 1);
    }
    // Restitution after the sub-steps: the bounce speed is the target of the velocity the step ends with. A few
    // passes over the bouncing contacts alone, so that contacts that land together (a plank on two supports) share
    // the bounce as they would solved together, not in favour of the first one visited.
    std::vector<int>& bouncing = memory.bouncing;
    bouncing.clear();
    for (int k = 0; k < m; ++k)
    {
        const SoftContact& c = contacts[static_cast<size_t>(k)];
        if (!c.bounces)
        {
            continue;
        }
        // How fast gravity closes the pair along the normal: it pulls only the awake dynamic bodies.
        const Vec2 gravityA = IsAwakeDynamic(bodies[c.a]) ? settings.gravity : Vec2{};
        const Vec2 gravityB = IsAwakeDynamic(bodies[c.b]) ? settings.gravity : Vec2{};
        const double pull = std::max(0.0, -Dot(gravityB - gravityA, c.normal));
        if (SoftBounceTargets(solvedAt(k), c, states[static_cast<size_t>(c.a)], states[static_cast<size_t>(c.b)], pull,
                              h, dt))
        {
            bouncing.push_back(k);
        }
    }
    for (int pass = 0; pass < kRestitutionPasses && !bouncing.empty(); ++pass)
    {
        for (const int k : bouncing)
        {
            SoftContact& c = contacts[static_cast<size_t>(k)];
            ApplySoftRestitution(solvedAt(k), c, states[static_cast<size_t>(c.a)], states[static_cast<size_t>(c.b)]);
        }
    }
    // The impulses go back to the solver contacts (StoreImpulses keeps them for the next step's warm start).
    for (int k = 0; k < m; ++k)
    {
        const SoftContact& c = contacts[static_cast<size_t>(k)];
        SolverContact& solved = solvedAt(k);
        for (int i = 0; i < c.count; ++i)
        {
            solved.points[i].normalImpulse = c.points[i].normalImpulse;
            solved.points[i].tangentImpulse = c.points[i].tangentImpulse;
            solved.points[i].maxNormalImpulse = c.points[i].maxNormalImpulse;
            solved.points[i].stuck = c.stuck[i];
        }
        if (c.traced)
        {
            world.trace->blockSolved = false;
        }
    }
    for (int i = 0; i < n; ++i)
    {
        solverBodies[i].v = states[static_cast<size_t>(i)].v;
        solverBodies[i].w = states[static_cast<size_t>(i)].w;
    }
    RecordAfter();
    // Move takes each body along a straight path over dt: the velocity of its move within the sub-steps. The
    // velocity the sub-steps end with is the body's for the next step (Move gives it back).
    memory.softVelocities = solverBodies;
    for (const int code : awake)
    {
        const int i = code >= 0 ? code : -1 - code;
        const SoftBody& s = states[static_cast<size_t>(i)];
        solverBodies[i].v = (1.0 / dt) * s.position;
        solverBodies[i].w = s.angle / dt;
    }
}

} // namespace satviz::detail
