// SPDX-License-Identifier: MIT
// satviz render, private: the figures of concave shapes, each drawn in panels of its own rather than as a step of
// the pair's SAT test: a decomposition by both methods side by side, a body before and after a cut, a thick bullet,
// a concave pair's test piece by piece. What they share:
// a caption band, panels framed on a world box, pieces in colours of their own with their seams dashed.
#pragma once

#include "draw_kit.h"
#include "label_placer.h"

#include <satviz/decompose.h>
#include <satviz/disc_cast.h>
#include <satviz/render/painter.h>

#include <string>
#include <vector>

namespace satviz
{

/// A framed part of a figure: its screen rectangle and the camera that shows its world box inside it.
struct Panel
{
    ScreenRect rect;
    View view;
};

/// The panel over `rect` that shows the world box [low, high] whole, centred, `margin` pixels inside the rectangle,
/// at `zoom` pixels per unit when zoom > 0 (panels side by side at one scale) or else the largest that fits.
Panel FramePanel(const ScreenRect& rect, Vec2 low, Vec2 high, int width, int height, float margin, double zoom = 0.0);

/// The largest zoom at which the world box [low, high] fits in `rect` with `margin` pixels around it.
double FitZoom(const ScreenRect& rect, Vec2 low, Vec2 high, float margin);

/// The colour of piece i: the Okabe-Ito hues in turn, so that neighbouring pieces differ.
Color PieceColor(int i);

/// Draws the caption band at the top of the figure: the scene's title (when not empty) in the heading style, then
/// `text` wrapped to the width, the band at least `lines` lines high (steps of one figure keep one band, so that
/// the picture does not move between them). Returns the band's bottom edge.
float DrawCaptionBand(Canvas& canvas, const std::string& title, const std::string& text, float width, int lines = 0);

/// The lines DrawCaptionBand takes for this title and text.
int CaptionBandLines(Canvas& canvas, const std::string& title, const std::string& text, float width);

/// Opens a figure of panels: the background over the whole image, then, with the caption layer, the caption band of
/// `text` under the figure's caption (at least `lines` lines high), which labels keep off. Returns the band's bottom
/// edge, 0 without the caption layer.
float DrawBackgroundAndCaption(Canvas& canvas, LabelPlacer& labels, const Figure& figure, const std::string& text,
                               int lines = 0);

/// Draws convex pieces placed by xf: each filled in its own colour, its outline edges solid ink and each seam
/// between two pieces dashed once (drawn from the piece where it runs from the lower vertex index to the higher).
void DrawPieces(Canvas& canvas, const View& view, const std::vector<ConvexPiece>& pieces, const Transform& xf,
                const ScreenRect& bounds);

/// The vertices of a polygon body in its frame: a concave body's outline as written, else its polygon's vertices.
std::vector<Vec2> BodyOutline(const Body& body);

/// The decomposition figure (FigureKind::Decomposition): the body cut by Fast and by Fewest side by side, each
/// panel's pieces in their own colours, seams dashed, piece numbers and counts, reflex vertices ringed.
void PaintDecomposition(Canvas& canvas, const Scene& scene, int body, const Figure& figure);

/// The caption of the decomposition figure: the outline's vertices and reflex vertices, both methods' pieces and
/// seams, and the least number of pieces any decomposition needs, from the two decompositions of the outline.
std::string DescribeDecomposition(const std::vector<Vec2>& outline, const Decomposition& fast,
                                  const Decomposition& fewest);

/// The points where the segment from a to b crosses the closed outline (world), in order from a, each once.
std::vector<Vec2> CutCrossings(const std::vector<Vec2>& outline, Vec2 a, Vec2 b);

/// The slice figure (FigureKind::Slice): the body before and after the cut along the view's `cut` segment, side by
/// side at one scale: the cut and its crossings of the outline, then each part in a colour of its own, drawn a
/// little apart, cut into convex pieces, with its area.
void PaintSlice(Canvas& canvas, const Scene& scene, int body, const Figure& figure);

/// The caption of the slice figure: the cut's ends, where it crosses the outline, the parts' areas and their sum,
/// and each part's convex pieces (`pieces`, one decomposition per part), or why nothing was cut.
std::string DescribeSlice(const Body& body, Vec2 a, Vec2 b, const std::vector<std::vector<Vec2>>& parts,
                          const std::vector<Decomposition>& pieces);

/// Where the figure's disc, `disc` (a circle moving along its velocity), first touches `target`: CastDisc.
DiscHit CastFigureDisc(const Body& target, const Body& disc);

/// The disc-cast figure (FigureKind::DiscCast): the disc at its start and end, the path of its centre and the band
/// it sweeps, the target's outline pushed out by the radius (dashed), and where the disc first touches: its centre on
/// that outline, the contact point and the normal.
void PaintDiscCast(Canvas& canvas, const Scene& scene, int target, int disc, const Figure& figure);

/// The caption of the disc-cast figure: the disc's radius and path, and the hit as numbers a reader can check
/// (centre = contact point + radius * normal), or why there is none.
std::string DescribeDiscCast(const Body& target, const Body& disc, const DiscHit& hit);

/// A piece's box in the world, as the concave queries' broadphase compares them.
struct PieceBox
{
    Vec2 min;
    Vec2 max;
};

/// One pair of pieces whose boxes overlap, tested as a convex pair.
struct PiecePairTest
{
    int i = 0;         ///< A's piece (0 for a convex body)
    int j = 0;         ///< B's piece
    Manifold manifold; ///< Collide on the two pieces
    bool seam = false; ///< they overlap and the push points through a seam of either (rule 2 of concave.h)
};

/// A pair with a concave body, piece by piece: the boxes, the pairs tested in order, and the merged answer.
struct PieceStudy
{
    std::vector<PieceBox> boxesA;
    std::vector<PieceBox> boxesB;
    std::vector<PiecePairTest> tested;
    ConcaveManifold merged; ///< the concave Collide on the pair
};

/// The box of part i of a body (a concave body's piece i, else its shape), in the world.
PieceBox PartBox(const Body& body, int i);

/// Tests the pair piece by piece as the concave Collide does, keeping each step.
PieceStudy StudyPieces(const Body& a, const Body& b);

/// The sentence of step `step` of the pieces figure: 0 the broadphase, 1 .. tested the pairs, then the verdict.
std::string DescribePieceStep(const Body& a, const Body& b, const PieceStudy& study, int step);

/// Steps of the pieces figure of the pair: the broadphase, one per pair tested, the verdict.
int PieceStepCount(const Scene& scene, const PairStudy& study);

/// The pieces figure (FigureKind::Pieces): the step `figure.step` of the concave pair's test.
void PaintPieceSteps(Canvas& canvas, const Scene& scene, const PairStudy& study, const Figure& figure);

} // namespace satviz
