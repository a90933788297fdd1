// SPDX-License-Identifier: MIT
#include "label_placer.h"
#include "draw_kit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz
{

namespace
{

constexpr float kLabelSpacing = 3.0f; // pixels kept free beside a label where the room allows
constexpr float kHalo = 2.0f;         // the halo reaches this far left and right of the text
constexpr float kMargin = 2.0f;       // pixels kept between a label and the image's top and bottom edges
constexpr float kSideMargin = 4.0f;   // and its left and right edges, beyond the halo: a glyph flush with it reads cut
// What a label keeps clear around its text in any case: two labels on one line closer than two spaces read as one
// ("-3.00 -3.00", "c2 1"), and stacked labels that touch read as one block.
constexpr float kKeepX = 4.0f;
constexpr float kKeepY = 3.0f;
constexpr float kLabelApart = 8.0f;
constexpr float kOtherLabelApart = 14.0f;
constexpr float kSmallLabel = 18.0f; // a label narrower than this is a glyph or two // and two labels side by side this much more
constexpr float kNameRoom = 5.0f; // and a body's name this much more
constexpr float kNearAnchor = 24.0f; // a leader line's first pixels, beside the mark it starts from
constexpr double kPi = 3.14159265358979323846;

// Labels that are left out when no place is free: numbers of vertices and names of edges.
bool MayLeaveOut(LabelRank rank)
{
    return rank == LabelRank::Vertex || rank == LabelRank::Edge || rank == LabelRank::Named;
}

// The rectangle of a label `size` big whose point nearest the anchor lies `reach` pixels away along `angle`.
ScreenRect Around(ScreenPoint anchor, ScreenPoint size, double angle, float reach)
{
    const float ux = static_cast<float>(std::cos(angle));
    const float uy = static_cast<float>(std::sin(angle));
    const float cx = anchor.x + ux * (reach + 0.5f * size.x * std::fabs(ux));
    const float cy = anchor.y + uy * (reach + 0.5f * size.y * std::fabs(uy));
    ScreenRect rect{std::round(cx - 0.5f * size.x), std::round(cy - 0.5f * size.y), 0.0f, 0.0f};
    rect.maxX = rect.minX + size.x;
    rect.maxY = rect.minY + size.y;
    return rect;
}

// What a label covers: its text, the halo beside it and the room it keeps from other labels.
ScreenRect Footprint(const ScreenRect& text)
{
    return {text.minX - kKeepX, text.minY - kKeepY, text.maxX + kKeepX, text.maxY + kKeepY};
}

// Whether a point lies strictly inside a convex outline of either orientation.
bool InsideConvex(const std::vector<ScreenPoint>& outline, ScreenPoint p)
{
    if (outline.size() < 3)
    {
        return false;
    }
    int sign = 0;
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const ScreenPoint& a = outline[i];
        const ScreenPoint& b = outline[(i + 1) % outline.size()];
        const float cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        const int s = cross > 0.0f ? 1 : (cross < 0.0f ? -1 : 0);
        if (s == 0 || (sign != 0 && s != sign))
        {
            return false;
        }
        sign = s;
    }
    return true;
}

// How many of the four points a quarter in from the rectangle's corners lie inside the outline: two of them inside
// is a label that reads as lying in it, though its centre and its edges miss it.
int QuarterPointsInside(const std::vector<ScreenPoint>& outline, const ScreenRect& rect)
{
    const float qx = 0.25f * (rect.maxX - rect.minX);
    const float qy = 0.25f * (rect.maxY - rect.minY);
    int inside = 0;
    for (const ScreenPoint p : {ScreenPoint{rect.minX + qx, rect.minY + qy}, ScreenPoint{rect.maxX - qx, rect.minY + qy},
                                ScreenPoint{rect.minX + qx, rect.maxY - qy}, ScreenPoint{rect.maxX - qx, rect.maxY - qy}})
    {
        inside += InsideConvex(outline, p) ? 1 : 0;
    }
    return inside;
}

// Whether the segment pq runs along the segment uv: more than 16 pixels of pq lie within 4 pixels of uv, beside it.
// A line that crosses uv at a shallow angle (under about 30 degrees) runs along it for a while too; a steeper one
// crosses it.
bool RunsAlong(ScreenPoint p, ScreenPoint q, ScreenPoint u, ScreenPoint v, float within = 4.0f)
{
    const float ux = v.x - u.x;
    const float uy = v.y - u.y;
    const float length = std::hypot(ux, uy);
    const float own = std::hypot(q.x - p.x, q.y - p.y);
    if (length < 10.0f || own < 10.0f)
    {
        return false;
    }
    const int samples = static_cast<int>(own);
    int near = 0;
    for (int k = 0; k <= samples; ++k)
    {
        const float t = static_cast<float>(k) / static_cast<float>(samples);
        const float x = p.x + (q.x - p.x) * t - u.x;
        const float y = p.y + (q.y - p.y) * t - u.y;
        const float along = (x * ux + y * uy) / length;
        near += along >= 0.0f && along <= length && std::abs(x * uy - y * ux) / length < within ? 1 : 0;
    }
    return near > 16;
}

// Whether the segments pq and uv cross.
bool Cross(ScreenPoint p, ScreenPoint q, ScreenPoint u, ScreenPoint v)
{
    auto side = [](ScreenPoint a, ScreenPoint b, ScreenPoint c) {
        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    };
    return side(p, q, u) * side(p, q, v) < 0.0f && side(u, v, p) * side(u, v, q) < 0.0f;
}

// Whether a label's rectangle reads as lying in the outline: its centre inside it, one of the outline's edges
// through its text (a label astride the outline's edge reads as either body's, and its halo hides that edge), or
// two of the points a quarter in from its corners.
// A label whose anchor lies inside the outline only keeps its text off the outline's edges. One whose anchor lies
// outside also stays on the anchor's side of the outline: a label with the other body between it and its anchor
// (a ball's name beyond the wall it rests against) reads as that body's.
bool InOutline(const std::vector<ScreenPoint>& outline, const ScreenRect& rect, bool edgesOnly, ScreenPoint anchor)
{
    const float cx = 0.5f * (rect.minX + rect.maxX);
    const float cy = 0.5f * (rect.minY + rect.maxY);
    if (!edgesOnly && InsideConvex(outline, {cx, cy}))
    {
        return true;
    }
    for (size_t i = 0; !edgesOnly && i < outline.size() && outline.size() >= 3; ++i)
    {
        if (Cross(anchor, {cx, cy}, outline[i], outline[(i + 1) % outline.size()]))
        {
            return true;
        }
    }
    // An edge that only grazes the rectangle's rim runs beside the text, not through it.
    const ScreenRect text{rect.minX + 1.0f, rect.minY + 2.0f, rect.maxX - 1.0f, rect.maxY - 2.0f};
    for (size_t i = 0; i < outline.size() && outline.size() >= 3; ++i)
    {
        ScreenPoint a = outline[i];
        ScreenPoint b = outline[(i + 1) % outline.size()];
        if (ClipSegment(a, b, text))
        {
            return true;
        }
    }
    if (edgesOnly)
    {
        return false;
    }
    return QuarterPointsInside(outline, rect) >= 2;
}

// Whether a label's rectangle lies clear of the outline: its middle outside it, no two of the points a quarter in
// from its corners inside it, and none of its edges through the text.
bool ClearOf(const std::vector<ScreenPoint>& outline, const ScreenRect& rect)
{
    if (outline.size() < 3)
    {
        return true;
    }
    if (InsideConvex(outline, {0.5f * (rect.minX + rect.maxX), 0.5f * (rect.minY + rect.maxY)}) ||
        InOutline(outline, rect, true, {}))
    {
        return false;
    }
    return QuarterPointsInside(outline, rect) < 2;
}

// Whether a rectangle and a convex outline share interior: no separating axis among the rectangle's two and the
// outline's edge normals.
bool RectMeetsConvex(const ScreenRect& rect, const std::vector<ScreenPoint>& outline)
{
    if (outline.size() < 3)
    {
        return false;
    }
    float lo = INFINITY, hi = -INFINITY, top = INFINITY, bottom = -INFINITY;
    for (const ScreenPoint& p : outline)
    {
        lo = std::min(lo, p.x);
        hi = std::max(hi, p.x);
        top = std::min(top, p.y);
        bottom = std::max(bottom, p.y);
    }
    if (hi <= rect.minX || lo >= rect.maxX || bottom <= rect.minY || top >= rect.maxY)
    {
        return false;
    }
    const ScreenPoint corners[4] = {
        {rect.minX, rect.minY}, {rect.maxX, rect.minY}, {rect.maxX, rect.maxY}, {rect.minX, rect.maxY}};
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const ScreenPoint& a = outline[i];
        const ScreenPoint& b = outline[(i + 1) % outline.size()];
        const float nx = b.y - a.y;
        const float ny = a.x - b.x;
        float pmin = INFINITY, pmax = -INFINITY, cmin = INFINITY, cmax = -INFINITY;
        for (const ScreenPoint& p : outline)
        {
            pmin = std::min(pmin, nx * p.x + ny * p.y);
            pmax = std::max(pmax, nx * p.x + ny * p.y);
        }
        for (const ScreenPoint& c : corners)
        {
            cmin = std::min(cmin, nx * c.x + ny * c.y);
            cmax = std::max(cmax, nx * c.x + ny * c.y);
        }
        if (pmax > pmin && (cmax <= pmin || pmax <= cmin))
        {
            return false;
        }
    }
    return true;
}

// Whether a label's middle lies beyond its anchor along its preferred direction, when it must; with `whole`, all
// of it (a label at the end of a leader line, whose middle alone beyond an edge's line can still sit over the
// corner, beside the next edge).
bool OnItsSide(bool onSide, ScreenPoint anchor, float dx, float dy, const ScreenRect& rect, bool whole = false)
{
    if (!onSide)
    {
        return true;
    }
    if (whole)
    {
        for (const ScreenPoint c : {ScreenPoint{rect.minX, rect.minY}, ScreenPoint{rect.maxX, rect.minY},
                                    ScreenPoint{rect.minX, rect.maxY}, ScreenPoint{rect.maxX, rect.maxY}})
        {
            if ((c.x - anchor.x) * dx + (c.y - anchor.y) * dy <= 0.0f)
            {
                return false;
            }
        }
        return true;
    }
    const float cx = 0.5f * (rect.minX + rect.maxX) - anchor.x;
    const float cy = 0.5f * (rect.minY + rect.maxY) - anchor.y;
    return cx * dx + cy * dy > 0.0f;
}

} // namespace

LabelPlacer::LabelPlacer(Canvas& canvas, float width, float height) : m_canvas(canvas), m_width(width), m_height(height) {}

LabelPlacer::LabelPlacer(Canvas& canvas, const Figure& figure)
    : LabelPlacer(canvas, static_cast<float>(figure.view.width), static_cast<float>(figure.view.height))
{
    for (const DrawnOver& region : figure.drawnOver)
    {
        Reserve({region.min.x, region.min.y, region.max.x, region.max.y});
    }
}

void LabelPlacer::Reserve(const ScreenRect& rect)
{
    m_taken.push_back(rect);
}

void LabelPlacer::ReserveBand(const ScreenRect& rect)
{
    m_taken.push_back(rect);
    m_bands.push_back(rect);
}

void LabelPlacer::ReserveShape(const std::vector<ScreenPoint>& outline)
{
    m_shapes.push_back(outline);
}

void LabelPlacer::ReserveLine(ScreenPoint a, ScreenPoint b, float thickness, LabelRank from)
{
    m_lines.push_back({a, b, thickness, from});
}

void LabelPlacer::ReserveEdge(ScreenPoint a, ScreenPoint b)
{
    m_lines.push_back({a, b, 1.0f});
    m_lines.back().edge = true;
}

void LabelPlacer::ReserveShaft(ScreenPoint a, ScreenPoint b, float thickness)
{
    ReserveLine(a, b, thickness);
    m_shafts.push_back({a, b});
}

bool LabelPlacer::OnShaft(ScreenPoint p, float within) const
{
    return std::any_of(m_shafts.begin(), m_shafts.end(), [&](const std::pair<ScreenPoint, ScreenPoint>& shaft) {
        // Beside the shaft, not beyond either end of it: ahead of the head the arrow points at the place.
        const float dx = shaft.second.x - shaft.first.x;
        const float dy = shaft.second.y - shaft.first.y;
        const float length2 = dx * dx + dy * dy;
        const float t = length2 > 0.0f ? ((p.x - shaft.first.x) * dx + (p.y - shaft.first.y) * dy) / length2 : -1.0f;
        return t > 0.0f && t < 1.0f && DistanceToSegment(p, shaft.first, shaft.second) < within &&
               std::hypot(p.x - shaft.first.x, p.y - shaft.first.y) >= within;
    });
}

bool LabelPlacer::NearCrossingShaft(ScreenPoint p, float within, ScreenPoint a, ScreenPoint b) const
{
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    if (length <= 0.0f)
    {
        return false;
    }
    return std::any_of(m_shafts.begin(), m_shafts.end(), [&](const std::pair<ScreenPoint, ScreenPoint>& shaft) {
        const ScreenPoint tail = shaft.first;
        const float off = std::fabs((b.x - a.x) * (tail.y - a.y) - (b.y - a.y) * (tail.x - a.x)) / length;
        return off > 3.0f && DistanceToSegment(p, shaft.first, shaft.second) < within;
    });
}

bool LabelPlacer::NearArrowTail(ScreenPoint p, float within, ScreenPoint own) const
{
    return std::any_of(m_shafts.begin(), m_shafts.end(), [&](const std::pair<ScreenPoint, ScreenPoint>& shaft) {
        const float dx = shaft.second.x - shaft.first.x;
        const float dy = shaft.second.y - shaft.first.y;
        const float length = std::hypot(dx, dy);
        const bool along = length > 0.0f && (dx * own.x + dy * own.y) > 0.9f * length;
        return !along && std::hypot(p.x - shaft.first.x, p.y - shaft.first.y) < within;
    });
}

bool LabelPlacer::CutOffFromAnchor(const Label& label, const ScreenRect& rect, ScreenPoint at) const
{
    if (label.rank > LabelRank::Named)
    {
        return false;
    }
    const ScreenPoint middle{0.5f * (rect.minX + rect.maxX), 0.5f * (rect.minY + rect.maxY)};
    // What it names: its corner, or the point of its face nearest it.
    ScreenPoint to = at;
    if (label.face.size() == 2)
    {
        const ScreenPoint a = label.face[0];
        const ScreenPoint b = label.face[1];
        const float dx = b.x - a.x;
        const float dy = b.y - a.y;
        const float length2 = dx * dx + dy * dy;
        const float t =
            length2 > 0.0f ? std::clamp(((middle.x - a.x) * dx + (middle.y - a.y) * dy) / length2, 0.0f, 1.0f) : 0.0f;
        to = {a.x + dx * t, a.y + dy * t};
    }
    if (std::any_of(m_shafts.begin(), m_shafts.end(), [&](const std::pair<ScreenPoint, ScreenPoint>& shaft) {
            return Cross(middle, to, shaft.first, shaft.second);
        }))
    {
        return true;
    }
    // Nor another label between them, placed before it: the number reads as that label's part, or as naming
    // something beyond it (pitfall_one_shape's "2" above "pitfall 0.257", which sat on the diamond's top corner).
    for (size_t k = m_reserved; k < m_taken.size(); ++k)
    {
        const ScreenRect& r = m_taken[k];
        const ScreenPoint corners[4] = {{r.minX, r.minY}, {r.maxX, r.minY}, {r.maxX, r.maxY}, {r.minX, r.maxY}};
        for (int i = 0; i < 4; ++i)
        {
            if (Cross(middle, to, corners[i], corners[(i + 1) % 4]))
            {
                return true;
            }
        }
    }
    return false;
}

void LabelPlacer::ReserveFaintLine(ScreenPoint a, ScreenPoint b, float thickness)
{
    m_lines.push_back({a, b, thickness, LabelRank::Vertex, true});
}

void LabelPlacer::ReservePartingLine(ScreenPoint a, ScreenPoint b, float thickness)
{
    m_lines.push_back({a, b, thickness, LabelRank::Vertex, false, true});
}

bool LabelPlacer::Place(ScreenPoint anchor, std::string_view text, TextStyle style, Color color, float dx, float dy,
                        float distance, LabelRank rank)
{
    // A number whose vertex or edge cannot be seen would name nothing.
    const bool hidden =
        anchor.x < 0.0f || anchor.y < 0.0f || anchor.x > m_width || anchor.y > m_height ||
        std::any_of(m_bands.begin(), m_bands.end(), [&](const ScreenRect& band) {
            return anchor.x >= band.minX && anchor.x <= band.maxX && anchor.y >= band.minY && anchor.y <= band.maxY;
        });
    if (hidden && MayLeaveOut(rank))
    {
        return false;
    }
    m_labels.push_back({anchor, std::string(text), style, color, dx, dy, distance, rank, {}, false, false, {}, false, {}, {}, {}, -1, false, {}, {}, {}, {}});
    return true;
}

bool LabelPlacer::PlaceOutside(const std::vector<ScreenPoint>& other, ScreenPoint anchor, std::string_view text,
                               TextStyle style, Color color, float dx, float dy, float distance, LabelRank rank)
{
    if (!Place(anchor, text, style, color, dx, dy, distance, rank))
    {
        return false;
    }
    // An anchor inside the other body (a shape contained in the other, a corner pushed into it) has no outside
    // near it: its label stays beside it rather than at the end of a long leader line, off that body's edges.
    m_labels.back().avoid = other;
    m_labels.back().edgesOnly = InsideConvex(other, anchor);
    return true;
}

void LabelPlacer::AlsoAt(std::vector<ScreenPoint> anchors)
{
    if (m_labels.empty())
    {
        return;
    }
    Label& label = m_labels.back();
    // An anchor in the other body would put the label there, where it reads as that body's, unless the label's own
    // anchor lies there too.
    if (!label.avoid.empty() && !label.edgesOnly)
    {
        anchors.erase(std::remove_if(anchors.begin(), anchors.end(),
                                     [&](ScreenPoint p) { return InsideConvex(label.avoid, p); }),
                      anchors.end());
    }
    label.alternates = std::move(anchors);
}

void LabelPlacer::AlsoBeside(std::vector<ScreenPoint> anchors)
{
    if (!m_labels.empty())
    {
        m_labels.back().alternates = std::move(anchors);
        m_labels.back().across = true;
    }
}

void LabelPlacer::OutsideBoth(std::vector<ScreenPoint> own)
{
    if (!m_labels.empty())
    {
        m_labels.back().own = std::move(own);
    }
}

void LabelPlacer::KeepOutOf(std::vector<ScreenPoint> outline, bool leaderToo)
{
    if (!m_labels.empty())
    {
        if (leaderToo)
        {
            m_labels.back().leaderOut.push_back(outline);
        }
        m_labels.back().keepOut.push_back(std::move(outline));
    }
}

void LabelPlacer::ReserveGridLine(ScreenPoint a, ScreenPoint b)
{
    m_grid.push_back({a, b});
}

void LabelPlacer::PreferOutOf(std::vector<ScreenPoint> outline)
{
    if (!m_labels.empty())
    {
        m_labels.back().preferOut.push_back(std::move(outline));
    }
}

void LabelPlacer::InFaceSpan()
{
    if (!m_labels.empty())
    {
        m_labels.back().inSpan = true;
    }
}

void LabelPlacer::Within(std::vector<ScreenPoint> own)
{
    if (!m_labels.empty())
    {
        m_labels.back().home = std::move(own);
    }
}

void LabelPlacer::KeepOnSide()
{
    if (!m_labels.empty())
    {
        m_labels.back().onSide = true;
    }
}

void LabelPlacer::AddMark(MarkKind kind, ScreenPoint at, ScreenPoint toward, bool ofBody)
{
    m_marks.push_back({kind, at, toward, ofBody});
}

void LabelPlacer::Names(MarkKind kind)
{
    if (!m_labels.empty())
    {
        m_labels.back().names = static_cast<int>(kind);
    }
}

void LabelPlacer::LeadsOffArrow()
{
    if (!m_labels.empty())
    {
        m_labels.back().offArrow = true;
    }
}

void LabelPlacer::LeadsOffEdges()
{
    if (!m_labels.empty())
    {
        m_labels.back().offEdges = true;
    }
}

bool LabelPlacer::NearestOwn(const Label& label, const ScreenRect& rect, ScreenPoint at) const
{
    if (label.names < 0)
    {
        return true;
    }
    const MarkKind kind = static_cast<MarkKind>(label.names);
    // The marks at the anchor are its own: an arrow's head lies a few pixels back from the tip it is anchored at,
    // and a corner resting on the other body's is one place.
    const float own = kind == MarkKind::ArrowHead ? 14.0f : 3.0f;
    const ScreenPoint middle{0.5f * (rect.minX + rect.maxX), 0.5f * (rect.minY + rect.maxY)};
    // Measured to its own mark, beside its anchor: an arrow's head, not the tip it is anchored at.
    ScreenPoint mark = at;
    float nearest = own;
    for (const Mark& m : m_marks)
    {
        const float d = std::hypot(m.at.x - at.x, m.at.y - at.y);
        if (m.kind == kind && d <= nearest)
        {
            mark = m.at;
            nearest = d;
        }
    }
    const float mine = std::hypot(middle.x - mark.x, middle.y - mark.y);
    // A corner's number or a contact's name keeps a few pixels' lead, so that it reads as its mark's at a glance;
    // an arrow's name, larger and beside a larger mark, only gives way to a head clearly nearer than its own.
    // Beside its shaft, away from its head, it keeps well clear of every other head: a shaft runs past them.
    const bool alongShaft = at.x != label.anchor.x || at.y != label.anchor.y;
    const float lead = kind != MarkKind::ArrowHead ? 3.0f : (alongShaft ? 10.0f : -6.0f);
    for (const Mark& m : m_marks)
    {
        // A contact's name nearer a corner than its dot reads as the corner's (containment's "c2" beside the
        // triangle's corner 1, its dot just inside it).
        // A corner of a body under the dot is where the contact is.
        // Nor a corner's number not clearly nearer its corner than a contact's dot, where it reads as the dot's
        // name (ex05_inside's "3" half way down the side from its corner to c1).
        const bool corner = kind == MarkKind::Contact && m.kind == MarkKind::Corner && m.ofBody;
        const bool dot = kind == MarkKind::Corner && m.kind == MarkKind::Contact;
        if ((m.kind != kind && !corner && !dot) ||
            std::hypot(m.at.x - label.anchor.x, m.at.y - label.anchor.y) <= (corner || dot ? 5.0f : own))
        {
            continue;
        }
        // Farther than 30 pixels from its corner a number no longer reads as that corner's at a glance: it keeps
        // clearly nearer it than any other corner, at most 4/5 as far (pitfall_one_shape's "2" beside the diamond's
        // upper-left edge, 34 pixels from its top corner and 39 from its left one).
        const bool far = kind == MarkKind::Corner && m.kind == MarkKind::Corner && mine > 30.0f;
        if (std::hypot(middle.x - m.at.x, middle.y - m.at.y) <=
            mine + (far ? std::max(0.25f * mine, lead) : corner ? -4.0f : dot ? 4.0f : lead))
        {
            return false;
        }
    }
    // An arrow's name is nearer its own arrow than any other arrow's shaft: beyond its head, by the tail of a face's
    // normal that points on the same way, it reads as that normal's (pitfall_direction's "pitfall 0.20" over the
    // block's own bottom normal).
    if (kind == MarkKind::ArrowHead)
    {
        for (const std::pair<ScreenPoint, ScreenPoint>& shaft : m_shafts)
        {
            if (std::hypot(shaft.second.x - label.anchor.x, shaft.second.y - label.anchor.y) <= own)
            {
                continue; // its own
            }
            if (DistanceToSegment(middle, shaft.first, shaft.second) < mine)
            {
                return false;
            }
        }
    }
    return true;
}

void LabelPlacer::NamesFace(ScreenPoint a, ScreenPoint b, std::vector<std::vector<ScreenPoint>> rivals)
{
    if (!m_labels.empty())
    {
        m_labels.back().face = {a, b};
        m_labels.back().rivals = std::move(rivals);
    }
}

bool LabelPlacer::NearestFace(const Label& label, const ScreenRect& rect) const
{
    if (label.face.size() != 2)
    {
        return true;
    }
    // A name about as near the rival's outline as its own face reads as either's: it keeps a lead of a few pixels,
    // and half its distance from its face more, as a name farther out is read by what lies nearest around it.
    const ScreenPoint middle{0.5f * (rect.minX + rect.maxX), 0.5f * (rect.minY + rect.maxY)};
    const auto to = [&](ScreenPoint a, ScreenPoint b) {
        const float dx = b.x - a.x;
        const float dy = b.y - a.y;
        const float length2 = dx * dx + dy * dy;
        const float t =
            length2 > 0.0f ? std::clamp(((middle.x - a.x) * dx + (middle.y - a.y) * dy) / length2, 0.0f, 1.0f) : 0.0f;
        return std::hypot(a.x + dx * t - middle.x, a.y + dy * t - middle.y);
    };
    const ScreenPoint a = label.face[0];
    const ScreenPoint b = label.face[1];
    const float own = to(a, b);
    const float lead = std::max(4.0f, 0.5f * own);
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    // A rival's edge flush along the face (a box standing on the floor) is where the face is: it does not count.
    const auto off = [&](ScreenPoint p) {
        return std::fabs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / std::max(length, 1e-3f);
    };
    for (const std::vector<ScreenPoint>& rival : label.rivals)
    {
        for (size_t i = 0; rival.size() >= 2 && i < rival.size(); ++i)
        {
            const ScreenPoint u = rival[i];
            const ScreenPoint v = rival[(i + 1) % rival.size()];
            if (off(u) < 2.0f && off(v) < 2.0f)
            {
                continue;
            }
            if (to(u, v) < own + lead)
            {
                return false;
            }
        }
    }
    // Nor in a row with a contact's dot just past its end, where it reads as the dot's name (l06_tilted_plank's
    // "reference face" ending some 15 px left of c1).
    for (const Mark& m : m_marks)
    {
        const float dx = std::max({rect.minX - m.at.x, m.at.x - rect.maxX, 0.0f});
        const float dy = std::max({rect.minY - m.at.y, m.at.y - rect.maxY, 0.0f});
        if (m.kind == MarkKind::Contact && dy <= 2.0f && dx < 26.0f)
        {
            return false;
        }
    }
    // Nor about as near the head of another arrow as its own face: just past the head it reads as that arrow's name
    // (B's "e0" at the tip of A's e1 normal, which points into B along B's bottom face). Its own face's normal
    // points square to the face, from a point of it.
    for (const Mark& m : m_marks)
    {
        if (m.kind != MarkKind::ArrowHead || length <= 0.0f)
        {
            continue;
        }
        const float along = ((m.at.x - a.x) * (b.x - a.x) + (m.at.y - a.y) * (b.y - a.y)) / length;
        const float slant = std::fabs(m.toward.x * (b.x - a.x) + m.toward.y * (b.y - a.y)) / length;
        if (along >= 0.0f && along <= length && slant < 0.3f)
        {
            continue;
        }
        // Near it, or ahead of it on its line, where an arrow's name is written.
        const float ahead = (middle.x - m.at.x) * m.toward.x + (middle.y - m.at.y) * m.toward.y;
        const float aside = std::fabs((middle.x - m.at.x) * m.toward.y - (middle.y - m.at.y) * m.toward.x);
        if (std::hypot(m.at.x - middle.x, m.at.y - middle.y) < own + lead + 8.0f ||
            (ahead > 0.0f && ahead < 48.0f && aside < 14.0f))
        {
            return false;
        }
    }
    return true;
}

void LabelPlacer::Centre()
{
    if (!m_labels.empty())
    {
        m_labels.back().centred = true;
    }
}

bool LabelPlacer::Inside(const ScreenRect& rect) const
{
    return rect.minX >= kSideMargin && rect.minY >= kMargin && rect.maxX <= m_width - kSideMargin &&
           rect.maxY <= m_height - kMargin;
}

LabelPlacer::LeaderLine LabelPlacer::Leader(ScreenPoint anchor, const ScreenRect& rect)
{
    // From just beside the anchor to the nearest point of the label.
    const ScreenPoint b{std::clamp(anchor.x, rect.minX, rect.maxX), std::clamp(anchor.y, rect.minY, rect.maxY)};
    const float length = std::hypot(b.x - anchor.x, b.y - anchor.y);
    if (length <= 4.0f)
    {
        return {};
    }
    return {{anchor.x + (b.x - anchor.x) * 3.0f / length, anchor.y + (b.y - anchor.y) * 3.0f / length}, b, true};
}

bool LabelPlacer::LeaderClear(ScreenPoint anchor, const ScreenRect& rect) const
{
    const LeaderLine line = Leader(anchor, rect);
    if (!line.drawn)
    {
        return true;
    }
    // Two leader lines that cross read as leading each to the other's label; two that start at one point make a
    // corner there that reads as one line from one label to the other.
    for (const Line& other : m_lines)
    {
        if (other.leader && (Cross(line.from, line.to, other.a, other.b) ||
                             std::hypot(other.a.x - line.from.x, other.a.y - line.from.y) < 8.0f))
        {
            return false;
        }
    }
    if (LeaderRunsAlong(anchor, rect))
    {
        return false;
    }
    // Under a label's halo the line would vanish and seem to lead to that label; under a band, from nowhere. The
    // marks at the anchor (a contact point, two close ones that share a label, an arrow head) are where it starts.
    const ScreenRect start{anchor.x - 8.0f, anchor.y - 8.0f, anchor.x + 8.0f, anchor.y + 8.0f};
    for (size_t k = 0; k < m_taken.size(); ++k)
    {
        const ScreenRect& other = m_taken[k];
        const bool label = k >= m_reserved;
        if (!label && other.Overlaps(start))
        {
            continue;
        }
        ScreenPoint a = line.from;
        ScreenPoint b = line.to;
        if (ClipSegment(a, b, other) && std::hypot(b.x - a.x, b.y - a.y) > 0.5f)
        {
            return false;
        }
    }
    return true;
}

bool LabelPlacer::LeaderRunsAlong(ScreenPoint anchor, const ScreenRect& rect) const
{
    // A leader line that runs along a body's edge merges with it and seems to name that edge, or the corner where it
    // leaves it. One that starts on an edge (the face it names) leaves it steeply enough to be told from it.
    const LeaderLine line = Leader(anchor, rect);
    if (!line.drawn)
    {
        return false;
    }
    if (std::any_of(m_lines.begin(), m_lines.end(),
                    [&](const Line& other) { return other.edge && RunsAlong(line.from, line.to, other.a, other.b); }))
    {
        return true;
    }
    // Nor along a line of the grid, which hides it.
    if (LeaderAlongGrid(anchor, rect))
    {
        return true;
    }
    // Nor past a contact's dot other than the ones at its anchor: it seems to lead from that dot.
    return std::any_of(m_marks.begin(), m_marks.end(), [&](const Mark& mark) {
        return mark.kind == MarkKind::Contact && std::hypot(mark.at.x - anchor.x, mark.at.y - anchor.y) > 8.0f &&
               DistanceToSegment(mark.at, line.from, line.to) < 6.0f;
    });
}

bool LabelPlacer::LeaderAlongGrid(ScreenPoint anchor, const ScreenRect& rect) const
{
    // A short one, its label beside its mark, reads as the mark's without it.
    const LeaderLine line = Leader(anchor, rect);
    return line.drawn && std::hypot(line.to.x - line.from.x, line.to.y - line.from.y) > 30.0f &&
           std::any_of(m_grid.begin(), m_grid.end(), [&](const std::pair<ScreenPoint, ScreenPoint>& grid) {
               return RunsAlong(line.from, line.to, grid.first, grid.second, 2.5f);
           });
}

bool LabelPlacer::LeaderCrossesBar(ScreenPoint anchor, const ScreenRect& rect) const
{
    // A leader line across a thick bar (a projection interval, a marked face) seems to name the bar. Only the
    // stretch away from the anchor counts: a contact point on a face is led out across that face.
    const LeaderLine leader = Leader(anchor, rect);
    const float length = std::hypot(leader.to.x - leader.from.x, leader.to.y - leader.from.y);
    if (!leader.drawn || length <= kNearAnchor)
    {
        return false;
    }
    const ScreenPoint from{leader.from.x + (leader.to.x - leader.from.x) * kNearAnchor / length,
                           leader.from.y + (leader.to.y - leader.from.y) * kNearAnchor / length};
    return std::any_of(m_lines.begin(), m_lines.end(), [&](const Line& line) {
        return !line.leader && line.thickness >= 4.0f && Cross(from, leader.to, line.a, line.b);
    });
}

bool LabelPlacer::LeaderAstray(const Label& label, ScreenPoint anchor, const ScreenRect& rect, bool edges) const
{
    const LeaderLine leader = Leader(anchor, rect);
    if (!(label.offArrow || label.offEdges) || !leader.drawn)
    {
        return false;
    }
    // Leaving the head within 30 degrees of the arrow's line, it carries the shaft on past the head
    // (pitfall_one_shape's "pitfall 0.257" led up through the diamond's top corner), or runs back over it.
    const float lx = leader.to.x - leader.from.x;
    const float ly = leader.to.y - leader.from.y;
    const float length = std::hypot(lx, ly);
    const float own = std::hypot(label.dx, label.dy);
    if (label.offArrow && length > 0.0f && own > 0.0f &&
        std::fabs(lx * label.dx + ly * label.dy) / (length * own) > 0.866f)
    {
        return true;
    }
    // Across a body's edge, to a place beyond it, it reads as naming that edge or what lies across it
    // (disc_cast_cup's "t = 0.74" led across the cup's whole right arm), while a place on its own side may be free.
    return edges && std::any_of(m_lines.begin(), m_lines.end(), [&](const Line& line) {
               return line.edge && Cross(leader.from, leader.to, line.a, line.b);
           });
}

bool LabelPlacer::AcrossParting(const Label& label, const ScreenRect& rect, ScreenPoint at) const
{
    // A corner's number or a face's name beyond the separating line from what it names sits on the other body's
    // side, among that body's numbers, where it reads as one of them (the diamond's "3" beside the box's corner).
    // A face a sentence names may still be named there when no other place is free, as it may beside the other
    // body (the face rule of Flush).
    if (label.rank > LabelRank::Named)
    {
        return false;
    }
    for (const Line& line : m_lines)
    {
        if (!line.parting)
        {
            continue;
        }
        const float dx = line.b.x - line.a.x;
        const float dy = line.b.y - line.a.y;
        const float length = std::sqrt(dx * dx + dy * dy);
        if (length <= 0.0f)
        {
            continue;
        }
        const auto side = [&](float x, float y) { return (dx * (y - line.a.y) - dy * (x - line.a.x)) / length; };
        const float own = side(at.x, at.y);
        // An anchor on the line (a corner it passes through) has no side.
        if (std::abs(own) < 1.0f)
        {
            continue;
        }
        for (const ScreenPoint& corner : {ScreenPoint{rect.minX, rect.minY}, ScreenPoint{rect.maxX, rect.minY},
                                          ScreenPoint{rect.minX, rect.maxY}, ScreenPoint{rect.maxX, rect.maxY}})
        {
            if (side(corner.x, corner.y) * own < 0.0f)
            {
                return true;
            }
        }
    }
    return false;
}

bool LabelPlacer::LeaderCrossesLine(ScreenPoint anchor, const ScreenRect& rect) const
{
    // An edge's name led across the separating line beside its face lands on the far side of it, among the other
    // body's labels: the face is named just inside its own body instead.
    const LeaderLine leader = Leader(anchor, rect);
    if (!leader.drawn)
    {
        return false;
    }
    return std::any_of(m_lines.begin(), m_lines.end(), [&](const Line& line) {
        return line.parting && Cross(leader.from, leader.to, line.a, line.b);
    });
}

bool LabelPlacer::Free(const ScreenRect& rect, float spacing, LabelRank rank, bool everyLine) const
{
    const ScreenRect foot = Footprint(rect);
    // A body's name keeps more room from every other label, placed before it or after it, where the figure has
    // that room (the first pass, which also keeps a space beside every label).
    const float room = rank == LabelRank::Name && spacing > 0.0f ? kNameRoom : 0.0f;
    const ScreenRect spaced{foot.minX - spacing - room, foot.minY - room, foot.maxX + spacing + room, foot.maxY + room};
    for (size_t k = 0; k < m_taken.size(); ++k)
    {
        // Two labels side by side keep more room between them than a label and a mark: closer than about three
        // spaces they read as one phrase, and two of different things (colours) closer than about four read as
        // naming one thing ("c2 e2", "c1 pitfall 0.20").
        const float apart = k < m_reserved                                      ? 0.0f
                            : (m_takenColors[k - m_reserved] >> 8) == (m_placing >> 8) ? kLabelApart
                                                                                      : kOtherLabelApart;
        const ScreenRect& other = m_taken[k];
        if (other.Overlaps({spaced.minX - apart, spaced.minY, spaced.maxX + apart, spaced.maxY}))
        {
            return false;
        }
    }
    if (std::any_of(m_shapes.begin(), m_shapes.end(),
                    [&](const std::vector<ScreenPoint>& shape) { return RectMeetsConvex(foot, shape); }))
    {
        return false;
    }
    for (const Line& line : m_lines)
    {
        // A label of a glyph or two (a number, "e2", "c1", "v") on a faint line reads as the name of its end, as
        // a vertex number does; a longer one is read as words across it.
        const bool small = rect.maxX - rect.minX < kSmallLabel;
        if ((rank < line.from || (line.faint && rank > LabelRank::Named && !small)) && !everyLine)
        {
            continue;
        }
        const float r = 0.5f * line.thickness;
        ScreenPoint a = line.a;
        ScreenPoint b = line.b;
        if (ClipSegment(a, b, {foot.minX - r, foot.minY - r, foot.maxX + r, foot.maxY + r}))
        {
            return false;
        }
    }
    return true;
}

void LabelPlacer::Flush(Color halo)
{
    // The most important first; labels of one rank in the order they were added.
    std::vector<const Label*> order;
    for (const Label& label : m_labels)
    {
        order.push_back(&label);
    }
    std::stable_sort(order.begin(), order.end(), [](const Label* a, const Label* b) { return a->rank > b->rank; });
    struct Placed
    {
        const Label* label;
        ScreenRect rect;
        bool leader;
        ScreenPoint from; // the anchor it sits beside
    };
    std::vector<Placed> placed;
    m_reserved = m_taken.size(); // the marks, panels and lines reserved; the labels' footprints follow
    m_takenColors.clear();
    // Whether a place keeps the label out of the other body (and, with OutsideBoth, out of its own too).
    bool preferring = false; // a first search that keeps the label out of the outlines it prefers to keep out of
    const auto Away = [&preferring, this](const Label& label, const ScreenRect& rect, ScreenPoint at) {
        if (label.inSpan && label.face.size() == 2)
        {
            const ScreenPoint a = label.face[0];
            const ScreenPoint b = label.face[1];
            const float length2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
            const float t = length2 > 0.0f ? (((rect.minX + rect.maxX) * 0.5f - a.x) * (b.x - a.x) +
                                              ((rect.minY + rect.maxY) * 0.5f - a.y) * (b.y - a.y)) /
                                                 length2
                                           : 0.5f;
            // Past an end only on a leader line that leaves the face at 30 degrees or more (one nearly along it
            // runs into the body beside it and ends short of the face); and on no leader line that runs near
            // another edge, where it reads as naming that edge.
            const LeaderLine line = Leader(at, rect);
            const float lx = line.to.x - line.from.x;
            const float ly = line.to.y - line.from.y;
            const float cross = std::abs(lx * (b.y - a.y) - ly * (b.x - a.x));
            if ((t < 0.0f || t > 1.0f) && (!line.drawn || cross < 0.5f * std::hypot(lx, ly) * std::sqrt(length2)))
            {
                return false;
            }
            if (line.drawn && std::any_of(m_lines.begin(), m_lines.end(), [&](const Line& edge) {
                    const bool own = std::hypot(edge.a.x - a.x, edge.a.y - a.y) + std::hypot(edge.b.x - b.x, edge.b.y - b.y) < 3.0f ||
                                     std::hypot(edge.a.x - b.x, edge.a.y - b.y) + std::hypot(edge.b.x - a.x, edge.b.y - a.y) < 3.0f;
                    return edge.edge && !own && RunsAlong(line.from, line.to, edge.a, edge.b, 8.0f);
                }))
            {
                return false;
            }
        }
        if (!std::all_of(label.keepOut.begin(), label.keepOut.end(),
                         [&](const std::vector<ScreenPoint>& outline) { return ClearOf(outline, rect); }))
        {
            return false;
        }
        // Nor led across what it keeps its leader out of: the line would run through it and seem to start there.
        if (const LeaderLine leader = Leader(at, rect); leader.drawn)
        {
            for (const std::vector<ScreenPoint>& outline : label.leaderOut)
            {
                for (size_t k = 0; k < outline.size(); ++k)
                {
                    if (Cross(leader.from, leader.to, outline[k], outline[(k + 1) % outline.size()]))
                    {
                        return false;
                    }
                }
            }
        }
        if (preferring && !std::all_of(label.preferOut.begin(), label.preferOut.end(),
                                       [&](const std::vector<ScreenPoint>& outline) { return ClearOf(outline, rect); }))
        {
            return false;
        }
        if (!label.own.empty())
        {
            return ClearOf(label.avoid, rect) && ClearOf(label.own, rect);
        }
        return !InOutline(label.avoid, rect, label.edgesOnly, at);
    };
    for (const Label* label : order)
    {
        const ScreenPoint size = m_canvas.MeasureText(label->text, label->style);
        m_placing = label->color;
        const bool directed = label->dx != 0.0f || label->dy != 0.0f;
        const double start = directed ? std::atan2(label->dy, label->dx) : 0.0;
        ScreenRect chosen{};
        bool found = false;
        bool leader = false;
        // Near the anchor: eight directions at three distances, the preferred direction first; turning a label 45
        // degrees away from it costs about as much as moving it 12 pixels farther out. A space's width is kept from
        // other labels ("gap 0.60" beside "0" reads "gap 0.600") and given up before a label has to move farther.
        // A label with other anchors along what it names slides there before it turns: each next anchor costs a
        // little less than a turn of 45 degrees, and only the preferred direction and the one opposite are tried
        // at them, square to what it names (a label turned part way would sit beyond its end or across it).
        struct Candidate
        {
            int turn;
            int ring;
            size_t anchor; // 0: the label's own anchor, k: alternates[k - 1]
        };
        // Turns are in sixteenths of a full turn: the eight directions are the even ones.
        std::vector<Candidate> candidates;
        for (int ring = 0; ring < 3; ++ring)
        {
            for (int turn : {0, 1, -1, 2, -2, 3, -3, 4})
            {
                candidates.push_back({2 * turn, ring, 0});
            }
            for (size_t k = 1; k <= label->alternates.size(); ++k)
            {
                candidates.push_back({label->across ? 4 : 0, ring, k});
                candidates.push_back({label->across ? -4 : 8, ring, k});
            }
        }
        auto cost = [](const Candidate& c) { return 2 * std::abs(c.turn) + 3 * c.ring + 3 * static_cast<int>(c.anchor); };
        std::stable_sort(candidates.begin(), candidates.end(),
                         [&](const Candidate& a, const Candidate& b) { return cost(a) < cost(b); });
        // A vertex number, which has no leader line to fall back on, tries the eight directions between those and a
        // fourth ring before it is left out: a corner crowded by an edge's name on one side and a contact's on the
        // other often has room half way between them.
        if (label->rank == LabelRank::Vertex)
        {
            const size_t base = candidates.size();
            for (int ring = 0; ring < 4; ++ring)
            {
                for (int turn : {1, -1, 3, -3, 5, -5, 7, -7})
                {
                    candidates.push_back({turn, ring, 0});
                }
                for (int turn : {0, 2, -2, 4, -4, 6, -6, 8})
                {
                    if (ring == 3)
                    {
                        candidates.push_back({turn, ring, 0});
                    }
                }
            }
            // Nearest the preferred direction first, as above: outside the corner before inside its body.
            std::stable_sort(candidates.begin() + static_cast<std::ptrdiff_t>(base), candidates.end(),
                             [&](const Candidate& a, const Candidate& b) { return cost(a) < cost(b); });
        }
        ScreenPoint from = label->anchor;
        // A face a sentence names is named even where every place near it reads as the other body's too (its face
        // flush against that body, the canvas narrow): the places are tried again without that rule.
        // A label that prefers to keep out of some outlines (a band's size out of the bodies) first looks for a
        // place out of them, near its anchor or on a short leader line, and only then anywhere.
        for (int prefer = label->preferOut.empty() ? 0 : 1; prefer >= 0 && !found; --prefer)
        {
            preferring = prefer == 1;
            for (int faceRule = 1; faceRule >= 0 && !found; --faceRule)
            {
                const bool faceFree = faceRule == 0;
                if (faceFree && label->rank != LabelRank::Named)
                {
                    break;
                }
                if (label->centred)
                {
                    const float left = std::round(label->anchor.x - 0.5f * size.x);
                    const float top = std::round(label->anchor.y - 0.5f * size.y);
                    const ScreenRect centred{left, top, left + size.x, top + size.y};
                    if (Inside(centred) && Free(centred, 0.0f, label->rank))
                    {
                        chosen = centred;
                        found = true;
                    }
                }
                // A vertex number or an edge name may sit on a line the others keep off (a separating line, a dashed
                // outline) rather than be left out, but it reads better beside it: the first pass (-1) keeps it off every
                // line.
                for (int pass = -1; pass < 2 && !found; ++pass)
                {
                    for (const Candidate& c : candidates)
                    {
                        const ScreenPoint at = c.anchor == 0 ? label->anchor : label->alternates[c.anchor - 1];
                        const float reach = label->distance + static_cast<float>(c.ring) * 9.0f;
                        const ScreenRect rect = Around(at, size, start + c.turn * 0.125 * kPi, reach);
                        if (Inside(rect) && Free(rect, pass <= 0 ? kLabelSpacing : 0.0f, label->rank, pass < 0) &&
                            Away(*label, rect, at) && NearestOwn(*label, rect, at) &&
                            (faceFree || NearestFace(*label, rect)) && !CutOffFromAnchor(*label, rect, at) &&
                            (faceFree || !AcrossParting(*label, rect, at)) && OnItsSide(label->onSide, at, label->dx, label->dy, rect))
                        {
                            chosen = rect;
                            from = at;
                            found = true;
                            break;
                        }
                    }
                }
                // Farther out, on a leader line back to the anchor: sixteen directions, at growing distances. Not a vertex
                // number or an edge name that no sentence names: a number at the end of a line, among the shapes' outlines,
                // reads as any corner's (the floor's "3" led into the box standing on it); it is left out instead.
                // A label that is always drawn tries those places once more when none is free, its leader line then
                // allowed across other marks (across a thick bar only on a last try), before it is drawn over something at
                // its preferred place.
                // A face's name tries the other anchors along its face on short leader lines before a long one from
                // its own: a leader from the point another leader starts from reads as joining the two labels.
                struct Trial
                {
                    ScreenPoint at;
                    int ring;
                };
                std::vector<Trial> trials;
                for (int ring = 0; ring < 9; ++ring)
                {
                    trials.push_back({label->anchor, ring});
                }
                if (label->face.size() == 2)
                {
                    std::vector<ScreenPoint> along = label->alternates;
                    const ScreenPoint a = label->face[0];
                    const ScreenPoint b = label->face[1];
                    for (const float t : {0.3f, 0.7f})
                    {
                        along.push_back({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t});
                    }
                    for (const ScreenPoint& at : along)
                    {
                        // An edge's own name only close by: farther, among the faces, it reads as another's.
                        for (int ring = 0; ring < (label->rank > LabelRank::Named ? 9 : 2); ++ring)
                        {
                            trials.push_back({at, ring});
                        }
                    }
                }
                for (int ring = 9; ring < (preferring ? 9 : 27); ++ring)
                {
                    trials.push_back({label->anchor, ring});
                }
                for (const Trial& trial : trials)
                {
                    const int ring = trial.ring;
                    const ScreenPoint at = trial.at;
                    if (found || label->rank <= LabelRank::Edge || (ring >= 9 && MayLeaveOut(label->rank)))
                    {
                        break;
                    }
                    const bool strict = ring < 9;
                    const bool clearOfBars = ring < 18; // and its leader line off the bars while it can
                    const float reach = std::max(label->distance, 0.0f) + 28.0f + 16.0f * static_cast<float>(ring % 9);
                    for (int i = 0; i < 16 && !found; ++i)
                    {
                        const int k = (i + 1) / 2 * (i % 2 == 1 ? 1 : -1);
                        const ScreenRect rect = Around(at, size, start + k * 0.125 * kPi, reach);
                        if (Inside(rect) && Free(rect, 0.0f, label->rank) && Away(*label, rect, at) &&
                            OnItsSide(label->onSide, at, label->dx, label->dy, rect, true) &&
                            (!strict || LeaderClear(at, rect)) && (!clearOfBars || !LeaderCrossesBar(at, rect)) &&
                            (!clearOfBars || !LeaderRunsAlong(at, rect)) && !LeaderAstray(*label, at, rect, strict) &&
                            !(label->onSide && LeaderCrossesLine(at, rect)))
                        {
                            chosen = rect;
                            from = at;
                            found = true;
                            leader = true;
                        }
                    }
                }
                // A face a sentence names with no room on its outside (flush against the other body, or facing the image's
                // border) is named just inside its own body, beside it, where it still reads as that face's; with its
                // body's outline known, a little deeper in too (beside the body's name, the arrow or the ghost over it),
                // wholly inside that outline, where it cannot be read as a neighbouring face's.
                const auto Home = [&](const ScreenRect& rect) {
                    return label->home.size() >= 3 && InsideConvex(label->home, {rect.minX, rect.minY}) &&
                           InsideConvex(label->home, {rect.maxX, rect.minY}) &&
                           InsideConvex(label->home, {rect.minX, rect.maxY}) &&
                           InsideConvex(label->home, {rect.maxX, rect.maxY});
                };
                for (int ring = 0; ring < 7 && !found && label->rank == LabelRank::Named && label->onSide; ++ring)
                {
                    if (ring >= 3 && label->home.size() < 3)
                    {
                        break;
                    }
                    for (size_t k = 0; k <= label->alternates.size() && !found; ++k)
                    {
                        const ScreenPoint at = k == 0 ? label->anchor : label->alternates[k - 1];
                        for (int turn : {4, 3, -3})
                        {
                            const ScreenRect rect = Around(at, size, start + turn * 0.25 * kPi,
                                                           label->distance + static_cast<float>(ring) * 9.0f);
                            if (!found && Inside(rect) && Free(rect, 0.0f, label->rank) && Away(*label, rect, at) &&
                                (faceFree || NearestFace(*label, rect)) && (ring < 3 || Home(rect)))
                            {
                                chosen = rect;
                                from = at;
                                found = true;
                            }
                        }
                    }
                }
                // With no room inside either (a small body, its arrow and ghost over it), the face is named beyond the
                // other body it rests on, on a leader line across that body: the line shows which face the name belongs to,
                // and the name itself still keeps out of that body, off every label and clear of the separating line.
                for (int ring = 0; ring < 9 && !found && label->rank == LabelRank::Named && label->onSide; ++ring)
                {
                    const float reach = std::max(label->distance, 0.0f) + 28.0f + 16.0f * static_cast<float>(ring);
                    for (int i = 0; i < 16 && !found; ++i)
                    {
                        const int k = (i + 1) / 2 * (i % 2 == 1 ? 1 : -1);
                        const ScreenRect rect = Around(label->anchor, size, start + k * 0.125 * kPi, reach);
                        if (Inside(rect) && Free(rect, 0.0f, label->rank) && ClearOf(label->avoid, rect) &&
                            std::all_of(label->keepOut.begin(), label->keepOut.end(),
                                        [&](const std::vector<ScreenPoint>& outline) { return ClearOf(outline, rect); }) &&
                            OnItsSide(true, label->anchor, label->dx, label->dy, rect, true) &&
                            LeaderClear(label->anchor, rect) && !LeaderCrossesLine(label->anchor, rect) &&
                            !LeaderCrossesBar(label->anchor, rect))
                        {
                            chosen = rect;
                            found = true;
                            leader = true;
                        }
                    }
                }
            }
        }
        if (!found)
        {
            if (MayLeaveOut(label->rank))
            {
                continue;
            }
            // No free place: the preferred one, kept inside the image.
            chosen = Around(label->anchor, size, start, label->distance);
            const float shiftX =
                std::clamp(chosen.minX, kSideMargin, std::max(kSideMargin, m_width - kSideMargin - size.x)) -
                chosen.minX;
            const float shiftY =
                std::clamp(chosen.minY, kMargin, std::max(kMargin, m_height - kMargin - size.y)) - chosen.minY;
            chosen = {chosen.minX + shiftX, chosen.minY + shiftY, chosen.maxX + shiftX, chosen.maxY + shiftY};
        }
        // A body's name keeps more room around it: a number or an edge name close beside it reads as part of it
        // ("plank e0").
        const ScreenRect foot = Footprint(chosen);
        const float room = label->rank == LabelRank::Name ? kNameRoom : 0.0f;
        m_taken.push_back({foot.minX - room, foot.minY - room, foot.maxX + room, foot.maxY + room});
        m_takenColors.push_back(label->color);
        placed.push_back({label, chosen, leader, from});
        if (leader)
        {
            // Later labels keep off the leader line, which their halos would hide.
            const LeaderLine line = Leader(from, chosen);
            if (line.drawn)
            {
                m_lines.push_back({line.from, line.to, 1.0f, LabelRank::Vertex, false, false, true});
            }
        }
    }
    m_canvas.BeginGroup("labels");
    for (const Placed& p : placed)
    {
        if (p.leader)
        {
            const LeaderLine line = Leader(p.from, p.rect);
            if (line.drawn)
            {
                m_canvas.Segment(line.from, line.to, WithAlpha(p.label->color, 0.7f), 1.0f);
            }
        }
    }
    for (const Placed& p : placed)
    {
        m_canvas.FillRect({p.rect.minX - kHalo, p.rect.minY}, {p.rect.maxX + kHalo, p.rect.maxY}, halo);
        m_canvas.Text({p.rect.minX, p.rect.minY}, p.label->text, p.label->style, p.label->color);
    }
    m_labels.clear();
}

bool LineWatch::Watched(Color color) const
{
    // A line almost transparent (a body's faint fill edge, a ghost) shows too little to be read as cut.
    return m_group != "background" && m_group != "axes" && m_group != "labels" && (color & 0xFFu) >= 0x40u;
}

void LineWatch::Note(const ScreenPoint* points, int count, bool closed, Color color, float thickness)
{
    if (m_group == "background" && count == 2 && !closed)
    {
        m_labels.ReserveGridLine(points[0], points[1]);
    }
    if (!Watched(color))
    {
        return;
    }
    for (int i = 0; i + 1 < count + (closed ? 1 : 0); ++i)
    {
        if ((color & 0xFFu) >= 0xC0u)
        {
            m_labels.ReserveLine(points[i], points[(i + 1) % count], std::max(thickness, 1.0f));
        }
        else
        {
            m_labels.ReserveFaintLine(points[i], points[(i + 1) % count], std::max(thickness, 1.0f));
        }
    }
}

void LineWatch::Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness)
{
    const ScreenPoint ends[2] = {a, b};
    Note(ends, 2, false, color, thickness);
    m_canvas.Segment(a, b, color, thickness);
}

void LineWatch::Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness)
{
    Note(points, count, closed, color, thickness);
    m_canvas.Polyline(points, count, closed, color, thickness);
}

void LineWatch::FillConvex(const ScreenPoint* points, int count, Color color)
{
    // A small, nearly opaque triangle is an arrow's head (or a time's marker): a label names the one beside it.
    if (count == 3 && (color & 0xFFu) >= 0x80u && m_group != "background" && m_group != "axes" && m_group != "labels")
    {
        const float w = std::max({points[0].x, points[1].x, points[2].x}) - std::min({points[0].x, points[1].x, points[2].x});
        const float h = std::max({points[0].y, points[1].y, points[2].y}) - std::min({points[0].y, points[1].y, points[2].y});
        if (w <= 24.0f && h <= 24.0f)
        {
            // Its tip is the corner opposite the shortest side: the head points from that side's middle to it.
            size_t tip = 0;
            float shortest = std::numeric_limits<float>::max();
            for (size_t k = 0; k < 3; ++k)
            {
                const ScreenPoint u = points[(k + 1) % 3];
                const ScreenPoint v = points[(k + 2) % 3];
                const float side = std::hypot(v.x - u.x, v.y - u.y);
                if (side < shortest)
                {
                    shortest = side;
                    tip = k;
                }
            }
            const ScreenPoint base{0.5f * (points[(tip + 1) % 3].x + points[(tip + 2) % 3].x),
                                   0.5f * (points[(tip + 1) % 3].y + points[(tip + 2) % 3].y)};
            const float reach = std::hypot(points[tip].x - base.x, points[tip].y - base.y);
            const ScreenPoint toward = reach > 0.0f ? ScreenPoint{(points[tip].x - base.x) / reach,
                                                                  (points[tip].y - base.y) / reach}
                                                    : ScreenPoint{};
            m_labels.AddMark(MarkKind::ArrowHead,
                             {(points[0].x + points[1].x + points[2].x) / 3.0f,
                              (points[0].y + points[1].y + points[2].y) / 3.0f},
                             toward);
        }
    }
    m_canvas.FillConvex(points, count, color);
}

void LineWatch::FillOutlined(const ScreenPoint* points, int count, Color fill, Color outline, float thickness)
{
    Note(points, count, true, outline, thickness);
    m_canvas.FillOutlined(points, count, fill, outline, thickness);
}

void LineWatch::Circle(ScreenPoint center, float radius, Color color, float thickness)
{
    // The circle as a polygon of 32 sides, close enough at the sizes a label keeps off it.
    ScreenPoint points[32];
    for (int i = 0; i < 32; ++i)
    {
        const double a = 2.0 * kPi * i / 32.0;
        points[i] = {center.x + radius * static_cast<float>(std::cos(a)),
                     center.y + radius * static_cast<float>(std::sin(a))};
    }
    Note(points, 32, true, color, thickness);
    m_canvas.Circle(center, radius, color, thickness);
}

void LineWatch::FillCircle(ScreenPoint center, float radius, Color color)
{
    m_canvas.FillCircle(center, radius, color);
}

void LineWatch::FillRect(ScreenPoint min, ScreenPoint max, Color color)
{
    m_canvas.FillRect(min, max, color);
}

void LineWatch::Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color)
{
    m_canvas.Text(topLeft, text, style, color);
}

ScreenPoint LineWatch::MeasureText(std::string_view text, TextStyle style)
{
    return m_canvas.MeasureText(text, style);
}

void LineWatch::BeginGroup(std::string_view name)
{
    m_group = std::string(name);
    m_canvas.BeginGroup(name);
}

} // namespace satviz
