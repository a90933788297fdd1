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
        // Each body is read once, in order, into small arrays (a body is several cache lines): whether it is
        // dynamic and awake, and how long it has rested.
        const double linear2 = settings.sleepLinearSpeed * settings.sleepLinearSpeed;
        std::vector<int> parent(n);
        std::vector<uint8_t> dynamic(n), awake(n);
        std::vector<double> rest(n);
        for (int i = 0; i < n; ++i)
        {
            RigidBody& body = bodies[i];
            parent[i] = i;
            dynamic[i] = body.type == BodyType::Dynamic ? 1 : 0;
            awake[i] = body.awake ? 1 : 0;
            if (IsAwakeDynamic(body))
            {
                const bool resting = LengthSquared(body.velocity) <= linear2 &&
                                     std::fabs(body.angularVelocity) <= settings.sleepAngularSpeed;
                body.sleepTime = resting ? body.sleepTime + dt : 0.0;
            }
            rest[i] = body.sleepTime;
        }
        for (const WorldContact& c : world.contacts)
        {
            if (dynamic[c.a] != 0 && dynamic[c.b] != 0)
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
            if (dynamic[i] == 0)
            {
                continue;
            }
            const int root = FindRoot(parent, i);
            shortest[root] = std::min(shortest[root], awake[i] != 0 ? rest[i] : INFINITY);
            anyAwake[root] |= awake[i];
        }
        for (int i = 0; i < n; ++i)
        {
            if (dynamic[i] == 0 || awake[i] == 0)
            {
                continue;
            }
            const int root = FindRoot(parent, i);
            if (anyAwake[root] && shortest[root] >= settings.timeToSleep)
            {
                RigidBody& body = bodies[i];
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
