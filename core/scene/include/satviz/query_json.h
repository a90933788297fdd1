// SPDX-License-Identifier: MIT
// satviz: query results and step traces as JSON, as printed by satviz-query.
#pragma once

#include <satviz/collide.h>
#include <satviz/scene.h>
#include <satviz/textbook.h>

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>

namespace satviz
{

/// The deciding axis as JSON: {"kind": "face", "shape": "a", "edge": 2}, {"kind": "vertex-to-center", "shape": "b",
/// "vertex": 1} or {"kind": "center-to-center"}.
nlohmann::ordered_json AxisJson(const AxisRef& axis);

/// One pair's result: {"a", "b", "overlap", "depth" or "gap", "normal", "contacts", "axis"}.
nlohmann::ordered_json ManifoldJson(const std::string& nameA, const std::string& nameB, const Manifold& manifold);

/// A step trace of the face tests: {"view": "faces"}, the axes in test order with their intervals, the contact
/// clipping and why the test ended.
nlohmann::ordered_json TraceJson(const Trace& trace);

/// A step trace of the textbook test: {"view": "textbook"}, each distinct axis with the faces on it, both
/// intervals, the gap or the overlap and the way of the shorter push, then the result (the MTV).
nlohmann::ordered_json TextbookTraceJson(const TextbookTrace& trace);

/// A step trace of the textbook swept test: each axis with its intervals at t = 0, the rate, entry and exit.
nlohmann::ordered_json TextbookSweepTraceJson(const TextbookSweepTrace& trace);

/// Every pair of bodies of a scene, in file order, then every body with its convex pieces: {"scene": file,
/// "pairs": [...], "bodies": [{"name", "pieces"}, ...]} (a concave body adds "decompose" and "vertices", its pairs
/// "piece_pairs" and the axis's "piece"). A scene whose view is a slice figure adds "cut": its cut applied to the
/// body in the scene's world (CutBody), each part's mass, centroid, inertia and motion, and the momenta before and
/// after. Pairs where a body moves also
/// carry "toi" (the time of impact in [0, 1], 0 when overlapping at the start, null for a miss), "toi_normal" and
/// "toi_contacts". With `withTrace`, each pair also carries its "trace" in the chosen view (and, in the textbook
/// view, moving pairs their "sweep_trace"). `progress`, when not null, gets a line before each long trace.
nlohmann::ordered_json QuerySceneJson(const Scene& scene, const std::string& file, bool withTrace,
                                      StepView view = StepView::Textbook, std::ostream* progress = nullptr);

/// The pairs of bodies that touch or overlap, found through the broadphase (TouchingPairs), in body order:
/// {"scene": file, "touching": [["A", "B"], ...], "bodies": n}. Close to linear in the number of bodies.
nlohmann::ordered_json TouchingSceneJson(const Scene& scene, const std::string& file);

} // namespace satviz
