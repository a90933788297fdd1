// SPDX-License-Identifier: MIT
// satviz render, private: the "legend" layer, a key to the colours and marks of a figure, each drawn as the
// painter draws it beside one line that says what it means.
#pragma once

#include "draw_kit.h"

#include <satviz/render/palette.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/render/view.h>

#include <cmath>
#include <vector>

namespace satviz
{

/// A colour or mark a figure can use, in the order the key lists them.
enum class LegendMark
{
    CandidateAxis, ///< the long grey dashes through the pair: every candidate axis
    AxisArrow,  ///< the grey arrow named "axis N" (or "face test N") beside the pair: the axis tested, its direction
    Projection, ///< the blue and orange bars along the axis, with thin dashed guides from the shapes: their intervals
    AxisFace,   ///< the thick dark edge whose normal is the current axis
    Normal,     ///< a short arrow on a face: its outward normal, in its body's colour, black on the axis's face
    VertexAxis, ///< the dark dot and dashed line: an axis from a vertex (or a centre) to a circle's centre
    BestAxis,   ///< the light-blue edges of the best axis so far (of axes that tie, the first tested)
    Overlap,    ///< the pink band: the two intervals overlap
    Gap,        ///< the green band: a gap between the intervals
    Behind,     ///< the band of a face test: how far the other shape lies behind (or beyond) the face
    Swept,      ///< the pale bar: the interval B sweeps from t = 0 to 1 (a step; a second in a world's scene)
    TimeMarks,  ///< the dark triangles on the time bar: entry and exit
    Impact,     ///< the vermillion tick on the time bar: the time of first contact
    Window,     ///< the pink band on the time bar: the times at which every axis so far overlaps
    NoWindow,   ///< the orange band under the time bar: the axes' windows do not meet, no common time
    Other,      ///< a grey body: not in the tested pair (a wall, a mark)
    Centre,     ///< a small dot in a circle: its centre
    Asleep,     ///< a hatched body: asleep in a world (neither moved nor tested)
    Reference,  ///< the thick edge in a body's colour: the reference face
    Incident,   ///< the doubled edge: the incident edge
    SidePlanes, ///< the thin grey dashed lines at the reference face's ends: its side planes
    Contact,    ///< the vermillion dots: contact points
    Mtv,        ///< the vermillion arrow: the minimum translation vector
    Dashed,     ///< a dashed outline: a body at another time, or moved out by the MTV
    Separating, ///< the green dashed line: a separating line
    PitfallPush, ///< the black dashed arrow and outline: a pitfall's wrong push, beside the right one, and where it
                 ///< leaves B when the pair overlaps
    Cut,        ///< the vermillion line with dots: a cut, and where it crosses the outline
    FocusPiece, ///< a convex piece filled darker than the others: the piece of the pair at hand, or that decides
    PieceFills, ///< fills in turn sky blue, orange, green, yellow: each part of a cut, or each convex piece, in its own
    Reflex,     ///< the vermillion ring round a corner of a concave outline: a reflex vertex
    Seam,       ///< the thin dashed line inside a concave body: a seam between two of its convex pieces
    PieceBox,   ///< the grey dashed rectangle round a piece: its box, which the broadphase compares
    SeamPush,   ///< the grey arrow: a pair of pieces' push that points through a seam, which the seam rule drops
};

/// The colour of a piece's box in the pieces figure and its key: grey dashes, apart from the body's own seams.
constexpr Color kPieceBoxColor = palette::kMuted;
/// The width of a piece's box's dashes.
constexpr float kPieceBoxWidth = 1.2f;

/// How the candidate axes are drawn, in the figure and its key: long grey dashes, unlike the grid's solid lines.
constexpr Color kCandidateAxisColor = WithAlpha(palette::kMuted, 0.6f);
/// The width of a candidate axis's dashes.
constexpr float kCandidateAxisWidth = 1.2f;
/// The length of a candidate axis's dashes.
constexpr float kCandidateAxisDash = 14.0f;
/// The gap between a candidate axis's dashes.
constexpr float kCandidateAxisGap = 6.0f;

/// How the axis tested is drawn beside the pair, in the figure and its key: a grey arrow this wide ...
constexpr float kAxisArrowWidth = 1.5f;
/// ... with a head this long.
constexpr float kAxisArrowHead = 11.0f;
/// The width of an interval's bar along the axis, in the figure and its key.
constexpr float kIntervalBar = 6.0f;

/// Every mark, in the key's order.
std::vector<LegendMark> AllLegendMarks();

/// The size of the key to `marks`, at most `maxWidth` pixels wide where its meanings can wrap between their words
/// to fit (a narrow canvas); one line per mark when it fits.
ScreenPoint LegendSize(Canvas& canvas, const std::vector<LegendMark>& marks, float maxWidth = INFINITY);

/// Draws the key to `marks` with its top-left corner at `topLeft`, in the group "legend": a panel, and one row per
/// mark, its swatch drawn as the figure draws it, then its meaning, wrapped as LegendSize wraps it to `maxWidth`.
void PaintLegend(Canvas& canvas, ScreenPoint topLeft, const std::vector<LegendMark>& marks,
                 float maxWidth = INFINITY);

/// Where a figure that frames itself draws its key, and how its picture moves aside for it.
struct KeyPlace
{
    ScreenPoint at{};    ///< the key's top-left corner
    double scale = 1.0;  ///< the picture's scale about its content, at most 1
    ScreenPoint from{};  ///< the middle of the content before the move
    ScreenPoint to{};    ///< where that middle goes
};

/// The place of a key of `size` in a corner of the scene area `scene` (never its top right one when
/// `skipTopRight`, the Minkowski inset's): the first corner whose key leaves `content` (what the picture draws
/// there) uncovered, else the corner and side that keep the content largest beside or above or below the key,
/// the content scaled down about its middle and moved as little as it can.
KeyPlace PlaceKey(const ScreenRect& scene, const ScreenRect& content, ScreenPoint size, bool skipTopRight);

/// The camera `view` with its picture scaled and moved as `place` says, so that the content keeps clear of the key.
View MovedAside(const View& view, const KeyPlace& place);

/// The bounds, inside `scene`, of what a figure recorded on `canvas` draws there but its background, grid,
/// candidate axes, Voronoi regions, Minkowski inset, key and texts (labels are placed round the key): the content
/// its key must not cover.
ScreenRect KeyObstacles(const RecordingCanvas& canvas, const ScreenRect& scene);

} // namespace satviz
