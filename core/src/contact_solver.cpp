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
        p.restitutionFactor = 0.0;
        if (approach[i] < -restitutionThreshold)
        {
            const double e = c.material.restitution;
            const double v = approach[i];
            // Only the overlap this step's approach can have made counts: a deeper one was there before the impact
            // and gravity's energy stored in it is not the impact's to return. A gap (a speculative contact) counts
            // as a negative overlap: the fall through it adds to the speed at the surface.
            const double d = p.separation < 0.0 ? std::min(-p.separation, -v * dt) : -p.separation;
            const double gdt = pull * dt;
            const double u2 = std::max(0.0, v * v - gdt * v - 2.0 * pull * d);
            p.bounce = 0.5 * (std::sqrt(gdt * gdt + 4.0 * std::max(0.0, 2.0 * pull * d + e * e * u2)) - gdt);
            if (e == 0.0)
            {
                p.bounce = 0.0;
            }
            // The compression stops the point at -gapSpeed (its gap closed); the restitution impulse, a multiple of
            // the compression impulse, must then bring it to the bounce speed.
            const double compression = gdt - v - p.gapSpeed;
            p.restitutionFactor = p.bounce > 0.0 && compression > 0.0 ? (p.bounce + p.gapSpeed) / compression : 0.0;
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

namespace
{

int Root(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

} // namespace

void ApplyRestitution(std::vector<SolverContact>& contacts, const std::vector<int>& order,
                      std::vector<SolverBody>& bodies, const std::vector<double>& energyBefore, int passes)
{
    bool any = false;
    for (SolverContact& c : contacts)
    {
        // At most what the contact alone would need to bring its points from the end of their compression (their
        // gap closed) to their bounce speeds: a compression impulse raised by other contacts' loads is not the
        // impact's to return.
        double alone[2] = {0.0, 0.0};
        const double u0 = c.points[0].bounce + c.points[0].gapSpeed;
        const double u1 = c.points[1].bounce + c.points[1].gapSpeed;
        if (c.block)
        {
            alone[0] = c.m11 * u0 + c.m12 * u1;
            alone[1] = c.m12 * u0 + c.m22 * u1;
        }
        else
        {
            alone[0] = c.points[0].normalMass * u0;
            alone[1] = c.points[1].normalMass * u1;
        }
        for (int i = 0; i < c.count; ++i)
        {
            SolverPoint& p = c.points[i];
            p.restitutionImpulse = std::min(p.restitutionFactor * p.normalImpulse, std::max(0.0, alone[i]));
            any = any || p.restitutionImpulse > 0.0;
        }
    }
    if (!any)
    {
        return;
    }
    // Groups: union-find over the bodies that move.
    const int n = static_cast<int>(bodies.size());
    std::vector<int> parent(n);
    for (int i = 0; i < n; ++i)
    {
        parent[i] = i;
    }
    auto moves = [&](int i) { return bodies[i].invMass > 0.0 || bodies[i].invInertia > 0.0; };
    for (const SolverContact& c : contacts)
    {
        if (moves(c.a) && moves(c.b))
        {
            const int ra = Root(parent, c.a), rb = Root(parent, c.b);
            parent[ra < rb ? rb : ra] = ra < rb ? ra : rb;
        }
    }
    // The velocity change of the unscaled restitution impulses, per body.
    std::vector<Vec2> dv(n);
    std::vector<double> dw(n, 0.0);
    for (const int k : order)
    {
        const SolverContact& c = contacts[static_cast<size_t>(k)];
        for (int i = 0; i < c.count; ++i)
        {
            const SolverPoint& p = c.points[i];
            if (p.restitutionImpulse > 0.0)
            {
                SolverBody a{dv[c.a], dw[c.a], bodies[c.a].invMass, bodies[c.a].invInertia};
                SolverBody b{dv[c.b], dw[c.b], bodies[c.b].invMass, bodies[c.b].invInertia};
                ApplyImpulse(a, b, p.rA, p.rB, p.restitutionImpulse * c.normal);
                dv[c.a] = a.v;
                dw[c.a] = a.w;
                dv[c.b] = b.v;
                dw[c.b] = b.w;
            }
        }
    }
    // Per group: energy now (e0), its allowance, and the linear (g) and quadratic (h) terms in the scale.
    std::vector<double> e0(n, 0.0), allowed(n, 0.0), g(n, 0.0), h(n, 0.0);
    for (int i = 0; i < n; ++i)
    {
        if (!moves(i))
        {
            continue;
        }
        const int r = Root(parent, i);
        const SolverBody& b = bodies[i];
        e0[r] += Energy(b);
        allowed[r] += energyBefore[i];
        const double m = b.invMass > 0.0 ? 1.0 / b.invMass : 0.0;
        const double inertia = b.invInertia > 0.0 ? 1.0 / b.invInertia : 0.0;
        g[r] += m * Dot(b.v, dv[i]) + inertia * b.w * dw[i];
        h[r] += 0.5 * (m * Dot(dv[i], dv[i]) + inertia * dw[i] * dw[i]);
    }
    std::vector<double> scale(n, 1.0);
    for (int r = 0; r < n; ++r)
    {
        if (parent[r] != r || h[r] <= 0.0 || e0[r] + g[r] + h[r] <= allowed[r])
        {
            continue;
        }
        const double c0 = e0[r] - allowed[r];
        const double disc = g[r] * g[r] - 4.0 * h[r] * c0;
        scale[r] = c0 >= 0.0 || disc < 0.0 ? 0.0 : std::min(1.0, (-g[r] + std::sqrt(disc)) / (2.0 * h[r]));
    }
    bool applied = false;
    for (const int k : order)
    {
        SolverContact& c = contacts[static_cast<size_t>(k)];
        const int r = Root(parent, moves(c.a) ? c.a : c.b);
        for (int i = 0; i < c.count; ++i)
        {
            SolverPoint& p = c.points[i];
            if (p.restitutionImpulse > 0.0)
            {
                p.restitutionImpulse *= scale[r];
                ApplyImpulse(bodies[c.a], bodies[c.b], p.rA, p.rB, p.restitutionImpulse * c.normal);
                p.normalImpulse += p.restitutionImpulse;
                applied = applied || p.restitutionImpulse > 0.0;
            }
        }
    }
    if (!applied)
    {
        return;
    }
    // A bounce can drive a body into another of its contacts: push-only passes stop such approaches, inelastically,
    // and never take back any of the impulses above.
    for (int pass = 0; pass < passes; ++pass)
    {
        for (const int k : order)
        {
            SolverContact& c = contacts[static_cast<size_t>(k)];
            SolverBody& a = bodies[c.a];
            SolverBody& b = bodies[c.b];
            for (int i = 0; i < c.count; ++i)
            {
                SolverPoint& p = c.points[i];
                const double vn = Dot(RelativeVelocity(a, b, p.rA, p.rB), c.normal) + p.gapSpeed;
                const double next = std::max(0.0, p.pushImpulse - p.normalMass * vn);
                ApplyImpulse(a, b, p.rA, p.rB, (next - p.pushImpulse) * c.normal);
                p.pushImpulse = next;
            }
        }
    }
}

} // namespace satviz::detail
