// SPDX-License-Identifier: MIT
// satviz: cutting a body of the world along a segment into new bodies that keep its motion.
#pragma once

#include <satviz/decompose.h>
#include <satviz/world.h>

#include <string>
#include <vector>

namespace satviz
{

/// Default least area, in square units, of a part that a cut keeps as a body. Below it a part is a sliver: thinner
/// than the world's default linear slop (0.005) along a cut of length 0.2, too thin for the contacts to hold.
constexpr double kMinCutArea = 1e-3;

/// How CutBody cuts.
struct CutOptions
{
    /// Parts whose area is below this (square units) are slivers: dropped, see CutBody.
    double minArea = kMinCutArea;
    /// How a concave part is cut into the convex pieces of its new body.
    DecomposeMethod method = DecomposeMethod::Fast;
};

/// What a cut did.
struct BodyCut
{
    bool cut = false;   ///< the body was replaced by two or more new bodies
    std::string reason; ///< why not, when not cut: one line ("a circle cannot be cut", ...)
    /// The new bodies' indices: the first takes the cut body's index, the others are appended to the world in
    /// order, so the indices of every other body stay as they were.
    std::vector<int> bodies;
    /// Each new body's outline in its body frame (which is the cut body's: same position and angle),
    /// counter-clockwise: what a scene writes for it.
    std::vector<std::vector<Vec2>> outlines;
    int slivers = 0;          ///< parts dropped for an area below CutOptions::minArea (or that could not be cut
                              ///< into convex pieces)
    double sliverMass = 0.0;  ///< their mass, gone from the world
    Vec2 sliverMomentum{};    ///< the linear momentum they carried away
    double sliverSpin = 0.0;  ///< the angular momentum they carried away, about the cut body's centre of mass
};

/// The outline of a body in its body frame, counter-clockwise: a polygon's vertices, or for a concave body the
/// outline edges of its pieces (those not internal) joined end to end. Empty for a circle.
std::vector<Vec2> BodyOutline(const RigidBody& body);

/// Cuts body `index` along the segment from world point `a` to `b`: wherever the segment runs through the body
/// from one point of its outline to another (SliceAlongSegment; a segment that stops inside does not cut that far,
/// and a line is a segment longer than the body). Each part becomes a body of its own, of the cut body's type,
/// material and density, at the same position and angle (its outline in the same body frame), convex or
/// concave (decomposed by CutOptions::method), with the mass, centre of mass and inertia of its own outline
/// (AddBody). Each moves as its point of the cut body moved: its velocity is the cut body's velocity at its new
/// centre of mass, v + w x (c_part - c), and its angular velocity w. The velocity field is the same rigid motion,
/// so the parts' linear momenta sum to the body's, and their spins plus the moments of their momenta to its
/// angular momentum about any point.
/// Slivers (parts below CutOptions::minArea) are dropped: their mass leaves the world with the momentum it carried
/// (reported, so the kept bodies' momentum is the body's less the slivers'). A cut that leaves fewer than two
/// parts of at least that area cuts nothing: the body stays whole, `cut` false. So does a circle, a segment that
/// does not cross the body, or an index out of range.
/// The contacts of the last step that involved the body are removed (its shape changed: their points and impulses
/// no longer belong to it), and the bodies they touched are woken, as are the new bodies. O(n^2) in the outline's
/// vertex count (the decomposition of the parts).
BodyCut CutBody(World& world, int index, Vec2 a, Vec2 b, const CutOptions& options = {});

} // namespace satviz
