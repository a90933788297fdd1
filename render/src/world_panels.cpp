// SPDX-License-Identifier: MIT
#include "world_views.h"

namespace satviz
{

namespace
{

constexpr LayerMask kWorldLayers = kLayerBroadphase | kLayerResponse | kLayerHits | kLayerPlots;

// The panels from top to bottom: counts, response, hits, plots.
void PanelOrder(LayerMask layers, float top, float& counts, float& response, float& hits, float& plots)
{
    float y = top;
    counts = y;
    y += (layers & kLayerBroadphase) ? kCountsPanel : 0.0f;
    response = y;
    y += (layers & kLayerResponse) ? kResponsePanel : 0.0f;
    hits = y;
    y += (layers & kLayerHits) ? kHitsPanel : 0.0f;
    plots = y;
}

} // namespace

float HitsPanelTop(LayerMask layers, float worldTop)
{
    float counts = 0.0f, response = 0.0f, hits = 0.0f, plots = 0.0f;
    PanelOrder(layers & kWorldLayers, worldTop, counts, response, hits, plots);
    return hits;
}

std::vector<HitMark> HitMarks(Canvas& canvas, const Scene& scene, const PairStudy& study, const Figure& figure)
{
    if (figure.sim == nullptr || !(figure.layers & kLayerHits))
    {
        return {};
    }
    const FigureLayout layout =
        LayoutFigure(study, figure.layers, figure.view.width, figure.view.height, !figure.caption.empty());
    return LayOutHitMarks(canvas, scene, *figure.sim, static_cast<float>(figure.view.width),
                          HitsPanelTop(figure.layers, layout.worldTop));
}

float WorldPanelsHeight(LayerMask layers)
{
    return ((layers & kLayerBroadphase) ? kCountsPanel : 0.0f) + ((layers & kLayerResponse) ? kResponsePanel : 0.0f) +
           ((layers & kLayerHits) ? kHitsPanel : 0.0f) + ((layers & kLayerPlots) ? kPlotsPanel : 0.0f);
}

void PaintWorldScene(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene, const Figure& figure,
                     const ScreenRect& bounds)
{
    if (figure.sim == nullptr || (figure.layers & kWorldLayers) == 0)
    {
        return;
    }
    const SimRecord& sim = *figure.sim;
    if (figure.layers & kLayerBroadphase)
    {
        PaintBroadphaseScene(canvas, view, scene, sim, bounds);
    }
    if (figure.layers & kLayerHits)
    {
        PaintHitsScene(canvas, labels, view, scene, sim, figure.hit, bounds);
    }
    if (figure.layers & kLayerResponse)
    {
        PaintResponseScene(canvas, labels, view, scene, sim);
    }
}

void PaintWorldPanels(Canvas& canvas, const Scene& scene, const Figure& figure, float top)
{
    const LayerMask layers = figure.layers & kWorldLayers;
    if (layers == 0)
    {
        return;
    }
    const float width = static_cast<float>(figure.view.width);
    const float height = static_cast<float>(figure.view.height);
    canvas.BeginGroup("world panels");
    canvas.FillRect({0.0f, top}, {width, height}, palette::kPanel);
    canvas.Segment({0.0f, top}, {width, top}, palette::kFaint, 1.0f);
    if (figure.sim == nullptr)
    {
        canvas.Text({12.0f, top + 6.0f}, "The world was not stepped: these layers draw a scene stepped by --sim-steps.",
                    TextStyle::Label, palette::kMuted);
        return;
    }
    float counts = 0.0f, response = 0.0f, hits = 0.0f, plots = 0.0f;
    PanelOrder(layers, top, counts, response, hits, plots);
    const SimRecord& sim = *figure.sim;
    if (layers & kLayerBroadphase)
    {
        PaintCountsPanel(canvas, sim, width, counts);
    }
    if (layers & kLayerResponse)
    {
        canvas.Segment({0.0f, response}, {width, response}, palette::kFaint, 1.0f);
        PaintResponsePanel(canvas, scene, sim, width, response);
    }
    if (layers & kLayerHits)
    {
        canvas.Segment({0.0f, hits}, {width, hits}, palette::kFaint, 1.0f);
        PaintHitsPanel(canvas, scene, sim, figure.hit, width, hits);
    }
    if (layers & kLayerPlots)
    {
        canvas.Segment({0.0f, plots}, {width, plots}, palette::kFaint, 1.0f);
        PaintPlotsPanel(canvas, sim, width, plots);
    }
}

} // namespace satviz
