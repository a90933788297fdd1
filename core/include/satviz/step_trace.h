// SPDX-License-Identifier: MIT
// satviz: what one step of the world did with all its bodies, recorded for teaching views: the boxes the broadphase
// compared, the pairs it passed on, and the time-ordered hits in the order they were resolved.
#pragma once

#include <satviz/broadphase.h>
#include <satviz/math.h>

#include <utility>
#include <vector>

namespace satviz
{

/// One time-ordered hit, as the world resolved it (World's step, stage 3).
struct StepHit
{
    double time = 0.0;          ///< when within the step, as a fraction of it in [0, 1]
    int a = -1;                 ///< the lower-index body
    int b = -1;                 ///< the other body
    Vec2 normal{};              ///< unit normal from a to b
    Vec2 points[2]{};           ///< contact points at the time of the hit, valid up to pointCount
    int pointCount = 0;         ///< 0 (the sweep stopped the pair short of a contact), 1 or 2
    Vec2 position[2]{};         ///< positions of a and b at the time of the hit
    double angle[2]{};          ///< angles of a and b at the time of the hit
    Vec2 velocityBefore[2]{};   ///< velocities of a and b as they hit
    double spinBefore[2]{};     ///< angular velocities of a and b as they hit
    Vec2 velocityAfter[2]{};    ///< velocities of a and b after the hit's impulses
    double spinAfter[2]{};      ///< angular velocities of a and b after the hit's impulses
};

/// The world's record of one step (World::stepTrace). Recording changes nothing the step computes.
struct StepTrace
{
    /// Each body's box at the start of the step, grown by how far it can move within the step (a dynamic body's
    /// reach) or, for a static body, by how far the position passes can push a body (its guards' margin): the boxes
    /// the broadphase compares.
    std::vector<Aabb> bounds;
    std::vector<double> grow;                    ///< how much each box grew on every side
    std::vector<std::pair<int, int>> candidates; ///< the pairs the broadphase passed to the narrowphase, i < j
    std::vector<StepHit> hits;                   ///< the time-ordered hits, in the order they were resolved
    /// Empties the record.
    void Clear() { *this = StepTrace(); }
};

} // namespace satviz
