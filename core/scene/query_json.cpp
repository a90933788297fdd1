// SPDX-License-Identifier: MIT
// satviz: JSON output of query results and traces. nlohmann-json prints doubles in their shortest form that reads
// back as the same double.

#include <satviz/query_json.h>
#include <satviz/scene_world.h>
#include <satviz/sweep.h>
#include <satviz/world.h>
#include <satviz/world_cut.h>

#include <cmath>
#include <ostream>

namespace satviz
{
namespace
{

using Json = nlohmann::ordered_json;

Json Pair(Vec2 v)
{
    return Json::array({v.x + 0.0, v.y + 0.0}); // -0 prints as 0
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

// A swept pair's fields: "toi_status", "toi", "toi_normal", "toi_contacts".
void SweepJson(Json& pair, const SweepResult& sweep)
{
    pair["toi_status"] = sweep.status == SweepStatus::Miss  ? "miss"
                         : sweep.status == SweepStatus::Hit ? "hit"
                                                            : "overlapping";
    if (sweep.status == SweepStatus::Miss)
    {
        pair["toi"] = nullptr;
        pair["toi_normal"] = nullptr;
        pair["toi_contacts"] = Json::array();
        return;
    }
    pair["toi"] = sweep.toi + 0.0; // -0 prints as 0
    pair["toi_normal"] = Pair(sweep.normal);
    Json contacts = Json::array();
    const ContactPoint* points = sweep.status == SweepStatus::Hit ? sweep.contacts : sweep.initial.contacts;
    const int count = sweep.status == SweepStatus::Hit ? sweep.contactCount : sweep.initial.contactCount;
    for (int k = 0; k < count; ++k)
    {
        contacts.push_back(Pair(points[k].point));
    }
    pair["toi_contacts"] = contacts;
}

// The axis of a pair with a concave body names the piece its edge or vertex belongs to.
void NamePiece(Json& axis, const AxisRef& ref, int pieceA, int pieceB)
{
    const int piece = ref.shape == 0 ? pieceA : (ref.shape == 1 ? pieceB : -1);
    if (axis.is_object() && piece >= 0)
    {
        axis["piece"] = piece;
    }
}

// A pair with a concave body: the same fields as a convex pair, from the concave queries (concave.h).
Json ConcavePairJson(const Body& a, const Body& b, bool withTrace, StepView view)
{
    ConcaveManifold m;
    if (a.IsConcave() && b.IsConcave())
    {
        m = Collide(a.concave, a.Xf(), b.concave, b.Xf());
    }
    else if (a.IsConcave())
    {
        m = Collide(a.concave, a.Xf(), b.shape, b.Xf());
    }
    else
    {
        m = Collide(a.shape, a.Xf(), b.concave, b.Xf());
    }
    Json pair = ManifoldJson(a.name, b.name, m.manifold);
    NamePiece(pair["axis"], m.manifold.axis, m.pieceA, m.pieceB);
    // How the pieces took part: the pairs of pieces whose boxes overlapped (each collided as a convex pair), those
    // that overlap, and those whose push pointed along a seam (left out).
    pair["piece_pairs"] = {{"tested", m.pairsTested}, {"overlapping", m.pairsOverlap}, {"seam", m.pairsSeam}};
    if (a.velocity != Vec2{} || b.velocity != Vec2{})
    {
        ConcaveSweepResult sweep;
        if (a.IsConcave() && b.IsConcave())
        {
            sweep = Sweep(a.concave, a.Xf(), a.velocity, b.concave, b.Xf(), b.velocity);
        }
        else if (a.IsConcave())
        {
            sweep = Sweep(a.concave, a.Xf(), a.velocity, b.shape, b.Xf(), b.velocity);
        }
        else
        {
            sweep = Sweep(a.shape, a.Xf(), a.velocity, b.concave, b.Xf(), b.velocity);
        }
        SweepJson(pair, sweep.result);
    }
    if (withTrace)
    {
        pair["trace"] = {{"view", view == StepView::Faces ? "faces" : "textbook"},
                         {"note", "a pair with a concave body is tested piece by piece; no step trace is recorded"}};
    }
    return pair;
}

// Each body's name and convex pieces: a concave body's count and how its outline was cut, 1 for any other.
Json BodiesJson(const Scene& scene)
{
    Json bodies = Json::array();
    for (const Body& body : scene.bodies)
    {
        Json entry = {{"name", body.name}, {"pieces", body.IsConcave() ? body.concave.parts.size() : size_t{1}}};
        if (body.IsConcave())
        {
            entry["decompose"] = body.decompose == DecomposeMethod::Fast ? "fast" : "fewest";
            entry["vertices"] = body.outline.size();
        }
        bodies.push_back(std::move(entry));
    }
    return bodies;
}

// The body's linear momentum m v and its angular momentum about the world origin, I w + m (c x v).
void AddMomentum(const RigidBody& body, Vec2& momentum, double& angular)
{
    const Vec2 c = TransformPoint(MakeTransform(body.position, body.angle), body.localCenter);
    momentum = momentum + body.mass * body.velocity;
    angular += body.inertia * body.angularVelocity + body.mass * Cross(c, body.velocity);
}

// The body's kinetic energy, 1/2 m |v|^2 + 1/2 I w^2.
double Energy(const RigidBody& body)
{
    return 0.5 * body.mass * Dot(body.velocity, body.velocity) +
           0.5 * body.inertia * body.angularVelocity * body.angularVelocity;
}

// The slice figure's cut applied to its body in the scene's world (CutBody): each part's mass, centre of mass,
// inertia and motion, and the momenta and kinetic energies before and after.
Json CutJson(const Scene& scene)
{
    int index = 0;
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        if (!scene.view.bodyA.empty() && scene.bodies[i].name == scene.view.bodyA)
        {
            index = static_cast<int>(i);
        }
    }
    if (const std::string problem = ValidateSceneWorld(scene); !problem.empty())
    {
        return {{"body", scene.bodies[static_cast<size_t>(index)].name}, {"cut", false}, {"reason", problem}};
    }
    World world = MakeWorld(scene);
    Vec2 momentumBefore{};
    double angularBefore = 0.0;
    AddMomentum(world.bodies[static_cast<size_t>(index)], momentumBefore, angularBefore);
    const double energyBefore = Energy(world.bodies[static_cast<size_t>(index)]);
    const Body& source = scene.bodies[static_cast<size_t>(index)];
    CutOptions options;
    options.method = source.decompose;
    const BodyCut cut = CutBody(world, index, scene.view.cut[0], scene.view.cut[1], options);
    Json out = {{"body", source.name}, {"cut", cut.cut}};
    if (!cut.cut)
    {
        out["reason"] = cut.reason;
        return out;
    }
    Json parts = Json::array();
    Vec2 momentumAfter{};
    double angularAfter = 0.0;
    double energyAfter = 0.0;
    for (size_t k = 0; k < cut.bodies.size(); ++k)
    {
        const RigidBody& part = world.bodies[static_cast<size_t>(cut.bodies[k])];
        const Vec2 c = TransformPoint(MakeTransform(part.position, part.angle), part.localCenter);
        // The area of the part's outline (shoelace), which a static part, of no mass, has too.
        const std::vector<Vec2>& outline = cut.outlines[k];
        double twice = 0.0;
        for (size_t i = 0; i < outline.size(); ++i)
        {
            twice += Cross(outline[i], outline[(i + 1) % outline.size()]);
        }
        parts.push_back({{"area", std::abs(0.5 * twice)},
                         {"mass", part.mass},
                         {"centroid", Pair(c)},
                         {"inertia", part.inertia},
                         {"pieces", part.concave.parts.empty() ? size_t{1} : part.concave.parts.size()},
                         {"velocity", Pair(part.velocity)},
                         {"angular_velocity", part.angularVelocity + 0.0}});
        AddMomentum(part, momentumAfter, angularAfter);
        energyAfter += Energy(part);
    }
    out["parts"] = parts;
    out["slivers"] = cut.slivers;
    out["momentum_before"] = Pair(momentumBefore);
    out["momentum_after"] = Pair(momentumAfter);
    out["angular_momentum_before"] = angularBefore + 0.0;
    out["angular_momentum_after"] = angularAfter + 0.0;
    out["kinetic_energy_before"] = energyBefore + 0.0;
    out["kinetic_energy_after"] = energyAfter + 0.0;
    return out;
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
    // The count the face view steps through ("face test 1 of N"), so a reader need not count the list.
    const int tested = static_cast<int>(trace.axes.size());
    Json out = {{"view", "faces"},
                {"axes", axes},
                {"faces_tested", tested},
                {"exit", ExitName(trace.exit)},
                {"untraced_path", trace.untracedPath == InstructionPath::Avx512 ? "avx512"
                                  : trace.untracedPath == InstructionPath::Avx2 ? "avx2"
                                                                                : "baseline"}};
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

namespace
{

Json FacesJson(const AxisRef* faces, int count)
{
    Json out = Json::array();
    for (int f = 0; f < count; ++f)
    {
        out.push_back(AxisJson(faces[f]));
    }
    return out;
}

// A time that may be infinite (JSON has no infinity): "never" and "always" in words, NaN as null.
Json TimeJson(double t)
{
    if (std::isnan(t))
    {
        return nullptr;
    }
    if (std::isinf(t))
    {
        return t > 0 ? "never" : "always";
    }
    return t + 0.0;
}

} // namespace

Json TextbookTraceJson(const TextbookTrace& trace)
{
    Json axes = Json::array();
    for (const TextbookAxis& t : trace.axes)
    {
        Json entry = {{"faces", FacesJson(t.faces, t.faceCount)},
                      {"direction", Pair(t.direction)},
                      {"interval_a", Json::array({t.minA, t.maxA})},
                      {"interval_b", Json::array({t.minB, t.maxB})},
                      {"separating", t.separating}};
        if (t.separating)
        {
            entry["gap"] = t.gap;
        }
        else
        {
            entry["overlap"] = t.overlap;
            entry["push"] = t.pushSign > 0 ? "along" : "against";
        }
        entry["best"] = t.best;
        axes.push_back(entry);
    }
    const TextbookResult& r = trace.result;
    Json result = {{"overlap", r.overlap}};
    if (r.overlap)
    {
        result["depth"] = r.depth;
    }
    else
    {
        result["gap"] = r.gap;
    }
    result["normal"] = Pair(r.normal);
    result["axis"] = r.axis;
    result["axes_tested"] = r.axesTested;
    result["axis_count"] = r.axisCount;
    return {{"view", "textbook"}, {"axes", axes}, {"result", result}};
}

Json TextbookSweepTraceJson(const TextbookSweepTrace& trace)
{
    Json axes = Json::array();
    for (const TextbookSweepAxis& t : trace.axes)
    {
        axes.push_back({{"faces", FacesJson(t.faces, t.faceCount)},
                        {"direction", Pair(t.direction)},
                        {"interval_a", Json::array({t.minA, t.maxA})},
                        {"interval_b", Json::array({t.minB, t.maxB})},
                        {"rate", t.rate + 0.0},
                        {"entry", TimeJson(t.entry)},
                        {"exit", TimeJson(t.exit)},
                        {"never", t.never},
                        {"latest_entry", t.latestEntry},
                        {"earliest_exit", t.earliestExit},
                        {"ends_test", t.endsTest}});
    }
    const TextbookSweepResult& r = trace.result;
    return {{"view", "textbook"},
            {"axes", axes},
            {"status", r.status == SweepStatus::Miss  ? "miss"
                       : r.status == SweepStatus::Hit ? "hit"
                                                      : "overlapping"},
            {"toi", r.status == SweepStatus::Hit ? Json(r.toi + 0.0) : Json(nullptr)}};
}

Json QuerySceneJson(const Scene& scene, const std::string& file, bool withTrace, StepView view, std::ostream* progress)
{
    // A trace records every face's intervals, so its cost grows with the square of the vertex count.
    constexpr int kSlowTrace = 4096;
    constexpr long long kTextbookTraceBudget = 400000000;
    Json pairs = Json::array();
    Trace trace;
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        for (size_t j = i + 1; j < scene.bodies.size(); ++j)
        {
            const Body& a = scene.bodies[i];
            const Body& b = scene.bodies[j];
            auto vertices = [](const Shape& s) { return s.type == ShapeType::Polygon ? s.polygon.Count() : 1; };
            const int total = vertices(a.shape) + vertices(b.shape);
            if (withTrace && progress != nullptr && total > kSlowTrace)
            {
                *progress << "satviz-query: " << file << ": tracing " << a.name << " and " << b.name << ", " << total
                          << " vertices (every face's intervals)" << std::endl;
            }
            if (a.IsConcave() || b.IsConcave())
            {
                pairs.push_back(ConcavePairJson(a, b, withTrace, view));
                continue;
            }
            const Manifold manifold = Collide(a.shape, a.Xf(), b.shape, b.Xf(), withTrace ? &trace : nullptr);
            Json pair = ManifoldJson(a.name, b.name, manifold);
            // Only pairs where something moves are swept: a still pair has nothing to add.
            if (a.velocity != Vec2{} || b.velocity != Vec2{})
            {
                SweepJson(pair, Sweep(a.shape, a.Xf(), a.velocity, b.shape, b.Xf(), b.velocity));
            }
            // The textbook test projects every vertex on every axis: past a budget the face tests are printed,
            // and the trace says why.
            const bool textbookTooLarge = static_cast<long long>(total) * total > kTextbookTraceBudget;
            if (withTrace && (view == StepView::Faces || textbookTooLarge))
            {
                pair["trace"] = TraceJson(trace);
                if (view == StepView::Textbook)
                {
                    pair["trace"]["note"] = "too many vertices for the textbook trace (every vertex on every axis): "
                                            "the face tests are printed";
                }
            }
            else if (withTrace)
            {
                TextbookTrace textbook;
                TextbookCollide(a.shape, a.Xf(), b.shape, b.Xf(), &textbook);
                pair["trace"] = TextbookTraceJson(textbook);
                if (a.velocity != Vec2{} || b.velocity != Vec2{})
                {
                    TextbookSweepTrace sweep;
                    TextbookSweep(a.shape, a.Xf(), a.velocity, b.shape, b.Xf(), b.velocity, &sweep);
                    pair["sweep_trace"] = TextbookSweepTraceJson(sweep);
                }
            }
            pairs.push_back(pair);
        }
    }
    Json result = {{"scene", file}, {"pairs", pairs}, {"bodies", BodiesJson(scene)}};
    if (scene.view.figure == FigureKind::Slice)
    {
        result["cut"] = CutJson(scene);
    }
    return result;
}

Json TouchingSceneJson(const Scene& scene, const std::string& file)
{
    std::vector<Shape> shapes;
    std::vector<Transform> transforms;
    shapes.reserve(scene.bodies.size());
    transforms.reserve(scene.bodies.size());
    for (const Body& body : scene.bodies)
    {
        shapes.push_back(body.shape);
        transforms.push_back(body.Xf());
    }
    Json touching = Json::array();
    for (const auto& [i, j] : TouchingPairs(shapes, transforms))
    {
        // A concave body's shape is its hull: the pair touches when its pieces do.
        const Body& a = scene.bodies[static_cast<size_t>(i)];
        const Body& b = scene.bodies[static_cast<size_t>(j)];
        if ((a.IsConcave() || b.IsConcave()) &&
            !(a.IsConcave() && b.IsConcave() ? Overlap(a.concave, a.Xf(), b.concave, b.Xf())
              : a.IsConcave()                ? Overlap(a.concave, a.Xf(), b.shape, b.Xf())
                                             : Overlap(a.shape, a.Xf(), b.concave, b.Xf())))
        {
            continue;
        }
        touching.push_back(
            Json::array({scene.bodies[static_cast<size_t>(i)].name, scene.bodies[static_cast<size_t>(j)].name}));
    }
    return {{"scene", file}, {"touching", std::move(touching)}, {"bodies", scene.bodies.size()}};
}

} // namespace satviz
