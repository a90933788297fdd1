// SPDX-License-Identifier: MIT
// satviz: a scene stepped as a world, keeping what the views of a simulation need: the world after each step, the
// totals of every step so far (for plots over time), and the last step's records (its boxes, pairs and hits, and
// the solver's work on one chosen contact). The app steps it one step at a time; satviz-render steps it N times.
#pragma once

#include <satviz/scene.h>
#include <satviz/step_trace.h>
#include <satviz/world.h>

#include <string>
#include <vector>

namespace satviz
{

/// The world's totals after a step, for plots over time.
struct SimSample
{
    int step = 0;                ///< steps taken (0: the scene as written)
    double time = 0.0;           ///< simulated time
    double kinetic = 0.0;        ///< KineticEnergy: linear plus rotational, of the dynamic bodies
    double potential = 0.0;      ///< gravitational potential energy of the dynamic bodies, -m g . c (0 at the origin)
    Vec2 momentum{};             ///< LinearMomentum of the dynamic bodies
    double deepestOverlap = 0.0; ///< the largest depth of any two bodies that overlap (0 when none do)
};

/// The totals of a world as it is now: energies, momentum, and the deepest overlap (every touching pair found by
/// TouchingPairs, its depth by Collide).
SimSample MeasureWorld(const World& world, int step);

/// A scene stepped as a world, with its history and the last step's records. The world's record pointers are null
/// between steps, so the struct can be copied freely.
struct SimRecord
{
    World world;                     ///< the world after the last step (MakeWorld of the scene before the first)
    double dt = 1.0;                 ///< the step length, the scene's world.dt
    int steps = 0;                   ///< steps taken
    std::vector<SimSample> history;  ///< one sample per step taken, and one for the scene as written: steps + 1
    StepTrace lastStep;              ///< the last step's boxes, broadphase pairs and time-ordered hits
    ContactSolveTrace contact;       ///< the solver's record of the chosen pair in the last step
    std::vector<RigidBody> before;   ///< the bodies as the last step began (its contacts were found for these)
};

/// Starts a record of the scene (which must pass ValidateSceneWorld): the world made from it, sample 0, and the
/// pair (pairA, pairB) whose contact the solver records (-1: none).
SimRecord StartRecord(const Scene& scene, int pairA, int pairB);

/// Takes one step of the record's world, recording its boxes, pairs, hits and the chosen contact, and appends the
/// step's totals to the history.
void StepRecord(SimRecord& record);

/// Steps the scene `steps` (>= 0) times into a record, and copies the world's state back into the scene as
/// SimulateScene does. Returns "" on success, else the problem (SimulateScene's), the scene unchanged.
std::string SimulateSceneRecorded(Scene& scene, int steps, int pairA, int pairB, SimRecord& record);

} // namespace satviz
