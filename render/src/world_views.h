// SPDX-License-Identifier: MIT
// satviz render, private: the layers that draw a stepped world (Figure::sim): what the broadphase skipped, the
// solver's response to one contact, the step's time-ordered hits, and plots over the steps. Each lives in its own
// file; world_panels.cpp stacks their panels below the figure and dispatches to them.
#pragma once

#include "draw_kit.h"
#include "label_placer.h"

#include <satviz/render/painter.h>

namespace satviz
{

/// Height of the world's panels at the bottom of a figure with these layers (0 when none of them is on).
float WorldPanelsHeight(LayerMask layers);

/// Draws the world's layers in the scene, above the bodies: boxes and pairs, sleeping bodies hatched (broadphase);
/// impulse arrows at the contact points (response); the bodies at each hit (hits).
void PaintWorldScene(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene, const Figure& figure,
                     const ScreenRect& bounds);

/// Draws the world's panels from `top` to the bottom of the figure.
void PaintWorldPanels(Canvas& canvas, const Scene& scene, const Figure& figure, float top);

// One layer each (the files broadphase_view.cpp, response_view.cpp, hits_view.cpp, plots_view.cpp).

/// Panel heights in pixels.
constexpr float kCountsPanel = 28.0f;
constexpr float kResponsePanel = 262.0f;
constexpr float kHitsPanel = 82.0f;
constexpr float kPlotsPanel = 150.0f;

/// The broadphase's boxes and pairs, and sleeping bodies hatched.
void PaintBroadphaseScene(Canvas& canvas, const View& view, const Scene& scene, const SimRecord& sim,
                          const ScreenRect& bounds);
/// The step's counts in one line.
void PaintCountsPanel(Canvas& canvas, const SimRecord& sim, float width, float top);

/// Arrows for the normal and friction impulses at the chosen contact's points.
void PaintResponseScene(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene,
                        const SimRecord& sim);
/// The response's steps, one sentence each, and the passes' impulses before and after the clamp.
void PaintResponsePanel(Canvas& canvas, const Scene& scene, const SimRecord& sim, float width, float top);

/// The bodies of each hit at its time, dashed and numbered; when `chosen` is a hit of the step, that hit's bodies
/// alone, solid.
void PaintHitsScene(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene, const SimRecord& sim,
                    int chosen, const ScreenRect& bounds);
/// The hits on a time bar of the step, in the order resolved; `chosen` (a hit of the step, or -1) ringed, and its
/// instant said.
void PaintHitsPanel(Canvas& canvas, const Scene& scene, const SimRecord& sim, int chosen, float width, float top);
/// Where the hits panel at `top` puts each hit's dot and label.
std::vector<HitMark> LayOutHitMarks(Canvas& canvas, const Scene& scene, const SimRecord& sim, float width, float top);
/// Top of the hits panel among the world's panels that start at `worldTop`.
float HitsPanelTop(LayerMask layers, float worldTop);

/// Energy, momentum and the deepest overlap over the steps, the current step marked.
void PaintPlotsPanel(Canvas& canvas, const SimRecord& sim, float width, float top);

/// The ink of a body in world views: the recorded pair's first body blue, its second orange, the others grey.
inline Color PairInk(const SimRecord& sim, int body)
{
    return body == sim.contact.bodyA ? palette::kShapeA
                                     : (body == sim.contact.bodyB ? palette::kShapeBInk : palette::kMuted);
}

} // namespace satviz
