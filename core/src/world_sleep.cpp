// SPDX-License-Identifier: MIT
// satviz: the step's last stage: islands of resting bodies fall asleep.

#include "stepper.h"
#include "world_lookup.h"

#include <algorithm>
#include <cmath>

namespace satviz::detail
{

// Stage 6: islands of touching dynamic bodies sleep together once all have rested long enough.
void Stepper::Sleep()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    StepCounts& counts = world.counts;
    if (!settings.sleeping)
    {
        for (RigidBody& body : bodies)
        {
            if (body.type == BodyType::Dynamic)
            {
                body.awake = true;
                body.sleepTime = 0.0;
            }
        }
    }
    else
    {
        const double linear2 = settings.sleepLinearSpeed * settings.sleepLinearSpeed;
        for (RigidBody& body : bodies)
        {
            if (!IsAwakeDynamic(body))
            {
                continue;
            }
            const bool resting = LengthSquared(body.velocity) <= linear2 &&
                                 std::fabs(body.angularVelocity) <= settings.sleepAngularSpeed;
            body.sleepTime = resting ? body.sleepTime + dt : 0.0;
        }
        std::vector<int> parent(n);
        for (int i = 0; i < n; ++i)
        {
            parent[i] = i;
        }
        for (const WorldContact& c : world.contacts)
        {
            if (bodies[c.a].type == BodyType::Dynamic && bodies[c.b].type == BodyType::Dynamic)
            {
                const int ra = FindRoot(parent, c.a), rb = FindRoot(parent, c.b);
                if (ra != rb)
                {
                    parent[ra > rb ? ra : rb] = ra < rb ? ra : rb;
                }
            }
        }
        // The shortest rest in each island, and whether any body of it is awake.
        std::vector<double> shortest(n, INFINITY);
        std::vector<uint8_t> anyAwake(n, 0);
        for (int i = 0; i < n; ++i)
        {
            if (bodies[i].type != BodyType::Dynamic)
            {
                continue;
            }
            const int root = FindRoot(parent, i);
            shortest[root] = std::min(shortest[root], bodies[i].awake ? bodies[i].sleepTime : INFINITY);
            anyAwake[root] |= bodies[i].awake ? 1 : 0;
        }
        for (int i = 0; i < n; ++i)
        {
            RigidBody& body = bodies[i];
            if (body.type != BodyType::Dynamic || !body.awake)
            {
                continue;
            }
            const int root = FindRoot(parent, i);
            if (anyAwake[root] && shortest[root] >= settings.timeToSleep)
            {
                body.awake = false;
                body.velocity = {};
                body.angularVelocity = 0.0;
            }
        }
    }
    counts.awakeBodies = 0;
    counts.sleepingBodies = 0;
    for (const RigidBody& body : bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            (body.awake ? counts.awakeBodies : counts.sleepingBodies) += 1;
        }
    }
}

} // namespace satviz::detail
