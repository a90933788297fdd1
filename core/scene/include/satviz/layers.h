// SPDX-License-Identifier: MIT
// satviz scene: the drawing layers a scene's view can choose, in one table. Each row gives a layer's name (in scene
// files' "view.layers" and satviz-render's --layers), the bit the painter tests, whether a figure draws it when a
// scene does not choose, and the one-line description the app shows beside its switch. Everything else about layers
// is derived from it. It belongs to the scene format, which the loader checks against it; the painter, the renderer
// and the app read it from here.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace satviz
{

/// A set of drawing layers, one bit per layer.
using LayerMask = uint32_t;

/// The drawing layers. A layer that is off costs nothing: the painter skips its work entirely.
enum Layer : LayerMask
{
    kLayerShapes = 1u << 0,     ///< the bodies, filled and outlined
    kLayerLabels = 1u << 1,     ///< body names, vertex and edge numbers
    kLayerNormals = 1u << 2,    ///< outward edge normals
    kLayerAxes = 1u << 3,       ///< every candidate axis, faint, through the pair
    kLayerProjection = 1u << 4, ///< the current axis, both projection intervals on it and on a number line
    kLayerExit = 1u << 5,       ///< the early exit: the separating line of a separating axis
    kLayerBest = 1u << 6,       ///< the best (least overlap or latest entry) axis so far
    kLayerMtv = 1u << 7,        ///< the minimum translation vector and B moved out by it
    kLayerContacts = 1u << 8,   ///< contact points, reference face, incident edge, clipping planes
    kLayerSwept = 1u << 9,      ///< velocities, swept intervals, entry and exit times on a time bar
    kLayerGhost = 1u << 10,     ///< the moving shapes at the time of impact (and at the chosen time)
    kLayerCaption = 1u << 11,   ///< the caption above the figure
    /// An inset of the Minkowski difference A - B: the origin inside it exactly when the shapes overlap, the MTV as
    /// the origin's shortest way out, and for sweeps the relative motion as a ray from the origin.
    kLayerMinkowski = 1u << 12,
    /// The Voronoi regions of the pair's polygon (a face region in front of each edge, a vertex region at each
    /// corner), and the one that holds the other shape's centre.
    kLayerVoronoi = 1u << 13,
    /// A key to the figure's colours and marks, in a corner of the scene; drawn alone, the key to every mark.
    kLayerLegend = 1u << 14,
    /// What the world's broadphase skipped: each body's box grown by its reach, the pairs passed on as thin lines,
    /// the step's counts, sleeping bodies hatched.
    kLayerBroadphase = 1u << 15,
    /// The solver's response to the chosen contact: impulse arrows at its points and a panel of its steps.
    kLayerResponse = 1u << 16,
    kLayerHits = 1u << 17,  ///< the step's time-ordered hits on a time bar, and the bodies at each hit
    kLayerPlots = 1u << 18, ///< kinetic and potential energy, momentum and the deepest overlap over the steps
};

/// One drawing layer: a row of kLayerTable.
struct LayerInfo
{
    std::string_view name;        ///< its name in scene files ("view.layers") and satviz-render's --layers
    LayerMask bit = 0;            ///< the painter's bit for it (one of Layer)
    bool byDefault = false;       ///< drawn when a scene does not choose its layers
    std::string_view description; ///< one line for the app's layer switches
};

/// Every drawing layer, in drawing order: the one list of layer names, bits and descriptions (the "view block"
/// section of core/scene/README.md describes them for users).
inline constexpr std::array<LayerInfo, 19> kLayerTable = {{
    {"shapes", kLayerShapes, true, "the bodies, filled and outlined"},
    {"labels", kLayerLabels, true, "body names, vertex and edge numbers"},
    {"normals", kLayerNormals, false, "every outward edge normal"},
    {"axes", kLayerAxes, false, "every candidate axis, faint"},
    {"projection", kLayerProjection, true, "the current axis, both intervals, the number line"},
    {"exit", kLayerExit, true, "the separating line of an early exit"},
    {"best", kLayerBest, true, "the best axis so far"},
    {"mtv", kLayerMtv, true, "the minimum translation vector"},
    {"contacts", kLayerContacts, true, "contact points, reference face, incident edge"},
    {"swept", kLayerSwept, true, "velocities, swept intervals, the time bar"},
    {"ghost", kLayerGhost, true, "the moving bodies at the time of impact"},
    {"caption", kLayerCaption, true, "the step's sentence above the figure"},
    {"minkowski", kLayerMinkowski, false,
     "the Minkowski difference A - B in an inset: the origin inside it exactly when they overlap"},
    {"voronoi", kLayerVoronoi, false, "the polygon's face and vertex regions, and the one holding the other's centre"},
    {"legend", kLayerLegend, false, "a key to the colours and marks the figure uses"},
    {"broadphase", kLayerBroadphase, false,
     "the world's boxes grown by their reach, the pairs tested, the step's counts; sleeping bodies hatched"},
    {"response", kLayerResponse, false, "the solver's impulses on the pair's contact, step by step"},
    {"hits", kLayerHits, false, "the step's time-ordered hits on a time bar, and the bodies at each"},
    {"plots", kLayerPlots, false, "energy, momentum and the deepest overlap over the steps"},
}};

/// True when every row of the table has its own single bit, in drawing order (row i has bit i).
constexpr bool LayerTableIsOrdered()
{
    for (size_t i = 0; i < kLayerTable.size(); ++i)
    {
        if (kLayerTable[i].bit != (1u << i) || kLayerTable[i].name.empty())
        {
            return false;
        }
    }
    return true;
}
static_assert(LayerTableIsOrdered(), "each layer of kLayerTable has bit i in row i");

/// The mask of the table's layers: all of them, or with `defaultsOnly` those drawn by default.
constexpr LayerMask LayerTableMask(bool defaultsOnly)
{
    LayerMask mask = 0;
    for (const LayerInfo& layer : kLayerTable)
    {
        if (!defaultsOnly || layer.byDefault)
        {
            mask |= layer.bit;
        }
    }
    return mask;
}

/// Every layer.
constexpr LayerMask kAllLayers = LayerTableMask(false);
/// The layers drawn when a scene does not choose: all but the normals, the candidate axes, the Minkowski inset, the
/// Voronoi regions and the world's layers (broadphase, response, hits, plots).
constexpr LayerMask kDefaultLayers = LayerTableMask(true);

/// The row of the layer named `name` ("shapes", "labels", ...), or null for an unknown name.
constexpr const LayerInfo* FindLayer(std::string_view name)
{
    for (const LayerInfo& layer : kLayerTable)
    {
        if (layer.name == name)
        {
            return &layer;
        }
    }
    return nullptr;
}

/// The bit of the layer named `name`, or 0 for an unknown name.
constexpr LayerMask LayerFromName(std::string_view name)
{
    const LayerInfo* layer = FindLayer(name);
    return layer != nullptr ? layer->bit : 0;
}

/// The mask of a list of layer names; unknown names are ignored (the scene loader rejects them).
inline LayerMask LayersFromNames(const std::vector<std::string>& names)
{
    LayerMask mask = 0;
    for (const std::string& name : names)
    {
        mask |= LayerFromName(name);
    }
    return mask;
}

/// The names of the layers in `mask`, in drawing order (what a saved scene's "view.layers" lists).
inline std::vector<std::string> LayerNames(LayerMask mask)
{
    std::vector<std::string> names;
    for (const LayerInfo& layer : kLayerTable)
    {
        if (mask & layer.bit)
        {
            names.emplace_back(layer.name);
        }
    }
    return names;
}

/// Every layer name in drawing order, separated by ", " (for the error that names an unknown layer).
inline std::string LayerNameList()
{
    std::string list;
    for (const LayerInfo& layer : kLayerTable)
    {
        list += (list.empty() ? "" : ", ") + std::string(layer.name);
    }
    return list;
}

} // namespace satviz
