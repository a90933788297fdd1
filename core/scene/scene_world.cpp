// SPDX-License-Identifier: MIT
// satviz: scenes to worlds and back.

#include <satviz/scene_world.h>

#include <cassert>

namespace satviz
{

BodyDef MakeBodyDef(const Body& body)
{
    BodyDef def;
    def.shape = body.shape;
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
        to.angle = from.angle;
        to.velocity = from.velocity;
        to.angularVelocity = from.angularVelocity;
    }
}

} // namespace satviz
