// SPDX-License-Identifier: MIT
#include <satviz/collide.h>
#include <satviz/scene_world.h>
#include <satviz/sim_record.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

SimSample MeasureWorld(const World& world, int step)
{
    SimSample sample;
    sample.step = step;
    sample.time = world.time;
    sample.kinetic = KineticEnergy(world);
    sample.momentum = LinearMomentum(world);
    std::vector<Shape> shapes;
    std::vector<Transform> xfs;
    shapes.reserve(world.bodies.size());
    xfs.reserve(world.bodies.size());
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            sample.potential -= body.mass * Dot(world.settings.gravity, body.WorldCenter());
        }
        shapes.push_back(body.shape);
        xfs.push_back(body.Xf());
    }
    for (const auto& [i, j] : TouchingPairs(shapes, xfs))
    {
        if (world.bodies[static_cast<size_t>(i)].type == BodyType::Static &&
            world.bodies[static_cast<size_t>(j)].type == BodyType::Static)
        {
            continue; // walls that meet are not an overlap the world has to remove
        }
        const Manifold m = Collide(shapes[static_cast<size_t>(i)], xfs[static_cast<size_t>(i)],
                                   shapes[static_cast<size_t>(j)], xfs[static_cast<size_t>(j)]);
        if (m.overlap)
        {
            sample.deepestOverlap = std::max(sample.deepestOverlap, m.depth);
        }
    }
    return sample;
}

SimRecord StartRecord(const Scene& scene, int pairA, int pairB)
{
    SimRecord record;
    record.world = MakeWorld(scene);
    record.dt = scene.world.dt;
    record.contact.bodyA = pairA;
    record.contact.bodyB = pairB;
    record.history.push_back(MeasureWorld(record.world, 0));
    return record;
}

void StepRecord(SimRecord& record)
{
    record.before = record.world.bodies;
    record.world.stepTrace = &record.lastStep;
    record.world.trace = &record.contact;
    Step(record.world, record.dt);
    record.world.stepTrace = nullptr;
    record.world.trace = nullptr;
    ++record.steps;
    record.history.push_back(MeasureWorld(record.world, record.steps));
}

std::string SimulateSceneRecorded(Scene& scene, int steps, int pairA, int pairB, SimRecord& record)
{
    if (steps < 0)
    {
        return "expected a whole number of steps of at least 0, got " + std::to_string(steps);
    }
    if (std::string error = ValidateSceneWorld(scene); !error.empty())
    {
        return error;
    }
    record = StartRecord(scene, pairA, pairB);
    for (int i = 0; i < steps; ++i)
    {
        StepRecord(record);
    }
    return StoreWorldState(record.world, scene, steps);
}

} // namespace satviz
