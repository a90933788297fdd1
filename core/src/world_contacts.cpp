// SPDX-License-Identifier: MIT
// satviz: the step's first stage: the contacts of the bodies, found, warm started and waking their islands.

#include "body_queries.h"
#include "stepper.h"
#include "parallel_for.h"
#include "time_of_impact.h"
#include "widen_within.h"
#include "world_lookup.h"

#include <satviz/collide.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace satviz::detail
{

namespace
{

// Identifies a contact point from step to step: the deciding axis (kind, shape, index), the incident edge and the
// point's slot. Points whose features persist keep their impulses (warm starting).
uint32_t FeatureKey(const Manifold& m, int slot)
{
    const uint32_t kind = static_cast<uint32_t>(m.axis.kind) & 3u;
    const uint32_t shape = static_cast<uint32_t>(m.axis.shape + 1) & 3u;
    const uint32_t index = static_cast<uint32_t>(m.axis.index + 1) & 0x1fffu;
    const uint32_t incident = static_cast<uint32_t>(m.incidentEdge + 1) & 0x1fffu;
    return kind | shape << 2 | index << 4 | incident << 17 | static_cast<uint32_t>(slot) << 30;
}

// The same for a pair with a concave body: the deciding pieces are folded into the high bits of the index and the
// incident edge (a piece's own edges are few), so that a point on another piece is another point.
uint32_t FeatureKey(const Manifold& m, int pieceA, int pieceB, int slot)
{
    const uint32_t foldA = static_cast<uint32_t>(pieceA + 1) & 0x3fu;
    const uint32_t foldB = static_cast<uint32_t>(pieceB + 1) & 0x3fu;
    return FeatureKey(m, slot) ^ (foldA << 11 | foldB << 24);
}

// Whether x and y are the same double to the bit (+0 and -0 apart, whose sines differ in sign).
bool SameBits(double x, double y)
{
    uint64_t a = 0, b = 0;
    std::memcpy(&a, &x, sizeof a);
    std::memcpy(&b, &y, sizeof b);
    return a == b;
}

// Candidate pairs (or bodies) that one piece of parallel work takes at least: fewer cost more to hand to another
// thread than to do here.
constexpr int kPairsPerPiece = 64;
constexpr int kBodiesPerPiece = 128;

struct PairFilter
{
    const std::vector<RigidBody>* bodies = nullptr;
    bool skipStatic = true;
};

// A pair is skipped when both bodies are static (if the world skips those) or when neither is awake and dynamic.
bool SkipPair(const void* context, int i, int j)
{
    const PairFilter& filter = *static_cast<const PairFilter*>(context);
    const RigidBody& a = (*filter.bodies)[i];
    const RigidBody& b = (*filter.bodies)[j];
    if (a.type == BodyType::Static && b.type == BodyType::Static)
    {
        return filter.skipStatic;
    }
    return !IsAwakeDynamic(a) && !IsAwakeDynamic(b);
}

// Wakes the sleeping bodies in `seeds` and every sleeping dynamic body joined to them through contacts: an island
// wakes as a whole. Static bodies do not join islands.
void WakeIslands(World& world, std::vector<int>& seeds)
{
    std::vector<RigidBody>& bodies = world.bodies;
    if (seeds.empty())
    {
        return;
    }
    const int n = static_cast<int>(bodies.size());
    std::vector<int> start(n + 1, 0);
    for (const WorldContact& c : world.contacts)
    {
        ++start[c.a + 1];
        ++start[c.b + 1];
    }
    for (int i = 0; i < n; ++i)
    {
        start[i + 1] += start[i];
    }
    std::vector<int> next(start.begin(), start.end() - 1);
    std::vector<int> neighbours(start[n]);
    for (const WorldContact& c : world.contacts)
    {
        neighbours[next[c.a]++] = c.b;
        neighbours[next[c.b]++] = c.a;
    }
    while (!seeds.empty())
    {
        const int i = seeds.back();
        seeds.pop_back();
        RigidBody& body = bodies[i];
        if (body.type != BodyType::Dynamic || body.awake)
        {
            continue;
        }
        body.awake = true;
        body.sleepTime = 0.0;
        for (int k = start[i]; k < start[i + 1]; ++k)
        {
            seeds.push_back(neighbours[k]);
        }
    }
}

// A point of this step's contact takes the impulses of the last step's point it continues, to warm start from.
void TakeImpulses(WorldContactPoint& p, const WorldContactPoint& old)
{
    p.normalImpulse = old.normalImpulse;
    p.tangentImpulse = old.tangentImpulse;
    p.subStepNormalImpulse = old.subStepNormalImpulse;
    p.subStepTangentImpulse = old.subStepTangentImpulse;
}

} // namespace

// Whether the pair (i, j), still apart, is left to the sweep instead of given a speculative contact: one of its
// bodies is a bullet (it moves farther within the step than its reach, speculativeReach outer radii, or turns
// faster than speculativeTurn) and the two outrun each other (detail::OutrunsPair, the sweep's own rule), judged
// from the velocities after the step's gravity. A speculative contact holds its pair at the velocities the solver
// leaves, to first order, from the start of the step: it would bounce a bullet off a face it has not reached yet,
// far short of where the exact hit would leave it. The sweep finds that hit at its time instead. The points are
// kept as a guard (WorldContact::guard): the velocity passes ignore them, and the position passes, which push
// bodies out of each other, see that a ball skimming a floor is there and do not push it through.
// Inline: FindContacts, its only caller, asks it of every pair still apart.
inline bool Stepper::LeftToSweep(int i, int j) const
{
    if (!bullets[static_cast<size_t>(i)] && !bullets[static_cast<size_t>(j)])
    {
        return false;
    }
    const RigidBody& a = world.bodies[static_cast<size_t>(i)];
    const RigidBody& b = world.bodies[static_cast<size_t>(j)];
    const bool movesA = IsAwakeDynamic(a), movesB = IsAwakeDynamic(b);
    const Vec2 va = movesA ? a.velocity + dt * settings.gravity : Vec2{};
    const Vec2 vb = movesB ? b.velocity + dt * settings.gravity : Vec2{};
    const double wa = movesA ? a.angularVelocity : 0.0;
    const double wb = movesB ? b.angularVelocity : 0.0;
    return detail::OutrunsPair(settings, a, va, wa, b, vb, wb, dt);
}

// Stage 1: bounds, broadphase, narrowphase, warm starting, waking.
void Stepper::FindContacts()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    StepCounts& counts = world.counts;
    counts.pairs = static_cast<int64_t>(n) * (n - 1) / 2;

    int64_t statics = 0, idle = 0;
    std::vector<uint8_t> awakeAtStart(n);
    for (int i = 0; i < n; ++i)
    {
        statics += bodies[i].type == BodyType::Static;
        idle += !IsAwakeDynamic(bodies[i]);
        awakeAtStart[i] = IsAwakeDynamic(bodies[i]);
    }
    counts.staticPairs = settings.skipStaticPairs ? statics * (statics - 1) / 2 : 0;
    const int64_t idlePairs = idle * (idle - 1) / 2 - statics * (statics - 1) / 2;
    counts.sleepingPairs = idlePairs;

    // How far a pass of the position correction can move a body at a point (maxCorrection): a body beside a static
    // one within this distance beyond its reach gets a guard, so that the passes, pushing it out of another body,
    // do not push it into the static one. (Several passes can move it farther, but only out of an overlap that
    // deep, which the sweep and the contacts leave rare.)
    const double correctionReach = settings.positionIterations > 0 ? settings.maxCorrection : 0.0;
    PairFilter filter{&bodies, settings.skipStaticPairs};
    std::vector<std::pair<int, int>>& candidates = memory.candidates;
    candidates.clear();
    StepTrace* stepTrace = world.stepTrace;
    std::vector<Aabb>& boxes = memory.boxes;
    const bool withBoxes = settings.broadphase || stepTrace != nullptr;
    if (withBoxes)
    {
        boxes.resize(n);
        if (stepTrace != nullptr)
        {
            stepTrace->grow.resize(n);
        }
    }
    xfs.resize(n);
    bodyReach.assign(static_cast<size_t>(n), 0.0);
    bullets.assign(static_cast<size_t>(n), 0);
    const double fall = Length(settings.gravity) * dt;
    // Each body's transform, reach and box, body by body on any thread.
    const auto bound = [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
        {
            const RigidBody& body = bodies[i];
            // The rotation of the angle the last step's move left, if the body still has that angle (to the
            // bit: the body may have been turned or replaced since), else a sine and a cosine.
            const bool kept = static_cast<size_t>(i) < rotationAngles.size() &&
                              SameBits(rotationAngles[static_cast<size_t>(i)], body.angle);
            xfs[i] = {body.position, kept ? rotations[static_cast<size_t>(i)] : MakeRot(body.angle)};
            // How far each awake dynamic body can move within the step (its speed after gravity, and the turn of its
            // farthest point), at most speculativeReach outer radii: a body that moves farther is a bullet, and the
            // sweep finds its hits; none for a body turning more than speculativeTurn.
            if (settings.speculativeContacts && IsAwakeDynamic(body))
            {
                const double move =
                    dt * (Length(body.velocity) + fall + std::fabs(body.angularVelocity) * body.turnRadius);
                const double cap = settings.speculativeReach * body.outerRadius;
                // A body that turns fast is left to the sweep: a contact found at the start of the step follows a
                // turn only to first order.
                const bool turnsFast = TurnsBeyondContacts(settings, body, body.angularVelocity, dt);
                bullets[static_cast<size_t>(i)] = turnsFast || move > cap ? 1 : 0;
                if (!turnsFast)
                {
                    bodyReach[static_cast<size_t>(i)] = std::min(move, cap);
                }
            }
            if (!withBoxes)
            {
                continue;
            }
            boxes[i] = ComputeAabb(body.shape, xfs[i]);
            // A body's box grows by the reach of its speculative contacts, so the pairs within it are found; a
            // static body's by how far the position passes can move a body, so its guards are found.
            const double grow = body.type == BodyType::Static ? correctionReach : bodyReach[static_cast<size_t>(i)];
            boxes[i].min = boxes[i].min - Vec2{grow, grow};
            boxes[i].max = boxes[i].max + Vec2{grow, grow};
            if (stepTrace != nullptr)
            {
                stepTrace->grow[i] = grow;
            }
        }
    };
    ParallelFor(world.tasks, n, kBodiesPerPiece, bound);
    if (settings.broadphase)
    {
        FindPairs(world.broadphase, boxes, candidates, SkipPair, &filter);
        counts.broadphaseComparisons = world.broadphase.comparisons;
    }
    else
    {
        for (int i = 0; i < n; ++i)
        {
            for (int j = i + 1; j < n; ++j)
            {
                if (!SkipPair(&filter, i, j))
                {
                    candidates.emplace_back(i, j);
                }
            }
        }
    }
    counts.tested = static_cast<int64_t>(candidates.size());
    if (stepTrace != nullptr)
    {
        stepTrace->bounds = std::move(boxes);
        stepTrace->candidates = candidates;
    }
    counts.boundsApart = counts.pairs - counts.staticPairs - counts.sleepingPairs - counts.tested;

    // The last step's contacts go to the working lists, and the list they leave there takes this step's.
    std::vector<WorldContact>& previous = memory.previousContacts;
    previous.swap(world.contacts);
    // The previous contacts are in pair order: those of body a are previous[firstOf[a]] up to firstOf[a + 1], a
    // few to scan for b.
    std::vector<int> firstOf(static_cast<size_t>(n) + 1, 0);
    for (const WorldContact& c : previous)
    {
        ++firstOf[static_cast<size_t>(c.a) + 1];
    }
    for (int i = 0; i < n; ++i)
    {
        firstOf[static_cast<size_t>(i) + 1] += firstOf[static_cast<size_t>(i)];
    }
    const auto previousOf = [&](int a, int b) -> const WorldContact* {
        for (int k = firstOf[static_cast<size_t>(a)]; k < firstOf[static_cast<size_t>(a) + 1]; ++k)
        {
            if (previous[static_cast<size_t>(k)].b == b)
            {
                return &previous[static_cast<size_t>(k)];
            }
        }
        return nullptr;
    };
    // The candidates are cut into pieces that may be collided on any thread, each piece's contacts appended to a
    // list of its own; the first piece's list is the world's, and the others follow it in order: the contacts come
    // in the candidates' order, as from one pass over them. On one thread there is one piece.
    const int pairCount = static_cast<int>(candidates.size());
    const int pieces = PieceCount(world.tasks, pairCount, kPairsPerPiece);
    std::vector<WorldContact>& contacts = world.contacts;
    contacts.clear();
    contacts.reserve(previous.size() + 16);
    std::vector<std::vector<WorldContact>> later(static_cast<size_t>(pieces - 1));
    std::vector<int64_t> touchingOf(static_cast<size_t>(pieces), 0), speculativeOf(static_cast<size_t>(pieces), 0);
    const auto collide = [&](int piece, int begin, int end) {
        std::vector<WorldContact>& out = piece == 0 ? contacts : later[static_cast<size_t>(piece - 1)];
        for (int slot = begin; slot < end; ++slot)
        {
            const int i = candidates[static_cast<size_t>(slot)].first;
            const int j = candidates[static_cast<size_t>(slot)].second;
            const RigidBody& a = bodies[i];
            const RigidBody& b = bodies[j];
            // A pair with a concave body takes the concave queries (one merged manifold, seams dropped), and the
            // pieces that decided it name its points (CollidePair).
            if (a.type == BodyType::Static && b.type == BodyType::Static)
            {
                detail::CollidePair(a, xfs[i], b, xfs[j]);
                continue;
            }
            // The pair's speculative margin: how far the two can close within the step.
            const double margin = bodyReach[static_cast<size_t>(i)] + bodyReach[static_cast<size_t>(j)];
            // The manifold is made where it stays, not copied out of a wrapper: a copy of a structure just written
            // field by field stalls on the stores it reads back. A convex pair collides once for both margins.
            const bool concave = AnyConcave(a, b);
            int pieceA = -1;
            int pieceB = -1;
            const auto concaveWithin = [&](double within) -> Manifold {
                const ConcaveManifold cm = detail::CollidePair(a, xfs[i], b, xfs[j], within);
                pieceA = cm.pieceA;
                pieceB = cm.pieceB;
                return cm.manifold;
            };
            Manifold m = concave ? concaveWithin(margin) : Collide(a.shape, xfs[i], b.shape, xfs[j]);
            const bool widened = !concave && margin > 0.0 && WidenWithin(m, a.shape, xfs[i], b.shape, xfs[j], margin);
            bool guard = false;
            if (m.contactCount == 0)
            {
                // Beyond reach of a static body, but within what the position passes can move it: a guard. The
                // pair is apart (the call above found nothing within the margin), so whatever the wider call finds
                // is a guard, even when it calls the pair touching: a body resting against a wall, at rest in a
                // world without gravity, has no margin, and the wider call, which grows one shape by the margin
                // and takes it off again, can round its gap of a few ulps to a touch.
                if (correctionReach > 0.0 && (a.type == BodyType::Static) != (b.type == BodyType::Static))
                {
                    if (concave)
                    {
                        m = concaveWithin(margin + correctionReach);
                    }
                    else
                    {
                        // Collide's manifold is still in m unless the first margin replaced it.
                        if (widened)
                        {
                            m = Collide(a.shape, xfs[i], b.shape, xfs[j]);
                        }
                        // As CollidePair: a margin that is not above 0 (a body whose velocity is not a number
                        // has a reach that is not one) leaves Collide's manifold.
                        if (margin + correctionReach > 0.0)
                        {
                            WidenWithin(m, a.shape, xfs[i], b.shape, xfs[j], margin + correctionReach);
                        }
                    }
                    guard = m.contactCount > 0;
                }
                if (!guard)
                {
                    continue;
                }
            }
            WorldContact& c = out.emplace_back();
            // A pair still apart that the sweep takes gets no speculative contact, only a guard (see LeftToSweep).
            c.guard = guard || (!m.overlap && LeftToSweep(i, j));
            touchingOf[static_cast<size_t>(piece)] += m.overlap && !guard;
            speculativeOf[static_cast<size_t>(piece)] += !m.overlap && !c.guard;
            c.a = i;
            c.b = j;
            c.normal = m.normal;
            c.normalBody = m.axis.shape == 1 ? 1 : 0;
            c.pointCount = m.contactCount;
            c.material = CombineMaterials(a.material, b.material);
            const WorldContact* old = previousOf(i, j);
            const double reach = 0.25 * std::min(a.type == BodyType::Dynamic ? a.innerRadius : INFINITY,
                                                 b.type == BodyType::Dynamic ? b.innerRadius : INFINITY);
            for (int k = 0; k < m.contactCount; ++k)
            {
                WorldContactPoint& p = c.points[k];
                p.point = m.contacts[k].point;
                p.separation = m.contacts[k].separation;
                p.key = FeatureKey(m, pieceA, pieceB, k);
                if (old != nullptr && !c.guard)
                {
                    bool matched = false;
                    for (int l = 0; l < old->pointCount; ++l)
                    {
                        if (old->points[l].key == p.key)
                        {
                            TakeImpulses(p, old->points[l]);
                            matched = true;
                        }
                    }
                    // The reference face can pass from one body to the other between steps when two faces are
                    // nearly parallel (a stack of equal boxes): the point is the same, its key is not. Such a point
                    // takes the impulses of the old point nearest to it, if close and the normal has not turned.
                    if (!matched && Dot(old->normal, c.normal) > 0.95)
                    {
                        double nearest = reach * reach;
                        for (int l = 0; l < old->pointCount; ++l)
                        {
                            const double d2 = LengthSquared(old->points[l].point - p.point);
                            if (d2 < nearest)
                            {
                                nearest = d2;
                                TakeImpulses(p, old->points[l]);
                                matched = true;
                            }
                        }
                    }
                }
            }
        }
    };
    ParallelForPieces(world.tasks, pairCount, pieces, collide);
    int64_t touching = 0, speculative = 0;
    for (int piece = 0; piece < pieces; ++piece)
    {
        if (piece > 0)
        {
            const std::vector<WorldContact>& more = later[static_cast<size_t>(piece - 1)];
            contacts.insert(contacts.end(), more.begin(), more.end());
        }
        touching += touchingOf[static_cast<size_t>(piece)];
        speculative += speculativeOf[static_cast<size_t>(piece)];
    }
    // A body that touches a sleeping one wakes its island.
    std::vector<int> wake;
    for (const WorldContact& c : contacts)
    {
        if (awakeAtStart[c.a] != awakeAtStart[c.b])
        {
            wake.push_back(awakeAtStart[c.a] ? c.b : c.a);
        }
    }
    // The contacts of pairs skipped because neither body was awake are kept as they were: neither body moved. Both
    // lists are in pair order, so a merge keeps the whole in order.
    const size_t found = contacts.size();
    counts.touching = touching;
    counts.speculative = speculative;
    for (const WorldContact& c : previous)
    {
        if (!awakeAtStart[c.a] && !awakeAtStart[c.b])
        {
            contacts.push_back(c);
        }
    }
    std::inplace_merge(
        contacts.begin(), contacts.begin() + static_cast<std::ptrdiff_t>(found), contacts.end(),
        [](const WorldContact& x, const WorldContact& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); });
    WakeIslands(world, wake);
}

} // namespace satviz::detail
