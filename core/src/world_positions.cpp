// SPDX-License-Identifier: MIT
// satviz: the step's position stages: the move with time-ordered hits, the guards for where the bodies went, and
// the position passes.

#include "body_queries.h"
#include "stepper.h"
#include "time_of_impact.h"
#include "world_lookup.h"

#include <satviz/collide.h>
#include <satviz/sweep.h>

#include <algorithm>
#include <cmath>

namespace satviz::detail
{

namespace
{

// q turned by a small angle: the rotation by (1, angle) normalised, which costs no sine or cosine. The passes use
// it for their anchors; the body's angle is summed exactly and its rotation taken from it at the end.
Rot TurnBy(Rot q, double angle)
{
    const double c = q.c - angle * q.s;
    const double s = q.s + angle * q.c;
    // |(c, s)|^2 = 1 + x with x about angle^2. A pass turns a body by little, and for small x the series
    // 1 - x/2 + 3x^2/8 of 1/sqrt(1 + x) is exact to rounding (its next term, 5x^3/16, is below 1e-16), without a
    // square root or a division.
    const double x = c * c + s * s - 1.0;
    const double inv = std::fabs(x) < 1e-6 ? 1.0 - x * (0.5 - 0.375 * x) : 1.0 / std::sqrt(1.0 + x);
    return {c * inv, s * inv};
}

} // namespace

// Stage 4: positions, with the hits of fast bodies in time order.
void Stepper::Move()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    for (int i = 0; i < n; ++i)
    {
        if (IsAwakeDynamic(bodies[i]))
        {
            bodies[i].velocity = solverBodies[i].v;
            bodies[i].angularVelocity = solverBodies[i].w;
        }
    }
    detail::TimeOfImpactStage stage(world, dt, xfs, centers, solverBodies, memory.near);
    stage.Run();
    hit.assign(static_cast<size_t>(n), 0);
    rotations.resize(static_cast<size_t>(n));
    rotationAngles.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
    {
        hit[static_cast<size_t>(i)] = stage.TookHit(i) ? 1 : 0;
        rotations[static_cast<size_t>(i)] = stage.Rotation(i);
        rotationAngles[static_cast<size_t>(i)] = bodies[i].angle;
    }
    if (settings.softStep)
    {
        // The soft step moved each body with the velocity of its path over the sub-steps; it keeps the velocity
        // the last sub-step left, plus what its hits changed (so that momentum is kept: a hit's impulses are equal
        // and opposite, and so are the sub-steps').
        for (int i = 0; i < n; ++i)
        {
            if (!IsAwakeDynamic(bodies[i]))
            {
                continue;
            }
            const SolverBody& last = memory.softVelocities[static_cast<size_t>(i)];
            if (hit[static_cast<size_t>(i)])
            {
                bodies[i].velocity = bodies[i].velocity + (last.v - solverBodies[i].v);
                bodies[i].angularVelocity += last.w - solverBodies[i].w;
            }
            else
            {
                bodies[i].velocity = last.v;
                bodies[i].angularVelocity = last.w;
            }
        }
    }
}

// Guards for where the bodies went. FindContacts gave guards to the static bodies within reach of the position
// passes of where each body could go at its speed at the start of the step; the velocity passes and the hits can
// send a body farther (a light body struck by a heavy one), and the passes, pushing it out of the body that struck
// it, would then push it on into a wall no guard watches. A body that moved beyond the reach it was given gets
// guards with the static bodies within maxCorrection of its path.
// c and turn: each body's centre of mass after the move, and its turn since the start of the step.
void Stepper::GuardAfterMove(const std::vector<Vec2>& c, const std::vector<Rot>& turn)
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    std::vector<int> statics;
    for (int i = 0; i < n; ++i)
    {
        const RigidBody& body = bodies[i];
        if (!IsAwakeDynamic(body))
        {
            continue;
        }
        const double reach = bodyReach[static_cast<size_t>(i)];
        const double d2 = LengthSquared(c[i] - centers[i]);
        if (d2 <= reach * reach && body.turnRadius == 0.0)
        {
            continue;
        }
        const double moved =
            std::sqrt(d2) + body.turnRadius * std::sqrt(LengthSquared(Vec2{turn[i].c - 1.0, turn[i].s}));
        if (moved <= reach)
        {
            continue;
        }
        if (statics.empty())
        {
            for (int k = 0; k < n; ++k)
            {
                if (bodies[k].type == BodyType::Static)
                {
                    statics.push_back(k);
                }
            }
            if (statics.empty())
            {
                return;
            }
        }
        // The box of every place the body was in the step, grown by what a pass can move it.
        const double margin = moved + settings.maxCorrection;
        Aabb path = ComputeAabb(body.shape, xfs[i]);
        path.min = path.min - Vec2{margin, margin};
        path.max = path.max + Vec2{margin, margin};
        for (const int s : statics)
        {
            if (!AabbOverlap(path, ComputeAabb(bodies[s].shape, xfs[s])))
            {
                continue;
            }
            const int a = std::min(i, s), b = std::max(i, s);
            const WorldContact* existing = FindContact(world.contacts, a, b);
            if (existing != nullptr)
            {
                continue;
            }
            const Manifold m = detail::CollidePair(bodies[a], xfs[a], bodies[b], xfs[b], margin).manifold;
            if (m.contactCount == 0)
            {
                continue;
            }
            SolverContact g;
            g.a = a;
            g.b = b;
            g.material = CombineMaterials(bodies[a].material, bodies[b].material);
            g.normal = m.normal;
            g.normalBody = m.axis.shape == 1 ? 1 : 0;
            g.count = m.contactCount;
            for (int k = 0; k < g.count; ++k)
            {
                g.points[k].rA = m.contacts[k].point - centers[a];
                g.points[k].rB = m.contacts[k].point - centers[b];
                g.points[k].separation = m.contacts[k].separation;
            }
            guards.push_back(g);
        }
    }
}

// Stage 5: overlap removed by moving the positions, not the velocities (nonlinear Gauss-Seidel: Catto, Box2D).
// Each pass measures every point's overlap at the bodies' present positions, from the point's anchors on both bodies
// and the normal turned with the body whose face (or vertex) it is, as Box2D measures it from the reference face,
// and moves the two bodies apart along the normal by correctionFactor times the overlap beyond the slop (at most
// maxCorrection), weighted by their inverse masses and inertias. Passes see the moves of the passes before them, so
// a body that sank during this step's move is lifted in the same step. Speculative points (a gap) are left alone.
void Stepper::CorrectPositions()
{
    std::vector<RigidBody>& bodies = world.bodies;
    const int n = static_cast<int>(bodies.size());
    std::vector<Vec2> c(n);
    std::vector<double> angle(n);
    // Each body's turn since the start of the step, as a rotation: the anchors found then turn by it. A circle
    // turning about its centre keeps the identity, for its turning moves no point of its outline (a ball spinning
    // a full turn in a step would otherwise be pushed along a normal turned any which way).
    std::vector<Rot> turn(n);
    std::vector<uint8_t> turns(n); // turning moves the outline: not a circle about its centre
    std::vector<uint8_t> spinning(n); // turned farther in the move than a contact's anchors follow
    for (int i = 0; i < n; ++i)
    {
        angle[i] = bodies[i].angle;
        const Rot q = rotations[static_cast<size_t>(i)];
        c[i] = bodies[i].position + Rotate(q, bodies[i].localCenter);
        turns[i] = bodies[i].turnRadius > 0.0 ? 1 : 0;
        turn[i] = turns[i] ? InvMulRot(xfs[i].q, q) : Rot{};
        spinning[i] = TurnsBeyondContacts(settings, bodies[i], solverBodies[i].w, dt) ? 1 : 0;
    }
    if (settings.positionIterations > 0)
    {
        GuardAfterMove(c, turn);
    }
    // Body i's transform with its centre of mass at `center`, turned as the passes have turned it so far.
    const auto PoseAt = [&](int i, Vec2 center) {
        Transform xf;
        const Rot q0 = xfs[i].q, d = turn[i];
        xf.q = {q0.c * d.c - q0.s * d.s, q0.s * d.c + q0.c * d.s};
        xf.p = center - Rotate(xf.q, bodies[i].localCenter);
        return xf;
    };
    // Moves bodies a and b apart along n0 at a point with lever arms rA, rB and separation sep, by `factor` of the
    // overlap beyond the slop.
    const auto push = [&](int a, int b, Vec2 n0, Vec2 rA, Vec2 rB, double sep, double factor) {
        const SolverBody& sa = solverBodies[a];
        const SolverBody& sb = solverBodies[b];
        double C = factor * (sep + settings.linearSlop);
        C = std::max(-settings.maxCorrection, std::min(0.0, C));
        const double rnA = Cross(rA, n0), rnB = Cross(rB, n0);
        const double K = sa.invMass + sb.invMass + sa.invInertia * rnA * rnA + sb.invInertia * rnB * rnB;
        if (!(K > 0.0) || C == 0.0)
        {
            return;
        }
        const Vec2 P = (-C / K) * n0;
        const double turnA = -sa.invInertia * Cross(rA, P);
        const double turnB = sb.invInertia * Cross(rB, P);
        c[a] = c[a] - sa.invMass * P;
        angle[a] += turnA;
        c[b] = c[b] + sb.invMass * P;
        angle[b] += turnB;
        if (turns[a])
        {
            turn[a] = TurnBy(turn[a], turnA);
        }
        if (turns[b])
        {
            turn[b] = TurnBy(turn[b], turnB);
        }
    };
    // A guard's pair may have moved far against each other: anchors found at the start of the step say nothing of
    // where they are now, so its overlap is measured afresh, by Collide at the present positions, once its bodies
    // may have crossed the gap it started with (each point of a body has moved at most the distance of its centre
    // plus the turn radius times the chord of its turn).
    const auto guard = [&](const SolverContact& g, double factor, bool straight) {
        const int a = g.a, b = g.b;
        // The passes leave out a body that took a hit (see correct), but not the last lift out of a static body,
        // measured afresh: a light body pressed into a wall by a heavy one takes a hit in every step, and the sweep
        // lets it creep in by less than the slop each time.
        const bool tookHit = hit[static_cast<size_t>(a)] || hit[static_cast<size_t>(b)];
        if (tookHit && !straight)
        {
            return;
        }
        // The chord of a turn by `turn` is |turn - 1| (a circle's turn is kept as the identity, and its turn radius
        // is 0 anyway).
        const auto moved = [&](int i) {
            return std::sqrt(LengthSquared(c[i] - centers[i])) +
                   bodies[i].turnRadius * std::sqrt(LengthSquared(Vec2{turn[i].c - 1.0, turn[i].s}));
        };
        const double gap = std::min(g.points[0].separation, g.count > 1 ? g.points[1].separation : INFINITY);
        if (gap - moved(a) - moved(b) > -settings.linearSlop)
        {
            return;
        }
        const auto pose = [&](int i) { return PoseAt(i, c[i]); };
        // Along n (from the static body to the moving one): the static body's (piece's) extent, `top`, and the
        // moving one's deepest point and its height, `bottom`.
        const auto extents = [&](int fixedBody, int fixedPiece, int moving, int movingPiece, Vec2 n, double& top,
                                 double& bottom, Vec2& deepest) {
            const Transform xs = pose(fixedBody), xm = pose(moving);
            const Shape& shapeS = detail::PieceShape(bodies[fixedBody], fixedPiece);
            const Shape& shapeM = detail::PieceShape(bodies[moving], movingPiece);
            top = -INFINITY;
            if (shapeS.type == ShapeType::Circle)
            {
                top = Dot(n, TransformPoint(xs, shapeS.circle.center)) + shapeS.circle.radius;
            }
            else
            {
                for (const Vec2& v : shapeS.polygon.Vertices())
                {
                    top = std::max(top, Dot(n, TransformPoint(xs, v)));
                }
            }
            bottom = INFINITY;
            if (shapeM.type == ShapeType::Circle)
            {
                deepest = TransformPoint(xm, shapeM.circle.center) - shapeM.circle.radius * n;
                bottom = Dot(n, deepest);
            }
            else
            {
                for (const Vec2& v : shapeM.polygon.Vertices())
                {
                    const Vec2 w = TransformPoint(xm, v);
                    if (Dot(n, w) < bottom)
                    {
                        bottom = Dot(n, w);
                        deepest = w;
                    }
                }
            }
        };
        const int fixedBody = bodies[a].type == BodyType::Static ? a : (bodies[b].type == BodyType::Static ? b : -1);
        // The last lift of a convex body along a static body's own face, fixed: when the body is within the slop
        // of it along that face's normal there is nothing to lift, whatever Collide would say, so Collide is not
        // asked (a resting pile's contacts with the floor, every step).
        if (straight && fixedBody >= 0 && !tookHit && (g.normalBody == 1 ? b : a) == fixedBody &&
            !detail::AnyConcave(bodies[a], bodies[b]))
        {
            const int moving = fixedBody == a ? b : a;
            const Vec2 n = fixedBody == a ? g.normal : -1.0 * g.normal;
            double top = 0.0, bottom = 0.0;
            Vec2 deepest{};
            extents(fixedBody, -1, moving, -1, n, top, bottom, deepest);
            if (bottom - top + settings.linearSlop >= 0.0)
            {
                return;
            }
        }
        // Beside a static body, once Collide finds them overlapping, the axis is the guard's normal, fixed as the
        // static body is: the moving body's deepest point along it against the static body's extent. Measured so,
        // a body pushed past the middle of a thin wall is still pushed back the way it came; Collide's own normal
        // would push it on through.
        // A concave body's part in the overlap is the piece that decided it: its vertices bound the push below.
        const ConcaveManifold cm = detail::CollidePair(bodies[a], pose(a), bodies[b], pose(b));
        const Manifold& m = cm.manifold;
        const int pieceA = cm.pieceA, pieceB = cm.pieceB;
        if (!m.overlap)
        {
            return;
        }
        if (fixedBody >= 0)
        {
            const int moving = fixedBody == a ? b : a;
            // The axis turns with the body whose face it is: fixed if the static body's, as found now if the moving
            // body's (a plank's face turning on a peg).
            const int owner = g.normalBody == 1 ? b : a;
            // A body that took a hit may be far from where the guard was found: its overlap is the one Collide
            // finds now, shallow (the sweep left it touching), along Collide's normal.
            const Vec2 axis = owner == fixedBody && !tookHit ? g.normal : m.normal;
            const Vec2 n = fixedBody == a ? axis : -1.0 * axis; // from the static body to the moving one
            double top = 0.0, bottom = 0.0;
            Vec2 deepest{};
            extents(fixedBody, fixedBody == a ? pieceA : pieceB, moving, moving == a ? pieceA : pieceB, n, top, bottom,
                    deepest);
            const Vec2 normal = fixedBody == a ? n : -1.0 * n;
            if (straight)
            {
                // Straight out, without turning: every point of the body rises by the same amount, so the deepest
                // one comes out and no other goes in (pushed at one corner, a sliver lying in the floor would turn
                // its other end down).
                const double C = std::max(-settings.maxCorrection, std::min(0.0, bottom - top + settings.linearSlop));
                c[moving] = c[moving] - C * n;
                RigidBody& body = bodies[moving];
                if (C < 0.0 && IsAwakeDynamic(body))
                {
                    // The body sank into the static one beyond the slop: the step's contacts and sweep missed it (a
                    // corner brought down by a turn that a contact follows only to first order). Its approach at
                    // the deepest point is taken as a hit would take it, with the pair's restitution, so that the
                    // lift does not leave it moving on into the wall, to be lifted again: lifted while still
                    // falling, it would gain the height for nothing.
                    const Vec2 r = deepest - c[moving];
                    const double vn = Dot(body.velocity + body.angularVelocity * LeftPerp(r), n);
                    if (vn < 0.0)
                    {
                        const double rn = Cross(r, n);
                        const double K = body.invMass + body.invInertia * rn * rn;
                        const double j = -(1.0 + g.material.restitution) * vn / K;
                        body.velocity = body.velocity + (j * body.invMass) * n;
                        body.angularVelocity += body.invInertia * j * rn;
                    }
                }
                return;
            }
            push(a, b, normal, deepest - c[a], deepest - c[b], bottom - top, factor);
            return;
        }
        for (int k = 0; k < m.contactCount; ++k)
        {
            const Vec2 point = m.contacts[k].point;
            push(a, b, m.normal, point - c[a], point - c[b], m.contacts[k].separation, factor);
        }
    };
    // Per contact: its bodies moved far against each other in the step, at the velocities that moved them.
    std::vector<uint8_t> farApart(solverContacts.size());
    for (size_t k = 0; k < solverContacts.size(); ++k)
    {
        const SolverContact& sc = solverContacts[k];
        const SolverBody& sa = solverBodies[sc.a];
        const SolverBody& sb = solverBodies[sc.b];
        farApart[k] = OutrunsPair(settings, bodies[sc.a], sa.v, sa.w, bodies[sc.b], sb.v, sb.w, dt) ? 1 : 0;
    }
    // One contact's points moved apart by `factor` of their overlap beyond the slop.
    const auto correct = [&](const SolverContact& sc, double factor) {
        const int a = sc.a, b = sc.b;
        // A body that took a hit went where the sweep sent it, which may be far from where this contact was
        // found: the contact's anchors and normal no longer describe its surroundings (measured from them, a
        // ball that crossed the room would seem deep in the wall it started beside, and be pushed through the
        // floor). The sweep leaves its bodies apart; the next step finds their contacts afresh.
        if (hit[static_cast<size_t>(a)] || hit[static_cast<size_t>(b)])
        {
            return;
        }
        // A position pass moves a body only out of an overlap its shapes have now: any other push lifts it with no
        // cause, energy from nowhere. The anchors and the normal follow a body's turn to first order only: for a
        // body that turned farther in the step than a contact follows (TurnsBeyondContacts: the sweep, not this
        // contact, held the pair), they measure an overlap that is not there (a spinning box's face, turned half a
        // radian about its centre, still reaching a post its outline has left), and each push turns that face
        // further in. Such a pair is measured afresh at the present poses, as a guard is.
        // So is a pair whose bodies moved far against each other in the step (OutrunsPair, the sweep's own rule):
        // the anchors hold only while each point stays on the face it was found on. A body sliding fast past a
        // thin post's end carries its face's plane beyond the post's corner, and measured against that plane the
        // corner, now clear of the body, seems deep inside it.
        if (spinning[static_cast<size_t>(a)] || spinning[static_cast<size_t>(b)] ||
            farApart[static_cast<size_t>(&sc - solverContacts.data())])
        {
            guard(sc, factor, false);
            return;
        }
        const SolverBody& sa = solverBodies[a];
        const SolverBody& sb = solverBodies[b];
        // The normal turns with the body that holds it; between two circles it joins their centres.
        Vec2 n0 = Rotate(turn[sc.normalBody == 1 ? b : a], sc.normal);
        if (!turns[a] && !turns[b])
        {
            const Vec2 d = c[b] - c[a];
            const double length = std::sqrt(LengthSquared(d));
            if (length > 0.0)
            {
                n0 = (1.0 / length) * d;
            }
        }
        for (int k = 0; k < sc.count; ++k)
        {
            // Each body's anchor is the point of its own surface: the contact point lies halfway between them, a
            // half separation along the normal from each. Turned with its body, an anchor off the surface would
            // swing by the turn times that offset: a body turning towards the floor across a wide speculative gap
            // would seem to reach it, and be lifted.
            const detail::SolverPoint& p = sc.points[k];
            const Vec2 half = (0.5 * p.separation) * sc.normal;
            const Vec2 rA = Rotate(turn[a], p.rA - half);
            const Vec2 rB = Rotate(turn[b], p.rB + half);
            const double sep = Dot((c[b] + rB) - (c[a] + rA), n0);
            // A bounce that carries the point out of this much overlap within the step is left to do so: the
            // separating speed the velocity passes left at the point, not the one the restitution asked for,
            // which other contacts may have taken back.
            const double C = std::max(-settings.maxCorrection, std::min(0.0, factor * (sep + settings.linearSlop)));
            if (p.bounce > 0.0 && Dot(detail::RelativeVelocity(sa, sb, p.rA, p.rB), sc.normal) * dt >= -C)
            {
                continue;
            }
            push(a, b, n0, rA, rB, sep, factor);
        }
    };
    const std::vector<Vec2> afterMove = c; // where the move left the centres, before the passes
    for (int pass = 0; pass < settings.positionIterations; ++pass)
    {
        for (const SolverContact& sc : solverContacts)
        {
            correct(sc, settings.correctionFactor);
        }
        for (const SolverContact& g : guards)
        {
            guard(g, settings.correctionFactor, false);
        }
    }
    // The passes move bodies too: pressed by a heavy body, a light one can be pushed right through a thin static
    // body within them, and the lift below finds no overlap with a body already past it. A body the passes moved
    // is swept, without turning, from where the move left it to where the passes put it, against each static body
    // it has a contact or a guard with, and stops where it would touch it.
    const auto stopAtStatic = [&](const SolverContact& sc) {
        const bool staticA = bodies[sc.a].type == BodyType::Static;
        if (staticA == (bodies[sc.b].type == BodyType::Static))
        {
            return;
        }
        const int s = staticA ? sc.a : sc.b, i = staticA ? sc.b : sc.a;
        const Vec2 d = c[i] - afterMove[i];
        if (!IsAwakeDynamic(bodies[i]) || LengthSquared(d) <= settings.linearSlop * settings.linearSlop)
        {
            return;
        }
        const SweepResult r =
            detail::AnyConcave(bodies[s], bodies[i])
                ? detail::SweepBodies(bodies[s], xfs[s], Vec2{}, bodies[i], PoseAt(i, afterMove[i]), d).result
                : Sweep(bodies[s].shape, xfs[s], Vec2{}, bodies[i].shape, PoseAt(i, afterMove[i]), d);
        if (r.status == SweepStatus::Overlapping)
        {
            // Already touching it (a body resting on the floor overlaps it by up to the slop): the sweep cannot
            // say when it would go in, for it is in. The passes may slide it along the static body and lift it
            // out, never take it deeper: the part of the displacement into the static body, along the normal of
            // their overlap, is taken out.
            const Vec2 out = r.initial.normal; // from the static body (A of the sweep) to the moving one
            const double into = Dot(d, out);
            if (into < 0.0)
            {
                c[i] = c[i] - into * out;
            }
        }
        else if (r.status == SweepStatus::Hit)
        {
            c[i] = afterMove[i] + r.toi * d;
        }
    };
    if (settings.positionIterations > 0)
    {
        for (const SolverContact& sc : solverContacts)
        {
            stopAtStatic(sc);
        }
        for (const SolverContact& g : guards)
        {
            stopAtStatic(g);
        }
    }
    // Last, the contacts with bodies that do not move (static or asleep) take out their whole overlap beyond the
    // slop. The passes share each overlap between the bodies by their masses: a heavy body landing on a light
    // sliver that lies on the floor pushes the sliver down as far as the floor pushes it up, and under enough
    // weight it sinks into the floor, and through a thin one. Nothing can push back a static body, so its overlap
    // is the one that must go.
    const auto fixed = [&](const SolverContact& sc) {
        const SolverBody& sa = solverBodies[sc.a];
        const SolverBody& sb = solverBodies[sc.b];
        return (sa.invMass == 0.0 && sa.invInertia == 0.0) || (sb.invMass == 0.0 && sb.invInertia == 0.0);
    };
    if (settings.positionIterations > 0)
    {
        for (const SolverContact& sc : solverContacts)
        {
            if (!fixed(sc))
            {
                continue;
            }
            // Against a static body, measured afresh as a guard is, and lifted straight out: a contact's anchors see
            // only the points found at the start of the step, and a sliver that turned can poke another corner into
            // the wall.
            if (bodies[sc.a].type == BodyType::Static || bodies[sc.b].type == BodyType::Static)
            {
                guard(sc, 1.0, true);
            }
            else
            {
                correct(sc, 1.0);
            }
        }
        for (const SolverContact& g : guards)
        {
            if (fixed(g))
            {
                guard(g, 1.0, true);
            }
        }
    }
    for (int i = 0; i < n; ++i)
    {
        if (IsAwakeDynamic(bodies[i]))
        {
            // The passes turned few bodies: the others keep the rotation Move computed for their angle.
            const Rot q = angle[i] == bodies[i].angle ? rotations[static_cast<size_t>(i)] : MakeRot(angle[i]);
            bodies[i].angle = angle[i];
            bodies[i].position = c[i] - Rotate(q, bodies[i].localCenter);
        }
    }
}

} // namespace satviz::detail
