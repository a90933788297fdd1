// SPDX-License-Identifier: MIT
// satviz: the soft step's records of bodies and contacts and its pass over one contact (internal).
#pragma once

#include "contact_solver.h"

#include <cstdint>

namespace satviz::detail
{

/// What the soft step's sub-steps change of one body, in one record of one cache line: a contact's visit reads its
/// two bodies' records and nothing else of them.
struct alignas(64) SoftBody
{
    Vec2 v{};           ///< linear velocity of the centre of mass
    double w = 0.0;     ///< angular velocity
    double angle = 0.0; ///< turn since the start of the step, in radians (for the body's angle)
    Vec2 position{};    ///< displacement of the centre of mass since the start of the step
    Rot rotation{};     ///< turn since the start of the step, as a rotation (for the anchors)
};

/// One point of a SoftContact. The normal and the tangent are fixed over the step, and so are the lever arms (from
/// the centres of mass to the point, at the start of the step): the passes need only the lever arms' cross
/// products with them, which give a spin's share of a point's speed along the normal and the tangent, an impulse's
/// share of the spin, and, with a body's turn, the anchor's move along the normal.
struct SoftPoint
{
    double rnA = 0.0;              ///< Cross(rA, normal), rA from A's centre of mass to the point
    double rnB = 0.0;              ///< Cross(rB, normal)
    double rtA = 0.0;              ///< Cross(rA, tangent) = -Dot(rA, normal), tangent = RightPerp(normal)
    double rtB = 0.0;              ///< Cross(rB, tangent)
    double separation = 0.0;       ///< overlap (< 0) or gap (> 0) found at the start of the step
    double normalMass = 0.0;       ///< effective mass along the normal
    double tangentMass = 0.0;      ///< effective mass along the tangent
    double normalImpulse = 0.0;    ///< accumulated normal impulse
    double tangentImpulse = 0.0;   ///< accumulated friction impulse
    double maxNormalImpulse = 0.0; ///< the largest accumulated normal impulse over the sub-steps
    double normalTotal = 0.0;      ///< the accumulated normal impulses of the sub-steps done, summed
    double tangentTotal = 0.0;     ///< the accumulated friction impulses of the sub-steps done, summed
};

/// A contact as the soft step's passes read it: what they need of a SolverContact and of its bodies' masses, made
/// once a step (MakeSoftContact) and stored top down (the solver contact it came from, which gets its impulses back
/// after the step, is the Stepper's solveOrder at the same place). The passes read it packed in a SoftBatch with
/// others of its colour (soft_lanes.h), or as it is when the step trace records it.
struct SoftContact
{
    int a = -1;                     ///< first body
    int b = -1;                     ///< second body
    uint8_t count = 0;              ///< points, 1 or 2
    bool block = false;             ///< the two normal impulses are solved together (in the relax)
    bool stiff = false;             ///< one of the bodies cannot give way (static or asleep): the stiffer spring
    bool traced = false;            ///< the world records this contact's passes
    bool bounces = false;           ///< a point has a bounce target (PrepareContact)
    bool stuck[2] = {false, false}; ///< static friction held in the last pass, per point
    Vec2 normal{};                  ///< unit normal from a to b
    double friction = 0.0;          ///< sliding friction
    double staticFriction = 0.0;    ///< static friction
    double invMassA = 0.0, invInertiaA = 0.0; ///< A's inverse mass and inertia (0 for static and sleeping bodies)
    double invMassB = 0.0, invInertiaB = 0.0; ///< B's
    double k11 = 0.0, k12 = 0.0, k22 = 0.0;   ///< the 2x2 normal mass matrix K (symmetric)
    SoftPoint points[2]{};                    ///< the points
};

/// Fills `s` with the soft record of solver contact `c`, whose bodies have the solver states sa and sb (the points
/// beyond c.count are left as they were: nothing reads them).
void MakeSoftContact(SoftContact& s, const SolverContact& c, const SolverBody& sa, const SolverBody& sb);

/// The velocities of a contact's two bodies while a visit works on them: read from their SoftBody records once and
/// written back once, so that the visit's chain of impulses runs in registers.
struct SoftPair
{
    Vec2 vA{};       ///< A's linear velocity
    double wA = 0.0; ///< A's angular velocity
    Vec2 vB{};       ///< B's linear velocity
    double wB = 0.0; ///< B's angular velocity
};

/// The velocities of bodies a and b.
inline SoftPair LoadPair(const SoftBody& a, const SoftBody& b)
{
    return {a.v, a.w, b.v, b.w};
}

/// Writes the velocities of `v` back to bodies a and b.
inline void StorePair(const SoftPair& v, SoftBody& a, SoftBody& b)
{
    a.v = v.vA;
    a.w = v.wA;
    b.v = v.vB;
    b.w = v.wB;
}

/// The speed of B's point against A's point along `direction` (the normal or the tangent), with rA and rB the lever
/// arms' cross products with it.
inline double SpeedAlong(const SoftPair& v, Vec2 direction, double rA, double rB)
{
    return Dot(v.vB - v.vA, direction) + v.wB * rB - v.wA * rA;
}

/// Adds impulse `impulse` along `direction` (lever arms' cross products rA, rB with it): -impulse on A, +impulse on
/// B.
inline void ApplyImpulse(const SoftContact& c, SoftPair& v, Vec2 direction, double rA, double rB, double impulse)
{
    v.vA = v.vA - (c.invMassA * impulse) * direction;
    v.wA -= c.invInertiaA * impulse * rA;
    v.vB = v.vB + (c.invMassB * impulse) * direction;
    v.wB += c.invInertiaB * impulse * rB;
}

/// Applies the accumulated impulses (warm starting, once per sub-step).
inline void WarmStart(const SoftContact& c, SoftBody& a, SoftBody& b)
{
    const Vec2 n = c.normal;
    const Vec2 t = RightPerp(n);
    SoftPair v = LoadPair(a, b);
    for (int i = 0; i < c.count; ++i)
    {
        const SoftPoint& p = c.points[i];
        const Vec2 impulse = p.normalImpulse * n + p.tangentImpulse * t;
        v.vA = v.vA - c.invMassA * impulse;
        v.wA -= c.invInertiaA * (p.normalImpulse * p.rnA + p.tangentImpulse * p.rtA);
        v.vB = v.vB + c.invMassB * impulse;
        v.wB += c.invInertiaB * (p.normalImpulse * p.rnB + p.tangentImpulse * p.rtB);
    }
    StorePair(v, a, b);
}

/// How far a body's turn q moves an anchor along the normal, from its lever arm's cross products rn, rt with the
/// normal and the tangent: Dot(Rotate(q, r) - r, n) = q.s Cross(r, n) + (q.c - 1) Dot(r, n).
inline double TurnAlongNormal(Rot q, double rn, double rt)
{
    return q.s * rn - (q.c - 1.0) * rt;
}

/// Separation of point p now: the one found at the start of the step plus its anchors' moves along the normal,
/// each anchor moved with its body's centre and turned with its body.
/// `moved`: how far B's centre moved from A's along the normal, Dot(b.position - a.position, c.normal).
inline double SeparationNow(const SoftPoint& p, double moved, Rot turnA, Rot turnB)
{
    return p.separation + moved + TurnAlongNormal(turnB, p.rnB, p.rtB) - TurnAlongNormal(turnA, p.rnA, p.rtA);
}

/// What BlockImpulses reads of a two-point contact: K's inverse, K's off-diagonal and the points' effective masses.
struct BlockMasses
{
    double m11, m12, m22; ///< K's inverse
    double k12;           ///< K's off-diagonal
    struct
    {
        double normalMass; ///< 1 / K's diagonal
    } points[2];           ///< per point
};

/// The two normal impulses of a two-point contact (c.block) solved together, as in the velocity passes: the
/// accumulated impulses x >= 0 that bring the points' normal speeds to `target` (or beyond it with x = 0), a 2x2
/// linear complementarity problem solved by trying its four cases in turn. Returns the applied increments.
inline void SolveNormalBlock(SoftContact& c, SoftPair& v, const double target[2], double applied[2])
{
    const Vec2 n = c.normal;
    SoftPoint& p1 = c.points[0];
    SoftPoint& p2 = c.points[1];
    const double vn1 = SpeedAlong(v, n, p1.rnA, p1.rnB);
    const double vn2 = SpeedAlong(v, n, p2.rnA, p2.rnB);
    const double a1 = p1.normalImpulse;
    const double a2 = p2.normalImpulse;
    // The speeds after impulses x are K x + b; each case sets some of them to zero.
    const double b1 = (vn1 - target[0]) - (c.k11 * a1 + c.k12 * a2);
    const double b2 = (vn2 - target[1]) - (c.k12 * a1 + c.k22 * a2);
    // K's inverse is taken here, as PrepareContact takes it, rather than kept in the record: the passes read every
    // record some twelve times a step, this only the relax's two-point contacts.
    const double inv = 1.0 / (c.k11 * c.k22 - c.k12 * c.k12);
    const BlockMasses masses{inv * c.k22, -inv * c.k12, inv * c.k11, c.k12, {{p1.normalMass}, {p2.normalMass}}};
    double x1 = 0.0;
    double x2 = 0.0;
    BlockImpulses(masses, b1, b2, a1, a2, x1, x2);
    applied[0] = x1 - a1;
    applied[1] = x2 - a2;
    ApplyImpulse(c, v, n, p1.rnA, p1.rnB, applied[0]);
    ApplyImpulse(c, v, n, p2.rnA, p2.rnB, applied[1]);
    p1.normalImpulse = x1;
    p2.normalImpulse = x2;
}

/// Whether no point of contact c has a normal or a friction impulse.
inline bool Idle(const SoftContact& c)
{
    bool idle = true;
    for (int i = 0; i < c.count; ++i)
    {
        idle = idle && c.points[i].normalImpulse == 0.0 && c.points[i].tangentImpulse == 0.0;
    }
    return idle;
}

/// Outline of one soft-step pass over a contact (Catto, "Solver2D", 2024, the soft step; Box2D v3's contact
/// solver), with `UseBias` the solve of a sub-step and without it the relax that follows its move:
///  1. Normal, per point: the separation now (SeparationNow) follows the bodies through the sub-steps without the
///     narrowphase. A gap may close within the sub-step (the approach speed it allows is the gap over h); an
///     overlap is pushed out by the soft constraint (solve only: the relax has no push, so that the push's velocity
///     does not stay in the bodies); the accumulated impulse is clamped to be a push.
///  2. Friction, per point, as in the velocity passes: within staticFriction times the normal impulse it is taken
///     whole (the point sticks), beyond it is clamped to friction times the normal impulse.
/// The normal is fixed over the step and the lever arms are those of the start of the step: a sub-step turns a
/// body by little. In the solve the two normal impulses of a two-point contact are solved one after the other (the
/// soft constraint's leak is per point); in the relax, which is rigid, together (SolveNormalBlock), so that a
/// symmetric landing stays symmetric. `pass` numbers the record.
template <bool UseBias, typename Recorder>
void SolveSoftContact(SoftContact& c, SoftBody& a, SoftBody& b, const Softness& softness, double invH,
                      double maxPushSpeed, int pass, Recorder& recorder)
{
    const Vec2 n = c.normal;
    const Vec2 t = RightPerp(n);
    SoftPair v = LoadPair(a, b);
    const double moved = Dot(b.position - a.position, n);
    const Rot turnA = a.rotation;
    const Rot turnB = b.rotation;
    // A contact that pushes nothing and holds nothing yet, whose gaps stay open at its points' speeds over the
    // sub-step, gets no impulse from the visit (a normal impulse below zero is clamped to zero, and friction is
    // bounded by it): its rows are skipped. Speculative contacts of bodies that do not meet are many.
    if (!Recorder::kRecords && Idle(c))
    {
        bool open = true;
        for (int i = 0; i < c.count && open; ++i)
        {
            const SoftPoint& p = c.points[i];
            const double s = SeparationNow(p, moved, turnA, turnB);
            open = s > 0.0 && SpeedAlong(v, n, p.rnA, p.rnB) + s * invH > 0.0;
        }
        if (open)
        {
            for (int i = 0; i < c.count; ++i)
            {
                const SoftPoint& p = c.points[i];
                c.stuck[i] = p.tangentMass * SpeedAlong(v, t, p.rtA, p.rtB) == 0.0;
            }
            return;
        }
    }
    ContactPointSolve record[2]{};
    const bool together = !UseBias && c.block;
    if (together)
    {
        double target[2] = {0.0, 0.0};
        for (int i = 0; i < 2; ++i)
        {
            const SoftPoint& p = c.points[i];
            const double s = SeparationNow(p, moved, turnA, turnB);
            target[i] = s > 0.0 ? -s * invH : 0.0;
            record[i].pass = pass;
            record[i].point = i;
            record[i].normalSpeed = SpeedAlong(v, n, p.rnA, p.rnB);
        }
        double applied[2] = {0.0, 0.0};
        SolveNormalBlock(c, v, target, applied);
        for (int i = 0; i < 2; ++i)
        {
            SoftPoint& p = c.points[i];
            p.maxNormalImpulse = std::max(p.maxNormalImpulse, p.normalImpulse);
            record[i].normalImpulseWanted = p.normalImpulse;
            record[i].normalImpulse = p.normalImpulse;
        }
    }
    for (int i = 0; i < c.count && !together; ++i)
    {
        SoftPoint& p = c.points[i];
        const double s = SeparationNow(p, moved, turnA, turnB);
        double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
        if (s > 0.0)
        {
            bias = s * invH;
        }
        else if (UseBias)
        {
            bias = std::max(softness.biasRate * s, -maxPushSpeed);
            massScale = softness.massScale;
            impulseScale = softness.impulseScale;
        }
        const double vn = SpeedAlong(v, n, p.rnA, p.rnB);
        const double wanted = p.normalImpulse - p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
        const double next = std::max(wanted, 0.0);
        const double applied = next - p.normalImpulse;
        p.normalImpulse = next;
        p.maxNormalImpulse = std::max(p.maxNormalImpulse, next);
        ApplyImpulse(c, v, n, p.rnA, p.rnB, applied);
        record[i].pass = pass;
        record[i].point = i;
        record[i].normalSpeed = vn;
        record[i].normalImpulseWanted = wanted;
        record[i].normalImpulse = next;
    }
    for (int i = 0; i < c.count; ++i)
    {
        SoftPoint& p = c.points[i];
        const double vt = SpeedAlong(v, t, p.rtA, p.rtB);
        const double wanted = p.tangentImpulse - p.tangentMass * vt;
        const double staticLimit = c.staticFriction * p.normalImpulse;
        const double slidingLimit = c.friction * p.normalImpulse;
        double next = wanted;
        c.stuck[i] = std::fabs(wanted) <= staticLimit;
        if (!c.stuck[i])
        {
            next = std::max(-slidingLimit, std::min(slidingLimit, wanted));
        }
        const double applied = next - p.tangentImpulse;
        p.tangentImpulse = next;
        ApplyImpulse(c, v, t, p.rtA, p.rtB, applied);
        record[i].tangentSpeed = vt;
        record[i].tangentImpulseWanted = wanted;
        record[i].staticLimit = staticLimit;
        record[i].dynamicLimit = slidingLimit;
        record[i].tangentImpulse = next;
        record[i].stuck = c.stuck[i];
    }
    StorePair(v, a, b);
    if constexpr (!UseBias)
    {
        // The relax ends a sub-step, which applies the accumulated impulses whole: the step's are their sum.
        for (int i = 0; i < c.count; ++i)
        {
            c.points[i].normalTotal += c.points[i].normalImpulse;
            c.points[i].tangentTotal += c.points[i].tangentImpulse;
        }
    }
    for (int i = 0; i < c.count; ++i)
    {
        recorder.Pass(record[i]);
    }
}

/// The soft step's bounce targets, after its sub-steps: a point bounces when it approached faster than the
/// threshold at the start of the step (PrepareContact gave `solved` a bounce) and pushed within the sub-steps (in
/// the soft record c). Its bounce speed is set anew from the energy, so that it does not depend on where in the
/// step the impact fell: sub-steps of h under a pull g (gravity along the normal) keep v^2 / 2 + g y - g h v / 2
/// in free flight, so the speed at the surface of the fall that began the step at separation s0 with normal speed
/// v is u, u^2 = (v - g h / 2)^2 - 2 g d (d the overlap this step's approach can have made, -s0 for a gap); the
/// point, now at separation s (moved with its bodies through the sub-steps), must leave at the speed w that brings
/// it back to the surface at restitution times u: (w - g h / 2)^2 = e^2 u^2 - 2 g s. Without gravity, w = e |v|.
/// Points that do not bounce get 0 in `solved`, and every point's restitutionImpulse is cleared. Returns whether any
/// point bounces.
bool SoftBounceTargets(SolverContact& solved, const SoftContact& c, const SoftBody& a, const SoftBody& b, double pull,
                       double h, double dt);

/// One pass of restitution after the soft step's sub-steps (after Box2D v3's): each point with a bounce target (in
/// `solved`) gets the impulse that brings its normal speed to it, added to its accumulated impulse, which stays a
/// push (both points of a two-point block together). Added to `solved`'s restitutionImpulse, so that only the rest
/// is warm started.
void ApplySoftRestitution(SolverContact& solved, SoftContact& c, SoftBody& a, SoftBody& b);

} // namespace satviz::detail
