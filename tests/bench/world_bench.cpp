// SPDX-License-Identifier: MIT
// satviz-bench --world: milliseconds per step of satviz's rigid-body world, and of Box2D 2.4.1's b2World on the
// same scenes in the same process; what each saving of the world saves; penetration and energy drift of both.
//
// Scenes: n dynamic bodies of mixed shapes, a third each boxes (aspect 1:2 to 2:1), circles and random convex
// polygons of 3 to 8 vertices, each held by a circle of diameter 0.5 to 1 about its origin; density 1, friction 0.6
// (static and dynamic), restitution 0.1; gravity (0, -10), dt 1/60; each engine with its default passes (satviz:
// 10 velocity and 5 position passes; Box2D: b2World::Step(dt, 8, 3), the iterations its manual recommends). Three
// static bodies: a wide ground box and two walls; the container is as wide as a square grid of the bodies at a pitch
// of 1.2.
//  pile: the bodies start at rest in that grid just above the ground, fall and settle;
//  rain: the same grid stretched upwards so that the top row lands at 70% of the run (245 units high for 600 steps),
//        the rows jittered, each body with a small random velocity and spin: bodies land one row after another on
//        what has landed before, at up to 70 units per second.
// Box2D gets the same shapes (b2PolygonShape::Set on the same vertices, with its default skin b2_polygonRadius;
// b2CircleShape), the same positions, angles and centre-of-mass velocities, and satviz's restitution threshold
// (0.5; Box2D's default is 1). Its bodies are not bullets, so only static contacts get its continuous collision.
//
// Method: per scene and size, one untimed run of each engine measures the quality at the end of every step; then
// `rounds` timed rounds run the scene from its start in each configuration, satviz and Box2D one right after the
// other (their order alternates between rounds), then satviz with each saving off. Each step is timed by the
// thread's processor time (CLOCK_THREAD_CPUTIME_ID), which does not count the time the thread waits while other
// processes run on a shared machine, and by the wall clock. A run's figure is its mean time per step over the whole
// run and over its last quarter (the settled tail); a configuration's figure is the median over the rounds, and a
// ratio is the median over the rounds of the ratio of two runs of one round. Both engines are deterministic: every
// run of a scene in one configuration takes the same steps.
//
// Quality, measured alike for both engines: after every step, every pair of the scene whose shapes overlap, found
// by satviz's TouchingPairs, and its depth by satviz's Collide in double on the positions the engine left (Box2D's
// shapes without their skin: the overlap of the shapes as drawn). Beside it the penetration of each engine's own
// contacts at the end of the step, against the surfaces the engine collides: satviz's are its shapes as drawn;
// Box2D's b2WorldManifold separations are taken to its skinned shapes (the polygons grown by b2_polygonRadius =
// 0.01), which keep resting polygons apart by up to 0.02 as drawn (the gap, also printed). Energy: E = kinetic +
// potential (m g y of each centre of mass),
// which gravity and inelastic, frictional contacts can only lower; its largest rise over the run (the most E gained
// between any two moments, E(t2) - E(t1) with t1 < t2), also as the height by which that energy would lift the
// whole mass, and the kinetic energy's largest rise within the settled tail.

#include "world_bench.h"

#include "box2d_v3.h"

#include "support/random_shapes.h"

#include <satviz/collide.h>
#include <satviz/scene.h>
#include <satviz/scene_world.h>
#include <satviz/tasks.h>
#include <satviz/world.h>

#ifdef SATVIZ_HAVE_BOX2D
#include <box2d/box2d.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <time.h>
#include <unordered_map>
#include <vector>

namespace satviz::bench
{
namespace
{

using testing::Rng;

constexpr double kDt = 1.0 / 60.0;
constexpr double kGravity = 10.0;
constexpr double kDensity = 1.0;
constexpr double kFriction = 0.6;
constexpr double kRestitution = 0.1;
constexpr double kPitch = 1.2; // grid pitch: every body lies within 0.5 of its origin
constexpr double kRainLanding = 0.7;

// The configurations of a scene, in the order of the tables.
enum Config
{
    kSatviz,
    kBox2D,
    kNoBroadphase,
    kStaticPairsTested,
    kEveryBodySwept,
    kNoSleeping,
    kConfigs
};

const char* const kConfigNames[kConfigs] = {"satviz",
                                            "box2d",
                                            "satviz, broadphase off",
                                            "satviz, static pairs tested",
                                            "satviz, every moving body swept",
                                            "satviz, no sleeping"};

bool IsSatviz(int config)
{
    return config != kBox2D;
}

// The configurations timed in the first round only and up to kWorldCostlyLimit bodies.
bool IsCostly(int config)
{
    return config == kNoBroadphase || config == kEveryBodySwept;
}

/// One body of a scene, as both engines get it.
struct SceneBody
{
    Shape shape;
    bool dynamic = true;
    Vec2 position{};
    double angle = 0.0;
    Vec2 velocity{}; // of the centre of mass
    double angularVelocity = 0.0;
};

struct Scene
{
    std::string name;
    std::vector<SceneBody> bodies; // the static ones first
    int dynamicCount = 0;
};

#ifdef SATVIZ_HAVE_BOX2D
// The polygon as Box2D builds it from the same vertices (its hull, its own centroid, its skin).
b2PolygonShape ToBox2D(const Polygon& polygon)
{
    b2Vec2 points[b2_maxPolygonVertices];
    for (int i = 0; i < polygon.Count(); ++i)
    {
        points[i].Set(static_cast<float>(polygon.Vertices()[i].x), static_cast<float>(polygon.Vertices()[i].y));
    }
    b2PolygonShape shape;
    shape.Set(points, polygon.Count());
    return shape;
}
#endif

// True when Box2D keeps every vertex of the shape (its Set welds vertices closer than half its linear slop).
bool Box2DKeepsShape([[maybe_unused]] const Shape& shape)
{
#ifdef SATVIZ_HAVE_BOX2D
    return shape.type != ShapeType::Polygon ||
           (shape.polygon.Count() <= b2_maxPolygonVertices && ToBox2D(shape.polygon).m_count == shape.polygon.Count());
#else
    return true;
#endif
}

// A box, a circle or a random convex polygon of 3 to 8 vertices, within a circle of diameter 0.5 to 1 about the
// body origin.
Shape RandomBodyShape(Rng& rng)
{
    for (;;)
    {
        const double radius = 0.5 * rng.Uniform(0.5, 1.0);
        Shape shape;
        switch (rng.Int(0, 2))
        {
        case 0:
        {
            const double diagonal = rng.Uniform(std::atan(0.5), std::atan(2.0)); // aspect 1:2 to 2:1
            shape = MakeShape(MakeBox(radius * std::cos(diagonal), radius * std::sin(diagonal)).polygon);
            break;
        }
        case 1:
        {
            Circle circle;
            circle.radius = radius;
            shape = MakeShape(circle);
            break;
        }
        default:
            shape = MakeShape(testing::RandomPolygon(rng, rng.Int(3, 8), radius, rng.Uniform(0.6, 1.0)));
            break;
        }
        if (Box2DKeepsShape(shape))
        {
            return shape;
        }
    }
}

SceneBody StaticBox(double halfWidth, double halfHeight, Vec2 position)
{
    SceneBody body;
    body.shape = MakeShape(MakeBox(halfWidth, halfHeight).polygon);
    body.dynamic = false;
    body.position = position;
    return body;
}

Scene MakeScene(bool rain, int n, int steps, uint64_t seed)
{
    Rng rng(seed + static_cast<uint64_t>(n) * 2 + (rain ? 1 : 0));
    Scene scene;
    scene.name = rain ? "rain" : "pile";
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    const int rows = (n + columns - 1) / columns;
    const double width = columns * kPitch;
    double pitch = kPitch;
    if (rain)
    {
        const double fall = kRainLanding * steps * kDt;
        pitch = std::max(kPitch, 0.5 * kGravity * fall * fall / rows);
    }
    std::vector<SceneBody> dynamic;
    double top = 0.0;
    for (int k = 0; k < n; ++k)
    {
        SceneBody body;
        body.shape = RandomBodyShape(rng);
        const int column = k % columns;
        const int row = k / columns;
        body.position = {-0.5 * width + kPitch * (column + 0.5) + rng.Uniform(-0.05, 0.05),
                         0.6 + pitch * row + (rain ? rng.Uniform(0.0, pitch - kPitch) : 0.0)};
        body.angle = rng.Uniform(-testing::kPi, testing::kPi);
        if (rain)
        {
            body.velocity = {rng.Uniform(-0.5, 0.5), rng.Uniform(-2.0, 0.0)};
            body.angularVelocity = rng.Uniform(-2.0, 2.0);
        }
        top = std::max(top, body.position.y);
        dynamic.push_back(std::move(body));
    }
    const double wall = top + 2.0;
    scene.bodies.push_back(StaticBox(0.5 * width + 1.0, 0.5, {0.0, -0.5}));
    scene.bodies.push_back(StaticBox(0.5, 0.5 * wall, {-0.5 * width - 0.5, 0.5 * wall}));
    scene.bodies.push_back(StaticBox(0.5, 0.5 * wall, {0.5 * width + 0.5, 0.5 * wall}));
    for (SceneBody& body : dynamic)
    {
        scene.bodies.push_back(std::move(body));
    }
    scene.dynamicCount = n;
    return scene;
}

WorldSettings SettingsOf(int config, bool softStep)
{
    WorldSettings settings;
    settings.softStep = softStep;
    settings.gravity = {0.0, -kGravity};
    settings.broadphase = config != kNoBroadphase;
    settings.skipStaticPairs = config != kStaticPairsTested;
    settings.sweepOnlyFast = config != kEveryBodySwept;
    settings.sleeping = config != kNoSleeping;
    return settings;
}

// A body of a benchmark scene as a body of a scene file, with the benchmark's density and material: the world
// satviz steps is built from these (MakeBodyDef), and --write-scenes writes them, so both are one description.
satviz::Body FileBody(const SceneBody& from)
{
    satviz::Body body;
    body.shape = from.shape;
    body.isStatic = !from.dynamic;
    body.density = kDensity;
    body.material.restitution = kRestitution;
    body.material.friction = kFriction;
    body.material.staticFriction = kFriction;
    body.position = from.position;
    body.angle = from.angle;
    body.velocity = from.velocity;
    body.angularVelocity = from.angularVelocity;
    return body;
}

World BuildSatviz(const Scene& scene, const WorldSettings& settings)
{
    World world;
    world.settings = settings;
    world.bodies.reserve(scene.bodies.size());
    for (const SceneBody& body : scene.bodies)
    {
        AddBody(world, MakeBodyDef(FileBody(body)));
    }
    return world;
}

#ifdef SATVIZ_HAVE_BOX2D
struct Box2DScene
{
    std::unique_ptr<b2World> world;
    std::vector<b2Body*> bodies; // in the scene's order
};

Box2DScene BuildBox2D(const Scene& scene)
{
    Box2DScene out;
    out.world = std::make_unique<b2World>(b2Vec2(0.0f, static_cast<float>(-kGravity)));
    const float threshold = static_cast<float>(WorldSettings{}.restitutionThreshold);
    for (const SceneBody& body : scene.bodies)
    {
        b2BodyDef def;
        def.type = body.dynamic ? b2_dynamicBody : b2_staticBody;
        def.position.Set(static_cast<float>(body.position.x), static_cast<float>(body.position.y));
        def.angle = static_cast<float>(body.angle);
        b2Body* b = out.world->CreateBody(&def);
        b2FixtureDef fixture;
        fixture.density = static_cast<float>(kDensity);
        fixture.friction = static_cast<float>(kFriction);
        fixture.restitution = static_cast<float>(kRestitution);
        fixture.restitutionThreshold = threshold;
        b2PolygonShape polygon;
        b2CircleShape circle;
        if (body.shape.type == ShapeType::Polygon)
        {
            polygon = ToBox2D(body.shape.polygon);
            fixture.shape = &polygon;
        }
        else
        {
            circle.m_p.Set(static_cast<float>(body.shape.circle.center.x),
                           static_cast<float>(body.shape.circle.center.y));
            circle.m_radius = static_cast<float>(body.shape.circle.radius);
            fixture.shape = &circle;
        }
        b->CreateFixture(&fixture);
        // After the mass is known: Box2D's velocity is its centre of mass's, as satviz's (a body definition's
        // velocity would be taken at the body origin and moved to the centre by the spin).
        if (body.dynamic)
        {
            b->SetLinearVelocity(b2Vec2(static_cast<float>(body.velocity.x), static_cast<float>(body.velocity.y)));
            b->SetAngularVelocity(static_cast<float>(body.angularVelocity));
        }
        out.bodies.push_back(b);
    }
    return out;
}

void StepBox2D(Box2DScene& scene)
{
    scene.world->Step(static_cast<float>(kDt), 8, 3);
}

int AwakeBodies(const Box2DScene& scene)
{
    int awake = 0;
    for (const b2Body* body : scene.bodies)
    {
        awake += body->GetType() == b2_dynamicBody && body->IsAwake() ? 1 : 0;
    }
    return awake;
}
#endif

using Clock = std::chrono::steady_clock;

// The thread's processor time in milliseconds: unlike the wall clock, it does not count the time the thread waits
// while other processes run on a shared machine.
double ThreadMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// The milliseconds of each step of one run (processor time of the thread, and wall clock), and what the world
// reported it did (satviz only).
struct TimedRun
{
    std::vector<double> ms;
    std::vector<double> wallMs;
    double tested = 0.0;   // pairs given to the narrowphase, per step
    double swept = 0.0;    // pairs swept for a time of impact, per step
    double compared = 0.0; // broadphase box comparisons, per step
    double hits = 0.0;     // time-ordered hits resolved, per step
    int awakeEnd = 0;
};

int TailStart(int steps)
{
    return steps - std::max(1, steps / 4);
}

double MeanMs(const std::vector<double>& ms, int from)
{
    double sum = 0.0;
    for (size_t i = static_cast<size_t>(from); i < ms.size(); ++i)
    {
        sum += ms[i];
    }
    return sum / static_cast<double>(ms.size() - static_cast<size_t>(from));
}

// threads: what satviz's world steps on; above 1, its ms are the wall clock's (see WorldBenchSettings::threads).
TimedRun TimeRun(const Scene& scene, int config, int steps, int threads, bool softStep)
{
    TimedRun run;
    run.ms.resize(static_cast<size_t>(steps));
    run.wallMs.resize(static_cast<size_t>(steps));
    if (IsSatviz(config))
    {
        World world = BuildSatviz(scene, SettingsOf(config, softStep));
        ThreadPool pool(threads);
        world.tasks = PoolTasks(pool);
        for (int i = 0; i < steps; ++i)
        {
            const Clock::time_point start = Clock::now();
            const double cpu = ThreadMs();
            Step(world, kDt);
            run.ms[static_cast<size_t>(i)] = ThreadMs() - cpu;
            run.wallMs[static_cast<size_t>(i)] =
                std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            if (threads > 1)
            {
                run.ms[static_cast<size_t>(i)] = run.wallMs[static_cast<size_t>(i)];
            }
            run.tested += static_cast<double>(world.counts.tested);
            run.swept += static_cast<double>(world.counts.swept);
            run.compared += static_cast<double>(world.counts.broadphaseComparisons);
            run.hits += static_cast<double>(world.counts.hits);
        }
        run.tested /= steps;
        run.swept /= steps;
        run.compared /= steps;
        run.hits /= steps;
        run.awakeEnd = world.counts.awakeBodies;
        return run;
    }
#ifdef SATVIZ_HAVE_BOX2D
    Box2DScene world = BuildBox2D(scene);
    for (int i = 0; i < steps; ++i)
    {
        const Clock::time_point start = Clock::now();
        const double cpu = ThreadMs();
        StepBox2D(world);
        run.ms[static_cast<size_t>(i)] = ThreadMs() - cpu;
        run.wallMs[static_cast<size_t>(i)] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    run.awakeEnd = AwakeBodies(world);
#endif
    return run;
}

// Box2D v3's bodies for a scene.
std::vector<V3Body> ToV3Bodies(const Scene& scene)
{
    std::vector<V3Body> bodies;
    for (const SceneBody& body : scene.bodies)
    {
        V3Body b;
        b.shape = body.shape;
        b.dynamic = body.dynamic;
        b.position = body.position;
        b.angle = body.angle;
        b.velocity = body.velocity;
        b.angularVelocity = body.angularVelocity;
        bodies.push_back(b);
    }
    return bodies;
}

V3Settings V3SettingsOf(int workers)
{
    V3Settings settings;
    settings.density = kDensity;
    settings.friction = kFriction;
    settings.restitution = kRestitution;
    settings.restitutionThreshold = WorldSettings{}.restitutionThreshold;
    settings.gravity = kGravity;
    settings.dt = kDt;
    settings.workers = workers;
    return settings;
}

// A run of Box2D v3 with `workers` threads of its own scheduler: ms is the calling thread's processor time (with
// more than one worker, the others' time is not in it: compare by the wall clock then).
TimedRun TimeBox2DV3(const Scene& scene, int workers, int steps)
{
    TimedRun run;
    run.ms.resize(static_cast<size_t>(steps));
    run.wallMs.resize(static_cast<size_t>(steps));
    Box2DV3World world(ToV3Bodies(scene), V3SettingsOf(workers));
    for (int i = 0; i < steps; ++i)
    {
        const Clock::time_point start = Clock::now();
        const double cpu = ThreadMs();
        world.Step();
        run.ms[static_cast<size_t>(i)] = ThreadMs() - cpu;
        run.wallMs[static_cast<size_t>(i)] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    run.awakeEnd = world.AwakeBodies();
    return run;
}

// What one step's end looked like.
struct StepQuality
{
    double maxDepth = 0.0; // deepest overlap of two shapes (the referee)
    double sumDepth = 0.0;
    int64_t overlapping = 0; // pairs whose shapes overlap
    double ownMax = 0.0;     // the engine's own deepest contact, at the end of the step
    double ownSum = 0.0;
    int64_t ownCount = 0; // the engine's touching contacts
    double gapSum = 0.0;  // drawn shapes' gap of the touching contacts whose shapes as drawn do not overlap
};

// The depth of the overlap of two shapes as drawn (0 when apart), and the gap between them (0 when they overlap;
// a separated pair's gap is the separating axis's, which is at most their distance).
void DrawnDepthAndGap(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, double& depth,
                      double& gap)
{
    const Manifold m = Collide(a, xfA, b, xfB);
    depth = m.overlap ? m.depth : 0.0;
    gap = m.overlap ? 0.0 : m.gap;
}

// The referee: every pair with a dynamic body whose shapes overlap, and its depth, by satviz's Collide in double.
void Referee(const std::vector<Shape>& shapes, const std::vector<bool>& dynamic, const std::vector<Transform>& xfs,
             StepQuality& q)
{
    for (const auto& [i, j] : TouchingPairs(shapes, xfs))
    {
        const size_t a = static_cast<size_t>(i);
        const size_t b = static_cast<size_t>(j);
        if (!dynamic[a] && !dynamic[b])
        {
            continue;
        }
        const Manifold m = Collide(shapes[a], xfs[a], shapes[b], xfs[b]);
        if (m.overlap)
        {
            q.maxDepth = std::max(q.maxDepth, m.depth);
            q.sumDepth += m.depth;
            ++q.overlapping;
        }
    }
}

/// The largest rise of a series: max over t1 < t2 of v[t2] - v[t1], within [from, end).
double MaxRise(const std::vector<double>& v, size_t from)
{
    double lowest = v[from];
    double rise = 0.0;
    for (size_t i = from; i < v.size(); ++i)
    {
        lowest = std::min(lowest, v[i]);
        rise = std::max(rise, v[i] - lowest);
    }
    return rise;
}

// The quality of one engine on one scene.
struct Quality
{
    bool measured = false;
    double maxDepth = 0.0, meanDepth = 0.0, tailMaxDepth = 0.0, tailMeanDepth = 0.0, pairsPerStep = 0.0;
    double ownMax = 0.0, ownMean = 0.0, ownTailMax = 0.0, ownTailMean = 0.0, gapMean = 0.0;
    double totalMass = 0.0;
    double energyRise = 0.0, energyRiseTail = 0.0, kineticTailRise = 0.0, kineticTailMax = 0.0, kineticEnd = 0.0;
    double energyStart = 0.0, energyEnd = 0.0;
    int awakeEnd = 0;
};

// Summarises a run's per-step measures: steps[0] is the start (energies only), steps[i] the end of step i.
Quality Summarise(const std::vector<StepQuality>& q, const std::vector<double>& kinetic,
                  const std::vector<double>& energy, double totalMass, int awakeEnd)
{
    Quality out;
    out.measured = true;
    out.totalMass = totalMass;
    out.awakeEnd = awakeEnd;
    const int steps = static_cast<int>(q.size()) - 1;
    const int tail = TailStart(steps) + 1; // the first measure of the tail: the end of its first step
    double sum = 0.0, tailSum = 0.0, ownSum = 0.0, ownTailSum = 0.0, gapSum = 0.0;
    int64_t count = 0, tailCount = 0, ownCount = 0, ownTailCount = 0;
    for (int i = 1; i <= steps; ++i)
    {
        const StepQuality& s = q[static_cast<size_t>(i)];
        out.maxDepth = std::max(out.maxDepth, s.maxDepth);
        out.ownMax = std::max(out.ownMax, s.ownMax);
        sum += s.sumDepth;
        count += s.overlapping;
        ownSum += s.ownSum;
        ownCount += s.ownCount;
        gapSum += s.gapSum;
        if (i >= tail)
        {
            out.tailMaxDepth = std::max(out.tailMaxDepth, s.maxDepth);
            tailSum += s.sumDepth;
            tailCount += s.overlapping;
            out.ownTailMax = std::max(out.ownTailMax, s.ownMax);
            ownTailSum += s.ownSum;
            ownTailCount += s.ownCount;
        }
    }
    out.meanDepth = count > 0 ? sum / static_cast<double>(count) : 0.0;
    out.tailMeanDepth = tailCount > 0 ? tailSum / static_cast<double>(tailCount) : 0.0;
    out.ownMean = ownCount > 0 ? ownSum / static_cast<double>(ownCount) : 0.0;
    out.ownTailMean = ownTailCount > 0 ? ownTailSum / static_cast<double>(ownTailCount) : 0.0;
    out.gapMean = ownCount > 0 ? gapSum / static_cast<double>(ownCount) : 0.0;
    out.pairsPerStep = static_cast<double>(count) / steps;
    out.energyRise = MaxRise(energy, 0);
    out.energyRiseTail = MaxRise(energy, static_cast<size_t>(tail - 1));
    out.kineticTailRise = MaxRise(kinetic, static_cast<size_t>(tail - 1));
    out.kineticTailMax = *std::max_element(kinetic.begin() + (tail - 1), kinetic.end());
    out.kineticEnd = kinetic.back();
    out.energyStart = energy.front();
    out.energyEnd = energy.back();
    return out;
}

Quality MeasureSatviz(const Scene& scene, int steps, bool softStep)
{
    World world = BuildSatviz(scene, SettingsOf(kSatviz, softStep));
    std::vector<Shape> shapes;
    std::vector<bool> dynamic;
    double totalMass = 0.0;
    for (const RigidBody& body : world.bodies)
    {
        shapes.push_back(body.shape);
        dynamic.push_back(body.type == BodyType::Dynamic);
        totalMass += body.mass;
    }
    std::vector<Transform> xfs(shapes.size());
    std::vector<StepQuality> q(static_cast<size_t>(steps) + 1);
    std::vector<double> kinetic, energy;
    const auto measureEnergy = [&] {
        double potential = 0.0;
        for (const RigidBody& body : world.bodies)
        {
            potential += body.mass * kGravity * body.WorldCenter().y;
        }
        const double k = KineticEnergy(world);
        kinetic.push_back(k);
        energy.push_back(k + potential);
    };
    measureEnergy();
    for (int i = 1; i <= steps; ++i)
    {
        Step(world, kDt);
        measureEnergy();
        StepQuality& s = q[static_cast<size_t>(i)];
        for (size_t b = 0; b < world.bodies.size(); ++b)
        {
            xfs[b] = world.bodies[b].Xf();
        }
        Referee(shapes, dynamic, xfs, s);
        // satviz's surfaces are its shapes as drawn: the depth at the end of the step.
        for (const WorldContact& c : world.contacts)
        {
            // Speculative contacts of pairs still apart at the start of the step are not touching contacts.
            if (c.points[0].separation > 0.0 && (c.pointCount < 2 || c.points[1].separation > 0.0))
            {
                continue;
            }
            double deepest = 0.0, gap = 0.0;
            DrawnDepthAndGap(shapes[static_cast<size_t>(c.a)], xfs[static_cast<size_t>(c.a)],
                             shapes[static_cast<size_t>(c.b)], xfs[static_cast<size_t>(c.b)], deepest, gap);
            s.ownMax = std::max(s.ownMax, deepest);
            s.ownSum += deepest;
            s.gapSum += gap;
            ++s.ownCount;
        }
    }
    return Summarise(q, kinetic, energy, totalMass, world.counts.awakeBodies);
}

#ifdef SATVIZ_HAVE_BOX2D
Quality MeasureBox2D(const Scene& scene, int steps)
{
    Box2DScene world = BuildBox2D(scene);
    std::vector<Shape> shapes;
    std::vector<bool> dynamic;
    double totalMass = 0.0;
    for (size_t b = 0; b < scene.bodies.size(); ++b)
    {
        shapes.push_back(scene.bodies[b].shape);
        dynamic.push_back(scene.bodies[b].dynamic);
        totalMass += world.bodies[b]->GetMass();
    }
    std::unordered_map<const b2Body*, size_t> index;
    for (size_t b = 0; b < world.bodies.size(); ++b)
    {
        index[world.bodies[b]] = b;
    }
    std::vector<Transform> xfs(shapes.size());
    std::vector<StepQuality> q(static_cast<size_t>(steps) + 1);
    std::vector<double> kinetic, energy;
    const auto measureEnergy = [&] {
        double k = 0.0, potential = 0.0;
        for (const b2Body* body : world.bodies)
        {
            if (body->GetType() != b2_dynamicBody)
            {
                continue;
            }
            const double mass = body->GetMass();
            const b2Vec2 v = body->GetLinearVelocity();
            const b2Vec2 c = body->GetLocalCenter();
            // GetInertia is about the body origin; the centre's is less by m |c|^2.
            const double inertia =
                body->GetInertia() - mass * (static_cast<double>(c.x) * c.x + static_cast<double>(c.y) * c.y);
            const double w = body->GetAngularVelocity();
            k += 0.5 * mass * (static_cast<double>(v.x) * v.x + static_cast<double>(v.y) * v.y) + 0.5 * inertia * w * w;
            potential += mass * kGravity * body->GetWorldCenter().y;
        }
        kinetic.push_back(k);
        energy.push_back(k + potential);
    };
    measureEnergy();
    for (int i = 1; i <= steps; ++i)
    {
        StepBox2D(world);
        measureEnergy();
        StepQuality& s = q[static_cast<size_t>(i)];
        for (size_t b = 0; b < world.bodies.size(); ++b)
        {
            const b2Transform& xf = world.bodies[b]->GetTransform();
            // The rotation as Box2D holds it (its cosine and sine, in float), not recomputed from the angle.
            xfs[b].p = {xf.p.x, xf.p.y};
            xfs[b].q.c = xf.q.c;
            xfs[b].q.s = xf.q.s;
        }
        Referee(shapes, dynamic, xfs, s);
        for (b2Contact* c = world.world->GetContactList(); c != nullptr; c = c->GetNext())
        {
            if (!c->IsTouching())
            {
                continue;
            }
            b2WorldManifold manifold;
            c->GetWorldManifold(&manifold);
            double deepest = 0.0;
            for (int p = 0; p < c->GetManifold()->pointCount; ++p)
            {
                deepest = std::max(deepest, -static_cast<double>(manifold.separations[p]));
            }
            s.ownMax = std::max(s.ownMax, deepest);
            s.ownSum += deepest;
            double drawnDepth = 0.0, gap = 0.0;
            const size_t a = index.at(c->GetFixtureA()->GetBody());
            const size_t b = index.at(c->GetFixtureB()->GetBody());
            DrawnDepthAndGap(shapes[a], xfs[a], shapes[b], xfs[b], drawnDepth, gap);
            s.gapSum += gap;
            ++s.ownCount;
        }
    }
    return Summarise(q, kinetic, energy, totalMass, AwakeBodies(world));
}
#endif

// Box2D v3's quality, measured as the others' by the referee (its own contacts are not read: the penetration
// figures compared with it are the referee's).
Quality MeasureBox2DV3(const Scene& scene, int steps)
{
    Box2DV3World world(ToV3Bodies(scene), V3SettingsOf(1));
    std::vector<Shape> shapes;
    std::vector<bool> dynamic;
    for (const SceneBody& body : scene.bodies)
    {
        shapes.push_back(body.shape);
        dynamic.push_back(body.dynamic);
    }
    std::vector<Transform> xfs;
    std::vector<StepQuality> q(static_cast<size_t>(steps) + 1);
    std::vector<double> kinetic, energy;
    const auto measureEnergy = [&] {
        const double k = world.KineticEnergy();
        kinetic.push_back(k);
        energy.push_back(k + world.PotentialEnergy());
    };
    measureEnergy();
    for (int i = 1; i <= steps; ++i)
    {
        world.Step();
        measureEnergy();
        world.Transforms(xfs);
        Referee(shapes, dynamic, xfs, q[static_cast<size_t>(i)]);
    }
    return Summarise(q, kinetic, energy, world.TotalMass(), world.AwakeBodies());
}

double Median(std::vector<double> v)
{
    if (v.empty())
    {
        return 0.0;
    }
    std::sort(v.begin(), v.end());
    const size_t h = v.size() / 2;
    return v.size() % 2 == 1 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

// The figures of one configuration on one scene.
struct ConfigResult
{
    bool run = false;
    std::vector<double> ms, tailMs, wallMs;          // per round
    std::vector<double> ratio, tailRatio, wallRatio; // per round: to Box2D (satviz) or to satviz (savings off)
    double tested = 0.0, swept = 0.0, compared = 0.0, hits = 0.0;
    int awakeEnd = 0;
};

struct SceneResult
{
    std::string scene;
    int bodies = 0;
    ConfigResult configs[kConfigs];
    Quality quality[3];  // satviz, Box2D 2.4.1, Box2D v3
    ConfigResult v3[2];  // Box2D v3 with 1 and 2 workers; ratio: satviz's to it (by the wall clock for 2)
};

bool HaveBox2D()
{
#ifdef SATVIZ_HAVE_BOX2D
    return true;
#else
    return false;
#endif
}

SceneResult RunScene(const WorldBenchSettings& s, bool rain, int n)
{
    const Scene scene = MakeScene(rain, n, s.steps, s.seed);
    SceneResult result;
    result.scene = scene.name;
    result.bodies = n;
    std::fprintf(stderr, "satviz-bench --world: %s, %d bodies: quality run\n", scene.name.c_str(), n);
    result.quality[0] = MeasureSatviz(scene, s.steps, s.softStep);
#ifdef SATVIZ_HAVE_BOX2D
    result.quality[1] = MeasureBox2D(scene, s.steps);
#endif
    if (HaveBox2DV3())
    {
        result.quality[2] = MeasureBox2DV3(scene, s.steps);
        result.v3[0].run = result.v3[1].run = true;
    }
    std::vector<int> configs;
    for (int c = 0; c < kConfigs; ++c)
    {
        if ((c == kBox2D && !HaveBox2D()) || (IsCostly(c) && n > kWorldCostlyLimit))
        {
            continue;
        }
        configs.push_back(c);
        result.configs[c].run = true;
    }
    const int tail = TailStart(s.steps);
    for (int round = 0; round < s.rounds; ++round)
    {
        std::fprintf(stderr, "satviz-bench --world: %s, %d bodies: round %d of %d\n", scene.name.c_str(), n, round + 1,
                     s.rounds);
        // satviz and Box2D one right after the other, the order alternating; then the savings switched off.
        std::vector<int> order = configs;
        if (round % 2 == 1 && order.size() > 1 && order[1] == kBox2D)
        {
            std::swap(order[0], order[1]);
        }
        double whole[kConfigs] = {};
        double tailMs[kConfigs] = {};
        double wall[kConfigs] = {};
        for (int c : order)
        {
            if (IsCostly(c) && round > 0)
            {
                continue;
            }
            const TimedRun run = TimeRun(scene, c, s.steps, s.threads, s.softStep);
            whole[c] = MeanMs(run.ms, 0);
            tailMs[c] = MeanMs(run.ms, tail);
            wall[c] = MeanMs(run.wallMs, 0);
            ConfigResult& r = result.configs[c];
            r.ms.push_back(whole[c]);
            r.wallMs.push_back(wall[c]);
            r.tailMs.push_back(tailMs[c]);
            r.tested = run.tested;
            r.swept = run.swept;
            r.compared = run.compared;
            r.hits = run.hits;
            r.awakeEnd = run.awakeEnd;
        }
        for (int c : configs)
        {
            const int base = c == kSatviz ? kBox2D : kSatviz;
            if (c != kBox2D && result.configs[base].run && !(IsCostly(c) && round > 0))
            {
                result.configs[c].ratio.push_back(whole[c] / whole[base]);
                result.configs[c].tailRatio.push_back(tailMs[c] / tailMs[base]);
                result.configs[c].wallRatio.push_back(wall[c] / wall[base]);
            }
        }
        // Box2D v3 with one worker and with two, against this round's satviz.
        for (int w = 0; w < 2 && HaveBox2DV3(); ++w)
        {
            const TimedRun run = TimeBox2DV3(scene, w + 1, s.steps);
            ConfigResult& r = result.v3[w];
            r.ms.push_back(MeanMs(run.ms, 0));
            r.wallMs.push_back(MeanMs(run.wallMs, 0));
            r.tailMs.push_back(MeanMs(run.ms, tail));
            r.awakeEnd = run.awakeEnd;
            r.ratio.push_back(w == 0 ? whole[kSatviz] / r.ms.back() : wall[kSatviz] / r.wallMs.back());
            r.wallRatio.push_back(wall[kSatviz] / r.wallMs.back());
            std::fprintf(stderr, "  Box2D v3, %d worker%s: %.3f ms per step (wall %.3f)\n", w + 1, w == 0 ? "" : "s",
                         r.ms.back(), r.wallMs.back());
        }
        // The round's figures as they come, for a long run.
        std::fprintf(stderr, "  ms per step:");
        for (int c : order)
        {
            if (!(IsCostly(c) && round > 0))
            {
                std::fprintf(stderr, " %s %.3f;", kConfigNames[c], whole[c]);
            }
        }
        std::fprintf(stderr, "\n");
    }
    return result;
}

std::string Figure(const char* format, double value)
{
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

void PrintTables(const WorldBenchSettings& s, const std::vector<SceneResult>& results)
{
    const int tail = TailStart(s.steps);
    std::printf("satviz-bench --world: ms per step (processor time of the thread), %d steps of 1/60 per run (tail:\n"
                "steps %d to %d), median of %d rounds; ratios: median over the rounds of the ratio of two runs of one\n"
                "round (<1: satviz faster); wall: the same ratio by the wall clock\n",
                s.steps, tail + 1, s.steps, s.rounds);
    if (s.threads > 1)
    {
        std::printf("satviz steps on %d threads (--threads): its ms per step are the wall clock's\n", s.threads);
    }
    if (s.softStep)
    {
        std::printf("satviz steps with the soft step (--soft-step: %d sub-steps, contacts of %g Hz, damping ratio %g, "
                    "push at most %g), not its passes\n",
                    WorldSettings{}.subSteps, WorldSettings{}.contactHertz, WorldSettings{}.contactDampingRatio,
                    WorldSettings{}.maxPushSpeed);
    }
    std::printf(
        "(n dynamic bodies, a third each boxes, circles and convex 3- to 8-gons of size 0.5 to 1; density 1,\n"
        " friction 0.6, restitution 0.1; gravity 10; satviz: its defaults, %d velocity and %d position passes;\n"
        " Box2D %s: b2World::Step(dt, 8, 3), the iterations its manual recommends)\n\n",
        WorldSettings{}.velocityIterations, WorldSettings{}.positionIterations,
#ifdef SATVIZ_HAVE_BOX2D
        SATVIZ_BOX2D_VERSION
#else
        "(not in this build)"
#endif
    );
    std::printf("%-6s %6s %10s %10s %8s %11s %11s %8s %8s %14s\n", "scene", "bodies", "satviz", "box2d", "ratio",
                "satviz tail", "box2d tail", "ratio", "wall", "awake at end");
    for (const SceneResult& r : results)
    {
        const ConfigResult& a = r.configs[kSatviz];
        const ConfigResult& b = r.configs[kBox2D];
        const auto ms = [](const ConfigResult& c, const std::vector<double>& v) {
            return c.run ? Figure("%.3f", Median(v)) : std::string("-");
        };
        std::printf("%-6s %6d %10s %10s %8s %11s %11s %8s %8s %14s\n", r.scene.c_str(), r.bodies, ms(a, a.ms).c_str(),
                    ms(b, b.ms).c_str(), b.run ? Figure("%.2f", Median(a.ratio)).c_str() : "-", ms(a, a.tailMs).c_str(),
                    ms(b, b.tailMs).c_str(), b.run ? Figure("%.2f", Median(a.tailRatio)).c_str() : "-",
                    b.run ? Figure("%.2f", Median(a.wallRatio)).c_str() : "-",
                    (std::to_string(a.awakeEnd) + (b.run ? " / " + std::to_string(b.awakeEnd) : "")).c_str());
    }

    if (HaveBox2DV3())
    {
        std::printf("\nbeside Box2D v3 %s (built outside this repository; b2World_Step(dt, %d sub-steps), its own scheduler;\n"
                    "ratio 1 worker: satviz's processor time over v3's, same round; 2 workers: satviz's wall clock over\n"
                    "v3's, same round; satviz steps on %d thread%s)\n",
                    Box2DV3Version().c_str(), V3Settings{}.subSteps, s.threads, s.threads == 1 ? "" : "s");
        std::printf("%-6s %6s %10s %12s %8s %14s %8s %14s\n", "scene", "bodies", "satviz", "v3 1 worker", "ratio",
                    "v3 2 (wall)", "ratio", "awake at end");
        for (const SceneResult& r : results)
        {
            const ConfigResult& a = r.configs[kSatviz];
            std::printf("%-6s %6d %10.3f %12.3f %8.2f %14.3f %8.2f %14s\n", r.scene.c_str(), r.bodies, Median(a.ms),
                        Median(r.v3[0].ms), Median(r.v3[0].ratio), Median(r.v3[1].wallMs), Median(r.v3[1].ratio),
                        (std::to_string(a.awakeEnd) + " / " + std::to_string(r.v3[0].awakeEnd)).c_str());
        }
    }

    std::printf("\nwhat each saving saves: satviz with one switched off (ratio to satviz with all on, same round; "
                "per step:\npairs given to the narrowphase, pairs swept, time-ordered hits, broadphase box "
                "comparisons;\nbroadphase off and every moving body swept: first round only, up to %d bodies)\n",
                kWorldCostlyLimit);
    std::printf("%-6s %6s %-32s %10s %7s %11s %7s %9s %10s %8s %12s\n", "scene", "bodies", "configuration", "ms/step",
                "ratio", "tail ms", "ratio", "tested", "swept", "hits", "comparisons");
    for (const SceneResult& r : results)
    {
        for (int c : {kSatviz, kNoBroadphase, kStaticPairsTested, kEveryBodySwept, kNoSleeping})
        {
            const ConfigResult& x = r.configs[c];
            if (!x.run)
            {
                if (c == kNoBroadphase)
                {
                    std::printf("%-6s %6d %-32s %10s   (not run: O(n^2), %.2g pairs per step)\n", r.scene.c_str(),
                                r.bodies, kConfigNames[c], "-", 0.5 * (r.bodies + 3.0) * (r.bodies + 2.0));
                }
                else
                {
                    std::printf("%-6s %6d %-32s %10s   (not run: about 100 times the default's step at 1000 bodies)\n",
                                r.scene.c_str(), r.bodies, kConfigNames[c], "-");
                }
                continue;
            }
            std::printf("%-6s %6d %-32s %10.3f %7s %11.3f %7s %9.0f %10.1f %8.1f %12.0f\n", r.scene.c_str(), r.bodies,
                        kConfigNames[c], Median(x.ms), c == kSatviz ? "1" : Figure("%.2f", Median(x.ratio)).c_str(),
                        Median(x.tailMs), c == kSatviz ? "1" : Figure("%.2f", Median(x.tailRatio)).c_str(), x.tested,
                        x.swept, x.hits, x.compared);
        }
    }

    std::printf("\nquality (an untimed run of each engine, measured after every step)\n"
                "overlap: depth of the actual overlap of two shapes, every overlapping pair, by satviz Collide in\n"
                "  double on the engine's positions (Box2D's polygons without their 0.01 skin); max, mean over the\n"
                "  overlapping pairs of every step, the same over the tail, overlapping pairs per step;\n"
                "  (box2d3: Box2D v3, 1 worker; its own contacts are not read, compare the overlap columns);\n"
                "own: penetration of the engine's own contacts at the end of the step, against the surfaces it\n"
                "  collides (satviz: the shapes as drawn; Box2D: b2WorldManifold separations, to its polygons with\n"
                "  their skin); max and mean over the touching contacts of every step (0 for one not overlapping;\n"
                "  satviz's speculative contacts of pairs still apart at the start of the step are not counted),\n"
                "  the same over the tail; gap: mean gap between the shapes as drawn over the touching contacts\n"
                "  (Box2D's skin keeps resting polygons up to 0.02 apart);\n"
                "E rise: the largest gain of kinetic + potential energy between two moments of the run (whole\n"
                "  run, tail; 'height': that energy as a lift of the whole mass, E / (M g)); KE: kinetic energy\n"
                "  in the tail, largest value and largest rise; awake: dynamic bodies awake at the end\n");
    std::printf("%-6s %6s %-7s %9s %9s %9s %9s %8s %9s %9s %9s %9s %9s %10s %9s %9s %9s %9s %7s\n", "scene", "bodies",
                "engine", "ovl max", "ovl mean", "tail max", "tail mean", "pairs", "own max", "own mean", "own tmax",
                "own tmean", "gap", "E rise", "height", "tail", "KE max", "KE rise", "awake");
    for (const SceneResult& r : results)
    {
        for (int e = 0; e < 3; ++e)
        {
            const Quality& q = r.quality[e];
            if (!q.measured)
            {
                continue;
            }
            std::printf("%-6s %6d %-7s %9.2e %9.2e %9.2e %9.2e %8.0f %9.2e %9.2e %9.2e %9.2e %9.2e %10.3g %9.2e %9.3g "
                        "%9.3g %9.3g "
                        "%7d\n",
                        r.scene.c_str(), r.bodies, e == 0 ? "satviz" : e == 1 ? "box2d" : "box2d3", q.maxDepth, q.meanDepth, q.tailMaxDepth,
                        q.tailMeanDepth, q.pairsPerStep, q.ownMax, q.ownMean, q.ownTailMax, q.ownTailMean, q.gapMean,
                        q.energyRise, q.energyRise / (q.totalMass * kGravity), q.energyRiseTail, q.kineticTailMax,
                        q.kineticTailRise, q.awakeEnd);
        }
    }
}

void PrintTargets(const std::vector<SceneResult>& results, bool quick)
{
    std::printf("\ntargets (satviz faster than Box2D at 1000 and 10 000 bodies, no deeper penetration of the surfaces "
                "each engine collides, no more energy drift)\n");
    if (quick)
    {
        std::printf("  --quick: tiny scenes, few steps, one round: these figures are not measurements\n");
    }
    const auto target = [](const std::string& label, double value, double limit) {
        std::printf("  %-58s %10.3g  (target <= %g)  %s\n", label.c_str(), value, limit,
                    value <= limit ? "met" : "MISSED");
    };
    if (HaveBox2DV3())
    {
        for (const SceneResult& r : results)
        {
            const std::string name = r.scene + ", " + std::to_string(r.bodies) + " bodies: ";
            if (r.bodies >= 1000 || quick)
            {
                target(name + "satviz / v3 1 worker, ms per step", Median(r.v3[0].ratio), 1.0);
                target(name + "satviz / v3 2 workers, wall ms per step", Median(r.v3[1].ratio), 1.0);
            }
            const Quality& a = r.quality[0];
            const Quality& c = r.quality[2];
            target(name + "overlap max, satviz - v3", a.maxDepth - c.maxDepth, 0.0);
            target(name + "overlap mean, satviz - v3", a.meanDepth - c.meanDepth, 0.0);
            target(name + "E rise, satviz - v3", a.energyRise - c.energyRise, 0.0);
        }
    }
    else
    {
        std::printf("  (built without Box2D v3: configure with -DSATVIZ_BOX2D_V3_ROOT=PREFIX to compare with it)\n");
    }
    if (!HaveBox2D())
    {
        std::printf("  (built without Box2D: no comparison)\n");
        return;
    }
    for (const SceneResult& r : results)
    {
        const std::string name = r.scene + ", " + std::to_string(r.bodies) + " bodies: ";
        if (r.bodies >= 1000 || quick)
        {
            target(name + "satviz / box2d, ms per step", Median(r.configs[kSatviz].ratio), 1.0);
        }
        const Quality& a = r.quality[0];
        const Quality& b = r.quality[1];
        target(name + "penetration max, satviz - box2d", a.ownMax - b.ownMax, 0.0);
        target(name + "penetration mean, satviz - box2d", a.ownMean - b.ownMean, 0.0);
        target(name + "E rise, satviz - box2d", a.energyRise - b.energyRise, 0.0);
    }
}

std::string CsvName(std::string name)
{
    std::replace(name.begin(), name.end(), ',', ';');
    return name;
}

bool WriteCsv(const WorldBenchSettings& s, const std::vector<SceneResult>& results)
{
    std::ofstream csv(std::filesystem::path(s.csvDirectory) / "world.csv");
    csv << "scene,bodies,configuration,steps,rounds,ms_step,ms_step_tail,ratio,ratio_tail,ratio_to,wall_ms_step,wall_"
           "ratio,"
           "tested_per_step,"
           "swept_per_step,hits_per_step,comparisons_per_step,awake_end,overlap_max,overlap_mean,overlap_tail_max,"
           "overlap_tail_mean,overlapping_pairs_per_step,own_max,own_mean,own_tail_max,own_tail_mean,gap_mean,"
           "energy_rise,energy_rise_height,"
           "energy_rise_tail,kinetic_tail_max,kinetic_tail_rise,energy_start,energy_end,total_mass\n";
    for (const SceneResult& r : results)
    {
        for (int c = 0; c < kConfigs; ++c)
        {
            const ConfigResult& x = r.configs[c];
            if (!x.run)
            {
                continue;
            }
            csv << r.scene << ',' << r.bodies << ',' << CsvName(kConfigNames[c]) << ',' << s.steps << ',' << x.ms.size()
                << ',' << Median(x.ms) << ',' << Median(x.tailMs) << ',';
            if (!x.ratio.empty())
            {
                csv << Median(x.ratio) << ',' << Median(x.tailRatio) << ',' << (c == kSatviz ? "box2d" : "satviz");
            }
            else
            {
                csv << ",,";
            }
            csv << ',' << Median(x.wallMs) << ',';
            if (!x.wallRatio.empty())
            {
                csv << Median(x.wallRatio);
            }
            csv << ',';
            if (IsSatviz(c))
            {
                csv << x.tested << ',' << x.swept << ',' << x.hits << ',' << x.compared;
            }
            else
            {
                csv << ",,,";
            }
            csv << ',' << x.awakeEnd;
            const Quality* q = c == kSatviz ? &r.quality[0] : c == kBox2D ? &r.quality[1] : nullptr;
            if (q != nullptr && q->measured)
            {
                csv << ',' << q->maxDepth << ',' << q->meanDepth << ',' << q->tailMaxDepth << ',' << q->tailMeanDepth
                    << ',' << q->pairsPerStep << ',' << q->ownMax << ',' << q->ownMean << ',' << q->ownTailMax << ','
                    << q->ownTailMean << ',' << q->gapMean << ',' << q->energyRise << ','
                    << q->energyRise / (q->totalMass * kGravity) << ',' << q->energyRiseTail << ',' << q->kineticTailMax
                    << ',' << q->kineticTailRise << ',' << q->energyStart << ',' << q->energyEnd << ',' << q->totalMass;
            }
            else
            {
                csv << ",,,,,,,,,,,,,,,,,,"; // the 18 quality columns, empty
            }
            csv << '\n';
        }
        for (int w = 0; w < 2; ++w)
        {
            const ConfigResult& x = r.v3[w];
            if (!x.run)
            {
                continue;
            }
            // satviz's ratio to it: by processor time for 1 worker, by the wall clock for 2.
            csv << r.scene << ',' << r.bodies << ',' << (w == 0 ? "box2d v3; 1 worker" : "box2d v3; 2 workers") << ','
                << s.steps << ',' << x.ms.size() << ',' << Median(x.ms) << ',' << Median(x.tailMs) << ','
                << 1.0 / Median(x.ratio) << ",," << "satviz" << ',' << Median(x.wallMs) << ',' << 1.0 / Median(x.wallRatio)
                << ",,,,," << x.awakeEnd;
            const Quality& q = r.quality[2];
            if (w == 0 && q.measured)
            {
                csv << ',' << q.maxDepth << ',' << q.meanDepth << ',' << q.tailMaxDepth << ',' << q.tailMeanDepth
                    << ',' << q.pairsPerStep << ",,,,,," << q.energyRise << ','
                    << q.energyRise / (q.totalMass * kGravity) << ',' << q.energyRiseTail << ',' << q.kineticTailMax
                    << ',' << q.kineticTailRise << ',' << q.energyStart << ',' << q.energyEnd << ',' << q.totalMass;
            }
            else
            {
                csv << ",,,,,,,,,,,,,,,,,,"; // the 18 quality columns, empty
            }
            csv << '\n';
        }
    }
    csv.close();
    return static_cast<bool>(csv);
}

} // namespace

std::string CheckWorldBenchSettings(const WorldBenchSettings& settings)
{
    if (settings.scenes.empty())
    {
        return "--scenes: give at least one scene (pile, rain)";
    }
    for (const std::string& scene : settings.scenes)
    {
        if (scene != "pile" && scene != "rain")
        {
            return "--scenes: the scenes are pile and rain, got " + scene;
        }
    }
    if (settings.bodies.empty())
    {
        return "--bodies: give at least one body count";
    }
    for (int n : settings.bodies)
    {
        if (n < 1)
        {
            return "--bodies: a scene has at least 1 body, got " + std::to_string(n);
        }
    }
    if (settings.steps < 4)
    {
        return "--steps: at least 4 steps (the last quarter is the tail), got " + std::to_string(settings.steps);
    }
    if (settings.rounds < 1)
    {
        return "--rounds: at least 1 round, got " + std::to_string(settings.rounds);
    }
    if (settings.threads < 1 || settings.threads > 256)
    {
        return "--threads: from 1 to 256 threads, got " + std::to_string(settings.threads);
    }
    return "";
}

WorldBenchSettings QuickWorldBenchSettings(WorldBenchSettings settings)
{
    settings.bodies = {30, 120};
    settings.steps = 60;
    settings.rounds = 1;
    settings.quick = true;
    return settings;
}

bool WriteWorldScenes(const WorldBenchSettings& settings, const std::string& directory, std::string& error)
{
    for (const char* name : {"pile", "rain"})
    {
        if (std::find(settings.scenes.begin(), settings.scenes.end(), name) == settings.scenes.end())
        {
            continue;
        }
        for (int n : settings.bodies)
        {
            const Scene scene = MakeScene(std::string(name) == "rain", n, settings.steps, settings.seed);
            satviz::Scene file;
            file.description = "satviz-bench --world's " + scene.name + " of " + std::to_string(n) +
                               " bodies, seed " + std::to_string(settings.seed) + ", " +
                               std::to_string(settings.steps) + " steps";
            file.hasWorld = true;
            file.world.gravity = {0.0, -kGravity};
            file.world.dt = kDt;
            int walls = 0, dynamic = 0;
            for (const SceneBody& from : scene.bodies)
            {
                satviz::Body body = FileBody(from);
                body.name = from.dynamic ? "body " + std::to_string(dynamic++) : "static " + std::to_string(walls++);
                file.bodies.push_back(std::move(body));
            }
            const std::string path = directory + "/" + scene.name + "-" + std::to_string(n) + ".json";
            if (!SaveScene(file, path, error))
            {
                return false;
            }
            std::fprintf(stderr, "satviz-bench: %s written\n", path.c_str());
        }
    }
    return true;
}

bool RunWorldBench(const WorldBenchSettings& settings)
{
    std::vector<SceneResult> results;
    for (const char* scene : {"pile", "rain"})
    {
        if (std::find(settings.scenes.begin(), settings.scenes.end(), scene) == settings.scenes.end())
        {
            continue;
        }
        for (int n : settings.bodies)
        {
            results.push_back(RunScene(settings, std::string(scene) == "rain", n));
        }
    }
    PrintTables(settings, results);
    PrintTargets(results, settings.quick);
    if (settings.csvDirectory.empty())
    {
        return true;
    }
    if (WriteCsv(settings, results))
    {
        std::fprintf(stderr, "satviz-bench: world.csv written to %s\n", settings.csvDirectory.c_str());
        return true;
    }
    std::fprintf(stderr, "satviz-bench: --csv %s: writing world.csv failed\n", settings.csvDirectory.c_str());
    return false;
}

} // namespace satviz::bench
