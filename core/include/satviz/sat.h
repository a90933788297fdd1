// SPDX-License-Identifier: MIT
// satviz: the Separating Axis Theorem for 2D collision detection.
//
// SUMMARY
//   Convex polygons of any vertex count and circles. Overlap() answers yes or no as fast as possible; Collide()
//   returns the minimum translation vector (depth and unit normal from A to B), up to two contact points and the
//   axis that decided. Both can record a complete step trace (TraceT) for teaching views, with results
//   bit-identical to the untraced call. Double precision by default; every type and query also exists for float.
//
// THE IMPORTANT PARTS
//   math.h      Vec2, Rot, Transform and their operations.
//   polygon.h   Polygon; MakePolygon (validates: count, finite, duplicates, collinear, winding, convexity,
//               self-intersection, with an optional repair), ComputeHull, MakeBox, MakeRegularPolygon.
//   shape.h     Circle, and Shape (a polygon or a circle).
//   collide.h   Overlap(A, xfA, B, xfB) -> bool and Collide(A, xfA, B, xfB) -> Manifold, for every pair of shape
//               kinds; an optional Trace* records every step.
//   manifold.h  Manifold, ContactPoint, AxisRef (which shape, which edge or vertex).
//   trace.h     Trace: the axes in test order with both projection intervals, then the contact clipping.
//   sweep.h     Sweep(A, xfA, vA, B, xfB, vB): time of impact of translating shapes, exact at any speed, with
//               its own trace (entry and exit times per axis); SweepTime, the same without contact points.
//   slide.h     MoveAndSlide: move a shape through a step, stopping at surfaces and sliding along them.
//   raycast.h   RayCast(shape, xf, p1, p2): where a segment first meets a shape (bullets, picking).
//   decompose.h Decompose: a simple polygon (concave, either orientation) cut into convex pieces, fast (ear
//               clipping, Hertel-Mehlhorn) or fewest (exact dynamic programme); internal edges flagged; an outline
//               that is not simple is refused naming the two edges that meet.
//   concave.h   Concave: the pieces of a decomposition as one shape, in Overlap, Collide (one manifold per pair,
//               contacts along internal edges dropped or re-tested on the surface axes), Sweep and RayCast.
//   disc_cast.h CastDisc(shape, xf, p1, p2, radius): thick bullets, a disc moved along a segment, like RayCast.
//   slice.h     SliceConvex (a convex polygon cut by a line into two convex parts) and SliceAlongSegment (a
//               simple polygon cut wherever a segment crosses it from outline to outline).
//   cache.h     SatCache: a pair's separating face from the previous frame, tested first by Overlap next frame.
//   textbook.h  TextbookCollide and TextbookSweep: the test as textbooks teach it (intervals on each distinct
//               axis), for reading and for the teaching views; the queries above answer the same, faster.
//
// CONVENTIONS
//   y points up; angles are radians, counter-clockwise. Polygon vertices are listed counter-clockwise in the body
//   frame, so the interior lies to the left of each edge and RightPerp(edge) is the outward normal. A transform
//   maps body coordinates to world: world = Rotate(q, local) + p. Normals in results point from A to B: moving B
//   by depth * normal separates the shapes. Touching shapes overlap with depth 0.
//
// NUMERIC ROBUSTNESS
//   The queries work in A's frame: B's offset from A is formed as xfB.p - xfA.p before any rotation, so a pair far
//   from the origin (1e6, 1e8) is decided as precisely as the same pair at the origin; only the world coordinates
//   of the returned contact points carry the rounding of their magnitude. Support points are found by walking
//   along the outline and deciding on the sign of Dot(direction, edge), never by comparing two rounded
//   projections, so nearly parallel edges cannot send the walk astray. Construction rejects collinear vertices
//   (turns below a few ulps), whose turn direction rounding could not decide.
//
// COST
//   Overlap and Collide run in O(n + m) for polygons of n and m vertices. The vertices of a polygon of at most 16
//   are scanned: each face of the other polygon is tested against all of them, without branches, the fastest way at
//   that size; that is n m products, but with m at most 16. The support point of a larger polygon turns with the
//   normals of the other, so it is walked forward, not searched for each axis. Overlap of large polygons
//   tests only the faces that see one point of the other polygon (the others cannot separate): a bisection finds
//   them, so a pair whose point lies inside costs O(log n + log m). No heap allocation per query. Faces of B
//   exactly anti-parallel to a face of A lie on an axis already tested and are skipped; a face test is one side of
//   an axis, so an axis is two face tests (two aligned boxes: 2 axes, the four faces of A; two rotated boxes:
//   4 axes, all eight faces).
//
// REFERENCES
//   C. Ericson, Real-Time Collision Detection, Morgan Kaufmann 2005, chapter 5.
//   D. Gregorius, The Separating Axis Test between Convex Polyhedra, GDC 2013.
//   E. Catto, Contact Manifolds, GDC 2007.
#pragma once

#include <satviz/cache.h>
#include <satviz/collide.h>
#include <satviz/concave.h>
#include <satviz/decompose.h>
#include <satviz/disc_cast.h>
#include <satviz/manifold.h>
#include <satviz/math.h>
#include <satviz/polygon.h>
#include <satviz/raycast.h>
#include <satviz/shape.h>
#include <satviz/slice.h>
#include <satviz/slide.h>
#include <satviz/sweep.h>
#include <satviz/textbook.h>
#include <satviz/trace.h>
