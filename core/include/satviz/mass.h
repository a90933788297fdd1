// SPDX-License-Identifier: MIT
// satviz: mass, centre of mass and moment of inertia of a shape of uniform density.
#pragma once

#include <satviz/concave.h>
#include <satviz/shape.h>

namespace satviz
{

/// The mass properties of a shape of uniform density, in its body frame.
struct MassProperties
{
    double mass = 0.0;    ///< density times area
    Vec2 center{};        ///< centre of mass, body frame
    double inertia = 0.0; ///< moment of inertia about the centre of mass
};

/// Mass, centre of mass and moment of inertia of `shape` with `density` (mass per unit area, > 0).
/// Polygon: the sum over the triangles that the centroid fans out to the edges, each triangle's area and second
/// moment taken exactly (Ericson, Real-Time Collision Detection, and Catto's Box2D use the same fan; the fan's apex
/// at a point inside the polygon keeps every triangle small, so the sums lose no digits far from the body origin).
/// Circle: mass density pi r^2, inertia m r^2 / 2. O(n) for an n-gon.
MassProperties ComputeMass(const Shape& shape, double density);

/// Radius of the largest circle about the centre of mass inside the shape: the distance from `center` to the
/// nearest face of a polygon, the radius of a circle less the offset of `center` from the circle's centre. Used
/// to decide whether a body moves far within a step compared with its size. O(n) for an n-gon.
double InnerRadius(const Shape& shape, Vec2 center);

/// Largest distance from `center` to a point of the shape: the radius of the circle about `center` that holds it.
/// Bounds how far a point of the shape moves when the body turns. O(n) for an n-gon.
double OuterRadius(const Shape& shape, Vec2 center);

/// Bounds how far the outline of the shape moves, per radian, when the body turns about `center`: OuterRadius for a
/// polygon; for a circle the offset of its centre from `center` alone, since turning about its own centre leaves a
/// circle where it is (a spinning ball reaches no farther than a still one). O(n) for an n-gon.
double TurnRadius(const Shape& shape, Vec2 center);

/// Mass, centre of mass and moment of inertia of a concave shape with `density`: the pieces' masses summed, the
/// centre their mass-weighted mean, and each piece's inertia moved from its own centre to the shape's (parallel
/// axes: I + m d^2). The pieces do not overlap (they tile the outline), so the sums are the outline's own. O(n) in
/// the vertices of all pieces.
MassProperties ComputeMass(const Concave& shape, double density);

/// A concave shape's size for the sweep rule: the least InnerRadius of a piece about its own centroid. The centre of
/// mass of a concave shape may lie outside it (an L's), so the largest circle about it says nothing; a body whose
/// thinnest piece can move by a fraction of its own width within a step is fast. O(n).
double InnerRadius(const Concave& shape);

/// Largest distance from `center` to a point of any piece: the radius of the circle about `center` that holds the
/// shape. A concave shape is made of polygons, so this also bounds its turn (TurnRadius). O(n).
double OuterRadius(const Concave& shape, Vec2 center);

} // namespace satviz
