// SPDX-License-Identifier: MIT
#include "view_choices.h"

namespace satviz
{

bool operator==(const ViewChoices& a, const ViewChoices& b)
{
    return a.bodyA == b.bodyA && a.bodyB == b.bodyB && a.query == b.query && a.steps == b.steps &&
           a.pitfall == b.pitfall && a.singlePrecision == b.singlePrecision && a.layers == b.layers;
}

ViewChoices ChoicesOfView(const SceneView& view)
{
    ViewChoices choices;
    choices.bodyA = view.bodyA;
    choices.bodyB = view.bodyB;
    choices.query = view.query;
    choices.steps = view.steps;
    choices.pitfall = view.pitfall;
    choices.singlePrecision = view.singlePrecision;
    choices.layers = view.layers.empty() ? kDefaultLayers : LayersFromNames(view.layers);
    return choices;
}

void WriteChoices(const ViewChoices& choices, SceneView& view)
{
    view.bodyA = choices.bodyA;
    view.bodyB = choices.bodyB;
    view.query = choices.query;
    view.steps = choices.steps;
    view.pitfall = choices.pitfall;
    view.singlePrecision = choices.singlePrecision;
    view.layers = LayerNames(choices.layers);
}

} // namespace satviz
