// SPDX-License-Identifier: MIT
// satviz: move a shape through a step, stopping at surfaces and sliding along them.
#pragma once

#include <satviz/shape.h>

namespace satviz
{

/// A still obstacle for MoveAndSlide: a shape and where it is.
template <typename S>
struct ObstacleT
{
    const ShapeT<S>* shape = nullptr; ///< the obstacle's shape (not owned)
    TransformT<S> xf{};               ///< its transform
};

/// Double-precision obstacle.
using Obstacle = ObstacleT<double>;

/// Most contacts MoveAndSlide handles in one step.
constexpr int kMaxSlideContacts = 8;

/// The outcome of MoveAndSlide.
template <typename S>
struct SlideResultT
{
    TransformT<S> xf{};                    ///< the mover's transform at the end of the step
    Vec2T<S> remaining{};                  ///< displacement left over when the contact budget ran out (else 0)
    int contactCount = 0;                  ///< surfaces met during the step
    Vec2T<S> normals[kMaxSlideContacts]{}; ///< their normals, from the mover towards the obstacle, in order
    int obstacles[kMaxSlideContacts]{};    ///< which obstacle each contact was with
};

/// Double-precision slide result.
using SlideResult = SlideResultT<double>;

/// The gap MoveAndSlide keeps from surfaces when `skin` is not given: 1e-7 of the mover's size, and never less
/// than 64 ulps of its position, so that the next sweep from there sees a real gap rather than rounding.
template <typename S>
S DefaultSkin(const ShapeT<S>& mover, const TransformT<S>& xf);

/// Moves `mover` from `xf` by `displacement` through still obstacles (collide and slide):
///   1. Sweep the rest of the displacement against every obstacle; take the earliest hit.
///   2. Move to the time of impact, stopped `skin` short of the surface along its normal, so the next sweep from
///      there does not start touching (which would report t = 0 and stick); a hit already closer than `skin`
///      backs off along the normal to `skin`.
///   3. Remove the part of the remaining displacement that points into the surface; continue along it.
///   4. Stop when nothing is hit, or after `maxContacts` contacts (at most kMaxSlideContacts).
/// A mover that starts interpenetrating an obstacle is first pushed out along the minimum translation vector,
/// `skin` beyond touching (a contact); one that starts touching an obstacle, or closer to it than `skin`, is lifted
/// to `skin` from it (no contact). `skin` < 0 selects DefaultSkin. The mover keeps its orientation.
/// Cost: at most maxContacts + 1 rounds, each one SweepTime against every obstacle (no broadphase: pass only the
/// obstacles near the path). No heap allocation.
template <typename S>
SlideResultT<S> MoveAndSlide(const ShapeT<S>& mover, const TransformT<S>& xf, Vec2T<S> displacement,
                             const ObstacleT<S>* obstacles, int obstacleCount, S skin = S(-1), int maxContacts = 4);

} // namespace satviz
