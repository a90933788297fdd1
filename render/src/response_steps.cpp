// SPDX-License-Identifier: MIT
#include <satviz/render/describe.h>
#include <satviz/render/response_steps.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

namespace satviz
{

namespace
{

std::string N(double value)
{
    return FormatResponseNumber(value);
}

std::string V(Vec2 v)
{
    return FormatResponseVector(v);
}

// A number as N prints it, read back: a speed printed as 0.00 is no approach.
double Shown(double value)
{
    return std::strtod(N(value).c_str(), nullptr);
}

// The unit of the last digit of a printed number: 0.01 for 0.45, 1e-5 for 0.00511, 1e-6 for 2.5e-5.
double LastDigit(const std::string& text)
{
    const size_t e = text.find('e');
    const std::string mantissa = text.substr(0, e);
    const int exponent = e == std::string::npos ? 0 : std::atoi(text.c_str() + e + 1);
    const size_t point = mantissa.find('.');
    const int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
    return std::pow(10.0, exponent - decimals);
}

// `value` printed as N prints it with `extra` more decimals, the zeros this adds at its end dropped again (2.6 stays
// "2.60", 1.0472 becomes "1.0472"); a number N prints with an exponent stays as N prints it.
std::string Finer(double value, int extra)
{
    const std::string base = N(value);
    const size_t point = base.find('.');
    if (extra == 0 || point == std::string::npos || base.find('e') != std::string::npos || Shown(value) == 0.0)
    {
        return base;
    }
    const int decimals = static_cast<int>(base.size() - point - 1);
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.*f", decimals + extra, value);
    std::string text = buffer;
    while (static_cast<int>(text.size() - point - 1) > decimals && text.back() == '0')
    {
        text.pop_back();
    }
    return text;
}

// A computation a sentence writes out, as printed: its numbers and its result.
struct Written
{
    std::vector<std::string> numbers;
    std::string result;
};

// The numbers of a computation ("2.60 x 1.0472 = 2.723"), printed with as few more digits as it takes for `redo`
// on the numbers as printed, rounded to the digits of the result, to give the printed result, the solver's `value`:
// a student checking it by hand gets what is printed. Where no number of digits does (a value on a rounding edge),
// the numbers as N prints them and the result redone from them.
Written Computation(const std::vector<double>& numbers, double value,
                    const std::function<double(const std::vector<double>&)>& redo)
{
    const std::string result = N(value);
    Written written;
    for (int extra = 0; extra <= 6; ++extra)
    {
        written.numbers.clear();
        std::vector<double> shown;
        for (const double x : numbers)
        {
            written.numbers.push_back(Finer(x, extra));
            shown.push_back(std::strtod(written.numbers.back().c_str(), nullptr));
        }
        if (std::fabs(redo(shown) - Shown(value)) <= 0.5 * LastDigit(result) * (1.0 + 1e-9))
        {
            written.result = result;
            return written;
        }
    }
    written.numbers.clear();
    std::vector<double> shown;
    for (const double x : numbers)
    {
        written.numbers.push_back(N(x));
        shown.push_back(Shown(x));
    }
    written.result = N(redo(shown));
    return written;
}

double Product(const std::vector<double>& x)
{
    return x[0] * x[1];
}

double Sum(const std::vector<double>& x)
{
    double sum = 0.0;
    for (const double term : x)
    {
        sum += term;
    }
    return sum;
}

double Reciprocal(const std::vector<double>& x)
{
    return 1.0 / Sum(x);
}

// "a x b = c", as Computation prints it.
std::string Times(double a, double b, double value)
{
    const Written w = Computation({a, b}, value, Product);
    return w.numbers[0] + " x " + w.numbers[1] + " = " + w.result;
}

const WorldContact* FindWorldContact(const World& world, int a, int b)
{
    for (const WorldContact& c : world.contacts)
    {
        if (c.a == a && c.b == b)
        {
            return &c;
        }
    }
    return nullptr;
}

std::string Name(const Scene& scene, int body)
{
    return body >= 0 && static_cast<size_t>(body) < scene.bodies.size() ? scene.bodies[static_cast<size_t>(body)].name
                                                                        : "body " + std::to_string(body);
}

} // namespace

ResponsePasses ResponsePassesOf(const SimRecord& record, int point)
{
    ResponsePasses passes;
    for (const ContactPointSolve& pass : record.contact.passes)
    {
        if (pass.point == point && pass.pass >= 0)
        {
            passes.wanted.push_back(pass.normalImpulseWanted);
            passes.kept.push_back(pass.normalImpulse);
        }
    }
    return passes;
}

// Round-off leaves residues like -2.78e-17 where the arithmetic gives 0; printed, they read as real numbers a
// student cannot reproduce, so anything below 1e-12 of the scale it sits beside is shown as 0.
static double Clean(double value, double scale)
{
    return std::fabs(value) <= 1e-12 * std::max(1.0, std::fabs(scale)) ? 0.0 : value;
}

std::string FormatResponseNumber(double value)
{
    return FormatNumber(Clean(value, value), kResponseDigits);
}

std::string FormatResponseVector(Vec2 v)
{
    const double scale = std::max(std::fabs(v.x), std::fabs(v.y));
    return "(" + FormatNumber(Clean(v.x, scale), kResponseDigits) + ", " +
           FormatNumber(Clean(v.y, scale), kResponseDigits) + ")";
}

const ContactPointSolve* LastPass(const ContactSolveTrace& trace, int point)
{
    const ContactPointSolve* last = nullptr;
    for (const ContactPointSolve& pass : trace.passes)
    {
        if (pass.point == point && pass.pass >= 0)
        {
            last = &pass;
        }
    }
    return last;
}

std::vector<ResponseStep> DescribeResponse(const Scene& scene, const SimRecord& record)
{
    std::vector<ResponseStep> steps;
    const ContactSolveTrace& trace = record.contact;
    const int lo = std::min(trace.bodyA, trace.bodyB);
    const int hi = std::max(trace.bodyA, trace.bodyB);
    const std::string a = Name(scene, lo);
    const std::string b = Name(scene, hi);
    const std::string when = "step " + std::to_string(record.steps);
    if (lo < 0 || hi >= static_cast<int>(record.world.bodies.size()) || lo == hi)
    {
        steps.push_back({"No pair", "No pair of bodies is chosen for the response."});
        return steps;
    }
    if (!trace.found)
    {
        // A pair that approaches is farther apart than it can close in the step; one whose centres move apart (after
        // a bounce) closes nothing, and saying "close" there would read as if they still came together.
        const std::vector<RigidBody>& start = record.before.empty() ? record.world.bodies : record.before;
        const RigidBody& first = start[static_cast<size_t>(lo)];
        const RigidBody& second = start[static_cast<size_t>(hi)];
        const bool parting = Dot(second.position - first.position, second.velocity - first.velocity) > 0.0;
        std::string sentence = "In " + when + " " + a + " and " + b + " had no contact: " +
                               (parting ? "they were apart at its start and their centres were moving apart."
                                        : "they were farther apart than they could close within the step.");
        // A pair with no body awake keeps its contact from the step it fell asleep in, but the world neither tests
        // nor solves it: saying they were apart would contradict the contact drawn.
        const auto resting = [&](int i) {
            const RigidBody& body = start[static_cast<size_t>(i)];
            return body.type == BodyType::Static || !body.awake;
        };
        std::string heading = "No contact";
        if (resting(lo) && resting(hi))
        {
            // Their contact is held (and drawn): the heading says why it is not solved, not that there is none.
            heading = "Resting, not solved";
            sentence = "In " + when + " " + a + " and " + b + " were asleep (or static): the world neither tests " +
                       "nor solves their contact, and they rest where they are until something touches them.";
        }
        else if (trace.hits > 0)
        {
            sentence = "In " + when + " " + a + " and " + b + " had no contact at its start, but the sweep found " +
                       std::to_string(trace.hits) + (trace.hits == 1 ? " hit" : " hits") + ", the first at " +
                       N(trace.hitTime) + " of the step (see the hits layer).";
        }
        steps.push_back({heading, sentence});
        return steps;
    }
    const RigidBody& bodyA = record.world.bodies[static_cast<size_t>(lo)];
    const RigidBody& bodyB = record.world.bodies[static_cast<size_t>(hi)];
    const WorldContact* contact = FindWorldContact(record.world, lo, hi);
    const double separation = contact != nullptr ? contact->points[0].separation : 0.0;
    const int points = trace.pointCount;
    std::string kind =
        separation > 0.0
            ? "are " + N(separation) + " m apart, closer than they can move within the step: a " + "speculative contact"
            : "touch";
    steps.push_back({"Contact", "At the start of " + when + ", " + a + " and " + b + " " + kind +
                                    "; the normal n = " + V(trace.normal) + " points from " + a + " to " + b + "; " +
                                    std::to_string(points) + (points == 1 ? " contact point." : " contact points.")});

    const double vn = trace.approachSpeed[0];
    std::string approach =
        "vn = (v" + b + " - v" + a + ") . n at the point = " + N(vn) + " m/s, before the step's " + "gravity: ";
    approach += Shown(vn) < 0.0 ? "they approach at " + N(-vn) + " m/s." : "they do not approach.";
    if (points == 2)
    {
        approach += " At point 2: " + N(trace.approachSpeed[1]) + " m/s.";
    }
    steps.push_back({"Approach", approach});

    // The turning terms from the point's lever arms at the start of the step (lesson 16): (r x n)^2 / I per body.
    double turning = 0.0;
    if (contact != nullptr && record.before.size() == record.world.bodies.size())
    {
        const RigidBody& startA = record.before[static_cast<size_t>(lo)];
        const RigidBody& startB = record.before[static_cast<size_t>(hi)];
        const Vec2 rA = contact->points[0].point - startA.WorldCenter();
        const Vec2 rB = contact->points[0].point - startB.WorldCenter();
        const double rnA = Cross(rA, trace.normal), rnB = Cross(rB, trace.normal);
        turning = rnA * rnA * startA.invInertia + rnB * rnB * startB.invInertia;
    }
    const Written inverse = Computation({bodyA.invMass, bodyB.invMass, turning}, trace.normalMass[0], Reciprocal);
    std::string mass = "m_eff = 1 / (1/m" + a + " + 1/m" + b + " + (rA x n)^2/IA + (rB x n)^2/IB) = 1 / (" +
                       inverse.numbers[0] + " + " + inverse.numbers[1] + " + " + inverse.numbers[2] +
                       ") = " + inverse.result + " kg";
    mass += bodyA.invMass == 0.0 || bodyB.invMass == 0.0 ? " (a static body adds 0)." : ".";
    steps.push_back({"Effective mass", mass});

    const double threshold = record.world.settings.restitutionThreshold;
    std::string target;
    if (trace.bounceSpeed[0] > 0.0)
    {
        const Written leave = Computation({trace.restitution, -vn}, trace.bounceSpeed[0], Product);
        target = "e = " + leave.numbers[0] + " and the approach " + N(-vn) + " m/s is above the " + N(threshold) +
                 " m/s threshold: the point is to leave at e x " + leave.numbers[1] + " = " + leave.result + " m/s.";
    }
    else
    {
        target = "e = " + N(trace.restitution) +
                 (trace.restitution > 0.0 && -vn > 0.0 && -vn <= threshold
                      ? ", but the approach is below the " + N(threshold) + " m/s threshold"
                      : "") +
                 ": no bounce; the target is to stop approaching.";
    }
    steps.push_back({"Restitution target", target});

    const ContactPointSolve* last = LastPass(trace, 0);
    const double jn = last != nullptr ? last->normalImpulse : 0.0;
    std::string compression = "Each pass adds what brings vn to its target and keeps the running total >= 0 (a "
                              "contact only pushes): after " +
                              std::to_string(ResponsePassesOf(record, 0).kept.size()) + " passes jn = " + N(jn) +
                              " N s";
    // Both points' impulses move the bodies: a student adding up the velocities needs the second one too.
    const ContactPointSolve* last2 = points == 2 ? LastPass(trace, 1) : nullptr;
    if (last2 != nullptr)
    {
        compression += " at point 1 and jn = " + N(last2->normalImpulse) + " N s at point 2" +
                       (trace.blockSolved ? ", the two solved together" : "");
    }
    if (trace.gapSpeed[0] > 0.0)
    {
        compression += ", which leaves the point approaching at " + N(trace.gapSpeed[0]) +
                       " m/s, the speed that closes its gap within the step";
    }
    const std::string warm =
        last2 != nullptr ? N(trace.warmNormal[0]) + " and " + N(trace.warmNormal[1]) : N(trace.warmNormal[0]);
    compression += trace.warmNormal[0] > 0.0 || (last2 != nullptr && trace.warmNormal[1] > 0.0)
                       ? " (the passes start from last step's " + warm + ")."
                       : ".";
    steps.push_back({"Normal impulse", compression});

    const double jr = trace.restitutionImpulse[0];
    if (jr > 0.0)
    {
        // The restitution impulse is the factor times jn unless that would return more than the contact alone needs
        // for its bounce, or give the bodies more energy than they had: then it is less, and the sentence says so.
        const double asked = trace.restitutionFactor[0] * jn;
        const bool whole = std::fabs(jr - asked) <= 1e-9 * std::max(jr, 1e-300);
        std::string bounce = "Restitution adds " + Times(trace.restitutionFactor[0], jn, asked);
        bounce += whole ? " N s"
                        : " N s, held to " + N(jr) +
                              " N s: no more than the contact alone needs for its bounce, nor than would give the "
                              "bodies energy";
        const Written all = Computation({jn, jr}, jn + jr, Sum);
        bounce += ": in all j = " + all.numbers[0] + " + " + all.numbers[1] + " = " + all.result + " N s.";
        steps.push_back({"Bounce", bounce});
    }

    // Friction at one point of the last pass: what stopping the slip needs against the static limit, and what it
    // took or gave.
    const ContactMaterial material =
        contact != nullptr ? contact->material : CombineMaterials(bodyA.material, bodyB.material);
    auto friction = [&](const ContactPointSolve& pass, double jnEnd) {
        const double needed = std::fabs(pass.tangentImpulseWanted);
        // Friction comes first in a pass: its limits are the coefficients times the normal impulse as the pass
        // began, the one the pass before left (or last step's, for the first pass).
        const ContactPointSolve* before = nullptr;
        for (const ContactPointSolve& earlier : trace.passes)
        {
            if (earlier.point == pass.point && earlier.pass >= 0 && earlier.pass < pass.pass)
            {
                before = &earlier;
            }
        }
        const double jnStart = before != nullptr ? before->normalImpulse : trace.warmNormal[pass.point];
        const std::string startJn =
            N(jnStart) == N(jnEnd) ? "" : ", with jn as the last pass began (friction comes first in a pass)";
        const Written limit = Computation({material.staticFriction, jnStart}, pass.staticLimit, Product);
        // Printed alike, the two differ beyond the digits shown: saying so keeps "beyond" from reading as a slip.
        const std::string close = N(needed) == limit.result ? " (by less than the digits shown)" : "";
        std::string text = "Stopping the slip (" + N(pass.tangentSpeed) + " m/s) needs |jt| = " + N(needed) +
                           " N s; the static limit is mu_s jn = " + limit.numbers[0] + " x " + limit.numbers[1] +
                           " = " + limit.result + " N s" + startJn + ": ";
        text += pass.stuck
                    ? "within it" + close + ", so the point sticks, and friction takes " +
                          N(std::fabs(pass.tangentImpulse)) + " N s."
                    : "beyond it" + close + ", so the point slides, and friction gives the dynamic limit mu jn = " +
                          Times(material.friction, jnStart, pass.dynamicLimit) + " N s.";
        return text;
    };
    if (last != nullptr)
    {
        std::string text = friction(*last, jn);
        std::string title = last->stuck ? "Friction: sticks" : "Friction: slides";
        if (last2 != nullptr)
        {
            std::string second = friction(*last2, last2->normalImpulse);
            text[0] = 's';
            second[0] = 's';
            text = "At point 1, " + text + " At point 2, " + second;
            title = last->stuck == last2->stuck ? title : "Friction: one sticks, one slides";
        }
        steps.push_back({title, text});
    }

    auto motion = [&](int side, const RigidBody& body, const std::string& name) {
        if (body.type == BodyType::Static)
        {
            return name + " is static and does not move";
        }
        return name + ": v " + V(trace.velocityBefore[side]) + " -> " + V(trace.velocityAfter[side]) + " m/s, spin " +
               N(trace.spinBefore[side]) + " -> " + N(trace.spinAfter[side]) + " rad/s";
    };
    std::string velocities = motion(0, bodyA, a) + "; " + motion(1, bodyB, b) + ".";
    const Vec2 gdt = record.dt * record.world.settings.gravity;
    if (gdt.x != 0.0 || gdt.y != 0.0)
    {
        velocities += " After includes the step's gravity, g dt = " + V(gdt) + " m/s.";
    }
    steps.push_back({"Velocities", velocities});
    return steps;
}

} // namespace satviz
