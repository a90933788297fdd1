// SPDX-License-Identifier: MIT
// satviz: what the world's stages ask of its bodies and contacts: which bodies move, and a pair's contact (internal).
#pragma once

#include <satviz/world.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace satviz::detail
{

/// Whether the step moves the body: dynamic and awake. Static and sleeping bodies keep their place.
inline bool IsAwakeDynamic(const RigidBody& body)
{
    return body.type == BodyType::Dynamic && body.awake;
}

/// The contact of the pair (a, b), a < b, in `contacts` sorted by (a, b), guards included; nullptr if it has none.
inline const WorldContact* FindContact(const std::vector<WorldContact>& contacts, int a, int b)
{
    auto it = std::lower_bound(contacts.begin(), contacts.end(), std::make_pair(a, b),
                               [](const WorldContact& c, const std::pair<int, int>& key) {
                                   return c.a < key.first || (c.a == key.first && c.b < key.second);
                               });
    return it != contacts.end() && it->a == a && it->b == b ? &*it : nullptr;
}

/// The step's contact of the pair (a, b), a < b, if it has one (a guard is not a contact).
inline const WorldContact* ContactOf(const std::vector<WorldContact>& contacts, int a, int b)
{
    const WorldContact* contact = FindContact(contacts, a, b);
    return contact != nullptr && !contact->guard ? contact : nullptr;
}

} // namespace satviz::detail
