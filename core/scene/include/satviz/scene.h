// SPDX-License-Identifier: MIT
// satviz: scenes, read from JSON files shared by the tools, tests, figures and benchmarks.
#pragma once

#include <satviz/shape.h>

#include <string>
#include <string_view>
#include <vector>

namespace satviz
{

/// A body of a scene: a named shape placed in the world, with the displacement it makes over one step.
struct Body
{
    std::string name;   ///< unique name within the scene
    Shape shape;        ///< the shape, in the body frame
    Vec2 position{};    ///< world position of the body origin
    double angle = 0.0; ///< rotation in radians, counter-clockwise
    Vec2 velocity{};    ///< displacement over one step, world frame
    /// The body's transform (body frame to world).
    Transform Xf() const { return MakeTransform(position, angle); }
};

/// A scene: bodies in the world.
struct Scene
{
    std::string description;  ///< optional free text
    std::vector<Body> bodies; ///< the bodies, in file order
};

/// The outcome of loading a scene: the scene, or a one-line error "FILE: JSON.PATH: what is wrong".
struct SceneResult
{
    Scene scene;       ///< the scene; empty when error is set
    std::string error; ///< empty on success
    /// True when the scene was loaded.
    bool Ok() const { return error.empty(); }
};

/// Largest accepted magnitude of a position, velocity, radius or vertex coordinate in a scene file.
constexpr double kMaxSceneValue = 1e12;

/// Parses a scene from JSON text. `file` names the source in error messages.
/// Format (see core/scene/scene.schema.json): {"bodies": [{"name": "A", "polygon": [[x, y], ...], "position": [x, y],
/// "angle": 0.0, "velocity": [vx, vy]}, {"name": "B", "circle": {"radius": 0.5}, ...}]}. A body has exactly one
/// shape: "polygon" (counter-clockwise vertices), "box" ([width, height]), "regular" ({"sides": n, "radius": r})
/// or "circle" ({"radius": r, "center": [x, y]}). Unknown fields are errors, with a hint for misspellings, unless
/// namespaced ("tool:field").
SceneResult ParseScene(std::string_view text, const std::string& file);

/// Reads and parses a scene file.
SceneResult LoadScene(const std::string& file);

} // namespace satviz
