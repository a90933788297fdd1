// SPDX-License-Identifier: MIT
// satviz: the world's positions stage: bodies move, and fast bodies take their hits in time order (internal).
#pragma once

#include "box_grid.h"
#include "contact_solver.h"

#include <satviz/world.h>

#include <cstdint>
#include <queue>
#include <vector>

namespace satviz::detail
{

/// The sweep's rule for one body (WorldSettings::sweepFraction): a point of it moving at (v, w) can travel more
/// than sweepFraction of its inner radius within `span` time units.
bool OutrunsBody(const WorldSettings& settings, const RigidBody& body, Vec2 v, double w, double span);

/// The contacts' rule for one body (WorldSettings::speculativeTurn): turning at w, it turns farther within `span`
/// than a contact found at the start of the step follows (to first order), so the sweep holds its pairs, and the
/// position passes measure its overlaps afresh. A circle turning about its centre moves no point of its outline.
bool TurnsBeyondContacts(const WorldSettings& settings, const RigidBody& body, double w, double span);

/// The sweep's rule for a pair: a point of one body can travel, relative to the other, more than sweepFraction of
/// the smaller inner radius of the pair's dynamic bodies within `span`. Bodies that move together (a pile falling
/// as one) do not outrun each other. A body that does not move has velocities 0.
bool OutrunsPair(const WorldSettings& settings, const RigidBody& a, Vec2 va, double wa, const RigidBody& b, Vec2 vb,
                 double wb, double span);

/// Moves every awake body over the step. Fast bodies are swept first and their hits resolved in time order.
///
/// Outline (event-driven time of impact, after Mirtich's "Impulse-based dynamic simulation", 1996, and Catto's
/// "Continuous Collision", GDC 2013):
///  1. Each body keeps its own time within the step (0 at the start) and a pose at that time; it moves in a
///     straight line and turns at a constant rate between hits.
///  2. A body is fast when a point of it can move more than sweepFraction of its inner radius in the step. Its
///     reach (a box holding every place it can be within the step) is paired by sort and sweep with the bounds of
///     the other bodies. Every such pair whose bodies outrun each other (OutrunsPair) is swept, except the pairs the
///     step's contacts hold, which are left to them while neither body takes a hit nor turns faster than a contact
///     follows (speculativeTurn): the solver's contacts hold a pair only to first order, at the velocities it
///     solved. (The step gives a pair that outruns no speculative contact, so the solver does not take its bounce
///     early; a contact it has is one of shapes already touching.)
///  3. Each such pair is swept from the later of the two bodies' times: by Sweep when the turning of both moves no
///     point more than a quarter of the slop (exact for translation), else by conservative advancement: the SAT
///     gap, a lower bound of the distance, divided by the fastest approach any two points can make (relative
///     speed plus spin times outer radius), is a time the shapes cannot meet within; advance by it, until the gap
///     is within the slop.
///  4. The earliest hit of all is taken first: its two bodies move to that time, the hit is resolved with the
///     solver's impulses (restitution, static and dynamic friction), their stamps change (so their older hits are
///     dropped), and their pairs are swept again from that time.
///     Hits within a millionth of the step of each other are resolved together, as one step's contacts are.
///  5. A body that takes maxHitsPerBody hits stops where it is, at rest, for the rest of the step, and so does a
///     pair that conservative advancement cannot bring within the slop in kMaxAdvances passes. When the queue is
///     empty, every body moves on to the end of the step.
class TimeOfImpactStage
{
  public:
    /// The stage for `world`'s bodies, with the solved velocities of `solverBodies`, the
    /// transforms and the centres of mass at the start of the step. `near` holds each body's list of the bodies it
    /// is swept with; kept by the caller from step to step, the lists keep their memory.
    TimeOfImpactStage(World& world, double dt, const std::vector<Transform>& xfs, const std::vector<Vec2>& centers,
                      const std::vector<SolverBody>& solverBodies, std::vector<std::vector<int>>& near);
    /// Moves the bodies to the end of the step.
    void Run();
    /// Whether body i took a time-ordered hit in the step (after Run): its pose is the sweep's, not the one the
    /// step's contacts were solved for.
    bool TookHit(int i) const { return !m_hits.empty() && m_hits[static_cast<size_t>(i)] > 0; }
    /// Body i's rotation at the end of the step (after Run): MakeRot of its angle, computed once here for the
    /// position passes.
    Rot Rotation(int i) const { return m_rotation[static_cast<size_t>(i)]; }

  private:
    struct Motion
    {
        Vec2 center{};      // centre of mass at time t
        double angle = 0.0; // angle at time t
        double t = 0.0;     // the body's time, as a fraction of the step
        Vec2 v{};           // velocity
        double w = 0.0;     // turning rate
        bool moves = false; // an awake dynamic body
        // The velocity holds the gravity of the step up to this fraction of it: all of it for a body awake at the
        // start (the velocity passes gave it the whole step's), none for a body woken by a hit. A body stopped
        // short of a contact gives back the gravity of the rest of the step once, not again at a later stop.
        double fallsUntil = 0.0;
    };
    struct Event
    {
        double t = 0.0;
        int i = -1, j = -1;
        uint32_t stampI = 0, stampJ = 0;
        Vec2 normal{};
        Vec2 points[2]{};
        int count = 0;
    };
    struct Later
    {
        bool operator()(const Event& x, const Event& y) const
        {
            return x.t > y.t || (x.t == y.t && (x.i > y.i || (x.i == y.i && x.j > y.j)));
        }
    };

    Transform PoseAt(int i, double t) const;
    Vec2 CenterAt(int i, double t) const;
    double Speed(int i) const;
    bool IsFast(int i) const;
    bool TurnsFast(int i) const;
    Aabb Reach(int i, double speed) const;
    Aabb PathBox(int i, double t) const;
    bool Approaching(int i, int j, double t, Vec2 normal, const Vec2* points, int count, double minSpeed = 0.0,
                     const double* gaps = nullptr) const;
    double CloseSpeed(double t) const;
    // What sweeping a pair found: nothing to sweep, swept without a hit, or a hit (its event).
    enum class SweepOutcome : uint8_t
    {
        Skipped,
        Missed,
        Hit,
    };
    void SweepPair(int i, int j, bool anySpeed = false); // anySpeed: also a pair that is not fast
    SweepOutcome SweepPairEvent(int i, int j, bool anySpeed, Event& event) const;
    bool HeldByContact(int i, int j) const;
    bool Advance(int i, int j, double t0, Event& event) const;
    void Resolve(const std::vector<Event>& group);
    void Connect(int i, int j);
    void ConnectReach(int k);

    World& m_world;
    double m_dt;
    const std::vector<Transform>& m_xfs;
    std::vector<Motion> m_motion;
    std::vector<Rot> m_rotation; // each body's rotation at the end of the step (Run)
    std::vector<uint8_t> m_fast;
    std::vector<Aabb> m_reach;
    std::vector<uint8_t> m_connected; // m_near lists every body the reach meets
    std::vector<uint32_t> m_stamp;
    std::vector<int> m_hits;
    std::vector<std::vector<int>>& m_near;
    // The reaches, filed at the first body that must find every reach its own meets (ConnectReach).
    BoxGrid m_reachGrid;
    bool m_reachFiled = false;
    std::vector<int> m_met;
    std::priority_queue<Event, std::vector<Event>, Later> m_queue;
};

} // namespace satviz::detail
