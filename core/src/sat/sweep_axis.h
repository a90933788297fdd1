// SPDX-License-Identifier: MIT
// satviz (private), chapter 10: one face's entry and exit, the rule of the swept test (Ericson, Real-Time Collision
// Detection, 5.5.2). Between shapes that translate, a face's separation changes linearly with time: the shapes'
// intervals on the face's normal begin to overlap at its entry and stop overlapping at its exit. First the rule for one axis as the textbook writes it
// (AxisTimes), then the same rule for four axes at once, in lanes and without branches (AxisLanes), which the face
// loops of the sweep use.
#pragma once

#include <satviz/math.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace satviz::detail
{

// No entry yet (negated), or no exit.
template <typename S>
constexpr S kInfinity = std::numeric_limits<S>::infinity();

// Entry and exit times of one axis whose separation is `separation` at t = 0 and changes by `rate` per unit of
// t; false when the axis never closes (it separates or only touches, and does not approach).
template <typename S>
bool AxisTimes(S separation, S rate, S& entry, S& exit)
{
    entry = S(0);
    exit = kInfinity<S>;
    if (separation >= S(0))
    {
        if (rate >= S(0))
        {
            return false;
        }
        entry = separation / -rate;
    }
    else if (rate > S(0))
    {
        exit = -separation / rate;
    }
    return true;
}

// The rate below which the motion counts as parallel to a face: a few roundings of Dot(n, v) with |n| = 1.
template <typename S>
S StillRate(Vec2T<S> velocity)
{
    return S(8) * std::numeric_limits<S>::epsilon() * std::max(std::abs(velocity.x), std::abs(velocity.y));
}

// The rates, with those within `still` of 0 set to 0 (StillRate).
template <typename L, typename S>
L Moving(const L& rate, S still)
{
    return Select(Max(rate, -rate) > L::Fill(still), rate, L::Fill(S(0)));
}

// Entry, exit and whether the axis never closes, for four axes at once (the per-axis rule of AxisTimes, without
// branches). A rate within `still` of 0 is 0: the motion runs along the face as far as its rounding can tell, so
// touching and sliding along a face is no hit. With q = s / -r: s >= 0 enters at q (r < 0) or never (r >= 0);
// s < 0 is overlapping from t = 0 (no entry: -infinity, so that a face touching at t = 0, whose entry is 0, is the
// latest entry rather than any overlapping face) and, when r > 0, exits at q.
template <typename L>
struct AxisLanes
{
    using S = std::decay_t<decltype(std::declval<L>().Get(0))>;
    L entry;
    L leave;
    typename L::Mask apart;
    typename L::Mask never;

    AxisLanes(const L& separation, const L& rawRate, S still)
    {
        const L zero = L::Fill(0);
        const L rate = Moving(rawRate, still);
        apart = separation >= zero;
        const L q = separation / -rate;
        const L infinity = L::Fill(std::numeric_limits<S>::infinity());
        entry = Select(apart, q, -infinity);
        leave = Select(~apart & (rate > zero), q, infinity);
        never = apart & (rate >= zero);
    }
};

} // namespace satviz::detail
