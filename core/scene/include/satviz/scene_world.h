// SPDX-License-Identifier: MIT
// satviz: a scene as a rigid-body world, and the world's state back into the scene.
#pragma once

#include <satviz/scene.h>
#include <satviz/world.h>

#include <string>

namespace satviz
{

/// The definition AddBody takes for a scene body: its shape, static or dynamic, density, material, position,
/// angle, velocity and angular velocity.
BodyDef MakeBodyDef(const Body& body);

/// Empty when every body of the scene makes a valid world body, else the first problem, naming the body by its
/// JSON path and name ("bodies[2] (\"ball\"): density must be > 0"). A loaded scene always passes; a scene built
/// or edited in code may not.
std::string ValidateSceneWorld(const Scene& scene);

/// A world for the scene: its gravity, and one body per scene body in the scene's order (body i of the world is
/// body i of the scene), added by AddBody. The scene must pass ValidateSceneWorld. The world's other settings are
/// its defaults; the step length is the caller's (scene.world.dt).
World MakeWorld(const Scene& scene);

/// Copies the world's state into the scene's bodies, body i to body i: positions, angles (turned into [-pi, pi]:
/// the same orientation, without the world's count of whole turns), velocities and angular velocities, so that
/// SaveScene writes the world as it is now as a scene that loads again. The world must have
/// been made from the scene (the same number of bodies).
void CopyWorldState(const World& world, Scene& scene);

/// CopyWorldState for a world stepped `steps` times, unless a body's position, velocity or angular velocity is
/// beyond what a scene holds (kMaxSceneValue): then it returns that problem, naming the body and the step count,
/// and leaves the scene unchanged, as a file keeps a state whole or not at all. Returns "" when copied.
std::string StoreWorldState(const World& world, Scene& scene, int steps);

/// Steps the scene as a world `steps` (>= 0) times by its dt and copies the state back: MakeWorld, Step,
/// CopyWorldState. What satviz-render and the app do for a view's sim_steps. Returns "" on success, else the
/// problem, the scene unchanged: a scene that fails ValidateSceneWorld, a negative count, or a state the scene
/// format cannot hold (a body flung beyond kMaxSceneValue).
std::string SimulateScene(Scene& scene, int steps);

} // namespace satviz
