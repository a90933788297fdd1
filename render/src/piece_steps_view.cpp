// SPDX-License-Identifier: MIT
// The pieces figure: the SAT test of a pair with a concave body, step by step as the concave Collide runs it: the
// broadphase over the pieces' boxes, each pair of pieces whose boxes overlap tested as a convex pair, and the merged
// verdict.
#include "concave_views.h"
#include "legend.h"

#include <satviz/collide.h>
#include <satviz/render/describe.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz
{

namespace
{

// The shortest gap bar, in pixels, drawn as a bar alone; a shorter one gets ticks and arrows at its ends.
constexpr float kLeastGapBar = 8.0f;

} // namespace

namespace
{

constexpr float kMargin = 40.0f; // room around the pair, for the pieces' names

std::string Coordinate(double value)
{
    return value == 0.0 ? "0.00" : FormatNumber(value);
}

std::string Point(Vec2 p)
{
    return "(" + Coordinate(p.x) + ", " + Coordinate(p.y) + ")";
}

// The convex parts of a body: a concave body's pieces, or its one shape.
int PartCount(const Body& body)
{
    return body.IsConcave() ? static_cast<int>(body.concave.parts.size()) : 1;
}

const Shape& PartShape(const Body& body, int i)
{
    return body.IsConcave() ? body.concave.parts[static_cast<size_t>(i)].shape : body.shape;
}

// The normal `outward` (world, out of part i of the body) points along one of the part's seams: it is a seam's
// normal, or, for a vertex axis of that part, it leans past a corner into a seam's outer side (concave.h, rule 2).
bool AlongSeam(const Body& body, int i, Vec2 outward, const AxisRef& axis, int side)
{
    if (!body.IsConcave())
    {
        return false;
    }
    const ConcavePart& part = body.concave.parts[static_cast<size_t>(i)];
    const Polygon& polygon = part.shape.polygon;
    const Vec2 n = InvRotate(body.Xf().q, outward);
    const int count = polygon.Count();
    for (int e = 0; e < count; ++e)
    {
        if (part.internal[static_cast<size_t>(e)] &&
            Dot(n, polygon.Normal(e)) >= 1.0 - 64.0 * std::numeric_limits<double>::epsilon())
        {
            return true;
        }
    }
    if (axis.kind == AxisKind::VertexToCenter && axis.shape == side)
    {
        for (const int e : {(axis.index + count - 1) % count, axis.index})
        {
            if (part.internal[static_cast<size_t>(e)] && Dot(n, polygon.Normal(e)) > 0.0)
            {
                return true;
            }
        }
    }
    return false;
}

std::string PieceName(const Body& body, int i)
{
    return body.IsConcave() ? body.name + std::to_string(i + 1) : body.name;
}

Vec2 PartMiddle(const Body& body, int i)
{
    const Shape& shape = PartShape(body, i);
    if (shape.type == ShapeType::Circle)
    {
        return TransformPoint(body.Xf(), shape.circle.center);
    }
    Vec2 sum{};
    for (const Vec2& v : shape.polygon.Vertices())
    {
        sum = sum + v;
    }
    return TransformPoint(body.Xf(), (1.0 / shape.polygon.Count()) * sum);
}

// The interval part i of the body covers along unit direction n: [low, high].
void PartRange(const Body& body, int i, Vec2 n, double& low, double& high)
{
    const Shape& shape = PartShape(body, i);
    const Transform xf = body.Xf();
    if (shape.type == ShapeType::Circle)
    {
        const double c = Dot(TransformPoint(xf, shape.circle.center), n);
        low = c - shape.circle.radius;
        high = c + shape.circle.radius;
        return;
    }
    low = INFINITY;
    high = -INFINITY;
    for (const Vec2& v : shape.polygon.Vertices())
    {
        const double d = Dot(TransformPoint(xf, v), n);
        low = std::min(low, d);
        high = std::max(high, d);
    }
}

// The interval a piece's box covers along unit direction n: [low, high].
void BoxRange(const PieceBox& box, Vec2 n, double& low, double& high)
{
    low = INFINITY;
    high = -INFINITY;
    for (const Vec2 corner : {box.min, Vec2{box.max.x, box.min.y}, box.max, Vec2{box.min.x, box.max.y}})
    {
        low = std::min(low, Dot(corner, n));
        high = std::max(high, Dot(corner, n));
    }
}

} // namespace

PieceBox PartBox(const Body& body, int i)
{
    const Shape& shape = PartShape(body, i);
    const Transform xf = body.Xf();
    PieceBox box{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
    auto grow = [&](Vec2 p) {
        box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y)};
        box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y)};
    };
    // As the concave queries take it: the box of the piece's corners as placed.
    if (shape.type == ShapeType::Polygon)
    {
        for (const Vec2& v : shape.polygon.Vertices())
        {
            grow(TransformPoint(xf, v));
        }
    }
    else
    {
        const Vec2 c = TransformPoint(xf, shape.circle.center);
        grow(c - Vec2{shape.circle.radius, shape.circle.radius});
        grow(c + Vec2{shape.circle.radius, shape.circle.radius});
    }
    return box;
}

PieceStudy StudyPieces(const Body& a, const Body& b)
{
    PieceStudy study;
    for (int i = 0; i < PartCount(a); ++i)
    {
        study.boxesA.push_back(PartBox(a, i));
    }
    for (int j = 0; j < PartCount(b); ++j)
    {
        study.boxesB.push_back(PartBox(b, j));
    }
    for (int i = 0; i < PartCount(a); ++i)
    {
        for (int j = 0; j < PartCount(b); ++j)
        {
            const PieceBox& p = study.boxesA[static_cast<size_t>(i)];
            const PieceBox& q = study.boxesB[static_cast<size_t>(j)];
            if (p.min.x > q.max.x || q.min.x > p.max.x || p.min.y > q.max.y || q.min.y > p.max.y)
            {
                continue;
            }
            PiecePairTest test;
            test.i = i;
            test.j = j;
            test.manifold = Collide(PartShape(a, i), a.Xf(), PartShape(b, j), b.Xf());
            test.seam = test.manifold.overlap && (AlongSeam(a, i, test.manifold.normal, test.manifold.axis, 0) ||
                                                  AlongSeam(b, j, -test.manifold.normal, test.manifold.axis, 1));
            study.tested.push_back(test);
        }
    }
    const Transform xfA = a.Xf();
    const Transform xfB = b.Xf();
    study.merged = a.IsConcave() ? (b.IsConcave() ? Collide(a.concave, xfA, b.concave, xfB)
                                                  : Collide(a.concave, xfA, b.shape, xfB))
                                 : Collide(a.shape, xfA, b.concave, xfB);
    return study;
}

std::string DescribePieceStep(const Body& a, const Body& b, const PieceStudy& study, int step)
{
    const int pieces = PartCount(a) * PartCount(b);
    const int tested = static_cast<int>(study.tested.size());
    const std::string header = "Step " + std::to_string(step + 1) + " of " + std::to_string(tested + 2) + ": ";
    if (step == 0)
    {
        std::string list;
        for (size_t k = 0; k < study.tested.size(); ++k)
        {
            list += (k == 0 ? "" : (k + 1 == study.tested.size() ? " and " : ", ")) + PieceName(a, study.tested[k].i) +
                    " with " + PieceName(b, study.tested[k].j);
        }
        return header + "a broadphase over the pieces' boxes (grey, dashed). " + a.name + " has " +
               std::to_string(PartCount(a)) + (PartCount(a) == 1 ? " piece" : " pieces") + " and " + b.name + " " +
               std::to_string(PartCount(b)) + ", so there are " + std::to_string(pieces) + " pairs of pieces; " +
               (tested == 0 ? "no box of " + a.name + "'s pieces overlaps one of " + b.name + "'s, so no pair is tested."
                            : std::to_string(tested) + (tested == 1 ? " has" : " have") +
                                  " overlapping boxes: " + list + ". Only " + (tested == 1 ? "it is" : "these are") +
                                  " tested; pieces whose boxes are apart cannot touch.");
    }
    if (step <= tested)
    {
        const PiecePairTest& t = study.tested[static_cast<size_t>(step - 1)];
        const std::string pair = PieceName(a, t.i) + " against " + PieceName(b, t.j);
        const Manifold& m = t.manifold;
        if (!m.overlap)
        {
            return header + pair + ", two convex pieces tested as any convex pair: apart, with a gap of at least " +
                   FormatNumber(m.gap) + " along " + Point(m.normal) + ".";
        }
        std::string text = header + pair + ", two convex pieces tested as any convex pair: they overlap by " +
                           FormatNumber(m.depth) + " along " + Point(m.normal) + ", from " + a.name + " to " + b.name +
                           ".";
        if (t.seam)
        {
            const bool circle =
                PartShape(a, t.i).type == ShapeType::Circle || PartShape(b, t.j).type == ShapeType::Circle;
            text += " But that push (grey) points through a seam (dashed, inside the body), where the body goes on "
                    "past the piece: a ghost collision. " +
                    std::string(circle ? "The pair is left out, unless every overlapping pair is."
                                       : "The pair is tested again on the axes of the pieces' outline edges alone.");
        }
        return text;
    }
    const ConcaveManifold& merged = study.merged;
    if (!merged.manifold.overlap)
    {
        return header + "the verdict. No pair of pieces overlaps, so " + a.name + " and " + b.name +
               " do not overlap: the least gap is at least " + FormatNumber(merged.manifold.gap) + " along " +
               Point(merged.manifold.normal) + ".";
    }
    const int ia = std::max(0, merged.pieceA);
    const int jb = std::max(0, merged.pieceB);
    return header + "the verdict. " + std::to_string(merged.pairsOverlap) + " of the " + std::to_string(tested) +
           " pairs tested overlap; the deepest left after the seam rule, " + PieceName(a, ia) + " with " +
           PieceName(b, jb) + ", decides: " + a.name + " and " + b.name + " overlap by " +
           FormatNumber(merged.manifold.depth) + " along " + Point(merged.manifold.normal) + ", with " +
           std::to_string(merged.manifold.contactCount) +
           (merged.manifold.contactCount == 1 ? " contact" : " contacts") +
           ". The depths of the pairs are never added: moving " + b.name +
           " by the deciding depth clears that pair, "
           "and a sum would push a body lying across a seam twice.";
}

int PieceStepCount(const Scene& scene, const PairStudy& study)
{
    if (study.bodyA < 0 || study.bodyB < 0)
    {
        return 1;
    }
    return static_cast<int>(StudyPieces(scene.bodies[static_cast<size_t>(study.bodyA)],
                                        scene.bodies[static_cast<size_t>(study.bodyB)])
                                .tested.size()) +
           2;
}

namespace
{

// The pieces figure; `place`, when given, moves the picture aside for the key and puts the key there.
void PaintPieceStepsKeyed(Canvas& surface, const Scene& scene, const PairStudy& pair, const Figure& figure,
                          const KeyPlace* place)
{
    // Every line is drawn through the watch, so that the labels keep off it.
    LabelPlacer labels(surface, figure);
    LineWatch canvas(surface, labels);
    const Body& a = scene.bodies[static_cast<size_t>(pair.bodyA)];
    const Body& b = scene.bodies[static_cast<size_t>(pair.bodyB)];
    const PieceStudy study = StudyPieces(a, b);
    const int tested = static_cast<int>(study.tested.size());
    const int step = std::clamp(figure.step, 0, tested + 1);
    const float width = static_cast<float>(figure.view.width);
    const float height = static_cast<float>(figure.view.height);

    // One band for every step, as high as the longest step's text needs: stepping does not move the picture.
    int lines = 0;
    for (int k = 0; k <= tested + 1; ++k)
    {
        lines = std::max(lines, CaptionBandLines(canvas, figure.caption, DescribePieceStep(a, b, study, k), width));
    }
    const float top = DrawBackgroundAndCaption(canvas, labels, figure, DescribePieceStep(a, b, study, step), lines);

    Vec2 low{INFINITY, INFINITY};
    Vec2 high{-INFINITY, -INFINITY};
    for (const std::vector<PieceBox>* boxes : {&study.boxesA, &study.boxesB})
    {
        for (const PieceBox& box : *boxes)
        {
            low = {std::min(low.x, box.min.x), std::min(low.y, box.min.y)};
            high = {std::max(high.x, box.max.x), std::max(high.y, box.max.y)};
        }
    }
    const ScreenRect rect{0.0f, top, width, height};
    View view = figure.framesItself ? FramePanel(rect, low, high, figure.view.width, figure.view.height, kMargin).view
                                    : figure.view;
    if (place != nullptr)
    {
        view = MovedAside(view, *place);
    }

    // Which pieces this step is about: a tested pair's two, the deciding pair at the verdict, all at the broadphase.
    int focusA = -1;
    int focusB = -1;
    if (step >= 1 && step <= tested)
    {
        focusA = study.tested[static_cast<size_t>(step - 1)].i;
        focusB = study.tested[static_cast<size_t>(step - 1)].j;
    }
    else if (step == tested + 1 && (study.merged.manifold.overlap || std::isfinite(study.merged.manifold.gap)))
    {
        // The pair that decides: the deepest overlap, or apart the one with the least gap.
        focusA = std::max(0, study.merged.pieceA);
        focusB = std::max(0, study.merged.pieceB);
    }
    // Apart at the verdict, the least gap was found between two pieces tested as a convex pair, or between the boxes
    // of two pieces that the broadphase parted: those boxes are drawn, as the gap is theirs.
    const bool apartVerdict = step == tested + 1 && focusA >= 0 && !study.merged.manifold.overlap;
    const bool gapOfBoxes =
        apartVerdict && std::none_of(study.tested.begin(), study.tested.end(), [&](const PiecePairTest& t) {
            return t.i == focusA && t.j == focusB;
        });
    std::vector<LegendMark> used; // the marks drawn, for the key
    canvas.BeginGroup("pieces");
    for (int side = 0; side < 2; ++side)
    {
        const Body& body = side == 0 ? a : b;
        const int focus = side == 0 ? focusA : focusB;
        const Color color = side == 0 ? palette::kShapeA : palette::kShapeB;
        const Transform xf = body.Xf();
        for (int i = 0; i < PartCount(body); ++i)
        {
            const float fill = focusA < 0 ? 0.3f : (i == focus ? 0.45f : 0.08f);
            if (focusA >= 0 && PartCount(body) > 1)
            {
                used.push_back(LegendMark::FocusPiece);
            }
            const Shape& shape = PartShape(body, i);
            std::vector<ScreenPoint> points = ShapeOutline(view, shape, xf);
            canvas.FillConvex(points.data(), static_cast<int>(points.size()), WithAlpha(color, fill));
            if (shape.type == ShapeType::Polygon)
            {
                for (int e = 0; e < shape.polygon.Count(); ++e)
                {
                    const ScreenPoint p = ToScreen(view, TransformPoint(xf, shape.polygon.Vertices()[e]));
                    const ScreenPoint q =
                        ToScreen(view, TransformPoint(xf, shape.polygon.Vertices()[(e + 1) % shape.polygon.Count()]));
                    const bool seam =
                        body.IsConcave() && body.concave.parts[static_cast<size_t>(i)].internal[static_cast<size_t>(e)];
                    if (seam)
                    {
                        DashedSegment(canvas, p, q, WithAlpha(color, 0.8f), 1.2f, rect, 5.0f, 4.0f);
                        used.push_back(LegendMark::Seam);
                    }
                    else
                    {
                        canvas.Segment(p, q, side == 0 ? color : palette::kShapeBInk, 2.0f);
                    }
                }
            }
            else
            {
                canvas.Polyline(points.data(), static_cast<int>(points.size()), true, palette::kShapeBInk, 2.0f);
            }
            const ScreenPoint middle = ToScreen(view, PartMiddle(body, i));
            labels.Place(middle, PieceName(body, i), TextStyle::Heading,
                         side == 0 ? palette::kShapeA : palette::kShapeBInk, 0.0f, 0.0f, 0.0f, LabelRank::Name);
            // Beside the middle when the push drawn from there takes it, rather than on a leader line from the
            // push's tail, where it reads as naming the arrow.
            labels.AlsoAt({{middle.x, middle.y + 20.0f}, {middle.x, middle.y - 20.0f}, {middle.x - 30.0f, middle.y},
                           {middle.x + 30.0f, middle.y}});
        }
    }
    // The boxes: every piece's at the broadphase, the pair's own at a pair's step.
    canvas.BeginGroup("boxes");
    for (int side = 0; side < 2; ++side)
    {
        const std::vector<PieceBox>& boxes = side == 0 ? study.boxesA : study.boxesB;
        for (size_t i = 0; i < boxes.size(); ++i)
        {
            const int focus = side == 0 ? focusA : focusB;
            if (!(step == 0 || ((step <= tested || gapOfBoxes) && static_cast<int>(i) == focus)))
            {
                continue;
            }
            // Grey, and a few pixels outside the piece, so that a box's side along a seam is not read as the seam
            // (dashed in the body's colour) nor hidden on the outline.
            ScreenPoint p = ToScreen(view, boxes[i].min);
            ScreenPoint q = ToScreen(view, boxes[i].max);
            p = {p.x - 4.0f, p.y + 4.0f};
            q = {q.x + 4.0f, q.y - 4.0f};
            DashedOutline(canvas, {{p.x, p.y}, {q.x, p.y}, {q.x, q.y}, {p.x, q.y}}, kPieceBoxColor, kPieceBoxWidth,
                          rect);
            used.push_back(LegendMark::PieceBox);
        }
    }
    // A push: at a pair's step that pair's own, at the verdict the merged one; from the middle of B's piece.
    const Manifold* push = nullptr;
    bool seam = false;
    if (step >= 1 && step <= tested)
    {
        push = &study.tested[static_cast<size_t>(step - 1)].manifold;
        seam = study.tested[static_cast<size_t>(step - 1)].seam;
    }
    else if (step == tested + 1)
    {
        push = &study.merged.manifold;
    }
    if (push != nullptr && push->overlap && focusB >= 0)
    {
        canvas.BeginGroup("push");
        const Vec2 from = PartMiddle(b, focusB);
        const ScreenPoint start = ToScreen(view, from);
        const ScreenPoint e = ToScreen(view, from + push->depth * push->normal);
        const float length = std::hypot(e.x - start.x, e.y - start.y);
        // A push too short to see is drawn 24 pixels long: its direction is what the step is about.
        ScreenPoint tip = length >= 24.0f ? e
                                          : ScreenPoint{start.x + 24.0f * static_cast<float>(push->normal.x),
                                                        start.y - 24.0f * static_cast<float>(push->normal.y)};
        // A push from a middle that lies on a piece's edge (a box centred over the corner of an L) would be drawn
        // on that edge, the two one stroke: it moves aside, parallel, by a little more than its head's width.
        ScreenPoint s = start;
        const float dx = tip.x - s.x;
        const float dy = tip.y - s.y;
        const float shaft = std::max(std::hypot(dx, dy), 1e-3f);
        bool alongEdge = false;
        for (const Body* body : {&a, &b})
        {
            for (int i = 0; i < PartCount(*body) && !alongEdge; ++i)
            {
                const Shape& shape = PartShape(*body, i);
                for (int k = 0; shape.type == ShapeType::Polygon && k < shape.polygon.Count() && !alongEdge; ++k)
                {
                    const ScreenPoint u = ToScreen(view, TransformPoint(body->Xf(), shape.polygon.Vertices()[k]));
                    const ScreenPoint v = ToScreen(
                        view, TransformPoint(body->Xf(), shape.polygon.Vertices()[(k + 1) % shape.polygon.Count()]));
                    // Both ends of the shaft within 2 pixels of the edge's line, and the edge along the shaft.
                    const float ex = v.x - u.x;
                    const float ey = v.y - u.y;
                    const float edge = std::hypot(ex, ey);
                    const auto off = [&](ScreenPoint p) { return std::abs((p.x - u.x) * ey - (p.y - u.y) * ex) / edge; };
                    const auto along = [&](ScreenPoint p) { return ((p.x - u.x) * ex + (p.y - u.y) * ey) / edge; };
                    alongEdge = edge > 1.0f && off(s) < 2.0f && off(tip) < 2.0f &&
                                std::max(along(s), along(tip)) > 0.0f && std::min(along(s), along(tip)) < edge;
                }
            }
        }
        if (alongEdge)
        {
            const ScreenPoint side{-dy / shaft * 8.0f, dx / shaft * 8.0f};
            s = {s.x + side.x, s.y + side.y};
            tip = {tip.x + side.x, tip.y + side.y};
        }
        labels.Reserve(Arrow(canvas, s, tip, seam ? palette::kMuted : palette::kResult, 2.0f));
        used.push_back(seam ? LegendMark::SeamPush : LegendMark::Mtv);
        labels.ReserveLine(s, tip, 2.0f);
        labels.Place(tip, (seam ? "through a seam: " : "") + FormatNumber(push->depth), TextStyle::Label,
                     seam ? palette::kMuted : palette::kResult, tip.x - s.x, tip.y - s.y, 6.0f, LabelRank::Verdict);
        if (step == tested + 1)
        {
            for (int k = 0; k < push->contactCount; ++k)
            {
                const ScreenPoint c = ToScreen(view, push->contacts[k].point);
                canvas.FillCircle(c, 4.5f, palette::kResult);
                labels.Reserve({c.x - 5.0f, c.y - 5.0f, c.x + 5.0f, c.y + 5.0f});
                used.push_back(LegendMark::Contact);
            }
        }
    }
    if (apartVerdict)
    {
        // The gap, as the static convex verdict draws it: the separating line through its middle, perpendicular to the
        // normal, and the gap itself as a bar from one piece (or box) to the other, named by its size.
        canvas.BeginGroup("gap");
        const Vec2 n = study.merged.manifold.normal;
        const Vec2 across = LeftPerp(n);
        double loA = 0.0, hiA = 0.0, loB = 0.0, hiB = 0.0;
        double sideA[2] = {0.0, 0.0};
        double sideB[2] = {0.0, 0.0};
        if (gapOfBoxes)
        {
            BoxRange(study.boxesA[static_cast<size_t>(focusA)], n, loA, hiA);
            BoxRange(study.boxesB[static_cast<size_t>(focusB)], n, loB, hiB);
            BoxRange(study.boxesA[static_cast<size_t>(focusA)], across, sideA[0], sideA[1]);
            BoxRange(study.boxesB[static_cast<size_t>(focusB)], across, sideB[0], sideB[1]);
        }
        else
        {
            PartRange(a, focusA, n, loA, hiA);
            PartRange(b, focusB, n, loB, hiB);
            PartRange(a, focusA, across, sideA[0], sideA[1]);
            PartRange(b, focusB, across, sideB[0], sideB[1]);
        }
        const double gap = study.merged.manifold.gap;
        const double middle = hiA + 0.5 * gap;
        // The line runs where both pieces lie across the normal (else between them), a little beyond: it parts these
        // two, not the whole bodies, and must not cut through another piece of a concave body. The bar crosses in
        // the middle of that stretch.
        const double overlapLow = std::max(sideA[0], sideB[0]);
        const double overlapHigh = std::min(sideA[1], sideB[1]);
        const double spanLow = overlapLow <= overlapHigh ? overlapLow : overlapHigh;
        const double spanHigh = overlapLow <= overlapHigh ? overlapHigh : overlapLow;
        const double shared = 0.5 * (spanLow + spanHigh);
        const double reach = 0.1 * (spanHigh - spanLow) + 12.0 / view.zoom;
        const ScreenPoint lineFrom = ToScreen(view, middle * n + (spanLow - reach) * across);
        const ScreenPoint lineTo = ToScreen(view, middle * n + (spanHigh + reach) * across);
        DashedSegment(canvas, lineFrom, lineTo, palette::kGap, 2.5f, rect, 10.0f, 6.0f);
        labels.ReservePartingLine(lineFrom, lineTo, 2.5f);
        used.push_back(LegendMark::Separating);
        const ScreenPoint barFrom = ToScreen(view, hiA * n + shared * across);
        const ScreenPoint barTo = ToScreen(view, (hiA + gap) * n + shared * across);
        canvas.Segment(barFrom, barTo, palette::kGap, 4.0f);
        labels.ReserveLine(barFrom, barTo, 4.0f);
        // A gap of a few pixels is a bar too short to see: marked as a drawing marks a small dimension, its true
        // ends by ticks across it and two arrows from outside pointing at them, and named by its number.
        const float barDx = barTo.x - barFrom.x, barDy = barTo.y - barFrom.y;
        const float barLength = std::sqrt(barDx * barDx + barDy * barDy);
        if (barLength < kLeastGapBar)
        {
            const float ux = static_cast<float>(n.x), uy = -static_cast<float>(n.y); // n on the screen (y down)
            const float tx = -uy * 7.0f, ty = ux * 7.0f;
            for (const ScreenPoint& p : {barFrom, barTo})
            {
                canvas.Segment({p.x - tx, p.y - ty}, {p.x + tx, p.y + ty}, palette::kGap, 2.0f);
            }
            const ScreenPoint outA{barFrom.x - ux * 22.0f, barFrom.y - uy * 22.0f};
            const ScreenPoint outB{barTo.x + ux * 22.0f, barTo.y + uy * 22.0f};
            Arrow(canvas, outA, barFrom, palette::kGap, 2.0f, 7.0f);
            Arrow(canvas, outB, barTo, palette::kGap, 2.0f, 7.0f);
            labels.ReserveLine(outA, outB, 14.0f);
        }
        used.push_back(LegendMark::Gap);
        const std::string size = FormatNumber(gap);
        // At an end of the line, beyond it: in the gap itself a label would hide the bar or lie on a piece. Between
        // boxes the gap is a bound: the pieces may lie farther apart than their boxes.
        const ScreenPoint end = lineTo.y < lineFrom.y || (lineTo.y == lineFrom.y && lineTo.x > lineFrom.x) ? lineTo
                                                                                                            : lineFrom;
        const ScreenPoint start = end.x == lineTo.x && end.y == lineTo.y ? lineFrom : lineTo;
        labels.Place(end, (gapOfBoxes ? "gap at least " : "gap ") + size, TextStyle::Label, 0x006E50FFu,
                     end.x - start.x, end.y - start.y, 6.0f, LabelRank::Verdict);
    }
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    ScreenPoint keyAt{};
    if ((figure.layers & kLayerLegend) && !used.empty())
    {
        // The key in the corner of the picture that hides least of the pieces, kept free of labels.
        const ScreenPoint size = LegendSize(canvas, used, std::max(width - 16.0f, 120.0f));
        const ScreenPoint lo = ToScreen(view, low);
        const ScreenPoint hi = ToScreen(view, high);
        const ScreenRect pieces{std::min(lo.x, hi.x), std::min(lo.y, hi.y), std::max(lo.x, hi.x), std::max(lo.y, hi.y)};
        const float m = 8.0f;
        const ScreenPoint corners[4] = {{m, height - m - size.y},
                                        {width - m - size.x, height - m - size.y},
                                        {m, top + m},
                                        {width - m - size.x, top + m}};
        float least = INFINITY;
        for (const ScreenPoint& c : corners)
        {
            const float w = std::max(0.0f, std::min(c.x + size.x, pieces.maxX) - std::max(c.x, pieces.minX));
            const float h = std::max(0.0f, std::min(c.y + size.y, pieces.maxY) - std::max(c.y, pieces.minY));
            if (w * h < least)
            {
                least = w * h;
                keyAt = c;
            }
        }
        if (place != nullptr)
        {
            keyAt = place->at;
        }
        labels.ReserveBand({keyAt.x, keyAt.y, keyAt.x + size.x, keyAt.y + size.y});
    }
    labels.Flush(palette::kBackground);
    if ((figure.layers & kLayerLegend) && !used.empty())
    {
        PaintLegend(surface, keyAt, used, std::max(width - 16.0f, 120.0f));
    }
}

} // namespace

void PaintPieceSteps(Canvas& surface, const Scene& scene, const PairStudy& pair, const Figure& figure)
{
    if ((figure.layers & kLayerLegend) && figure.framesItself)
    {
        // The key must hide no piece and no label: drawn once unseen, the picture shows what it covers and the key's
        // size; then the picture moves aside for the key (scaled down if need be) and is drawn again.
        RecordingCanvas unseen;
        PaintPieceStepsKeyed(unseen, scene, pair, figure, nullptr);
        const std::vector<const DrawCommand*> key = unseen.InGroup("legend");
        float top = 0.0f;
        for (const DrawCommand* c : unseen.InGroup("caption"))
        {
            if (c->kind == DrawCommand::Kind::FillRect)
            {
                top = std::max(top, c->points[1].y);
            }
        }
        if (!key.empty() && key[0]->kind == DrawCommand::Kind::FillRect)
        {
            const ScreenPoint size{key[0]->points[1].x - key[0]->points[0].x,
                                   key[0]->points[1].y - key[0]->points[0].y};
            const ScreenRect area{0.0f, top, static_cast<float>(figure.view.width),
                                  static_cast<float>(figure.view.height)};
            const KeyPlace place = PlaceKey(area, KeyObstacles(unseen, area), size, false);
            PaintPieceStepsKeyed(surface, scene, pair, figure, &place);
            return;
        }
    }
    PaintPieceStepsKeyed(surface, scene, pair, figure, nullptr);
}

} // namespace satviz
