// SPDX-License-Identifier: MIT
// satviz: JSON output of query results and traces. nlohmann-json prints doubles in their shortest form that reads
// back as the same double.

#include <satviz/query_json.h>
#include <satviz/sweep.h>

namespace satviz
{
namespace
{

using Json = nlohmann::ordered_json;

Json Pair(Vec2 v)
{
    return Json::array({v.x, v.y});
}

const char* ShapeLetter(int shape)
{
    return shape == 0 ? "a" : "b";
}

const char* ExitName(TraceExit exit)
{
    switch (exit)
    {
    case TraceExit::SeparatingAxis:
        return "separating-axis";
    case TraceExit::AllAxesOverlap:
        return "all-axes-overlap";
    case TraceExit::VertexInside:
        return "vertex-inside";
    case TraceExit::None:
        break;
    }
    return "none";
}

} // namespace

Json AxisJson(const AxisRef& axis)
{
    switch (axis.kind)
    {
    case AxisKind::FaceNormal:
        return {{"kind", "face"}, {"shape", ShapeLetter(axis.shape)}, {"edge", axis.index}};
    case AxisKind::VertexToCenter:
        return {{"kind", "vertex-to-center"}, {"shape", ShapeLetter(axis.shape)}, {"vertex", axis.index}};
    case AxisKind::CenterToCenter:
        return {{"kind", "center-to-center"}};
    case AxisKind::None:
        break;
    }
    return nullptr;
}

Json ManifoldJson(const std::string& nameA, const std::string& nameB, const Manifold& manifold)
{
    Json pair = {{"a", nameA}, {"b", nameB}, {"overlap", manifold.overlap}};
    if (manifold.overlap)
    {
        pair["depth"] = manifold.depth + 0.0; // touching: -0 prints as 0
    }
    else
    {
        pair["gap"] = manifold.gap;
    }
    pair["normal"] = Pair(manifold.normal);
    Json contacts = Json::array();
    for (int i = 0; i < manifold.contactCount; ++i)
    {
        contacts.push_back(Pair(manifold.contacts[i].point));
    }
    pair["contacts"] = contacts;
    pair["axis"] = AxisJson(manifold.axis);
    return pair;
}

Json TraceJson(const Trace& trace)
{
    Json axes = Json::array();
    for (const AxisTest& test : trace.axes)
    {
        Json entry = AxisJson(test.axis);
        entry["direction"] = Pair(test.direction);
        entry["interval_a"] = Json::array({test.minA, test.maxA});
        entry["interval_b"] = Json::array({test.minB, test.maxB});
        entry["separation"] = test.separation;
        entry["support_a"] = test.supportA;
        entry["support_b"] = test.supportB;
        entry["separating"] = test.separating;
        entry["best"] = test.best;
        if (test.pruned)
        {
            entry["pruned"] = true;
            entry["bound"] = test.bound;
        }
        if (test.skipped)
        {
            entry["skipped"] = true;
            entry["duplicate_of"] = test.duplicateOf;
        }
        axes.push_back(entry);
    }
    Json out = {{"axes", axes}, {"exit", ExitName(trace.exit)}};
    if (trace.hasClip)
    {
        const ClipTrace& clip = trace.clip;
        Json clipped1 = Json::array();
        for (int k = 0; k < clip.sideClip1Count; ++k)
        {
            clipped1.push_back(Pair(clip.sideClip1[k]));
        }
        Json clipped2 = Json::array();
        for (int k = 0; k < clip.sideClip2Count; ++k)
        {
            clipped2.push_back({{"point", Pair(clip.sideClip2[k])},
                                {"separation", clip.clippedSeparation[k]},
                                {"kept", clip.kept[k]}});
        }
        out["clip"] = {{"reference_face", AxisJson(clip.reference)},
                       {"reference_vertices", Json::array({Pair(clip.referenceV1), Pair(clip.referenceV2)})},
                       {"reference_normal", Pair(clip.referenceNormal)},
                       {"incident_edge", {{"shape", ShapeLetter(clip.incidentShape)}, {"edge", clip.incidentEdge}}},
                       {"incident_vertices", Json::array({Pair(clip.incidentV1), Pair(clip.incidentV2)})},
                       {"side_clip_1", clipped1},
                       {"side_clip_2", clipped2},
                       {"fallback", clip.usedFallback}};
    }
    return out;
}

Json QuerySceneJson(const Scene& scene, const std::string& file, bool withTrace)
{
    Json pairs = Json::array();
    Trace trace;
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        for (size_t j = i + 1; j < scene.bodies.size(); ++j)
        {
            const Body& a = scene.bodies[i];
            const Body& b = scene.bodies[j];
            const Manifold manifold = Collide(a.shape, a.Xf(), b.shape, b.Xf(), withTrace ? &trace : nullptr);
            Json pair = ManifoldJson(a.name, b.name, manifold);
            // Only pairs where something moves are swept: a still pair has nothing to add.
            if (a.velocity != Vec2{} || b.velocity != Vec2{})
            {
                const SweepResult sweep = Sweep(a.shape, a.Xf(), a.velocity, b.shape, b.Xf(), b.velocity);
                pair["toi_status"] = sweep.status == SweepStatus::Miss  ? "miss"
                                     : sweep.status == SweepStatus::Hit ? "hit"
                                                                        : "overlapping";
                if (sweep.status == SweepStatus::Miss)
                {
                    pair["toi"] = nullptr;
                    pair["toi_normal"] = nullptr;
                    pair["toi_contacts"] = Json::array();
                }
                else
                {
                    pair["toi"] = sweep.toi + 0.0; // -0 prints as 0
                    pair["toi_normal"] = Pair(sweep.normal);
                    Json contacts = Json::array();
                    const ContactPoint* points =
                        sweep.status == SweepStatus::Hit ? sweep.contacts : sweep.initial.contacts;
                    const int count =
                        sweep.status == SweepStatus::Hit ? sweep.contactCount : sweep.initial.contactCount;
                    for (int k = 0; k < count; ++k)
                    {
                        contacts.push_back(Pair(points[k].point));
                    }
                    pair["toi_contacts"] = contacts;
                }
            }
            if (withTrace)
            {
                pair["trace"] = TraceJson(trace);
            }
            pairs.push_back(pair);
        }
    }
    return {{"scene", file}, {"pairs", pairs}};
}

} // namespace satviz
