// SPDX-License-Identifier: MIT
#include <satviz/collide.h>
#include <satviz/render/study.h>

namespace satviz
{

Transform BodyTransformAt(const Body& body, double t)
{
    return MakeTransform(body.position + t * body.velocity, body.angle);
}

PairStudy StudyPair(const Scene& scene, int a, int b, ViewQuery query)
{
    PairStudy study;
    study.bodyA = a;
    study.bodyB = b;
    const Body& bodyA = scene.bodies[static_cast<size_t>(a)];
    const Body& bodyB = scene.bodies[static_cast<size_t>(b)];
    const Transform xfA = bodyA.Xf();
    const Transform xfB = bodyB.Xf();
    study.manifold = Collide(bodyA.shape, xfA, bodyB.shape, xfB, &study.trace);
    const bool moving = bodyA.velocity != bodyB.velocity;
    study.sweep = query == ViewQuery::Sweep || (query == ViewQuery::Automatic && moving);
    if (study.sweep)
    {
        study.sweepResult =
            Sweep(bodyA.shape, xfA, bodyA.velocity, bodyB.shape, xfB, bodyB.velocity, &study.sweepTrace);
        if (study.sweepResult.status == SweepStatus::Overlapping)
        {
            study.sweep = false;
            study.startsOverlapping = true;
        }
    }
    return study;
}

} // namespace satviz
