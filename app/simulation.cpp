// SPDX-License-Identifier: MIT
#include "simulation.h"

#include <satviz/scene_world.h>

#include <algorithm>
#include <chrono>
#include <utility>

namespace satviz
{

namespace
{

bool SameShape(const Shape& a, const Shape& b)
{
    if (a.type != b.type)
    {
        return false;
    }
    if (a.type == ShapeType::Circle)
    {
        return a.circle.center == b.circle.center && a.circle.radius == b.circle.radius;
    }
    const auto va = a.polygon.Vertices();
    const auto vb = b.polygon.Vertices();
    return std::equal(va.begin(), va.end(), vb.begin(), vb.end());
}

bool SameBody(const Body& a, const Body& b)
{
    return a.position == b.position && a.angle == b.angle && a.velocity == b.velocity &&
           a.angularVelocity == b.angularVelocity && a.isStatic == b.isStatic && a.density == b.density &&
           a.material.restitution == b.material.restitution && a.material.friction == b.material.friction &&
           a.material.staticFriction == b.material.staticFriction && SameShape(a.shape, b.shape);
}

} // namespace

bool SameWorld(const Scene& a, const Scene& b)
{
    return a.world.gravity == b.world.gravity && a.world.dt == b.world.dt &&
           std::equal(a.bodies.begin(), a.bodies.end(), b.bodies.begin(), b.bodies.end(), SameBody);
}

void Simulation::Restart(const Scene& scene, int pairA, int pairB)
{
    pairA_ = pairA;
    pairB_ = pairB;
    playing_ = false;
    clock_ = 0.0;
    // An undo of an edit made at a step gives back the scene the run before started from: that run comes back.
    const bool tookSteps = !states_.empty() && Last() > 0;
    if (haveAside_ && SameWorld(aside_.start, scene))
    {
        Run back = std::move(aside_);
        haveAside_ = tookSteps;
        if (tookSteps)
        {
            aside_ = Run{std::move(start_), std::move(states_), std::move(samples_), first_, shown_};
        }
        start_ = std::move(back.start);
        states_ = std::move(back.states);
        samples_ = std::move(back.samples);
        first_ = back.first;
        Record(back.shown);
        return;
    }
    if (tookSteps)
    {
        aside_ = Run{std::move(start_), std::move(states_), std::move(samples_), first_, shown_};
        haveAside_ = true;
    }
    start_ = scene;
    states_.clear();
    samples_.clear();
    first_ = 0;
    shown_ = 0;
    error_ = ValidateSceneWorld(scene);
    if (!error_.empty())
    {
        record_ = SimRecord{};
        shownScene_ = scene;
        return;
    }
    record_ = StartRecord(scene, pairA_, pairB_);
    states_.push_back(record_.world);
    samples_ = record_.history;
    shownScene_ = scene;
}

bool Simulation::StartedFrom(const Scene& scene) const
{
    return SameWorld(start_, scene);
}

// Makes the record of step `step` (which the history holds): the step before it taken again from its stored
// state, with the chosen pair recorded. The world is deterministic, so the step taken again gives the same bits
// as the stored state of `step`.
void Simulation::Record(int step)
{
    shown_ = std::clamp(step, first_, Last());
    if (!error_.empty())
    {
        return;
    }
    record_.contact = ContactSolveTrace{};
    record_.contact.bodyA = pairA_;
    record_.contact.bodyB = pairB_;
    record_.lastStep.Clear();
    record_.before.clear();
    if (shown_ == first_)
    {
        record_.world = StateAt(shown_);
        record_.steps = shown_;
        record_.history.assign(samples_.begin(), samples_.begin() + shown_ + 1);
    }
    else
    {
        record_.world = StateAt(shown_ - 1);
        record_.steps = shown_ - 1;
        record_.history.assign(samples_.begin(), samples_.begin() + shown_);
        StepRecord(record_);
    }
    shownScene_ = start_;
    CopyWorldState(record_.world, shownScene_);
}

void Simulation::ShowStep(int step)
{
    if (states_.empty())
    {
        return;
    }
    Record(step);
}

void Simulation::StepForward()
{
    if (states_.empty() || !error_.empty())
    {
        return;
    }
    if (shown_ < Last())
    {
        Record(shown_ + 1);
        return;
    }
    // The latest step: take a new one from the record of the step shown, whose world is the latest state.
    record_.contact = ContactSolveTrace{};
    record_.contact.bodyA = pairA_;
    record_.contact.bodyB = pairB_;
    StepRecord(record_);
    states_.push_back(record_.world);
    samples_.push_back(record_.history.back());
    shown_ = Last();
    Drop();
    CopyWorldState(record_.world, shownScene_);
}

void Simulation::StepBack()
{
    if (shown_ > first_)
    {
        Record(shown_ - 1);
    }
}

// Drops the oldest states beyond the bounds (kMaxStates, kMaxBodyStates); the samples of every step stay for the
// plots.
void Simulation::Drop()
{
    const long long bodies = std::max<long long>(1, static_cast<long long>(start_.bodies.size()));
    const size_t most =
        static_cast<size_t>(std::max<long long>(2, std::min<long long>(kMaxStates, kMaxBodyStates / bodies)));
    while (states_.size() > most)
    {
        states_.pop_front();
        ++first_;
    }
}

void Simulation::SetPlaying(bool playing)
{
    playing_ = playing && error_.empty() && !states_.empty();
    clock_ = 0.0;
}

void Simulation::SetSpeed(double stepsPerSecond)
{
    speed_ = std::clamp(stepsPerSecond, 1.0, 240.0);
}

bool Simulation::Advance(double seconds)
{
    if (!playing_)
    {
        return false;
    }
    clock_ += seconds;
    const double interval = 1.0 / speed_;
    // Several steps in one frame keep the speed when the frames are slower than the steps, as long as they are
    // cheap: past kStepBudget seconds of stepping the simulation runs slower instead, so that a large world does
    // not slow the frames down further.
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    int taken = 0;
    while (clock_ >= interval && taken < 4 &&
           (taken == 0 || std::chrono::duration<double>(Clock::now() - start).count() < kStepBudget))
    {
        clock_ -= interval;
        StepForward();
        ++taken;
    }
    clock_ = std::min(clock_, interval);
    return taken > 0;
}

double Simulation::SecondsUntilNextStep() const
{
    return std::max(0.0, 1.0 / speed_ - clock_);
}

void Simulation::ChoosePair(int pairA, int pairB)
{
    if (pairA == pairA_ && pairB == pairB_)
    {
        return;
    }
    pairA_ = pairA;
    pairB_ = pairB;
    if (!states_.empty())
    {
        Record(shown_);
    }
}

} // namespace satviz
