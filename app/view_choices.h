// SPDX-License-Identifier: MIT
// satviz app: what the viewer is asked to show, as a scene's view block records it. The viewer holds these choices,
// a save writes them into the file, and each change of one is an edit that undo takes back.
#pragma once

#include <satviz/layers.h>
#include <satviz/scene.h>

#include <string>

namespace satviz
{

/// The viewer's choices that belong to the scene: the pair, the query, the algorithm the steps show, the pitfall,
/// the precision and the layers. They are saved in the view block and restored by undo and redo.
struct ViewChoices
{
    std::string bodyA;                      ///< first body of the pair; empty: the scene's first body
    std::string bodyB;                      ///< second body of the pair; empty: the scene's second body
    ViewQuery query = ViewQuery::Automatic; ///< which test is shown
    StepView steps = StepView::Textbook;    ///< which algorithm the steps show
    Pitfall pitfall = Pitfall::None;        ///< a classic mistake shown beside the right answer
    bool singlePrecision = false;           ///< the queries run in float instead of double
    LayerMask layers = kDefaultLayers;      ///< layers drawn
};

/// True when both hold the same choices.
bool operator==(const ViewChoices& a, const ViewChoices& b);

/// False when both hold the same choices.
inline bool operator!=(const ViewChoices& a, const ViewChoices& b)
{
    return !(a == b);
}

/// The choices a scene's view block makes (the default layers when it names none).
ViewChoices ChoicesOfView(const SceneView& view);

/// Writes `choices` into a view block, as a saved scene holds them (the layers by name, in drawing order).
void WriteChoices(const ViewChoices& choices, SceneView& view);

} // namespace satviz
