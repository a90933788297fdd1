// SPDX-License-Identifier: MIT
// satviz render: a stepped world in words, as the app's simulation panel lists it beside the canvas: the step and
// its time, the contacts the world holds (a sleeping pair's kept from the last step it was awake) and each body's
// state. GL-free, like the step describers, so that the words can be tested against the world they describe.
#pragma once

#include <satviz/scene.h>
#include <satviz/sim_record.h>

#include <string>
#include <vector>

namespace satviz
{

/// One contact the world holds after the record's step, in the contact list.
struct WorldContactWords
{
    int a = -1;        ///< the lower-index body
    int b = -1;        ///< the other
    bool kept = false; ///< no body of the pair was awake as the step began: kept from the last step it was awake
    std::string text;  ///< "floor and box: 2 points, overlap 0.0051 and 0.0049", "... (kept)"
};

/// The world after the record's step, in words.
struct WorldWords
{
    std::string time;                        ///< "Step 23: time 0.383 s (dt 0.0167 s)"
    std::string contactsTitle;               ///< "Contacts held after step 23: 2"
    std::string contactsNote;                ///< what the overlaps, gaps and "kept" of the list mean
    std::vector<WorldContactWords> contacts; ///< every contact but the world's guards, in the world's order
    std::vector<std::string> bodies;         ///< one line per body: static, asleep, or awake with its motion
};

/// The record's world after its last step in words, each number as the response's sentences print it
/// (FormatNumber with kResponseDigits): a contact's overlap or gap per point as found at the start of the step,
/// "(kept)" for a pair with no body awake then, and per body its state, position, velocity and spin.
WorldWords DescribeWorld(const Scene& scene, const SimRecord& record);

} // namespace satviz
