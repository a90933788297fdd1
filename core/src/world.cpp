// SPDX-License-Identifier: MIT
// satviz: the rigid-body world: bodies, the step, and what it counts.

#include "stepper.h"

#include <satviz/collide.h>
#include <satviz/world.h>

#include <cmath>

namespace satviz
{

namespace
{

bool FiniteNumber(double x)
{
    return std::isfinite(x);
}

} // namespace

std::string ValidateBodyDef(const BodyDef& def)
{
    if (!def.concave.parts.empty())
    {
        for (const ConcavePart& part : def.concave.parts)
        {
            if (part.shape.type != ShapeType::Polygon || part.shape.polygon.Count() < 3 ||
                part.internal.size() != static_cast<size_t>(part.shape.polygon.Count()))
            {
                return "shape: each piece of a concave body must be a polygon of at least 3 vertices, with a flag "
                       "per edge";
            }
        }
    }
    else if (def.shape.type == ShapeType::Polygon)
    {
        if (def.shape.polygon.Count() < 3)
        {
            return "shape: a polygon needs at least 3 vertices";
        }
    }
    else if (!(def.shape.circle.radius > 0.0) || !FiniteNumber(def.shape.circle.radius) ||
             !IsFinite(def.shape.circle.center))
    {
        return "shape: a circle needs a finite radius > 0";
    }
    if (!IsFinite(def.position) || !FiniteNumber(def.angle))
    {
        return "position and angle must be finite";
    }
    if (!IsFinite(def.velocity))
    {
        return "velocity must be finite";
    }
    if (!FiniteNumber(def.angularVelocity))
    {
        return "angular_velocity must be finite";
    }
    if (def.type == BodyType::Dynamic && !(def.density > 0.0 && FiniteNumber(def.density)))
    {
        return "density must be finite and > 0 on a dynamic body";
    }
    if (!(def.material.restitution >= 0.0 && def.material.restitution <= 1.0))
    {
        return "restitution must be in [0, 1]";
    }
    if (!(def.material.friction >= 0.0 && FiniteNumber(def.material.friction)))
    {
        return "friction must be finite and >= 0";
    }
    if (!(def.material.staticFriction >= 0.0 && FiniteNumber(def.material.staticFriction)))
    {
        return "static_friction must be finite and >= 0";
    }
    return {};
}

int AddBody(World& world, const BodyDef& def)
{
    RigidBody body;
    const bool concave = !def.concave.parts.empty();
    if (concave)
    {
        body.concave = def.concave;
        std::vector<Vec2> points;
        for (const ConcavePart& part : def.concave.parts)
        {
            const Vec2Span<double> vertices = part.shape.polygon.Vertices();
            points.insert(points.end(), vertices.begin(), vertices.end());
        }
        body.shape = MakeShape(ComputeHull(points).polygon);
    }
    else
    {
        body.shape = def.shape;
    }
    body.type = def.type;
    body.material = def.material;
    body.position = def.position;
    body.angle = def.angle;
    const MassProperties mass = concave ? ComputeMass(def.concave, 1.0) : ComputeMass(def.shape, 1.0);
    body.localCenter = mass.center;
    if (def.type == BodyType::Dynamic)
    {
        body.mass = def.density * mass.mass;
        body.inertia = def.density * mass.inertia;
        body.invMass = body.mass > 0.0 ? 1.0 / body.mass : 0.0;
        body.invInertia = body.inertia > 0.0 ? 1.0 / body.inertia : 0.0;
        body.velocity = def.velocity;
        body.angularVelocity = def.angularVelocity;
    }
    if (concave)
    {
        body.innerRadius = InnerRadius(def.concave);
        body.outerRadius = OuterRadius(def.concave, mass.center);
        body.turnRadius = body.outerRadius;
    }
    else
    {
        body.innerRadius = InnerRadius(def.shape, mass.center);
        body.outerRadius = OuterRadius(def.shape, mass.center);
        body.turnRadius = TurnRadius(def.shape, mass.center);
    }
    world.bodies.push_back(std::move(body));
    world.broadphase.order.clear();
    return static_cast<int>(world.bodies.size()) - 1;
}

double KineticEnergy(const World& world)
{
    double energy = 0.0;
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            energy += 0.5 * body.mass * LengthSquared(body.velocity) +
                      0.5 * body.inertia * body.angularVelocity * body.angularVelocity;
        }
    }
    return energy;
}

Vec2 LinearMomentum(const World& world)
{
    Vec2 p{};
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            p = p + body.mass * body.velocity;
        }
    }
    return p;
}

double AngularMomentum(const World& world, Vec2 origin)
{
    double l = 0.0;
    for (const RigidBody& body : world.bodies)
    {
        if (body.type == BodyType::Dynamic)
        {
            l += body.inertia * body.angularVelocity + Cross(body.WorldCenter() - origin, body.mass * body.velocity);
        }
    }
    return l;
}

std::vector<std::pair<int, int>> TouchingPairs(const std::vector<Shape>& shapes, const std::vector<Transform>& xfs)
{
    std::vector<Aabb> boxes(shapes.size());
    for (size_t i = 0; i < shapes.size(); ++i)
    {
        boxes[i] = ComputeAabb(shapes[i], xfs[i]);
    }
    SortAndSweep sweep;
    std::vector<std::pair<int, int>> candidates;
    FindPairs(sweep, boxes, candidates);
    std::vector<std::pair<int, int>> touching;
    for (const auto& [i, j] : candidates)
    {
        if (Overlap(shapes[i], xfs[i], shapes[j], xfs[j]))
        {
            touching.emplace_back(i, j);
        }
    }
    return touching;
}

namespace detail
{

StepMemory& MemoryOf(World& world)
{
    std::unique_ptr<StepMemory, void (*)(StepMemory*)>& memory = world.stepMemory.memory;
    if (memory == nullptr)
    {
        memory = std::unique_ptr<StepMemory, void (*)(StepMemory*)>(new StepMemory, [](StepMemory* m) { delete m; });
    }
    return *memory;
}

} // namespace detail

void Step(World& world, double dt)
{
    world.counts = StepCounts();
    if (world.trace != nullptr)
    {
        world.trace->Clear();
    }
    if (world.stepTrace != nullptr)
    {
        world.stepTrace->Clear();
    }
    detail::Stepper stepper(world, dt);
    stepper.FindContacts();
    stepper.SolveVelocities();
    stepper.StoreImpulses();
    stepper.Move();
    if (!world.settings.softStep)
    {
        stepper.CorrectPositions();
    }
    stepper.Sleep();
    world.time += dt;
}

} // namespace satviz
