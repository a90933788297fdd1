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
           a.material.staticFriction == b.material.staticFriction && SameShape(a.shape, b.shape) &&
           a.outline == b.outline && a.decompose == b.decompose; // a concave body's hull hides its notches
}

void PutHand(World& world, int body, Vec2 position, Vec2 velocity)
{
    RigidBody& held = world.bodies[static_cast<size_t>(body)];
    held.position = position;
    held.velocity = velocity;
    held.angularVelocity = 0.0;
    held.awake = true;
    held.sleepTime = 0.0;
}

} // namespace

bool SameWorld(const Scene& a, const Scene& b)
{
    return a.world.gravity == b.world.gravity && a.world.dt == b.world.dt &&
           std::equal(a.bodies.begin(), a.bodies.end(), b.bodies.begin(), b.bodies.end(), SameBody);
}

void Simulation::PutAside()
{
    aside_ = Run{
        std::move(start_), std::move(states_), std::move(samples_), sampleFirst_, std::move(hands_), first_, shown_};
}

void Simulation::TakeBack(Run& run)
{
    start_ = std::move(run.start);
    states_ = std::move(run.states);
    samples_ = std::move(run.samples);
    sampleFirst_ = run.sampleFirst;
    hands_ = std::move(run.hands);
    first_ = run.first;
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
            PutAside();
        }
        TakeBack(back);
        Record(back.shown);
        return;
    }
    if (tookSteps)
    {
        PutAside();
        haveAside_ = true;
    }
    start_ = scene;
    states_.clear();
    samples_.clear();
    sampleFirst_ = 0;
    hands_.clear();
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
    samples_.assign(record_.history.begin(), record_.history.end());
    shownScene_ = scene;
}

bool Simulation::StartedFrom(const Scene& scene) const
{
    return SameWorld(start_, scene);
}

// Makes the record of step `step` (which the history holds): the step before it taken again from its stored
// state, with the chosen pair recorded, and the hands of step `step` put back. The world is deterministic, so the
// step taken again gives the same bits as the stored state of `step`.
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
        record_.world = StateAt(shown_); // its hands are in the stored state
        record_.steps = shown_;
    }
    else
    {
        record_.world = StateAt(shown_ - 1);
        record_.steps = shown_ - 1;
        StepRecord(record_);
        const auto hands = hands_.find(shown_);
        if (hands != hands_.end())
        {
            for (const BodyHand& hand : hands->second)
            {
                PutHand(record_.world, hand.body, hand.position, hand.velocity);
            }
        }
    }
    SampleHistory(shown_);
    shownScene_ = start_;
    CopyWorldState(record_.world, shownScene_);
}

// The record's history: the samples held from the oldest to step `step`.
void Simulation::SampleHistory(int step)
{
    const size_t end = static_cast<size_t>(std::clamp(step - sampleFirst_ + 1, 0, static_cast<int>(samples_.size())));
    record_.history.assign(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(end));
}

void Simulation::TakeSample(const SimSample& sample)
{
    samples_.push_back(sample);
    while (samples_.size() > static_cast<size_t>(kMaxSamples))
    {
        samples_.pop_front();
        ++sampleFirst_;
    }
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
    TakeSample(record_.history.back());
    if (record_.history.size() > static_cast<size_t>(kMaxSamples))
    {
        record_.history.erase(record_.history.begin(),
                              record_.history.end() - static_cast<std::ptrdiff_t>(kMaxSamples));
    }
    shown_ = Last();
    Drop();
    CopyWorldState(record_.world, shownScene_);
}

void Simulation::Hand(int body, Vec2 position, Vec2 velocity)
{
    if (states_.empty() || !error_.empty() || body < 0 || body >= static_cast<int>(record_.world.bodies.size()) ||
        record_.world.bodies[static_cast<size_t>(body)].type == BodyType::Static)
    {
        return;
    }
    if (shown_ == 0)
    {
        StepForward(); // step 0 is the scene as written
    }
    // What came after the step shown came from the state without the hand: it is dropped.
    while (Last() > shown_)
    {
        states_.pop_back();
    }
    while (!samples_.empty() && sampleFirst_ + static_cast<int>(samples_.size()) - 1 > shown_)
    {
        samples_.pop_back();
    }
    hands_.erase(hands_.upper_bound(shown_), hands_.end());
    std::vector<BodyHand>& hands = hands_[shown_];
    const auto same = std::find_if(hands.begin(), hands.end(), [&](const BodyHand& h) { return h.body == body; });
    if (same != hands.end())
    {
        *same = BodyHand{body, position, velocity};
    }
    else
    {
        hands.push_back(BodyHand{body, position, velocity});
    }
    PutHand(states_.back(), body, position, velocity);
    PutHand(record_.world, body, position, velocity);
    // The plots' totals of this step are those of the state with the hand.
    const SimSample sample = MeasureWorld(record_.world, shown_);
    if (!samples_.empty() && sampleFirst_ + static_cast<int>(samples_.size()) - 1 == shown_)
    {
        samples_.back() = sample;
    }
    if (!record_.history.empty())
    {
        record_.history.back() = sample;
    }
    CopyWorldState(record_.world, shownScene_);
}

void Simulation::StepBack()
{
    if (shown_ > first_)
    {
        Record(shown_ - 1);
    }
}

// Drops the oldest states beyond the bounds (kMaxStates, kMaxBodyStates); the plots' samples have their own bound
// (kMaxSamples).
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
    // The state of the oldest step held has its hands in it; those of older steps are of no more use.
    hands_.erase(hands_.begin(), hands_.lower_bound(first_ + 1));
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
