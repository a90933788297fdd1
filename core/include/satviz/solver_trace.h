// SPDX-License-Identifier: MIT
// satviz: what the contact solver did for one contact, recorded for teaching views.
#pragma once

#include <satviz/math.h>

#include <vector>

namespace satviz
{

/// One pass of the solver over one contact point.
struct ContactPointSolve
{
    int pass = 0;                      ///< velocity pass, from 0; -1 for a time-ordered hit's own solve
    int point = 0;                     ///< contact point index (0 or 1)
    double normalSpeed = 0.0;          ///< relative normal velocity at the point before this pass (< 0: approaching)
    double normalImpulseWanted = 0.0;  ///< accumulated normal impulse the pass asked for, before the clamp
    double normalImpulse = 0.0;        ///< after the clamp to >= 0 (a contact only pushes)
    double tangentSpeed = 0.0;         ///< relative tangential velocity at the point before the friction impulse
    double tangentImpulseWanted = 0.0; ///< accumulated friction impulse that would stop the slip, before the cone
    double staticLimit = 0.0;          ///< staticFriction * normalImpulse
    double dynamicLimit = 0.0;         ///< friction * normalImpulse
    double tangentImpulse = 0.0;       ///< after the cone: the wanted impulse if within the static limit, else clamped
    bool stuck = false;                ///< static friction held (the wanted impulse was within the static limit)
};

/// The solver's record of one contact over one step: its setup and every pass.
struct ContactSolveTrace
{
    int bodyA = -1;            ///< the pair to record (set by the caller), a < b or b < a
    int bodyB = -1;            ///< see bodyA
    bool found = false;        ///< the pair had a contact in the step (touching, or speculative)
    Vec2 normal{};             ///< unit contact normal from the lower-index body to the other
    int pointCount = 0;        ///< contact points
    double approachSpeed[2]{}; ///< relative normal velocity per point before gravity and the solve
    /// Per point: a speculative point's gap (> 0 at the start of the step) over dt, the approach speed the passes
    /// leave it, so that it closes the gap within the step and no more; 0 for a point already touching.
    double gapSpeed[2]{};
    double restitution = 0.0;              ///< the contact's combined restitution
    double bounceSpeed[2]{};               ///< separating speed per point the restitution gives a lone contact:
                                           ///< restitution * approach without gravity, or 0 below the threshold
    double restitutionFactor[2]{};         ///< restitution impulse per point as a multiple of its compression impulse
    double restitutionImpulse[2]{};        ///< impulse the restitution added per point after the passes
    double normalMass[2]{};                ///< effective mass along the normal per point
    double tangentMass[2]{};               ///< effective mass along the tangent per point
    double warmNormal[2]{};                ///< normal impulse carried over from the last step (warm start)
    double warmTangent[2]{};               ///< friction impulse carried over from the last step
    bool blockSolved = false;              ///< the two normal impulses were solved together
    /// The passes left the contact's group of bodies (those its contacts join) with more kinetic energy than they
    /// had before the contacts acted, beyond the drift the slop allows (passes from a warm start that have not
    /// converged can): the group got more passes (recorded in `passes`, numbered on from velocityIterations), and if
    /// it still gained, every impulse of the group, this contact's among them, was scaled by impulseScale.
    bool energyLimited = false;
    double impulseScale = 1.0; ///< the factor of energyLimited; 1 when the impulses were kept as solved
    std::vector<ContactPointSolve> passes; ///< every pass over every point, in order
    /// Velocities of the lower-index body (0) and the other (1) at the start of the step, before gravity and the
    /// solve; 0 for a static body.
    Vec2 velocityBefore[2]{};
    double spinBefore[2]{}; ///< angular velocities, as velocityBefore
    /// Velocities after the step's gravity, the velocity passes over every contact and the restitution: what the
    /// bodies move with (unless a time-ordered hit changes them later in the step).
    Vec2 velocityAfter[2]{};
    double spinAfter[2]{}; ///< angular velocities, as velocityAfter
    int hits = 0;                          ///< time-ordered hits between the pair within the step
    double hitTime = -1.0;                 ///< time of the first such hit within the step, in [0, 1] of the step, or -1
    /// Empties the record, keeping the pair.
    void Clear()
    {
        const int a = bodyA, b = bodyB;
        *this = ContactSolveTrace();
        bodyA = a;
        bodyB = b;
    }
};

} // namespace satviz
