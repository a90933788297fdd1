// SPDX-License-Identifier: MIT
// satviz-v3-profile: steps the bodies of a scene file (as satviz-bench --world --write-scenes writes them) in Box2D
// v3, as satviz-bench --world does (density 1, friction 0.6, restitution 0.1, gravity 10, 4 sub-steps), and prints
// v3's own profile (b2World_GetProfile), each stage's mean ms per step: where v3's time goes on the same scene as
// satviz's. Built only with SATVIZ_BOX2D_V3_ROOT, beside satviz-bench.
#include <box2d/box2d.h>

#include <satviz/scene.h>
#include <satviz/scene_world.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

// Box2D v3's body of a satviz body, with the benchmark's materials.
void AddBody(b2WorldId world, const satviz::RigidBody& body)
{
    b2BodyDef def = b2DefaultBodyDef();
    const bool dynamic = body.type == satviz::BodyType::Dynamic;
    def.type = dynamic ? b2_dynamicBody : b2_staticBody;
    def.position = {static_cast<float>(body.position.x), static_cast<float>(body.position.y)};
    def.rotation = b2MakeRot(static_cast<float>(body.angle));
    const b2BodyId id = b2CreateBody(world, &def);
    b2ShapeDef shapeDef = b2DefaultShapeDef();
    shapeDef.density = 1.0f;
    shapeDef.material.friction = 0.6f;
    shapeDef.material.restitution = 0.1f;
    if (body.shape.type == satviz::ShapeType::Polygon)
    {
        b2Vec2 points[B2_MAX_POLYGON_VERTICES];
        const int count = body.shape.polygon.Count();
        for (int i = 0; i < count && i < B2_MAX_POLYGON_VERTICES; ++i)
        {
            points[i] = {static_cast<float>(body.shape.polygon.Vertices()[i].x),
                         static_cast<float>(body.shape.polygon.Vertices()[i].y)};
        }
        const b2Hull hull = b2ComputeHull(points, count < B2_MAX_POLYGON_VERTICES ? count : B2_MAX_POLYGON_VERTICES);
        const b2Polygon polygon = b2MakePolygon(&hull, 0.0f);
        b2CreatePolygonShape(id, &shapeDef, &polygon);
    }
    else
    {
        b2Circle circle;
        circle.center = {static_cast<float>(body.shape.circle.center.x),
                         static_cast<float>(body.shape.circle.center.y)};
        circle.radius = static_cast<float>(body.shape.circle.radius);
        b2CreateCircleShape(id, &shapeDef, &circle);
    }
    if (dynamic)
    {
        b2Body_SetLinearVelocity(id, {static_cast<float>(body.velocity.x), static_cast<float>(body.velocity.y)});
        b2Body_SetAngularVelocity(id, static_cast<float>(body.angularVelocity));
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 4)
    {
        std::fprintf(stderr, "usage: satviz-v3-profile SCENE.json [STEPS (default 600)] [WORKERS (default 1)]\n");
        return 2;
    }
    const int steps = argc > 2 ? std::atoi(argv[2]) : 600;
    const int workers = argc > 3 ? std::atoi(argv[3]) : 1;
    if (steps < 1 || workers < 1)
    {
        std::fprintf(stderr, "satviz-v3-profile: STEPS and WORKERS must be at least 1\n");
        return 2;
    }
    const satviz::SceneResult loaded = satviz::LoadScene(argv[1]);
    if (!loaded.Ok())
    {
        std::fprintf(stderr, "satviz-v3-profile: %s\n", loaded.error.c_str());
        return 1;
    }
    const satviz::World scene = satviz::MakeWorld(loaded.scene);
    b2WorldDef worldDef = b2DefaultWorldDef();
    worldDef.gravity = {0.0f, -10.0f};
    worldDef.restitutionThreshold = 1.0f;
    worldDef.workerCount = workers;
    const b2WorldId world = b2CreateWorld(&worldDef);
    for (const satviz::RigidBody& body : scene.bodies)
    {
        AddBody(world, body);
    }
    // b2Profile is a run of floats, each a stage's ms in the last step.
    constexpr int kFields = static_cast<int>(sizeof(b2Profile) / sizeof(float));
    static const char* const kNames[kFields] = {
        "step",          "pairs",        "collide",    "solve",         "solverSetup",        "constraints",
        "prepareConstraints", "integrateVelocities", "warmStart", "solveImpulses", "integratePositions",
        "relaxImpulses", "applyRestitution", "storeImpulses", "splitIslands", "transforms", "sensorHits",
        "jointEvents",   "hitEvents",    "refit",      "bullets",       "sleepIslands",       "sensors"};
    double sum[kFields] = {};
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k)
    {
        b2World_Step(world, 1.0f / 60.0f, 4);
        const b2Profile profile = b2World_GetProfile(world);
        const float* fields = reinterpret_cast<const float*>(&profile);
        for (int i = 0; i < kFields; ++i)
        {
            sum[i] += fields[i];
        }
    }
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %d steps, %d worker(s), %.1f ms by the wall clock (%.3f ms per step)\n", argv[1], steps, workers,
                wall, wall / steps);
    for (int i = 0; i < kFields; ++i)
    {
        std::printf("%-20s %8.3f ms/step %6.1f %%\n", kNames[i], sum[i] / steps, 100.0 * sum[i] / sum[0]);
    }
    b2DestroyWorld(world);
    return 0;
}
