// SPDX-License-Identifier: MIT
// satviz app: the simulation of the document's scene: its world stepped from the scene as written, a bounded
// history of the world's states for the time slider and the step back, and the record of the step shown (its
// boxes, pairs and hits, and the solver's work on the chosen pair) that the world's layers draw. No ImGui here.
#pragma once

#include <satviz/scene.h>
#include <satviz/sim_record.h>
#include <satviz/world.h>

#include <deque>
#include <map>
#include <string>
#include <vector>

namespace satviz
{

/// A scene stepped as a world one step at a time, with the states it went through. Step 0 is the scene as written;
/// step k is k steps of its dt later, the same bits satviz-sim prints for step k.
class Simulation
{
  public:
    /// Most world states the history holds; older ones are dropped, and the slider starts at the oldest held.
    static constexpr int kMaxStates = 1000;
    /// Most body states (bodies times steps) the history holds, so that a large world keeps fewer steps:
    /// 500 bodies keep 400 steps, 2000 bodies 100.
    static constexpr long long kMaxBodyStates = 200000;
    /// Seconds of stepping in one frame beyond which Advance takes no further step in that frame.
    static constexpr double kStepBudget = 0.004;
    /// Most steps whose totals (SimSample) the plots keep: the latest ones, a minute at 60 steps a second; older
    /// ones are dropped as new steps are taken.
    static constexpr int kMaxSamples = 3600;

    /// Starts over from `scene` at step 0, paused, recording the solver's work on the pair (pairA, pairB). The run
    /// it replaces is kept aside when it took steps, and comes back, at the step it showed, when a later Restart
    /// gives the scene it started from (undoing an edit made at a step). A scene that is not a valid world leaves
    /// the simulation empty, Error() saying why.
    void Restart(const Scene& scene, int pairA, int pairB);
    /// True when the simulation was started from a scene with the same bodies, materials and world as `scene`.
    bool StartedFrom(const Scene& scene) const;
    /// Why the scene cannot be stepped; empty when it can.
    const std::string& Error() const { return m_error; }

    /// The step shown.
    int Shown() const { return m_shown; }
    /// The oldest step the history still holds.
    int First() const { return m_first; }
    /// The latest step taken.
    int Last() const { return m_first + static_cast<int>(m_states.size()) - 1; }
    /// Shows step `step`, clamped to [First(), Last()].
    void ShowStep(int step);
    /// Shows the next step, taking it when it is the latest.
    void StepForward();
    /// Shows the step before, when the history holds it.
    void StepBack();

    /// True while playing.
    bool Playing() const { return m_playing; }
    /// Plays or pauses.
    void SetPlaying(bool playing);
    /// Steps per second while playing.
    double Speed() const { return m_speed; }
    /// Sets the steps per second, in [1, 240].
    void SetSpeed(double stepsPerSecond);
    /// Lets `seconds` pass: while playing, one step every 1 / Speed() seconds (at most four in one call, and more
    /// than one only while they take less than kStepBudget, so that a slow frame does not make the next one
    /// slower). True when the step shown changed.
    bool Advance(double seconds);
    /// While playing, the seconds until Advance takes the next step.
    double SecondsUntilNextStep() const;

    /// A hand on body `body` (a grab and a throw with the mouse while playing): in the state of the step shown it
    /// is at `position` moving at `velocity`, without spin, and awake; the steps taken from there start from that
    /// state. A hand at step 0 (the scene as written) acts on step 1, taken first. The steps after the one shown
    /// are dropped; the hand is kept with its step, so that stepping back and forward again shows the same
    /// states. A static body, or a body that does not exist, takes no hand.
    void Hand(int body, Vec2 position, Vec2 velocity);

    /// Records the solver's work on the pair (pairA, pairB) in the step shown.
    void ChoosePair(int pairA, int pairB);
    /// The world at the step shown, with the record of the step that led to it (none at step 0).
    const SimRecord& Record() const { return m_record; }
    /// The scene with its bodies where the world has them at the step shown.
    const Scene& ShownScene() const { return m_shownScene; }
    /// The world's state at step `step`, which the history must hold.
    const World& StateAt(int step) const { return m_states[static_cast<size_t>(step - m_first)]; }

  private:
    /// A hand on a body at one step (Hand).
    struct BodyHand
    {
        int body = -1;
        Vec2 position{};
        Vec2 velocity{};
    };

    /// One run: a start scene and the states it went through.
    struct Run
    {
        Scene start;
        std::deque<World> states;
        std::deque<SimSample> samples;
        int sampleFirst = 0;
        std::map<int, std::vector<BodyHand>> hands;
        int first = 0;
        int shown = 0;
    };

    void Record(int step);
    void Drop();
    void TakeSample(const SimSample& sample);
    void SampleHistory(int step);
    void PutAside();
    void TakeBack(Run& run);

    Scene m_start;
    std::string m_error;
    std::deque<World> m_states;      // m_states[i] is the world at step m_first + i
    std::deque<SimSample> m_samples; // the totals of the steps from m_sampleFirst to Last(), at most kMaxSamples
    int m_sampleFirst = 0;
    std::map<int, std::vector<BodyHand>> m_hands; // the hands each step took, by step
    int m_first = 0;
    int m_shown = 0;
    int m_pairA = -1;
    int m_pairB = -1;
    bool m_playing = false;
    double m_speed = 60.0;
    double m_clock = 0.0;
    SimRecord m_record;
    Scene m_shownScene;
    bool m_haveAside = false;
    Run m_aside;
};

/// What the simulation panel says of the steps taken, beside the step shown (`shown`, of `last` taken): "135 steps
/// taken" at the latest; back at step 0 (Reset), that the world is back at its start after them; at another step
/// before the latest, which of them it is. Forward and the slider go through the steps taken again.
std::string StepsTakenWords(int shown, int last);

/// True when both scenes make the same world: the same bodies (shapes, states, static or dynamic, densities,
/// materials) in the same order, and the same gravity and dt.
bool SameWorld(const Scene& a, const Scene& b);

} // namespace satviz
