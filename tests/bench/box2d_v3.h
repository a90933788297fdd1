// SPDX-License-Identifier: MIT
// Box2D v3's world on the benchmark's scenes, behind an interface without Box2D types. Box2D v3 and Debian's Box2D
// 2.4.1 both install the header box2d/box2d.h, so v3 is compiled in a file of its own (box2d_v3.cpp), found through
// the CMake option SATVIZ_BOX2D_V3_ROOT (an install prefix of Box2D v3, built outside this repository).
#pragma once

#include <satviz/shape.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace satviz::bench
{

/// One body as the benchmark gives it to an engine.
struct V3Body
{
    Shape shape;                  ///< a circle or a convex polygon of at most 8 vertices, in the body frame
    bool dynamic = true;          ///< dynamic or static
    Vec2 position{};              ///< body origin
    double angle = 0.0;           ///< radians
    Vec2 velocity{};              ///< of the centre of mass
    double angularVelocity = 0.0; ///< radians per second
};

/// The materials and the step every body of a benchmark scene shares.
struct V3Settings
{
    double density = 1.0;              ///< of every body
    double friction = 0.6;             ///< of every shape
    double restitution = 0.1;          ///< of every shape
    double restitutionThreshold = 1.0; ///< approach speed below which contacts do not bounce
    double gravity = 10.0;             ///< downwards
    double dt = 1.0 / 60.0;            ///< the step
    int subSteps = 4;                  ///< Box2D v3's sub-steps per step (its recommended 4)
    int workers = 1;                   ///< worker threads of its own scheduler (1: serial)
};

/// True when this build has Box2D v3.
bool HaveBox2DV3();

/// The version of Box2D v3 in this build ("3.2.0"), or "" without it.
std::string Box2DV3Version();

/// A Box2D v3 world built from a benchmark scene. Only constructed when HaveBox2DV3().
class Box2DV3World
{
  public:
    /// The world of `bodies` (in this order) with `settings`.
    Box2DV3World(const std::vector<V3Body>& bodies, const V3Settings& settings);
    ~Box2DV3World();
    Box2DV3World(const Box2DV3World&) = delete;
    Box2DV3World& operator=(const Box2DV3World&) = delete;

    /// One step of settings.dt with settings.subSteps sub-steps.
    void Step();
    /// Dynamic bodies awake now.
    int AwakeBodies() const;
    /// Each body's transform, in the order given, as Box2D holds it (its rotation's cosine and sine, in float).
    void Transforms(std::vector<Transform>& xfs) const;
    /// Kinetic energy of the dynamic bodies (about their centres of mass).
    double KineticEnergy() const;
    /// Potential energy of the dynamic bodies in the gravity, from height 0.
    double PotentialEnergy() const;
    /// Total mass of the dynamic bodies.
    double TotalMass() const;
    /// Box2D v3's own profile of the last step (b2World_GetProfile): each stage's name and milliseconds, the whole
    /// step first.
    std::vector<std::pair<std::string, double>> LastStepProfile() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
};

} // namespace satviz::bench
