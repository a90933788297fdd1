// SPDX-License-Identifier: MIT
#include "voronoi_view.h"

#include <satviz/render/palette.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace satviz
{

namespace
{

// The polygon of the pair in world coordinates, the other shape's centre, and the region that centre lies in.
struct Regions
{
    bool ok = false;
    int shape = 0;       // 0: the polygon is A, 1: it is B
    std::vector<Vec2> v; // vertices, counter-clockwise
    std::vector<Vec2> n; // n[i]: unit outward normal of edge i, from v[i] to v[i + 1]
    Vec2 point;          // the other shape's centre
    double reach = 0.0;  // how far the other shape reaches from that centre
    enum class Kind
    {
        Inside,
        Face,
        Vertex
    } kind = Kind::Inside;
    int index = 0; // the edge or vertex whose region holds the point
};

Regions FindRegions(const Scene& scene, const PairStudy& study)
{
    Regions r;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    r.shape = bodies[0]->shape.type == ShapeType::Polygon ? 0 : 1;
    const Body& polygon = *bodies[r.shape];
    const Body& other = *bodies[1 - r.shape];
    if (polygon.shape.type != ShapeType::Polygon)
    {
        return r;
    }
    const Transform xf = polygon.Xf();
    const auto& poly = polygon.shape.polygon;
    for (int i = 0; i < poly.Count(); ++i)
    {
        r.v.push_back(TransformPoint(xf, poly.Vertices()[i]));
        r.n.push_back(Rotate(xf.q, poly.Normal(i)));
    }
    const Transform otherXf = other.Xf();
    r.point = TransformPoint(otherXf, other.shape.type == ShapeType::Circle ? other.shape.circle.center
                                                                            : other.shape.polygon.Centroid());
    if (other.shape.type == ShapeType::Circle)
    {
        r.reach = other.shape.circle.radius;
    }
    else
    {
        for (const Vec2& v : other.shape.polygon.Vertices())
        {
            r.reach = std::max(r.reach, Length(v - other.shape.polygon.Centroid()));
        }
    }
    const int count = static_cast<int>(r.v.size());
    // A vertex's region: the point lies behind both edges that meet there, measured along each edge away from the
    // vertex, so the vertex is its nearest point of the outline.
    for (int i = 0; i < count; ++i)
    {
        const Vec2 d = r.point - r.v[static_cast<size_t>(i)];
        const Vec2 next = r.v[static_cast<size_t>((i + 1) % count)] - r.v[static_cast<size_t>(i)];
        const Vec2 previous = r.v[static_cast<size_t>((i + count - 1) % count)] - r.v[static_cast<size_t>(i)];
        if (Dot(d, next) <= 0.0 && Dot(d, previous) <= 0.0)
        {
            r.kind = Regions::Kind::Vertex;
            r.index = i;
            r.ok = true;
            return r;
        }
    }
    // A face's region: in front of the edge and between the normals through its ends.
    for (int i = 0; i < count; ++i)
    {
        const Vec2 d = r.point - r.v[static_cast<size_t>(i)];
        const Vec2 edge = r.v[static_cast<size_t>((i + 1) % count)] - r.v[static_cast<size_t>(i)];
        if (Dot(d, r.n[static_cast<size_t>(i)]) > 0.0 && Dot(d, edge) >= 0.0 && Dot(d, edge) <= Dot(edge, edge))
        {
            r.kind = Regions::Kind::Face;
            r.index = i;
            r.ok = true;
            return r;
        }
    }
    r.kind = Regions::Kind::Inside;
    r.ok = true;
    return r;
}

// Clips a convex polygon to the image (Sutherland-Hodgman against its four sides), so that regions that run to
// infinity are drawn as far as the picture goes and no farther.
std::vector<ScreenPoint> ClipToImage(std::vector<ScreenPoint> points, float width, float height)
{
    auto clip = [&](auto inside, auto cross) {
        std::vector<ScreenPoint> out;
        for (size_t i = 0; i < points.size(); ++i)
        {
            const ScreenPoint a = points[i];
            const ScreenPoint b = points[(i + 1) % points.size()];
            if (inside(a))
            {
                out.push_back(a);
            }
            if (inside(a) != inside(b))
            {
                out.push_back(cross(a, b));
            }
        }
        points = out;
    };
    auto at = [](ScreenPoint a, ScreenPoint b, float t) {
        return ScreenPoint{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    };
    clip([](ScreenPoint p) { return p.x >= 0.0f; },
         [&](ScreenPoint a, ScreenPoint b) { return at(a, b, a.x / (a.x - b.x)); });
    clip([&](ScreenPoint p) { return p.x <= width; },
         [&](ScreenPoint a, ScreenPoint b) { return at(a, b, (width - a.x) / (b.x - a.x)); });
    clip([](ScreenPoint p) { return p.y >= 0.0f; },
         [&](ScreenPoint a, ScreenPoint b) { return at(a, b, a.y / (a.y - b.y)); });
    clip([&](ScreenPoint p) { return p.y <= height; },
         [&](ScreenPoint a, ScreenPoint b) { return at(a, b, (height - a.y) / (b.y - a.y)); });
    return points;
}

// A length in world units that reaches past every corner of the image from any vertex of the polygon.
double Reach(const View& view, const Regions& r)
{
    const Vec2 corner0 = ToWorld(view, {0.0f, 0.0f});
    const Vec2 corner1 = ToWorld(view, {static_cast<float>(view.width), static_cast<float>(view.height)});
    double far = Length(corner1 - corner0);
    for (const Vec2& v : r.v)
    {
        far = std::max(far, 2.0 * Length(v - corner0) + Length(corner1 - corner0));
    }
    return far;
}

Color RegionColor(int shape)
{
    return shape == 0 ? palette::kShapeA : palette::kShapeB;
}

Color RegionInk(int shape)
{
    return shape == 0 ? palette::kShapeA : palette::kShapeBInk;
}

} // namespace

void PaintVoronoiRegions(Canvas& canvas, const View& view, const Scene& scene, const PairStudy& study)
{
    const Regions r = FindRegions(scene, study);
    if (!r.ok)
    {
        return;
    }
    canvas.BeginGroup("voronoi");
    const float width = static_cast<float>(view.width);
    const float height = static_cast<float>(view.height);
    const double reach = Reach(view, r);
    const int count = static_cast<int>(r.v.size());
    const Color hue = RegionColor(r.shape);
    auto fill = [&](const std::vector<Vec2>& world, Color color) {
        std::vector<ScreenPoint> screen;
        for (const Vec2& p : world)
        {
            screen.push_back(ToScreen(view, p));
        }
        screen = ClipToImage(screen, width, height);
        if (screen.size() >= 3)
        {
            canvas.FillConvex(screen.data(), static_cast<int>(screen.size()), color);
        }
    };
    for (int i = 0; i < count; ++i)
    {
        const Vec2 a = r.v[static_cast<size_t>(i)];
        const Vec2 b = r.v[static_cast<size_t>((i + 1) % count)];
        const Vec2 n = r.n[static_cast<size_t>(i)];
        const Vec2 before = r.n[static_cast<size_t>((i + count - 1) % count)];
        const bool faceHolds = r.kind == Regions::Kind::Face && r.index == i;
        const bool vertexHolds = r.kind == Regions::Kind::Vertex && r.index == i;
        fill({a, b, b + reach * n, a + reach * n},
             faceHolds ? WithAlpha(palette::kResult, 0.16f) : WithAlpha(hue, 0.07f));
        fill({a, a + reach * before, a + reach * (before + n), a + reach * n},
             vertexHolds ? WithAlpha(palette::kResult, 0.16f) : WithAlpha(hue, 0.2f));
    }
    const ScreenRect bounds{-4.0f, -4.0f, width + 4.0f, height + 4.0f};
    for (int i = 0; i < count; ++i)
    {
        const Vec2 a = r.v[static_cast<size_t>(i)];
        for (const Vec2& n : {r.n[static_cast<size_t>(i)], r.n[static_cast<size_t>((i + count - 1) % count)]})
        {
            DashedSegment(canvas, ToScreen(view, a), ToScreen(view, a + reach * n), WithAlpha(RegionInk(r.shape), 0.5f),
                          1.0f, bounds, 6.0f, 5.0f);
        }
    }
}

void MarkVoronoiRegions(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene,
                        const PairStudy& study)
{
    const Regions r = FindRegions(scene, study);
    if (!r.ok)
    {
        return;
    }
    canvas.BeginGroup("voronoi");
    // The centre is marked as the shapes layer marks a circle's centre, a small dot in the body's colour: the
    // vermillion dot means a contact point.
    const ScreenPoint centre = ToScreen(view, r.point);
    constexpr float kDot = 2.5f;
    canvas.FillCircle(centre, kDot, r.shape == 0 ? palette::kShapeB : palette::kShapeA);
    labels.Reserve({centre.x - kDot - 2.0f, centre.y - kDot - 2.0f, centre.x + kDot + 2.0f, centre.y + kDot + 2.0f});
    const int count = static_cast<int>(r.v.size());
    const Color ink = WithAlpha(RegionInk(r.shape), 0.8f);
    // Each region's name sits well out from the polygon, along the edge's normal or the corner's bisector; the
    // region holding the centre is named first, in the result colour, beyond the other shape so as not to cover it.
    const double out = 70.0 / view.zoom;
    const double beyond = Length(r.point - r.v[static_cast<size_t>(r.index)]) + r.reach + 24.0 / view.zoom;
    for (int pass = 0; pass < 2; ++pass)
    {
        for (int i = 0; i < count; ++i)
        {
            const Vec2 a = r.v[static_cast<size_t>(i)];
            const Vec2 b = r.v[static_cast<size_t>((i + 1) % count)];
            const Vec2 n = r.n[static_cast<size_t>(i)];
            const Vec2 bisector = Normalize(r.n[static_cast<size_t>((i + count - 1) % count)] + n);
            const bool faceHolds = r.kind == Regions::Kind::Face && r.index == i;
            const bool vertexHolds = r.kind == Regions::Kind::Vertex && r.index == i;
            if (faceHolds == (pass == 0))
            {
                const Vec2 at =
                    0.5 * (a + b) + (faceHolds ? Dot(r.point - a, n) + r.reach + 24.0 / view.zoom : out) * n;
                labels.Place(ToScreen(view, at),
                             (faceHolds ? "the centre's region: face e" : "face e") + std::to_string(i),
                             TextStyle::Label, faceHolds ? palette::kResult : ink, static_cast<float>(n.x),
                             static_cast<float>(-n.y), 0.0f,
                             faceHolds ? LabelRank::Verdict : LabelRank::Vertex);
            }
            if (vertexHolds == (pass == 0))
            {
                const Vec2 at = a + (vertexHolds ? beyond : out) * bisector;
                labels.Place(ToScreen(view, at),
                             (vertexHolds ? "the centre's region: vertex " : "vertex ") + std::to_string(i),
                             TextStyle::Label, vertexHolds ? palette::kResult : ink, static_cast<float>(bisector.x),
                             static_cast<float>(-bisector.y), 0.0f,
                             vertexHolds ? LabelRank::Verdict : LabelRank::Vertex);
            }
        }
    }
}

} // namespace satviz
