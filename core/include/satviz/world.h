// SPDX-License-Identifier: MIT
// satviz: a rigid-body world: bodies that fall, collide, bounce, slide, stick and spin.
#pragma once

#include <satviz/broadphase.h>
#include <satviz/concave.h>
#include <satviz/manifold.h>
#include <satviz/mass.h>
#include <satviz/material.h>
#include <satviz/shape.h>
#include <satviz/solver_trace.h>
#include <satviz/step_trace.h>
#include <satviz/tasks.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace satviz
{

namespace detail
{
struct StepMemory;
} // namespace detail

/// The working lists of the step (its bodies' velocities, its contacts as the solver sees them, their order, ...),
/// kept between steps so that a step reuses the memory of the one before instead of allocating its own. Working
/// memory, not state: a step sets what it reads before reading it, or reads a value kept from the step before only
/// where the bodies show it still holds (a body's rotation, while the body has the angle it was taken of), so a copy
/// of a world, which starts without any, steps as the original.
struct StepMemoryCache
{
    /// The lists; null until the first step.
    std::unique_ptr<detail::StepMemory, void (*)(detail::StepMemory*)> memory{nullptr, nullptr};

    StepMemoryCache() = default;
    /// A copy starts empty: two worlds never share their working memory.
    StepMemoryCache(const StepMemoryCache&) {}
    /// Keeps its own memory: the lists are not part of what is copied.
    StepMemoryCache& operator=(const StepMemoryCache&) { return *this; }
    StepMemoryCache(StepMemoryCache&&) = default;
    StepMemoryCache& operator=(StepMemoryCache&&) = default;
    ~StepMemoryCache() = default;
};

/// A static body never moves (infinite mass); a dynamic body moves under gravity and contacts.
enum class BodyType
{
    Static,  ///< fixed in place: ground, walls, slopes
    Dynamic, ///< moved by the world
};

/// What a body is made of and how it starts: the input of AddBody.
struct BodyDef
{
    Shape shape;                       ///< the shape, in the body frame (ignored when `concave` has pieces)
    /// A concave body: its convex pieces in the body frame (MakeConcave of a decomposition). Empty for a convex
    /// body, whose shape is `shape`.
    Concave concave;
    BodyType type = BodyType::Dynamic; ///< static or dynamic
    double density = 1.0;              ///< mass per unit area of a dynamic body, > 0
    Material material{};               ///< restitution and frictions
    Vec2 position{};                   ///< world position of the body origin
    double angle = 0.0;                ///< rotation in radians, counter-clockwise
    Vec2 velocity{};                   ///< velocity of the centre of mass, units per time unit
    double angularVelocity = 0.0;      ///< radians per time unit, counter-clockwise
};

/// A body of the world. The state is public to read; change it between steps only through the fields that say so.
struct RigidBody
{
    /// The shape, in the body frame. For a concave body, the convex hull of its pieces: a bound for the broadphase
    /// (boxes and reaches); the contacts and sweeps take the pieces.
    Shape shape;
    /// A concave body's pieces in the body frame, which the queries of the step take (concave.h): one body with one
    /// mass and one island, whose pairs get one manifold each. Empty for a convex body.
    Concave concave;
    BodyType type = BodyType::Dynamic; ///< static or dynamic
    Material material{};               ///< restitution and frictions
    Vec2 position{};                   ///< world position of the body origin
    double angle = 0.0;                ///< rotation in radians
    Vec2 velocity{};                   ///< velocity of the centre of mass
    double angularVelocity = 0.0;      ///< radians per time unit
    double mass = 0.0;                 ///< 0 for a static body
    double invMass = 0.0;              ///< 1 / mass, 0 for a static body
    double inertia = 0.0;              ///< moment of inertia about the centre of mass, 0 for a static body
    double invInertia = 0.0;           ///< 1 / inertia, 0 for a static body
    Vec2 localCenter{};                ///< centre of mass in the body frame
    double innerRadius = 0.0;          ///< InnerRadius about the centre of mass: the body's size for the sweep rule
    double outerRadius = 0.0;          ///< OuterRadius about the centre of mass: how far the shape reaches
    double turnRadius = 0.0;           ///< TurnRadius about the centre of mass: bounds how far turning moves it
    bool awake = true;                 ///< false while asleep: not moved, not solved, until something touches it
    double sleepTime = 0.0;            ///< how long the body has been slower than the sleep thresholds

    /// True for a concave body (its shape is `concave`).
    bool IsConcave() const { return !concave.parts.empty(); }
    /// The body's transform (body frame to world).
    Transform Xf() const { return MakeTransform(position, angle); }
    /// The centre of mass in world space.
    Vec2 WorldCenter() const { return TransformPoint(Xf(), localCenter); }
};

/// How the world steps, and which of its savings are on. Every saving can be switched off to measure what it saves;
/// the results stay the same up to the order in which contacts are solved, except sleeping, which freezes bodies
/// that would otherwise creep by rounding.
struct WorldSettings
{
    Vec2 gravity{}; ///< acceleration, units per time unit squared
    /// Sequential-impulse passes over the contacts for the velocities. Ten, not Box2D's eight: in deep piles eight
    /// leave the bodies sunk deeper than Box2D's (satviz-bench --world measures both).
    int velocityIterations = 10;
    int positionIterations = 5; ///< passes of the position correction that removes overlap
    /// Overlap left in place, in units: contacts are kept touching by this much so that they persist from step to
    /// step (and warm start), and the push-out never overshoots into a gap.
    double linearSlop = 0.005;
    /// Fraction of the overlap beyond the slop that a pass of the position correction removes (Baumgarte's factor,
    /// applied to positions only, so removing overlap adds no velocity).
    double correctionFactor = 0.3;
    /// Most overlap a pass of the position correction removes at a point, in units: a deep overlap (a fast body
    /// that was not swept) is removed over several steps instead of flinging the bodies apart.
    double maxCorrection = 0.2;
    /// Below this approach speed (units per time unit) a contact does not bounce: resting contacts stay at rest.
    double restitutionThreshold = 0.5;
    /// A pair of bodies is swept (its hits found by time of impact and taken in time order, see Step) when a point
    /// of one can move, relative to the other, more than this fraction of the smaller inner radius of the dynamic
    /// bodies of the pair within a step. Bodies that fall together are not swept against each other.
    double sweepFraction = 0.5;
    /// Most time-ordered hits a body takes in one step; after that it stops at its last hit, at rest, for the rest
    /// of the step (a body wedged between two walls cannot stall the step).
    int maxHitsPerBody = 16;
    /// Below these speeds (units and radians per time unit) a body counts as resting; an island of bodies resting
    /// for timeToSleep goes to sleep.
    double sleepLinearSpeed = 0.01;
    double sleepAngularSpeed = 0.035; ///< see sleepLinearSpeed
    double timeToSleep = 0.5;         ///< see sleepLinearSpeed

    /// Speculative contacts (Catto; Firth): pairs not yet touching but within the distance their bodies can close
    /// in the step (the sum of their reaches: a body's speed after gravity and the turn of its farthest point,
    /// times dt) get contact points with their gap (CollideWithin), and the solver lets each point close its gap
    /// within the step and no more. A body landing on a pile then stops at the surface instead of sinking into it
    /// for a step, and a pile's bodies are solved together rather than hit by hit. Off: only touching pairs get
    /// contacts.
    bool speculativeContacts = true;
    /// Most reach of a body, in its outer radii (2: its diameter). A body that moves farther within a step is a
    /// bullet: its sweep finds its hits, and a long reach would give it contacts with faces it passes by.
    double speculativeReach = 2.0;
    /// Most turn of a body within a step, in radians, for it to have speculative contacts: a contact found at the
    /// start of the step follows a turn only to first order, so a body that turns faster is left to the sweep,
    /// which follows it exactly.
    double speculativeTurn = 0.25;
    bool broadphase = true;      ///< sort and sweep; off: every pair goes to the narrowphase
    bool skipStaticPairs = true; ///< no pair of two static bodies is considered; off: they are tested too
    bool sweepOnlyFast = true;   ///< only fast bodies are swept; off: every moving dynamic body is
    bool sleeping = true;        ///< resting islands sleep; off: every dynamic body is stepped always

    /// The soft step (Catto, "Solver2D", 2024, its soft step; the solver of Box2D v3) in place of the velocity
    /// passes, the restitution's push-only passes and the position passes. Off (the default), a step runs stages 2
    /// and 4 of Step as described there. On, stage 2 prepares each contact once (effective masses, bounce targets,
    /// anchors from the bodies' centres of mass) and then, for each of subSteps sub-steps of dt / subSteps:
    ///  1. gravity for the sub-step;
    ///  2. warm start: the accumulated impulses applied again;
    ///  3. solve: at each point the separation now, from the found one and the bodies' moves so far within the step
    ///     (no narrowphase); a point still apart may approach by its gap within the sub-step, an overlapping one is
    ///     pushed out by a soft constraint, a damped spring of contactHertz and contactDampingRatio, at most at
    ///     maxPushSpeed; friction as in the velocity passes (static limit, then Coulomb's cone);
    ///  4. the bodies' positions and turns integrated over the sub-step (kept as moves since the start of the step);
    ///  5. relax: the same pass without the push, so that the push leaves no velocity behind.
    /// After the sub-steps one pass of restitution brings each point that approached faster than the threshold, and
    /// pushed, to its bounce speed. The bodies then move as the sub-steps moved them (the hits of fast bodies in time
    /// order as before) and keep the velocity of the last sub-step. No position passes: the soft push has taken out
    /// the overlap within the sub-steps. Cheaper per step; it leaves the teaching figures and the block solve of
    /// two-point contacts aside, so the lessons describe the step with it off.
    bool softStep = false;
    int subSteps = 4;                  ///< soft step: sub-steps per step, at least 1
    /// Soft step: stiffness of the push out of an overlap, as the frequency of a spring, per time unit; at most a
    /// quarter of the sub-step rate, and twice this against static and sleeping bodies, which cannot give way. A
    /// resting contact carries its load with an overlap of about g / (2 pi hertz)^2 per body of the pile above it:
    /// 60 (a quarter of the rate of 4 sub-steps of 1/60) leaves a pile a quarter of the overlap of Box2D v3's 30.
    double contactHertz = 60.0;
    double contactDampingRatio = 10.0; ///< soft step: the spring's damping ratio (above 1: no bounce from the push)
    /// Soft step: most speed, in units per time unit, at which the push separates an overlapping point: a deep
    /// overlap is taken out over several steps, not by flinging the bodies apart.
    double maxPushSpeed = 3.0;
};

/// What one step did with the pairs of bodies, stage by stage: how many were considered and how many each
/// saving removed, so a view can show what was skipped.
struct StepCounts
{
    int64_t pairs = 0;         ///< pairs of bodies: n (n - 1) / 2
    int64_t staticPairs = 0;   ///< of those, skipped because both bodies are static
    int64_t sleepingPairs = 0; ///< skipped because neither body is awake (asleep or static, at least one asleep)
    int64_t boundsApart = 0;   ///< skipped by the broadphase: their bounding boxes do not overlap
    int64_t tested = 0;        ///< given to the narrowphase (Collide)
    /// Of the tested, found touching or overlapping (contacts kept from sleeping pairs are not counted, nor the
    /// speculative contacts of pairs still apart).
    int64_t touching = 0;
    int64_t speculative = 0; ///< of the tested, found apart but within reach: speculative contacts (WorldSettings)
    int64_t swept = 0;       ///< pairs swept for a time of impact (fast bodies)
    int64_t hits = 0;        ///< time-ordered hits resolved within the step
    int64_t broadphaseComparisons = 0; ///< box comparisons the broadphase made
    int awakeBodies = 0;               ///< dynamic bodies awake after the step
    int sleepingBodies = 0;            ///< dynamic bodies asleep after the step
};

/// One contact point of a contact, with the impulses the solver accumulated on it.
struct WorldContactPoint
{
    Vec2 point{};                ///< world position (from Collide)
    double separation = 0.0;     ///< < 0: overlap; > 0: a gap (a speculative contact, see WorldSettings)
    double normalImpulse = 0.0;  ///< accumulated normal impulse of the last step
    double tangentImpulse = 0.0; ///< accumulated friction impulse of the last step
    /// With WorldSettings::softStep, normalImpulse and tangentImpulse are the step's summed over its sub-steps,
    /// and these the last sub-step's, from which the next step's sub-steps warm start; without, the same as they.
    double subStepNormalImpulse = 0.0;
    double subStepTangentImpulse = 0.0; ///< see subStepNormalImpulse
    bool stuck = false;                 ///< static friction held this point in the last step
    uint32_t key = 0;            ///< identifies the point from step to step (reference face, incident edge, slot)
};

/// A touching pair of bodies: their manifold and the solver's state for it. Bodies a < b.
struct WorldContact
{
    int a = -1;    ///< first body
    int b = -1;    ///< second body
    Vec2 normal{}; ///< unit normal from a to b
    /// The body whose turning turns the normal: 1 when b holds the reference face (or the vertex of a vertex-to-circle
    /// axis), else 0 (a holds it, or the normal joins two circles' centres).
    int normalBody = 0;
    WorldContactPoint points[2]{}; ///< contact points, valid up to pointCount
    int pointCount = 0;            ///< 1 or 2
    ContactMaterial material{};    ///< combined restitution and frictions
    /// A guard, not a contact: the pair is still apart and either left to the sweep (fast against each other) or
    /// a body beside a static one beyond its reach (see Step). The velocity passes ignore its points; they keep the
    /// position passes from pushing one body into the other.
    bool guard = false;
};

/// The world: bodies, settings and what the last step found.
struct World
{
    WorldSettings settings{};           ///< how to step
    std::vector<RigidBody> bodies;      ///< the bodies, by index
    double time = 0.0;                  ///< simulated time
    StepCounts counts{};                ///< what the last step did
    std::vector<WorldContact> contacts; ///< contacts of the last step, sorted by (a, b)
    /// When not null, the solver records what it does for the pair (trace->bodyA, trace->bodyB) during each step
    /// (cleared at the start of the step). Null: nothing is recorded and nothing is paid.
    ContactSolveTrace* trace = nullptr;
    /// When not null, each step records there its grown boxes, the broadphase's pairs and its time-ordered hits
    /// (cleared at the start of the step). Null: nothing is recorded and nothing is paid.
    StepTrace* stepTrace = nullptr;
    /// Where the step runs its work whose results do not depend on order (each body's pose, box and move, the
    /// narrowphase of each pair, the preparation of each contact, the first sweeps of the fast pairs): on the
    /// caller's parallel-for (PoolTasks of a ThreadPool, or the caller's own). The default runs it all on the calling
    /// thread. Every body ends each step with the same bits for any number of workers.
    TaskRunner tasks{};

    /// The broadphase's box order, kept between steps so that sorting costs close to linear time. Working memory,
    /// not state: two worlds with the same bodies and contacts step alike whatever it holds.
    SortAndSweep broadphase;
    /// The same for the swept boxes of the time-ordered hits.
    SortAndSweep sweptBroadphase;
    /// The step's working lists, kept between steps to save allocating them again.
    StepMemoryCache stepMemory;
};

/// Adds a body, computing its mass properties from the shape and the density (a static body gets none); a concave
/// body's from its pieces (ComputeMass of a Concave), its `shape` set to their convex hull. Returns its index. The
/// definition must be valid: a finite state, a shape built by the polygon builders or a circle of positive radius
/// (or pieces that are such polygons), a positive density for a dynamic body, non-negative finite material
/// coefficients (ValidateBodyDef says what is wrong).
int AddBody(World& world, const BodyDef& def);

/// Empty when the definition is valid, else what is wrong, naming the field ("density must be > 0", ...).
std::string ValidateBodyDef(const BodyDef& def);

/// Advances the world by `dt` (> 0) time units. One step, after Catto's sequential impulses (Box2D) with the
/// hits of fast bodies taken in time order:
///  1. Bounds: each body's box, grown by its reach (how far it can move in the step); the broadphase pairs the
///     overlapping ones (skipping static-static and sleeping pairs); the narrowphase (CollideWithin) turns the
///     touching pairs into contacts, and the pairs still apart but within their reaches into speculative contacts
///     (points with a gap), keeping the impulses of the points that persist from the last step (warm starting).
///     A bullet (a body that moves beyond its reach, or turns faster than speculativeTurn) gets no speculative
///     contact with what it moves fast against: the sweep takes that pair. Such pairs, and a body within
///     maxCorrection of a static body beyond its reach, get guards instead (WorldContact::guard).
///  2. Velocities: gravity, then the velocity passes, over the contacts from the highest to the lowest along
///     gravity (so the weight of a pile's upper rows reaches the rows below within one pass; without gravity, in
///     the order found): at each contact point a normal impulse that stops the
///     approach (compression; a speculative point may approach at the speed that closes its gap within the step),
///     accumulated and clamped to push only; and a friction impulse with its own effective
///     mass, held within static friction times the normal impulse while the point sticks, else the dynamic limit
///     (Coulomb's cone). Two-point contacts solve their normal impulses together (a 2x2 block), so a flat landing
///     does not spin. Then restitution (Poisson's rule): a point that approached faster than the restitution
///     threshold (measured before the step's gravity) gets a multiple of its compression impulse once more, the
///     multiple that gives a lone contact its bounce speed; in a group of contacts that mixes restitutions the
///     bounce impulses are scaled down as far as needed to return no more kinetic energy than the group had; and
///     push-only passes stop any approach a bounce made at another point.
///  3. Positions: each body moves with its velocity. A pair whose bodies move fast against each other (see
///     WorldSettings::sweepFraction) is swept, unless the step's contacts hold it (they do until a hit changes one
///     of its bodies, or the solver leaves one turning faster than speculativeTurn): translation by Sweep, turning
///     by conservative advancement (the distance bound of SAT divided by the fastest the shapes can close along
///     it). The earliest hit of the world comes first: its two bodies move to that time, the hit is resolved with
///     the same impulses, their pairs are swept again from that time (with static bodies whatever their speeds, so
///     a hit cannot push a body through the wall it rests on), and the step goes on, so two hits in one step happen
///     in order.
///  4. Overlap: nonlinear Gauss-Seidel on the positions (Catto; Box2D 2.4): each pass measures a point's overlap at
///     the bodies' present positions and moves them apart by correctionFactor times the overlap beyond the slop;
///     guards count too, their overlap measured afresh by Collide; a last pass lifts each body straight out of the
///     static bodies it overlaps beyond the slop. The contacts of a body that took a hit are left out: the sweep put
///     it where it is.
///     It changes positions only, so removing overlap adds no kinetic energy; a bouncing point whose bounce
///     carries it out of the overlap within the step is left to do so. Chosen over split impulses (pseudo-velocities
///     from the overlap at the start of the step) because it sees the overlap after the move: a body that sank during
///     this step is lifted in this step.
///  5. Sleep: islands of touching bodies that have rested for timeToSleep sleep; a body that touches a sleeping
///     one wakes its island.
/// Deterministic: the same world stepped the same way gives the same bits, in every build.
/// Cost: the broadphase (FindPairs) plus one Collide per pair whose boxes overlap; per contact point a constant
/// amount of work in each velocity and position pass; one Sweep per fast pair, and again for the pairs of a body
/// after each hit it takes (at most maxHitsPerBody). A sleeping body keeps its box in the broadphase and costs no
/// narrowphase and no solving.
void Step(World& world, double dt);

/// The pairs of bodies whose shapes touch or overlap, (i, j) with i < j in ascending order, found through the
/// broadphase (sort and sweep) and the Overlap test: what a scene's bodies touch without stepping it.
std::vector<std::pair<int, int>> TouchingPairs(const std::vector<Shape>& shapes, const std::vector<Transform>& xfs);

/// Total kinetic energy of the dynamic bodies: linear plus rotational.
double KineticEnergy(const World& world);

/// Total linear momentum of the dynamic bodies.
Vec2 LinearMomentum(const World& world);

/// Total angular momentum of the dynamic bodies about `origin`: spin plus the moment of the linear momentum.
double AngularMomentum(const World& world, Vec2 origin);

} // namespace satviz
