// SPDX-License-Identifier: MIT
#include "outline_edit.h"

#include <satviz/decompose.h>
#include <satviz/polygon.h>

#include <utility>

namespace satviz
{

std::vector<Vec2> EditableOutline(const Body& body)
{
    if (body.IsConcave())
    {
        return body.outline;
    }
    if (body.shape.type != ShapeType::Polygon)
    {
        return {};
    }
    return {body.shape.polygon.Vertices().begin(), body.shape.polygon.Vertices().end()};
}

bool InsideOutline(const std::vector<Vec2>& outline, Vec2 local)
{
    bool inside = false;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
    {
        const Vec2& a = outline[i];
        const Vec2& b = outline[j];
        if ((a.y > local.y) != (b.y > local.y) && local.x < (b.x - a.x) * (local.y - a.y) / (b.y - a.y) + a.x)
        {
            inside = !inside;
        }
    }
    return inside;
}

std::string ReshapeToOutline(Body& body, const std::vector<Vec2>& outline)
{
    const Decomposition pieces = Decompose(outline, body.decompose);
    if (!pieces.Ok())
    {
        return DescribeDecomposeError(pieces, outline);
    }
    if (pieces.pieces.size() == 1)
    {
        // Convex: the vertices as given, so that a dragged vertex keeps its index, or reversed when they run
        // clockwise. A vertex repeated or on the line through its neighbours is refused, as a scene refuses it for
        // a convex polygon: dropping it would renumber the vertices under a drag.
        PolygonResult made = MakePolygon(outline);
        if (!made.Ok() && made.error == PolygonError::Clockwise)
        {
            made = MakePolygon(std::vector<Vec2>(outline.rbegin(), outline.rend()));
        }
        if (!made.Ok())
        {
            const std::string why = DescribePolygonError(made.error, made.vertex);
            return why.substr(0, why.find(" ("));
        }
        body.shape = MakeShape(std::move(made.polygon));
        body.concave.parts.clear();
        body.outline.clear();
        return "";
    }
    body.concave = MakeConcave(pieces.pieces);
    std::vector<Vec2> corners;
    for (const ConcavePart& part : body.concave.parts)
    {
        corners.insert(corners.end(), part.shape.polygon.Vertices().begin(), part.shape.polygon.Vertices().end());
    }
    body.shape = MakeShape(ComputeHull(corners).polygon);
    body.outline = outline;
    return "";
}

Vec2 OutlineCentroid(const std::vector<Vec2>& outline)
{
    const Vec2 o = outline.front();
    double area2 = 0.0;
    Vec2 first{};
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const Vec2 p = outline[i] - o;
        const Vec2 q = outline[(i + 1) % outline.size()] - o;
        const double cross = Cross(p, q);
        area2 += cross;
        first = first + cross * (p + q);
    }
    return area2 == 0.0 ? o : o + (1.0 / (3.0 * area2)) * first;
}

} // namespace satviz
