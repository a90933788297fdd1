// SPDX-License-Identifier: MIT
// satviz: the SAT queries: Overlap (yes or no) and Collide (minimum translation vector and contacts).
#pragma once

#include <satviz/manifold.h>
#include <satviz/polygon.h>
#include <satviz/shape.h>
#include <satviz/trace.h>

namespace satviz
{

/// True when the shapes intersect (touching counts). Stops at the first separating axis (polygons of up to 8
/// vertices: at the first polygon whose faces, tested four at a time, hold one; on processors with AVX-512, whose
/// registers hold all 8 faces, both polygons are tested and decided at once, which costs less than the branch
/// between them), uses unnormalised edge normals (no square root, no division), and skips the faces of B that are
/// exactly anti-parallel to a face of A (their test is the same as that face's). Polygons above 16 vertices test
/// only the faces that see a point of the other polygon, found by bisection: O(log n + log m) plus those faces and
/// the walk of the support points between them, at most O(n + m). No heap allocation.
/// With a non-null `trace`, every step is recorded there; the answer is bit-identical either way.
template <typename S>
bool Overlap(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace = nullptr);

/// Polygon against circle; see the polygon overload.
template <typename S>
bool Overlap(const PolygonT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace = nullptr);

/// Circle against polygon; see the polygon overload.
template <typename S>
bool Overlap(const CircleT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace = nullptr);

/// Circle against circle.
template <typename S>
bool Overlap(const CircleT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace = nullptr);

/// Any two shapes.
template <typename S>
bool Overlap(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
             TraceT<S>* trace = nullptr);

/// The manifold of two polygons: overlap, penetration depth and unit normal from A to B (the minimum translation
/// vector, also when one polygon contains the other), up to two contact points from clipping the incident edge to
/// the reference face, and the deciding axis. The reference face is the face of largest separation (least
/// penetration) of either polygon; on a tie it is A's: B's face is taken only when its separation is strictly
/// larger. When separated: the separating axis found and its gap.
/// Works in A's frame (B relative to A), so shapes far from the origin keep their precision. O(n + m), no heap
/// allocation. With a non-null `trace`, every step is recorded; the result is bit-identical either way.
template <typename S>
ManifoldT<S> Collide(const PolygonT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace = nullptr);

/// Polygon against circle (Voronoi regions of the polygon: a face normal, or the axis from the closest vertex to
/// the circle's centre).
template <typename S>
ManifoldT<S> Collide(const PolygonT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace = nullptr);

/// Circle against polygon; the normal still points from A (the circle) to B.
template <typename S>
ManifoldT<S> Collide(const CircleT<S>& a, const TransformT<S>& xfA, const PolygonT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace = nullptr);

/// Circle against circle. Concentric circles get the normal (0, 1).
template <typename S>
ManifoldT<S> Collide(const CircleT<S>& a, const TransformT<S>& xfA, const CircleT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace = nullptr);

/// Any two shapes.
template <typename S>
ManifoldT<S> Collide(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
                     TraceT<S>* trace = nullptr);

/// Speculative contacts (Catto; Firth): Collide, and for shapes apart by at most `margin` (>= 0) also the contact
/// points they would have if they touched, each with its separation (> 0: the gap still open), so that a solver
/// can let the pair close its gap within a step and no more. `overlap`, `depth` and `gap` mean what they mean for
/// Collide; a pair apart by at most the margin has overlap false and contactCount 1 or 2, and its normal, gap and
/// axis are those of the reference face (the face of largest separation; for circles, their Voronoi axis), where
/// Collide stops at the first separating axis. Costs Collide when the shapes overlap or when Collide's separating
/// axis already holds them farther apart than the margin; otherwise, for two polygons, a face query of every face
/// of both and a clipping, O(n m) for small polygons. Not traced.
template <typename S>
ManifoldT<S> CollideWithin(const ShapeT<S>& a, const TransformT<S>& xfA, const ShapeT<S>& b, const TransformT<S>& xfB,
                           S margin);

} // namespace satviz
