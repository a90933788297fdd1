// SPDX-License-Identifier: MIT
// The world's building blocks against independent computations: mass properties against closed forms and the
// shoelace sums about the origin, the material rule, and the validation of body definitions (the broadphase's tests
// are in test_broadphase.cpp).

#include "support/builders.h"
#include "support/random_shapes.h"
#include "support/world_scenes.h"

#include <satviz/collide.h>
#include <satviz/mass.h>
#include <satviz/material.h>
#include <satviz/world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

/// |a - b| <= rel * |b| (+ a tiny absolute floor for b == 0).
bool Near(double a, double b, double rel)
{
    return std::abs(a - b) <= rel * std::abs(b) + 1e-300;
}

/// The mass properties of a polygon from its outline alone, in long double: the shoelace area, the centroid, and
/// the polar second moment about the origin (each edge with the origin as a triangle), then the parallel-axis
/// theorem to move it to the centroid. A different fan from the library's (the origin, not the centroid).
struct ReferenceMass
{
    long double mass = 0;
    long double cx = 0;
    long double cy = 0;
    long double inertia = 0;
};

ReferenceMass Reference(const std::vector<Vec2>& points, double density)
{
    long double area2 = 0, sx = 0, sy = 0, polar = 0;
    const size_t n = points.size();
    for (size_t i = 0; i < n; ++i)
    {
        const long double px = points[i].x, py = points[i].y;
        const long double qx = points[(i + 1) % n].x, qy = points[(i + 1) % n].y;
        const long double cross = px * qy - qx * py;
        area2 += cross;
        sx += (px + qx) * cross;
        sy += (py + qy) * cross;
        polar += cross * (px * px + px * qx + qx * qx + py * py + py * qy + qy * qy);
    }
    ReferenceMass r;
    r.mass = density * area2 / 2;
    r.cx = sx / (3 * area2);
    r.cy = sy / (3 * area2);
    const long double polarOrigin = density * polar / 12;
    r.inertia = polarOrigin - r.mass * (r.cx * r.cx + r.cy * r.cy);
    return r;
}

std::vector<Vec2> Outline(const Polygon& polygon)
{
    return std::vector<Vec2>(polygon.Vertices().begin(), polygon.Vertices().end());
}

Shape PolygonShape(const std::vector<Vec2>& points)
{
    PolygonResult result = MakePolygon(points);
    REQUIRE(result.Ok());
    return MakeShape(result.polygon);
}

/// Lower case, without spaces and underscores: "staticFriction", "static friction" and "static_friction" alike.
std::string Folded(const std::string& s)
{
    std::string folded;
    for (unsigned char c : s)
    {
        if (c != ' ' && c != '_')
        {
            folded.push_back(static_cast<char>(std::tolower(c)));
        }
    }
    return folded;
}

} // namespace

TEST_CASE("ComputeMass of boxes matches the closed form", "[world][mass]")
{
    // Full sides w = 2 hx and h = 2 hy: m = rho w h, I = m (w^2 + h^2) / 12 about the centre.
    for (double hx : {0.01, 0.5, 1.0, 3.0, 250.0})
    {
        for (double hy : {0.02, 0.5, 2.0, 7.5})
        {
            for (double density : {0.1, 1.0, 37.0})
            {
                const MassProperties mp = ComputeMass(BoxShape(hx, hy), density);
                const double w = 2.0 * hx, h = 2.0 * hy;
                const double m = density * w * h;
                INFO("hx " << hx << ", hy " << hy << ", density " << density);
                CHECK(Near(mp.mass, m, 1e-13));
                CHECK(Near(mp.inertia, m * (w * w + h * h) / 12.0, 1e-12));
                CHECK(std::abs(mp.center.x) <= 1e-14 * (hx + hy));
                CHECK(std::abs(mp.center.y) <= 1e-14 * (hx + hy));
            }
        }
    }
}

TEST_CASE("ComputeMass of regular polygons matches the closed form", "[world][mass]")
{
    // n vertices on a circle of radius R: area n R^2 sin(2 pi / n) / 2, and about the centre
    // I = m R^2 (1 + 2 cos^2(pi / n)) / 6 (a square of side s: m s^2 / 6; n to infinity: m R^2 / 2).
    for (int n : {3, 4, 5, 6, 7, 8, 9, 12, 16, 33, 100})
    {
        for (double radius : {0.05, 1.0, 40.0})
        {
            for (double phase : {0.0, 0.3, 2.0})
            {
                PolygonResult result = MakeRegularPolygon(n, radius, phase);
                REQUIRE(result.Ok());
                const double density = 2.5;
                const MassProperties mp = ComputeMass(MakeShape(result.polygon), density);
                const double m = density * 0.5 * n * radius * radius * std::sin(2.0 * kPi / n);
                const double c = std::cos(kPi / n);
                INFO("n " << n << ", radius " << radius << ", phase " << phase);
                CHECK(Near(mp.mass, m, 1e-12));
                CHECK(Near(mp.inertia, m * radius * radius * (1.0 + 2.0 * c * c) / 6.0, 1e-12));
                CHECK(std::abs(mp.center.x) <= 1e-13 * radius);
                CHECK(std::abs(mp.center.y) <= 1e-13 * radius);
            }
        }
    }
}

TEST_CASE("ComputeMass of triangles matches the closed form", "[world][mass]")
{
    // A triangle with sides a, b, c: the centroid is the mean of the vertices, and the polar moment about it is
    // m (a^2 + b^2 + c^2) / 36.
    Rng rng(401);
    for (int k = 0; k < 2000; ++k)
    {
        std::vector<Vec2> points(3);
        for (Vec2& p : points)
        {
            p = {rng.Uniform(-3.0, 3.0), rng.Uniform(-3.0, 3.0)};
        }
        const double cross = Cross(points[1] - points[0], points[2] - points[0]);
        if (std::abs(cross) < 0.05)
        {
            continue;
        }
        if (cross < 0.0)
        {
            std::swap(points[1], points[2]);
        }
        const double density = rng.Uniform(0.1, 10.0);
        const MassProperties mp = ComputeMass(PolygonShape(points), density);
        const double m = density * 0.5 * std::abs(cross);
        const double sides2 = LengthSquared(points[1] - points[0]) + LengthSquared(points[2] - points[1]) +
                              LengthSquared(points[0] - points[2]);
        const Vec2 centroid = (1.0 / 3.0) * (points[0] + points[1] + points[2]);
        INFO("triangle " << k);
        REQUIRE(Near(mp.mass, m, 1e-12));
        REQUIRE(Near(mp.inertia, m * sides2 / 36.0, 1e-11));
        REQUIRE(std::abs(mp.center.x - centroid.x) <= 1e-13 * 3.0);
        REQUIRE(std::abs(mp.center.y - centroid.y) <= 1e-13 * 3.0);
    }
}

TEST_CASE("ComputeMass of circles, centred and off-centre", "[world][mass][circle]")
{
    // m = rho pi r^2, centre at the circle's centre, I = m r^2 / 2 about that centre wherever it sits in the body.
    for (double radius : {0.01, 0.5, 3.0, 100.0})
    {
        for (Vec2 center : {Vec2{0.0, 0.0}, Vec2{0.7, -0.2}, Vec2{-5.0, 12.0}, Vec2{1e4, 3e3}})
        {
            Circle circle;
            circle.radius = radius;
            circle.center = center;
            const double density = 3.0;
            const MassProperties mp = ComputeMass(MakeShape(circle), density);
            const double m = density * kPi * radius * radius;
            INFO("radius " << radius << ", centre " << center.x << ", " << center.y);
            CHECK(Near(mp.mass, m, 1e-14));
            CHECK(Near(mp.inertia, 0.5 * m * radius * radius, 1e-14));
            CHECK(mp.center == center);
        }
    }
}

TEST_CASE("ComputeMass of random convex polygons matches the shoelace sums about the origin", "[world][mass]")
{
    Rng rng(402);
    for (int k = 0; k < 3000; ++k)
    {
        const int n = rng.Chance(0.8) ? rng.Int(3, 12) : rng.Int(13, 120);
        const double radius = rng.LogUniform(-1.0, 1.0);
        const double aspect = rng.Chance(0.1) ? rng.LogUniform(-2.0, -1.0) : rng.Uniform(0.3, 1.0);
        Polygon polygon = RandomPolygon(rng, n, radius, aspect);
        // Off the origin by up to a few sizes, so the centroid is not at the body origin.
        const Vec2 shift{rng.Uniform(-3.0, 3.0) * radius, rng.Uniform(-3.0, 3.0) * radius};
        std::vector<Vec2> points = Outline(polygon);
        for (Vec2& p : points)
        {
            p = p + shift;
        }
        const double density = rng.LogUniform(-1.0, 1.0);
        const MassProperties mp = ComputeMass(PolygonShape(points), density);
        const ReferenceMass ref = Reference(points, density);
        INFO("polygon " << k << ", n " << n << ", radius " << radius << ", aspect " << aspect);
        REQUIRE(Near(mp.mass, static_cast<double>(ref.mass), 1e-12));
        // The reference loses digits in the parallel-axis step when the centroid is several sizes out; the error
        // bound scales with m |c|^2.
        const double scale =
            static_cast<double>(ref.mass * (ref.cx * ref.cx + ref.cy * ref.cy)) + static_cast<double>(ref.inertia);
        REQUIRE(std::abs(mp.inertia - static_cast<double>(ref.inertia)) <= 1e-12 * scale);
        REQUIRE(std::abs(mp.center.x - static_cast<double>(ref.cx)) <= 1e-13 * 4.0 * radius);
        REQUIRE(std::abs(mp.center.y - static_cast<double>(ref.cy)) <= 1e-13 * 4.0 * radius);
    }
}

TEST_CASE("Translating a polygon's vertices moves its centre and keeps its inertia about the centre", "[world][mass]")
{
    Rng rng(403);
    for (int k = 0; k < 500; ++k)
    {
        const int n = rng.Int(3, 24);
        const double radius = rng.Uniform(0.2, 2.0);
        const double aspect = rng.Uniform(0.2, 1.0);
        const Polygon polygon = RandomPolygon(rng, n, radius, aspect);
        const std::vector<Vec2> points = Outline(polygon);
        const MassProperties base = ComputeMass(MakeShape(polygon), 1.7);
        for (double distance : {1.0, 1e3, 1e5})
        {
            const double angle = rng.Uniform(0.0, 2.0 * kPi);
            const Vec2 offset{distance * std::cos(angle), distance * std::sin(angle)};
            std::vector<Vec2> moved = points;
            for (Vec2& p : moved)
            {
                p = p + offset;
            }
            const MassProperties mp = ComputeMass(PolygonShape(moved), 1.7);
            // The translated vertices are rounded to the spacing of doubles at `distance`: the shape itself changes
            // by that much, relative to its size.
            const double rounding = 4.0 * std::numeric_limits<double>::epsilon() * distance;
            INFO("polygon " << k << ", distance " << distance);
            REQUIRE(Near(mp.mass, base.mass, 1e-12 + 10.0 * rounding));
            REQUIRE(Near(mp.inertia, base.inertia, 1e-11 + 10.0 * rounding));
            REQUIRE(std::abs(mp.center.x - (base.center.x + offset.x)) <= 1e-13 + 4.0 * rounding);
            REQUIRE(std::abs(mp.center.y - (base.center.y + offset.y)) <= 1e-13 + 4.0 * rounding);
        }
    }
}

TEST_CASE("InnerRadius and OuterRadius of boxes and circles", "[world][mass]")
{
    const Shape box = BoxShape(2.0, 0.5);
    CHECK(InnerRadius(box, {0.0, 0.0}) == Approx(0.5).epsilon(1e-14));
    CHECK(OuterRadius(box, {0.0, 0.0}) == Approx(std::sqrt(4.25)).epsilon(1e-14));
    // About a point off the centre: the nearest face is 0.3 away, the farthest corner (-2, -0.5) from (0.5, 0.2).
    CHECK(InnerRadius(box, {0.5, 0.2}) == Approx(0.3).epsilon(1e-14));
    CHECK(OuterRadius(box, {0.5, 0.2}) == Approx(std::sqrt(2.5 * 2.5 + 0.7 * 0.7)).epsilon(1e-14));

    Circle circle;
    circle.radius = 1.5;
    circle.center = {3.0, 4.0};
    const Shape disc = MakeShape(circle);
    CHECK(InnerRadius(disc, {3.0, 4.0}) == Approx(1.5).epsilon(1e-14));
    CHECK(OuterRadius(disc, {3.0, 4.0}) == Approx(1.5).epsilon(1e-14));
    CHECK(InnerRadius(disc, {3.6, 4.8}) == Approx(0.5).epsilon(1e-14));
    CHECK(OuterRadius(disc, {3.6, 4.8}) == Approx(2.5).epsilon(1e-14));
    // A body whose origin is off the circle: the radii about the centre of mass do not depend on the origin.
    CHECK(OuterRadius(disc, ComputeMass(disc, 1.0).center) == Approx(1.5).epsilon(1e-14));
}

TEST_CASE("CombineMaterials takes the larger restitution and the geometric mean of the frictions", "[world][material]")
{
    Rng rng(404);
    for (int k = 0; k < 1000; ++k)
    {
        double c[6];
        for (double& x : c)
        {
            x = rng.Uniform(0.0, 2.0);
        }
        const Material a = MakeMaterial(0.5 * c[0], c[1], c[2]);
        const Material b = MakeMaterial(0.5 * c[3], c[4], c[5]);
        const ContactMaterial ab = CombineMaterials(a, b);
        const ContactMaterial ba = CombineMaterials(b, a);
        REQUIRE(ab.restitution == std::max(a.restitution, b.restitution));
        REQUIRE(Near(ab.friction, std::sqrt(a.friction * b.friction), 1e-15));
        REQUIRE(Near(ab.staticFriction, std::sqrt(a.staticFriction * b.staticFriction), 1e-15));
        REQUIRE(ab.restitution == ba.restitution);
        REQUIRE(ab.friction == ba.friction);
        REQUIRE(ab.staticFriction == ba.staticFriction);
    }
    // Ice against anything slides; a dead floor does not stop a bouncy ball bouncing.
    const ContactMaterial ice = CombineMaterials(MakeMaterial(0.0, 0.0, 0.0), MakeMaterial(0.2, 0.9, 1.1));
    CHECK(ice.friction == 0.0);
    CHECK(ice.staticFriction == 0.0);
    CHECK(ice.restitution == 0.2);
    const ContactMaterial same = CombineMaterials(MakeMaterial(0.5, 0.3, 0.4), MakeMaterial(0.5, 0.3, 0.4));
    CHECK(same.restitution == 0.5);
    CHECK(same.friction == Approx(0.3).epsilon(1e-15));
    CHECK(same.staticFriction == Approx(0.4).epsilon(1e-15));
    const ContactMaterial mixed = CombineMaterials(MakeMaterial(1.0, 0.25, 0.5), MakeMaterial(0.0, 1.0, 0.5));
    CHECK(mixed.restitution == 1.0);
    CHECK(mixed.friction == Approx(0.5).epsilon(1e-15));
    CHECK(mixed.staticFriction == Approx(0.5).epsilon(1e-15));
}

TEST_CASE("ComputeMass of lopsided polygons matches a sum over the cells of a fine grid", "[world][mass]")
{
    // Polygons with most vertices bunched on one side, so that the mean of the vertices lies far from the centre of
    // mass. The oracle sums the cells of a 1000 x 1000 grid whose centres lie inside: no formula of the polygon's
    // outline is used. The sum is off by about a cell's width along the outline, well below 1e-2 of each value.
    Rng rng(20261127);
    for (int i = 0; i < 12; ++i)
    {
        std::vector<Vec2> points{{-2.0, rng.Uniform(-0.5, 0.5)}};
        const int bunched = rng.Int(5, 9);
        for (int k = 0; k < bunched; ++k)
        {
            const double angle = -1.2 + 2.4 * k / (bunched - 1);
            points.push_back({1.0 + 0.3 * std::cos(angle), std::sin(angle)});
        }
        const Shape shape = PolygonShape(points);
        const Polygon& polygon = shape.polygon;
        const double density = rng.Uniform(0.5, 3.0);
        const MassProperties mass = ComputeMass(shape, density);
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (const Vec2& v : polygon.Vertices())
        {
            lo[0] = std::min(lo[0], v.x), hi[0] = std::max(hi[0], v.x);
            lo[1] = std::min(lo[1], v.y), hi[1] = std::max(hi[1], v.y);
        }
        constexpr int kCells = 1000;
        const double w = (hi[0] - lo[0]) / kCells, h = (hi[1] - lo[1]) / kCells;
        double area = 0.0, sx = 0.0, sy = 0.0, polar = 0.0;
        for (int r = 0; r < kCells; ++r)
        {
            for (int c = 0; c < kCells; ++c)
            {
                const Vec2 p{lo[0] + (c + 0.5) * w, lo[1] + (r + 0.5) * h};
                bool inside = true;
                for (int f = 0; f < polygon.Count() && inside; ++f)
                {
                    inside = Dot(polygon.Normal(f), p - polygon.Vertices()[f]) <= 0.0;
                }
                if (inside)
                {
                    area += w * h;
                    sx += w * h * p.x;
                    sy += w * h * p.y;
                    polar += w * h * LengthSquared(p);
                }
            }
        }
        const Vec2 center{sx / area, sy / area};
        const double inertia = density * (polar - area * LengthSquared(center));
        Vec2 mean{};
        for (const Vec2& v : polygon.Vertices())
        {
            mean = mean + (1.0 / polygon.Count()) * v;
        }
        INFO("polygon " << i << ": mass " << mass.mass << " against " << density * area << ", centre (" << mass.center.x
                        << ", " << mass.center.y << ") against (" << center.x << ", " << center.y
                        << "), inertia " << mass.inertia << " against " << inertia);
        // Lopsided: the centre lies far from the mean of the vertices.
        REQUIRE(Length(center - mean) > 0.3);
        CHECK(Near(mass.mass, density * area, 1e-2));
        CHECK(Length(mass.center - center) <= 1e-2);
        CHECK(Near(mass.inertia, inertia, 1e-2));
    }
}

TEST_CASE("ValidateBodyDef names the field that is wrong", "[world][validate]")
{
    BodyDef good;
    good.shape = BoxShape(0.5, 0.5);
    CHECK(ValidateBodyDef(good).empty());
    BodyDef staticZero = good;
    staticZero.type = BodyType::Static;
    staticZero.density = 0.0;
    CHECK(ValidateBodyDef(staticZero).empty()); // a static body has no mass
    BodyDef elastic = good;
    elastic.material.restitution = 1.0;
    CHECK(ValidateBodyDef(elastic).empty());

    struct Case
    {
        const char* what;
        BodyDef def;
        std::vector<const char*> names; // any of these must appear in the folded message
    };
    std::vector<Case> cases;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    {
        Case c{"negative density", good, {"density"}};
        c.def.density = -1.0;
        cases.push_back(c);
    }
    {
        Case c{"zero density", good, {"density"}};
        c.def.density = 0.0;
        cases.push_back(c);
    }
    {
        Case c{"NaN density", good, {"density"}};
        c.def.density = nan;
        cases.push_back(c);
    }
    {
        Case c{"negative friction", good, {"friction"}};
        c.def.material.friction = -0.1;
        cases.push_back(c);
    }
    {
        Case c{"negative static friction", good, {"staticfriction"}};
        c.def.material.staticFriction = -0.1;
        cases.push_back(c);
    }
    {
        Case c{"NaN velocity", good, {"velocity"}};
        c.def.velocity = {nan, 0.0};
        cases.push_back(c);
    }
    {
        Case c{"infinite velocity", good, {"velocity"}};
        c.def.velocity = {0.0, inf};
        cases.push_back(c);
    }
    {
        Case c{"NaN angular velocity", good, {"angularvelocity"}};
        c.def.angularVelocity = nan;
        cases.push_back(c);
    }
    {
        Case c{"NaN position", good, {"position"}};
        c.def.position = {0.0, nan};
        cases.push_back(c);
    }
    {
        Case c{"infinite angle", good, {"angle"}};
        c.def.angle = inf;
        cases.push_back(c);
    }
    {
        Case c{"restitution above 1", good, {"restitution"}};
        c.def.material.restitution = 1.5;
        cases.push_back(c);
    }
    {
        Case c{"negative restitution", good, {"restitution"}};
        c.def.material.restitution = -0.5;
        cases.push_back(c);
    }
    {
        Case c{"circle of zero radius", good, {"radius", "shape"}};
        c.def.shape = DiscShape(1.0);
        c.def.shape.circle.radius = 0.0;
        cases.push_back(c);
    }
    {
        Case c{"empty polygon", good, {"shape", "polygon"}};
        c.def.shape = MakeShape(Polygon());
        cases.push_back(c);
    }
    for (const Case& c : cases)
    {
        const std::string message = ValidateBodyDef(c.def);
        INFO(c.what << ": \"" << message << "\"");
        CHECK(!message.empty());
        const std::string lower = Folded(message);
        bool named = false;
        for (const char* name : c.names)
        {
            named = named || lower.find(name) != std::string::npos;
        }
        CHECK(named);
    }
}
