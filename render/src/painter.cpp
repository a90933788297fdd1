// SPDX-License-Identifier: MIT
#include "concave_views.h"
#include "draw_kit.h"
#include "label_placer.h"
#include "legend.h"
#include "voronoi_view.h"
#include "world_views.h"

#include <satviz/collide.h>
#include <satviz/render/describe.h>
#include <satviz/render/painter.h>
#include <satviz/render/response_steps.h>
#include <satviz/render/wrap.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

namespace satviz
{

namespace
{

constexpr float kCaptionLines = 3.0f;      // caption lines the band holds (longer captions take a smaller size)
constexpr int kSmallFigure = 560;          // figures narrower than this reserve label-size caption lines
constexpr int kSmallPanelHeight = 400;     // figures lower than this show no number-line panel
constexpr float kLineHeight = 19.0f;       // caption line spacing
constexpr float kLabelLineHeight = 16.0f;  // caption line spacing at label size (small figures)
constexpr float kPad = 12.0f;              // padding inside bands
constexpr float kStaticPanel = 108.0f;     // number-line panel height, static test
constexpr float kSweepPanel = 184.0f;      // number line and time bar, swept test
constexpr float kAxisGap = 30.0f;          // pixels between the pair's disc and the axis line
constexpr size_t kMinkowskiPoints = 65536; // largest n * m the Minkowski inset draws
constexpr int kFitAxes = 128;              // at most about this many axis lines are framed by FitFigure
constexpr float kFitMargin = 22.0f;        // pixels between the axis line and the scene area's edge
constexpr float kFitSide = 36.0f;          // at the left and right edges: room for a corner's number and edge name
constexpr float kOutline = 2.0f;           // shape outline thickness
constexpr float kClearOfDot = 12.0f;       // a face's name led from this far off a contact's dot
constexpr float kBar = kIntervalBar;       // interval bar thickness, as the key draws it
constexpr float kLinePad = 26.0f;          // the axis line runs this far beyond the intervals

bool Has(const Figure& figure, LayerMask layer)
{
    return (figure.layers & layer) != 0;
}

Vec2 Along(Vec2 base, Vec2 direction, double u)
{
    return base + u * direction;
}

// Points that bound the pair, each with a radius around it: polygon vertices and circles, at t = 0 and, for
// sweeps, at t = 1.
std::vector<std::pair<Vec2, double>> PairPoints(const Scene& scene, const PairStudy& study)
{
    std::vector<std::pair<Vec2, double>> points;
    const int ids[2] = {study.bodyA, study.bodyB};
    for (int id : ids)
    {
        const Body& body = scene.bodies[static_cast<size_t>(id)];
        const int times = study.sweep && body.velocity != Vec2{} ? 2 : 1;
        for (int k = 0; k < times; ++k)
        {
            const Transform xf = BodyTransformAt(body, k);
            if (body.shape.type == ShapeType::Polygon)
            {
                for (const Vec2& v : body.shape.polygon.Vertices())
                {
                    points.push_back({TransformPoint(xf, v), 0.0});
                }
            }
            else
            {
                points.push_back({TransformPoint(xf, body.shape.circle.center), body.shape.circle.radius});
            }
        }
    }
    return points;
}

// The disc around the pair's bounding box.
void PairDisc(const std::vector<std::pair<Vec2, double>>& points, Vec2& center, double& radius)
{
    Vec2 low = points.front().first;
    Vec2 high = low;
    for (const auto& [p, r] : points)
    {
        low = {std::min(low.x, p.x - r), std::min(low.y, p.y - r)};
        high = {std::max(high.x, p.x + r), std::max(high.y, p.y + r)};
    }
    center = 0.5 * (low + high);
    radius = 0.0;
    for (const auto& [p, r] : points)
    {
        radius = std::max(radius, Length(p - center) + r);
    }
    radius = std::max(radius, 1e-9);
}

// The side of the pair the axis line goes: below it, or left of it for a vertical axis.
Vec2 AxisSide(Vec2 d)
{
    Vec2 n = LeftPerp(d);
    if (n.y > 0.0 || (n.y == 0.0 && n.x > 0.0))
    {
        n = -n;
    }
    return n;
}

// The axis line beside the pair: the points base + u d, u a projection value on d, run parallel to the axis at
// `gap` (world units) beyond the pair on the AxisSide.
Vec2 AxisLineBase(const std::vector<std::pair<Vec2, double>>& points, Vec2 d, double gap)
{
    const Vec2 n = AxisSide(d);
    double offset = -INFINITY;
    for (const auto& [p, r] : points)
    {
        offset = std::max(offset, Dot(p, n) + r);
    }
    return (offset + gap) * n;
}

// The span of projection values the axis line shows: both intervals, and B's swept interval.
void AxisLineSpan(double minA, double maxA, double minB, double maxB, double& lo, double& hi)
{
    lo = std::min(minA, minB);
    hi = std::max(maxA, maxB);
}

Vec2 ShapeCenter(const Shape& shape, const Transform& xf)
{
    return TransformPoint(xf, shape.type == ShapeType::Polygon ? shape.polygon.Centroid() : shape.circle.center);
}

// Lowest and highest projection of a placed shape on a unit direction, with the points that reach them.
void Extremes(const Shape& shape, const Transform& xf, Vec2 d, Vec2& low, Vec2& high)
{
    if (shape.type == ShapeType::Circle)
    {
        const Vec2 c = TransformPoint(xf, shape.circle.center);
        low = c - shape.circle.radius * d;
        high = c + shape.circle.radius * d;
        return;
    }
    double lo = INFINITY;
    double hi = -INFINITY;
    for (const Vec2& v : shape.polygon.Vertices())
    {
        const Vec2 p = TransformPoint(xf, v);
        const double s = Dot(p, d);
        if (s < lo)
        {
            lo = s;
            low = p;
        }
        if (s > hi)
        {
            hi = s;
            high = p;
        }
    }
}

// One axis as the painter shows it, whichever test produced it.
struct ShownAxis
{
    AxisRef faces[kMaxFacesPerAxis]{}; // the faces (or vertex, or centres) on the axis; faces[0] gave its direction
    int faceCount = 0;
    Vec2 direction{};
    double minA = 0.0, maxA = 0.0, minB = 0.0, maxB = 0.0;
    double separation = 0.0;
    bool textbook = false; // an axis of the textbook test: a two-sided interval comparison, not a face test
    bool swept = false;
    double sweptMinB = 0.0, sweptMaxB = 0.0;
    double entry = 0.0, exit = 0.0;
    bool never = false;                         // the intervals never overlap (textbook sweeps)
    double windowEntry = 0.0, windowExit = 0.0; // latest entry and earliest exit so far
    bool separating = false;
    bool skipped = false;
    // A face the sweep decided without evaluating it (not walked to, or ruled out by bisection): drawn faintly, its
    // numbers computed for the view only. `boundAt`: with `bounded`, where on the axis the vertex that bounds the
    // gap lies (the other shape's near end is no farther out).
    bool decided = false;
    bool bounded = false;
    double boundAt = 0.0;
    int index = 0;
    // The band between the bars runs from leadMax to otherMin, separation = otherMin - leadMax: a gap when
    // positive, else an overlap of -separation. A face test measures it from the face's shape (the shape whose
    // axis it is, or A) to the other shape's trailing end, which can exceed the intervals' intersection when the
    // other shape lies behind; the textbook test takes the shorter of the two ways.
    double leadMax = 0.0;
    double otherMin = 0.0;
    const AxisRef& Ref() const { return faces[0]; }
    void SetLead(bool fromB)
    {
        leadMax = fromB ? maxB : maxA;
        otherMin = fromB ? minA : minB;
    }
    void SetSource(const AxisRef& ref)
    {
        faces[0] = ref;
        faceCount = 1;
    }
};

// Every kind of axis record (the face tests', the sweep's, the textbook test's) carries the axis and both shapes'
// intervals on it under the same names.
template <typename Axis>
void CopyIntervals(const Axis& t, ShownAxis& s)
{
    s.direction = t.direction;
    s.minA = t.minA;
    s.maxA = t.maxA;
    s.minB = t.minB;
    s.maxB = t.maxB;
}

// A textbook axis: the faces it stands for and its intervals.
template <typename Axis>
void CopyTextbookAxis(const Axis& t, ShownAxis& s)
{
    std::copy(t.faces, t.faces + kMaxFacesPerAxis, s.faces);
    s.faceCount = t.faceCount;
    CopyIntervals(t, s);
    s.textbook = true;
}

// The window in which every interval overlaps, as the sweep knew it at this axis: from the latest entry to the
// earliest exit so far, or the axis's own while the first of them is not known.
template <typename Axis>
void SetWindow(const std::vector<Axis>& axes, const Axis& t, ShownAxis& s)
{
    if (t.latestEntry >= 0 && t.earliestExit >= 0)
    {
        s.windowEntry = axes[static_cast<size_t>(t.latestEntry)].entry;
        s.windowExit = axes[static_cast<size_t>(t.earliestExit)].exit;
    }
    else
    {
        s.windowEntry = t.entry;
        s.windowExit = t.exit;
    }
}

ShownAxis FromStatic(const PairStudy& study, int index)
{
    const AxisTest& t = study.trace.axes[static_cast<size_t>(index)];
    ShownAxis s;
    s.SetSource(t.axis);
    CopyIntervals(t, s);
    s.separation = t.separation;
    s.separating = t.separating;
    s.skipped = t.skipped;
    s.index = index;
    s.SetLead(MeasuredFromB(t.axis));
    return s;
}

ShownAxis FromTextbook(const PairStudy& study, int index)
{
    const TextbookAxis& t = study.textbook.axes[static_cast<size_t>(index)];
    ShownAxis s;
    CopyTextbookAxis(t, s);
    s.separation = t.separating ? t.gap : -t.overlap;
    s.separating = t.separating;
    s.index = index;
    // The gap lies on the side where B's interval is beyond A's; the overlap on the side of the shorter push.
    const bool bAhead = t.separating ? t.minB - t.maxA > 0.0 : t.pushSign > 0;
    s.SetLead(!bAhead);
    return s;
}

ShownAxis FromSweep(const PairStudy& study, int index)
{
    const SweepAxis& t = study.sweepTrace.axes[static_cast<size_t>(index)];
    ShownAxis s;
    s.SetSource(t.axis);
    CopyIntervals(t, s);
    s.separation = t.separation;
    s.swept = true;
    s.sweptMinB = t.sweptMinB;
    s.sweptMaxB = t.sweptMaxB;
    s.entry = t.entry;
    s.exit = t.exit;
    s.separating = t.endsTest;
    s.decided = t.bounded || t.skipped;
    s.bounded = t.bounded;
    // On the axis from A towards B: a vertex of B lies `bound` beyond A's face (at maxA), a vertex of A `bound`
    // beyond B's face (at minB, beyond it being towards A).
    s.boundAt = t.axis.shape == 0 ? t.maxA + t.bound : t.minB - t.bound;
    s.index = index;
    s.SetLead(false);
    // A face the other shape is beyond (or on) and does not approach never closes: it has no entry or exit time
    // (the trace's 0 and infinity are placeholders), and when it ends the test there is no common window.
    if (t.axis.kind == AxisKind::FaceNormal && !s.decided && t.separation >= 0.0 && t.rate >= 0.0)
    {
        s.never = true;
        s.entry = std::numeric_limits<double>::quiet_NaN();
        s.exit = s.entry;
        if (t.endsTest)
        {
            s.windowEntry = s.entry;
            s.windowExit = s.entry;
            return s;
        }
    }
    SetWindow(study.sweepTrace.axes, t, s);
    return s;
}

ShownAxis FromTextbookSweep(const PairStudy& study, int index)
{
    const TextbookSweepAxis& t = study.textbookSweep.axes[static_cast<size_t>(index)];
    ShownAxis s;
    CopyTextbookAxis(t, s);
    const double along = t.minB - t.maxA;
    const double against = t.minA - t.maxB;
    if (along > 0.0 || against > 0.0)
    {
        s.separation = std::max(along, against);
        s.SetLead(!(along > 0.0));
    }
    else
    {
        s.separation = -std::min(-along, -against);
        s.SetLead(!(-along <= -against));
    }
    s.swept = true;
    s.sweptMinB = std::min(t.minB, t.minB + t.rate);
    s.sweptMaxB = std::max(t.maxB, t.maxB + t.rate);
    s.entry = t.entry;
    s.exit = t.exit;
    s.never = t.never;
    s.separating = t.endsTest;
    s.index = index;
    SetWindow(study.textbookSweep.axes, t, s);
    return s;
}

ShownAxis ShowAxis(const PairStudy& study, int index)
{
    if (study.Textbook())
    {
        return study.sweep ? FromTextbookSweep(study, index) : FromTextbook(study, index);
    }
    return study.sweep ? FromSweep(study, index) : FromStatic(study, index);
}

// The label of the band between the bars: a two-sided overlap or gap, or how far the other shape lies behind or
// beyond a face.
// The amount is computed from the interval ends as the figure prints them, so that it agrees with them and with the
// caption.
std::string BandLabel(const ShownAxis& axis)
{
    const bool gap = axis.separation > 0.0;
    const std::string amount = ShownBand(axis.leadMax, axis.otherMin, axis.separation);
    if (axis.textbook)
    {
        return (gap ? "gap " : "overlap ") + amount;
    }
    return amount + (gap ? " beyond" : " behind");
}

// The axis the verdict step shows: the separating axis, the axis of the smallest push, or the latest entry.
int DecidingAxis(const PairStudy& study)
{
    if (study.AxisCount() == 0)
    {
        return -1;
    }
    if (study.Textbook())
    {
        const int last = study.AxisCount() - 1;
        if (study.sweep)
        {
            const TextbookSweepResult& r = study.textbookSweepResult;
            return r.status == SweepStatus::Hit && r.axis >= 0 ? r.axis : last;
        }
        return study.textbookResult.axis >= 0 ? study.textbookResult.axis : last;
    }
    if (study.sweep)
    {
        const SweepAxis& last = study.sweepTrace.axes.back();
        if (study.sweepResult.status == SweepStatus::Hit && last.latestEntry >= 0)
        {
            return last.latestEntry;
        }
        // A polygon pair's miss: the axis that ended the test, which faces evaluated with it or decided without
        // evaluation may follow (against a polygon above 16 vertices).
        for (int k = study.AxisCount() - 1;
             k >= 0 && !last.endsTest && study.sweepTrace.exit != SweepExit::RoundedOutline; --k)
        {
            if (study.sweepTrace.axes[static_cast<size_t>(k)].endsTest)
            {
                return k;
            }
        }
        return study.AxisCount() - 1;
    }
    const AxisTest& last = study.trace.axes.back();
    return last.separating || last.best < 0 ? study.AxisCount() - 1 : last.best;
}

// The verdict of a sweep shows the common window of all axes: the latest entry and the earliest exit as the last
// step holds them. The deciding axis's own step holds them only so far, and a later axis can exit earlier (a
// circle's verdict shows the face it reaches first, not the last one tested).
void SetWholeWindow(const PairStudy& study, ShownAxis& shown)
{
    if (!study.sweep || study.AxisCount() == 0)
    {
        return;
    }
    if (study.Textbook())
    {
        const std::vector<TextbookSweepAxis>& axes = study.textbookSweep.axes;
        const TextbookSweepAxis& last = axes.back();
        if (study.textbookSweepResult.status == SweepStatus::Hit && last.latestEntry >= 0 && last.earliestExit >= 0)
        {
            shown.windowEntry = axes[static_cast<size_t>(last.latestEntry)].entry;
            shown.windowExit = axes[static_cast<size_t>(last.earliestExit)].exit;
        }
        return;
    }
    const std::vector<SweepAxis>& axes = study.sweepTrace.axes;
    const SweepAxis& last = axes.back();
    if (study.sweepResult.status == SweepStatus::Hit && last.latestEntry >= 0 && last.earliestExit >= 0)
    {
        shown.windowEntry = axes[static_cast<size_t>(last.latestEntry)].entry;
        shown.windowExit = axes[static_cast<size_t>(last.earliestExit)].exit;
    }
}

class Painter
{
  public:
    /// `keyAt`, when given, is where the key goes (PlaceKey's corner for a figure that frames itself).
    Painter(Canvas& canvas, const Scene& scene, const PairStudy& study, const Figure& figure,
            const ScreenPoint* keyAt = nullptr)
        : m_labels(canvas, figure), m_watch(canvas, m_labels), m_canvas(m_watch), m_scene(scene), m_study(study),
          m_figure(figure), m_keyAt(keyAt), m_view(figure.view),
          m_layout(LayoutFigure(study, figure.layers, figure.view.width, figure.view.height, !figure.caption.empty())),
          m_bodyA(scene.bodies[static_cast<size_t>(study.bodyA)]), m_bodyB(scene.bodies[static_cast<size_t>(study.bodyB)])
    {
        m_bounds = {-4.0f, -4.0f, static_cast<float>(m_view.width) + 4.0f, static_cast<float>(m_view.height) + 4.0f};
        m_points = PairPoints(scene, study);
        PairDisc(m_points, m_discCenter, m_discRadius);
        m_verdict = figure.step == study.VerdictStep();
        m_axisIndex = m_verdict ? DecidingAxis(study) : figure.step;
        if (m_axisIndex >= 0 && m_axisIndex < study.AxisCount())
        {
            m_axis = ShowAxis(study, m_axisIndex);
            m_hasAxis = true;
            if (m_verdict)
            {
                SetWholeWindow(study, m_axis);
            }
        }
    }

    void Paint()
    {
        m_canvas.BeginGroup("background");
        m_canvas.FillRect({0.0f, 0.0f}, {static_cast<float>(m_view.width), static_cast<float>(m_view.height)},
                         palette::kBackground);
        if ((m_figure.layers & ~kLayerCaption) == kLayerLegend)
        {
            // The legend alone: the key to every mark, in the middle of the scene area.
            const std::vector<LegendMark> marks = AllLegendMarks();
            const ScreenPoint size = LegendSize(m_canvas, marks, KeyRoom());
            const float middle = 0.5f * (m_layout.sceneTop + m_layout.sceneBottom);
            float top = std::round(middle - 0.5f * size.y);
            const float least = m_layout.sceneBottom - 8.0f - size.y;
            const float most = m_layout.sceneTop + 8.0f;
            if (least < most)
            {
                // Taller than the canvas (a short window beside the lesson column): it starts at its top and
                // scrolls with the camera, as the pair it has in place of a picture would move, so that dragging
                // the canvas up brings its last rows into sight.
                const float scroll = At(m_discCenter).y - 0.5f * static_cast<float>(m_view.height);
                top = std::round(std::clamp(most + scroll, least, most));
            }
            PaintLegend(m_canvas, {std::round(0.5f * (Width() - size.x)), top}, marks, KeyRoom());
            if (least < most)
            {
                m_canvas.BeginGroup("legend hint");
                const bool below = top > least + 0.5f;
                const std::string hint = below ? "drag the canvas up for the rest of the key"
                                               : "drag the canvas down for the start of the key";
                const ScreenPoint hintSize = m_canvas.MeasureText(hint, TextStyle::Label);
                const float y = below ? m_layout.sceneBottom - hintSize.y - 6.0f : m_layout.sceneTop + 4.0f;
                const float x = std::round(0.5f * (Width() - hintSize.x));
                m_canvas.FillRect({0.0f, y - 4.0f}, {Width(), y + hintSize.y + 4.0f}, palette::kBackground);
                m_canvas.Segment({0.0f, below ? y - 4.0f : y + hintSize.y + 4.0f},
                                 {Width(), below ? y - 4.0f : y + hintSize.y + 4.0f}, palette::kFaint, 1.0f);
                m_canvas.Text({x, y}, hint, TextStyle::Label, palette::kInk);
            }
            if (Has(m_figure, kLayerCaption))
            {
                m_caption = LayOutCaption();
                Caption();
            }
            return;
        }
        Grid();
        ReserveBands();
        if (Has(m_figure, kLayerVoronoi))
        {
            PaintVoronoiRegions(m_canvas, m_view, m_scene, m_study);
        }
        if (Has(m_figure, kLayerAxes))
        {
            CandidateAxes();
        }
        if (Has(m_figure, kLayerShapes))
        {
            Shapes();
        }
        if (Has(m_figure, kLayerNormals))
        {
            Normals();
        }
        PaintWorldScene(m_canvas, m_labels, m_view, m_scene, m_figure, m_bounds);
        // The shapes at the time of impact under the velocity arrows, whose heads their outlines would cut.
        if (Has(m_figure, kLayerGhost) && m_study.sweep)
        {
            Ghosts();
        }
        if (Has(m_figure, kLayerSwept) && m_study.sweep)
        {
            Motion();
        }
        else if (Has(m_figure, kLayerSwept))
        {
            Velocities();
        }
        if (m_hasAxis && Has(m_figure, kLayerProjection) && !m_axis.skipped)
        {
            AxisInScene();
        }
        else if (m_hasAxis && Has(m_figure, kLayerProjection))
        {
            // A face skipped as anti-parallel to one already tested: its caption names it, so it is marked faintly,
            // without an axis line (its axis was tested with the other face).
            m_canvas.BeginGroup("projection");
            AxisSource(m_axis.Ref(), WithAlpha(palette::kInk, 0.4f));
        }
        // The face the axis comes from, over the axis line's bars and projectors, which would hide its normal's
        // head; a vertex's dot and line last, over the best axis's edge ending at that vertex, the separating line
        // through the narrow gap beside it and the body moved out by the MTV.
        const auto axisSource = [&](bool faces) {
            if (m_hasAxis && Has(m_figure, kLayerProjection) && !m_axis.skipped)
            {
                m_canvas.BeginGroup("projection");
                const Color ink = WithAlpha(palette::kInk, m_axis.decided ? 0.4f : 1.0f);
                for (int f = 0; f < m_axis.faceCount; ++f)
                {
                    if ((m_axis.faces[f].kind == AxisKind::FaceNormal) == faces)
                    {
                        AxisSource(m_axis.faces[f], ink);
                    }
                }
            }
        };
        axisSource(true);
        // After the projection, whose bars would hide the best axis's arrow heads where they cross.
        if (m_hasAxis && Has(m_figure, kLayerBest))
        {
            BestSoFar();
        }
        if (m_hasAxis && Has(m_figure, kLayerExit) && m_axis.separating && !m_axis.swept)
        {
            SeparatingLine();
        }
        if (m_verdict && Has(m_figure, kLayerMtv))
        {
            Mtv();
        }
        axisSource(false);
        if (m_verdict && Has(m_figure, kLayerContacts))
        {
            Contacts();
        }
        if (Has(m_figure, kLayerVoronoi))
        {
            MarkVoronoiRegions(m_canvas, m_labels, m_view, m_scene, m_study);
        }
        if (Has(m_figure, kLayerLabels))
        {
            Labels();
        }
        std::vector<LegendMark> legend;
        ScreenPoint legendAt{};
        if (Has(m_figure, kLayerLegend))
        {
            legend = UsedMarks();
            const ScreenPoint size = LegendSize(m_canvas, legend, KeyRoom());
            legendAt = m_keyAt != nullptr ? *m_keyAt : LegendCorner(size);
            m_labels.ReserveBand({legendAt.x, legendAt.y, legendAt.x + size.x, legendAt.y + size.y});
        }
        if (Has(m_figure, kLayerShapes))
        {
            // A label astride a body's outline hides it under its halo (a small ball's name over the ball) and
            // reads as either body's: labels keep off both outlines.
            for (int s = 0; s < 2; ++s)
            {
                const std::vector<ScreenPoint> outline = OutlineOf(s);
                for (size_t i = 0; i < outline.size(); ++i)
                {
                    m_labels.ReserveEdge(outline[i], outline[(i + 1) % outline.size()]);
                }
            }
        }
        m_labels.Flush(WithAlpha(palette::kBackground, 0.72f));
        if (m_hasMtvArrow || m_hasPitfallArrow)
        {
            MtvArrow();
        }
        if (Has(m_figure, kLayerMinkowski))
        {
            Minkowski();
        }
        PaintLegend(m_canvas, legendAt, legend, KeyRoom());
        if (m_layout.panelTop < m_layout.worldTop)
        {
            Panel();
        }
        PaintWorldPanels(m_canvas, m_scene, m_figure, m_layout.worldTop);
        if (Has(m_figure, kLayerCaption))
        {
            Caption();
        }
    }

  private:
    ScreenPoint At(Vec2 world) const { return ToScreen(m_view, world); }
    float Width() const { return static_cast<float>(m_view.width); }
    float Height() const { return static_cast<float>(m_view.height); }
    Color ColorOf(int shape) const { return shape == 0 ? palette::kShapeA : palette::kShapeB; }
    Color InkOf(int shape) const { return shape == 0 ? palette::kShapeA : palette::kShapeBInk; }
    const Body& BodyOf(int shape) const { return shape == 0 ? m_bodyA : m_bodyB; }
    // A body of the pair's outline on screen, where it stands in the figure.
    // What a face's name must sit clearly nearer its face than: the other body of the pair, and every ghost drawn.
    std::vector<std::vector<ScreenPoint>> Rivals(const std::vector<ScreenPoint>& other) const
    {
        std::vector<std::vector<ScreenPoint>> rivals = m_ghostOutlines;
        rivals.push_back(other);
        return rivals;
    }

    std::vector<ScreenPoint> OutlineOf(int shape) const
    {
        const Body& body = BodyOf(shape);
        return ShapeOutline(m_view, body.shape, body.Xf());
    }

    // Faint world grid at a round spacing of at least 40 pixels, with the world axes a little stronger.
    // The grid's spacing in world units: the first round step (1, 2 or 5 times a power of ten) of 40 pixels or more.
    double GridSpacing() const
    {
        const double target = 40.0 / m_view.zoom;
        const double decade = std::pow(10.0, std::floor(std::log10(target)));
        double spacing = decade;
        for (double factor : {1.0, 2.0, 5.0, 10.0})
        {
            spacing = factor * decade;
            if (spacing >= target)
            {
                break;
            }
        }
        return spacing;
    }

    void Grid()
    {
        const double spacing = GridSpacing();
        const Vec2 low = ToWorld(m_view, {0.0f, Height()});
        const Vec2 high = ToWorld(m_view, {Width(), 0.0f});
        const Color grid = WithAlpha(palette::kFaint, 0.45f);
        for (double x = std::ceil(low.x / spacing) * spacing; x <= high.x; x += spacing)
        {
            const float sx = At({x, 0.0}).x;
            m_canvas.Segment({sx, 0.0f}, {sx, Height()}, x == 0.0 ? palette::kFaint : grid, 1.0f);
        }
        for (double y = std::ceil(low.y / spacing) * spacing; y <= high.y; y += spacing)
        {
            const float sy = At({0.0, y}).y;
            m_canvas.Segment({0.0f, sy}, {Width(), sy}, y == 0.0 ? palette::kFaint : grid, 1.0f);
        }
    }

    // Where the Minkowski inset goes: the scene's top right corner.
    ScreenRect InsetBox() const
    {
        const float side = std::min(220.0f, 0.42f * std::min(Width(), m_layout.sceneBottom - m_layout.sceneTop));
        const float right = Width() - 10.0f;
        const float top = m_layout.sceneTop + 10.0f;
        return {right - side, top, right, top + side};
    }

    // The marks this figure draws, in the key's order, for the legend.
    std::vector<LegendMark> UsedMarks() const
    {
        std::vector<LegendMark> used = m_used;
        if (Has(m_figure, kLayerAxes))
        {
            used.push_back(LegendMark::CandidateAxis);
        }
        if (Has(m_figure, kLayerShapes) && m_scene.bodies.size() > 2)
        {
            used.push_back(LegendMark::Other);
        }
        if (m_hasAxis && Has(m_figure, kLayerProjection) && !m_axis.skipped)
        {
            used.push_back(LegendMark::AxisArrow);
            used.push_back(LegendMark::Projection);
            for (int f = 0; f < m_axis.faceCount; ++f)
            {
                if (m_axis.faces[f].kind == AxisKind::FaceNormal)
                {
                    used.push_back(LegendMark::AxisFace);
                }
            }
            used.push_back(!m_axis.textbook ? LegendMark::Behind
                                           : (m_axis.separation > 0.0 ? LegendMark::Gap : LegendMark::Overlap));
            if (m_axis.swept)
            {
                used.push_back(LegendMark::Swept);
            }
        }
        if (m_hasAxis && m_axis.swept && m_layout.panelTop < Height())
        {
            used.push_back(LegendMark::TimeMarks);
            const SweepStatus status =
                m_study.Textbook() ? m_study.textbookSweepResult.status : m_study.sweepResult.status;
            if (m_verdict && status == SweepStatus::Hit)
            {
                used.push_back(LegendMark::Impact);
            }
            if (CommonWindow() == WindowShown::Open)
            {
                used.push_back(LegendMark::Window);
            }
            else if (CommonWindow() == WindowShown::Never)
            {
                used.push_back(LegendMark::NoWindow);
            }
        }
        if (m_hasMtvArrow)
        {
            used.push_back(LegendMark::Mtv);
        }
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        return used;
    }

    // The corner of the scene area where the legend hides least of the pair (never the Minkowski inset's), kept
    // free of labels.
    // The widest the key may be: the figure's width within its margins, its lines wrapped to fit a narrow canvas.
    float KeyRoom() const
    {
        return std::max(Width() - 16.0f, 120.0f);
    }

    ScreenPoint LegendCorner(ScreenPoint size)
    {
        ScreenRect pair{INFINITY, INFINITY, -INFINITY, -INFINITY};
        for (const auto& [p, r] : m_points)
        {
            const ScreenPoint q = At(p);
            const float pr = ToPixels(m_view, r);
            pair = {std::min(pair.minX, q.x - pr), std::min(pair.minY, q.y - pr), std::max(pair.maxX, q.x + pr),
                    std::max(pair.maxY, q.y + pr)};
        }
        // The axis line beside the pair and its bars.
        ScreenRect line{INFINITY, INFINITY, -INFINITY, -INFINITY};
        if (m_hasAxis && Has(m_figure, kLayerProjection) && !m_axis.skipped)
        {
            const Vec2 d = m_axis.direction;
            double lo = std::min(m_axis.minA, m_axis.minB) - kLinePad / m_view.zoom;
            double hi = std::max(m_axis.maxA, m_axis.maxB) + kLinePad / m_view.zoom;
            if (m_axis.swept)
            {
                lo = std::min(lo, m_axis.sweptMinB);
                hi = std::max(hi, m_axis.sweptMaxB);
            }
            const Vec2 base = AxisBaseInSight(d, lo, hi);
            for (const double u : {lo, hi})
            {
                const ScreenPoint q = At(Along(base, d, u));
                line = {std::min(line.minX, q.x - 12.0f), std::min(line.minY, q.y - 12.0f),
                        std::max(line.maxX, q.x + 12.0f), std::max(line.maxY, q.y + 12.0f)};
            }
        }
        const auto covered = [&](ScreenPoint c, const ScreenRect& r) {
            const float w = std::max(0.0f, std::min(c.x + size.x, r.maxX) - std::max(c.x, r.minX));
            const float h = std::max(0.0f, std::min(c.y + size.y, r.maxY) - std::max(c.y, r.minY));
            return w * h;
        };
        const float m = 8.0f;
        const ScreenPoint corners[4] = {{m, m_layout.sceneBottom - m - size.y},
                                        {Width() - m - size.x, m_layout.sceneBottom - m - size.y},
                                        {m, m_layout.sceneTop + m},
                                        {Width() - m - size.x, m_layout.sceneTop + m}};
        ScreenPoint best = corners[0];
        float least = INFINITY;
        for (int k = 0; k < 4; ++k)
        {
            if (k == 3 && Has(m_figure, kLayerMinkowski))
            {
                continue;
            }
            const float area = covered(corners[k], pair) + covered(corners[k], line);
            if (area < least)
            {
                least = area;
                best = corners[k];
            }
        }
        return {std::round(best.x), std::round(best.y)};
    }

    // An arrow whose head and shaft no label may cover.
    void MarkedArrow(ScreenPoint a, ScreenPoint b, Color color, float thickness, float head)
    {
        const ScreenRect tip = Arrow(m_canvas, a, b, color, thickness, head);
        m_labels.Reserve(tip);
        m_labels.ReserveShaft(a, b, thickness + 2.0f);
        m_heads.push_back(tip);
    }

    // Whether the segment ab runs over an arrow head drawn so far.
    bool CrossesHead(ScreenPoint a, ScreenPoint b, float thickness) const
    {
        return std::any_of(m_heads.begin(), m_heads.end(), [&](const ScreenRect& head) {
            ScreenPoint p = a;
            ScreenPoint q = b;
            const float r = 0.5f * thickness + 1.0f;
            return ClipSegment(p, q, {head.minX - r, head.minY - r, head.maxX + r, head.maxY + r});
        });
    }

    static ScreenRect Disc(ScreenPoint center, float radius)
    {
        return {center.x - radius, center.y - radius, center.x + radius, center.y + radius};
    }

    // The part of the image where the scene shows: below the caption band and above the number line.
    ScreenRect SceneInSight() const
    {
        const float top = Has(m_figure, kLayerCaption) ? m_caption.bottom + 1.0f : 0.0f;
        return {0.0f, top, Width(), std::min(Height(), m_layout.panelTop)};
    }

    // True when no point of `body`'s outline, where it is now, lies in the scene in sight.
    bool OutOfSight(const Body& body) const
    {
        const std::vector<ScreenPoint> now = ShapeOutline(m_view, body.shape, body.Xf());
        const ScreenRect sight = SceneInSight();
        return std::none_of(now.begin(), now.end(), [&](const ScreenPoint& p) {
            return p.x >= sight.minX && p.x <= sight.maxX && p.y >= sight.minY && p.y <= sight.maxY;
        });
    }

    // A body out of the picture (l14_head_on's B after the hit) has no velocity arrow in sight: its speed is written
    // where the picture's edge is nearest it, named after it. A bare "v = 3.80 m/s" at the edge, beside the other
    // body's arrow, read as that body's speed.
    void SpeedAtEdge(int s)
    {
        const Body& body = BodyOf(s);
        const ScreenPoint from = At(ShapeCenter(body.shape, body.Xf()));
        const ScreenRect sight = SceneInSight();
        const ScreenPoint edge{std::clamp(from.x, sight.minX + 16.0f, sight.maxX - 16.0f),
                               std::clamp(from.y, sight.minY + 16.0f, sight.maxY - 16.0f)};
        m_labels.Place(edge,
                       body.name + ": v = " + FormatLabelNumber(Length(body.velocity)) +
                           (m_scene.hasWorld ? " m/s" : " per step"),
                       TextStyle::Label, InkOf(s), edge.x - from.x, edge.y - from.y, 6.0f, LabelRank::Note);
    }

    // A dashed outline (where the MTV or a pitfall's push leaves a body) reads as broken, and a label on it hides
    // it: a body's name, a note or a verdict's label keeps off it. A vertex number or an edge name may sit on
    // it rather than be left out, as the outline lies close beside the body's own.
    void ReserveOutline(const std::vector<ScreenPoint>& outline, float thickness)
    {
        // A polygon's corners (not a round outline's many points): a number beside one reads as that corner's.
        for (size_t i = 0; i < outline.size() && outline.size() <= 24; ++i)
        {
            m_labels.AddMark(MarkKind::Corner, outline[i]);
        }
        for (size_t i = 0; i < outline.size(); ++i)
        {
            m_labels.ReserveLine(outline[i], outline[(i + 1) % outline.size()], thickness, LabelRank::Named);
        }
    }

    void ReserveBands()
    {
        if (Has(m_figure, kLayerMinkowski))
        {
            m_labels.ReserveBand(InsetBox());
        }
        if (Has(m_figure, kLayerCaption))
        {
            m_caption = LayOutCaption();
            m_labels.ReserveBand({0.0f, 0.0f, Width(), m_caption.bottom + 1.0f});
        }
        if (m_layout.panelTop < Height())
        {
            m_labels.ReserveBand({0.0f, m_layout.panelTop, Width(), Height()});
        }
    }

    // Every axis the full test could try: the face normals of both polygons (and the circle axes recorded).
    void CandidateAxes()
    {
        m_canvas.BeginGroup("axes");
        const double reach = m_discRadius + kAxisGap / m_view.zoom;
        // Long grey dashes, which the solid faint lines of the grid (as often square to the world as the axes) do
        // not look like.
        auto line = [&](Vec2 d) {
            // A candidate axis drawn on a line of the grid would be lost on it, its dashes read as the grid's solid
            // line (two aligned boxes): it runs beside it instead, still across the pair.
            Vec2 through = m_discCenter;
            const Vec2 across = LeftPerp(d);
            const bool alongGrid = std::fabs(d.x) < 1e-12 || std::fabs(d.y) < 1e-12;
            if (alongGrid)
            {
                const double spacing = GridSpacing();
                const double at = Dot(through, across);
                const double off = at - spacing * std::round(at / spacing);
                if (std::fabs(off) * m_view.zoom < 4.0)
                {
                    through = through + ((off >= 0.0 ? 10.0 : -10.0) / m_view.zoom - off) * across;
                }
            }
            DashedSegment(m_canvas, At(through - reach * d), At(through + reach * d), kCandidateAxisColor,
                          kCandidateAxisWidth, m_bounds, kCandidateAxisDash, kCandidateAxisGap);
        };
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            if (body.shape.type == ShapeType::Polygon && body.shape.polygon.Count() <= 64)
            {
                const Rot q = body.Xf().q;
                for (const Vec2& n : body.shape.polygon.Normals())
                {
                    line(Rotate(q, n));
                }
            }
        }
        if (!m_study.sweep && m_study.Textbook())
        {
            for (const TextbookAxis& t : m_study.textbook.axes)
            {
                if (t.faces[0].kind != AxisKind::FaceNormal)
                {
                    line(t.direction);
                }
            }
        }
        else if (!m_study.sweep)
        {
            for (const AxisTest& t : m_study.trace.axes)
            {
                if (t.axis.kind != AxisKind::FaceNormal)
                {
                    line(t.direction);
                }
            }
        }
    }

    void Shapes()
    {
        m_canvas.BeginGroup("shapes");
        int others = 0;
        for (size_t i = 0; i < m_scene.bodies.size(); ++i)
        {
            const int index = static_cast<int>(i);
            if (index == m_study.bodyA || index == m_study.bodyB)
            {
                continue;
            }
            const Body& body = m_scene.bodies[i];
            if (OffPicture(body.shape, body.Xf()))
            {
                continue;
            }
            ++others;
            DrawBody(body, palette::kOther, 0.18f);
            // A label on a grey body would read as that body's.
            if (!body.IsConcave())
            {
                m_labels.ReserveShape(ShapeOutline(m_view, body.shape, body.Xf()));
            }
            for (const ConcavePart& part : body.IsConcave() ? body.concave.parts : std::vector<ConcavePart>{})
            {
                m_labels.ReserveShape(ShapeOutline(m_view, part.shape, body.Xf()));
            }
        }
        DrawBody(m_bodyA, palette::kShapeA, 0.22f);
        DrawBody(m_bodyB, palette::kShapeB, 0.28f);
        FrameSmallPair(others);
    }

    // Among many other bodies a pair drawn small is lost (crowd.json: two hundred bodies, the pair in the middle a
    // few pixels wide): a frame round it, named, shows which pair is tested.
    void FrameSmallPair(int others)
    {
        if (others < kCrowd)
        {
            return;
        }
        float minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
        for (const Body* body : {&m_bodyA, &m_bodyB})
        {
            for (const ScreenPoint& p : ShapeOutline(m_view, body->shape, body->Xf()))
            {
                minX = std::min(minX, p.x);
                minY = std::min(minY, p.y);
                maxX = std::max(maxX, p.x);
                maxY = std::max(maxY, p.y);
            }
        }
        const float sceneHeight = m_layout.sceneBottom - m_layout.sceneTop;
        if (std::max(maxX - minX, maxY - minY) > 0.2f * std::min(Width(), sceneHeight))
        {
            return;
        }
        m_canvas.BeginGroup("tested pair");
        const float pad = 10.0f;
        const ScreenPoint corners[4] = {
            {minX - pad, minY - pad}, {maxX + pad, minY - pad}, {maxX + pad, maxY + pad}, {minX - pad, maxY + pad}};
        m_canvas.Polyline(corners, 4, true, palette::kInk, 1.5f);
        for (int k = 0; k < 4; ++k)
        {
            m_labels.ReserveLine(corners[k], corners[(k + 1) % 4], 1.5f);
        }
        m_labels.Place({0.5f * (minX + maxX), minY - pad}, "tested: " + m_bodyA.name + " and " + m_bodyB.name,
                       TextStyle::Label, palette::kInk, 0.0f, -1.0f, 4.0f, LabelRank::Name);
    }
    // Other bodies in the picture from which on a small pair is framed.
    static constexpr int kCrowd = 12;

    // A body as drawn: a concave body by its pieces, filled, its outline as written, and the seams between its
    // pieces dashed (they are no surface: nothing collides with them); any other body by its shape.
    void DrawBody(const Body& body, Color color, float fill)
    {
        if (!body.IsConcave())
        {
            DrawShape(body.shape, body.Xf(), color, fill);
            return;
        }
        const Transform xf = body.Xf();
        for (const ConcavePart& part : body.concave.parts)
        {
            std::vector<ScreenPoint> piece;
            for (const Vec2& v : part.shape.polygon.Vertices())
            {
                piece.push_back(At(TransformPoint(xf, v)));
            }
            m_canvas.FillConvex(piece.data(), static_cast<int>(piece.size()), WithAlpha(color, fill));
        }
        const float dash = 6.0f;
        for (const ConcavePart& part : body.concave.parts)
        {
            const Polygon& polygon = part.shape.polygon;
            for (int e = 0; e < polygon.Count(); ++e)
            {
                if (!part.internal[static_cast<size_t>(e)])
                {
                    continue;
                }
                const ScreenPoint a = At(TransformPoint(xf, polygon.Vertices()[e]));
                const ScreenPoint b = At(TransformPoint(xf, polygon.Vertices()[(e + 1) % polygon.Count()]));
                const float length = std::hypot(b.x - a.x, b.y - a.y);
                for (float t = 0.0f; t < length; t += 2.0f * dash)
                {
                    const float u = t / length, w = std::min(t + dash, length) / length;
                    m_canvas.Segment({a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)},
                                    {a.x + w * (b.x - a.x), a.y + w * (b.y - a.y)}, WithAlpha(color, 0.6f), 1.0f);
                }
            }
        }
        std::vector<ScreenPoint> outline;
        for (const Vec2& v : body.outline)
        {
            outline.push_back(At(TransformPoint(xf, v)));
        }
        m_canvas.Polyline(outline.data(), static_cast<int>(outline.size()), true, color, kOutline);
    }

    // True when the shape placed by xf lies wholly outside the picture (a body the camera does not see), judged by
    // the circle about its origin that holds it.
    bool OffPicture(const Shape& shape, const Transform& xf) const
    {
        Vec2 center = xf.p;
        double radius = 0.0;
        if (shape.type == ShapeType::Circle)
        {
            center = TransformPoint(xf, shape.circle.center);
            radius = shape.circle.radius;
        }
        else
        {
            for (const Vec2& v : shape.polygon.Vertices())
            {
                radius = std::max(radius, Length(v));
            }
        }
        const ScreenPoint at = At(center);
        const float reach = static_cast<float>(radius * m_view.zoom) + kOutline;
        return at.x + reach < m_bounds.minX || at.x - reach > m_bounds.maxX || at.y + reach < m_bounds.minY ||
               at.y - reach > m_bounds.maxY;
    }

    void DrawShape(const Shape& shape, const Transform& xf, Color color, float fill)
    {
        const std::vector<ScreenPoint> outline = ShapeOutline(m_view, shape, xf);
        if (outline.size() >= 3)
        {
            m_canvas.FillOutlined(outline.data(), static_cast<int>(outline.size()), WithAlpha(color, fill), color,
                                 kOutline);
        }
        else
        {
            m_canvas.Polyline(outline.data(), static_cast<int>(outline.size()), true, color, kOutline);
        }
        if (shape.type == ShapeType::Circle)
        {
            m_canvas.FillCircle(At(TransformPoint(xf, shape.circle.center)), 2.5f, color);
            m_used.push_back(LegendMark::Centre);
        }
    }

    void Normals()
    {
        m_canvas.BeginGroup("normals");
        m_used.push_back(LegendMark::Normal);
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            if (body.shape.type != ShapeType::Polygon)
            {
                continue;
            }
            const Transform xf = body.Xf();
            const auto& poly = body.shape.polygon;
            const std::vector<ScreenPoint> other = OutlineOf(1 - s);
            // Whether the arrow from `a` runs along an edge of the other body, which is drawn over it (as the
            // tested face, thick and dark) and would hide it: two boxes side by side, one's middle level with the
            // other's edge.
            const auto alongOther = [&](ScreenPoint a, ScreenPoint tip) {
                for (size_t k = 0; k < other.size(); ++k)
                {
                    const ScreenPoint p = other[k];
                    const ScreenPoint q = other[(k + 1) % other.size()];
                    const float length = std::hypot(q.x - p.x, q.y - p.y);
                    if (length < 1.0f)
                    {
                        continue;
                    }
                    const auto off = [&](ScreenPoint m) {
                        return std::fabs((q.x - p.x) * (m.y - p.y) - (q.y - p.y) * (m.x - p.x)) / length;
                    };
                    const auto within = [&](ScreenPoint m) {
                        const float t = ((m.x - p.x) * (q.x - p.x) + (m.y - p.y) * (q.y - p.y)) / (length * length);
                        return t > -0.05f && t < 1.05f;
                    };
                    if (off(a) < 4.0f && off(tip) < 4.0f && (within(a) || within(tip)))
                    {
                        return true;
                    }
                }
                return false;
            };
            for (int i = 0; i < poly.Count(); ++i)
            {
                const Vec2 n = Rotate(xf.q, poly.Normal(i));
                const auto from = [&](double t) { return At(TransformPoint(xf, poly.Vertices()[i] + t * poly.Edge(i))); };
                const auto tipOf = [&](ScreenPoint a) {
                    return ScreenPoint{a.x + 22.0f * static_cast<float>(n.x), a.y - 22.0f * static_cast<float>(n.y)};
                };
                ScreenPoint a = from(0.5);
                for (const double t : {0.5, 0.35, 0.65, 0.25, 0.75})
                {
                    if (!alongOther(from(t), tipOf(from(t))))
                    {
                        a = from(t);
                        break;
                    }
                }
                MarkedArrow(a, tipOf(a), InkOf(s), 1.5f, 7.0f);
            }
        }
    }

    // Whether two bodies' velocity arrows lie on one line on screen: parallel, and within a few pixels of it.
    bool OnOneLine(const Body& a, const Body& b) const
    {
        const ScreenPoint a0 = At(ShapeCenter(a.shape, a.Xf()));
        const ScreenPoint a1 = At(ShapeCenter(a.shape, a.Xf()) + a.velocity);
        const ScreenPoint b0 = At(ShapeCenter(b.shape, b.Xf()));
        const ScreenPoint b1 = At(ShapeCenter(b.shape, b.Xf()) + b.velocity);
        const float la = std::hypot(a1.x - a0.x, a1.y - a0.y);
        const float lb = std::hypot(b1.x - b0.x, b1.y - b0.y);
        if (la < 1.0f || lb < 1.0f)
        {
            return false;
        }
        const float ux = (a1.x - a0.x) / la;
        const float uy = (a1.y - a0.y) / la;
        const float sine = std::abs(ux * (b1.y - b0.y) - uy * (b1.x - b0.x)) / lb;
        const float apart = std::abs(ux * (b0.y - a0.y) - uy * (b0.x - a0.x));
        return sine < 0.05f && apart < 6.0f;
    }

    // Velocity arrows and each moving shape's outline at t = 1.
    void Motion()
    {
        m_canvas.BeginGroup("swept");
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            if (body.velocity == Vec2{})
            {
                continue;
            }
            // Where the shape would be at the end of the step; after a hit the ghost at impact says more.
            std::vector<ScreenPoint> endOutline;
            if (m_study.sweepResult.status != SweepStatus::Hit)
            {
                const Transform end = BodyTransformAt(body, 1.0);
                const std::vector<ScreenPoint> outline = ShapeOutline(m_view, body.shape, end);
                endOutline = outline;
                DashedOutline(m_canvas, outline, WithAlpha(ColorOf(s), 0.55f), 1.2f, m_bounds);
                // A face's name beside it would read as this outline's (the floor's e2 by the box's end).
                m_ghostOutlines.push_back(outline);
                m_used.push_back(LegendMark::Dashed);
            }
            const Vec2 c = ShapeCenter(body.shape, body.Xf());
            ScreenPoint from = At(c);
            if (OutOfSight(body))
            {
                SpeedAtEdge(s);
                continue;
            }
            // A velocity whose step runs far out of the scene (l17_bullet's 1667 m on a canvas of a few metres) is
            // drawn shorter, its head in sight, and its label gives the speed, as it is not to scale.
            bool shortened = false;
            ScreenPoint tip = TipInSight(from, At(c + body.velocity), &shortened);
            // Two arrows on one line (a head-on pair) would hide each other: each moves aside, parallel, A's to
            // the left of its motion and B's to the left of its own, so they pass.
            const Body& other = BodyOf(1 - s);
            if (other.velocity != Vec2{} && OnOneLine(body, other))
            {
                const float length = std::max(std::hypot(tip.x - from.x, tip.y - from.y), 1e-3f);
                const ScreenPoint side{(tip.y - from.y) / length * 6.0f, -(tip.x - from.x) / length * 6.0f};
                from = {from.x + side.x, from.y + side.y};
                tip = {tip.x + side.x, tip.y + side.y};
            }
            MarkedArrow(from, tip, InkOf(s), 2.0f, 11.0f);
            m_velocityShafts.emplace_back(from, tip);
            // Not beside its own ghost on the way, where the name reads as the ghost's.
            std::vector<ScreenPoint> ghost;
            if (m_study.sweepResult.status == SweepStatus::Hit && Has(m_figure, kLayerGhost))
            {
                ghost = ShapeOutline(m_view, body.shape, BodyTransformAt(body, m_study.sweepResult.toi));
            }
            // Kept out of the other body, where it would read as that body's velocity: by its head, or beside its own
            // shaft where the head is crowded (beside a face's normal, whose "v" it would seem).
            const std::vector<ScreenPoint> otherOutline = OutlineOf(1 - s);
            const auto along = [&](float f) {
                return ScreenPoint{from.x + (tip.x - from.x) * f, from.y + (tip.y - from.y) * f};
            };
            bool into = false;
            std::vector<ScreenPoint> shaft;
            std::vector<ScreenPoint> clear;
            // An arrow that runs through the other body and out beyond it (l14_head_on's A at 3 m/s, through the
            // ball B): by its head, past B, its name reads as B's velocity pointing the wrong way. It is named
            // beside the part of its shaft before the other body, as one that ends inside it.
            float through = -1.0f;
            if (!Covered(tip, otherOutline, 0.0f) && !Covered(from, otherOutline, 0.0f))
            {
                for (int k = 1; k < 64 && through < 0.0f; ++k)
                {
                    const float f = static_cast<float>(k) / 64.0f;
                    through = Covered(along(f), otherOutline, 0.0f) ? f : -1.0f;
                }
            }
            if (through > 0.0f)
            {
                float lo = through - 1.0f / 64.0f, hi = through;
                for (int k = 0; k < 16; ++k)
                {
                    const float mid = 0.5f * (lo + hi);
                    (Covered(along(mid), otherOutline, 0.0f) ? hi : lo) = mid;
                }
                const float enter = lo;
                float leave = 0.0f;
                if (Covered(from, OutlineOf(s), 0.0f))
                {
                    float a = 0.0f, b = enter;
                    for (int k = 0; k < 24; ++k)
                    {
                        const float mid = 0.5f * (a + b);
                        (Covered(along(mid), OutlineOf(s), 0.0f) ? a : b) = mid;
                    }
                    leave = b;
                }
                for (const float f : {0.5f, 0.35f, 0.65f, 0.2f, 0.8f})
                {
                    shaft.push_back(along(leave + (enter - leave) * f));
                }
            }
            else if (Covered(tip, otherOutline, 0.0f) && !Covered(from, otherOutline, 0.0f))
            {
                // An arrow that runs into the other body (a box thrown at a floor): by its head, inside that body,
                // the name would sit by that body's own name. It is named beside the part of its shaft between the
                // two bodies, from the middle of that part out; where that part is too short for it (a box resting
                // on a floor), by its head as before.
                const auto edge = [&](const std::vector<ScreenPoint>& outline, bool entering) {
                    float lo = 0.0f, hi = 1.0f;
                    for (int k = 0; k < 24; ++k)
                    {
                        const float mid = 0.5f * (lo + hi);
                        (Covered(along(mid), outline, 0.0f) == entering ? hi : lo) = mid;
                    }
                    return entering ? lo : hi;
                };
                const float enter = edge(otherOutline, true);
                const float leave = Covered(from, OutlineOf(s), 0.0f) ? edge(OutlineOf(s), false) : 0.0f;
                for (const float f : {0.5f, 0.35f, 0.65f, 0.2f, 0.8f})
                {
                    const ScreenPoint p = along(leave + (enter - leave) * f);
                    shaft.push_back(p);
                    if (!Covered(p, ghost, 24.0f))
                    {
                        clear.push_back(p);
                    }
                }
                into = true;
            }
            else
            {
                // A short shaft that runs wholly by it keeps its places: the ghost is then where the arrow is.
                for (const float f : {0.8f, 0.6f, 0.4f})
                {
                    const ScreenPoint p = along(f);
                    shaft.push_back(p);
                    if (!Covered(p, ghost, 24.0f))
                    {
                        clear.push_back(p);
                    }
                }
            }
            const std::string name = shortened ? "v = " + FormatLabelNumber(Length(body.velocity)) +
                                                     (m_scene.hasWorld ? " m/s" : " per step")
                                               : "v";
            if (through > 0.0f)
            {
                // Beside the middle of that part, on the side the arrow was moved to when it shares its line with
                // the other body's (left of its motion), square to the shaft.
                m_labels.PlaceOutside(otherOutline, shaft.front(), name,
                                      shortened ? TextStyle::Label : TextStyle::Heading, InkOf(s),
                                      static_cast<float>(-body.velocity.y), static_cast<float>(-body.velocity.x), 6.0f,
                                      LabelRank::Note);
                m_labels.PreferOutOf(otherOutline);
                m_labels.AlsoBeside(std::move(shaft));
            }
            else
            {
                m_labels.PlaceOutside(otherOutline, tip, name, shortened ? TextStyle::Label : TextStyle::Heading,
                                      InkOf(s), static_cast<float>(body.velocity.x),
                                      static_cast<float>(-body.velocity.y), 6.0f, LabelRank::Note);
                m_labels.Names(MarkKind::ArrowHead);
                if (into)
                {
                    m_labels.PreferOutOf(otherOutline);
                }
                // Its head is the centre of its dashed outline at the end of the step: a name beside it, inside
                // that outline, reads as the outline's (fly_by's "v" in the dashed box).
                if (!endOutline.empty())
                {
                    m_labels.PreferOutOf(endOutline);
                }
                m_labels.AlsoBeside(clear.empty() ? std::move(shaft) : std::move(clear));
            }
            // And out of the other body where its ghost shows it (at the hit, at the figure's time).
            for (const double t : {m_study.sweepResult.status == SweepStatus::Hit ? m_study.sweepResult.toi : -1.0,
                                   m_figure.time})
            {
                if (t >= 0.0 && Has(m_figure, kLayerGhost) && other.velocity != Vec2{})
                {
                    m_labels.KeepOutOf(ShapeOutline(m_view, other.shape, BodyTransformAt(other, t)));
                }
            }
        }
    }

    // The tip of an arrow from `from` to `tip`, drawn as far as it fits 16 pixels inside the scene in sight; one that
    // would leave it is drawn shorter, not to scale: a modest arrow, which points the way without crossing the
    // figure, and whose label then gives the speed.
    ScreenPoint TipInSight(ScreenPoint from, ScreenPoint tip, bool* shortened = nullptr) const
    {
        const ScreenRect sight = SceneInSight();
        const ScreenRect inside{sight.minX + 16.0f, std::max(sight.minY, m_layout.sceneTop) + 16.0f, sight.maxX - 16.0f,
                                std::min(sight.maxY, m_layout.sceneBottom) - 16.0f};
        float keep = 1.0f;
        const float dx = tip.x - from.x;
        const float dy = tip.y - from.y;
        if (dx > 0.0f && tip.x > inside.maxX)
        {
            keep = std::min(keep, (inside.maxX - from.x) / dx);
        }
        if (dx < 0.0f && tip.x < inside.minX)
        {
            keep = std::min(keep, (inside.minX - from.x) / dx);
        }
        if (dy > 0.0f && tip.y > inside.maxY)
        {
            keep = std::min(keep, (inside.maxY - from.y) / dy);
        }
        if (dy < 0.0f && tip.y < inside.minY)
        {
            keep = std::min(keep, (inside.minY - from.y) / dy);
        }
        if (shortened != nullptr)
        {
            *shortened = keep < 1.0f;
        }
        if (keep < 1.0f)
        {
            keep = std::min(keep, 140.0f / std::max(std::hypot(dx, dy), 1e-3f));
        }
        keep = std::max(keep, 0.0f);
        return {from.x + keep * dx, from.y + keep * dy};
    }

    // A figure of one instant (a static query) with the swept layer: each moving body's velocity as an arrow from
    // its centre, named with its speed. A second's travel is drawn when it fits in the scene; a longer one is drawn
    // shorter, where its head shows, and the speed in its name says how fast.
    void Velocities()
    {
        m_canvas.BeginGroup("swept");
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            const double speed = Length(body.velocity);
            if (speed <= 0.0)
            {
                continue;
            }
            if (OutOfSight(body))
            {
                SpeedAtEdge(s);
                continue;
            }
            const ScreenPoint from = At(ShapeCenter(body.shape, body.Xf()));
            const ScreenPoint tip = TipInSight(from, At(ShapeCenter(body.shape, body.Xf()) + body.velocity));
            if (std::hypot(tip.x - from.x, tip.y - from.y) < 20.0f)
            {
                continue; // no room for an arrow
            }
            MarkedArrow(from, tip, InkOf(s), 2.0f, 11.0f);
            m_velocityShafts.emplace_back(from, tip);
            const std::string unit = m_scene.hasWorld ? " m/s" : " per step";
            m_labels.Place(tip, "v = " + FormatLabelNumber(speed) + unit, TextStyle::Label, InkOf(s),
                          static_cast<float>(body.velocity.x), static_cast<float>(-body.velocity.y), 6.0f,
                          LabelRank::Note);
            m_labels.Names(MarkKind::ArrowHead);
        }
    }

    // The Minkowski difference A - B in an inset at the scene's top right, in its own scale: the points a - b of
    // every pair of points of the shapes, a convex polygon. The shapes overlap exactly when it holds the origin;
    // the MTV is the origin's shortest way out of it; a sweep moves it by -t (vB - vA), so the time of impact is
    // where the ray from the origin along the relative motion enters it (van den Bergen; Ericson 3.11).
    void Minkowski()
    {
        m_canvas.BeginGroup("minkowski");
        std::vector<Vec2> points;
        auto outline = [&](const Body& body) {
            std::vector<Vec2> out;
            const Transform xf = body.Xf();
            if (body.shape.type == ShapeType::Polygon)
            {
                for (const Vec2& v : body.shape.polygon.Vertices())
                {
                    out.push_back(TransformPoint(xf, v));
                }
            }
            else
            {
                const Vec2 c = TransformPoint(xf, body.shape.circle.center);
                for (int k = 0; k < 48; ++k)
                {
                    const double angle = 6.283185307179586 * k / 48.0;
                    out.push_back(c + body.shape.circle.radius * Vec2{std::cos(angle), std::sin(angle)});
                }
            }
            return out;
        };
        const std::vector<Vec2> a = outline(m_bodyA);
        const std::vector<Vec2> b = outline(m_bodyB);
        const ScreenRect box = InsetBox();
        const float side = box.maxX - box.minX;
        m_canvas.FillRect({box.minX, box.minY}, {box.maxX, box.maxY}, WithAlpha(palette::kPanel, 0.95f));
        m_canvas.Polyline(
            std::vector<ScreenPoint>{
                {box.minX, box.minY}, {box.maxX, box.minY}, {box.maxX, box.maxY}, {box.minX, box.maxY}}
                .data(),
            4, true, palette::kFaint, 1.0f);
        m_canvas.Text({box.minX + 6.0f, box.minY + 4.0f}, "Minkowski A - B", TextStyle::Label, palette::kMuted);
        if (a.size() * b.size() > kMinkowskiPoints)
        {
            m_canvas.Text({box.minX + 6.0f, box.minY + 22.0f}, "too many vertices to draw", TextStyle::Label,
                         palette::kMuted);
            return;
        }
        // Relative to A's position, so that a pair far from the origin keeps its digits.
        const Vec2 base = m_bodyA.position - m_bodyB.position;
        for (const Vec2& p : a)
        {
            for (const Vec2& q : b)
            {
                points.push_back((p - q) - base);
            }
        }
        const PolygonResult hull = ComputeHull(points);
        if (!hull.Ok())
        {
            return;
        }
        const Vec2 motion = m_bodyB.velocity - m_bodyA.velocity;
        const bool sweep = m_study.sweep;
        // The inset's scale: the hull, the origin and (sweeps) the ray's end, with a margin.
        Vec2 low{0.0, 0.0};
        Vec2 high{0.0, 0.0};
        auto include = [&](Vec2 p) {
            low = {std::min(low.x, p.x), std::min(low.y, p.y)};
            high = {std::max(high.x, p.x), std::max(high.y, p.y)};
        };
        const Vec2 origin = -1.0 * base;
        include(origin);
        for (const Vec2& p : hull.polygon.Vertices())
        {
            include(p);
        }
        if (sweep)
        {
            include(origin + motion);
        }
        const double span = std::max({high.x - low.x, high.y - low.y, 1e-12});
        double scale = (side - 44.0f) / span;
        // The closing note's top: one line 18 px above the inset's bottom, two lines (a sweep's note too wide for
        // one) a line higher. A tall difference is drawn smaller, so that its bottom stays 4 px above the note.
        const SweepStatus sweepStatus =
            m_study.Textbook() ? m_study.textbookSweepResult.status : m_study.sweepResult.status;
        const double sweepToi = m_study.Textbook() ? m_study.textbookSweepResult.toi : m_study.sweepResult.toi;
        const std::string sweepNote = "the ray enters at t = " + FormatNumber(sweepToi);
        const bool twoLines = sweep && sweepStatus == SweepStatus::Hit &&
                              m_canvas.MeasureText(sweepNote, TextStyle::Label).x > side - 12.0f;
        const float noteTop =
            box.maxY - 18.0f - (twoLines ? m_canvas.MeasureText(sweepNote, TextStyle::Label).y + 2.0f : 0.0f);
        const double halfHeight = 0.5 * (high.y - low.y);
        const double below = noteTop - 4.0f - (0.5f * (box.minY + box.maxY) + 8.0f);
        if (halfHeight > 0.0 && below > 0.0 && halfHeight * scale > below)
        {
            scale = below / halfHeight;
        }
        const Vec2 middle = 0.5 * (low + high);
        auto at = [&](Vec2 p) {
            return ScreenPoint{static_cast<float>(0.5 * (box.minX + box.maxX) + (p.x - middle.x) * scale),
                               static_cast<float>(0.5 * (box.minY + box.maxY) + 8.0 - (p.y - middle.y) * scale)};
        };
        std::vector<ScreenPoint> screen;
        for (const Vec2& p : hull.polygon.Vertices())
        {
            screen.push_back(at(p));
        }
        m_canvas.FillConvex(screen.data(), static_cast<int>(screen.size()), WithAlpha(palette::kOverlap, 0.25f));
        m_canvas.Polyline(screen.data(), static_cast<int>(screen.size()), true, palette::kOverlap, 1.5f);
        const ScreenPoint o = at(origin);
        // The origin's dot goes over the ray or the arrow that leaves it, whose start would hide it.
        const auto originDot = [&] { m_canvas.FillCircle(o, 3.5f, palette::kInk); };
        // "O" goes on the side away from the arrow or the ray that leaves the origin, whose head it would hide.
        Vec2 leaving{};
        const bool overlapping = m_study.Textbook() ? m_study.textbookResult.overlap : m_study.manifold.overlap;
        if (sweep)
        {
            leaving = motion;
        }
        else if (overlapping)
        {
            leaving = m_study.Textbook() ? m_study.textbookResult.normal : m_study.manifold.normal;
        }
        const double leavingLength = Length(leaving);
        if (leavingLength > 0.0)
        {
            const ScreenPoint size = m_canvas.MeasureText("O", TextStyle::Label);
            const float ux = static_cast<float>(leaving.x / leavingLength);
            const float uy = static_cast<float>(-leaving.y / leavingLength);
            const float reach = 0.5f * size.x * std::fabs(ux) + 0.5f * size.y * std::fabs(uy) + 6.0f;
            m_canvas.Text({o.x - ux * reach - 0.5f * size.x, o.y - uy * reach - 0.5f * size.y}, "O", TextStyle::Label,
                         palette::kInk);
        }
        else
        {
            m_canvas.Text({o.x + 5.0f, o.y + 2.0f}, "O", TextStyle::Label, palette::kInk);
        }
        // The inset's closing note, on two lines when the inset is too narrow for one.
        const auto note = [&](const std::string& text, Color color) {
            const float room = side - 12.0f;
            const size_t cut = text.rfind(' ', text.find(" at t"));
            if (m_canvas.MeasureText(text, TextStyle::Label).x <= room || cut == std::string::npos || cut == 0)
            {
                m_canvas.Text({box.minX + 6.0f, box.maxY - 18.0f}, text, TextStyle::Label, color);
                return;
            }
            m_canvas.Text({box.minX + 6.0f, box.maxY - 20.0f - m_canvas.MeasureText(text, TextStyle::Label).y}, text.substr(0, cut),
                         TextStyle::Label, color);
            m_canvas.Text({box.minX + 6.0f, box.maxY - 18.0f}, text.substr(cut + 1), TextStyle::Label, color);
        };
        if (sweep)
        {
            // The origin moves by the relative motion relative to the difference: where it enters is the hit.
            DashedSegment(m_canvas, o, at(origin + motion), palette::kShapeBInk, 1.5f, box, 5.0f, 4.0f);
            if (sweepStatus == SweepStatus::Hit)
            {
                const ScreenPoint hit = at(origin + sweepToi * motion);
                m_canvas.FillCircle(hit, 4.0f, palette::kResult);
                note(sweepNote, palette::kResult);
            }
            originDot();
            return;
        }
        const bool overlap = m_study.Textbook() ? m_study.textbookResult.overlap : m_study.manifold.overlap;
        if (overlap)
        {
            const double depth = m_study.Textbook() ? m_study.textbookResult.depth : m_study.manifold.depth;
            const Vec2 normal = m_study.Textbook() ? m_study.textbookResult.normal : m_study.manifold.normal;
            // Moving B by depth * normal moves A - B by -depth * normal: the origin reaches the boundary at
            // depth * normal, the nearest boundary point.
            ScreenPoint tip = at(origin + depth * normal);
            // A depth too small to see still gets a visible arrow in its direction, as the MTV's in the scene, its
            // head clear of the origin's dot.
            if (std::hypot(tip.x - o.x, tip.y - o.y) < 16.0f)
            {
                tip = {o.x + 16.0f * static_cast<float>(normal.x), o.y - 16.0f * static_cast<float>(normal.y)};
            }
            Arrow(m_canvas, o, tip, palette::kResult, 2.0f, 8.0f);
            originDot();
        }
        else
        {
            originDot();
        }
        m_canvas.Text({box.minX + 6.0f, box.maxY - 18.0f}, overlap ? "O inside: overlap" : "O outside: apart",
                     TextStyle::Label, overlap ? palette::kResult : 0x006E50FFu);
    }

    // The moving shapes at the time of impact, and at the figure's chosen time.
    void Ghosts()
    {
        m_canvas.BeginGroup("ghost");
        const SweepResult& r = m_study.sweepResult;
        auto draw = [&](double t, float alpha, const std::string& label) {
            for (int s = 0; s < 2; ++s)
            {
                const Body& body = BodyOf(s);
                if (body.velocity == Vec2{})
                {
                    continue;
                }
                const Transform xf = BodyTransformAt(body, t);
                const std::vector<ScreenPoint> outline = ShapeOutline(m_view, body.shape, xf);
                m_canvas.FillConvex(outline.data(), static_cast<int>(outline.size()), WithAlpha(ColorOf(s), 0.10f));
                DashedOutline(m_canvas, outline, WithAlpha(InkOf(s), alpha), 1.8f, m_bounds);
                // A contact point's name across the ghost's outline would hide it, as for the MTV's.
                ReserveOutline(outline, 1.8f);
                m_ghostOutlines.push_back(outline);
                m_used.push_back(LegendMark::Dashed);
                // The label goes above the ghost, towards its trailing side, the one it came from: its leading
                // side is where it meets the other body and the contact points are marked, which a label there
                // would hide and whose marks it would seem to name.
                const Vec2 v = (1.0 / Length(body.velocity)) * body.velocity;
                const float ux = static_cast<float>(v.x);
                const float uy = static_cast<float>(-v.y);
                // A corner buried in a body drawn where the sweep starts (its own, which a short move leaves the
                // ghost lying across, or the other) is passed over where another is free: a label led from there
                // lies across that body's edges and reads as one of its marks (l13_sweep's "t = 0.30" on the
                // triangle's top edge).
                const std::vector<ScreenPoint> own = ShapeOutline(m_view, body.shape, body.Xf());
                const Body& otherBody = BodyOf(1 - s);
                const std::vector<ScreenPoint> other = ShapeOutline(m_view, otherBody.shape, otherBody.Xf());
                auto buried = [&](const ScreenPoint& p) { return Covered(p, own, 4.0f) || Covered(p, other, 4.0f); };
                ScreenPoint back = outline.front();
                auto rank = [&](const ScreenPoint& p) {
                    return p.y + 0.3f * (p.x * ux + p.y * uy) + (buried(p) ? 1.0e6f : 0.0f);
                };
                for (const ScreenPoint& p : outline)
                {
                    back = rank(p) < rank(back) ? p : back;
                }
                // A moving body out of the picture (the bullet far from the wall in a close-up) is named on its
                // ghost, the only place it is seen: its own name would hang at the image's edge, beside nothing.
                const bool unseen = OutOfSight(body);
                m_nameOnGhost[s] = m_nameOnGhost[s] || unseen;
                m_labels.Place(back, unseen ? body.name + " at " + label : label, TextStyle::Label, InkOf(s), -ux, -1.0f,
                               3.0f, LabelRank::Verdict);
                // Nor where a corner of the pair has its number, placed after it (the crate's corner beside the
                // ball that reaches it).
                KeepOffNumberedCorners(20.0f);
            }
        };
        if (r.status == SweepStatus::Hit)
        {
            draw(r.toi, 1.0f, "t = " + FormatNumber(r.toi));
        }
        if (m_figure.time >= 0.0)
        {
            draw(m_figure.time, 0.6f, "t = " + FormatNumber(m_figure.time));
        }
    }

    // Where the current axis comes from: the face (thick, with its normal) or the vertex-to-centre line.
    void AxisSource(const AxisRef& ref, Color color)
    {
        if (ref.kind == AxisKind::FaceNormal && ref.shape >= 0)
        {
            const Body& body = BodyOf(ref.shape);
            if (body.shape.type != ShapeType::Polygon)
            {
                return;
            }
            const auto& poly = body.shape.polygon;
            const Transform xf = body.Xf();
            const Vec2 v1 = TransformPoint(xf, poly.Vertices()[ref.index]);
            const Vec2 v2 = TransformPoint(xf, poly.Vertices()[(ref.index + 1) % poly.Count()]);
            m_canvas.Segment(At(v1), At(v2), color, 4.0f);
            // The face the axis comes from: its name goes beside the marked face, not on it.
            m_labels.ReserveLine(At(v1), At(v2), 4.0f);
            // Its normal starts from the middle of the part of the face in sight, and is drawn only when its head
            // shows: the caption or the number line's panel would hide the head of one drawn beyond them.
            const ScreenRect sight = SceneInSight();
            const ScreenRect inside{sight.minX + 4.0f, sight.minY + 4.0f, sight.maxX - 4.0f, sight.maxY - 4.0f};
            const Vec2 n = Rotate(xf.q, poly.Normal(ref.index));
            float length = 30.0f;
            const auto tipOf = [&](ScreenPoint m) {
                return ScreenPoint{m.x + length * static_cast<float>(n.x), m.y - length * static_cast<float>(n.y)};
            };
            const auto seen = [&](ScreenPoint m) {
                const ScreenPoint t = tipOf(m);
                return m.x >= inside.minX && m.x <= inside.maxX && m.y >= inside.minY && m.y <= inside.maxY &&
                       t.x >= inside.minX && t.x <= inside.maxX && t.y >= inside.minY && t.y <= inside.maxY;
            };
            ScreenPoint mid = At(0.5 * (v1 + v2));
            ScreenPoint p = At(v1);
            ScreenPoint q = At(v2);
            const bool clipped = ClipSegment(p, q, inside);
            if (!seen(mid) && clipped)
            {
                mid = {0.5f * (p.x + q.x), 0.5f * (p.y + q.y)};
            }
            // Its head off another arrow's head (the best face's normal beside the tested face's, on a small box on
            // a floor): elsewhere along the face in sight, when the middle's would sit on one.
            // At the verdict the contacts layer draws the incident edge, on the other body's outline, over it.
            // Nor on the other body's outline or inside it, where it would point at that body's corner rather than
            // show the face's direction (the diamond's face normal on the box's corner just across the gap).
            const std::vector<ScreenPoint> other = OutlineOf(1 - ref.shape);
            // Nor on B's outline moved out by the MTV, dashed over it at the verdict.
            const std::vector<ScreenPoint> moved = MtvOutline();
            const auto clear = [&](ScreenPoint m) {
                const ScreenPoint t = tipOf(m);
                const ScreenPoint base{t.x - 9.0f * static_cast<float>(n.x), t.y + 9.0f * static_cast<float>(n.y)};
                const ScreenRect headBox{std::min(t.x, base.x) - 5.0f, std::min(t.y, base.y) - 5.0f,
                                         std::max(t.x, base.x) + 5.0f, std::max(t.y, base.y) + 5.0f};
                if (Covered(t, other, 0.0f))
                {
                    return false;
                }
                for (const std::vector<ScreenPoint>* outline : {&other, &moved})
                {
                    for (size_t k = 0; k < outline->size(); ++k)
                    {
                        ScreenPoint a = (*outline)[k];
                        ScreenPoint b = (*outline)[(k + 1) % outline->size()];
                        if (ClipSegment(a, b, outline == &other ? ScreenRect{t.x - 6.0f, t.y - 6.0f, t.x + 6.0f, t.y + 6.0f}
                                                                : headBox))
                        {
                            return false;
                        }
                    }
                }
                // Nor on the axis line's bars, where a head of the body's colour on its own interval's bar is lost
                // (a face below its body, facing the axis line a short way off).
                const ScreenPoint back{t.x - 9.0f * static_cast<float>(n.x), t.y + 9.0f * static_cast<float>(n.y)};
                for (const Bar& bar : m_bars)
                {
                    ScreenPoint a = bar.a;
                    ScreenPoint b = bar.b;
                    const float r = 0.5f * bar.thickness + 1.0f;
                    if (ClipSegment(a, b,
                                    {std::min(t.x, back.x) - 4.0f - r, std::min(t.y, back.y) - 4.0f - r,
                                     std::max(t.x, back.x) + 4.0f + r, std::max(t.y, back.y) + 4.0f + r}))
                    {
                        return false;
                    }
                }
                // Nor under the MTV's arrow, drawn over everything last.
                if (m_hasMtvArrow)
                {
                    ScreenPoint a = m_mtvFrom;
                    ScreenPoint b = m_mtvTo;
                    if (ClipSegment(a, b,
                                    {std::min(t.x, back.x) - 7.0f, std::min(t.y, back.y) - 7.0f,
                                     std::max(t.x, back.x) + 7.0f, std::max(t.y, back.y) + 7.0f}))
                    {
                        return false;
                    }
                }
                // Nor under a velocity arrow's shaft, drawn before it: the normal's head would be lost on the shaft
                // (the box sliding along the floor, its velocity across the floor's normal).
                for (const auto& [a0, b0] : m_velocityShafts)
                {
                    ScreenPoint a = a0;
                    ScreenPoint b = b0;
                    // Nor beside its head, where two heads read as one mark.
                    if (ClipSegment(a, b,
                                    {std::min(t.x, back.x) - 4.0f, std::min(t.y, back.y) - 4.0f,
                                     std::max(t.x, back.x) + 4.0f, std::max(t.y, back.y) + 4.0f}) ||
                        std::hypot(t.x - b0.x, t.y - b0.y) < 24.0f)
                    {
                        return false;
                    }
                }
                // Nor across a ghost, the moving body at another time: the normal would seem to be the ghost's
                // (the crate's face beside the ball at the time of impact). Its first pixels may touch the ghost,
                // which meets the face at the contact.
                for (const std::vector<ScreenPoint>& ghost : m_ghostOutlines)
                {
                    for (size_t k = 0; k < ghost.size(); ++k)
                    {
                        const ScreenPoint g0 = ghost[k];
                        const ScreenPoint g1 = ghost[(k + 1) % ghost.size()];
                        for (float s = 4.0f; s <= length; s += 2.0f)
                        {
                            const ScreenPoint at{m.x + s * static_cast<float>(n.x), m.y - s * static_cast<float>(n.y)};
                            if (DistanceToSegment(at, g0, g1) < 3.0f)
                            {
                                return false;
                            }
                        }
                    }
                }
                // Nor tail to tail with the opposite face's normal (a thin wall): the two would read as one
                // double-headed arrow across the body.
                for (const auto& [tail, direction] : m_faceNormals)
                {
                    if (std::hypot(m.x - tail.x, m.y - tail.y) < 12.0f &&
                        direction.x * static_cast<float>(n.x) - direction.y * static_cast<float>(n.y) < -0.9f)
                    {
                        return false;
                    }
                }
                // Only the head matters: a shaft across another head leaves both readable.
                return !CrossesHead(back, t, 9.0f);
            };
            if (clipped && !clear(mid))
            {
                // Elsewhere along the face, then shorter or longer: a normal that stops short of the bars, or
                // reaches past the outline moved out by the MTV close beside the face, still shows its direction.
                const ScreenPoint middle = mid;
                bool found = false;
                for (const float tried : {30.0f, 22.0f, 42.0f, 16.0f})
                {
                    length = tried;
                    for (const float t : {0.5f, 0.35f, 0.65f, 0.25f, 0.75f, 0.15f, 0.85f})
                    {
                        const ScreenPoint m = t == 0.5f ? middle : ScreenPoint{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
                        if (seen(m) && clear(m))
                        {
                            mid = m;
                            found = true;
                            break;
                        }
                    }
                    if (found)
                    {
                        break;
                    }
                }
                if (!found)
                {
                    length = 30.0f;
                    mid = middle;
                }
            }
            if (seen(mid))
            {
                MarkedArrow(mid, tipOf(mid), color, 2.0f, 9.0f);
                m_faceNormals.push_back({mid, {static_cast<float>(n.x), static_cast<float>(-n.y)}});
            }
        }
        else if (ref.kind == AxisKind::VertexToCenter && ref.shape >= 0)
        {
            const Body& poly = BodyOf(ref.shape);
            const Body& circle = BodyOf(1 - ref.shape);
            if (poly.shape.type != ShapeType::Polygon || circle.shape.type != ShapeType::Circle)
            {
                return;
            }
            const Vec2 v = TransformPoint(poly.Xf(), poly.shape.polygon.Vertices()[ref.index]);
            const Vec2 c = TransformPoint(circle.Xf(), circle.shape.circle.center);
            DashedSegment(m_canvas, At(v), At(c), color, 2.0f, m_bounds);
            m_canvas.FillCircle(At(v), 4.0f, color);
            m_labels.Reserve(Disc(At(v), 4.0f));
            // The line ends at the circle's centre: a name over it (the ball's, centred in a small ball) hides
            // where the axis comes from.
            m_labels.Reserve(Disc(At(c), 3.0f));
            m_labels.ReserveFaintLine(At(v), At(c), 2.0f);
            m_used.push_back(LegendMark::VertexAxis);
        }
        else if (ref.kind == AxisKind::CenterToCenter)
        {
            const Vec2 a = TransformPoint(m_bodyA.Xf(), m_bodyA.shape.circle.center);
            const Vec2 b = TransformPoint(m_bodyB.Xf(), m_bodyB.shape.circle.center);
            DashedSegment(m_canvas, At(a), At(b), color, 2.0f, m_bounds);
            m_labels.Reserve(Disc(At(a), 3.0f));
            m_labels.Reserve(Disc(At(b), 3.0f));
            m_labels.ReserveFaintLine(At(a), At(b), 2.0f);
            m_used.push_back(LegendMark::VertexAxis);
        }
    }

    // Where the axis line runs: beside the pair, or, when that lies under the caption, the number line's panel or
    // past the image's side (a wall as tall as the picture), moved across into the part of the scene in sight, so
    // that its arrow head and its bars show.
    Vec2 AxisBaseInSight(Vec2 d, double lo, double hi) const
    {
        Vec2 base = AxisLineBase(m_points, d, kAxisGap / m_view.zoom);
        const Vec2 n = AxisSide(d);
        const ScreenPoint middle = At(Along(base, d, 0.5 * (lo + hi)));
        const float across[2] = {static_cast<float>(n.x), static_cast<float>(-n.y)};
        const float at[2] = {middle.x, middle.y};
        const float margin = 12.0f;
        const ScreenRect sight = SceneInSight();
        const float low[2] = {margin, std::max(m_layout.sceneTop, sight.minY) + margin};
        const float high[2] = {Width() - margin, std::min(m_layout.sceneBottom, sight.maxY) - margin};
        float from = -INFINITY;
        float to = INFINITY;
        for (int c = 0; c < 2; ++c)
        {
            if (std::fabs(across[c]) < 1e-3f)
            {
                continue; // a move across the line cannot bring it in along this side
            }
            const float s1 = (low[c] - at[c]) / across[c];
            const float s2 = (high[c] - at[c]) / across[c];
            from = std::max(from, std::min(s1, s2));
            to = std::min(to, std::max(s1, s2));
        }
        if (from <= to && (from > 0.0f || to < 0.0f))
        {
            const float shift = from > 0.0f ? from : to;
            base = base + (static_cast<double>(shift) / m_view.zoom) * n;
        }
        return base;
    }

    void AxisInScene()
    {
        m_canvas.BeginGroup("projection");
        const Vec2 d = m_axis.direction;
        const Vec2 n = AxisSide(d);
        double lo = 0.0;
        double hi = 0.0;
        AxisLineSpan(m_axis.minA, m_axis.maxA, m_axis.minB, m_axis.maxB, lo, hi);
        WidenBySweepAndBound(lo, hi);
        const Vec2 base = AxisBaseInSight(d, lo, hi);
        // A face decided without evaluation is drawn faintly: its numbers are the view's, not the test's.
        const float fade = m_axis.decided ? 0.4f : 1.0f;
        const auto faint = [fade](Color color, float alpha) { return WithAlpha(color, alpha * fade); };
        const double pad = kLinePad / m_view.zoom;
        // The line ends where the scene leaves sight, so that the caption or the panel never hides its head.
        ScreenPoint tail = At(Along(base, d, lo - pad));
        ScreenPoint head = At(Along(base, d, hi + pad));
        const ScreenRect sight = SceneInSight();
        const ScreenRect scene{4.0f, std::max(m_layout.sceneTop, sight.minY) + 4.0f, Width() - 4.0f,
                               std::min(m_layout.sceneBottom, sight.maxY) - 4.0f};
        if (!ClipSegment(tail, head, scene))
        {
            tail = At(Along(base, d, lo - pad));
            head = At(Along(base, d, hi + pad));
        }
        MarkedArrow(tail, head, faint(palette::kMuted, 1.0f), kAxisArrowWidth, kAxisArrowHead);
        const std::string name = (m_axis.textbook ? "axis " : "face test ") + std::to_string(m_axis.index + 1);
        // Named at its head.
        m_labels.Place(head,
                      !m_axis.decided ? name : name + (m_axis.bounded ? " (not walked to)" : " (not evaluated)"),
                      TextStyle::Label, palette::kMuted, static_cast<float>(d.x), static_cast<float>(-d.y), 6.0f,
                      LabelRank::Note);

        // Projectors: from each shape's extreme points down to the axis line.
        const Transform xfA = m_bodyA.Xf();
        const Transform xfB = m_bodyB.Xf();
        Vec2 lowA, highA, lowB, highB;
        Extremes(m_bodyA.shape, xfA, d, lowA, highA);
        Extremes(m_bodyB.shape, xfB, d, lowB, highB);
        const float ox = static_cast<float>(n.x);
        const float oy = static_cast<float>(-n.y);
        auto bar = [&](double lo, double hi, float offset, Color color, float thickness) {
            ScreenPoint p = At(Along(base, d, lo));
            ScreenPoint q = At(Along(base, d, hi));
            p = {p.x - ox * offset, p.y - oy * offset};
            q = {q.x - ox * offset, q.y - oy * offset};
            m_canvas.Segment(p, q, color, thickness);
            m_bars.push_back({p, q, thickness});
            // A label's halo over a bar would hide the interval it draws.
            m_labels.ReserveLine(p, q, thickness);
        };
        auto projector = [&](Vec2 from, double value, float offset, Color color) {
            ScreenPoint to = At(Along(base, d, value));
            to = {to.x - ox * offset, to.y - oy * offset};
            DashedSegment(m_canvas, At(from), to, faint(color, 0.55f), 1.0f, m_bounds, 4.0f, 4.0f);
        };
        projector(lowA, m_axis.minA, 5.0f, palette::kShapeA);
        projector(highA, m_axis.maxA, 5.0f, palette::kShapeA);
        projector(lowB, m_axis.minB, -5.0f, palette::kShapeBInk);
        projector(highB, m_axis.maxB, -5.0f, palette::kShapeBInk);
        // The push that separates the pair, or the gap, between the bars, labelled with its size.
        const bool overlap = m_axis.separation <= 0.0;
        const Color mark = overlap ? palette::kOverlap : palette::kGap;
        const double from = m_axis.leadMax;
        const double to = m_axis.otherMin;
        bar(from, to, 0.0f, faint(mark, overlap ? 0.6f : 1.0f), overlap ? 14.0f : 3.0f);
        if (m_axis.swept)
        {
            bar(m_axis.sweptMinB, m_axis.sweptMaxB, -5.0f, faint(palette::kShapeB, 0.35f), kBar);
        }
        bar(m_axis.minA, m_axis.maxA, 5.0f, faint(palette::kShapeA, 1.0f), kBar);
        bar(m_axis.minB, m_axis.maxB, -5.0f, faint(palette::kShapeB, 1.0f), kBar);
        if (m_axis.bounded)
        {
            // The vertex that bounds the gap: the other shape's near end lies no farther out than this tick.
            const ScreenPoint at = At(Along(base, d, m_axis.boundAt));
            m_canvas.Segment({at.x - ox * 16.0f, at.y - oy * 16.0f}, {at.x + ox * 16.0f, at.y + oy * 16.0f},
                            palette::kInk, 2.0f);
            m_labels.Place({at.x + ox * 18.0f, at.y + oy * 18.0f}, "bound", TextStyle::Label, palette::kInk, ox, oy,
                          6.0f, LabelRank::Note);
        }

        // Its label hangs from the middle of the part of the band in sight: one hung from under the panel would
        // lead across the panel's words.
        ScreenPoint middle = At(Along(base, d, 0.5 * (from + to)));
        ScreenPoint bandFrom = At(Along(base, d, from));
        ScreenPoint bandTo = At(Along(base, d, to));
        const bool middleSeen =
            middle.x >= scene.minX && middle.x <= scene.maxX && middle.y >= scene.minY && middle.y <= scene.maxY;
        if (!middleSeen)
        {
            if (!ClipSegment(bandFrom, bandTo, scene))
            {
                return; // the band lies wholly under the caption or the panel, whose number line names it
            }
            middle = {0.5f * (bandFrom.x + bandTo.x), 0.5f * (bandFrom.y + bandTo.y)};
        }
        const std::string text = BandLabel(m_axis);
        // On the far side of the bars from the pair, where the shapes' own labels crowd less (lesson 4's pitfall
        // figure put it between the bars and the slab, and pushed the slab's reference face down below it).
        // From the band itself, so that a leader line, where one is needed, ends on the band.
        m_labels.Place(middle, text, TextStyle::Label, overlap ? 0x8E3F6CFFu : 0x006E50FFu, ox, oy, 18.0f,
                      LabelRank::Verdict);
        // With no room there (the bars beside the image's edge), beside the band on the pair's side, rather than
        // on a leader line back across the bars and the axis.
        std::vector<ScreenPoint> near;
        for (const float t : {0.5f, 0.3f, 0.7f, 0.2f, 0.8f})
        {
            near.push_back({bandFrom.x + t * (bandTo.x - bandFrom.x) - ox * 12.0f,
                            bandFrom.y + t * (bandTo.y - bandFrom.y) - oy * 12.0f});
        }
        m_labels.AlsoAt(near);
        // Out of the bodies where it can be: inside one it reads as that body's and hides its outline and the
        // projection's guides (overlapping_boxes' "overlap 0.525" inside A on the app's narrowest canvas).
        for (int s = 0; s < 2; ++s)
        {
            m_labels.PreferOutOf(OutlineOf(s));
        }
    }

    // The separating line of a separating axis: perpendicular to it, through the middle of the gap.
    void SeparatingLine()
    {
        m_canvas.BeginGroup("exit");
        m_used.push_back(LegendMark::Separating);
        const Vec2 d = m_axis.direction;
        const double lo = std::min(m_axis.maxA, m_axis.maxB);
        const double hi = std::max(m_axis.minA, m_axis.minB);
        const double middle = 0.5 * (lo + hi);
        const Vec2 n = LeftPerp(d);
        const Vec2 point = m_discCenter + (middle - Dot(m_discCenter, d)) * d;
        const double reach = m_discRadius;
        DashedSegment(m_canvas, At(point - reach * n), At(point + reach * n), palette::kGap, 2.5f, m_bounds, 10.0f, 6.0f);
        // Named at its upper end as far as the scene shows it (the caption or the panel may hide its ends).
        ScreenPoint a = At(point - reach * n);
        ScreenPoint b = At(point + reach * n);
        const ScreenRect scene{0.0f, m_layout.sceneTop + 4.0f, Width(), m_layout.sceneBottom - 4.0f};
        if (ClipSegment(a, b, scene))
        {
            // The gap's size or a note on the line would hide it and read as naming it; a vertex number or an edge
            // name may still sit on it, rather than be left out where the line runs close beside its edge.
            m_labels.ReservePartingLine(a, b, 2.5f);
            m_labels.Place(a.y < b.y ? a : b, "separating line", TextStyle::Label, 0x006E50FFu, 0.0f, -1.0f, 6.0f,
                          LabelRank::Verdict);
            // With no room at that end (the gap's band and its size there), beside the line farther along, rather
            // than on a leader line that starts among the gap's marks.
            m_labels.AlsoAt(AlongFace(a.y < b.y ? a : b, a.y < b.y ? b : a, a.y < b.y ? a : b, {}, 0.0f, 24.0f, 24.0f));
        }
    }

    // The best axis so far (the smallest push; for sweeps, the latest entry), when it is not the current one.
    void BestSoFar()
    {
        const size_t k = static_cast<size_t>(m_axisIndex);
        int best = -1;
        if (m_study.Textbook())
        {
            best = m_study.sweep ? m_study.textbookSweep.axes[k].latestEntry : m_study.textbook.axes[k].best;
        }
        else
        {
            best = m_study.sweep ? m_study.sweepTrace.axes[k].latestEntry : m_study.trace.axes[k].best;
        }
        if (best < 0 || best == m_axisIndex)
        {
            return;
        }
        m_used.push_back(LegendMark::BestAxis);
        m_canvas.BeginGroup("best");
        const ShownAxis shown = ShowAxis(m_study, best);
        for (int f = 0; f < shown.faceCount; ++f)
        {
            AxisSource(shown.faces[f], palette::kBest);
        }
    }

    // The MTV the verdict draws; false when the pair does not overlap.
    bool ShownMtv(Manifold& m) const
    {
        m = m_study.sweep ? m_study.sweepResult.initial : m_study.manifold;
        const bool overlapping = m_study.sweep ? m_study.sweepResult.status == SweepStatus::Overlapping : m.overlap;
        if (!overlapping)
        {
            return false;
        }
        if (m_study.Textbook() && !m_study.sweep)
        {
            // The MTV the textbook test found: its smallest overlap, pushed the shorter way.
            m.depth = m_study.textbookResult.depth;
            m.normal = m_study.textbookResult.normal;
        }
        return true;
    }

    // B's outline moved out by the MTV, dashed at the verdict; empty when the figure does not draw it.
    std::vector<ScreenPoint> MtvOutline() const
    {
        Manifold m;
        if (!m_verdict || !Has(m_figure, kLayerMtv) || !ShownMtv(m) || RoundOffVerdict(m_study))
        {
            return {};
        }
        Transform moved = m_bodyB.Xf();
        moved.p = moved.p + m.depth * m.normal;
        return ShapeOutline(m_view, m_bodyB.shape, moved);
    }

    void Mtv()
    {
        Manifold m;
        if (!ShownMtv(m))
        {
            // Apart, where a pitfall says they collide (pitfall_one_shape): its wrong push, dashed, from B's centre.
            m_canvas.BeginGroup("mtv");
            PitfallPush(At(ShapeCenter(m_bodyB.shape, m_bodyB.Xf())), nullptr);
            return;
        }
        m_canvas.BeginGroup("mtv");
        // The length as the number line prints it: the deciding axis's overlap from its shown ends.
        const std::string depth = m_hasAxis && m_axis.separation <= 0.0
                                      ? ShownBand(m_axis.leadMax, m_axis.otherMin, m_axis.separation)
                                      : FormatNumber(m.depth);
        // A depth of round-off size moves B by nothing the eye can see, and the sentence says the shapes touch: an
        // arrow or an outline drawn a visible length would show a push there is not. The MTV is named on B, with
        // what it means, above B (or below it), beside B as a whole: a leader line to B's centre would end among
        // the marks of its faces and read as naming one of them.
        if (RoundOffVerdict(m_study))
        {
            const std::vector<ScreenPoint> outline = OutlineOf(1);
            const auto byHeight = [](ScreenPoint p, ScreenPoint q) { return p.y < q.y; };
            const ScreenPoint top = *std::min_element(outline.begin(), outline.end(), byHeight);
            const ScreenPoint bottom = *std::max_element(outline.begin(), outline.end(), byHeight);
            const float middle = 0.5f * (std::min_element(outline.begin(), outline.end(),
                                                          [](ScreenPoint p, ScreenPoint q) { return p.x < q.x; })->x +
                                         std::max_element(outline.begin(), outline.end(),
                                                          [](ScreenPoint p, ScreenPoint q) { return p.x < q.x; })->x);
            m_labels.Place({middle, top.y}, "MTV " + depth + ": round-off, they touch", TextStyle::Heading,
                           palette::kResult, 0.0f, -1.0f, 8.0f, LabelRank::Verdict);
            m_labels.AlsoAt({{middle, bottom.y}});
            return;
        }
        const Vec2 shift = m.depth * m.normal;
        const std::vector<ScreenPoint> cleared = MtvOutline();
        DashedOutline(m_canvas, cleared, palette::kShapeBInk, 1.8f, m_bounds);
        ReserveOutline(cleared, 1.8f);
        m_used.push_back(LegendMark::Dashed);
        const Vec2 c = ShapeCenter(m_bodyB.shape, m_bodyB.Xf());
        ScreenPoint from = At(c);
        ScreenPoint to = At(c + shift);
        // A depth too small to see still gets a visible arrow in its direction.
        const float dx = to.x - from.x;
        const float dy = to.y - from.y;
        if (dx * dx + dy * dy < 400.0f)
        {
            to = {from.x + 20.0f * static_cast<float>(m.normal.x), from.y - 20.0f * static_cast<float>(m.normal.y)};
        }
        // An arrow along the same line (a face's normal from B's face) would vanish under the MTV's: the MTV
        // moves aside, parallel, by a little more than the heads' width.
        if (CrossesHead(from, to, 3.0f))
        {
            const float length = std::max(std::hypot(to.x - from.x, to.y - from.y), 1e-3f);
            const ScreenPoint side{-(to.y - from.y) / length * 12.0f, (to.x - from.x) / length * 12.0f};
            from = {from.x + side.x, from.y + side.y};
            to = {to.x + side.x, to.y + side.y};
        }
        // The arrow is drawn over the labels (MtvArrow), so that B's name never hides its shaft.
        m_mtvFrom = from;
        m_mtvTo = to;
        m_hasMtvArrow = true;
        // The arrow is drawn over the labels: none may lie under it.
        m_labels.ReserveLine(from, to, 3.0f);
        m_labels.Reserve({to.x - 12.0f, to.y - 12.0f, to.x + 12.0f, to.y + 12.0f});
        m_labels.Place(to, "MTV " + depth, TextStyle::Heading, palette::kResult, static_cast<float>(m.normal.x),
                      static_cast<float>(-m.normal.y), 6.0f, LabelRank::Verdict);
        m_labels.Names(MarkKind::ArrowHead);
        // Beside its shaft, down to its tail: an arrow inside B, short and with its head crowded, is named inside B
        // (pitfall_direction's block), where a leader line out to a place beyond B would cross B's side.
        std::vector<ScreenPoint> shaft;
        for (const float f : {0.3f, 0.6f, 0.9f})
        {
            shaft.push_back({to.x + (from.x - to.x) * f, to.y + (from.y - to.y) * f});
        }
        m_labels.AlsoBeside(std::move(shaft));
        // A pitfall's push beside the right one, dashed, so that the two can be compared.
        PitfallPush(from, &m);
    }

    // A pitfall's wrong push from screen point `from` (B's centre, or beside the MTV's arrow when the right answer
    // `right` is a collision; null when it is apart), dashed, with B's outline where it leaves B and the depth B is
    // left at; MtvArrow draws the arrow over the labels.
    void PitfallPush(ScreenPoint from, const Manifold* right)
    {
        const PitfallResult& pitfall = m_study.pitfall;
        if (pitfall.ran && pitfall.overlap && !m_study.sweep && pitfall.depth > 0.0)
        {
            const Vec2 c = ShapeCenter(m_bodyB.shape, m_bodyB.Xf());
            m_pitfallFrom = from;
            m_pitfallTo = At(c + pitfall.depth * pitfall.normal);
            if (std::hypot(m_pitfallTo.x - from.x, m_pitfallTo.y - from.y) < 20.0f)
            {
                m_pitfallTo = {from.x + 20.0f * static_cast<float>(pitfall.normal.x),
                              from.y - 20.0f * static_cast<float>(pitfall.normal.y)};
            }
            // On the MTV's line (the wrong way, or the right way by luck) the two arrows would read as one
            // through B's centre: the wrong push moves aside, parallel, as the MTV moves aside for a normal.
            if (right != nullptr && m_hasMtvArrow)
            {
                const float mx = m_mtvTo.x - m_mtvFrom.x;
                const float my = m_mtvTo.y - m_mtvFrom.y;
                const float length = std::max(std::hypot(mx, my), 1e-3f);
                const float px = m_pitfallTo.x - from.x;
                const float py = m_pitfallTo.y - from.y;
                const float across = std::fabs(mx * py - my * px) / length;
                if (across < 0.2f * std::max(std::hypot(px, py), 1e-3f))
                {
                    const ScreenPoint side{-my / length * 14.0f, mx / length * 14.0f};
                    m_pitfallFrom = {from.x + side.x, from.y + side.y};
                    m_pitfallTo = {m_pitfallTo.x + side.x, m_pitfallTo.y + side.y};
                    from = m_pitfallFrom;
                }
            }
            m_hasPitfallArrow = true;
            m_used.push_back(LegendMark::PitfallPush);
            // Apart, the push itself is the mistake (a collision reported, and a push for it), and where it leaves B
            // is left out, as the key allows: a push a fraction of B's size runs that outline through B, beside the
            // faces the sentences name.
            if (right == nullptr)
            {
                m_labels.ReserveLine(from, m_pitfallTo, 2.0f);
                m_labels.Reserve(
                    {m_pitfallTo.x - 10.0f, m_pitfallTo.y - 10.0f, m_pitfallTo.x + 10.0f, m_pitfallTo.y + 10.0f});
                m_labels.Place(m_pitfallTo, "pitfall " + FormatNumber(pitfall.depth), TextStyle::Label,
                               palette::kInk, static_cast<float>(pitfall.normal.x),
                               static_cast<float>(-pitfall.normal.y), 6.0f, LabelRank::Verdict);
                NamesPitfallArrow();
                return;
            }
            // Where the pitfall's push leaves B, and how deep B still lies in A there (or lies now, pushed the
            // wrong way): the wrong depth the mistake is about, beside the MTV's outline that just clears A.
            Transform pushed = m_bodyB.Xf();
            pushed.p = pushed.p + pitfall.depth * pitfall.normal;
            const std::vector<ScreenPoint> outline = ShapeOutline(m_view, m_bodyB.shape, pushed);
            DashedOutline(m_canvas, outline, palette::kInk, 1.2f, m_bounds);
            ReserveOutline(outline, 1.2f);
            // A face's name beside it would read as this outline's (the crate's e1 by its pushed right side).
            m_ghostOutlines.push_back(outline);
            const Manifold left = Collide(m_bodyA.shape, m_bodyA.Xf(), m_bodyB.shape, pushed);
            if (left.overlap && left.depth > 0.0)
            {
                // Anchored where the pushed outline still lies in A (between its contact points), away from B.
                Vec2 inside{};
                for (int k = 0; k < left.contactCount; ++k)
                {
                    inside = inside + (1.0 / left.contactCount) * left.contacts[k].point;
                }
                if (left.contactCount == 0)
                {
                    inside = ShapeCenter(m_bodyB.shape, pushed);
                }
                // Not from an arrow (a face's normal leaving the pushed outline's contact, or crossing it): a leader
                // line from there reads as naming the arrow (pitfall_direction's note led to the tail of the block's
                // bottom normal). The anchor slides along the pushed outline's contacts, or towards its middle.
                ScreenPoint anchor = At(inside);
                const auto onArrow = [&](ScreenPoint p) {
                    return m_labels.NearArrowTail(p, kClearOfDot, {}) || m_labels.OnShaft(p, kClearOfDot);
                };
                if (onArrow(anchor))
                {
                    std::vector<Vec2> tries;
                    if (left.contactCount == 2)
                    {
                        for (const double f : {0.25, 0.75, 0.1, 0.9})
                        {
                            tries.push_back(left.contacts[0].point + f * (left.contacts[1].point - left.contacts[0].point));
                        }
                    }
                    const Vec2 middle = ShapeCenter(m_bodyB.shape, pushed);
                    for (const double f : {0.25, 0.5})
                    {
                        tries.push_back(inside + f * (middle - inside));
                    }
                    for (const Vec2& t : tries)
                    {
                        if (!onArrow(At(t)))
                        {
                            anchor = At(t);
                            break;
                        }
                    }
                }
                const bool still = right != nullptr && Dot(pitfall.normal, right->normal) >= 0.0;
                m_labels.Place(anchor,
                               "after the pitfall's push: " + std::string(still ? "still " : "") +
                                   FormatNumber(left.depth) + " deep",
                               TextStyle::Label, palette::kInk, 1.0f, 1.0f, 14.0f, LabelRank::Verdict);
            }
            m_labels.ReserveLine(from, m_pitfallTo, 2.0f);
            m_labels.Reserve({m_pitfallTo.x - 10.0f, m_pitfallTo.y - 10.0f, m_pitfallTo.x + 10.0f, m_pitfallTo.y + 10.0f});
            m_labels.Place(m_pitfallTo, "pitfall " + FormatNumber(pitfall.depth), TextStyle::Label, palette::kInk,
                          static_cast<float>(pitfall.normal.x), static_cast<float>(-pitfall.normal.y), 6.0f,
                          LabelRank::Verdict);
            NamesPitfallArrow();
        }
    }

    // The pitfall's name names its arrow: beside its head or its shaft, nearer them than any other arrow.
    void NamesPitfallArrow()
    {
        m_labels.Names(MarkKind::ArrowHead);
        m_labels.LeadsOffArrow();
        std::vector<ScreenPoint> shaft;
        for (const float f : {0.3f, 0.6f})
        {
            shaft.push_back({m_pitfallTo.x + (m_pitfallFrom.x - m_pitfallTo.x) * f,
                             m_pitfallTo.y + (m_pitfallFrom.y - m_pitfallTo.y) * f});
        }
        m_labels.AlsoBeside(std::move(shaft));
    }

    void MtvArrow()
    {
        m_canvas.BeginGroup("mtv");
        if (m_hasMtvArrow)
        {
            Arrow(m_canvas, m_mtvFrom, m_mtvTo, palette::kResult, 3.0f, 12.0f);
        }
        if (m_hasPitfallArrow)
        {
            const ScreenPoint from = m_pitfallFrom;
            const ScreenPoint to = m_pitfallTo;
            // The head drawn whole, from a head's length back: drawn from a point just short of its tip, Arrow
            // would shrink it to a few pixels, too small to tell the arrow from a line.
            const float length = std::max(std::hypot(to.x - from.x, to.y - from.y), 1e-3f);
            const float head = std::min(10.0f, length);
            DashedSegment(m_canvas, from, to, palette::kInk, 2.0f, m_bounds, 6.0f, 4.0f);
            Arrow(m_canvas, {to.x - head * (to.x - from.x) / length, to.y - head * (to.y - from.y) / length}, to,
                  palette::kInk, 2.0f, 10.0f);
        }
    }

    void Contacts()
    {
        m_canvas.BeginGroup("contacts");
        const ContactPoint* points = nullptr;
        int count = 0;
        if (m_study.sweep)
        {
            if (m_study.sweepResult.status == SweepStatus::Hit)
            {
                points = m_study.sweepResult.contacts;
                count = m_study.sweepResult.contactCount;
            }
            else if (m_study.sweepResult.status == SweepStatus::Overlapping)
            {
                points = m_study.sweepResult.initial.contacts;
                count = m_study.sweepResult.initial.contactCount;
            }
        }
        else
        {
            points = m_study.manifold.contacts;
            count = m_study.manifold.contactCount;
            if (m_study.trace.hasClip)
            {
                ClipPlanes(m_study.trace.clip);
            }
        }
        ScreenPoint screen[2] = {};
        for (int i = 0; i < count; ++i)
        {
            screen[i] = At(points[i].point);
            m_canvas.FillCircle(screen[i], 5.5f, palette::kResult);
            m_used.push_back(LegendMark::Contact);
            m_canvas.Circle(screen[i], 5.5f, palette::kBackground, 1.5f);
            m_labels.Reserve(Disc(screen[i], 6.5f));
            m_labels.AddMark(MarkKind::Contact, screen[i]);
            m_contactDots.push_back(screen[i]);
        }
        // Two contacts closer on screen than a label is wide share one label, placed between them.
        if (count == 2 && std::hypot(screen[0].x - screen[1].x, screen[0].y - screen[1].y) < 16.0f)
        {
            const ScreenPoint middle{0.5f * (screen[0].x + screen[1].x), 0.5f * (screen[0].y + screen[1].y)};
            m_labels.Place(middle, "c1, c2", TextStyle::Label, palette::kResult, 1.0f, -1.0f, 6.0f, LabelRank::Verdict);
            return;
        }
        for (int i = 0; i < count; ++i)
        {
            // Of two points, each name leans away from the other point, so that neither sits between the two where
            // it could be either's (l09_landing's "c2" below and between the two dots).
            float dx = 1.0f;
            float dy = -1.0f;
            if (count == 2)
            {
                const float ax = screen[i].x - screen[1 - i].x;
                const float ay = screen[i].y - screen[1 - i].y;
                const float length = std::max(std::hypot(ax, ay), 1e-3f);
                dx = ax / length + 0.3f;
                dy = ay / length - 0.3f;
            }
            m_labels.Place(screen[i], "c" + std::to_string(i + 1), TextStyle::Label, palette::kResult, dx, dy, 6.0f,
                          LabelRank::Verdict);
            m_labels.Names(MarkKind::Contact);
        }
    }

    // Whether the box of half sizes hx, hy centred on p lies wholly in `outline` (a body's name fits there).
    static bool BoxCovered(ScreenPoint p, float hx, float hy, const std::vector<ScreenPoint>& outline)
    {
        for (const ScreenPoint corner : {ScreenPoint{p.x - hx, p.y - hy}, ScreenPoint{p.x + hx, p.y - hy},
                                         ScreenPoint{p.x - hx, p.y + hy}, ScreenPoint{p.x + hx, p.y + hy}})
        {
            if (!Covered(corner, outline, 0.0f))
            {
                return false;
            }
        }
        return true;
    }

    // Whether p lies inside `other` (a convex outline on screen, either way round), or within `near` pixels of it.
    static bool Covered(ScreenPoint p, const std::vector<ScreenPoint>& other, float near)
    {
        float area = 0.0f;
        for (size_t i = 0; i < other.size(); ++i)
        {
            const ScreenPoint& u = other[i];
            const ScreenPoint& v = other[(i + 1) % other.size()];
            area += u.x * v.y - v.x * u.y;
        }
        if (other.size() < 3 || area == 0.0f)
        {
            return false;
        }
        for (size_t i = 0; i < other.size(); ++i)
        {
            const ScreenPoint& u = other[i];
            const ScreenPoint& v = other[(i + 1) % other.size()];
            const float length = std::hypot(v.x - u.x, v.y - u.y);
            if (length == 0.0f)
            {
                continue;
            }
            // How far p lies outside this edge's line, in pixels (the outline runs either way round).
            const float cross = (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
            if ((area > 0.0f ? -cross : cross) / length >= near)
            {
                return false;
            }
        }
        return true;
    }

    // Points of the segment ab every `step` pixels, `keep` pixels or more from its ends, that `other` leaves in
    // sight (Covered with `near`), nearest to `from` first, `from` itself left out: where a face's name may slide
    // to along it, not so near its ends that it names the corner or the next face.
    static std::vector<ScreenPoint> AlongFace(ScreenPoint a, ScreenPoint b, ScreenPoint from,
                                              const std::vector<ScreenPoint>& other, float near, float step = 16.0f,
                                              float keep = 0.0f)
    {
        std::vector<ScreenPoint> points;
        const float length = std::hypot(b.x - a.x, b.y - a.y);
        const int count = static_cast<int>(length / step);
        for (int i = 0; i <= count && length > 0.0f; ++i)
        {
            const float t = count == 0 ? 0.5f : static_cast<float>(i) / static_cast<float>(count);
            if (t * length < keep || (1.0f - t) * length < keep)
            {
                continue;
            }
            const ScreenPoint p{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
            if (std::hypot(p.x - from.x, p.y - from.y) >= 0.5f * step && !Covered(p, other, near))
            {
                points.push_back(p);
            }
        }
        std::stable_sort(points.begin(), points.end(), [&](ScreenPoint p, ScreenPoint q) {
            return std::hypot(p.x - from.x, p.y - from.y) < std::hypot(q.x - from.x, q.y - from.y);
        });
        return points;
    }

    // Where to name a face from: the middle of its longest stretch outside `other` (a convex outline on screen),
    // or its middle when none of it lies outside. A face whose middle the other body covers (a box sunk into a
    // wide slab) is named beside the part that shows, not beside the other body's edge lying over it.
    // Covered means inside the other body, or within `near` pixels of it.
    static ScreenPoint FreeMiddle(ScreenPoint a, ScreenPoint b, const std::vector<ScreenPoint>& other,
                                  float near = 0.0f, bool otherHasCorners = true)
    {
        auto inside = [&](ScreenPoint p) { return Covered(p, other, near); };
        constexpr int kSamples = 40;
        int bestStart = -1, bestLength = 0, runStart = -1;
        for (int i = 0; i <= kSamples + 1; ++i)
        {
            const float t = static_cast<float>(i) / kSamples;
            const bool out = i <= kSamples && !inside({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t});
            if (out && runStart < 0)
            {
                runStart = i;
            }
            if (!out && runStart >= 0)
            {
                if (i - runStart > bestLength)
                {
                    bestLength = i - runStart;
                    bestStart = runStart;
                }
                runStart = -1;
            }
        }
        // None of it outside: the middle.
        if (bestStart < 0)
        {
            return {0.5f * (a.x + b.x), 0.5f * (a.y + b.y)};
        }
        // All of it outside: the middle, unless it lies by the other body's corner (below); a round body has none.
        if (bestLength > kSamples && !otherHasCorners)
        {
            return {0.5f * (a.x + b.x), 0.5f * (a.y + b.y)};
        }
        const float t = bestLength > kSamples
                            ? 0.5f
                            : (static_cast<float>(bestStart) + 0.5f * static_cast<float>(bestLength - 1)) / kSamples;
        const ScreenPoint middle{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
        // A middle within a few dozen pixels of the other body (the free stretch of a floor ending under a plank's
        // raised corner) puts the name beside that body's corner, where it reads as naming the corner: the name
        // goes where the free stretch lies farthest both from the other body and from the edge's own ends.
        constexpr float kCrowded = 60.0f;
        const auto fromOther = [&](ScreenPoint p) {
            float best = 1e9f;
            for (size_t i = 0; i < other.size(); ++i)
            {
                const ScreenPoint q = NearestOnSegment(other[i], other[(i + 1) % other.size()], p);
                best = std::min(best, std::hypot(q.x - p.x, q.y - p.y));
            }
            return best;
        };
        if (other.size() < 3 || fromOther(middle) >= kCrowded)
        {
            return middle;
        }
        ScreenPoint best = middle;
        float room = 0.0f;
        for (int i = 0; i <= kSamples; ++i)
        {
            const float u = static_cast<float>(i) / kSamples;
            const ScreenPoint p{a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u};
            if (inside(p))
            {
                continue;
            }
            const float r = std::min({fromOther(p), std::hypot(p.x - a.x, p.y - a.y), std::hypot(p.x - b.x, p.y - b.y)});
            if (r > room)
            {
                room = r;
                best = p;
            }
        }
        return best;
    }

    // The point of the segment ab nearest p.
    static ScreenPoint NearestOnSegment(ScreenPoint a, ScreenPoint b, ScreenPoint p)
    {
        const float dx = b.x - a.x;
        const float dy = b.y - a.y;
        const float length2 = dx * dx + dy * dy;
        const float t = length2 > 0.0f ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0f, 1.0f) : 0.0f;
        return {a.x + dx * t, a.y + dy * t};
    }

    // The reference face, the incident edge and the two side planes that clip it.
    void ClipPlanes(const ClipTrace& clip)
    {
        const int referenceShape = clip.reference.shape;
        const ScreenPoint r1 = At(clip.referenceV1);
        const ScreenPoint r2 = At(clip.referenceV2);
        const Vec2 n = clip.referenceNormal;
        const double reach = 0.5 * m_discRadius;
        for (const Vec2& v : {clip.referenceV1, clip.referenceV2})
        {
            DashedSegment(m_canvas, At(v - reach * n), At(v + 0.3 * reach * n), palette::kMuted, 1.2f, m_bounds, 5.0f,
                          4.0f);
        }
        m_used.push_back(LegendMark::SidePlanes);
        m_canvas.Segment(r1, r2, InkOf(referenceShape), 5.0f);
        // Labels go beside the reference face and the incident edge, not over them.
        m_labels.ReserveLine(r1, r2, 5.0f);
        // Each name on its own body's side of the contact, out of the other body, where it reads as that body's.
        // Named from the part of the face the figure shows.
        ScreenPoint shown1 = r1;
        ScreenPoint shown2 = r2;
        if (!ClipSegment(shown1, shown2, m_bounds))
        {
            shown1 = r1;
            shown2 = r2;
        }
        // The reference face is named where the contact is, as a textbook marks the face the incident edge is
        // clipped against: from the point of the shown face nearest the contact points' middle that the other body
        // leaves in sight (a wide floor's free stretch far from the contact would name the floor, not the face of
        // this contact), sliding along the face from there (AlsoAt) when the contact's own marks leave no room.
        const std::vector<ScreenPoint> other = OutlineOf(1 - referenceShape);
        ScreenPoint near = FreeMiddle(shown1, shown2, other);
        // Not from a contact's dot, where the other body leaves the face, nor from a face's normal (its tail, or
        // its shaft where it crosses the face): a leader line from there reads as naming the contact or the
        // arrow (l11_decimal_touch's, led to where the other body's normal leaves the shared face).
        const auto offMarks = [&](ScreenPoint p) {
            for (int i = 0; i < m_study.manifold.contactCount; ++i)
            {
                const ScreenPoint dot = At(m_study.manifold.contacts[i].point);
                if (std::hypot(p.x - dot.x, p.y - dot.y) < kClearOfDot)
                {
                    return false;
                }
            }
            // Nor where the other body's outline crosses the face: a leader line ending there names either body's
            // edge (l13_overlap's, led to where B's face crosses A's right side).
            // An edge flush along the face (a plank lying on the floor) is where the face is: it does not count.
            // So too the dashed outlines drawn over it: where the MTV or a sweep leaves a body.
            const float faceLength = std::max(std::hypot(shown2.x - shown1.x, shown2.y - shown1.y), 1e-3f);
            std::vector<std::vector<ScreenPoint>> crossing = m_ghostOutlines;
            crossing.push_back(other);
            if (m_hasMtvArrow)
            {
                crossing.push_back(MtvOutline());
            }
            for (const std::vector<ScreenPoint>& outline : crossing)
            {
                for (size_t i = 0; i < outline.size(); ++i)
                {
                    const ScreenPoint u = outline[i];
                    const ScreenPoint v = outline[(i + 1) % outline.size()];
                    const float edgeLength = std::max(std::hypot(v.x - u.x, v.y - u.y), 1e-3f);
                    const float sine =
                        std::fabs((v.x - u.x) * (shown2.y - shown1.y) - (v.y - u.y) * (shown2.x - shown1.x)) /
                        (edgeLength * faceLength);
                    if (sine > 0.2f && DistanceToSegment(p, u, v) < 6.0f)
                    {
                        return false;
                    }
                }
            }
            // Nor beside another face's normal, or the MTV, that crosses the face (l05_naive_push's B's top normal
            // and MTV, which start below A's top face and run up across it).
            const bool byMtv = m_hasMtvArrow && DistanceToSegment(p, m_mtvFrom, m_mtvTo) < kClearOfDot;
            return !m_labels.NearArrowTail(p, kClearOfDot, {static_cast<float>(n.x), -static_cast<float>(n.y)}) &&
                   !m_labels.OnShaft(p, kClearOfDot) && !m_labels.NearCrossingShaft(p, kClearOfDot, shown1, shown2) &&
                   !byMtv;
        };
        if (m_study.manifold.contactCount > 0)
        {
            Vec2 middle{};
            for (int i = 0; i < m_study.manifold.contactCount; ++i)
            {
                middle = middle + (1.0 / m_study.manifold.contactCount) * m_study.manifold.contacts[i].point;
            }
            const ScreenPoint foot = NearestOnSegment(shown1, shown2, At(middle));
            std::vector<ScreenPoint> free = AlongFace(shown1, shown2, foot, other, 0.0f, 4.0f);
            std::vector<ScreenPoint> offDots;
            std::copy_if(free.begin(), free.end(), std::back_inserter(offDots), offMarks);
            if (!offDots.empty())
            {
                free = offDots;
            }
            // Nor from the very end of the face, at its corner: a leader line there names the corner. When the rest
            // of the face lies in the other body (a face sunk in a large body), it crosses the other body's outline
            // to the face instead.
            const auto atEnd = [&](ScreenPoint p) {
                return std::min(std::hypot(p.x - shown1.x, p.y - shown1.y), std::hypot(p.x - shown2.x, p.y - shown2.y)) <
                       kClearOfDot;
            };
            const bool atEnds = std::all_of(free.begin(), free.end(), atEnd);
            free.erase(std::remove_if(free.begin(), free.end(), atEnd), free.end());
            // From a stretch of the face clear of the other body and the dots that is as long as the name where
            // there is one: beside a short stretch by the face's end the name lands beyond the corner, beside the
            // next face (l15_slope's "reference face" beside the slope's end).
            const float width = m_canvas.MeasureText("reference face", TextStyle::Label).x;
            const float faceLength = std::hypot(shown2.x - shown1.x, shown2.y - shown1.y);
            const auto stretch = [&](ScreenPoint p) {
                const auto clear = [&](float t) {
                    const ScreenPoint q{shown1.x + (shown2.x - shown1.x) * t, shown1.y + (shown2.y - shown1.y) * t};
                    if (Covered(q, other, 0.0f))
                    {
                        return false;
                    }
                    for (int i = 0; i < m_study.manifold.contactCount; ++i)
                    {
                        const ScreenPoint dot = At(m_study.manifold.contacts[i].point);
                        if (std::hypot(q.x - dot.x, q.y - dot.y) < kClearOfDot)
                        {
                            return false;
                        }
                    }
                    return true;
                };
                const float at = std::hypot(p.x - shown1.x, p.y - shown1.y) / faceLength;
                const float step = 4.0f / faceLength;
                float low = at;
                float high = at;
                while (low - step >= 0.0f && clear(low - step))
                {
                    low -= step;
                }
                while (high + step <= 1.0f && clear(high + step))
                {
                    high += step;
                }
                return (high - low) * faceLength;
            };
            if (faceLength > 0.0f && std::any_of(free.begin(), free.end(), [&](ScreenPoint p) { return stretch(p) >= width; }))
            {
                free.erase(std::remove_if(free.begin(), free.end(), [&](ScreenPoint p) { return stretch(p) < width; }),
                           free.end());
            }
            near = (!Covered(foot, other, 0.0f) && offMarks(foot)) || free.empty() || atEnds ? foot : free.front();
        }
        m_labels.PlaceOutside(other, near, "reference face", TextStyle::Label, InkOf(referenceShape),
                             static_cast<float>(-n.x), static_cast<float>(n.y), 10.0f, LabelRank::Verdict);
        // Not so far along a long face that the name no longer reads as the contact's face: farther than that,
        // a leader line from the contact's foot shows it.
        std::vector<ScreenPoint> along = AlongFace(shown1, shown2, near, other, 0.0f, 16.0f, 40.0f);
        along.erase(std::remove_if(along.begin(), along.end(),
                                   [&](ScreenPoint p) {
                                       return std::hypot(p.x - near.x, p.y - near.y) > 64.0f || !offMarks(p);
                                   }),
                    along.end());
        m_labels.AlsoAt(along);
        m_labels.NamesFace(r1, r2, Rivals(other));
        m_labels.InFaceSpan();
        const ScreenPoint i1 = At(clip.incidentV1);
        const ScreenPoint i2 = At(clip.incidentV2);
        m_canvas.Segment(i1, i2, InkOf(clip.incidentShape), 5.0f);
        m_labels.ReserveLine(i1, i2, 5.0f);
        m_canvas.Segment(i1, i2, palette::kBackground, 1.5f);
        m_used.push_back(LegendMark::Reference);
        m_used.push_back(LegendMark::Incident);
        // Named from the point of the edge nearest its middle that is clear of the contacts' dots and of other
        // faces' normals: a leader line from a dot reads as naming the contact (overlapping_boxes' incident edge,
        // whose middle is c1), and from an arrow as naming the arrow.
        ScreenPoint incidentAt = At(0.5 * (clip.incidentV1 + clip.incidentV2));
        {
            // And, where the edge runs on past the reference face, from that part: beside the face, a leader line
            // crosses the face to reach the edge and ends as near the face as the edge (overlapping_boxes' A's
            // right edge, 4 px beside B's left face).
            const float length = std::hypot(i2.x - i1.x, i2.y - i1.y);
            const float referenceLength = std::max(std::hypot(r2.x - r1.x, r2.y - r1.y), 1e-3f);
            float best = INFINITY;
            bool beyond = false;
            for (float d = 0.0f; length > 0.0f && d <= length; d += 2.0f)
            {
                const ScreenPoint p{i1.x + (i2.x - i1.x) * d / length, i1.y + (i2.y - i1.y) * d / length};
                bool clear = std::min(d, length - d) >= 6.0f;
                const float along = ((p.x - r1.x) * (r2.x - r1.x) + (p.y - r1.y) * (r2.y - r1.y)) / referenceLength;
                const bool far = along < -6.0f || along > referenceLength + 6.0f ||
                                 DistanceToSegment(p, r1, r2) >= 2.0f * kClearOfDot;
                for (int k = 0; k < m_study.manifold.contactCount && clear; ++k)
                {
                    const ScreenPoint dot = At(m_study.manifold.contacts[k].point);
                    clear = std::hypot(p.x - dot.x, p.y - dot.y) >= kClearOfDot;
                }
                clear = clear &&
                        !m_labels.NearArrowTail(p, kClearOfDot, {-static_cast<float>(n.x), static_cast<float>(n.y)}) &&
                        !m_labels.OnShaft(p, kClearOfDot);
                const float off = std::abs(d - 0.5f * length);
                if (clear && ((far && !beyond) || (far == beyond && off < best)))
                {
                    best = off;
                    incidentAt = p;
                    beyond = far;
                }
            }
        }
        m_labels.PlaceOutside(OutlineOf(1 - clip.incidentShape), incidentAt, "incident edge", TextStyle::Label,
                             InkOf(clip.incidentShape), static_cast<float>(n.x), static_cast<float>(-n.y), 10.0f,
                             LabelRank::Verdict);
        m_labels.NamesFace(i1, i2, Rivals(OutlineOf(1 - clip.incidentShape)));
    }

    // The edges (or vertices) of body `shape` that a sentence names: "floor's edge 2", "box's edges 0 and 2", "B's
    // edges 0, 1 and 3", "box's vertex 2".
    std::vector<int> NamedIn(const std::string& text, int shape, const std::string& one, const std::string& many) const
    {
        std::vector<int> numbers;
        const std::string owner = BodyOf(shape).name + "'s ";
        for (size_t at = text.find(owner); at != std::string::npos; at = text.find(owner, at + 1))
        {
            // Not the end of a longer name ("AB's edge 1" names AB, not B).
            if (at > 0 && (std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_'))
            {
                continue;
            }
            size_t i = at + owner.size();
            const bool plural = text.compare(i, many.size(), many) == 0;
            if (!plural && text.compare(i, one.size(), one) != 0)
            {
                continue;
            }
            i += plural ? many.size() : one.size();
            // " 2", or " 0, 1 and 3" after the plural.
            while (i + 1 < text.size() && text[i] == ' ' && std::isdigit(static_cast<unsigned char>(text[i + 1])))
            {
                size_t end = i + 1;
                while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])))
                {
                    ++end;
                }
                numbers.push_back(std::stoi(text.substr(i + 1, end - i - 1)));
                i = end;
                if (!plural)
                {
                    break;
                }
                if (text.compare(i, 1, ",") == 0)
                {
                    ++i;
                }
                else if (text.compare(i, 4, " and") == 0)
                {
                    i += 4;
                }
                else
                {
                    break;
                }
            }
        }
        return numbers;
    }

    // How far a polygon of the pair reaches from its centroid on screen, in pixels.
    double ExtentOnScreen(int s) const
    {
        const Body& body = BodyOf(s);
        double extent = 0.0;
        for (size_t i = 0; body.shape.type == ShapeType::Polygon && i < body.shape.polygon.Vertices().size(); ++i)
        {
            extent = std::max(extent, Length(body.shape.polygon.Vertices()[i] - body.shape.polygon.Centroid()) * m_view.zoom);
        }
        return extent;
    }

    // Keeps the label added last `reach` pixels (across and down) from every numbered corner of the pair, where the
    // corner's number, placed after it, would find no room.
    void KeepOffNumberedCorners(float reach)
    {
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            for (size_t i = 0; NumbersCorners(s) && i < body.shape.polygon.Vertices().size(); ++i)
            {
                const ScreenPoint p = At(TransformPoint(body.Xf(), body.shape.polygon.Vertices()[i]));
                m_labels.KeepOutOf({{p.x - reach, p.y - reach},
                                    {p.x + reach, p.y - reach},
                                    {p.x + reach, p.y + reach},
                                    {p.x - reach, p.y + reach}});
            }
        }
    }

    // Whether a polygon of the pair has its corners numbered: numbers crowd a shape only a few dozen pixels wide,
    // and a shape of many sides.
    bool NumbersCorners(int s) const
    {
        const Body& body = BodyOf(s);
        return body.shape.type == ShapeType::Polygon && ExtentOnScreen(s) >= 45.0 && body.shape.polygon.Count() <= 24;
    }

    void Labels()
    {
        m_canvas.BeginGroup("labels");
        // The faces and corners the step's sentences name keep their names however small their body is drawn (a
        // canvas narrower than the figure, beside a lesson): a sentence about "right wall's edge 3" beside a
        // picture with no "e3" names nothing the student can find. They are placed before the other numbers.
        // The number line's title names the axis's face too.
        const std::string sentence = DescribeStep(m_scene, m_study, m_figure.step) + " " +
                                     (m_hasAxis ? DescribeAxis(m_scene, m_study, m_axis.Ref()) : std::string());
        // Every corner of the pair, that a vertex number keeps nearer its own corner than any other.
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            for (size_t i = 0; body.shape.type == ShapeType::Polygon && i < body.shape.polygon.Vertices().size(); ++i)
            {
                m_labels.AddMark(MarkKind::Corner, At(TransformPoint(body.Xf(), body.shape.polygon.Vertices()[i])), {}, true);
            }
        }
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            const Transform xf = body.Xf();
            const bool polygon = body.shape.type == ShapeType::Polygon;
            const std::vector<int> named = polygon ? NamedIn(sentence, s, "edge", "edges") : std::vector<int>{};
            const std::vector<int> namedVertices =
                polygon ? NamedIn(sentence, s, "vertex", "vertices") : std::vector<int>{};
            if (polygon && (body.shape.polygon.Count() <= 24 || !named.empty() || !namedVertices.empty()))
            {
                const auto& poly = body.shape.polygon;
                const Vec2 centroid = TransformPoint(xf, poly.Centroid());
                const double extent = ExtentOnScreen(s);
                const bool vertexNumbers = NumbersCorners(s);
                const bool edgeNumbers = extent >= 70.0 && poly.Count() <= 16;
                // Which corners lie inside the other body; a body wholly inside it (a box in a box) has its
                // numbers there, as it has no outside near its corners.
                const std::vector<ScreenPoint> other = OutlineOf(1 - s);
                const std::vector<ScreenPoint> own = OutlineOf(s);
                std::vector<bool> pokedIn;
                for (const Vec2& corner : poly.Vertices())
                {
                    pokedIn.push_back(Covered(At(TransformPoint(xf, corner)), other, 0.0f));
                }
                const bool contained = std::all_of(pokedIn.begin(), pokedIn.end(), [](bool b) { return b; });
                for (int i = 0; i < poly.Count(); ++i)
                {
                    const bool isNamed = std::find(namedVertices.begin(), namedVertices.end(), i) != namedVertices.end();
                    if (!vertexNumbers && !isNamed)
                    {
                        continue;
                    }
                    const Vec2 v = TransformPoint(xf, poly.Vertices()[i]);
                    // Where a contact point's dot or an arrow's head stands on the corner, it takes the corner's
                    // place (lesson 1): a number beside it would read as the dot's or the arrow's.
                    const ScreenPoint corner = At(v);
                    const auto on = [&](ScreenPoint p) { return std::hypot(p.x - corner.x, p.y - corner.y) < 7.0f; };
                    if (!isNamed && (std::any_of(m_contactDots.begin(), m_contactDots.end(), on) ||
                                     std::any_of(m_velocityShafts.begin(), m_velocityShafts.end(),
                                                 [&](const auto& shaft) { return on(shaft.second); })))
                    {
                        continue;
                    }
                    const Vec2 out = v - centroid;
                    if (!m_labels.PlaceOutside(other, At(v), std::to_string(i), TextStyle::Label, InkOf(s),
                                               static_cast<float>(out.x), static_cast<float>(-out.y), 4.0f,
                                               isNamed ? LabelRank::Named : LabelRank::Vertex))
                    {
                        continue;
                    }
                    m_labels.Names(MarkKind::Corner);
                    if (pokedIn[static_cast<size_t>(i)] && !contained)
                    {
                        // A corner pushed into the other body is numbered just outside both, where the number
                        // reads as that corner's, not the other body's; with no room there it is left out.
                        m_labels.OutsideBoth(own);
                    }
                }
                for (int i = 0; i < poly.Count(); ++i)
                {
                    const bool isNamed = std::find(named.begin(), named.end(), i) != named.end();
                    if (!edgeNumbers && !isNamed)
                    {
                        continue;
                    }
                    // Named beside the part of the edge the other body leaves in sight, on the edge's outer side:
                    // not inside that body, nor within a label's height of it, where the name would sit on it or
                    // behind it (a ball resting against a wall covers the middle of the wall's face).
                    // Only the part of the edge the figure shows counts: a long floor's free stretch off the image
                    // would put the name out of sight.
                    ScreenPoint from = At(TransformPoint(xf, poly.Vertices()[i]));
                    ScreenPoint to = At(TransformPoint(xf, poly.Vertices()[(i + 1) % poly.Count()]));
                    const ScreenPoint wholeFrom = from;
                    const ScreenPoint wholeTo = to;
                    // A face a sentence names is named on the part of it in sight: not under the caption or the
                    // number line, which hide the top and bottom of a large disc. A face wholly out of sight (a
                    // long floor's far end) has nowhere to be named.
                    if (isNamed && !ClipSegment(from, to, SceneInSight()))
                    {
                        continue;
                    }
                    if (!isNamed && !ClipSegment(from, to, m_bounds))
                    {
                        from = wholeFrom;
                        to = wholeTo;
                    }
                    ScreenPoint mid = FreeMiddle(from, to, other, 12.0f, BodyOf(1 - s).shape.type == ShapeType::Polygon);
                    // Not where a velocity's path crosses the edge: a leader line ending there names the path's
                    // meeting with the face (l10_round_bullet's crate e2, where the bullet's path enters it).
                    const auto crossed = [&](ScreenPoint p) {
                        return std::any_of(m_velocityShafts.begin(), m_velocityShafts.end(),
                                           [&](const std::pair<ScreenPoint, ScreenPoint>& shaft) {
                                               return DistanceToSegment(p, shaft.first, shaft.second) < 10.0f;
                                           });
                    };
                    if (crossed(mid))
                    {
                        for (const ScreenPoint& p : AlongFace(from, to, mid, other, 12.0f, 8.0f, 12.0f))
                        {
                            if (!crossed(p))
                            {
                                mid = p;
                                break;
                            }
                        }
                    }
                    const Vec2 n = Rotate(xf.q, poly.Normal(i));
                    if (m_labels.PlaceOutside(other, mid, "e" + std::to_string(i), TextStyle::Label,
                                             WithAlpha(InkOf(s), 0.75f), static_cast<float>(n.x),
                                             static_cast<float>(-n.y), 5.0f,
                                             isNamed ? LabelRank::Named : LabelRank::Edge))
                    {
                        m_labels.KeepOnSide();
                        m_labels.NamesFace(wholeFrom, wholeTo, Rivals(other));
                        // Nor inside a ghost, on a leader line either: there it reads as the ghost's (the wall's
                        // e3 inside the puck at the time of impact, on a narrow canvas). A ghost over the face,
                        // or flush against all of it (the body's own ghost where it meets the face), leaves it no
                        // choice.
                        for (const std::vector<ScreenPoint>& ghost : m_ghostOutlines)
                        {
                            const bool flush = Covered(wholeFrom, ghost, 3.0f) && Covered(wholeTo, ghost, 3.0f);
                            if (!Covered(mid, ghost, 0.0f) && !flush)
                            {
                                m_labels.KeepOutOf(ghost, true);
                            }
                        }
                        // A face a sentence names may have its name anywhere along it, away from its corners,
                        // when its middle is taken (a thin wall's name beside it).
                        // One flush against the other body along all its length has its name just inside its
                        // own body, anywhere along it.
                        if (isNamed)
                        {
                            m_labels.Within(own);
                            std::vector<ScreenPoint> along = AlongFace(from, to, mid, other, 12.0f, 8.0f, 12.0f);
                            m_labels.AlsoAt(along.empty() ? AlongFace(from, to, mid, {}, 0.0f, 8.0f, 12.0f) : along);
                        }
                        else
                        {
                            // Any other edge's name slides along its edge, away from the corners, rather than be
                            // left out where the other body crowds its middle.
                            m_labels.AlsoAt(AlongFace(from, to, mid, other, 12.0f, 8.0f, 16.0f));
                        }
                    }
                }
            }
        }
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = BodyOf(s);
            if (m_nameOnGhost[s])
            {
                continue;
            }
            const Vec2 center = ShapeCenter(body.shape, body.Xf());
            // A name wider or taller than its shape on screen would cover it: it goes beside the shape instead,
            // to the right of a thin one, below a flat one.
            Vec2 low, high, left, right;
            Extremes(body.shape, body.Xf(), {0.0, 1.0}, low, high);
            Extremes(body.shape, body.Xf(), {1.0, 0.0}, left, right);
            const float wide = static_cast<float>((right.x - left.x) * m_view.zoom);
            const float tall = static_cast<float>((high.y - low.y) * m_view.zoom);
            const ScreenPoint text = m_canvas.MeasureText(body.name, TextStyle::Heading);
            // A polygon turned part way round is wide and tall on screen but may be thin (a tilted plank): its name
            // goes inside only when the name's box fits in the outline, else just below the shape's middle.
            const std::vector<ScreenPoint> outline = OutlineOf(s);
            const ScreenPoint middle = At(center);
            bool fits = true;
            if (body.shape.type == ShapeType::Polygon)
            {
                const float hx = 0.5f * text.x + 4.0f;
                const float hy = 0.5f * text.y + 2.0f;
                fits = BoxCovered(middle, hx, hy, outline);
            }
            if (!fits && wide >= text.x + 8.0f && tall >= text.y + 4.0f)
            {
                // The outline's lowest point straight below the middle.
                float below = middle.y;
                for (size_t i = 0; i < outline.size(); ++i)
                {
                    const ScreenPoint& a = outline[i];
                    const ScreenPoint& b = outline[(i + 1) % outline.size()];
                    if ((a.x - middle.x) * (b.x - middle.x) <= 0.0f && a.x != b.x)
                    {
                        below = std::max(below, a.y + (b.y - a.y) * (middle.x - a.x) / (b.x - a.x));
                    }
                }
                m_labels.PlaceOutside(OutlineOf(1 - s), {middle.x, below}, body.name, TextStyle::Heading, InkOf(s),
                                     0.0f, 1.0f, 6.0f, LabelRank::Name);
            }
            else if (wide >= text.x + 8.0f && tall >= text.y + 4.0f)
            {
                // A face a sentence names that lies flush against the other body along its length (a box on the
                // floor) has its name just inside its own body: the body's name moves away from that face, where it
                // still fits, to leave it the room.
                ScreenPoint anchor = middle;
                // With no room inside clear of such a face (a small body in the app's narrow canvas), the name
                // goes outside, on the side away from that face, and leaves the inside to the face's name.
                bool aside = false;
                ScreenPoint away{0.0f, 0.0f};
                if (body.shape.type == ShapeType::Polygon)
                {
                    const std::vector<ScreenPoint> other = OutlineOf(1 - s);
                    const auto& poly = body.shape.polygon;
                    for (const int i : NamedIn(sentence, s, "edge", "edges"))
                    {
                        const Vec2 n = Rotate(body.Xf().q, poly.Normal(i));
                        bool flush = true;
                        for (const double t : {0.2, 0.5, 0.8})
                        {
                            const ScreenPoint face = At(TransformPoint(body.Xf(), poly.Vertices()[i] + t * poly.Edge(i)));
                            const ScreenPoint out{face.x + 4.0f * static_cast<float>(n.x),
                                                  face.y - 4.0f * static_cast<float>(n.y)};
                            flush = flush && Covered(out, other, 0.0f);
                        }
                        // A small body's name (at most some 140 pixels across) at its middle leaves no room inside
                        // for the name of a face that a line or a mark crowds outside: it moves away from that face
                        // too, or out of the body.
                        const ScreenPoint start = At(TransformPoint(body.Xf(), poly.Vertices()[i]));
                        const float depth = (start.x - middle.x) * static_cast<float>(n.x) -
                                            (start.y - middle.y) * static_cast<float>(n.y);
                        const bool near = std::max(wide, tall) < 140.0f && depth < 0.5f * text.y + 22.0f;
                        if (!flush && !near)
                        {
                            continue;
                        }
                        bool moved = false;
                        for (const float shift : {20.0f, 16.0f, 12.0f, 8.0f})
                        {
                            const ScreenPoint p{anchor.x - shift * static_cast<float>(n.x),
                                                anchor.y + shift * static_cast<float>(n.y)};
                            const float hx = 0.5f * text.x + 4.0f;
                            const float hy = 0.5f * text.y + 2.0f;
                            const bool inside = BoxCovered(p, hx, hy, outline);
                            if (inside)
                            {
                                anchor = p;
                                moved = true;
                                break;
                            }
                        }
                        if (!moved && !aside)
                        {
                            aside = true;
                            away = {-static_cast<float>(n.x), static_cast<float>(n.y)};
                        }
                    }
                }
                if (aside)
                {
                    // The outline's farthest point from the face, along the way out.
                    ScreenPoint far = middle;
                    float reach = 0.0f;
                    for (const ScreenPoint& q : outline)
                    {
                        const float along = (q.x - middle.x) * away.x + (q.y - middle.y) * away.y;
                        if (along > reach)
                        {
                            reach = along;
                        }
                    }
                    far = {middle.x + reach * away.x, middle.y + reach * away.y};
                    m_labels.PlaceOutside(OutlineOf(1 - s), far, body.name, TextStyle::Heading, InkOf(s), away.x,
                                         away.y, 6.0f, LabelRank::Name);
                    continue;
                }
                // The MTV's arrow (or the pitfall's push) starts at the middle of the body it moves, and a velocity
                // at the middle of its body: the name goes just behind the arrow's tail or beside its shaft, where it still fits, rather
                // than hang on a leader line that ends on that tail and reads as naming the arrow (l17_corner's
                // ball, led to where its velocity starts).
                std::optional<std::pair<ScreenPoint, ScreenPoint>> tailed;
                if (m_hasMtvArrow && std::hypot(m_mtvFrom.x - anchor.x, m_mtvFrom.y - anchor.y) < 16.0f)
                {
                    tailed = std::pair{m_mtvFrom, m_mtvTo};
                }
                else if (m_hasPitfallArrow && std::hypot(m_pitfallFrom.x - anchor.x, m_pitfallFrom.y - anchor.y) < 16.0f)
                {
                    tailed = std::pair{m_pitfallFrom, m_pitfallTo};
                }
                for (const std::pair<ScreenPoint, ScreenPoint>& shaft : m_velocityShafts)
                {
                    if (!tailed && std::hypot(shaft.first.x - anchor.x, shaft.first.y - anchor.y) < 16.0f)
                    {
                        tailed = shaft;
                    }
                }
                if (tailed)
                {
                    const auto [tailFrom, tailTo] = *tailed;
                    const float length = std::hypot(tailFrom.x - tailTo.x, tailFrom.y - tailTo.y);
                    const ScreenPoint back{length > 0.0f ? (tailFrom.x - tailTo.x) / length : 0.0f,
                                           length > 0.0f ? (tailFrom.y - tailTo.y) / length : 1.0f};
                    const ScreenPoint shaftMiddle{0.5f * (tailFrom.x + tailTo.x), 0.5f * (tailFrom.y + tailTo.y)};
                    const float hx = 0.5f * text.x + 4.0f;
                    const float hy = 0.5f * text.y + 2.0f;
                    bool moved = false;
                    for (const auto& [origin, way] :
                         {std::pair{tailFrom, back}, std::pair{shaftMiddle, ScreenPoint{-back.y, back.x}},
                          std::pair{shaftMiddle, ScreenPoint{back.y, -back.x}}})
                    {
                        const float shift = std::abs(way.x) * hx + std::abs(way.y) * hy + 4.0f;
                        const ScreenPoint p{origin.x + shift * way.x, origin.y + shift * way.y};
                        const bool inside = BoxCovered(p, hx, hy, outline);
                        if (inside)
                        {
                            anchor = p;
                            moved = true;
                            break;
                        }
                    }
                    // A body too small to hold it there has a leader line to it start behind the tail, inside, not
                    // by a corner, where the leader would name the corner (pitfall_one_shape's diamond).
                    const auto byCorner = [&](ScreenPoint q) {
                        if (body.shape.type != ShapeType::Polygon)
                        {
                            return false;
                        }
                        for (const Vec2& v : body.shape.polygon.Vertices())
                        {
                            const ScreenPoint corner = At(TransformPoint(body.Xf(), v));
                            if (std::hypot(corner.x - q.x, corner.y - q.y) < 16.0f)
                            {
                                return true;
                            }
                        }
                        return false;
                    };
                    for (float d = 12.0f; !moved && d < 0.5f * std::max(wide, tall); d += 2.0f)
                    {
                        const ScreenPoint q{tailFrom.x + d * back.x, tailFrom.y + d * back.y};
                        if (!Covered(q, outline, -3.0f) || byCorner(q))
                        {
                            break;
                        }
                        anchor = q;
                    }
                }
                // A leader line to the name would start on an arrow's shaft there (a face's normal across a small
                // triangle's middle) and read as naming the arrow: it starts from a point of the body clear of them.
                if (m_labels.OnShaft(anchor, 8.0f))
                {
                    for (const auto& [fx, fy] : {std::pair{0.0f, -0.2f}, std::pair{0.0f, 0.2f}, std::pair{-0.2f, 0.0f},
                                                 std::pair{0.2f, 0.0f}})
                    {
                        const ScreenPoint p{anchor.x + fx * wide, anchor.y + fy * tall};
                        if (Covered(p, outline, -3.0f) && !m_labels.OnShaft(p, 8.0f))
                        {
                            anchor = p;
                            break;
                        }
                    }
                }
                m_labels.Place(anchor, body.name, TextStyle::Heading, InkOf(s), 0.0f, 1.0f, -7.0f, LabelRank::Name);
                // A large body's name may move within it when its middle is taken (by a pitfall's note, a line
                // across it), rather than hang on a leader line.
                std::vector<ScreenPoint> within;
                const float hx = 0.5f * text.x + 4.0f;
                const float hy = 0.5f * text.y + 2.0f;
                for (const auto& [fx, fy] : {std::pair{0.0f, 0.25f}, std::pair{0.0f, -0.25f}, std::pair{-0.25f, 0.0f},
                                             std::pair{0.25f, 0.0f}, std::pair{-0.25f, 0.25f}, std::pair{0.25f, 0.25f},
                                             std::pair{-0.25f, -0.25f}, std::pair{0.25f, -0.25f}})
                {
                    const ScreenPoint p{middle.x + fx * wide, middle.y + fy * tall};
                    const bool inside = BoxCovered(p, hx, hy, outline);
                    if (inside)
                    {
                        within.push_back(p);
                    }
                }
                m_labels.AlsoAt(within);
            }
            else
            {
                // A name beside its shape goes to the right of a thin one and below a flat one, unless a face the
                // sentences name looks that way: then it goes out on the opposite side, leaving that face's outside
                // to the face's name (pitfall_tunnel's bullet, some 20 pixels wide, with its e0 below it).
                ScreenPoint way = wide < text.x + 8.0f && tall >= 2.0f * text.y ? ScreenPoint{1.0f, 0.0f}
                                                                               : ScreenPoint{0.0f, 1.0f};
                ScreenPoint from = way.x > 0.0f ? At({right.x, center.y}) : At({center.x, low.y});
                if (body.shape.type == ShapeType::Polygon)
                {
                    for (const int i : NamedIn(sentence, s, "edge", "edges"))
                    {
                        const Vec2 n = Rotate(body.Xf().q, body.shape.polygon.Normal(i));
                        const ScreenPoint out{static_cast<float>(n.x), -static_cast<float>(n.y)};
                        if (out.x * way.x + out.y * way.y > 0.5f)
                        {
                            way = {-out.x, -out.y};
                            float reach = 0.0f;
                            for (const ScreenPoint& q : outline)
                            {
                                reach = std::max(reach, (q.x - middle.x) * way.x + (q.y - middle.y) * way.y);
                            }
                            from = {middle.x + reach * way.x, middle.y + reach * way.y};
                            break;
                        }
                    }
                }
                // A body that runs off the picture is named beside the part in sight (a tall wall whose middle lies
                // below the image), not on a leader line to a middle no one sees.
                if (way.x != 0.0f && (from.y < m_bounds.minY || from.y > m_bounds.maxY))
                {
                    const float top = std::max(At(high).y, m_bounds.minY);
                    const float bottom = std::min(At(low).y, m_bounds.maxY);
                    from.y = 0.5f * (top + bottom);
                }
                else if (way.y != 0.0f && (from.x < m_bounds.minX || from.x > m_bounds.maxX))
                {
                    const float leftmost = std::max(At(left).x, m_bounds.minX);
                    const float rightmost = std::min(At(right).x, m_bounds.maxX);
                    from.x = 0.5f * (leftmost + rightmost);
                }
                // Nor where an arrow leaves the body: a leader line ending there reads as naming the arrow
                // (pitfall_tunnel's bullet, its velocity leaving it at the middle of the side the name goes to).
                // The anchor slides along that side, a quarter of the body's size up or down, clear of the shafts.
                const auto onShaft = [&](ScreenPoint p) {
                    const bool mtv = m_hasMtvArrow && DistanceToSegment(p, m_mtvFrom, m_mtvTo) < 6.0f;
                    return mtv || std::any_of(m_velocityShafts.begin(), m_velocityShafts.end(),
                                              [&](const std::pair<ScreenPoint, ScreenPoint>& shaft) {
                                                  return DistanceToSegment(p, shaft.first, shaft.second) < 6.0f;
                                              });
                };
                if (onShaft(from))
                {
                    for (const float f : {-0.25f, 0.25f})
                    {
                        const ScreenPoint p = way.x != 0.0f ? ScreenPoint{from.x, from.y + f * tall}
                                                            : ScreenPoint{from.x + f * wide, from.y};
                        if (!onShaft(p))
                        {
                            from = p;
                            break;
                        }
                    }
                }
                m_labels.PlaceOutside(OutlineOf(1 - s), from, body.name, TextStyle::Heading, InkOf(s), way.x, way.y,
                                     6.0f, LabelRank::Name);
            }
        }
    }

    // The number line: both intervals (and for sweeps B's swept extent and a time bar), with their values.
    void Panel()
    {
        m_canvas.BeginGroup("panel");
        const float top = m_layout.panelTop;
        m_canvas.FillRect({0.0f, top}, {Width(), m_layout.worldTop}, palette::kPanel);
        m_canvas.Segment({0.0f, top}, {Width(), top}, palette::kFaint, 1.0f);
        if (!m_hasAxis)
        {
            return;
        }
        const float left = 24.0f;
        const float nameWidth = std::max(m_canvas.MeasureText(m_bodyA.name, TextStyle::Heading).x,
                                         m_canvas.MeasureText(m_bodyB.name, TextStyle::Heading).x) +
                                14.0f;
        const float lineLeft = left + nameWidth;
        const float lineRight = Width() - 28.0f;
        const std::string name = std::string(m_verdict ? "deciding " : "") +
                                 (m_axis.textbook ? "axis " : "face test ") + std::to_string(m_axis.index + 1);
        const std::string axis = DescribeAxis(m_scene, m_study, m_axis.Ref());
        const std::string note = !m_axis.decided  ? ""
                                 : m_axis.bounded ? " (not walked to: numbers for this view only)"
                                                  : " (not evaluated: numbers for this view only)";
        const std::string shortNote = !m_axis.decided ? "" : " (numbers for this view only)";
        // One line, high enough to keep clear of the end values above A's bar: on a narrow figure (the app's
        // smallest canvas) the words that the sentence and the picture also give go first, rather than the line
        // being cut at the figure's edge.
        const std::string titles[] = {name + ": projections on " + axis + (m_axis.decided ? note : " (number line)"),
                                      name + ": projections on " + axis + note,
                                      name + ": " + axis + shortNote,
                                      name + shortNote,
                                      name};
        std::string title = titles[4];
        for (const std::string& t : titles)
        {
            if (m_canvas.MeasureText(t, TextStyle::Label).x <= Width() - left - 8.0f)
            {
                title = t;
                break;
            }
        }
        m_canvas.Text({left, top + 4.0f}, title, TextStyle::Label, palette::kMuted);
        if (m_axis.skipped)
        {
            // Wrapped to the figure (the rows it stands for are empty): the app's smallest canvas is narrower.
            const std::vector<std::string> lines =
                WrapLines("skipped: anti-parallel to a face already tested (the same axis)", Width() - left - 8.0f,
                          [&](const std::string& t) { return m_canvas.MeasureText(t, TextStyle::Body).x; });
            float y = top + 36.0f;
            for (const std::string& line : lines)
            {
                m_canvas.Text({left, y}, line, TextStyle::Body, palette::kMuted);
                y += m_canvas.MeasureText(line, TextStyle::Body).y + 3.0f;
            }
            return;
        }
        double lo = std::min(m_axis.minA, m_axis.minB);
        double hi = std::max(m_axis.maxA, m_axis.maxB);
        WidenBySweepAndBound(lo, hi);
        const double pad = 0.06 * std::max(hi - lo, 1e-12);
        lo -= pad;
        hi += pad;
        auto x = [&](double v) { return static_cast<float>(lineLeft + (v - lo) / (hi - lo) * (lineRight - lineLeft)); };
        const float rowA = top + 42.0f;
        const float rowB = top + 78.0f;
        m_canvas.Text({left, rowA - 9.0f}, m_bodyA.name, TextStyle::Heading, palette::kShapeA);
        m_canvas.Text({left, rowB - 9.0f}, m_bodyB.name, TextStyle::Heading, palette::kShapeBInk);

        // Overlap or gap band behind the bars.
        const bool overlap = m_axis.separation <= 0.0;
        const float bandLo = x(std::min(m_axis.leadMax, m_axis.otherMin));
        const float bandHi = std::max(x(std::max(m_axis.leadMax, m_axis.otherMin)), bandLo + 1.0f);
        // Between the rows of end values (A's above its bar, B's under its own), which would run into it.
        m_canvas.FillRect({bandLo, rowA - 9.0f}, {bandHi, rowB + 9.0f},
                         WithAlpha(overlap ? palette::kOverlap : palette::kGap, 0.28f));
        const std::string amount = BandLabel(m_axis);
        const ScreenPoint amountSize = m_canvas.MeasureText(amount, TextStyle::Label);
        const float amountX =
            std::clamp(0.5f * (bandLo + bandHi) - 0.5f * amountSize.x, lineLeft, lineRight - amountSize.x);
        m_canvas.Text({amountX, 0.5f * (rowA + rowB) - 7.0f}, amount, TextStyle::Label,
                     overlap ? 0x8E3F6CFFu : 0x006E50FFu);

        if (m_axis.swept)
        {
            m_canvas.Segment({x(m_axis.sweptMinB), rowB}, {x(m_axis.sweptMaxB), rowB}, WithAlpha(palette::kShapeB, 0.35f),
                            12.0f);
        }
        // The four ends are read together, so they are written with as many decimals each.
        const std::vector<std::string> ends = FormatAlike({m_axis.minA, m_axis.maxA, m_axis.minB, m_axis.maxB});
        IntervalRow(x(m_axis.minA), x(m_axis.maxA), rowA, ends[0], ends[1], palette::kShapeA, palette::kShapeA, true,
                    lineLeft - 8.0f);
        IntervalRow(x(m_axis.minB), x(m_axis.maxB), rowB, ends[2], ends[3], palette::kShapeB, palette::kShapeBInk, false,
                    lineLeft - 8.0f);
        if (m_axis.bounded)
        {
            // The bound: a vertex of the other shape lies here, so the other shape's near end is no farther out.
            // Its label goes under B's row, beside the tick on the side clear of B's end values.
            const float bx = x(m_axis.boundAt);
            DashedSegment(m_canvas, {bx, rowA - 14.0f}, {bx, rowB + 14.0f}, palette::kInk, 1.5f, m_bounds, 4.0f, 3.0f);
            const std::string text = "bound " + FormatNumber(m_axis.boundAt);
            const float width = m_canvas.MeasureText(text, TextStyle::Label).x;
            const float lowEnd = x(m_axis.minB) - 4.5f;
            const float lowStart = lowEnd - m_canvas.MeasureText(ends[2], TextStyle::Label).x;
            const float highStart = x(m_axis.maxB) + 4.5f;
            const float highEnd = highStart + m_canvas.MeasureText(ends[3], TextStyle::Label).x;
            const auto clear = [&](float from) {
                return (from + width < lowStart || from > lowEnd) && (from + width < highStart || from > highEnd);
            };
            const float tx = clear(bx + 4.0f) ? bx + 4.0f : clear(bx - 4.0f - width) ? bx - 4.0f - width : bx + 4.0f;
            m_canvas.Text({std::clamp(tx, lineLeft, lineRight - width), rowB + 16.0f}, text, TextStyle::Label,
                         palette::kInk);
        }
        if (m_axis.swept)
        {
            TimeBar(top + 128.0f, lineLeft, lineRight);
        }
    }

    void IntervalRow(float x0, float x1, float y, const std::string& s0, const std::string& s1, Color color, Color ink,
                     bool above, float rowStart)
    {
        m_canvas.Segment({x0, y}, {x1, y}, color, 8.0f);
        m_canvas.Segment({x0, y - 7.0f}, {x0, y + 7.0f}, ink, 1.5f);
        m_canvas.Segment({x1, y - 7.0f}, {x1, y + 7.0f}, ink, 1.5f);
        const ScreenPoint size0 = m_canvas.MeasureText(s0, TextStyle::Label);
        const float ty = above ? y - 9.0f - size0.y : y + 9.0f;
        if (s0 == s1)
        {
            // Ends that print alike (a point, or an interval narrower than the printed digits): one value, over
            // the bar, rather than the same number twice side by side.
            m_canvas.Text({0.5f * (x0 + x1) - 0.5f * size0.x, ty}, s0, TextStyle::Label, ink);
            return;
        }
        // End values sit over their ticks, as on a ruler, so that read from left to right they come in the order of
        // the ends, however close the other interval's ends are (outside the bar ends, A's low value and B's high
        // one across a narrow gap swapped places); two spaces apart at least, so that they never read as one: a
        // short bar's values move apart, each outward. A long number (a pair far from the origin) slides in along
        // its row rather than reach the image's edge or the body's name at the row's start. A short bar near the
        // row's start (a thin wall's interval on a narrow canvas) pushes the low value onto the high one: the high
        // one then moves on to keep them apart.
        const float size1 = m_canvas.MeasureText(s1, TextStyle::Label).x;
        constexpr float kApart = 10.0f;
        float c0 = x0 - 0.5f * size0.x;
        float c1 = x1 - 0.5f * size1;
        const float crowding = c0 + size0.x + kApart - c1;
        if (crowding > 0.0f)
        {
            c0 -= 0.5f * crowding;
            c1 += 0.5f * crowding;
        }
        float t0 = std::max(c0, rowStart);
        float t1 = std::min(c1, Width() - 8.0f - size1);
        if (t0 + size0.x + kApart > t1)
        {
            t1 = std::min(t0 + size0.x + kApart, Width() - 8.0f - size1);
            t0 = std::min(t0, t1 - kApart - size0.x);
        }
        m_canvas.Text({t0, ty}, s0, TextStyle::Label, ink);
        m_canvas.Text({t1, ty}, s1, TextStyle::Label, ink);
    }

    // t from 0 to 1: this axis's entry and exit, and the window (latest entry, earliest exit) so far.
    // [lo, hi] on the axis grown to hold what the axis draws besides the intervals: the interval B sweeps, and the
    // vertex that bounds a decided face's gap. The axis line and the number line both span it.
    void WidenBySweepAndBound(double& lo, double& hi) const
    {
        if (m_axis.swept)
        {
            lo = std::min(lo, m_axis.sweptMinB);
            hi = std::max(hi, m_axis.sweptMaxB);
        }
        if (m_axis.bounded)
        {
            lo = std::min(lo, m_axis.boundAt);
            hi = std::max(hi, m_axis.boundAt);
        }
    }

    // What the time bar shows of the common window of all axes so far: a band where it is open within the step,
    // one where it never opens (some axis parts before another meets), or neither.
    enum class WindowShown
    {
        None,
        Open,
        Never,
    };
    WindowShown CommonWindow() const
    {
        const double w0 = std::max(m_axis.windowEntry, 0.0);
        const double w1 = std::min(m_axis.windowExit, 1.0);
        if (w0 <= w1 && m_axis.windowEntry <= 1.0)
        {
            return WindowShown::Open;
        }
        if (m_axis.windowExit < m_axis.windowEntry && m_axis.windowExit <= 1.0)
        {
            return WindowShown::Never;
        }
        return WindowShown::None;
    }

    void TimeBar(float y, float barLeft, float right)
    {
        m_canvas.BeginGroup("timebar");
        m_canvas.Text({24.0f, y - 8.0f}, "time", TextStyle::Heading, palette::kMuted);
        // Rows under the bar: the tick labels (y + 10), the marker labels (y + 25, a gap of 2 pixels below the
        // ticks') and a window that never opens (y + 43). The bar and its marker labels keep clear of the heading
        // (short body names leave the rows above a narrow margin), even for a time at or before 0.
        const float labelsFrom = 24.0f + m_canvas.MeasureText("time", TextStyle::Heading).x + 8.0f;
        const float left = std::max(barLeft, labelsFrom + 16.0f);
        auto x = [&](double t) { return static_cast<float>(left + std::clamp(t, -0.02, 1.02) * (right - left)); };
        m_canvas.Segment({x(0.0), y}, {x(1.0), y}, palette::kMuted, 2.0f);
        // The times the markers below will stand at: a tick's value that one would crowd (0.5 between a latest
        // entry of 0.482 and an earliest exit of 0.517) is left out, the markers' own labels giving the times.
        std::vector<double> marked;
        const SweepStatus shownStatus =
            m_study.Textbook() ? m_study.textbookSweepResult.status : m_study.sweepResult.status;
        if (m_verdict && shownStatus == SweepStatus::Hit)
        {
            marked = {m_axis.windowEntry, m_axis.windowExit,
                      m_study.Textbook() ? m_study.textbookSweepResult.toi : m_study.sweepResult.toi};
        }
        else
        {
            marked = {m_axis.entry, m_axis.exit};
        }
        for (double t : {0.0, 0.5, 1.0})
        {
            m_canvas.Segment({x(t), y - 5.0f}, {x(t), y + 5.0f}, palette::kMuted, 1.5f);
            const std::string text = t == 0.0 ? "t = 0" : (t == 1.0 ? "1" : "0.5");
            const ScreenPoint size = m_canvas.MeasureText(text, TextStyle::Label);
            const float tx = x(t) - 0.5f * size.x;
            const bool crowded = t == 0.5 && std::any_of(marked.begin(), marked.end(), [&](double m) {
                                     const float mx = x(m);
                                     return std::isfinite(m) && mx > tx - 8.0f && mx < tx + size.x + 8.0f;
                                 });
            if (!crowded)
            {
                m_canvas.Text({tx, y + 10.0f}, text, TextStyle::Label, palette::kMuted);
            }
        }
        // The common window of all axes so far: a hit needs it to be non-empty and to start within [0, 1].
        const double w0 = std::max(m_axis.windowEntry, 0.0);
        const double w1 = std::min(m_axis.windowExit, 1.0);
        if (CommonWindow() == WindowShown::Open)
        {
            m_canvas.FillRect({x(w0), y - 9.0f}, {std::max(x(w1), x(w0) + 2.0f), y + 1.0f},
                             WithAlpha(palette::kOverlap, 0.45f));
        }
        else if (CommonWindow() == WindowShown::Never)
        {
            // Some axis parts before another meets: the shapes never overlap on all axes at once.
            const float a = x(m_axis.windowExit);
            const float b = std::max(x(m_axis.windowEntry), a + 2.0f);
            m_canvas.FillRect({a, y - 3.0f}, {b, y + 3.0f}, WithAlpha(palette::kResult, 0.55f));
            const auto [entry, exit] = FormatTimes(m_axis.windowEntry, m_axis.windowExit);
            const std::string text = "no common time: exit " + exit + " < entry " + entry;
            const ScreenPoint size = m_canvas.MeasureText(text, TextStyle::Label);
            // A row of its own, under the entry and exit labels.
            m_canvas.Text({std::clamp(0.5f * (a + b) - 0.5f * size.x, left, right - size.x), y + 43.0f}, text,
                         TextStyle::Label, 0xA04000FFu);
        }
        // `shown`: t as the sentence writes it beside the other marker's time, with as many decimals (FormatTimes).
        auto marker = [&](double t, const std::string& shown, const std::string& name, bool up) {
            if (std::isinf(t) || std::isnan(t))
            {
                // A face test asks about one side of one face: an exit it never reaches is that face's alone, not
                // the pair's (bullet_wall's face test 4, where the shapes part at 0.517 by another face).
                const std::string text = std::isnan(t) ? name + ": never overlap"
                                         : t < 0.0     ? name + ": overlapping from the start"
                                         : m_study.Textbook() ? name + ": they never part"
                                                              : name + ": never, on this face";
                const ScreenPoint size = m_canvas.MeasureText(text, TextStyle::Label);
                m_canvas.Text({right - size.x, up ? y - 10.0f - size.y : y + 25.0f}, text, TextStyle::Label,
                             palette::kInk);
                return;
            }
            const bool inside = t >= -0.02 && t <= 1.02;
            const float px = x(t);
            const float dir = up ? -1.0f : 1.0f;
            const ScreenPoint tri[3] = {{px, y}, {px - 5.0f, y + dir * 9.0f}, {px + 5.0f, y + dir * 9.0f}};
            m_canvas.FillConvex(tri, 3, palette::kInk);
            std::string text = name + " " + (std::isinf(t) ? "never" : shown);
            if (!inside)
            {
                text += t < 0.0 ? " (before)" : " (after)";
            }
            const ScreenPoint size = m_canvas.MeasureText(text, TextStyle::Label);
            const float tx =
                std::clamp(px - 0.5f * size.x, std::max(left - 40.0f, labelsFrom), Width() - size.x - 4.0f);
            m_canvas.Text({tx, up ? y - 10.0f - size.y : y + 25.0f}, text, TextStyle::Label, palette::kInk);
        };
        const SweepStatus status = m_study.Textbook() ? m_study.textbookSweepResult.status : m_study.sweepResult.status;
        if (m_verdict && status == SweepStatus::Hit)
        {
            const float px = x(m_study.Textbook() ? m_study.textbookSweepResult.toi : m_study.sweepResult.toi);
            // Short enough to keep clear of the entry label above and the tick labels below; under the latest
            // entry's triangle, at the same time, which it would hide.
            m_canvas.Segment({px, y - 9.0f}, {px, y + 8.0f}, palette::kResult, 3.0f);
        }
        // A hit's verdict is the common window, as its sentence says: the latest entry and the earliest exit of all
        // axes (the deciding axis's own exit may come later). So is a miss's where they never meet: the band between
        // them is the miss, and the deciding axis's own entry would mark a time the verdict does not speak of.
        if (m_verdict && (status == SweepStatus::Hit || CommonWindow() == WindowShown::Never))
        {
            // A hit's latest entry is its time of first contact, written as the verdict's row, sentence and ghost
            // write it; a miss's two times are read together, as its "no common time" note gives them.
            auto [entry, exit] = FormatTimes(m_axis.windowEntry, m_axis.windowExit);
            if (status == SweepStatus::Hit)
            {
                entry = FormatNumber(m_axis.windowEntry);
                exit = FormatNumber(m_axis.windowExit);
            }
            marker(m_axis.windowEntry, entry, "latest entry", true);
            marker(m_axis.windowExit, exit, "earliest exit", false);
        }
        else
        {
            const auto [entry, exit] = FormatTimes(m_axis.entry, m_axis.exit);
            if (!std::isinf(m_axis.entry) || m_axis.separation > 0.0 || m_axis.never)
            {
                marker(m_axis.entry, entry, "entry", true);
            }
            const bool noCommonTime = !(w0 <= w1 && m_axis.windowEntry <= 1.0) && m_axis.windowExit < m_axis.windowEntry &&
                                      m_axis.windowExit <= 1.0;
            if (!(noCommonTime && std::isinf(m_axis.exit)) && !m_axis.never)
            {
                marker(m_axis.exit, exit, "exit", false);
            }
        }
    }

    // The band's lines, wrapped by WrapLines as every text of the figures and the app is: between words only, so
    // that a bracketed pair such as "(0.96, 0.30)" or a number and its unit ("0.417 s)") is never split across lines.
    std::vector<std::string> Wrap(const std::string& text, TextStyle style) const
    {
        if (text.empty())
        {
            return {};
        }
        const float maxWidth = Width() - 2.0f * kPad - 4.0f;
        return WrapLines(text, maxWidth, [&](const std::string& s) { return m_canvas.MeasureText(s, style).x; });
    }

    // The caption's lines and where its band ends, worked out before the labels are placed so that none goes under
    // a band that grows.
    struct CaptionLines
    {
        std::vector<std::pair<std::string, TextStyle>> rows; // the scene's own title
        std::vector<std::string> lines;                      // the step's explanation
        TextStyle style = TextStyle::Body;
        float height = kLineHeight;
        float bottom = 0.0f;
    };

    CaptionLines LayOutCaption() const
    {
        CaptionLines c;
        // The verdict counts the contact points only where the figure draws them.
        const std::string text = WorldCaption().empty()
                                     ? DescribeStep(m_scene, m_study, m_figure.step, Has(m_figure, kLayerContacts))
                                     : WorldCaption();
        const float y = kPad - 2.0f;
        const float room = m_layout.sceneTop - 6.0f;
        float used = 0.0f;
        if (!m_figure.caption.empty())
        {
            for (const std::string& l : Wrap(m_figure.caption, TextStyle::Heading))
            {
                c.rows.push_back({l, TextStyle::Heading});
                used += kLineHeight;
            }
        }
        auto fits = [&](const std::vector<std::string>& lines, float height) {
            return y + used + height * static_cast<float>(lines.size()) <= room + 1.0f;
        };
        c.lines = Wrap(text, c.style);
        if (!fits(c.lines, c.height))
        {
            c.style = TextStyle::Label;
            c.height = kLabelLineHeight;
            c.lines = Wrap(text, c.style);
        }
        if (!fits(c.lines, c.height) && m_view.width < kSmallFigure)
        {
            c.lines = Wrap(StepTitle(m_scene, m_study, m_figure.step), c.style);
        }
        c.bottom = std::max(m_layout.sceneTop, y + used + c.height * static_cast<float>(c.lines.size()) + 6.0f);
        return c;
    }

    // A figure of the world's layers is about the world's last step, not about a SAT test of the pair as the step
    // left it (which can say "no hit" of a pair the step has just bounced): its explanation is the step's own.
    // Empty when no world layer is drawn.
    std::string WorldCaption() const
    {
        const LayerMask world = kLayerBroadphase | kLayerResponse | kLayerHits | kLayerPlots;
        if (m_figure.sim == nullptr || (m_figure.layers & world) == 0)
        {
            return "";
        }
        const std::string step = std::to_string(m_figure.sim->steps);
        if (Has(m_figure, kLayerResponse))
        {
            return "The panel below follows the solver's response to " + m_bodyA.name + " and " + m_bodyB.name +
                   " in step " + step + ", one stage a line, each from the numbers before it.";
        }
        // The first stage says whether the pair had a contact in the step, and of which kind.
        const std::vector<ResponseStep> response = DescribeResponse(m_scene, *m_figure.sim);
        return response.empty() ? "Step " + step + " of the world." : response.front().sentence;
    }

    // The step's explanation under the scene's own title (its caption), in the band the layout reserves: at body
    // size, else at label size (the band grows over the scene's top when even that does not fit), and in small
    // figures, where it does not fit, the step's short title, so that the scene stays in view.
    void Caption()
    {
        m_canvas.BeginGroup("caption");
        const CaptionLines& c = m_caption;
        m_canvas.FillRect({0.0f, 0.0f}, {Width(), c.bottom}, palette::kPanel);
        m_canvas.Segment({0.0f, c.bottom}, {Width(), c.bottom}, palette::kFaint, 1.0f);
        float y = kPad - 2.0f;
        for (const auto& [l, rowStyle] : c.rows)
        {
            m_canvas.Text({kPad, y}, l, rowStyle, palette::kInk);
            y += kLineHeight;
        }
        for (const std::string& l : c.lines)
        {
            m_canvas.Text({kPad, y}, l, c.style, palette::kInk);
            y += c.height;
        }
    }

    LabelPlacer m_labels;
    LineWatch m_watch; // everything is drawn through it, so that the labels keep off every line drawn before them
    Canvas& m_canvas;
    const Scene& m_scene;
    const PairStudy& m_study;
    const Figure& m_figure;
    const ScreenPoint* m_keyAt = nullptr; // where the key goes, when the figure placed it
    const View& m_view;
    FigureLayout m_layout;
    const Body& m_bodyA;
    const Body& m_bodyB;
    ScreenRect m_bounds{};
    std::vector<std::pair<Vec2, double>> m_points;
    Vec2 m_discCenter{};
    double m_discRadius = 1.0;
    bool m_verdict = false;
    int m_axisIndex = -1;
    bool m_hasAxis = false;
    ShownAxis m_axis{};
    bool m_hasMtvArrow = false;
    bool m_nameOnGhost[2] = {false, false}; // a body out of the picture, named on its ghost
    std::vector<std::pair<ScreenPoint, ScreenPoint>> m_velocityShafts; // the velocity arrows drawn, tail to head
    // The tested faces' normals drawn, each its tail and its unit direction on screen.
    std::vector<std::pair<ScreenPoint, ScreenPoint>> m_faceNormals;
    std::vector<ScreenPoint> m_contactDots;                            // the contact points drawn
    ScreenPoint m_mtvFrom{};
    ScreenPoint m_mtvTo{};
    CaptionLines m_caption;
    std::vector<LegendMark> m_used; // marks drawn that only their drawing knows of
    bool m_hasPitfallArrow = false;
    std::vector<ScreenRect> m_heads; // the arrow heads drawn so far, which no later arrow may cover
    std::vector<std::vector<ScreenPoint>> m_ghostOutlines; // the ghosts drawn, moving bodies at other times
    struct Bar
    {
        ScreenPoint a, b;
        float thickness;
    };
    std::vector<Bar> m_bars; // the axis line's bars, which would hide an arrow head of like colour drawn on them
    ScreenPoint m_pitfallFrom{};
    ScreenPoint m_pitfallTo{};
};

} // namespace

FigureLayout LayoutFigure(const PairStudy& study, LayerMask layers, int width, int height, bool titled)
{
    FigureLayout layout;
    const float h = static_cast<float>(height);
    // Small figures reserve label-size lines; a scene's own caption takes one more line, as a title.
    const float line = width < kSmallFigure ? kLabelLineHeight : kLineHeight;
    layout.sceneTop =
        (layers & kLayerCaption) ? kPad + line * kCaptionLines + (titled ? kLineHeight : 0.0f) + 6.0f : 0.0f;
    // A small figure has no room for the number line under the scene: the axis line in the scene shows the
    // intervals alone.
    const bool panel = height >= kSmallPanelHeight && study.AxisCount() > 0 &&
                       ((layers & kLayerProjection) || (study.sweep && (layers & kLayerSwept)));
    const float panelHeight = panel ? (study.sweep ? kSweepPanel : kStaticPanel) : 0.0f;
    // Small images keep at least half their height for the scene.
    layout.worldTop = h - WorldPanelsHeight(layers);
    layout.panelTop =
        panel ? std::max(layout.worldTop - panelHeight, layout.sceneTop + 0.5f * (layout.worldTop - layout.sceneTop))
              : layout.worldTop;
    layout.sceneBottom = layout.panelTop;
    return layout;
}

View FitFigure(const Scene& scene, const PairStudy& study, LayerMask layers, int width, int height)
{
    const std::vector<std::pair<Vec2, double>> points = PairPoints(scene, study);
    const FigureLayout layout = LayoutFigure(study, layers, width, height, !scene.view.caption.empty());
    // B moved out by the minimum translation vector.
    std::vector<std::pair<Vec2, double>> moved;
    if ((layers & kLayerMtv) && !study.sweep && study.manifold.overlap)
    {
        Body shifted = scene.bodies[static_cast<size_t>(study.bodyB)];
        shifted.position = shifted.position + study.manifold.depth * study.manifold.normal;
        const Transform xf = shifted.Xf();
        if (shifted.shape.type == ShapeType::Polygon)
        {
            for (const Vec2& v : shifted.shape.polygon.Vertices())
            {
                moved.push_back({TransformPoint(xf, v), 0.0});
            }
        }
        else
        {
            moved.push_back({TransformPoint(xf, shifted.shape.circle.center), shifted.shape.circle.radius});
        }
    }
    // Every axis line the steps draw, so that the camera frames them all and stays put while stepping.
    std::vector<Vec2> directions;
    std::vector<std::pair<double, double>> spans;
    if (layers & kLayerProjection)
    {
        // Each axis line costs a pass over the pair's points: a large polygon's many axes are sampled evenly
        // (neighbouring faces' lines lie close together), which keeps the fit linear in the vertex count.
        const int count = study.AxisCount();
        const int stride = std::max(1, count / kFitAxes);
        for (int i = 0; i < count; i += (i + stride < count || i + 1 == count) ? stride : count - 1 - i)
        {
            ShownAxis axis = ShowAxis(study, i);
            if (axis.skipped)
            {
                continue;
            }
            double lo = 0.0;
            double hi = 0.0;
            AxisLineSpan(axis.minA, axis.maxA, axis.minB, axis.maxB, lo, hi);
            if (axis.swept)
            {
                lo = std::min(lo, axis.sweptMinB);
                hi = std::max(hi, axis.sweptMaxB);
            }
            directions.push_back(axis.direction);
            spans.push_back({lo, hi});
        }
    }
    // The Minkowski inset takes the scene's top right corner: the pair keeps to the left of it.
    const float inset = (layers & kLayerMinkowski)
                            ? std::min(220.0f, 0.42f * std::min(static_cast<float>(width),
                                                                  layout.sceneBottom - layout.sceneTop)) +
                                  20.0f
                            : 0.0f;
    const float areaWidth = static_cast<float>(width) - inset;
    const float areaHeight = layout.sceneBottom - layout.sceneTop;
    View view;
    view.width = width;
    view.height = height;
    view.zoom = 1.0;
    // The line gap and padding are in pixels, so the box depends on the zoom: two refinements settle it.
    for (int pass = 0; pass < 3; ++pass)
    {
        Vec2 low{INFINITY, INFINITY};
        Vec2 high{-INFINITY, -INFINITY};
        auto add = [&](Vec2 p, double r) {
            low = {std::min(low.x, p.x - r), std::min(low.y, p.y - r)};
            high = {std::max(high.x, p.x + r), std::max(high.y, p.y + r)};
        };
        for (const auto& [p, r] : points)
        {
            add(p, r);
        }
        for (const auto& [p, r] : moved)
        {
            add(p, r);
        }
        if (pass > 0)
        {
            const double pad = (kLinePad + 12.0) / view.zoom;
            for (size_t i = 0; i < directions.size(); ++i)
            {
                const Vec2 d = directions[i];
                const Vec2 base = AxisLineBase(points, d, kAxisGap / view.zoom);
                add(base + (spans[i].first - pad) * d, 6.0 / view.zoom);
                add(base + (spans[i].second + pad) * d, 6.0 / view.zoom);
            }
        }
        const double sizeX = std::max(high.x - low.x, 1e-12);
        const double sizeY = std::max(high.y - low.y, 1e-12);
        view.zoom = std::min((areaWidth - 2.0 * kFitSide) / sizeX, (areaHeight - 2.0 * kFitMargin) / sizeY);
        view.zoom = std::max(view.zoom, 1e-9);
        const Vec2 middle = 0.5 * (low + high);
        const double offsetY = 0.5 * (layout.sceneTop + layout.sceneBottom) - 0.5 * height;
        view.center = {middle.x + 0.5 * inset / view.zoom, middle.y + offsetY / view.zoom};
    }
    return view;
}

View Reframe(const SceneView& frame, const PairStudy& study, LayerMask layers, bool titled, int width, int height)
{
    if (width == frame.width && height == frame.height)
    {
        // The frame itself, not the same up to rounding: a figure at its scene's size is drawn as framed.
        View same;
        same.center = frame.center;
        same.zoom = frame.zoom;
        same.width = width;
        same.height = height;
        return same;
    }
    const FigureLayout from = LayoutFigure(study, layers, frame.width, frame.height, titled);
    const FigureLayout to = LayoutFigure(study, layers, width, height, titled);
    const double fromHeight = std::max(1.0, static_cast<double>(from.sceneBottom - from.sceneTop));
    const double toHeight = std::max(1.0, static_cast<double>(to.sceneBottom - to.sceneTop));
    View view;
    view.width = width;
    view.height = height;
    view.zoom = frame.zoom * std::min(static_cast<double>(width) / frame.width, toHeight / fromHeight);
    // The world point at the middle of the scene area stays at its middle.
    const double middle = frame.center.y - (0.5 * (from.sceneTop + from.sceneBottom) - 0.5 * frame.height) / frame.zoom;
    view.center = {frame.center.x, middle + (0.5 * (to.sceneTop + to.sceneBottom) - 0.5 * height) / view.zoom};
    return view;
}

void PaintFigure(Canvas& canvas, const Scene& scene, const PairStudy& study, const Figure& figure)
{
    if (figure.kind == FigureKind::Decomposition && figure.body >= 0 &&
        figure.body < static_cast<int>(scene.bodies.size()))
    {
        PaintDecomposition(canvas, scene, figure.body, figure);
        return;
    }
    if (figure.kind == FigureKind::Slice && figure.body >= 0 && figure.body < static_cast<int>(scene.bodies.size()))
    {
        PaintSlice(canvas, scene, figure.body, figure);
        return;
    }
    if (figure.kind == FigureKind::Pieces && study.bodyA >= 0 && study.bodyB >= 0)
    {
        PaintPieceSteps(canvas, scene, study, figure);
        return;
    }
    if (figure.kind == FigureKind::DiscCast && study.bodyA >= 0 && study.bodyB >= 0)
    {
        PaintDiscCast(canvas, scene, study.bodyA, study.bodyB, figure);
        return;
    }
    if ((figure.layers & kLayerLegend) && (figure.layers & ~(kLayerLegend | kLayerCaption)) && figure.framesItself)
    {
        // The key must hide no body and no label: drawn once unseen, the picture shows what it covers and the key's
        // size; then the picture moves aside for the key (scaled down if need be). Lines drawn to the scene's size
        // (a separating line, a wall longer than the scene) may reach the key again: up to four more looks move the
        // picture on.
        Figure moved = figure;
        KeyPlace place;
        bool placed = false;
        for (int pass = 0; pass < 5; ++pass)
        {
            RecordingCanvas unseen;
            Painter(unseen, scene, study, moved, placed ? &place.at : nullptr).Paint();
            const std::vector<const DrawCommand*> key = unseen.InGroup("legend");
            if (key.empty() || key[0]->kind != DrawCommand::Kind::FillRect)
            {
                break;
            }
            const ScreenRect drawn{key[0]->points[0].x, key[0]->points[0].y, key[0]->points[1].x,
                                   key[0]->points[1].y};
            const FigureLayout layout = LayoutFigure(study, figure.layers, figure.view.width, figure.view.height,
                                                     !figure.caption.empty());
            // The caption's band as drawn: a long caption takes more lines than the layout reserves.
            float top = layout.sceneTop;
            for (const DrawCommand* c : unseen.InGroup("caption"))
            {
                top = std::max(top, c->kind == DrawCommand::Kind::FillRect ? c->points[1].y : top);
            }
            const ScreenRect area{0.0f, top, static_cast<float>(figure.view.width), layout.sceneBottom};
            const ScreenRect obstacles = KeyObstacles(unseen, area);
            if (placed && !drawn.Overlaps(obstacles))
            {
                break;
            }
            place = PlaceKey(area, obstacles, {drawn.maxX - drawn.minX, drawn.maxY - drawn.minY},
                             (figure.layers & kLayerMinkowski) != 0);
            moved.view = MovedAside(moved.view, place);
            placed = true;
        }
        if (placed)
        {
            Painter(canvas, scene, study, moved, &place.at).Paint();
            return;
        }
    }
    Painter painter(canvas, scene, study, figure);
    painter.Paint();
}

} // namespace satviz
