// SPDX-License-Identifier: MIT
// satviz: mass properties of shapes of uniform density.

#include <satviz/mass.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

// Outline (Ericson, Real-Time Collision Detection, 2005; Catto, Box2D's polygon mass):
//  1. Fan the polygon into triangles from a point inside it (the vertex average), so each triangle's coordinates
//     are small and the sums keep their digits wherever the polygon sits in its frame.
//  2. Per triangle with edge vectors e1, e2 from the apex: area D / 2 with D = cross(e1, e2); its centroid at
//     (e1 + e2) / 3; its second moment about the apex D / 12 (e1.x^2 + e1.x e2.x + e2.x^2 + the same in y).
//  3. Sum, scale by the density, and move the moment from the apex to the centre of mass (parallel axes).
MassProperties ComputeMass(const Shape& shape, double density)
{
    MassProperties mass;
    if (shape.type == ShapeType::Circle)
    {
        const double r2 = shape.circle.radius * shape.circle.radius;
        mass.mass = density * 3.14159265358979323846 * r2;
        mass.center = shape.circle.center;
        mass.inertia = 0.5 * mass.mass * r2;
        return mass;
    }
    const Polygon& polygon = shape.polygon;
    const int n = polygon.Count();
    Vec2 apex{};
    for (const Vec2& v : polygon.Vertices())
    {
        apex = apex + v;
    }
    apex = (1.0 / n) * apex;

    double area = 0.0;
    Vec2 first{};
    double second = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const Vec2 e1 = polygon.Vertices()[i] - apex;
        const Vec2 e2 = polygon.Vertices()[i + 1 < n ? i + 1 : 0] - apex;
        const double d = Cross(e1, e2);
        area += 0.5 * d;
        first = first + (d / 6.0) * (e1 + e2);
        const double xx = e1.x * e1.x + e1.x * e2.x + e2.x * e2.x;
        const double yy = e1.y * e1.y + e1.y * e2.y + e2.y * e2.y;
        second += (d / 12.0) * (xx + yy);
    }
    const Vec2 offset = (1.0 / area) * first;
    mass.mass = density * area;
    mass.center = apex + offset;
    mass.inertia = density * second - mass.mass * Dot(offset, offset);
    return mass;
}

double InnerRadius(const Shape& shape, Vec2 center)
{
    if (shape.type == ShapeType::Circle)
    {
        return std::max(0.0, shape.circle.radius - Length(center - shape.circle.center));
    }
    const Polygon& polygon = shape.polygon;
    double inner = INFINITY;
    for (int i = 0; i < polygon.Count(); ++i)
    {
        inner = std::min(inner, Dot(polygon.Normal(i), polygon.Vertices()[i] - center));
    }
    return std::max(0.0, inner);
}

double OuterRadius(const Shape& shape, Vec2 center)
{
    if (shape.type == ShapeType::Circle)
    {
        return Length(center - shape.circle.center) + shape.circle.radius;
    }
    double outer2 = 0.0;
    for (const Vec2& v : shape.polygon.Vertices())
    {
        outer2 = std::max(outer2, LengthSquared(v - center));
    }
    return std::sqrt(outer2);
}

double TurnRadius(const Shape& shape, Vec2 center)
{
    if (shape.type == ShapeType::Circle)
    {
        return Length(center - shape.circle.center);
    }
    return OuterRadius(shape, center);
}

MassProperties ComputeMass(const Concave& shape, double density)
{
    MassProperties total;
    Vec2 moment{};
    for (const ConcavePart& part : shape.parts)
    {
        const MassProperties piece = ComputeMass(part.shape, density);
        total.mass += piece.mass;
        moment = moment + piece.mass * piece.center;
    }
    if (!(total.mass > 0.0))
    {
        return total;
    }
    total.center = (1.0 / total.mass) * moment;
    for (const ConcavePart& part : shape.parts)
    {
        const MassProperties piece = ComputeMass(part.shape, density);
        total.inertia += piece.inertia + piece.mass * LengthSquared(piece.center - total.center);
    }
    return total;
}

double InnerRadius(const Concave& shape)
{
    double inner = INFINITY;
    for (const ConcavePart& part : shape.parts)
    {
        inner = std::min(inner, InnerRadius(part.shape, part.shape.polygon.Centroid()));
    }
    return shape.parts.empty() ? 0.0 : inner;
}

double OuterRadius(const Concave& shape, Vec2 center)
{
    double outer = 0.0;
    for (const ConcavePart& part : shape.parts)
    {
        outer = std::max(outer, OuterRadius(part.shape, center));
    }
    return outer;
}

} // namespace satviz
