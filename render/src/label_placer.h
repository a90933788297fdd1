// SPDX-License-Identifier: MIT
// satviz render, private: where a figure's labels go. Labels are collected first and placed last, the most
// important first, so that none covers another label, an arrow head, a mark or a panel, and none leaves the image.
#pragma once

#include "draw_kit.h"

#include <satviz/render/painter.h>

#include <string>
#include <string_view>
#include <vector>

namespace satviz
{

/// How much a label matters. Places are handed out from the most important down; when no room is left near its
/// anchor, a vertex number is left out first, then an edge name, then (with no room on a leader line either) a
/// named one; the others are always drawn.
enum class LabelRank
{
    Vertex,  ///< a vertex number
    Edge,    ///< an edge name (e0, e1, ...)
    /// a vertex number or an edge name that the figure's sentences name: placed before the other numbers, on a
    /// leader line when it must, and left out only when no place at all is free (never drawn over another label)
    Named,
    Note,    ///< what an axis line, a bound or a moving body's arrow is
    Name,    ///< a body's name
    Verdict, ///< what the verdict shows: the MTV, contact points, the band's size, reference and incident faces
};

/// A kind of mark a label can name: a label sits nearer the mark it names than any other mark of that kind, where
/// which one it names would otherwise be a guess ("c1" between two contact points, a corner's number beside the
/// corner of the dashed outline where the MTV leaves its body, a velocity's "v" beside a face's normal).
enum class MarkKind
{
    Corner,    ///< a corner of a body of the pair, or of a dashed outline of where a body is moved to
    Contact,   ///< a contact point
    ArrowHead, ///< the head of an arrow (told by the line watch, as drawn)
};

/// Collects a figure's labels and places them: each tries eight directions around its anchor at three distances,
/// then (all but vertex numbers and edge names) farther places joined to the anchor by a thin leader line; a label
/// that finds no free place is left out when it is a vertex number or an edge name, and otherwise drawn at its
/// preferred place inside the image.
class LabelPlacer
{
  public:
    /// A placer for an image of the given size.
    LabelPlacer(Canvas& canvas, float width, float height);
    /// A placer for the figure's image, every region the caller draws over it reserved.
    LabelPlacer(Canvas& canvas, const Figure& figure);
    /// Marks a region no label may cover: a panel, the caption, an inset, an arrow head, a contact point.
    void Reserve(const ScreenRect& rect);
    /// Marks a band that hides what lies under it (the caption, the number-line panel, an inset): no label may
    /// cover it, and a vertex number or an edge name whose anchor it hides is left out.
    void ReserveBand(const ScreenRect& rect);
    /// Marks a line no label may cover, `thickness` pixels wide: one drawn over the labels, or one a label's halo
    /// would hide (a projection bar, a marked face). With `from` above LabelRank::Vertex only labels of that rank
    /// and above keep off it: a vertex number or an edge name may still sit on it rather than be left out.
    void ReserveLine(ScreenPoint a, ScreenPoint b, float thickness, LabelRank from = LabelRank::Vertex);
    /// Reserves an edge of a body's outline as ReserveLine does; a leader line may not run along it either.
    void ReserveEdge(ScreenPoint a, ScreenPoint b);
    /// Marks an arrow's shaft: as any line no label covers it, and no vertex number or edge name has it between
    /// itself and what it names, where the arrow cuts the number off from its corner and it reads as the arrow's.
    void ReserveShaft(ScreenPoint a, ScreenPoint b, float thickness);
    /// Whether `p` lies within `within` pixels beside an arrow's shaft marked so far (ReserveShaft), between its ends
    /// and away from its tail (a body's middle, where its velocity starts).
    bool OnShaft(ScreenPoint p, float within) const;
    /// Whether `p` lies within `within` pixels of the tail of an arrow marked so far (ReserveShaft) that does not
    /// point along `own` (a unit direction on screen): a face's normal starts on its face, and another face's normal
    /// there (the other body's, on a shared face) reads as what a leader line from there names.
    bool NearArrowTail(ScreenPoint p, float within, ScreenPoint own) const;
    /// Whether `p` lies within `within` pixels of the shaft of an arrow marked so far (ReserveShaft) whose tail lies
    /// off the line through `a` and `b` (a face): another face's normal crossing the face there, which a leader line
    /// from `p` would seem to name. The face's own normal, which starts on it, does not count.
    bool NearCrossingShaft(ScreenPoint p, float within, ScreenPoint a, ScreenPoint b) const;
    /// Marks a faint line (a dashed projection line, a ghost's outline, drawn translucent): a vertex number or an
    /// edge name keeps off it, where it would read as the number of the line's end; a larger label only where the
    /// room allows, as the line shows through its halo's gaps and is not read as part of it.
    void ReserveFaintLine(ScreenPoint a, ScreenPoint b, float thickness);
    /// Marks the separating line, which parts the two bodies: as any line no label covers it, and no edge's name is
    /// led across it, where it would land on the other body's side.
    void ReservePartingLine(ScreenPoint a, ScreenPoint b, float thickness);
    /// Marks a line of the faint grid under the figure: no leader line runs along it, where the grid line would
    /// hide it. Labels may still cover it.
    void ReserveGridLine(ScreenPoint a, ScreenPoint b);
    /// Marks a body outside the tested pair (a convex outline on screen): no label may lie on it or in it, where it
    /// would read as that body's.
    void ReserveShape(const std::vector<ScreenPoint>& outline);
    /// Adds `text` near `anchor`, `distance` pixels away, preferring the direction (dx, dy) (any length). False when
    /// a vertex number or an edge name is left out at once, its anchor out of sight.
    bool Place(ScreenPoint anchor, std::string_view text, TextStyle style, Color color, float dx, float dy,
               float distance = 6.0f, LabelRank rank = LabelRank::Note);
    /// Place, kept out of `other` (a convex outline on screen, any orientation): the label of a body's vertex,
    /// edge or face never sits inside the other body of the pair, where it would read as that body's, unless its
    /// anchor lies inside that body. False as for Place.
    bool PlaceOutside(const std::vector<ScreenPoint>& other, ScreenPoint anchor, std::string_view text,
                      TextStyle style, Color color, float dx, float dy, float distance, LabelRank rank);
    /// Keeps the label added last (a vertex number placed with PlaceOutside whose corner is pushed into the other
    /// body) out of both bodies: out of `own`, the outline of its own body, and out of the other body though its
    /// anchor lies there, where it would read as that body's. Only the places near its corner are tried: with none
    /// free, a vertex number is left out and a named one hangs on a leader line.
    void OutsideBoth(std::vector<ScreenPoint> own);
    /// Keeps the label added last out of `outline` too (a convex outline on screen): a body's velocity out of the
    /// other body drawn where it will be (its dashed ghost), where it would read as that ghost's. With `leaderToo`
    /// its leader line does not cross the outline either (a face's name led across a ghost seems to start there).
    void KeepOutOf(std::vector<ScreenPoint> outline, bool leaderToo = false);
    /// Keeps the label added last out of `outline` (a convex outline) where a place near its anchor or on a short
    /// leader line allows; where none does, it is placed as if without it.
    void PreferOutOf(std::vector<ScreenPoint> outline);
    /// Lets the label added last sit beside any of `anchors` (points along the face or edge it names, nearest
    /// first) when no place near its own anchor is free: it slides along what it names, on its preferred side
    /// or the other, before it moves farther out on a leader line.
    void AlsoAt(std::vector<ScreenPoint> anchors);
    /// Lets the label added last (an arrow's name) sit beside any of `anchors` (points along the arrow's shaft, from
    /// its head back) when no place near its own anchor is free, square to its preferred direction on either side:
    /// beside its own arrow rather than beside another arrow's head.
    void AlsoBeside(std::vector<ScreenPoint> anchors);
    /// Keeps the leader line of the label added last (an arrow's name, anchored at its head, preferring the arrow's
    /// direction) from running on along the arrow past its head, where it reads as a longer shaft and hides the
    /// head, and, as LeadsOffEdges does, from crossing a body's edge while another place is free.
    void LeadsOffArrow();
    /// Keeps the leader line of the label added last from crossing a body's edge to a place beyond it, where it reads
    /// as naming that edge; a place that needs it is taken only when no other is free.
    void LeadsOffEdges();
    /// Tells the label added last (a face's name) the outline of its own body (on screen): with no room outside the
    /// face, it may sit farther inside that body, wholly within it, where it still reads as that face's.
    void Within(std::vector<ScreenPoint> own);
    /// Keeps the label added last on the side its preferred direction points to, beyond the line through its anchor
    /// square to that direction: an edge's name outside its edge, where it names that edge and not the one opposite.
    void KeepOnSide();
    /// Marks a point a label may name: a corner (`ofBody`: of a body as it stands, not of a dashed outline), a
    /// contact point, an arrow head (with the unit direction it points in, `toward`).
    void AddMark(MarkKind kind, ScreenPoint at, ScreenPoint toward = {}, bool ofBody = false);
    /// Tells the label added last that it names the mark of `kind` at its anchor: beside its anchor (or beside what
    /// leads to it, with AlsoBeside) it only takes a place nearer there than any other mark of the kind (farther out,
    /// its leader line shows which it names).
    void Names(MarkKind kind);
    /// Tells the label added last (a face's name: "e2", "reference face") that it names the face ab, of a body
    /// whose partner in the pair, and any ghost drawn, have the outlines `rivals` (on screen): beside its anchor it
    /// only takes a place whose middle lies clearly nearer that face than any rival's outline, where it would read as
    /// the rival's (a floor's "e2" beside the plank's corner, "reference face" over the small box inside the large
    /// one, a body's "e2" between its edge and its ghost's). Farther out, its leader line shows which face it names.
    void NamesFace(ScreenPoint a, ScreenPoint b, std::vector<std::vector<ScreenPoint>> rivals);
    /// Keeps the label added last (a face's name, after NamesFace) beside its face: its middle, taken along the
    /// face, between the face's two ends, or past an end only on a leader line that leaves the face steeply and
    /// keeps well clear of every edge; not beyond a corner beside the next face, where it reads as that face's.
    void InFaceSpan();
    /// Puts the label added last centred on its anchor when that place is free: a name inside the shape it names.
    /// Elsewhere it is placed as any other label.
    void Centre();
    /// Places every label added and draws them, in the group "labels": leader lines first, then each label on a
    /// faint halo of the background.
    void Flush(Color halo);

  private:
    struct Label
    {
        ScreenPoint anchor;
        std::string text;
        TextStyle style;
        Color color;
        float dx, dy, distance;
        LabelRank rank;
        std::vector<ScreenPoint> avoid; // a convex outline the label stays out of (empty: none)
        bool edgesOnly = false;         // the anchor lies inside `avoid`: the label only keeps off its edges
        bool onSide = false;            // the label's middle stays beyond its anchor along (dx, dy)
        std::vector<ScreenPoint> alternates; // other anchors along what it names, nearest first
        bool centred = false;                // tried first centred on its anchor
        std::vector<ScreenPoint> own;        // with OutsideBoth: its own body's outline, which it keeps out of too
        std::vector<std::vector<ScreenPoint>> keepOut; // more outlines it stays out of
        std::vector<ScreenPoint> home;                 // with Within: its own body, which it may sit deep in
        int names = -1;                                // with Names: the MarkKind it names, else -1
        bool across = false;                           // with AlsoBeside: beside its alternates, not beyond them
        std::vector<ScreenPoint> face;                 // with NamesFace: the face it names, and the rivals' outlines
        std::vector<std::vector<ScreenPoint>> rivals;
        std::vector<std::vector<ScreenPoint>> preferOut; // with PreferOutOf: outlines it keeps out of where it can
        std::vector<std::vector<ScreenPoint>> leaderOut; // with KeepOutOf(.., true): outlines its leader does not cross
        bool inSpan = false;                             // with InFaceSpan: its middle along `face` within it
        bool offArrow = false;                           // with LeadsOffArrow
        bool offEdges = false;                           // with LeadsOffEdges
    };
    struct Mark
    {
        MarkKind kind;
        ScreenPoint at;
        ScreenPoint toward; // an arrow head's direction, unit length
        bool ofBody;        // a corner of a body as it stands
    };
    struct Line
    {
        ScreenPoint a, b;
        float thickness;
        LabelRank from = LabelRank::Vertex; // the lowest rank of label that keeps off the line
        bool faint = false;                 // labels above LabelRank::Named keep off it only where the room allows
        bool parting = false;               // the separating line
        bool leader = false;                // a leader line drawn for a label placed before
        bool edge = false;                  // an edge of a body's outline
    };
    struct LeaderLine
    {
        ScreenPoint from, to;
        bool drawn = false; // false when the label sits too close to its anchor to need one
    };
    static LeaderLine Leader(ScreenPoint anchor, const ScreenRect& rect);
    bool LeaderClear(ScreenPoint anchor, const ScreenRect& rect) const;
    bool LeaderCrossesLine(ScreenPoint anchor, const ScreenRect& rect) const;
    bool LeaderRunsAlong(ScreenPoint anchor, const ScreenRect& rect) const;
    bool LeaderCrossesBar(ScreenPoint anchor, const ScreenRect& rect) const;
    bool LeaderAstray(const Label& label, ScreenPoint anchor, const ScreenRect& rect, bool edges) const;
    bool LeaderAlongGrid(ScreenPoint anchor, const ScreenRect& rect) const;
    bool Free(const ScreenRect& rect, float spacing, LabelRank rank, bool everyLine = false) const;
    bool Inside(const ScreenRect& rect) const;
    bool NearestOwn(const Label& label, const ScreenRect& rect, ScreenPoint at) const;
    bool NearestFace(const Label& label, const ScreenRect& rect) const;
    bool CutOffFromAnchor(const Label& label, const ScreenRect& rect, ScreenPoint at) const;
    bool AcrossParting(const Label& label, const ScreenRect& rect, ScreenPoint at) const;
    Canvas& m_canvas;
    float m_width;
    float m_height;
    std::vector<ScreenRect> m_taken;
    size_t m_reserved = 0; // while placing: m_taken holds the reserved regions before this index, labels after it
    std::vector<ScreenRect> m_bands;
    std::vector<Line> m_lines;
    std::vector<std::pair<ScreenPoint, ScreenPoint>> m_grid; // the grid's lines, which only leader lines keep off
    std::vector<std::vector<ScreenPoint>> m_shapes;
    std::vector<std::pair<ScreenPoint, ScreenPoint>> m_shafts;
    std::vector<Label> m_labels;
    std::vector<Mark> m_marks;
    std::vector<Color> m_takenColors; // the colour of each label placed, in m_taken's order from m_reserved on
    Color m_placing = 0;              // the colour of the label being placed
};

/// A canvas that draws on another and tells a label placer of every line it draws there: a body's outline, a
/// piece's seam, a dashed projection line or outline, a separating line, a path. No label is placed over one: the
/// label's halo would cut the line, and its words would read as part of it (an edge name on the separating line, a
/// vertex number on the dashed line from its corner to the axis). Only the faint grid and candidate axes under
/// everything (the groups "background" and "axes") and the labels' own leader lines are not told.
class LineWatch final : public Canvas
{
  public:
    /// Draws on `canvas`, telling `labels` of each line.
    LineWatch(Canvas& canvas, LabelPlacer& labels) : m_canvas(canvas), m_labels(labels) {}
    void Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness) override;
    void Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness) override;
    void FillConvex(const ScreenPoint* points, int count, Color color) override;
    void FillOutlined(const ScreenPoint* points, int count, Color fill, Color outline, float thickness) override;
    void Circle(ScreenPoint center, float radius, Color color, float thickness) override;
    void FillCircle(ScreenPoint center, float radius, Color color) override;
    void FillRect(ScreenPoint min, ScreenPoint max, Color color) override;
    void Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color) override;
    ScreenPoint MeasureText(std::string_view text, TextStyle style) override;
    void BeginGroup(std::string_view name) override;

  private:
    // Whether lines drawn now are ones a label keeps off.
    bool Watched(Color color) const;
    void Note(const ScreenPoint* points, int count, bool closed, Color color, float thickness);
    Canvas& m_canvas;
    LabelPlacer& m_labels;
    std::string m_group;
};

} // namespace satviz
