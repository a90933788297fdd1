// SPDX-License-Identifier: MIT
// satviz: the contact solver's setup, warm start and split impulse.

#include "contact_solver.h"

namespace satviz::detail
{

void PrepareContact(SolverContact& c, const SolverBody& a, const SolverBody& b, const double approach[2],
                    double restitutionThreshold)
{
    const Vec2 n = c.normal;
    const Vec2 t = RightPerp(n);
    const double mA = a.invMass, mB = b.invMass, iA = a.invInertia, iB = b.invInertia;
    for (int i = 0; i < c.count; ++i)
    {
        SolverPoint& p = c.points[i];
        const double rnA = Cross(p.rA, n), rnB = Cross(p.rB, n);
        const double kn = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
        p.normalMass = kn > 0.0 ? 1.0 / kn : 0.0;
        const double rtA = Cross(p.rA, t), rtB = Cross(p.rB, t);
        const double kt = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
        p.tangentMass = kt > 0.0 ? 1.0 / kt : 0.0;
        p.bounce = approach[i] < -restitutionThreshold ? -c.material.restitution * approach[i] : 0.0;
    }
    c.block = false;
    if (c.count == 2)
    {
        const SolverPoint& p1 = c.points[0];
        const SolverPoint& p2 = c.points[1];
        const double rn1A = Cross(p1.rA, n), rn1B = Cross(p1.rB, n);
        const double rn2A = Cross(p2.rA, n), rn2B = Cross(p2.rB, n);
        c.k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
        c.k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
        c.k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
        const double det = c.k11 * c.k22 - c.k12 * c.k12;
        // Solve the pair as a block only while K is well conditioned (points far enough apart); Box2D uses the
        // same bound on the condition number.
        if (c.k11 * c.k11 < 1000.0 * det && det > 0.0)
        {
            c.block = true;
            const double inv = 1.0 / det;
            c.m11 = inv * c.k22;
            c.m12 = -inv * c.k12;
            c.m22 = inv * c.k11;
        }
    }
}

void WarmStart(SolverContact& c, SolverBody& a, SolverBody& b)
{
    const Vec2 t = RightPerp(c.normal);
    for (int i = 0; i < c.count; ++i)
    {
        const SolverPoint& p = c.points[i];
        ApplyImpulse(a, b, p.rA, p.rB, p.normalImpulse * c.normal + p.tangentImpulse * t);
    }
}

void SolveContactPosition(SolverContact& c, SolverBody& a, SolverBody& b, double dt, double slop, double factor)
{
    const Vec2 n = c.normal;
    for (int i = 0; i < c.count; ++i)
    {
        SolverPoint& p = c.points[i];
        if (p.bounce > 0.0)
        {
            continue;
        }
        const double excess = -p.separation - slop;
        const double target = excess > 0.0 ? factor * excess / dt : 0.0;
        const Vec2 dv = (b.pv + b.pw * LeftPerp(p.rB)) - (a.pv + a.pw * LeftPerp(p.rA));
        const double wanted = p.pseudoImpulse - p.normalMass * (Dot(dv, n) - target);
        const double next = wanted > 0.0 ? wanted : 0.0;
        const Vec2 impulse = (next - p.pseudoImpulse) * n;
        p.pseudoImpulse = next;
        a.pv = a.pv - a.invMass * impulse;
        a.pw -= a.invInertia * Cross(p.rA, impulse);
        b.pv = b.pv + b.invMass * impulse;
        b.pw += b.invInertia * Cross(p.rB, impulse);
    }
}

} // namespace satviz::detail
