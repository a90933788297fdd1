// SPDX-License-Identifier: MIT
// satviz: scenes, read from JSON files shared by the tools, tests, figures and benchmarks.
#pragma once

#include <satviz/concave.h>
#include <satviz/material.h>
#include <satviz/shape.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace satviz
{

/// A body of a scene: a named shape placed in the world, how it moves, and what a rigid-body world makes of it.
struct Body
{
    std::string name; ///< unique name within the scene
    /// The shape, in the body frame. For a concave body (read with SceneOptions::concave), the convex hull of its
    /// outline: a bound for broadphases; the queries take `concave`.
    Shape shape;
    /// A concave body: the pieces of its "polygon" (decomposed on load by "decompose"); empty for a convex body.
    Concave concave;
    std::vector<Vec2> outline;                         ///< a concave body's outline as written; else empty
    DecomposeMethod decompose = DecomposeMethod::Fast; ///< how the outline was cut ("decompose": "fast" or "fewest")
    /// True for a concave body.
    bool IsConcave() const { return !concave.parts.empty(); }
    Vec2 position{};    ///< world position of the body origin
    double angle = 0.0; ///< rotation in radians, counter-clockwise
    /// Velocity of the centre of mass, world frame, in units per time unit. A step lasts the scene's world dt,
    /// 1 by default, so in a scene without a "world" block it is the displacement over one step.
    Vec2 velocity{};
    double angularVelocity = 0.0; ///< radians per time unit, counter-clockwise ("angular_velocity")
    bool isStatic = false;        ///< never moves ("static"): ground, walls; its density is ignored
    double density = 1.0;         ///< mass per unit area of a dynamic body, > 0
    /// Restitution in [0, 1] and frictions >= 0 ("restitution", "friction", "static_friction"); a file without
    /// "static_friction" gives the body's friction.
    Material material{};
    /// The body's transform (body frame to world).
    Transform Xf() const { return MakeTransform(position, angle); }
};

/// How a rigid-body world steps the scene: the optional "world" block of a scene file.
struct SceneWorld
{
    Vec2 gravity{};  ///< acceleration, units per time unit squared ("gravity": [x, y], default [0, 0])
    double dt = 1.0; ///< time units per step, > 0 ("dt", default 1: a velocity is the displacement over one step)
};

/// Which query a view shows.
enum class ViewQuery
{
    Automatic, ///< the swept test when the pair moves, else the static test
    Collide,   ///< the static test: overlap, MTV and contacts
    Sweep,     ///< the swept test: time of impact
};

/// Which algorithm a view's steps show.
enum class StepView
{
    Textbook, ///< the textbook test: both projection intervals on each distinct axis (TextbookCollide, TextbookSweep)
    Faces,    ///< the face tests as the fast queries run them (Collide, Sweep): one side of an axis per step
};

/// A classic mistake of SAT implementations.
enum class Pitfall
{
    None,               ///< no mistake: the right algorithm only
    UnnormalisedAxes,   ///< overlaps measured on edge normals of different lengths, compared as if unit
    UncheckedDirection, ///< the push taken along a face normal as it points, without checking it points from A to B
    OneShapesAxes,      ///< only A's face normals tested
    SampledMotion,      ///< a moving pair tested at the start and the end of the step only (tunnelling)
    FloatWorld,         ///< float arithmetic on world coordinates, which far from the origin lose the overlap
};

/// The scene-file name of a pitfall ("unnormalised-axes", ...; "none"): the one list of them.
std::string_view PitfallName(Pitfall pitfall);

/// The pitfall of a name, false for an unknown one.
bool PitfallFromName(std::string_view name, Pitfall& pitfall);

/// What a figure of the scene shows ("figure" in the view block).
enum class FigureKind
{
    Pair,          ///< "pair": the SAT test of the pair, step by step (the default)
    Decomposition, ///< "decomposition": the pair's first body cut into convex pieces by both methods, side by side
    Slice,         ///< "slice": the pair's first body before and after a cut along the view's `cut` segment
    DiscCast,      ///< "disc-cast": the pair's second body, a circle, cast along its velocity against the first
    /// "pieces": the SAT test of a pair with a concave body, step by step: the broadphase over the pieces' boxes,
    /// each pair of pieces tested, the merged verdict
    Pieces,
};

/// The scene-file name of a figure kind ("pair", "decomposition", ...): the one list of them.
std::string_view FigureKindName(FigureKind kind);

/// The figure kind of a name, false for an unknown one.
bool FigureKindFromName(std::string_view name, FigureKind& kind);

/// The scene-file names of every figure kind, quoted, for error messages: "pair", ... or "decomposition".
std::string FigureKindList();

/// How a scene is to be pictured: camera, image size, layers, the pair and the step of its trace. Optional in a
/// scene file ("view": {...}); every field has a default.
struct SceneView
{
    bool fit = true;                        ///< frame the pair automatically (ignores center and zoom)
    Vec2 center{};                          ///< world point at the image centre, when not fit
    double zoom = 100.0;                    ///< pixels per world unit, when not fit
    int width = 800;                        ///< image width in pixels
    int height = 600;                       ///< image height in pixels
    std::vector<std::string> layers;        ///< layer names to draw; empty: the default set
    std::string bodyA;                      ///< first body of the pair; empty: the first body
    std::string bodyB;                      ///< second body of the pair; empty: the second body
    ViewQuery query = ViewQuery::Automatic; ///< which test to show
    StepView steps = StepView::Textbook;    ///< which algorithm the steps show ("steps": "textbook" or "faces")
    Pitfall pitfall = Pitfall::None;        ///< a classic mistake shown beside the right answer ("pitfall": name)
    /// Trace step to show, from 0 here; -1: the last step (the verdict). A scene file counts from 1 ("step": 1 is
    /// the first axis, as every view numbers it); 0 from older files also means the first.
    int step = -1;
    double time = -1.0;           ///< sweeps: draw the moving shapes at this time in [0, 1]; -1: not drawn
    std::string caption;          ///< text drawn above the figure; empty: the step's own description
    bool singlePrecision = false; ///< run the queries in float ("precision": "float") instead of double
    /// Rigid-body steps to take before the scene is pictured ("sim_steps"): its world (MakeWorld) is stepped this
    /// many times by the scene's dt and the bodies are drawn where the world leaves them (SimulateScene). 0, the
    /// default: drawn as written.
    int simSteps = 0;
    FigureKind figure = FigureKind::Pair; ///< what the figure shows ("figure"; default "pair")
    /// A slice figure's cut: the segment from cut[0] to cut[1], world coordinates ("cut": [[x, y], [x, y]]).
    Vec2 cut[2] = {};
};

/// Most rigid-body steps a view may ask for before it is pictured ("sim_steps").
constexpr int kMaxViewSimSteps = 1000000;

/// Largest accepted image side of a view, in pixels.
constexpr int kMaxViewSize = 8192;

/// Smallest accepted view zoom, in pixels per world unit: a 1e12-wide world still fits in a few pixels.
constexpr double kMinViewZoom = 1e-9;

/// Largest accepted view zoom, in pixels per world unit (the app's wheel zoom stops at the same bounds).
constexpr double kMaxViewZoom = 1e12;

/// What a scene file held beyond the scene itself: its key order, "$schema", namespaced fields ("tool:field"),
/// shorthand shapes ("box", "regular") and numbers as written. Defined in scene.cpp, read by SceneToJson.
struct SceneSource;

/// A scene: bodies in the world.
struct Scene
{
    std::string description;  ///< optional free text
    std::vector<Body> bodies; ///< the bodies, in file order
    bool hasView = false;     ///< the file has a "view" block
    SceneView view;           ///< how to picture it (defaults when hasView is false)
    bool hasWorld = false;    ///< the file has a "world" block
    SceneWorld world;         ///< how a rigid-body world steps it (defaults when hasWorld is false)
    /// The file the scene was parsed from, so that saving keeps its form; null for a scene built in code. Copies
    /// of the scene share it.
    std::shared_ptr<const SceneSource> source;
};

/// The outcome of loading a scene: the scene, or a one-line error "FILE: JSON.PATH: what is wrong".
struct SceneResult
{
    Scene scene;       ///< the scene; empty when error is set
    std::string error; ///< empty on success
    /// True when the scene was loaded.
    bool Ok() const { return error.empty(); }
};

/// Largest accepted magnitude of a position, velocity, angular velocity, radius, vertex coordinate, density,
/// friction, gravity or dt in a scene file.
constexpr double kMaxSceneValue = 1e12;

/// What a reader of scenes takes beyond convex bodies.
struct SceneOptions
{
    /// A "polygon" may be concave (simple, either orientation): it is decomposed on load into convex pieces
    /// (Body::concave), by the body's "decompose" ("fast", the default, or "fewest"). Tools that cannot answer for
    /// concave bodies leave this off, and such a polygon is refused as not convex.
    bool concave = false;
};

/// Parses a scene from JSON text. `file` names the source in error messages.
/// Format (see core/scene/scene.schema.json): {"bodies": [{"name": "A", "polygon": [[x, y], ...], "position": [x, y],
/// "angle": 0.0, "velocity": [vx, vy]}, {"name": "B", "circle": {"radius": 0.5}, ...}]}. A body has exactly one
/// shape: "polygon" (counter-clockwise vertices), "box" ([width, height]), "regular" ({"sides": n, "radius": r})
/// or "circle" ({"radius": r, "center": [x, y]}). A body may also give "angular_velocity", "static" (true or
/// false), "density" (> 0), "restitution" (in [0, 1]), "friction" and "static_friction" (>= 0); the scene may give
/// "world": {"gravity": [x, y], "dt": s} (dt > 0). Unknown fields are errors, with a hint for misspellings, unless
/// namespaced ("tool:field").
SceneResult ParseScene(std::string_view text, const std::string& file, SceneOptions options = {});

/// Reads and parses a scene file.
SceneResult LoadScene(const std::string& file, SceneOptions options = {});

/// The scene as JSON text that ParseScene reads back to the same scene: bodies with their polygon vertices,
/// circles, positions, angles, velocities and, where not at their defaults, angular velocities and physical
/// fields, every number printed so that it reads back as the same double; the view and world blocks when the
/// scene has them. A scene parsed from a file (scene.source) keeps that file's form: its key
/// order, "$schema" and namespaced fields, a "box" or "regular" body whose shape is unchanged, fields it had at
/// their default values, and numbers as they were written where their value is unchanged; a field it did not
/// have is added only when it is not at its default. One body per line.
std::string SceneToJson(const Scene& scene);

/// Writes the scene to `file` atomically: a temporary file in the same directory, then renamed
/// over the target, so that a failed write never damages the existing file. A relative "$schema" path kept from
/// the source file is rewritten to point at the same schema from the new file's folder. Returns false with a
/// one-line error naming the file.
bool SaveScene(const Scene& scene, const std::string& file, std::string& error);

} // namespace satviz
