// SPDX-License-Identifier: MIT
// The decomposition figure: one outline cut into convex pieces by both methods, side by side at one scale.
#include "concave_views.h"

#include <satviz/render/recording_canvas.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace satviz
{

namespace
{

constexpr float kMargin = 28.0f;       // room around the outline inside a panel, for vertex numbers

// Indices of the outline's reflex vertices, taken in counter-clockwise order whatever the outline's own.
std::vector<int> ReflexVertices(const std::vector<Vec2>& outline)
{
    const size_t n = outline.size();
    double area2 = 0.0;
    for (size_t i = 0; i < n; ++i)
    {
        area2 += Cross(outline[i], outline[(i + 1) % n]);
    }
    std::vector<int> reflex;
    for (size_t i = 0; i < n; ++i)
    {
        const Vec2 a = outline[(i + n - 1) % n];
        const Vec2 b = outline[i];
        const Vec2 c = outline[(i + 1) % n];
        const double turn = Cross(b - a, c - b) * (area2 < 0.0 ? -1.0 : 1.0);
        if (turn < 0.0)
        {
            reflex.push_back(static_cast<int>(i));
        }
    }
    return reflex;
}

// The input vertices that are corners of some piece (repeated and straight vertices are dropped before cutting).
int CornerCount(const Decomposition& d)
{
    std::set<int> corners;
    for (const ConvexPiece& piece : d.pieces)
    {
        corners.insert(piece.source.begin(), piece.source.end());
    }
    return static_cast<int>(corners.size());
}

std::string Plural(int count, const char* one, const char* many)
{
    return std::to_string(count) + " " + (count == 1 ? one : many);
}

} // namespace

std::string DescribeDecomposition(const std::vector<Vec2>& outline, const Decomposition& fast,
                                  const Decomposition& fewest)
{
    const int n = static_cast<int>(outline.size());
    const int corners = CornerCount(fast);
    const int reflex = static_cast<int>(ReflexVertices(outline).size());
    const int piecesFast = static_cast<int>(fast.pieces.size());
    const int piecesFewest = static_cast<int>(fewest.pieces.size());
    std::string text =
        "An outline of " + Plural(n, "vertex", "vertices") + ", " + std::to_string(reflex) + " of them reflex (ringed)";
    if (corners < n)
    {
        // Such a vertex is a corner of no piece: the pieces are strictly convex.
        text += "; " + Plural(n - corners, "vertex lies", "vertices lie") +
                (n - corners == 1 ? " on a straight line or repeats, a corner of no piece"
                                  : " on a straight line or repeat, corners of no piece");
    }
    if (reflex == 0)
    {
        return text + ". It is convex: one piece, cut by neither method.";
    }
    const int seams = corners - 3;
    const int kept = piecesFast - 1;
    text +=
        ". A convex piece has no reflex corner, so a seam (dashed) must end at each. Fast clips " +
        Plural(corners - 2, "triangle", "triangles") + " off the outline as ears, joined by " +
        Plural(seams, "seam", "seams") +
        ", then removes in turn each seam whose two ends stay convex without it: " + std::to_string(seams - kept) +
        " go, " + std::to_string(kept) + " stay, " + Plural(piecesFast, "piece", "pieces") +
        ". Fewest: " + Plural(piecesFewest, "piece", "pieces") + ", the fewest with corners at the outline's vertices" +
        (corners > kFewestMaxVertices ? " (above " + std::to_string(kFewestMaxVertices) + " vertices, Fast's pieces)"
                                      : std::string()) +
        ". A seam has two ends, so no decomposition has fewer than " + std::to_string(reflex) +
        "/2 rounded up + 1 = " + std::to_string((reflex + 1) / 2 + 1) + " pieces.";
    return text;
}

namespace
{

// The world box of the outline placed by xf.
void OutlineBox(const std::vector<Vec2>& outline, const Transform& xf, Vec2& low, Vec2& high)
{
    low = {INFINITY, INFINITY};
    high = {-INFINITY, -INFINITY};
    for (const Vec2& v : outline)
    {
        const Vec2 p = TransformPoint(xf, v);
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
}

// The subtitles of the two panels: the method each decomposition uses.
constexpr const char* kMethods[2] = {"ear clipping, then Hertel-Mehlhorn", "exact programme, corners at vertices"};

// The two panels below the caption band whose bottom is `top`, each below its header (`headers`), both below the
// taller: a narrow canvas wraps a subtitle to more lines.
void PanelRects(float top, float width, float height, PanelHeader (&headers)[2], ScreenRect (&rects)[2])
{
    headers[0] = LayOutPanelHeader(kMethods[0], 0.5f * width);
    headers[1] = LayOutPanelHeader(kMethods[1], 0.5f * width);
    const float header = std::max(headers[0].height, headers[1].height);
    rects[0] = {0.0f, top + header, 0.5f * width, height};
    rects[1] = {0.5f * width, top + header, width, height};
}

} // namespace

View FrameDecomposition(const Scene& scene, int bodyIndex, const Figure& figure)
{
    const Body& body = scene.bodies[static_cast<size_t>(bodyIndex)];
    const float width = static_cast<float>(figure.view.width);
    const std::vector<Vec2> outline = BodyOutline(body);
    float top = 0.0f;
    if (figure.layers & kLayerCaption)
    {
        // The band's height, from its wrapped lines, measured as the canvas measures them.
        RecordingCanvas measure;
        top = DrawCaptionBand(measure, figure.caption,
                              DescribeDecomposition(outline, Decompose(outline, DecomposeMethod::Fast),
                                                    Decompose(outline, DecomposeMethod::Fewest)),
                              width);
    }
    PanelHeader headers[2];
    ScreenRect rects[2];
    PanelRects(top, width, static_cast<float>(figure.view.height), headers, rects);
    Vec2 low{};
    Vec2 high{};
    OutlineBox(outline, body.Xf(), low, high);
    const double zoom = std::min(FitZoom(rects[0], low, high, kMargin), FitZoom(rects[1], low, high, kMargin));
    return FramePanel(rects[0], low, high, figure.view.width, figure.view.height, kMargin, zoom).view;
}

void PaintDecomposition(Canvas& surface, const Scene& scene, int bodyIndex, const Figure& figure)
{
    // Every line is drawn through the watch, so that the labels keep off it.
    LabelPlacer labels(surface, figure);
    LineWatch canvas(surface, labels);
    const Body& body = scene.bodies[static_cast<size_t>(bodyIndex)];
    const float width = static_cast<float>(figure.view.width);
    const float height = static_cast<float>(figure.view.height);
    const std::vector<Vec2> outline = BodyOutline(body);
    const Decomposition fast = Decompose(outline, DecomposeMethod::Fast);
    const Decomposition fewest = Decompose(outline, DecomposeMethod::Fewest);
    // Framing itself, the figure shows the outline alone, wherever the body stands; in the app the left panel draws
    // it through the camera, by which the pointer is mapped to the world (FrameDecomposition opens it framed), and
    // the right panel at the same scale half the image to the right.
    const Transform xf = figure.framesItself ? MakeTransform(Vec2{}, body.angle) : body.Xf();

    const float top = DrawBackgroundAndCaption(canvas, labels, figure, DescribeDecomposition(outline, fast, fewest));

    Vec2 low{};
    Vec2 high{};
    OutlineBox(outline, xf, low, high);
    PanelHeader headers[2];
    ScreenRect rects[2];
    PanelRects(top, width, height, headers, rects);
    const double zoom = std::min(FitZoom(rects[0], low, high, kMargin), FitZoom(rects[1], low, high, kMargin));
    const Decomposition* results[2] = {&fast, &fewest};
    const char* names[2] = {"Fast", "Fewest"};
    const std::vector<int> reflex = ReflexVertices(outline);
    const bool numbered = outline.size() <= 24;
    Vec2 middle{};
    for (const Vec2& v : outline)
    {
        middle = middle + (1.0 / static_cast<double>(outline.size())) * v;
    }
    canvas.BeginGroup("divider");
    canvas.Segment({0.5f * width, top}, {0.5f * width, height}, palette::kFaint, 1.0f);
    for (int side = 0; side < 2; ++side)
    {
        Panel panel{rects[side], figure.view};
        if (figure.framesItself)
        {
            panel = FramePanel(rects[side], low, high, figure.view.width, figure.view.height, kMargin, zoom);
        }
        else
        {
            panel.view.center.x -= side * 0.5 * width / figure.view.zoom;
        }
        const Decomposition& d = *results[side];
        canvas.BeginGroup(side == 0 ? "fast" : "fewest");
        const int pieces = static_cast<int>(d.pieces.size());
        const std::string title =
            std::string(names[side]) + ": " + std::to_string(pieces) + (pieces == 1 ? " piece" : " pieces");
        const float x = rects[side].minX + 12.0f;
        DrawPanelHeader(canvas, x, top, title, headers[side]);
        labels.Reserve({x, top + 4.0f, rects[side].maxX, rects[side].minY});
        DrawPieces(canvas, panel.view, d.pieces, xf, rects[side]);
        for (const int i : reflex)
        {
            const ScreenPoint p = ToScreen(panel.view, TransformPoint(xf, outline[static_cast<size_t>(i)]));
            canvas.Circle(p, 5.0f, palette::kResult, 1.5f);
            labels.Reserve({p.x - 6.0f, p.y - 6.0f, p.x + 6.0f, p.y + 6.0f});
        }
        for (int i = 0; i < pieces; ++i)
        {
            const Polygon& polygon = d.pieces[static_cast<size_t>(i)].polygon;
            Vec2 centre{};
            for (const Vec2& v : polygon.Vertices())
            {
                centre = centre + (1.0 / polygon.Count()) * v;
            }
            labels.Place(ToScreen(panel.view, TransformPoint(xf, centre)), std::to_string(i + 1), TextStyle::Heading,
                         palette::kInk, 0.0f, 0.0f, 0.0f, LabelRank::Name);
        }
        if (numbered && (figure.layers & kLayerLabels))
        {
            for (size_t i = 0; i < outline.size(); ++i)
            {
                const Vec2 out = outline[i] - middle;
                const Vec2 d2 = Rotate(xf.q, out);
                labels.Place(ToScreen(panel.view, TransformPoint(xf, outline[i])), std::to_string(i), TextStyle::Label,
                             palette::kMuted, static_cast<float>(d2.x), static_cast<float>(-d2.y), 8.0f,
                             LabelRank::Vertex);
            }
        }
    }
    labels.Flush(palette::kBackground);
}

} // namespace satviz
