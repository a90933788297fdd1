// SPDX-License-Identifier: MIT
// satviz: the world's step, stage by stage: the state its stages share (internal).
#pragma once

#include "contact_solver.h"
#include "soft_lanes.h"
#include "soft_solver.h"

#include <satviz/world.h>

#include <cstdint>
#include <vector>

namespace satviz::detail
{

/// The lists a step works in, kept between steps (World::stepMemory). Each stage sizes and fills a list before it
/// reads it, so nothing of one step reaches the next through them.
struct StepMemory
{
    std::vector<SolverBody> solverBodies;          ///< see Stepper
    std::vector<SolverContact> solverContacts;     ///< see Stepper
    std::vector<SolverContact> guards;             ///< see Stepper
    std::vector<int> solveOrder;                   ///< see Stepper
    std::vector<int> foundOrder;                   ///< see Stepper
    std::vector<double> energyBefore;              ///< see Stepper
    std::vector<Transform> xfs;                    ///< see Stepper
    std::vector<Vec2> centers;                     ///< see Stepper
    std::vector<uint8_t> hit;                      ///< see Stepper
    std::vector<uint8_t> bullets;                  ///< see Stepper
    std::vector<double> bodyReach;                 ///< see Stepper
    std::vector<Rot> rotations;                    ///< see Stepper
    std::vector<double> rotationAngles;            ///< Move: the angle of which each of rotations is the rotation
    std::vector<SolverContact> spareContacts;      ///< SortContacts: the contacts in their new order
    std::vector<uint8_t> moving;                   ///< PrepareContacts, SolveSoft: whether each body moves
    std::vector<WorldContact> previousContacts;    ///< FindContacts: the last step's contacts
    std::vector<std::pair<int, int>> candidates;   ///< FindContacts: the broadphase's pairs
    std::vector<Aabb> boxes;                       ///< FindContacts: the bodies' boxes
    std::vector<SoftBody> softBodies;              ///< SolveSoft: each body's velocities and move in the sub-steps
    std::vector<SoftContact> softContacts;         ///< SolveSoft: the contacts, top down
    std::vector<int> softAwake;                    ///< SolveSoft: the awake dynamic bodies
    std::vector<SoftBatch> softBatches;            ///< SolveSoft: the untraced contacts, four side by side
    std::vector<SoftColour> softColours;           ///< SolveSoft: each colour's batches and traced contacts
    std::vector<int> softSingle;                   ///< SolveSoft: the contacts visited one at a time, by colour
    std::vector<int> softLevels;                   ///< SolveSoft: each body's next colour, then each group's start
    std::vector<int> softKeys;                     ///< SolveSoft: each contact's colour and kind
    std::vector<int> softOrder;                    ///< SolveSoft: the contacts by colour and kind
    std::vector<SolverBody> softVelocities;        ///< SolveSoft: the velocities the sub-steps leave
    std::vector<int> bouncing;                     ///< SolveSoft: the contacts with a bouncing point
    std::vector<std::vector<int>> near;            ///< Move's time of impact: the bodies each body is swept with
};

/// The world's working lists, made on its first step.
StepMemory& MemoryOf(World& world);

/// The state of one step, shared by its stages. Step (world.cpp) runs them in this order:
///  1. FindContacts (world_contacts.cpp): bounds, broadphase, narrowphase, warm starting, waking. A pair that a
///     bullet would outrun (LeftToSweep) keeps its points only as a guard for the position passes.
///  2. SolveVelocities (world_velocities.cpp): gravity, the contacts ordered top down (OrderTopDown), the velocity
///     passes, and LimitEnergyGain for a group of bodies the passes left with more energy than it had. With
///     WorldSettings::softStep, SolveSoft (world_soft_step.cpp) instead: the sub-steps of the soft step.
///  3. StoreImpulses (world_velocities.cpp): the impulses go back to the world's contacts for the next warm start.
///  4. Move (world_positions.cpp): positions, with the hits of fast bodies in time order (TimeOfImpactStage).
///  5. CorrectPositions (world_positions.cpp): guards for where the bodies went (GuardAfterMove), then the position
///     passes remove the overlap left. Not with the soft step, whose sub-steps have removed it.
///  6. Sleep (world_sleep.cpp): islands of touching dynamic bodies that have rested long enough sleep.
struct Stepper
{
    World& world;
    double dt;
    const WorldSettings& settings;
    StepMemory& memory;
    std::vector<SolverBody>& solverBodies;
    std::vector<SolverContact>& solverContacts;
    std::vector<SolverContact>& guards; // the points of swept pairs: for the position passes only
    std::vector<int>& solveOrder;       // solverContacts' indices in the order the passes visit them (OrderTopDown)
    std::vector<int>& foundOrder;       // after SortContacts: the solver contacts' indices in the order found
    std::vector<double>& energyBefore;  // per body, after gravity and before the contacts
    std::vector<Transform>& xfs;        // transforms at the start of the step
    std::vector<Vec2>& centers;         // centres of mass at the start of the step
    std::vector<uint8_t>& hit;          // per body: took a time-ordered hit in the step (Move)
    std::vector<uint8_t>& bullets;      // per body: moves beyond its reach or turns fast (FindContacts)
    std::vector<double>& bodyReach;     // per body: how far FindContacts looked beyond its box
    std::vector<Rot>& rotations;        // per body: MakeRot of its angle after Move
    std::vector<double>& rotationAngles; // per body: that angle, kept to the next step's FindContacts

    /// The step of `world` by `step` seconds, with the world's settings, in the world's working lists.
    Stepper(World& w, double step)
        : world(w), dt(step), settings(w.settings), memory(MemoryOf(w)), solverBodies(memory.solverBodies),
          solverContacts(memory.solverContacts), guards(memory.guards), solveOrder(memory.solveOrder),
          foundOrder(memory.foundOrder), energyBefore(memory.energyBefore), xfs(memory.xfs), centers(memory.centers),
          hit(memory.hit), bullets(memory.bullets), bodyReach(memory.bodyReach), rotations(memory.rotations),
          rotationAngles(memory.rotationAngles)
    {
    }

    /// Stage 1: bounds, broadphase, narrowphase, warm starting, waking.
    void FindContacts();
    /// Whether the pair (i, j), still apart, is left to the sweep instead of given a speculative contact.
    bool LeftToSweep(int i, int j) const;
    /// Stage 2: gravity and the velocity passes (or, with WorldSettings::softStep, SolveSoft).
    void SolveVelocities();
    /// Stage 2's start, shared by both solvers: the solver bodies (velocities before gravity), each contact
    /// prepared once (lever arms from the centres of mass, effective masses, bounce targets), the guards, and the
    /// traced contact's setup.
    void PrepareContacts();
    /// Stage 2 with WorldSettings::softStep: the sub-steps of the soft step and the restitution after them. Leaves
    /// solverBodies with the velocities that take each body where the sub-steps moved it (its move over dt), for
    /// Move, and the velocities the sub-steps end with in the memory's softVelocities, which Move gives the bodies.
    void SolveSoft();
    /// The traced contact's restitution and its bodies' velocities after the solve.
    void RecordAfter();
    /// More passes, then smaller impulses, for a group of bodies the velocity passes left with more kinetic energy
    /// than it had; `unsolved` holds the velocities before the passes.
    template <typename SolvePass>
    void LimitEnergyGain(const std::vector<SolverBody>& unsolved, const SolvePass& solvePass);
    /// Stage 3: the accumulated impulses go back to the world's contacts for the next step's warm start.
    void StoreImpulses();
    /// Stage 4: positions, with the hits of fast bodies in time order.
    void Move();
    /// Guards with the static bodies near the path of a body that moved beyond the reach it was given; c and
    /// turn: each body's centre of mass after the move, and its turn since the start of the step.
    void GuardAfterMove(const std::vector<Vec2>& c, const std::vector<Rot>& turn);
    /// Stage 5: overlap removed by moving the positions, not the velocities.
    void CorrectPositions();
    /// Stage 6: islands of touching dynamic bodies sleep together once all have rested long enough.
    void Sleep();
    /// The order of the velocity and position passes (solveOrder): top down along gravity, ties in the order found.
    void OrderTopDown();
    /// Stores solverContacts in the order of the passes (solveOrder), so that each pass reads them in sequence, and
    /// keeps in foundOrder where each went, for the work whose results depend on the order found.
    void SortContacts();
};

/// Union-find over body indices: the root of i's set, halving the path on the way (for the groups of
/// LimitEnergyGain and the islands of sleeping).
inline int FindRoot(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

} // namespace satviz::detail
