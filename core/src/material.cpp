// SPDX-License-Identifier: MIT
// satviz: how the materials of two bodies combine at a contact.

#include <satviz/material.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

ContactMaterial CombineMaterials(const Material& a, const Material& b)
{
    ContactMaterial m;
    m.restitution = std::max(a.restitution, b.restitution);
    m.friction = std::sqrt(a.friction * b.friction);
    m.staticFriction = std::sqrt(a.staticFriction * b.staticFriction);
    return m;
}

} // namespace satviz
