// SPDX-License-Identifier: MIT
// satviz render: the solver's response to one contact, step by step, in a textbook's words (lessons 14 and 16):
// each step one sentence whose numbers a student can check by hand from the ones before it. The figures' response
// panel draws these; the app can list them beside its canvas.
#pragma once

#include <satviz/scene.h>
#include <satviz/sim_record.h>

#include <string>
#include <vector>

namespace satviz
{

/// The significant digits the response's numbers have at least, in its sentences, its arrows' labels and its table
/// of passes alike: FormatNumber(value, kResponseDigits) shows an impulse of 0.0102 as 0.0102, not 0.01.
constexpr int kResponseDigits = 3;

/// A number as the response and the world panel print it: kResponseDigits significant digits, a whole number of
/// five digits or more in groups of three as the figures' labels write it ("100 000"), and a round-off residue
/// (below 1e-12 of the value itself) shown as 0.
std::string FormatResponseNumber(double value);

/// A vector as the response and the world panel print it: "(x, y)", each part as FormatResponseNumber, with a
/// residue below 1e-12 of the larger part shown as 0 (a velocity of (2.918, -2.78e-17) reads (2.92, 0.00)).
std::string FormatResponseVector(Vec2 v);

/// One step of the response: a short title ("Approach", "Effective mass", ...) and its sentence.
struct ResponseStep
{
    std::string title;    ///< two or three words
    std::string sentence; ///< what the solver did, with its numbers
};

/// The passes of the solver over one point of the contact: the impulse each pass asked for and what it kept.
struct ResponsePasses
{
    std::vector<double> wanted; ///< accumulated normal impulse each pass asked for, before the clamp
    std::vector<double> kept;   ///< after the clamp to >= 0 (a contact only pushes)
};

/// The solver's work on the record's chosen pair in its last step, from the record alone (World's step, stage 2):
/// the contact, the approach speed along the normal, the effective mass, the restitution target, the passes, the
/// bounce, friction against its static and dynamic limits ("sticks" or "slides"), and each body's velocity and spin
/// before and after. When the pair had no contact in the step, one step says so (and when they hit within it).
std::vector<ResponseStep> DescribeResponse(const Scene& scene, const SimRecord& record);

/// The last velocity pass of the solver over contact point `point` in `trace` (a time-ordered hit's own solve is not
/// a pass); nullptr when it has none.
const ContactPointSolve* LastPass(const ContactSolveTrace& trace, int point);

/// The normal impulse of every velocity pass over contact point `point` of the last step (empty without a contact).
ResponsePasses ResponsePassesOf(const SimRecord& record, int point);

} // namespace satviz
