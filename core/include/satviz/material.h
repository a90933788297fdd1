// SPDX-License-Identifier: MIT
// satviz: the material of a body (bounce and friction) and how two materials combine at a contact.
#pragma once

#include <algorithm>
#include <cmath>

namespace satviz
{

/// How a body bounces and grips.
struct Material
{
    /// Coefficient of restitution in [0, 1]: the ratio of the separating to the approaching normal speed after a
    /// hit. 0 is a dead stop, 1 a perfectly elastic bounce.
    double restitution = 0.0;
    /// Coefficient of dynamic (kinetic) friction, >= 0: sliding, the tangential impulse is friction times the
    /// normal impulse, against the slip.
    double friction = 0.5;
    /// Coefficient of static friction, >= 0: a contact that is not slipping stays put while the tangential
    /// impulse it needs is at most staticFriction times the normal impulse.
    double staticFriction = 0.5;
};

/// The material of a contact between two bodies.
struct ContactMaterial
{
    double restitution = 0.0;    ///< max of the two restitutions
    double friction = 0.0;       ///< geometric mean of the two dynamic frictions
    double staticFriction = 0.0; ///< geometric mean of the two static frictions
};

/// The one rule of combination: the larger restitution (a bouncy ball bounces on a dead floor), the geometric
/// mean of the frictions (ice against anything slides: a zero coefficient wins). Box2D combines the same way.
/// Inline: the world combines two materials for every contact it finds, and a call returns the result through
/// memory that the caller then reads back whole, before the stores have landed.
inline ContactMaterial CombineMaterials(const Material& a, const Material& b)
{
    ContactMaterial m;
    m.restitution = std::max(a.restitution, b.restitution);
    m.friction = std::sqrt(a.friction * b.friction);
    m.staticFriction = std::sqrt(a.staticFriction * b.staticFriction);
    return m;
}

} // namespace satviz
