// SPDX-License-Identifier: MIT
// satviz render, private: the "voronoi" layer. The Voronoi regions of the pair's polygon outside it (Ericson 5.1):
// a face region in front of each edge, where the nearest point of the polygon lies on that edge, and a vertex
// region in the wedge at each corner, where the nearest point is the vertex. The region that holds the other
// shape's centre (a circle's centre, a polygon's centroid) is marked: it says which feature of the polygon that
// centre is nearest, and so which axis SAT needs against a circle (lesson 7).
#pragma once

#include "label_placer.h"

#include <satviz/render/study.h>
#include <satviz/scene.h>

namespace satviz
{

/// Shades the regions under the shapes, in the group "voronoi": face regions pale, vertex regions darker, both in
/// the polygon's colour, their borders dashed, and the region holding the other shape's centre in the result
/// colour. Draws nothing when neither shape of the pair is a polygon.
void PaintVoronoiRegions(Canvas& canvas, const View& view, const Scene& scene, const PairStudy& study);

/// Marks the other shape's centre with a dot above the shapes and names the regions ("face e2", "vertex 2"; the one
/// holding the centre in full, beside it). Call after the shapes are drawn and before their own labels are placed,
/// so that the centre's name keeps its place and the body's name moves off the dot; the region names, far out in
/// their regions, give way to any other label.
void MarkVoronoiRegions(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene,
                        const PairStudy& study);

} // namespace satviz
