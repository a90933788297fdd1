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
    m_aside = Run{
        std::move(m_start), std::move(m_states), std::move(m_samples), m_sampleFirst, std::move(m_hands), m_first, m_shown};
}

void Simulation::TakeBack(Run& run)
{
    m_start = std::move(run.start);
    m_states = std::move(run.states);
    m_samples = std::move(run.samples);
    m_sampleFirst = run.sampleFirst;
    m_hands = std::move(run.hands);
    m_first = run.first;
}

void Simulation::Restart(const Scene& scene, int pairA, int pairB)
{
    m_pairA = pairA;
    m_pairB = pairB;
    m_playing = false;
    m_clock = 0.0;
    // An undo of an edit made at a step gives back the scene the run before started from: that run comes back.
    const bool tookSteps = !m_states.empty() && Last() > 0;
    if (m_haveAside && SameWorld(m_aside.start, scene))
    {
        Run back = std::move(m_aside);
        m_haveAside = tookSteps;
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
        m_haveAside = true;
    }
    m_start = scene;
    m_states.clear();
    m_samples.clear();
    m_sampleFirst = 0;
    m_hands.clear();
    m_first = 0;
    m_shown = 0;
    m_error = ValidateSceneWorld(scene);
    if (!m_error.empty())
    {
        m_record = SimRecord{};
        m_shownScene = scene;
        return;
    }
    m_record = StartRecord(scene, m_pairA, m_pairB);
    m_states.push_back(m_record.world);
    m_samples.assign(m_record.history.begin(), m_record.history.end());
    m_shownScene = scene;
}

bool Simulation::StartedFrom(const Scene& scene) const
{
    return SameWorld(m_start, scene);
}

// Makes the record of step `step` (which the history holds): the step before it taken again from its stored
// state, with the chosen pair recorded, and the hands of step `step` put back. The world is deterministic, so the
// step taken again gives the same bits as the stored state of `step`.
void Simulation::Record(int step)
{
    m_shown = std::clamp(step, m_first, Last());
    if (!m_error.empty())
    {
        return;
    }
    m_record.contact = ContactSolveTrace{};
    m_record.contact.bodyA = m_pairA;
    m_record.contact.bodyB = m_pairB;
    m_record.lastStep.Clear();
    m_record.before.clear();
    if (m_shown == m_first)
    {
        m_record.world = StateAt(m_shown); // its hands are in the stored state
        m_record.steps = m_shown;
    }
    else
    {
        m_record.world = StateAt(m_shown - 1);
        m_record.steps = m_shown - 1;
        StepRecord(m_record);
        const auto hands = m_hands.find(m_shown);
        if (hands != m_hands.end())
        {
            for (const BodyHand& hand : hands->second)
            {
                PutHand(m_record.world, hand.body, hand.position, hand.velocity);
            }
        }
    }
    SampleHistory(m_shown);
    m_shownScene = m_start;
    CopyWorldState(m_record.world, m_shownScene);
}

// The record's history: the samples held from the oldest to step `step`.
void Simulation::SampleHistory(int step)
{
    const size_t end = static_cast<size_t>(std::clamp(step - m_sampleFirst + 1, 0, static_cast<int>(m_samples.size())));
    m_record.history.assign(m_samples.begin(), m_samples.begin() + static_cast<std::ptrdiff_t>(end));
}

void Simulation::TakeSample(const SimSample& sample)
{
    m_samples.push_back(sample);
    while (m_samples.size() > static_cast<size_t>(kMaxSamples))
    {
        m_samples.pop_front();
        ++m_sampleFirst;
    }
}

void Simulation::ShowStep(int step)
{
    if (m_states.empty())
    {
        return;
    }
    Record(step);
}

void Simulation::StepForward()
{
    if (m_states.empty() || !m_error.empty())
    {
        return;
    }
    if (m_shown < Last())
    {
        Record(m_shown + 1);
        return;
    }
    // The latest step: take a new one from the record of the step shown, whose world is the latest state.
    m_record.contact = ContactSolveTrace{};
    m_record.contact.bodyA = m_pairA;
    m_record.contact.bodyB = m_pairB;
    StepRecord(m_record);
    m_states.push_back(m_record.world);
    TakeSample(m_record.history.back());
    if (m_record.history.size() > static_cast<size_t>(kMaxSamples))
    {
        m_record.history.erase(m_record.history.begin(),
                              m_record.history.end() - static_cast<std::ptrdiff_t>(kMaxSamples));
    }
    m_shown = Last();
    Drop();
    CopyWorldState(m_record.world, m_shownScene);
}

void Simulation::Hand(int body, Vec2 position, Vec2 velocity)
{
    if (m_states.empty() || !m_error.empty() || body < 0 || body >= static_cast<int>(m_record.world.bodies.size()) ||
        m_record.world.bodies[static_cast<size_t>(body)].type == BodyType::Static)
    {
        return;
    }
    if (m_shown == 0)
    {
        StepForward(); // step 0 is the scene as written
    }
    // What came after the step shown came from the state without the hand: it is dropped.
    while (Last() > m_shown)
    {
        m_states.pop_back();
    }
    while (!m_samples.empty() && m_sampleFirst + static_cast<int>(m_samples.size()) - 1 > m_shown)
    {
        m_samples.pop_back();
    }
    m_hands.erase(m_hands.upper_bound(m_shown), m_hands.end());
    std::vector<BodyHand>& hands = m_hands[m_shown];
    const auto same = std::find_if(hands.begin(), hands.end(), [&](const BodyHand& h) { return h.body == body; });
    if (same != hands.end())
    {
        *same = BodyHand{body, position, velocity};
    }
    else
    {
        hands.push_back(BodyHand{body, position, velocity});
    }
    PutHand(m_states.back(), body, position, velocity);
    PutHand(m_record.world, body, position, velocity);
    // The plots' totals of this step are those of the state with the hand.
    const SimSample sample = MeasureWorld(m_record.world, m_shown);
    if (!m_samples.empty() && m_sampleFirst + static_cast<int>(m_samples.size()) - 1 == m_shown)
    {
        m_samples.back() = sample;
    }
    if (!m_record.history.empty())
    {
        m_record.history.back() = sample;
    }
    CopyWorldState(m_record.world, m_shownScene);
}

void Simulation::StepBack()
{
    if (m_shown > m_first)
    {
        Record(m_shown - 1);
    }
}

// Drops the oldest states beyond the bounds (kMaxStates, kMaxBodyStates); the plots' samples have their own bound
// (kMaxSamples).
void Simulation::Drop()
{
    const long long bodies = std::max<long long>(1, static_cast<long long>(m_start.bodies.size()));
    const size_t most =
        static_cast<size_t>(std::max<long long>(2, std::min<long long>(kMaxStates, kMaxBodyStates / bodies)));
    while (m_states.size() > most)
    {
        m_states.pop_front();
        ++m_first;
    }
    // The state of the oldest step held has its hands in it; those of older steps are of no more use.
    m_hands.erase(m_hands.begin(), m_hands.lower_bound(m_first + 1));
}

void Simulation::SetPlaying(bool playing)
{
    m_playing = playing && m_error.empty() && !m_states.empty();
    m_clock = 0.0;
}

void Simulation::SetSpeed(double stepsPerSecond)
{
    m_speed = std::clamp(stepsPerSecond, 1.0, 240.0);
}

bool Simulation::Advance(double seconds)
{
    if (!m_playing)
    {
        return false;
    }
    m_clock += seconds;
    const double interval = 1.0 / m_speed;
    // Several steps in one frame keep the speed when the frames are slower than the steps, as long as they are
    // cheap: past kStepBudget seconds of stepping the simulation runs slower instead, so that a large world does
    // not slow the frames down further.
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    int taken = 0;
    while (m_clock >= interval && taken < 4 &&
           (taken == 0 || std::chrono::duration<double>(Clock::now() - start).count() < kStepBudget))
    {
        m_clock -= interval;
        StepForward();
        ++taken;
    }
    m_clock = std::min(m_clock, interval);
    return taken > 0;
}

double Simulation::SecondsUntilNextStep() const
{
    return std::max(0.0, 1.0 / m_speed - m_clock);
}

void Simulation::ChoosePair(int pairA, int pairB)
{
    if (pairA == m_pairA && pairB == m_pairB)
    {
        return;
    }
    m_pairA = pairA;
    m_pairB = pairB;
    if (!m_states.empty())
    {
        Record(m_shown);
    }
}

std::string StepsTakenWords(int shown, int last)
{
    const std::string steps = std::to_string(last) + (last == 1 ? " step" : " steps");
    if (last == 0)
    {
        return "no step taken yet";
    }
    if (shown >= last)
    {
        return steps + " taken";
    }
    if (shown == 0)
    {
        return "back at the start, the scene as written, after " + steps +
               ": Forward and the slider go through them again";
    }
    return "back at step " + std::to_string(shown) + " of the " + steps + " taken";
}

} // namespace satviz
