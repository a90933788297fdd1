// SPDX-License-Identifier: MIT
// satviz: scenes to worlds and back.

#include <satviz/scene_world.h>

#include <cassert>
#include <cmath>

namespace satviz
{

namespace
{

constexpr double kTwoPi = 6.283185307179586476925286766559;

} // namespace

BodyDef MakeBodyDef(const Body& body)
{
    BodyDef def;
    def.shape = body.shape;
    def.concave = body.concave;
    def.type = body.isStatic ? BodyType::Static : BodyType::Dynamic;
    def.density = body.density;
    def.material = body.material;
    def.position = body.position;
    def.angle = body.angle;
    def.velocity = body.velocity;
    def.angularVelocity = body.angularVelocity;
    return def;
}

std::string ValidateSceneWorld(const Scene& scene)
{
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        const std::string error = ValidateBodyDef(MakeBodyDef(scene.bodies[i]));
        if (!error.empty())
        {
            return "bodies[" + std::to_string(i) + "] (\"" + scene.bodies[i].name + "\"): " + error;
        }
    }
    return {};
}

World MakeWorld(const Scene& scene)
{
    World world;
    world.settings.gravity = scene.world.gravity;
    world.bodies.reserve(scene.bodies.size());
    for (const Body& body : scene.bodies)
    {
        AddBody(world, MakeBodyDef(body));
    }
    return world;
}

void CopyWorldState(const World& world, Scene& scene)
{
    assert(world.bodies.size() == scene.bodies.size());
    for (size_t i = 0; i < scene.bodies.size() && i < world.bodies.size(); ++i)
    {
        const RigidBody& from = world.bodies[i];
        Body& to = scene.bodies[i];
        to.position = from.position;
        // The world sums a body's turning without bound; a scene holds its orientation, so the angle is written
        // turned into [-pi, pi].
        to.angle = std::remainder(from.angle, kTwoPi);
        to.velocity = from.velocity;
        to.angularVelocity = from.angularVelocity;
    }
}

std::string StoreWorldState(const World& world, Scene& scene, int steps)
{
    const std::string after = "after " + std::to_string(steps) + (steps == 1 ? " step" : " steps");
    for (size_t i = 0; i < world.bodies.size(); ++i)
    {
        const RigidBody& body = world.bodies[i];
        const double values[] = {body.position.x, body.position.y, body.velocity.x, body.velocity.y,
                                 body.angularVelocity};
        for (const double v : values)
        {
            if (!(std::fabs(v) <= kMaxSceneValue))
            {
                return "bodies[" + std::to_string(i) + "] (\"" + scene.bodies[i].name + "\"): " + after +
                       " its state is beyond what a scene holds (at most 1e12)";
            }
        }
    }
    CopyWorldState(world, scene);
    return {};
}

std::string SimulateScene(Scene& scene, int steps)
{
    if (steps < 0)
    {
        return "expected a whole number of steps of at least 0, got " + std::to_string(steps);
    }
    if (steps == 0)
    {
        return {};
    }
    if (std::string error = ValidateSceneWorld(scene); !error.empty())
    {
        return error;
    }
    World world = MakeWorld(scene);
    for (int i = 0; i < steps; ++i)
    {
        Step(world, scene.world.dt);
    }
    return StoreWorldState(world, scene, steps);
}

} // namespace satviz
