// SPDX-License-Identifier: MIT
// satviz: the soft step (WorldSettings::softStep): sub-steps of soft contacts in place of the velocity passes, the
// restitution's push-only passes and the position passes.

#include "sat/cpu_dispatch.h"
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

// The groups of contacts within a colour: SoftKind's, then the traced contacts.
constexpr int kKinds = 4;

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
        q.normalTotal = 0.0;
        q.tangentTotal = 0.0;
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
    // Two records past the bodies': a sink the lanes write the velocities of the bodies the passes do not move to
    // (never read), and a body at rest with no mass that the batches' padding lanes read.
    const int sink = n;
    const int rest = n + 1;
    std::vector<SoftBody>& states = memory.softBodies;
    states.assign(static_cast<size_t>(n) + 2, SoftBody{});
    std::vector<int>& awake = memory.softAwake;
    awake.clear();
    // Whether the passes move each body: awake and dynamic, as PrepareContacts read it from the bodies just before.
    const std::vector<uint8_t>& moves = memory.moving;
    for (int i = 0; i < n; ++i)
    {
        states[static_cast<size_t>(i)].v = solverBodies[i].v;
        states[static_cast<size_t>(i)].w = solverBodies[i].w;
        if (moves[static_cast<size_t>(i)] != 0)
        {
            // A body whose turn moves no point of its outline (a circle about its centre) keeps its anchors
            // unturned (the normal between two circles joins their centres, whatever they turn): stored as -1 - i.
            awake.push_back(bodies[i].turnRadius > 0.0 ? i : -1 - i);
        }
    }
    // Each contact is copied once into the small record the passes read, in the top-down order; the solver contacts
    // stay in the order found.
    foundOrder.resize(static_cast<size_t>(m));
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
    // The colours (after Box2D v3's graph colouring, here by levels): each contact, taken top down, gets the first
    // colour after those of the contacts before it that share a body the passes move, the largest of its moving
    // bodies' next free colours. Two contacts that share such a body are then visited in the top-down order (the
    // higher has the lower colour), and two that do not commute: visiting the colours in turn gives the same bits
    // as visiting the contacts top down one at a time. Static and sleeping bodies do not count: the lanes read them
    // and never write them, and a visit of one contact leaves their velocities as they are (they have no inverse
    // mass). Without wide vectors (AVX2) there is one colour, whose contacts are visited one at a time, top down:
    // lanes in the baseline's instructions (SSE2, two doubles a register) take more instructions than that.
    const bool wide = HasWideVectors();
    std::vector<int>& level = memory.softLevels;
    level.assign(static_cast<size_t>(n), 0);
    std::vector<int>& keys = memory.softKeys;
    keys.resize(static_cast<size_t>(m));
    int colours = 0;
    for (int k = 0; k < m; ++k)
    {
        const SoftContact& c = contacts[static_cast<size_t>(k)];
        const bool movesA = wide && moves[static_cast<size_t>(c.a)] != 0;
        const bool movesB = wide && moves[static_cast<size_t>(c.b)] != 0;
        const int colour =
            std::max(movesA ? level[static_cast<size_t>(c.a)] : 0, movesB ? level[static_cast<size_t>(c.b)] : 0);
        if (movesA)
        {
            level[static_cast<size_t>(c.a)] = colour + 1;
        }
        if (movesB)
        {
            level[static_cast<size_t>(c.b)] = colour + 1;
        }
        // Within a colour the contacts go by kind: the batches' lanes all do the same, and the traced ones are
        // visited one at a time (their record is the step trace's).
        const SoftKind kind = c.count == 1 ? SoftKind::OnePoint : c.block ? SoftKind::Block : SoftKind::TwoPoints;
        keys[static_cast<size_t>(k)] = kKinds * colour + (c.traced || !wide ? kKinds - 1 : static_cast<int>(kind));
        colours = std::max(colours, colour + 1);
    }
    // The contacts by colour and kind (a counting sort; within a group, top down).
    std::vector<int>& starts = level;
    starts.assign(static_cast<size_t>(kKinds * colours + 1), 0);
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
    for (int k = 0; k < m; ++k)
    {
        order[static_cast<size_t>(starts[static_cast<size_t>(keys[static_cast<size_t>(k)])]++)] = k;
    }
    // Each start moved to the next key's: moved back.
    for (size_t key = starts.size() - 1; key > 0; --key)
    {
        starts[key] = starts[key - 1];
    }
    starts[0] = 0;
    // Each colour's untraced contacts, kSoftLanes to a batch, and its traced ones, visited one at a time.
    // The list only grows: a batch is filled whole before it is read, so the ones kept from earlier steps need not
    // be cleared (a new one is, by the list).
    std::vector<SoftBatch>& batches = memory.softBatches;
    int batchCount = 0;
    std::vector<SoftColour>& colourList = memory.softColours;
    colourList.assign(static_cast<size_t>(colours), SoftColour{});
    std::vector<int>& single = memory.softSingle;
    single.clear();
    SoftContact padding{};
    padding.count = 2;
    padding.points[0].separation = 1.0; // an open gap: the padding lanes are skipped like idle contacts
    padding.points[1].separation = 1.0;
    for (int colour = 0; colour < colours; ++colour)
    {
        SoftColour& list = colourList[static_cast<size_t>(colour)];
        list.batchBegin = batchCount;
        list.singleBegin = static_cast<int>(single.size());
        for (int kind = 0; kind < kKinds; ++kind)
        {
            const int begin = starts[static_cast<size_t>(kKinds * colour + kind)];
            const int end = starts[static_cast<size_t>(kKinds * colour + kind) + 1];
            const bool lanes = kind < kKinds - 1;
            for (int j = begin; j < end && !lanes; ++j)
            {
                single.push_back(order[static_cast<size_t>(j)]);
            }
            for (int j = begin; j < end && lanes; j += kSoftLanes)
            {
                if (batchCount == static_cast<int>(batches.size()))
                {
                    batches.emplace_back();
                }
                SoftBatch& batch = batches[static_cast<size_t>(batchCount++)];
                batch.lanes = std::min(kSoftLanes, end - j);
                batch.kind = static_cast<SoftKind>(kind);
                for (int lane = 0; lane < kSoftLanes; ++lane)
                {
                    if (lane >= batch.lanes)
                    {
                        PackSoftLane(batch, lane, padding, rest, rest, sink, sink);
                        batch.contact[lane] = -1;
                        continue;
                    }
                    const int k = order[static_cast<size_t>(j + lane)];
                    const SoftContact& c = contacts[static_cast<size_t>(k)];
                    PackSoftLane(batch, lane, c, c.a, c.b, moves[static_cast<size_t>(c.a)] != 0 ? c.a : sink,
                                 moves[static_cast<size_t>(c.b)] != 0 ? c.b : sink);
                    batch.contact[lane] = k;
                }
            }
        }
        list.batchEnd = batchCount;
        list.singleEnd = static_cast<int>(single.size());
    }
    // A spring faster than a quarter of the sub-step rate is not resolved by the sub-step: it would only add
    // stiffness that the implicit step turns into damping. Against a body that cannot give way (static, asleep) the
    // spring is twice as stiff: a body in a pile pressed into the ground by the weight above must not sink.
    const double hertz = std::min(settings.contactHertz, 0.25 * invH);
    const Softness soft = hertz > 0.0 ? MakeSoftness(hertz, settings.contactDampingRatio, h) : Softness{};
    const Softness stiff = hertz > 0.0 ? MakeSoftness(2.0 * hertz, settings.contactDampingRatio, h) : Softness{};
    const SoftPassConstants constants{soft, stiff, invH, settings.maxPushSpeed};
    NullSolveRecorder quiet;
    TraceSolveRecorder loud{world.trace};
    // One contact's visit (SolveSoftContact and WarmStart, whose operations the lanes repeat); `which` is a
    // std::integral_constant of SoftPass, so that each pass's loop is compiled for its visit alone.
    const auto visit = [&](auto which, int number, SoftContact& c, auto& recorder) {
        SoftBody& a = states[static_cast<size_t>(c.a)];
        SoftBody& b = states[static_cast<size_t>(c.b)];
        const Softness& softness = c.stiff ? stiff : soft;
        if constexpr (decltype(which)::value == SoftPass::WarmStart)
        {
            WarmStart(c, a, b);
        }
        else
        {
            constexpr bool kUseBias = decltype(which)::value == SoftPass::Solve;
            SolveSoftContact<kUseBias>(c, a, b, softness, invH, settings.maxPushSpeed, number, recorder);
        }
    };
    // A pass: the colours in turn, each colour's batches side by side in lanes, then its contacts visited one at a
    // time.
    const auto pass = [&](auto which, int number) {
        for (const SoftColour& list : colourList)
        {
            if (list.batchBegin < list.batchEnd)
            {
                SoftPassOverBatches(decltype(which)::value, batches.data() + list.batchBegin,
                                    batches.data() + list.batchEnd, states.data(), constants);
            }
            for (int t = list.singleBegin; t < list.singleEnd; ++t)
            {
                SoftContact& c = contacts[static_cast<size_t>(single[static_cast<size_t>(t)])];
                if (c.traced)
                {
                    visit(which, number, c, loud);
                }
                else
                {
                    visit(which, number, c, quiet);
                }
            }
        }
    };
    using WarmStartPass = std::integral_constant<SoftPass, SoftPass::WarmStart>;
    using SolvePass = std::integral_constant<SoftPass, SoftPass::Solve>;
    using RelaxPass = std::integral_constant<SoftPass, SoftPass::Relax>;
    for (int sub = 0; sub < subSteps; ++sub)
    {
        for (const int code : awake)
        {
            SoftBody& s = states[static_cast<size_t>(code >= 0 ? code : -1 - code)];
            s.v = s.v + h * settings.gravity;
        }
        pass(WarmStartPass{}, 2 * sub);
        pass(SolvePass{}, 2 * sub);
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
        // The relax adds each contact's impulses of the sub-step to the step's (SoftPoint::normalTotal).
        pass(RelaxPass{}, 2 * sub + 1);
    }
    // The traced contact's record gives each pass's impulses, and friction's limits, over the step so far (the
    // sub-steps before its own added), as the velocity passes record theirs: the last pass's are the step's.
    if (world.trace != nullptr)
    {
        ContactPointSolve before[2]{};
        for (ContactPointSolve& record : world.trace->passes)
        {
            const ContactPointSolve& done = before[record.point];
            record.normalImpulseWanted += done.normalImpulse;
            record.normalImpulse += done.normalImpulse;
            record.tangentImpulseWanted += done.tangentImpulse;
            record.tangentImpulse += done.tangentImpulse;
            record.staticLimit += done.staticLimit;
            record.dynamicLimit += done.dynamicLimit;
            if (record.pass % 2 == 1)
            {
                // The relax ends its sub-step.
                before[record.point] = record;
            }
        }
    }
    for (int i = 0; i < batchCount; ++i)
    {
        const SoftBatch& batch = batches[static_cast<size_t>(i)];
        for (int lane = 0; lane < batch.lanes; ++lane)
        {
            UnpackSoftLane(batch, lane, contacts[static_cast<size_t>(batch.contact[lane])]);
        }
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
        const Vec2 gravityA = moves[static_cast<size_t>(c.a)] != 0 ? settings.gravity : Vec2{};
        const Vec2 gravityB = moves[static_cast<size_t>(c.b)] != 0 ? settings.gravity : Vec2{};
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
            solved.points[i].normalTotal = c.points[i].normalTotal;
            solved.points[i].tangentTotal = c.points[i].tangentTotal;
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
