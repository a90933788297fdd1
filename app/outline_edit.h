// SPDX-License-Identifier: MIT
// satviz app: a body's shape as an outline the user edits (its vertices dragged, drawn by clicks, cut): the outline
// read from a body, and a body reshaped to an outline, convex or concave. No ImGui here.
#pragma once

#include <satviz/scene.h>

#include <string>
#include <vector>

namespace satviz
{

/// The outline the user edits, in the body frame: a concave body's outline as written, a polygon's vertices; empty
/// for a circle.
std::vector<Vec2> EditableOutline(const Body& body);

/// True when body-frame point `local` lies inside the outline (crossing number; either orientation).
bool InsideOutline(const std::vector<Vec2>& outline, Vec2 local);

/// Gives `body` the shape of `outline` (body frame, either orientation): a convex polygon when the decomposition
/// (the body's own method) gives one piece, its vertices in the order given (reversed when they run clockwise);
/// else a concave body of its pieces, its outline as given. Returns "" on success; else why not ("polygon is not
/// simple: edge 1 (vertex 1 to 2) meets edge 3 (vertex 3 to 0)"; for a convex outline, a vertex repeated or on
/// the line through its neighbours, which a scene refuses too), and the body is unchanged.
std::string ReshapeToOutline(Body& body, const std::vector<Vec2>& outline);

/// Area centroid of a simple outline (either orientation); its first vertex when it encloses no area.
Vec2 OutlineCentroid(const std::vector<Vec2>& outline);

} // namespace satviz
