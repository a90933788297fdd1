// SPDX-License-Identifier: MIT
// satviz: the contact solver of the world: sequential impulses on one contact at a time (internal).
#pragma once

#include <satviz/material.h>
#include <satviz/solver_trace.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace satviz::detail
{

/// The velocities the solver changes, and the inverse masses it reads, of one body.
struct SolverBody
{
    Vec2 v{};                ///< linear velocity of the centre of mass
    double w = 0.0;          ///< angular velocity
    double invMass = 0.0;    ///< 0 for static and sleeping bodies
    double invInertia = 0.0; ///< 0 for static and sleeping bodies
};

/// One point of a contact as the solver sees it.
struct SolverPoint
{
    Vec2 rA{};                       ///< from A's centre of mass to the point
    Vec2 rB{};                       ///< from B's centre of mass to the point
    double separation = 0.0;         ///< overlap (< 0) or gap (> 0, speculative) at the start of the step
    double gapSpeed = 0.0;           ///< the approach speed that closes the gap within the step (0: touching)
    double normalMass = 0.0;         ///< effective mass along the normal
    double tangentMass = 0.0;        ///< effective mass along the tangent
    double bounce = 0.0;             ///< separating normal speed the restitution asks for alone (0: none)
    double restitutionFactor = 0.0;  ///< the restitution impulse as a multiple of the compression impulse
    double restitutionImpulse = 0.0; ///< the impulse the restitution added after the passes
    double pushImpulse = 0.0;        ///< accumulated impulse of the push-only passes after the restitution
    double normalImpulse = 0.0;      ///< accumulated normal impulse
    double tangentImpulse = 0.0;     ///< accumulated friction impulse
    double normalTotal = 0.0;        ///< soft step: the normal impulse summed over the sub-steps (no restitution)
    double tangentTotal = 0.0;       ///< soft step: the friction impulse summed over the sub-steps
    bool stuck = false;              ///< static friction held in the last pass
    /// Soft step: the largest accumulated normal impulse over the sub-steps; 0 for a point that never pushed (a gap
    /// that stayed open), which does not bounce.
    double maxNormalImpulse = 0.0;
    double approach = 0.0; ///< relative normal velocity before the step's gravity (< 0: approaching)
};

/// A contact between solver bodies a and b, normal from a to b.
struct SolverContact
{
    int a = -1;                             ///< first body
    int b = -1;                             ///< second body
    Vec2 normal{};                          ///< unit normal from a to b
    int normalBody = 0;                     ///< the body whose turning turns the normal: 0 = a, 1 = b
    int count = 0;                          ///< points, 1 or 2
    SolverPoint points[2]{};                ///< the points
    ContactMaterial material{};             ///< restitution and frictions
    bool block = false;                     ///< the two normal impulses are solved together
    double k11 = 0.0, k12 = 0.0, k22 = 0.0; ///< the 2x2 normal mass matrix K (symmetric)
    double m11 = 0.0, m12 = 0.0, m22 = 0.0; ///< its inverse
    bool traced = false;                    ///< the world records this contact's passes
};

/// Records nothing: the fast path.
struct NullSolveRecorder
{
    static constexpr bool kRecords = false; ///< records nothing
    /// Ignores a pass.
    void Pass(const ContactPointSolve&) {}
};

/// Appends every pass to a ContactSolveTrace.
struct TraceSolveRecorder
{
    static constexpr bool kRecords = true; ///< records every pass
    ContactSolveTrace* trace = nullptr;    ///< where to record
    /// Records a pass.
    void Pass(const ContactPointSolve& pass) { trace->passes.push_back(pass); }
};

/// Relative velocity of B's point against A's point at offsets rA, rB.
inline Vec2 RelativeVelocity(const SolverBody& a, const SolverBody& b, Vec2 rA, Vec2 rB)
{
    return (b.v + b.w * LeftPerp(rB)) - (a.v + a.w * LeftPerp(rA));
}

/// Adds impulse p at offsets rA, rB: -p on A, +p on B.
inline void ApplyImpulse(SolverBody& a, SolverBody& b, Vec2 rA, Vec2 rB, Vec2 p)
{
    a.v = a.v - a.invMass * p;
    a.w -= a.invInertia * Cross(rA, p);
    b.v = b.v + b.invMass * p;
    b.w += b.invInertia * Cross(rB, p);
}

/// Effective masses, restitution targets and the 2x2 block of a contact whose points have rA, rB, separation and
/// gapSpeed set. `approach[i]` is the relative normal velocity of point i before the step's gravity (< 0: approaching);
/// `pull` is how fast gravity closes the pair along the normal (units per time unit squared, >= 0 when it pulls the
/// bodies together) and `dt` the step. Above the threshold the target separating speed is the one that leaves the
/// pair, one step later, with restitution squared times the energy of the approach, counted at the surface: the
/// overlap the point reached and the step's gravity are taken into account, so the bounce does not depend on the
/// phase of the step at which the impact fell. Without gravity it is restitution times the approach speed.
/// The restitution factor is the speed the restitution must add (from the end of the compression, -gapSpeed, to
/// the bounce) over the speed the compression takes away (the approach and the step's gravity, less gapSpeed): the
/// multiple of the compression impulse that gives a lone contact exactly its target. A gap (a speculative contact)
/// counts as a negative overlap: the fall through it adds to the speed at the surface.
void PrepareContact(SolverContact& c, const SolverBody& a, const SolverBody& b, const double approach[2], double pull,
                    double dt, double restitutionThreshold);

/// Applies the accumulated impulses of the last step (warm starting).
void WarmStart(SolverContact& c, SolverBody& a, SolverBody& b);

/// The two normal impulses x of a two-point contact (c.block) that solve its 2x2 block LCP: with the speeds after
/// them K x + b (b: the points' speeds less their targets, less K times the impulses a they have now), x >= 0,
/// K x + b >= 0 and x (K x + b) = 0. The four cases are tried in turn, as Catto's block solver does: both points
/// pushing, only the first, only the second, neither. When no case holds (round-off on a degenerate pair) the
/// impulses stay a.
/// `Contact` is SolverContact or the soft step's SoftContact (the same fields).
template <typename Contact>
inline void BlockImpulses(const Contact& c, double b1, double b2, double a1, double a2, double& x1, double& x2)
{
    x1 = -(c.m11 * b1 + c.m12 * b2);
    x2 = -(c.m12 * b1 + c.m22 * b2);
    if (!(x1 >= 0.0 && x2 >= 0.0))
    {
        x1 = -c.points[0].normalMass * b1;
        x2 = 0.0;
        if (!(x1 >= 0.0 && c.k12 * x1 + b2 >= 0.0))
        {
            x1 = 0.0;
            x2 = -c.points[1].normalMass * b2;
            if (!(x2 >= 0.0 && c.k12 * x2 + b1 >= 0.0))
            {
                x1 = 0.0;
                x2 = 0.0;
                if (!(b1 >= 0.0 && b2 >= 0.0))
                {
                    x1 = a1;
                    x2 = a2;
                }
            }
        }
    }
}

/// Outline of one velocity pass over a contact (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005;
/// "Fast and Simple Physics using Sequential Impulses", GDC 2006; Box2D's contact solver):
///  1. Friction first, per point: the impulse that stops the slip, with the tangent's effective mass, added to the
///     accumulated one. Within staticFriction times the normal impulse it is taken whole (the point sticks);
///     beyond, the accumulated impulse is clamped to friction times the normal impulse (it slides).
///  2. Normal: the impulse that stops the approach (compression), accumulated and clamped to be a push; a
///     speculative point (a gap at the start of the step) may approach at the speed that closes its gap. Two points
///     are solved together as a 2x2 linear complementarity problem (each point's impulse positive with its speed
///     zero, or zero with its speed positive: four cases, the first that holds), so that a symmetric landing stays
///     symmetric whatever the order of the points.
/// The bounce is not a target of these passes: ApplyRestitution adds it once they are done.
template <typename Recorder>
void SolveContactVelocity(SolverContact& c, SolverBody& a, SolverBody& b, int pass, Recorder& recorder)
{
    const Vec2 n = c.normal;
    const Vec2 t = RightPerp(n);
    ContactPointSolve record[2]{};
    for (int i = 0; i < c.count; ++i)
    {
        SolverPoint& p = c.points[i];
        const double vt = Dot(RelativeVelocity(a, b, p.rA, p.rB), t);
        const double wanted = p.tangentImpulse - p.tangentMass * vt;
        const double staticLimit = c.material.staticFriction * p.normalImpulse;
        const double dynamicLimit = c.material.friction * p.normalImpulse;
        double next = wanted;
        p.stuck = std::fabs(wanted) <= staticLimit;
        if (!p.stuck)
        {
            next = wanted > dynamicLimit ? dynamicLimit : (wanted < -dynamicLimit ? -dynamicLimit : wanted);
        }
        const double applied = next - p.tangentImpulse;
        p.tangentImpulse = next;
        ApplyImpulse(a, b, p.rA, p.rB, applied * t);
        record[i].pass = pass;
        record[i].point = i;
        record[i].tangentSpeed = vt;
        record[i].tangentImpulseWanted = wanted;
        record[i].staticLimit = staticLimit;
        record[i].dynamicLimit = dynamicLimit;
        record[i].tangentImpulse = next;
        record[i].stuck = p.stuck;
    }

    if (!c.block)
    {
        for (int i = 0; i < c.count; ++i)
        {
            SolverPoint& p = c.points[i];
            const double vn = Dot(RelativeVelocity(a, b, p.rA, p.rB), n);
            const double wanted = p.normalImpulse - p.normalMass * (vn + p.gapSpeed);
            const double next = wanted > 0.0 ? wanted : 0.0;
            const double applied = next - p.normalImpulse;
            p.normalImpulse = next;
            ApplyImpulse(a, b, p.rA, p.rB, applied * n);
            record[i].normalSpeed = vn;
            record[i].normalImpulseWanted = wanted;
            record[i].normalImpulse = next;
        }
    }
    else
    {
        SolverPoint& p1 = c.points[0];
        SolverPoint& p2 = c.points[1];
        const double vn1 = Dot(RelativeVelocity(a, b, p1.rA, p1.rB), n);
        const double vn2 = Dot(RelativeVelocity(a, b, p2.rA, p2.rB), n);
        const double a1 = p1.normalImpulse;
        const double a2 = p2.normalImpulse;
        // b = vn - K a: the speeds the impulses x must bring to the targets, vn' = K x + b, to be brought to zero.
        const double b1 = (vn1 + p1.gapSpeed) - (c.k11 * a1 + c.k12 * a2);
        const double b2 = (vn2 + p2.gapSpeed) - (c.k12 * a1 + c.k22 * a2);
        double x1 = 0.0;
        double x2 = 0.0;
        BlockImpulses(c, b1, b2, a1, a2, x1, x2);
        ApplyImpulse(a, b, p1.rA, p1.rB, (x1 - a1) * n);
        ApplyImpulse(a, b, p2.rA, p2.rB, (x2 - a2) * n);
        p1.normalImpulse = x1;
        p2.normalImpulse = x2;
        record[0].normalSpeed = vn1;
        record[1].normalSpeed = vn2;
        record[0].normalImpulseWanted = -(c.m11 * b1 + c.m12 * b2);
        record[1].normalImpulseWanted = -(c.m12 * b1 + c.m22 * b2);
        record[0].normalImpulse = x1;
        record[1].normalImpulse = x2;
    }
    for (int i = 0; i < c.count; ++i)
    {
        recorder.Pass(record[i]);
    }
}

/// The soft constraint of a contact over one sub-step (Catto, "Solver2D", 2024; Box2D v3's soft step): a damped
/// spring of frequency `hertz` and damping ratio zeta, solved implicitly over a sub-step of h, gives the velocity
/// target biasRate times the separation, with the effective mass scaled by massScale and the accumulated impulse
/// leaking by impulseScale (massScale + impulseScale = 1). Implicit, so it is stable for any stiffness: a stiff
/// spring is a rigid contact that takes out its overlap within a sub-step.
struct Softness
{
    double biasRate = 0.0;     ///< velocity target per unit of overlap, per time unit
    double massScale = 1.0;    ///< fraction of the effective mass the impulse uses
    double impulseScale = 0.0; ///< fraction of the accumulated impulse taken back each solve
};

/// The soft constraint of a spring of `hertz` (> 0) and damping ratio `zeta` over a sub-step `h`: with omega =
/// 2 pi hertz, biasRate = omega / (2 zeta + h omega), and with a = h omega (2 zeta + h omega), massScale = a / (1 + a)
/// and impulseScale = 1 / (1 + a). From the implicit Euler step of m x'' = -k x - c v.
inline Softness MakeSoftness(double hertz, double zeta, double h)
{
    const double omega = 2.0 * 3.14159265358979323846 * hertz;
    const double a1 = 2.0 * zeta + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

/// Kinetic energy of a solver body (0 for static and sleeping ones).
inline double Energy(const SolverBody& b)
{
    const double linear = b.invMass > 0.0 ? Dot(b.v, b.v) / b.invMass : 0.0;
    const double angular = b.invInertia > 0.0 ? b.w * b.w / b.invInertia : 0.0;
    return 0.5 * (linear + angular);
}

/// Outline of restitution after the velocity passes (Poisson's hypothesis: the restitution impulse is a multiple of
/// the compression impulse; Stronge, "Impact Mechanics", 2000, ch. 2; Mirtich, "Impulse-based Dynamic Simulation
/// of Rigid Body Systems", 1996, ch. 2):
///  1. The passes have left each point with the compression impulse that stops its approach (a speculative point:
///     that lets it close its gap and no more).
///  2. Each bouncing point's restitution impulse is its restitutionFactor times that impulse, at most the impulse
///     its contact alone would need to reach its bounce speeds (a compression raised by the loads of other contacts
///     is not the impact's to return: without the bound, a point whose gap nearly closed, whose factor is large,
///     would fling a light body wedged in a pile).
///  3. The contacts are split into groups of bodies they join (static and sleeping bodies join nothing). With one
///     restitution e < 1 in a group the total impulse, (1 + e) times the inelastic one, always loses energy; with
///     different restitutions it can gain some. So in each group the restitution impulses are scaled by the
///     largest s <= 1 that leaves the group's kinetic energy at most `energyBefore` (summed per body: the energy
///     before the contacts acted). The energy is quadratic in s, so s is a root of a quadratic.
///  4. The scaled impulses are applied.
///  5. If any was, `passes` push-only passes stop the approaches the bounces made at other points (an inelastic
///     solve whose impulses only add to the ones before: it cannot take a bounce back, nor add energy).
/// A lone contact, or contacts of one restitution, get their bounce speeds exactly (s = 1). Each point's added
/// impulse is left in `restitutionImpulse` and added to its normal impulse. Where the order of the contacts changes
/// the sums (the impulses applied, the push-only passes), they are visited in `order`, a list of their indices.
void ApplyRestitution(std::vector<SolverContact>& contacts, const std::vector<int>& order,
                      std::vector<SolverBody>& bodies, const std::vector<double>& energyBefore, int passes);

} // namespace satviz::detail
