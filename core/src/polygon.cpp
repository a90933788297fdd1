// SPDX-License-Identifier: MIT
// satviz: polygon validation and construction (MakePolygon, ComputeHull, MakeBox, MakeRegularPolygon).

#include <satviz/polygon.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace satviz
{
namespace
{

template <typename S>
PolygonResultT<S> Fail(PolygonError error, int vertex)
{
    PolygonResultT<S> result;
    result.error = error;
    result.vertex = vertex;
    return result;
}

// NotFinite or TooLarge for the first offending point; an empty result (Ok) when every point is acceptable.
template <typename S>
PolygonResultT<S> CheckCoordinates(const std::vector<Vec2T<S>>& points)
{
    for (size_t i = 0; i < points.size(); ++i)
    {
        if (!IsFinite(points[i]))
        {
            return Fail<S>(PolygonError::NotFinite, static_cast<int>(i));
        }
        if (std::abs(points[i].x) > S(kMaxCoordinate) || std::abs(points[i].y) > S(kMaxCoordinate))
        {
            return Fail<S>(PolygonError::TooLarge, static_cast<int>(i));
        }
    }
    return {};
}

// Relative tolerance under which a turn counts as straight: the cross product of two edge vectors carries a
// rounding error of a few ulps of |e1| |e2|, so smaller turns have no reliable sign.
template <typename S>
constexpr S kCollinearTolerance = S(8) * std::numeric_limits<S>::epsilon();

template <typename S>
bool IsStraightTurn(Vec2T<S> e1, Vec2T<S> e2)
{
    const S cross = Cross(e1, e2);
    return std::abs(cross) <= kCollinearTolerance<S> * Length(e1) * Length(e2);
}

// Drops repeated vertices and vertices on the line through their neighbours until none is left.
template <typename S>
void RemoveDuplicateAndCollinear(std::vector<Vec2T<S>>& points)
{
    bool changed = true;
    while (changed && points.size() >= 3)
    {
        changed = false;
        const size_t n = points.size();
        for (size_t i = 0; i < n; ++i)
        {
            const Vec2T<S> prev = points[(i + n - 1) % n];
            const Vec2T<S> next = points[(i + 1) % n];
            if (points[i] == prev || IsStraightTurn(points[i] - prev, next - points[i]))
            {
                points.erase(points.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
                break;
            }
        }
    }
}

} // namespace

template <typename S>
S SignedArea2(const std::vector<Vec2T<S>>& points)
{
    const size_t n = points.size();
    if (n < 3)
    {
        return S(0);
    }
    // Relative to the first vertex, so far-away outlines keep their precision.
    S area = S(0);
    const Vec2T<S> origin = points[0];
    for (size_t i = 1; i + 1 < n; ++i)
    {
        area += Cross(points[i] - origin, points[i + 1] - origin);
    }
    return area;
}

template <typename S>
PolygonResultT<S> MakePolygon(const std::vector<Vec2T<S>>& input, PolygonOptions options)
{
    if (PolygonResultT<S> bad = CheckCoordinates(input); !bad.Ok())
    {
        return bad;
    }

    std::vector<Vec2T<S>> points = input;
    if (options.repair)
    {
        RemoveDuplicateAndCollinear(points);
        if (points.size() >= 3 && SignedArea2(points) < S(0))
        {
            std::reverse(points.begin(), points.end());
        }
    }

    const int n = static_cast<int>(points.size());
    if (n < 3)
    {
        return Fail<S>(PolygonError::TooFewVertices, -1);
    }
    for (int i = 0; i < n; ++i)
    {
        if (points[i] == points[(i + n - 1) % n])
        {
            return Fail<S>(PolygonError::DuplicateVertex, i);
        }
    }

    // Classify the turn at every vertex.
    int leftTurns = 0;
    int rightTurns = 0;
    for (int i = 0; i < n; ++i)
    {
        const Vec2T<S> e1 = points[i] - points[(i + n - 1) % n];
        const Vec2T<S> e2 = points[(i + 1) % n] - points[i];
        if (IsStraightTurn(e1, e2))
        {
            return Fail<S>(PolygonError::CollinearVertex, i);
        }
        (Cross(e1, e2) > S(0) ? leftTurns : rightTurns) += 1;
    }
    if (leftTurns == 0)
    {
        return Fail<S>(PolygonError::Clockwise, -1);
    }
    if (rightTurns > 0)
    {
        // Report the first vertex that turns against the outline's overall winding.
        const bool counterClockwise = SignedArea2(points) > S(0);
        for (int i = 0; i < n; ++i)
        {
            const Vec2T<S> e1 = points[i] - points[(i + n - 1) % n];
            const Vec2T<S> e2 = points[(i + 1) % n] - points[i];
            if ((Cross(e1, e2) > S(0)) != counterClockwise)
            {
                return Fail<S>(PolygonError::NotConvex, i);
            }
        }
    }

    // Every turn is to the left: the outline is convex and simple exactly when it turns once around (2 pi), not
    // two or more times (a star such as the pentagram turns 4 pi).
    double turning = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const Vec2T<S> e1 = points[i] - points[(i + n - 1) % n];
        const Vec2T<S> e2 = points[(i + 1) % n] - points[i];
        turning += std::atan2(static_cast<double>(Cross(e1, e2)), static_cast<double>(Dot(e1, e2)));
    }
    constexpr double kPi = 3.14159265358979323846;
    if (turning > 3.0 * kPi)
    {
        return Fail<S>(PolygonError::SelfIntersecting, -1);
    }

    // One block: the vertices, vertex 0 again (so that edges need no wrapped index), then the normals.
    std::vector<Vec2T<S>> storage(2 * static_cast<size_t>(n) + 1);
    for (int i = 0; i < n; ++i)
    {
        storage[i] = points[i];
        storage[n + 1 + i] = Normalize(RightPerp(points[(i + 1) % n] - points[i]));
    }
    storage[n] = points[0];
    // Area centroid as the area-weighted mean of the triangles fanned from vertex 0, relative to vertex 0.
    S area = S(0);
    Vec2T<S> moment{};
    for (int i = 1; i + 1 < n; ++i)
    {
        const Vec2T<S> e1 = points[i] - points[0];
        const Vec2T<S> e2 = points[i + 1] - points[0];
        const S triangle = Cross(e1, e2);
        area += triangle;
        moment = moment + (triangle / S(3)) * (e1 + e2);
    }
    PolygonResultT<S> result;
    result.polygon = PolygonT<S>::FromStorage(std::move(storage), points[0] + (S(1) / area) * moment);
    return result;
}

template <typename S>
PolygonResultT<S> ComputeHull(const std::vector<Vec2T<S>>& input)
{
    if (PolygonResultT<S> bad = CheckCoordinates(input); !bad.Ok())
    {
        return bad;
    }
    std::vector<Vec2T<S>> points = input;
    std::sort(points.begin(), points.end(),
              [](Vec2T<S> a, Vec2T<S> b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
    {
        return Fail<S>(PolygonError::TooFewVertices, -1);
    }

    // Andrew's monotone chain: lower hull left to right, then upper hull right to left, keeping strict left turns.
    std::vector<Vec2T<S>> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i)
    {
        while (k >= 2 && Cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= S(0))
        {
            --k;
        }
        hull[k++] = points[i];
    }
    const size_t lower = k + 1;
    for (size_t i = points.size() - 1; i-- > 0;)
    {
        while (k >= lower && Cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= S(0))
        {
            --k;
        }
        hull[k++] = points[i];
    }
    hull.resize(k - 1);

    PolygonOptions options;
    options.repair = true;
    return MakePolygon(hull, options);
}

template <typename S>
PolygonResultT<S> MakeBox(S halfWidth, S halfHeight)
{
    const S x = halfWidth;
    const S y = halfHeight;
    return MakePolygon(std::vector<Vec2T<S>>{{-x, -y}, {x, -y}, {x, y}, {-x, y}});
}

template <typename S>
PolygonResultT<S> MakeRegularPolygon(int sides, S radius, S phase)
{
    if (sides < 3)
    {
        return Fail<S>(PolygonError::TooFewVertices, -1);
    }
    std::vector<Vec2T<S>> points(static_cast<size_t>(sides));
    for (int i = 0; i < sides; ++i)
    {
        const double angle = static_cast<double>(phase) + 2.0 * 3.14159265358979323846 * i / sides;
        points[static_cast<size_t>(i)] = {static_cast<S>(radius * std::cos(angle)),
                                          static_cast<S>(radius * std::sin(angle))};
    }
    return MakePolygon(points);
}

std::string DescribePolygonError(PolygonError error, int vertex)
{
    const std::string at = vertex >= 0 ? " " + std::to_string(vertex) : std::string();
    switch (error)
    {
    case PolygonError::None:
        return "polygon is valid";
    case PolygonError::TooFewVertices:
        return "polygon needs at least 3 distinct vertices that span an area";
    case PolygonError::NotFinite:
        return "vertex" + at + " is not a finite number";
    case PolygonError::TooLarge:
        return "vertex" + at + " exceeds 1e12 in magnitude";
    case PolygonError::DuplicateVertex:
        return "vertex" + at + " repeats the vertex before it (remove it)";
    case PolygonError::CollinearVertex:
        return "vertex" + at + " lies on the line through its neighbours (remove it)";
    case PolygonError::Clockwise:
        return "polygon winds clockwise (list the vertices counter-clockwise, y up)";
    case PolygonError::NotConvex:
        return "polygon is not convex at vertex" + at + " (use a convex decomposition)";
    case PolygonError::SelfIntersecting:
        return "polygon intersects itself (its outline winds around more than once)";
    }
    return "unknown polygon error";
}

template double SignedArea2(const std::vector<Vec2T<double>>&);
template float SignedArea2(const std::vector<Vec2T<float>>&);
template PolygonResultT<double> MakePolygon(const std::vector<Vec2T<double>>&, PolygonOptions);
template PolygonResultT<float> MakePolygon(const std::vector<Vec2T<float>>&, PolygonOptions);
template PolygonResultT<double> ComputeHull(const std::vector<Vec2T<double>>&);
template PolygonResultT<float> ComputeHull(const std::vector<Vec2T<float>>&);
template PolygonResultT<double> MakeBox(double, double);
template PolygonResultT<float> MakeBox(float, float);
template PolygonResultT<double> MakeRegularPolygon(int, double, double);
template PolygonResultT<float> MakeRegularPolygon(int, float, float);

} // namespace satviz
