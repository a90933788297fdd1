// SPDX-License-Identifier: MIT
#include "box2d_v3.h"

#ifdef SATVIZ_HAVE_BOX2D_V3
#include <box2d/box2d.h>
#endif

#include <stdexcept>

namespace satviz::bench
{

#ifdef SATVIZ_HAVE_BOX2D_V3

bool HaveBox2DV3()
{
    return true;
}

std::string Box2DV3Version()
{
    const b2Version v = b2GetVersion();
    return std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.revision);
}

struct Box2DV3World::Impl
{
    V3Settings settings;
    b2WorldId world{};
    std::vector<b2BodyId> bodies; // in the scene's order
    std::vector<bool> dynamic;
};

Box2DV3World::Box2DV3World(const std::vector<V3Body>& bodies, const V3Settings& settings) : impl(new Impl)
{
    impl->settings = settings;
    b2WorldDef worldDef = b2DefaultWorldDef();
    worldDef.gravity = {0.0f, static_cast<float>(-settings.gravity)};
    worldDef.restitutionThreshold = static_cast<float>(settings.restitutionThreshold);
    // Its own scheduler with this many workers (1: the serial path).
    worldDef.workerCount = settings.workers;
    impl->world = b2CreateWorld(&worldDef);
    for (const V3Body& body : bodies)
    {
        b2BodyDef def = b2DefaultBodyDef();
        def.type = body.dynamic ? b2_dynamicBody : b2_staticBody;
        def.position = {static_cast<float>(body.position.x), static_cast<float>(body.position.y)};
        def.rotation = b2MakeRot(static_cast<float>(body.angle));
        const b2BodyId id = b2CreateBody(impl->world, &def);
        b2ShapeDef shapeDef = b2DefaultShapeDef();
        shapeDef.density = static_cast<float>(settings.density);
        shapeDef.material.friction = static_cast<float>(settings.friction);
        shapeDef.material.restitution = static_cast<float>(settings.restitution);
        if (body.shape.type == ShapeType::Polygon)
        {
            b2Vec2 points[B2_MAX_POLYGON_VERTICES];
            const int count = body.shape.polygon.Count();
            if (count > B2_MAX_POLYGON_VERTICES)
            {
                throw std::invalid_argument("Box2D v3 takes polygons of at most 8 vertices");
            }
            for (int i = 0; i < count; ++i)
            {
                points[i] = {static_cast<float>(body.shape.polygon.Vertices()[i].x),
                             static_cast<float>(body.shape.polygon.Vertices()[i].y)};
            }
            const b2Hull hull = b2ComputeHull(points, count);
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
        // After the mass is known: the velocity of the centre of mass, as satviz's.
        if (body.dynamic)
        {
            b2Body_SetLinearVelocity(id, {static_cast<float>(body.velocity.x), static_cast<float>(body.velocity.y)});
            b2Body_SetAngularVelocity(id, static_cast<float>(body.angularVelocity));
        }
        impl->bodies.push_back(id);
        impl->dynamic.push_back(body.dynamic);
    }
}

Box2DV3World::~Box2DV3World()
{
    b2DestroyWorld(impl->world);
}

void Box2DV3World::Step()
{
    b2World_Step(impl->world, static_cast<float>(impl->settings.dt), impl->settings.subSteps);
}

int Box2DV3World::AwakeBodies() const
{
    int awake = 0;
    for (size_t i = 0; i < impl->bodies.size(); ++i)
    {
        awake += impl->dynamic[i] && b2Body_IsAwake(impl->bodies[i]) ? 1 : 0;
    }
    return awake;
}

void Box2DV3World::Transforms(std::vector<Transform>& xfs) const
{
    xfs.resize(impl->bodies.size());
    for (size_t i = 0; i < impl->bodies.size(); ++i)
    {
        const b2WorldTransform xf = b2Body_GetTransform(impl->bodies[i]);
        xfs[i].p = {xf.p.x, xf.p.y};
        xfs[i].q.c = xf.q.c;
        xfs[i].q.s = xf.q.s;
    }
}

double Box2DV3World::KineticEnergy() const
{
    double k = 0.0;
    for (size_t i = 0; i < impl->bodies.size(); ++i)
    {
        if (!impl->dynamic[i])
        {
            continue;
        }
        const b2BodyId id = impl->bodies[i];
        const double mass = b2Body_GetMass(id);
        const double inertia = b2Body_GetRotationalInertia(id); // about the centre of mass
        const b2Vec2 v = b2Body_GetLinearVelocity(id);
        const double w = b2Body_GetAngularVelocity(id);
        k += 0.5 * mass * (static_cast<double>(v.x) * v.x + static_cast<double>(v.y) * v.y) + 0.5 * inertia * w * w;
    }
    return k;
}

double Box2DV3World::PotentialEnergy() const
{
    double potential = 0.0;
    for (size_t i = 0; i < impl->bodies.size(); ++i)
    {
        if (impl->dynamic[i])
        {
            potential += b2Body_GetMass(impl->bodies[i]) * impl->settings.gravity * b2Body_GetWorldCenter(impl->bodies[i]).y;
        }
    }
    return potential;
}

double Box2DV3World::TotalMass() const
{
    double mass = 0.0;
    for (size_t i = 0; i < impl->bodies.size(); ++i)
    {
        mass += impl->dynamic[i] ? b2Body_GetMass(impl->bodies[i]) : 0.0;
    }
    return mass;
}

std::vector<std::pair<std::string, double>> Box2DV3World::LastStepProfile() const
{
    // b2Profile is a run of floats, each a stage's ms in the last step, in this order.
    constexpr int kFields = static_cast<int>(sizeof(b2Profile) / sizeof(float));
    static const char* const kNames[kFields] = {
        "step",          "pairs",        "collide",    "solve",         "solverSetup",        "constraints",
        "prepareConstraints", "integrateVelocities", "warmStart", "solveImpulses", "integratePositions",
        "relaxImpulses", "applyRestitution", "storeImpulses", "splitIslands", "transforms", "sensorHits",
        "jointEvents",   "hitEvents",    "refit",      "bullets",       "sleepIslands",       "sensors"};
    const b2Profile profile = b2World_GetProfile(impl->world);
    const float* fields = reinterpret_cast<const float*>(&profile);
    std::vector<std::pair<std::string, double>> stages;
    for (int i = 0; i < kFields; ++i)
    {
        stages.emplace_back(kNames[i], fields[i]);
    }
    return stages;
}

#else

bool HaveBox2DV3()
{
    return false;
}

std::string Box2DV3Version()
{
    return "";
}

struct Box2DV3World::Impl
{
};

Box2DV3World::Box2DV3World(const std::vector<V3Body>&, const V3Settings&)
{
    throw std::logic_error("this build has no Box2D v3 (configure with -DSATVIZ_BOX2D_V3_ROOT=PREFIX)");
}

Box2DV3World::~Box2DV3World() = default;

void Box2DV3World::Step() {}

int Box2DV3World::AwakeBodies() const
{
    return 0;
}

void Box2DV3World::Transforms(std::vector<Transform>&) const {}

double Box2DV3World::KineticEnergy() const
{
    return 0.0;
}

double Box2DV3World::PotentialEnergy() const
{
    return 0.0;
}

double Box2DV3World::TotalMass() const
{
    return 0.0;
}

std::vector<std::pair<std::string, double>> Box2DV3World::LastStepProfile() const
{
    return {};
}

#endif

} // namespace satviz::bench
