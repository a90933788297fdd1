// SPDX-License-Identifier: MIT
#include <satviz/render/describe.h>
#include <satviz/render/response_steps.h>
#include <satviz/render/world_words.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

namespace
{

std::string Name(const Scene& scene, int body)
{
    return body >= 0 && static_cast<size_t>(body) < scene.bodies.size() ? scene.bodies[static_cast<size_t>(body)].name
                                                                        : "body " + std::to_string(body);
}

// A point's separation as the list gives it: an overlap (< 0), a gap (> 0, a speculative contact), or touching.
std::string Separation(double separation)
{
    if (separation == 0.0)
    {
        return "touching";
    }
    return (separation < 0.0 ? "overlap " : "gap ") + FormatResponseNumber(std::fabs(separation));
}

} // namespace

WorldWords DescribeWorld(const Scene& scene, const SimRecord& record)
{
    WorldWords words;
    words.time = "Step " + std::to_string(record.steps) + ": time " + FormatResponseNumber(record.world.time) +
                 " s (dt " + FormatResponseNumber(record.dt) + " s)";
    // The contacts were found for the bodies as the step began: a pair with no body awake then was neither tested
    // nor solved, and holds the contact of the last step it was awake.
    const std::vector<RigidBody>& start = record.before.empty() ? record.world.bodies : record.before;
    const auto resting = [&](int i) {
        if (i < 0 || static_cast<size_t>(i) >= start.size())
        {
            return false;
        }
        const RigidBody& body = start[static_cast<size_t>(i)];
        return body.type == BodyType::Static || !body.awake;
    };
    for (const WorldContact& c : record.world.contacts)
    {
        if (c.guard)
        {
            continue;
        }
        WorldContactWords line;
        line.a = c.a;
        line.b = c.b;
        line.kept = resting(c.a) && resting(c.b);
        const double first = c.points[0].separation;
        const double second = c.pointCount == 2 ? c.points[1].separation : first;
        std::string points = Separation(first);
        if (c.pointCount == 2 && first == 0.0 && second == 0.0)
        {
            points = "both touching";
        }
        else if (c.pointCount == 2)
        {
            // "overlap 0.0051 and 0.0049": the kind once when both points are of it.
            const std::string other = Separation(second);
            const bool sameKind = first != 0.0 && second != 0.0 && (first < 0.0) == (second < 0.0);
            points += " and " + (sameKind ? other.substr(other.find(' ') + 1) : other);
        }
        line.text = Name(scene, c.a) + " and " + Name(scene, c.b) + ": " + std::to_string(c.pointCount) +
                    (c.pointCount == 1 ? " point, " : " points, ") + points;
        line.text += line.kept ? " (kept)" : "";
        words.contacts.push_back(line);
    }
    words.contactsTitle =
        "Contacts held after step " + std::to_string(record.steps) + ": " + std::to_string(words.contacts.size());
    words.contactsNote = "Overlap or gap per point, as found at the start of the step; kept: a sleeping pair's "
                         "contact, from the last step it was awake (neither tested nor solved).";
    for (size_t i = 0; i < record.world.bodies.size(); ++i)
    {
        const RigidBody& body = record.world.bodies[i];
        const std::string name = Name(scene, static_cast<int>(i));
        if (body.type == BodyType::Static)
        {
            words.bodies.push_back(name + ": static");
            continue;
        }
        const Vec2 at = body.WorldCenter();
        std::string line =
            name + (body.awake ? ": awake" : ": asleep") + ", centre of mass at " + FormatResponseVector(at);
        line += body.awake ? ", v " + FormatResponseVector(body.velocity) + " m/s, spin " +
                                 FormatResponseNumber(body.angularVelocity) + " rad/s"
                           : ", at rest until something touches it";
        words.bodies.push_back(line);
    }
    return words;
}

} // namespace satviz
