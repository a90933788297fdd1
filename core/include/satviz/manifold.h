// SPDX-License-Identifier: MIT
// satviz: the result of a collision query.
#pragma once

#include <satviz/math.h>

namespace satviz
{

/// Where a SAT axis comes from.
enum class AxisKind
{
    None,           ///< no axis (not computed)
    FaceNormal,     ///< the outward normal of edge `index` of polygon `shape`
    VertexToCenter, ///< the direction from vertex `index` of polygon `shape` to the circle's centre
    CenterToCenter, ///< the direction from circle A's centre to circle B's centre
};

/// A reference to a SAT axis: its kind, the shape it belongs to (0 = A, 1 = B, -1 = both) and the edge or vertex.
struct AxisRef
{
    AxisKind kind = AxisKind::None; ///< where the axis comes from
    int shape = -1;                 ///< 0 for shape A, 1 for shape B, -1 when the axis belongs to neither alone
    int index = -1;                 ///< edge index (FaceNormal) or vertex index (VertexToCenter), else -1
};

/// One contact point of a manifold.
template <typename S>
struct ContactPointT
{
    Vec2T<S> point{}; ///< world position, halfway between the two surfaces
    S separation{};   ///< signed distance between the surfaces at this point along the normal (< 0: penetrating)
};

/// Double-precision contact point.
using ContactPoint = ContactPointT<double>;

/// The result of Collide: whether the shapes overlap, the minimum translation vector and the contact points.
/// Touching shapes (separation exactly zero) overlap with depth 0: shapes are closed sets.
template <typename S>
struct ManifoldT
{
    bool overlap = false; ///< the shapes intersect (touching counts)
    /// Penetration depth (>= 0) when overlapping: moving B by depth * normal separates the shapes, and no shorter
    /// translation does. 0 when separated.
    S depth{};
    /// When separated: the gap (> 0) along `normal` on the separating axis that ended the test. It is a lower
    /// bound of the distance between the shapes, not the distance itself. 0 when overlapping.
    S gap{};
    /// Unit normal in world space, from A to B. Overlapping: the direction of the minimum translation vector of B.
    /// Separated: the separating axis, oriented from A to B.
    Vec2T<S> normal{};
    ContactPointT<S> contacts[2]{}; ///< contact points, valid up to contactCount
    int contactCount = 0;           ///< 0 when separated, 1 or 2 when overlapping
    /// The deciding axis: overlapping, the axis of least penetration (for polygons: the reference face, the face of
    /// largest separation over both polygons, A's on a tie, so that the normal and the contacts are then those of
    /// A's face); separated, the separating axis found.
    AxisRef axis{};
    /// Polygon pairs that overlap: the incident edge, on the shape that is not axis.shape; else -1.
    int incidentEdge = -1;
};

/// Double-precision manifold.
using Manifold = ManifoldT<double>;

} // namespace satviz
