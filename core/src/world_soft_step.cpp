// SPDX-License-Identifier: MIT
// satviz: the soft step (WorldSettings::softStep): sub-steps of soft contacts in place of the velocity passes, the
// restitution's push-only passes and the position passes.

#include "stepper.h"
#include "world_lookup.h"

#include <algorithm>
#include <cmath>

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

} // namespace

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
    // As in the velocity passes: top down, so that a pile's weight reaches its lower rows within one pass, and
    // stored in that order so that each pass reads the contacts in sequence.
    OrderTopDown();
    SortContacts();
    // A spring faster than a quarter of the sub-step rate is not resolved by the sub-step: it would only add
    // stiffness that the implicit step turns into damping. Against a body that cannot give way (static, asleep) the
    // spring is twice as stiff: a body in a pile pressed into the ground by the weight above must not sink.
    const double hertz = std::min(settings.contactHertz, 0.25 * invH);
    const Softness soft = hertz > 0.0 ? MakeSoftness(hertz, settings.contactDampingRatio, h) : Softness{};
    const Softness stiff = hertz > 0.0 ? MakeSoftness(2.0 * hertz, settings.contactDampingRatio, h) : Softness{};
    std::vector<SoftMove>& moves = memory.softMoves;
    moves.assign(static_cast<size_t>(n), SoftMove{});
    const auto fixed = [](const SolverBody& s) { return s.invMass == 0.0 && s.invInertia == 0.0; };
    NullSolveRecorder quiet;
    TraceSolveRecorder loud{world.trace};
    const auto pass = [&](bool useBias, int number) {
        for (SolverContact& c : solverContacts)
        {
            SolverBody& a = solverBodies[c.a];
            SolverBody& b = solverBodies[c.b];
            const Softness& softness = fixed(a) || fixed(b) ? stiff : soft;
            const SoftMove& moveA = moves[static_cast<size_t>(c.a)];
            const SoftMove& moveB = moves[static_cast<size_t>(c.b)];
            if (c.traced)
            {
                SolveSoftContact(c, a, b, moveA, moveB, softness, invH, settings.maxPushSpeed, useBias, number, loud);
            }
            else
            {
                SolveSoftContact(c, a, b, moveA, moveB, softness, invH, settings.maxPushSpeed, useBias, number, quiet);
            }
        }
    };
    for (int sub = 0; sub < subSteps; ++sub)
    {
        for (int i = 0; i < n; ++i)
        {
            if (IsAwakeDynamic(bodies[i]))
            {
                solverBodies[i].v = solverBodies[i].v + h * settings.gravity;
            }
        }
        for (SolverContact& c : solverContacts)
        {
            WarmStart(c, solverBodies[c.a], solverBodies[c.b]);
        }
        pass(true, 2 * sub);
        for (int i = 0; i < n; ++i)
        {
            if (IsAwakeDynamic(bodies[i]))
            {
                SoftMove& m = moves[static_cast<size_t>(i)];
                const SolverBody& s = solverBodies[i];
                m.position = m.position + h * s.v;
                m.angle += h * s.w;
                // A circle turning about its centre moves no point of its outline: its anchors stay (the normal
                // between two circles joins their centres, whatever they turn).
                if (bodies[i].turnRadius > 0.0)
                {
                    m.rotation = TurnBy(m.rotation, h * s.w);
                }
            }
        }
        pass(false, 2 * sub + 1);
    }
    // Restitution after the sub-steps: the bounce speed is the target of the velocity the step ends with. A few
    // passes over the bouncing contacts alone, so that contacts that land together (a plank on two supports) share
    // the bounce as they would solved together, not in favour of the first one visited.
    std::vector<int>& bouncing = memory.bouncing;
    bouncing.clear();
    for (int k = 0; k < static_cast<int>(solverContacts.size()); ++k)
    {
        SolverContact& c = solverContacts[static_cast<size_t>(k)];
        // How fast gravity closes the pair along the normal: it pulls only the awake dynamic bodies.
        const Vec2 gravityA = IsAwakeDynamic(bodies[c.a]) ? settings.gravity : Vec2{};
        const Vec2 gravityB = IsAwakeDynamic(bodies[c.b]) ? settings.gravity : Vec2{};
        const double pull = std::max(0.0, -Dot(gravityB - gravityA, c.normal));
        if (SoftBounceTargets(c, moves[static_cast<size_t>(c.a)], moves[static_cast<size_t>(c.b)], pull, h, dt))
        {
            bouncing.push_back(k);
        }
    }
    for (int pass = 0; pass < kRestitutionPasses && !bouncing.empty(); ++pass)
    {
        for (const int k : bouncing)
        {
            SolverContact& c = solverContacts[static_cast<size_t>(k)];
            ApplySoftRestitution(c, solverBodies[c.a], solverBodies[c.b]);
        }
    }
    if (world.trace != nullptr)
    {
        for (const SolverContact& c : solverContacts)
        {
            if (c.traced)
            {
                world.trace->blockSolved = false;
            }
        }
    }
    RecordAfter();
    // Move takes each body along a straight path over dt: the velocity of its move within the sub-steps. The
    // velocity the sub-steps end with is the body's for the next step (Move gives it back).
    memory.softVelocities = solverBodies;
    for (int i = 0; i < n; ++i)
    {
        if (IsAwakeDynamic(bodies[i]))
        {
            const SoftMove& m = moves[static_cast<size_t>(i)];
            solverBodies[i].v = (1.0 / dt) * m.position;
            solverBodies[i].w = m.angle / dt;
        }
    }
}

} // namespace satviz::detail
