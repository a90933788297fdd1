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

} // namespace satviz
