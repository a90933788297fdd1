// SPDX-License-Identifier: MIT
// satviz: the contact solver's setup and warm start.

#include "contact_solver.h"

#include <algorithm>
#include <cmath>

namespace satviz::detail
{

// The target comes from the energy that semi-implicit Euler keeps exactly in free fall: with v the velocity of a
// step's move and y the height reached, v^2 / 2 + g y - g dt v / 2 is the same at every step. At the impact, the
// approach v < 0 (before gravity) has reached an overlap d, so the speed it would have had at the surface is
// u^2 = v^2 + g dt |v| - 2 g d. The separating speed w that gives the same quantity restitution^2 u^2 / 2 at the
// surface after the step solves w^2 + g dt w = 2 g d + e^2 u^2.
void PrepareContact(SolverContact& c, const SolverBody& a, const SolverBody& b, const double approach[2], double pull,
                    double dt, double restitutionThreshold)
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
        p.bounce = 0.0;
        if (approach[i] < -restitutionThreshold)
        {
            const double e = c.material.restitution;
            const double v = approach[i];
            const double d = p.separation < 0.0 ? -p.separation : 0.0;
            const double gdt = pull * dt;
            const double u2 = std::max(0.0, v * v - gdt * v - 2.0 * pull * d);
            p.bounce = 0.5 * (std::sqrt(gdt * gdt + 4.0 * (2.0 * pull * d + e * e * u2)) - gdt);
            if (e == 0.0)
            {
                p.bounce = 0.0;
            }
        }
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

} // namespace satviz::detail
