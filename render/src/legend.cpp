// SPDX-License-Identifier: MIT
#include "legend.h"

#include "concave_views.h"

#include <satviz/render/palette.h>
#include <satviz/render/wrap.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace satviz
{

namespace
{

constexpr float kPadding = 8.0f; // inside the panel
constexpr float kRow = 17.0f;    // row height: 33 rows and the padding fit a canvas 600 pixels high
constexpr float kSwatch = 28.0f; // swatch width
constexpr float kGapAfterSwatch = 8.0f;
constexpr float kLine = 15.0f; // the step to a wrapped meaning's next line

const char* Meaning(LegendMark mark)
{
    switch (mark)
    {
    case LegendMark::CandidateAxis:
        return "long grey dashes through the pair: the candidate axes";
    case LegendMark::AxisArrow:
        return "grey arrow named \"axis N\": the axis tested (only its direction matters, not where it is drawn)";
    case LegendMark::Projection:
        return "blue and orange bars, dashed lines to them: each shape's interval, its projection on the axis";
    case LegendMark::AxisFace:
        return "thick dark edge: the face whose normal is the axis";
    case LegendMark::Normal:
        return "short arrow on a face: its outward normal (black on the axis's face)";
    case LegendMark::VertexAxis:
        return "dark dot and dashed line: the axis from a vertex (or a centre) to a circle's centre";
    case LegendMark::BestAxis:
        return "light-blue edges and their arrows: the faces of the best axis so far (of equal ones, the first)";
    case LegendMark::Overlap:
        return "pink band: the intervals overlap";
    case LegendMark::Gap:
        return "green band: a gap between the intervals";
    case LegendMark::Behind:
        return "band of a face test: how far behind (or beyond) the face";
    case LegendMark::Swept:
        return "pale bar: the interval swept from t = 0 to t = 1";
    case LegendMark::TimeMarks:
        return "dark triangles on the time bar: entry and exit";
    case LegendMark::Impact:
        return "vermillion tick on the time bar: the time of first contact";
    case LegendMark::Window:
        return "pink band on the time bar: when every axis so far overlaps";
    case LegendMark::NoWindow:
        return "orange band on the time bar: no common time, the axes' windows miss";
    case LegendMark::Other:
        return "grey body: not in the tested pair (a wall, a mark)";
    case LegendMark::Centre:
        return "small dot in a circle: its centre";
    case LegendMark::Asleep:
        return "hatched body (broadphase view): asleep, neither moved nor tested until woken";
    case LegendMark::Reference:
        return "thick edge in a body's colour: the reference face";
    case LegendMark::Incident:
        return "doubled edge: the incident edge";
    case LegendMark::SidePlanes:
        return "thin grey dashes at a reference face's ends: its side planes";
    case LegendMark::Contact:
        return "vermillion dot: a contact point";
    case LegendMark::Mtv:
        return "vermillion arrow: the minimum translation vector";
    case LegendMark::Dashed:
        return "dashed outline: a body at another time, or moved by the MTV";
    case LegendMark::Separating:
        return "green dashed line: a separating line";
    case LegendMark::PitfallPush:
        return "black dashed arrow (and outline): a pitfall's wrong push (and where it leaves the body)";
    case LegendMark::Cut:
        return "vermillion line with dots: a cut, and where it crosses the outline";
    case LegendMark::FocusPiece:
        return "darker piece: the piece of the pair at hand (at the verdict, the one that decides)";
    case LegendMark::PieceFills:
        return "sky-blue, orange, green, yellow fills: each part of a cut, or each convex piece";
    case LegendMark::Reflex:
        return "vermillion ring round a corner: a reflex vertex (its inside angle over 180 degrees)";
    case LegendMark::Seam:
        return "thin dashed line inside a body: a seam between two of its convex pieces";
    case LegendMark::PieceBox:
        return "grey dashed rectangle: a piece's box, which the broadphase compares";
    case LegendMark::SeamPush:
        return "grey arrow: a push through a seam, into the body's next piece (not used)";
    }
    return "";
}

void Swatch(Canvas& canvas, LegendMark mark, float x, float y)
{
    const float x1 = x + kSwatch;
    const float cy = y + 0.5f * kRow;
    switch (mark)
    {
    case LegendMark::CandidateAxis:
        DashedSegment(canvas, {x, cy}, {x1, cy}, kCandidateAxisColor, kCandidateAxisWidth,
                      {x - 1.0f, y, x1 + 1.0f, y + kRow}, kCandidateAxisDash, kCandidateAxisGap);
        break;
    case LegendMark::AxisArrow:
        // As the projection layer draws it (kAxisArrowWidth, kAxisArrowHead), in the group's grey.
        Arrow(canvas, {x, cy}, {x1, cy}, palette::kMuted, kAxisArrowWidth, kAxisArrowHead);
        break;
    case LegendMark::Projection:
    {
        // As the projection layer draws them, turned as lesson 1's first figure turns them (its axis upright): a bar
        // per shape, kIntervalBar wide, and thin dashed guides from the shapes' extreme points to the bars' ends.
        const ScreenRect clip{x - 1.0f, y, x1 + 1.0f, y + kRow};
        DashedSegment(canvas, {x1, y + 2.0f}, {x + 5.0f, y + 2.0f}, WithAlpha(palette::kShapeA, 0.55f), 1.0f, clip,
                      4.0f, 4.0f);
        DashedSegment(canvas, {x1, y + kRow - 2.0f}, {x + 13.0f, y + kRow - 2.0f}, WithAlpha(palette::kShapeBInk, 0.55f),
                      1.0f, clip, 4.0f, 4.0f);
        canvas.Segment({x + 5.0f, y + 2.0f}, {x + 5.0f, y + 11.0f}, palette::kShapeA, kIntervalBar);
        canvas.Segment({x + 13.0f, y + 7.0f}, {x + 13.0f, y + kRow - 2.0f}, palette::kShapeB, kIntervalBar);
        break;
    }
    case LegendMark::AxisFace:
        canvas.Segment({x, cy}, {x1, cy}, palette::kInk, 4.0f);
        break;
    case LegendMark::Normal:
        // As the painter draws them: a short arrow in a body's colour, and a black one on the axis's face.
        Arrow(canvas, {x + 6.0f, y + kRow - 2.0f}, {x + 6.0f, y + 2.0f}, palette::kShapeA, 1.5f, 7.0f);
        Arrow(canvas, {x + 20.0f, y + kRow - 2.0f}, {x + 20.0f, y + 2.0f}, palette::kInk, 2.0f, 8.0f);
        break;
    case LegendMark::VertexAxis:
        // As the painter draws a vertex axis: a dashed line from the vertex's dot to the centre.
        DashedSegment(canvas, {x + 4.0f, cy}, {x1, cy}, palette::kInk, 2.0f, {x - 1.0f, y, x1 + 1.0f, y + kRow}, 4.0f,
                      3.0f);
        canvas.FillCircle({x + 4.0f, cy}, 4.0f, palette::kInk);
        break;
    case LegendMark::BestAxis:
        canvas.Segment({x, cy}, {x1, cy}, palette::kBest, 4.0f);
        break;
    case LegendMark::Overlap:
        canvas.FillRect({x, y + 3.0f}, {x1, y + kRow - 3.0f}, WithAlpha(palette::kOverlap, 0.45f));
        break;
    case LegendMark::Gap:
        canvas.FillRect({x, y + 3.0f}, {x1, y + kRow - 3.0f}, WithAlpha(palette::kGap, 0.45f));
        break;
    case LegendMark::Behind:
        canvas.FillRect({x, y + 3.0f}, {x + 0.5f * kSwatch, y + kRow - 3.0f}, WithAlpha(palette::kOverlap, 0.45f));
        canvas.FillRect({x + 0.5f * kSwatch, y + 3.0f}, {x1, y + kRow - 3.0f}, WithAlpha(palette::kGap, 0.45f));
        break;
    case LegendMark::Swept:
        canvas.Segment({x, cy}, {x1, cy}, WithAlpha(palette::kShapeB, 0.35f), 8.0f);
        break;
    case LegendMark::TimeMarks:
    {
        const ScreenPoint down[3] = {{x + 8.0f, cy}, {x + 3.0f, cy - 7.0f}, {x + 13.0f, cy - 7.0f}};
        const ScreenPoint up[3] = {{x + 20.0f, cy}, {x + 15.0f, cy + 7.0f}, {x + 25.0f, cy + 7.0f}};
        canvas.Segment({x, cy}, {x1, cy}, palette::kMuted, 2.0f);
        canvas.FillConvex(down, 3, palette::kInk);
        canvas.FillConvex(up, 3, palette::kInk);
        break;
    }
    case LegendMark::Impact:
        canvas.Segment({x, cy}, {x1, cy}, palette::kMuted, 2.0f);
        canvas.Segment({x + 0.5f * kSwatch, cy - 7.0f}, {x + 0.5f * kSwatch, cy + 7.0f}, palette::kResult, 3.0f);
        break;
    case LegendMark::Window:
    {
        canvas.Segment({x, cy + 4.0f}, {x1, cy + 4.0f}, palette::kMuted, 2.0f);
        canvas.FillRect({x + 6.0f, cy - 5.0f}, {x1 - 6.0f, cy + 5.0f}, WithAlpha(palette::kOverlap, 0.45f));
        break;
    }
    case LegendMark::NoWindow:
    {
        canvas.Segment({x, cy}, {x1, cy}, palette::kMuted, 2.0f);
        canvas.FillRect({x + 6.0f, cy - 3.0f}, {x1 - 6.0f, cy + 3.0f}, WithAlpha(palette::kResult, 0.55f));
        break;
    }
    case LegendMark::Other:
        canvas.FillRect({x + 2.0f, y + 3.0f}, {x1 - 2.0f, y + kRow - 3.0f}, WithAlpha(palette::kOther, 0.18f));
        {
            const ScreenPoint box[4] = {
                {x + 2.0f, y + 3.0f}, {x1 - 2.0f, y + 3.0f}, {x1 - 2.0f, y + kRow - 3.0f}, {x + 2.0f, y + kRow - 3.0f}};
            canvas.Polyline(box, 4, true, palette::kOther, 2.0f);
        }
        break;
    case LegendMark::Centre:
        canvas.Circle({x + 0.5f * kSwatch, cy}, 7.0f, palette::kShapeBInk, 1.5f);
        canvas.FillCircle({x + 0.5f * kSwatch, cy}, 2.5f, palette::kShapeBInk);
        break;
    case LegendMark::Asleep:
    {
        // A grey body hatched as the broadphase layer hatches a sleeping one: diagonal lines 7 pixels apart.
        const ScreenPoint box[4] = {
            {x + 2.0f, y + 3.0f}, {x1 - 2.0f, y + 3.0f}, {x1 - 2.0f, y + kRow - 3.0f}, {x + 2.0f, y + kRow - 3.0f}};
        canvas.FillConvex(box, 4, WithAlpha(palette::kOther, 0.18f));
        for (float c = x + 2.0f + 4.0f; c < x1 - 2.0f + (kRow - 6.0f); c += 7.0f)
        {
            // Each line runs down and to the left, clipped to the box.
            ScreenPoint a{c, y + 3.0f};
            ScreenPoint b{c - (kRow - 6.0f), y + kRow - 3.0f};
            const float over = a.x - (x1 - 2.0f);
            if (over > 0.0f)
            {
                a = {x1 - 2.0f, a.y + over};
            }
            const float under = (x + 2.0f) - b.x;
            if (under > 0.0f)
            {
                b = {x + 2.0f, b.y - under};
            }
            canvas.Segment(a, b, WithAlpha(palette::kMuted, 0.8f), 1.0f);
        }
        canvas.Polyline(box, 4, true, palette::kOther, 2.0f);
        break;
    }
    case LegendMark::Reference:
        canvas.Segment({x, cy}, {x1, cy}, palette::kShapeA, 5.0f);
        break;
    case LegendMark::Incident:
        canvas.Segment({x, cy}, {x1, cy}, palette::kShapeBInk, 5.0f);
        canvas.Segment({x, cy}, {x1, cy}, palette::kBackground, 1.5f);
        break;
    case LegendMark::SidePlanes:
        // Two short dashed lines across the ends of a reference face, as the clip draws them.
        canvas.Segment({x + 5.0f, cy + 3.0f}, {x1 - 5.0f, cy + 3.0f}, palette::kShapeA, 5.0f);
        DashedSegment(canvas, {x + 5.0f, y + 1.0f}, {x + 5.0f, y + kRow - 1.0f}, palette::kMuted, 1.2f,
                      {x - 1.0f, y, x1 + 1.0f, y + kRow}, 5.0f, 4.0f);
        DashedSegment(canvas, {x1 - 5.0f, y + 1.0f}, {x1 - 5.0f, y + kRow - 1.0f}, palette::kMuted, 1.2f,
                      {x - 1.0f, y, x1 + 1.0f, y + kRow}, 5.0f, 4.0f);
        break;
    case LegendMark::Contact:
        canvas.FillCircle({x + 0.5f * kSwatch, cy}, 5.5f, palette::kResult);
        canvas.Circle({x + 0.5f * kSwatch, cy}, 5.5f, palette::kBackground, 1.5f);
        break;
    case LegendMark::Mtv:
        Arrow(canvas, {x, cy}, {x1, cy}, palette::kResult, 3.0f, 9.0f);
        break;
    case LegendMark::Dashed:
        DashedSegment(canvas, {x, cy}, {x1, cy}, palette::kShapeBInk, 1.8f, {x - 1.0f, y, x1 + 1.0f, y + kRow}, 6.0f,
                      4.0f);
        break;
    case LegendMark::Separating:
        DashedSegment(canvas, {x, cy}, {x1, cy}, palette::kGap, 2.5f, {x - 1.0f, y, x1 + 1.0f, y + kRow}, 10.0f, 6.0f);
        break;
    case LegendMark::Cut:
        // As the slice figures draw it: the line, its ends' small dots, a larger dot where it crosses an outline.
        canvas.Segment({x + 2.0f, cy}, {x1 - 2.0f, cy}, palette::kResult, 2.0f);
        canvas.FillCircle({x + 2.0f, cy}, 3.0f, palette::kResult);
        canvas.FillCircle({x1 - 2.0f, cy}, 3.0f, palette::kResult);
        canvas.FillCircle({x + 0.5f * kSwatch, cy}, 4.5f, palette::kResult);
        break;
    case LegendMark::PitfallPush:
        // As the pitfall figures draw it: a dashed shaft with a head, in ink.
        DashedSegment(canvas, {x, cy}, {x1 - 6.0f, cy}, palette::kInk, 2.0f, {x - 1.0f, y, x1 + 1.0f, y + kRow}, 6.0f,
                      4.0f);
        Arrow(canvas, {x1 - 6.1f, cy}, {x1, cy}, palette::kInk, 2.0f, 10.0f);
        break;
    case LegendMark::Seam:
        // As the pieces figure draws a seam: a thin dashed line in the body's colour across its fill.
        canvas.FillRect({x, y + 3.0f}, {x1, y + kRow - 3.0f}, WithAlpha(palette::kShapeA, 0.3f));
        DashedSegment(canvas, {x, cy}, {x1, cy}, WithAlpha(palette::kShapeA, 0.8f), 1.2f,
                      {x - 1.0f, y, x1 + 1.0f, y + kRow}, 5.0f, 4.0f);
        break;
    case LegendMark::PieceBox:
    {
        const ScreenPoint box[4] = {
            {x + 2.0f, y + 2.0f}, {x1 - 2.0f, y + 2.0f}, {x1 - 2.0f, y + kRow - 2.0f}, {x + 2.0f, y + kRow - 2.0f}};
        DashedOutline(canvas, std::vector<ScreenPoint>(box, box + 4), kPieceBoxColor, kPieceBoxWidth,
                      {x - 1.0f, y, x1 + 1.0f, y + kRow});
        break;
    }
    case LegendMark::FocusPiece:
    {
        // As the pieces figure fills them: the piece at hand darker, beside a pale one of the same body.
        const float mid = x + 0.5f * kSwatch;
        canvas.FillRect({x, y + 3.0f}, {mid, y + kRow - 3.0f}, WithAlpha(palette::kShapeA, 0.45f));
        canvas.FillRect({mid, y + 3.0f}, {x1, y + kRow - 3.0f}, WithAlpha(palette::kShapeA, 0.08f));
        const ScreenPoint box[4] = {
            {x, y + 3.0f}, {x1, y + 3.0f}, {x1, y + kRow - 3.0f}, {x, y + kRow - 3.0f}};
        canvas.Polyline(box, 4, true, palette::kShapeA, 1.5f);
        break;
    }
    case LegendMark::PieceFills:
        // As the decomposition and slice figures fill the pieces and parts: PieceColor in turn.
        for (int i = 0; i < 4; ++i)
        {
            const float x0 = x + 0.25f * kSwatch * static_cast<float>(i);
            canvas.FillRect({x0, y + 3.0f}, {x0 + 0.25f * kSwatch, y + kRow - 3.0f}, WithAlpha(PieceColor(i), 0.45f));
        }
        break;
    case LegendMark::Reflex:
        // As the decomposition figure rings a reflex vertex.
        canvas.Circle({x + 0.5f * kSwatch, cy}, 5.0f, palette::kResult, 1.5f);
        break;
    case LegendMark::SeamPush:
        Arrow(canvas, {x, cy}, {x1, cy}, palette::kMuted, 2.0f);
        break;
    }
}

} // namespace

std::vector<LegendMark> AllLegendMarks()
{
    std::vector<LegendMark> marks;
    for (int k = static_cast<int>(LegendMark::CandidateAxis); k <= static_cast<int>(LegendMark::SeamPush); ++k)
    {
        marks.push_back(static_cast<LegendMark>(k));
    }
    return marks;
}

namespace
{

// The lines of each mark's meaning: one line each when the key fits `maxWidth`, else each meaning wrapped between
// its words so that the key does (a narrow canvas beside the lesson column).
std::vector<std::vector<std::string>> LegendLines(Canvas& canvas, const std::vector<LegendMark>& marks,
                                                  float maxWidth)
{
    const float room = maxWidth - (2.0f * kPadding + kSwatch + kGapAfterSwatch);
    const auto measure = [&](const std::string& text) { return canvas.MeasureText(text, TextStyle::Label).x; };
    std::vector<std::vector<std::string>> lines;
    for (LegendMark mark : marks)
    {
        const std::string meaning = Meaning(mark);
        if (!std::isfinite(room) || measure(meaning) <= room)
        {
            lines.push_back({meaning});
        }
        else
        {
            lines.push_back(WrapLines(meaning, std::max(room, 1.0f), measure));
        }
    }
    return lines;
}

// The height of a mark's row of `lines` lines: its swatch's row, and a line more for each wrapped line.
float RowHeight(size_t lines)
{
    return kRow + kLine * static_cast<float>(lines > 0 ? lines - 1 : 0);
}

} // namespace

ScreenPoint LegendSize(Canvas& canvas, const std::vector<LegendMark>& marks, float maxWidth)
{
    float width = 0.0f;
    float height = 0.0f;
    for (const std::vector<std::string>& row : LegendLines(canvas, marks, maxWidth))
    {
        for (const std::string& line : row)
        {
            width = std::max(width, canvas.MeasureText(line, TextStyle::Label).x);
        }
        height += RowHeight(row.size());
    }
    return {2.0f * kPadding + kSwatch + kGapAfterSwatch + width, 2.0f * kPadding + height};
}

void PaintLegend(Canvas& canvas, ScreenPoint topLeft, const std::vector<LegendMark>& marks, float maxWidth)
{
    if (marks.empty())
    {
        return;
    }
    canvas.BeginGroup("legend");
    const ScreenPoint size = LegendSize(canvas, marks, maxWidth);
    const ScreenPoint bottomRight{topLeft.x + size.x, topLeft.y + size.y};
    canvas.FillRect(topLeft, bottomRight, WithAlpha(palette::kPanel, 0.95f));
    const ScreenPoint frame[4] = {topLeft, {bottomRight.x, topLeft.y}, bottomRight, {topLeft.x, bottomRight.y}};
    canvas.Polyline(frame, 4, true, palette::kFaint, 1.0f);
    const std::vector<std::vector<std::string>> lines = LegendLines(canvas, marks, maxWidth);
    float y = topLeft.y + kPadding;
    for (size_t k = 0; k < marks.size(); ++k)
    {
        Swatch(canvas, marks[k], topLeft.x + kPadding, y);
        float textY = y + 0.5f * (kRow - TextSize(TextStyle::Label));
        for (const std::string& line : lines[k])
        {
            canvas.Text({topLeft.x + kPadding + kSwatch + kGapAfterSwatch, textY}, line, TextStyle::Label,
                        palette::kInk);
            textY += kLine;
        }
        y += RowHeight(lines[k].size());
    }
}

KeyPlace PlaceKey(const ScreenRect& scene, const ScreenRect& content, ScreenPoint size, bool skipTopRight)
{
    constexpr float m = 8.0f; // the key's margin, and the content's from the key
    const ScreenPoint corners[4] = {{scene.minX + m, scene.maxY - m - size.y},
                                    {scene.maxX - m - size.x, scene.maxY - m - size.y},
                                    {scene.minX + m, scene.minY + m},
                                    {scene.maxX - m - size.x, scene.minY + m}};
    KeyPlace best;
    best.at = corners[0];
    best.scale = -1.0;
    float bestMove = INFINITY;
    const bool empty = !(content.minX <= content.maxX && content.minY <= content.maxY) || !std::isfinite(content.minX) ||
                       !std::isfinite(content.maxX) || !std::isfinite(content.minY) || !std::isfinite(content.maxY);
    const float cw = std::max(content.maxX - content.minX, 1.0f);
    const float ch = std::max(content.maxY - content.minY, 1.0f);
    const ScreenPoint middle = empty ? ScreenPoint{0.5f * (scene.minX + scene.maxX), 0.5f * (scene.minY + scene.maxY)}
                                     : ScreenPoint{0.5f * (content.minX + content.maxX),
                                                   0.5f * (content.minY + content.maxY)};
    for (int k = 0; k < 4; ++k)
    {
        if (k == 3 && skipTopRight)
        {
            continue;
        }
        const ScreenPoint c{std::round(corners[k].x), std::round(corners[k].y)};
        const ScreenRect key{c.x, c.y, c.x + size.x, c.y + size.y};
        if (empty || !key.Overlaps(content))
        {
            KeyPlace free;
            free.at = c;
            free.from = middle;
            free.to = middle;
            return free;
        }
        const bool left = k % 2 == 0;
        const bool bottom = k < 2;
        const ScreenRect beside = left ? ScreenRect{key.maxX + m, scene.minY, scene.maxX, scene.maxY}
                                       : ScreenRect{scene.minX, scene.minY, key.minX - m, scene.maxY};
        const ScreenRect across = bottom ? ScreenRect{scene.minX, scene.minY, scene.maxX, key.minY - m}
                                         : ScreenRect{scene.minX, key.maxY + m, scene.maxX, scene.maxY};
        for (const ScreenRect& room : {beside, across})
        {
            const float rw = room.maxX - room.minX;
            const float rh = room.maxY - room.minY;
            if (rw <= 0.0f || rh <= 0.0f)
            {
                continue;
            }
            const float s = std::min({1.0f, rw / cw, rh / ch});
            const float hw = 0.5f * s * cw;
            const float hh = 0.5f * s * ch;
            const ScreenPoint to{std::clamp(middle.x, room.minX + hw, std::max(room.minX + hw, room.maxX - hw)),
                                 std::clamp(middle.y, room.minY + hh, std::max(room.minY + hh, room.maxY - hh))};
            const float move = std::fabs(to.x - middle.x) + std::fabs(to.y - middle.y);
            if (s > best.scale + 1e-3 || (s > best.scale - 1e-3 && move < bestMove))
            {
                best.at = c;
                best.scale = s;
                best.from = middle;
                best.to = to;
                bestMove = move;
            }
        }
    }
    best.scale = std::max(best.scale, 1e-3);
    return best;
}

View MovedAside(const View& view, const KeyPlace& place)
{
    View moved = view;
    moved.zoom = view.zoom * place.scale;
    const Vec2 fixed = ToWorld(view, place.from);
    moved.center = {fixed.x - (place.to.x - 0.5 * view.width) / moved.zoom,
                    fixed.y + (place.to.y - 0.5 * view.height) / moved.zoom};
    return moved;
}

ScreenRect KeyObstacles(const RecordingCanvas& canvas, const ScreenRect& scene)
{
    ScreenRect bounds{INFINITY, INFINITY, -INFINITY, -INFINITY};
    const auto add = [&](float x0, float y0, float x1, float y1) {
        x0 = std::max(x0, scene.minX);
        y0 = std::max(y0, scene.minY);
        x1 = std::min(x1, scene.maxX);
        y1 = std::min(y1, scene.maxY);
        if (x0 <= x1 && y0 <= y1)
        {
            bounds = {std::min(bounds.minX, x0), std::min(bounds.minY, y0), std::max(bounds.maxX, x1),
                      std::max(bounds.maxY, y1)};
        }
    };
    for (const DrawCommand& c : canvas.commands)
    {
        if (c.group == "background" || c.group == "legend" || c.group == "caption" || c.group == "axes" ||
            c.group == "voronoi" || c.group == "minkowski" || c.points.empty())
        {
            continue;
        }
        if (c.kind == DrawCommand::Kind::Text || c.group == "labels")
        {
            // Labels (texts, halos, leader lines) find their places again round the key, which the label placer
            // keeps free; one pinned to the image's edge (the name of a body out of sight) would otherwise hold the
            // picture back however far it moved.
            continue;
        }
        if (c.kind == DrawCommand::Kind::Circle || c.kind == DrawCommand::Kind::FillCircle)
        {
            add(c.points[0].x - c.radius, c.points[0].y - c.radius, c.points[0].x + c.radius, c.points[0].y + c.radius);
        }
        else
        {
            // A line may run on out of sight (a separating line, a long path): it counts by its ends in sight, as
            // wherever the picture moves it will cross the scene. A fill counts whole, cut at the scene's edge.
            for (const ScreenPoint& p : c.points)
            {
                const bool inside = p.x >= scene.minX && p.x <= scene.maxX && p.y >= scene.minY && p.y <= scene.maxY;
                if (inside || c.kind != DrawCommand::Kind::Segment)
                {
                    add(p.x, p.y, p.x, p.y);
                }
            }
        }
    }
    return bounds;
}

} // namespace satviz
