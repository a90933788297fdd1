// SPDX-License-Identifier: MIT
// The expansion arithmetic of support/exact.h against long-integer arithmetic, and the exact tie-breaking of the
// reference (support/reference.h) against a long-integer oracle on touching and near-touching pairs.

#include "support/exact.h"
#include "support/random_shapes.h"
#include "support/reference.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

// Every double of these tests is a multiple of 2^-kScale: the oracle reads it as an integer scaled by 2^kScale.
constexpr int kScale = 160;

// A signed integer of any size, for the oracle: sign (-1, 0, +1) and magnitude in base 2^32, least significant limb
// first, without leading zero limbs.
struct BigInt
{
    int sign = 0;
    std::vector<uint32_t> limbs;
};

void Trim(std::vector<uint32_t>& limbs)
{
    while (!limbs.empty() && limbs.back() == 0)
    {
        limbs.pop_back();
    }
}

BigInt Make(int sign, std::vector<uint32_t> limbs)
{
    Trim(limbs);
    return {limbs.empty() ? 0 : sign, limbs};
}

int CompareMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b)
{
    if (a.size() != b.size())
    {
        return a.size() < b.size() ? -1 : 1;
    }
    for (size_t i = a.size(); i-- > 0;)
    {
        if (a[i] != b[i])
        {
            return a[i] < b[i] ? -1 : 1;
        }
    }
    return 0;
}

std::vector<uint32_t> AddMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b)
{
    std::vector<uint32_t> out(std::max(a.size(), b.size()) + 1);
    uint64_t carry = 0;
    for (size_t i = 0; i < out.size(); ++i)
    {
        const uint64_t sum = carry + (i < a.size() ? a[i] : 0) + (i < b.size() ? b[i] : 0);
        out[i] = static_cast<uint32_t>(sum);
        carry = sum >> 32;
    }
    return out;
}

// a - b for |a| >= |b|.
std::vector<uint32_t> SubtractMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b)
{
    std::vector<uint32_t> out(a.size());
    int64_t borrow = 0;
    for (size_t i = 0; i < a.size(); ++i)
    {
        int64_t difference = int64_t(a[i]) - (i < b.size() ? int64_t(b[i]) : 0) - borrow;
        borrow = difference < 0 ? 1 : 0;
        out[i] = static_cast<uint32_t>(difference + (borrow << 32));
    }
    return out;
}

BigInt operator-(BigInt a)
{
    a.sign = -a.sign;
    return a;
}

BigInt operator+(const BigInt& a, const BigInt& b)
{
    if (a.sign == 0)
    {
        return b;
    }
    if (b.sign == 0)
    {
        return a;
    }
    if (a.sign == b.sign)
    {
        return Make(a.sign, AddMagnitude(a.limbs, b.limbs));
    }
    const int order = CompareMagnitude(a.limbs, b.limbs);
    if (order == 0)
    {
        return {};
    }
    return order > 0 ? Make(a.sign, SubtractMagnitude(a.limbs, b.limbs))
                     : Make(b.sign, SubtractMagnitude(b.limbs, a.limbs));
}

BigInt operator-(const BigInt& a, const BigInt& b)
{
    return a + (-b);
}

BigInt operator*(const BigInt& a, const BigInt& b)
{
    if (a.sign == 0 || b.sign == 0)
    {
        return {};
    }
    std::vector<uint32_t> out(a.limbs.size() + b.limbs.size());
    for (size_t i = 0; i < a.limbs.size(); ++i)
    {
        uint64_t carry = 0;
        for (size_t j = 0; j < b.limbs.size(); ++j)
        {
            const uint64_t current = out[i + j] + uint64_t(a.limbs[i]) * b.limbs[j] + carry;
            out[i + j] = static_cast<uint32_t>(current);
            carry = current >> 32;
        }
        out[i + b.limbs.size()] = static_cast<uint32_t>(carry);
    }
    return Make(a.sign * b.sign, out);
}

// d * 2^scale, which must be an integer.
BigInt FromDouble(double d, int scale)
{
    if (d == 0.0)
    {
        return {};
    }
    int exponent = 0;
    const double fraction = std::frexp(std::fabs(d), &exponent); // |d| = fraction 2^exponent, fraction in [0.5, 1)
    uint64_t mantissa = static_cast<uint64_t>(std::ldexp(fraction, 53));
    int shift = exponent - 53 + scale;
    if (shift < 0)
    {
        if (shift <= -64 || (mantissa & ((uint64_t(1) << -shift) - 1)) != 0)
        {
            FAIL("" << d << " is not a multiple of 2^-" << scale);
        }
        mantissa >>= -shift;
        shift = 0;
    }
    std::vector<uint32_t> limbs(static_cast<size_t>(shift / 32), 0u);
    const unsigned __int128 shifted = static_cast<unsigned __int128>(mantissa) << (shift % 32);
    for (int k = 0; k < 3; ++k)
    {
        limbs.push_back(static_cast<uint32_t>(shifted >> (32 * k)));
    }
    return Make(d > 0 ? 1 : -1, limbs);
}

// The value of an expansion scaled by 2^scale.
BigInt FromExpansion(const Expansion& e, int scale)
{
    BigInt sum;
    for (const double component : e)
    {
        sum = sum + FromDouble(component, scale);
    }
    return sum;
}

bool operator==(const BigInt& a, const BigInt& b)
{
    return a.sign == b.sign && a.limbs == b.limbs;
}

// The lowest set bit of a nonzero double, as a power of two.
double LowestBit(double d)
{
    int exponent = 0;
    uint64_t mantissa = static_cast<uint64_t>(std::ldexp(std::frexp(std::fabs(d), &exponent), 53));
    int trailing = 0;
    while ((mantissa & 1) == 0)
    {
        mantissa >>= 1;
        ++trailing;
    }
    return std::ldexp(1.0, exponent - 53 + trailing);
}

// Nonzero components, each below the lowest set bit of the next: nonoverlapping, by increasing magnitude.
bool IsExpansion(const Expansion& e)
{
    for (size_t i = 0; i < e.size(); ++i)
    {
        if (e[i] == 0.0 || (i + 1 < e.size() && !(std::fabs(e[i]) < LowestBit(e[i + 1]))))
        {
            return false;
        }
    }
    return true;
}

// A point of the oracle: world coordinates scaled by 2^(2 kScale).
struct BigPoint
{
    BigInt x;
    BigInt y;
};

// c x - s y + px, s x + c y + py with every double read exactly.
BigPoint BigWorld(const Transform& xf, Vec2 v)
{
    const BigInt c = FromDouble(xf.q.c, kScale), s = FromDouble(xf.q.s, kScale);
    const BigInt x = FromDouble(v.x, kScale), y = FromDouble(v.y, kScale);
    return {c * x - s * y + FromDouble(xf.p.x, 2 * kScale), s * x + c * y + FromDouble(xf.p.y, 2 * kScale)};
}

std::vector<BigPoint> BigWorld(const Polygon& polygon, const Transform& xf)
{
    std::vector<BigPoint> out;
    for (const Vec2& v : polygon.Vertices())
    {
        out.push_back(BigWorld(xf, v));
    }
    return out;
}

BigInt BigCross(const BigPoint& u, const BigPoint& v)
{
    return u.x * v.y - u.y * v.x;
}

BigInt BigDot(const BigPoint& u, const BigPoint& v)
{
    return u.x * v.x + u.y * v.y;
}

BigPoint operator-(const BigPoint& a, const BigPoint& b)
{
    return {a.x - b.x, a.y - b.y};
}

int BigOrient(const BigPoint& a, const BigPoint& b, const BigPoint& c)
{
    return BigCross(b - a, c - a).sign;
}

// How two convex polygons (counter-clockwise) lie, by the separating axis theorem on the lines of their edges (a
// different method from the reference's): -1 apart (every vertex of one strictly outside an edge of the other), 0
// touching (not apart, but every vertex of one outside or on an edge's line), +1 interpenetrating.
int BigContact(const std::vector<BigPoint>& a, const std::vector<BigPoint>& b)
{
    int contact = 1;
    for (int side = 0; side < 2; ++side)
    {
        const std::vector<BigPoint>& owner = side == 0 ? a : b;
        const std::vector<BigPoint>& other = side == 0 ? b : a;
        for (size_t i = 0; i < owner.size(); ++i)
        {
            int deepest = -1;
            for (const BigPoint& v : other)
            {
                deepest = std::max(deepest, BigOrient(owner[i], owner[(i + 1) % owner.size()], v));
            }
            if (deepest < 0)
            {
                return -1;
            }
            contact = deepest == 0 ? 0 : contact;
        }
    }
    return contact;
}

// A closed disc and a closed convex polygon meet: the centre is inside, within r of a vertex, or projects inside an
// edge at a distance of at most r (by Lagrange's identity, |p - a|^2 |e|^2 - Dot(p - a, e)^2 <= r^2 |e|^2).
bool BigPolygonCircleOverlap(const std::vector<BigPoint>& outline, const BigPoint& p, double radius)
{
    const BigInt r = FromDouble(radius, 2 * kScale);
    const BigInt r2 = r * r;
    bool inside = true;
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const BigPoint& a = outline[i];
        const BigPoint& b = outline[(i + 1) % outline.size()];
        inside = inside && BigOrient(a, b, p) >= 0;
        const BigPoint e = b - a;
        const BigPoint pa = p - a;
        if ((BigDot(pa, pa) - r2).sign <= 0)
        {
            return true;
        }
        const BigInt along = BigDot(pa, e);
        const BigInt length2 = BigDot(e, e);
        if (along.sign > 0 && (along - length2).sign < 0 &&
            (BigDot(pa, pa) * length2 - along * along - r2 * length2).sign <= 0)
        {
            return true;
        }
    }
    return inside;
}

// Two closed discs meet: |cb - ca|^2 <= (ra + rb)^2.
bool BigCirclesOverlap(const BigPoint& ca, double ra, const BigPoint& cb, double rb)
{
    const BigPoint d = cb - ca;
    const BigInt r = FromDouble(ra, 2 * kScale) + FromDouble(rb, 2 * kScale);
    return (BigDot(d, d) - r * r).sign <= 0;
}

// A random double: up to `bits` significant bits, exponent in [lo, hi], either sign, now and then 0.
double RandomDouble(Rng& rng, int bits, int lo, int hi)
{
    if (rng.Chance(0.03))
    {
        return 0.0;
    }
    const uint64_t mantissa = (rng.engine() >> (64 - bits)) | (uint64_t(1) << (bits - 1));
    const double value = std::ldexp(static_cast<double>(mantissa), rng.Int(lo, hi) - bits);
    return rng.Chance(0.5) ? value : -value;
}

// j / 2^bits for j uniform in [lo, hi].
double Grid(Rng& rng, int lo, int hi, int bits)
{
    return std::ldexp(static_cast<double>(rng.Int(lo, hi)), -bits);
}

// A polygon with vertices on the grid of 2^-10, within `radius` of the origin.
Polygon GridPolygon(Rng& rng, int count, double radius)
{
    const int extent = static_cast<int>(radius * 1024);
    for (;;)
    {
        std::vector<Vec2> points;
        for (int i = 0; i < count; ++i)
        {
            points.push_back({Grid(rng, -extent, extent, 10), Grid(rng, -extent, extent, 10)});
        }
        PolygonResult result = ComputeHull(points);
        if (result.Ok())
        {
            return result.polygon;
        }
    }
}

std::vector<Vec2> Vertices(const Polygon& polygon)
{
    return {polygon.Vertices().begin(), polygon.Vertices().end()};
}

Polygon FromVertices(const std::vector<Vec2>& points)
{
    PolygonResult result = ComputeHull(points);
    REQUIRE(result.Ok());
    return result.polygon;
}

// B's vertices against edge `edge` of A (both in A's frame), B in the closed outer half-plane of the edge's line,
// touching it: either B's vertex farthest into the line placed on a grid point of the edge (a vertex of A now and
// then), or an edge of B laid along the line.
std::vector<Vec2> TouchingVertices(Rng& rng, const Polygon& a, int edge)
{
    const Vec2 p = a.Vertices()[edge];
    const Vec2 e = a.Edge(edge);
    std::vector<Vec2> points;
    if (rng.Chance(0.35))
    {
        const double from = Grid(rng, -16, 32, 4);
        const double to = from + Grid(rng, 1, 16, 4);
        points.push_back(p + from * e);
        points.push_back(p + to * e);
        const int extra = rng.Int(1, 4);
        for (int i = 0; i < extra; ++i)
        {
            points.push_back(p + Grid(rng, -16, 32, 4) * e + Grid(rng, 1, 16, 4) * RightPerp(e));
        }
        return Vertices(FromVertices(points));
    }
    const std::vector<Vec2> b = Vertices(GridPolygon(rng, rng.Int(3, 10), rng.Uniform(0.1, 1.0)));
    size_t deepest = 0;
    for (size_t k = 1; k < b.size(); ++k)
    {
        deepest = Cross(e, b[k]) > Cross(e, b[deepest]) ? k : deepest; // exact on the grid
    }
    const Vec2 target = p + Grid(rng, 0, 64, 6) * e;
    for (const Vec2& v : b)
    {
        points.push_back(v - b[deepest] + target);
    }
    return points;
}

// A translation by a few multiples of 2^-40 (or 2^-30 along the edge normal), or none: near-touching pairs.
Vec2 Nudge(Rng& rng, Vec2 normal)
{
    switch (rng.Int(0, 3))
    {
    case 0:
        return {Grid(rng, -3, 3, 40), Grid(rng, -3, 3, 40)};
    case 1:
        return Grid(rng, -2, 2, 30) * normal;
    default:
        return {};
    }
}

// Where a touching pair is placed: both shapes share a transform (the pair's exact geometry is an affine image of
// the body-frame one, so touching stays touching, while quad precision rounds it), or sit unrotated.
Transform Placement(Rng& rng, int kind)
{
    switch (kind)
    {
    case 0:
        return {Vec2{Grid(rng, -4096, 4096, 10), Grid(rng, -4096, 4096, 10)}, Rot{}};
    case 1:
        return MakeTransform(Vec2{Grid(rng, -4096, 4096, 10), Grid(rng, -4096, 4096, 10)}, rng.Uniform(-kPi, kPi));
    case 2:
    {
        // Far out: the world coordinates may need more bits than quad precision has.
        const double far = std::ldexp(1.0, rng.Int(50, 100));
        return {Vec2{far + Grid(rng, -4096, 4096, 10) * far / 1024, -far}, Rot{}};
    }
    default:
    {
        const double far = std::ldexp(1.0, rng.Int(10, 40));
        return MakeTransform(Vec2{far, Grid(rng, -4096, 4096, 10) * far}, rng.Uniform(-kPi, kPi));
    }
    }
}

} // namespace

TEST_CASE("Expansion arithmetic is exact", "[exact]")
{
    Rng rng(20260101);
    for (int trial = 0; trial < 20000; ++trial)
    {
        const double a = RandomDouble(rng, 53, -40, 40);
        const double b = RandomDouble(rng, 53, -40, 40);
        const double c = rng.Chance(0.2) ? -a : RandomDouble(rng, 53, -40, 40);
        const double d = rng.Chance(0.2) ? b : RandomDouble(rng, 53, -40, 40);
        INFO("trial " << trial << ": " << a << ", " << b << ", " << c << ", " << d);

        const TwoTerm sum = TwoSum(a, b);
        REQUIRE(FromDouble(sum.x, kScale) + FromDouble(sum.y, kScale) == FromDouble(a, kScale) + FromDouble(b, kScale));
        const TwoTerm product = TwoProduct(a, b);
        REQUIRE(FromExpansion(MakeExpansion(product), 2 * kScale) == FromDouble(a, kScale) * FromDouble(b, kScale));

        // ab + cd (cancelling to 0 now and then), (ab + cd) a, (ab + cd)(ab - cd), and their compressions.
        const BigInt ab = FromDouble(a, kScale) * FromDouble(b, kScale);
        const BigInt cd = FromDouble(c, kScale) * FromDouble(d, kScale);
        const Expansion e = ExpansionSum(MakeExpansion(TwoProduct(a, b)), MakeExpansion(TwoProduct(c, d)));
        const Expansion f = ExpansionDifference(MakeExpansion(TwoProduct(a, b)), MakeExpansion(TwoProduct(c, d)));
        REQUIRE(IsExpansion(e));
        REQUIRE(IsExpansion(f));
        REQUIRE(FromExpansion(e, 2 * kScale) == ab + cd);
        REQUIRE(FromExpansion(f, 2 * kScale) == ab - cd);
        REQUIRE(ExpansionSign(e) == (ab + cd).sign);
        REQUIRE(ExpansionSign(f) == (ab - cd).sign);

        const Expansion scaled = ScaleExpansion(e, a);
        REQUIRE(IsExpansion(scaled));
        REQUIRE(FromExpansion(scaled, 3 * kScale) == (ab + cd) * FromDouble(a, kScale));

        const Expansion ef = ExpansionProduct(e, f);
        REQUIRE(IsExpansion(ef));
        REQUIRE(FromExpansion(ef, 4 * kScale) == (ab + cd) * (ab - cd));
        REQUIRE(ExpansionSign(ef) == ((ab + cd) * (ab - cd)).sign);

        const Expansion compressed = Compress(GrowExpansion(scaled, c));
        REQUIRE(IsExpansion(compressed));
        REQUIRE(FromExpansion(compressed, 3 * kScale) == (ab + cd) * FromDouble(a, kScale) + FromDouble(c, 3 * kScale));
        if (!compressed.empty())
        {
            REQUIRE(std::fabs(Estimate(compressed) - compressed.back()) <= std::fabs(compressed.back()) * 0x1p-51);
        }
    }
}

TEST_CASE("Exact transforms and orientations agree with long-integer arithmetic", "[exact]")
{
    Rng rng(20260102);
    int quadNonzeroOnCollinear = 0;
    for (int trial = 0; trial < 20000; ++trial)
    {
        INFO("trial " << trial);
        // Three points, each under its own transform: small integers (any c and s, not only rotations) or dyadic
        // inputs (rotations of random angles, coordinates with up to 40 significant bits).
        const bool small = trial % 2 == 0;
        Transform xf[3];
        Vec2 local[3];
        for (int k = 0; k < 3; ++k)
        {
            if (small)
            {
                xf[k] = {Vec2{double(rng.Int(-50, 50)), double(rng.Int(-50, 50))},
                         Rot{double(rng.Int(-3, 3)), double(rng.Int(-3, 3))}};
                local[k] = {double(rng.Int(-20, 20)), double(rng.Int(-20, 20))};
            }
            else
            {
                xf[k] = MakeTransform(Vec2{RandomDouble(rng, 40, -10, 10), RandomDouble(rng, 40, -10, 10)},
                                      rng.Uniform(-kPi, kPi));
                local[k] = {RandomDouble(rng, 40, -10, 4), RandomDouble(rng, 40, -10, 4)};
            }
        }
        ExactPoint world[3];
        BigPoint big[3];
        for (int k = 0; k < 3; ++k)
        {
            world[k] = ExactTransform(xf[k], local[k]);
            big[k] = BigWorld(xf[k], local[k]);
            REQUIRE(IsExpansion(world[k].x));
            REQUIRE(IsExpansion(world[k].y));
            REQUIRE(FromExpansion(world[k].x, 2 * kScale) == big[k].x);
            REQUIRE(FromExpansion(world[k].y, 2 * kScale) == big[k].y);
        }
        REQUIRE(ExactOrient2d(world[0], world[1], world[2]) == BigOrient(big[0], big[1], big[2]));

        // A collinear triple a, a + i d, a + j d under one transform (exactly collinear: the transform is affine),
        // then the third point one ulp off the line.
        // Dyadic ones far from the origin with fine body-frame coordinates need more bits than quad precision has.
        const double far = std::ldexp(1.0, rng.Int(0, 60));
        const Transform shared =
            small ? xf[0]
                  : MakeTransform(Vec2{far * Grid(rng, -4096, 4096, 10), far * Grid(rng, -4096, 4096, 10)},
                                  rng.Uniform(-kPi, kPi));
        const Vec2 a = small ? Vec2{double(rng.Int(-20, 20)), double(rng.Int(-20, 20))}
                             : Vec2{Grid(rng, -(1 << 30), 1 << 30, 28), Grid(rng, -(1 << 30), 1 << 30, 28)};
        Vec2 d{double(rng.Int(-9, 9)), double(rng.Int(-9, 9))};
        if (d == Vec2{})
        {
            d = {1.0, 0.0};
        }
        d = (small ? 1.0 : std::ldexp(1.0, -rng.Int(0, 12))) * d;
        const Vec2 b = a + double(rng.Int(-8, 8)) * d;
        Vec2 c = a + double(rng.Int(-8, 8)) * d;
        const WorldPoint wa = MakeWorldPoint(shared, a), wb = MakeWorldPoint(shared, b), wc = MakeWorldPoint(shared, c);
        const int collinear = ExactOrient2d(Exact(wa), Exact(wb), Exact(wc));
        REQUIRE(collinear == BigOrient(BigWorld(shared, a), BigWorld(shared, b), BigWorld(shared, c)));
        REQUIRE(collinear == 0);
        quadNonzeroOnCollinear += QCross(wb.q - wa.q, wc.q - wa.q) != 0 ? 1 : 0;
        // The filtered orientation takes the exact path where quad precision cannot tell.
        PointSpread spread;
        Include(spread, {wa, wb, wc});
        REQUIRE(Orient2d(wa, wb, wc, FilterBound(spread)) == 0);

        const bool alongX = std::fabs(d.x) >= std::fabs(d.y);
        double& moved = alongX ? c.y : c.x;
        if (moved == 0.0)
        {
            continue; // one ulp of 0 is subnormal, outside the range of exact products
        }
        moved = std::nextafter(moved, rng.Chance(0.5) ? 1e300 : -1e300);
        const int off = BigOrient(BigWorld(shared, a), BigWorld(shared, b), BigWorld(shared, c));
        if (!(a == b) && (shared.q.c != 0.0 || shared.q.s != 0.0))
        {
            REQUIRE(off != 0);
        }
        REQUIRE(ExactOrient2d(ExactTransform(shared, a), ExactTransform(shared, b), ExactTransform(shared, c)) == off);
    }
    WARN("quad precision gave a nonzero orientation to " << quadNonzeroOnCollinear
                                                         << " of 20000 exactly collinear triples");
}

TEST_CASE("The filtered reference decides touching and near-touching pairs exactly", "[exact][properties]")
{
    // B against an edge of A, touching it exactly or moved by a hair, placed as Placement describes. Closed shapes:
    // touching counts as overlapping, as in the library. The oracle works on long integers.
    Rng rng(20260103);
    int overlapping = 0;
    int touching = 0;
    int separated = 0;
    int quadWrong = 0;
    constexpr int kPairs = 6000;
    for (int i = 0; i < kPairs; ++i)
    {
        INFO("pair " << i);
        const int placement = i % 4;
        const Polygon a = GridPolygon(rng, rng.Int(3, 10), rng.Uniform(0.2, 1.0));
        const int edge = rng.Int(0, a.Count() - 1);
        const std::vector<Vec2> against = TouchingVertices(rng, a, edge);
        const Vec2 nudge = Nudge(rng, RightPerp(a.Edge(edge)));
        Transform xfA = Placement(rng, placement);
        Transform xfB = xfA;
        Vec2 shift = nudge;
        if (placement == 0)
        {
            // Unrotated at different positions: B's vertices shifted by the difference, exactly.
            xfB.p = {Grid(rng, -4096, 4096, 10), Grid(rng, -4096, 4096, 10)};
            shift = shift + (xfA.p - xfB.p);
        }
        std::vector<Vec2> moved;
        for (const Vec2& v : against)
        {
            moved.push_back(v + shift);
        }
        const Polygon b = FromVertices(moved);

        const int contact = BigContact(BigWorld(a, xfA), BigWorld(b, xfB));
        const bool expected = contact >= 0;
        const Reference ref = ReferenceCollide(MakeShape(a), xfA, MakeShape(b), xfB);
        REQUIRE(ref.overlap == expected);
        const std::vector<WorldPoint> wa = WorldPoints(a, xfA);
        const std::vector<WorldPoint> wb = WorldPoints(b, xfB);
        REQUIRE(ReferenceOverlap(wa, wb, HUGE_VALQ) == expected);     // every sign by expansions
        quadWrong += ReferenceOverlap(wa, wb, 0) != expected ? 1 : 0; // every sign by its quad value
        (contact > 0 ? overlapping : contact == 0 ? touching : separated) += 1;
    }
    WARN(overlapping << " interpenetrating, " << touching << " touching, " << separated << " apart; deciding every "
                     << "sign by its quad value would get " << quadWrong << " wrong");
    REQUIRE(overlapping > kPairs / 10);
    REQUIRE(touching > kPairs / 10);
    REQUIRE(separated > kPairs / 10);
    REQUIRE(quadWrong > kPairs / 100); // the pairs are close enough to need the exact path
}

TEST_CASE("The filtered reference decides touching and near-touching circles exactly", "[exact][properties]")
{
    // Pythagorean offsets make exact distances: unrotated shapes touch exactly, far from the origin too, where quad
    // precision rounds their world coordinates (fine body-frame coordinates); rotated ones touch to within the
    // rounding of the rotation.
    const int triples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {0, 1, 1}};
    Rng rng(20260104);
    int overlapping = 0;
    int separated = 0;
    int quadWrong = 0;
    constexpr int kPairs = 6000;
    for (int i = 0; i < kPairs; ++i)
    {
        INFO("pair " << i);
        const int* t = triples[rng.Int(0, 4)];
        const double sx = rng.Chance(0.5) ? 1.0 : -1.0, sy = rng.Chance(0.5) ? 1.0 : -1.0;
        const bool swap = rng.Chance(0.5);
        const double unit = Grid(rng, 1, 16, 8);
        const Vec2 offset{sx * unit * (swap ? t[1] : t[0]), sy * unit * (swap ? t[0] : t[1])}; // length t[2] unit
        const double length = unit * t[2];
        const double tweak = rng.Chance(0.5) ? 0.0 : Grid(rng, -3, 3, 40);
        const Transform xf = Placement(rng, rng.Chance(0.5) ? 2 : rng.Int(0, 3));
        bool expected = false;
        Reference ref;
        if (i % 2 == 0)
        {
            Circle ca, cb;
            ca.center = {Grid(rng, -(1 << 30), 1 << 30, 30), Grid(rng, -(1 << 30), 1 << 30, 30)};
            cb.center = ca.center + offset;
            ca.radius = length * Grid(rng, 1, 15, 4);
            cb.radius = length - ca.radius + tweak;
            expected = BigCirclesOverlap(BigWorld(xf, ca.center), ca.radius, BigWorld(xf, cb.center), cb.radius);
            ref = ReferenceCollide(MakeShape(ca), xf, MakeShape(cb), xf);
        }
        else
        {
            // A polygon with an edge of Pythagorean direction (points strictly to its left complete it), the disc
            // touching that edge or a vertex.
            const Vec2 p{Grid(rng, -(1 << 29), 1 << 29, 30), Grid(rng, -(1 << 29), 1 << 29, 30)};
            const Vec2 e = LeftPerp(offset);
            std::vector<Vec2> points{p, p + e};
            while (points.size() < 5)
            {
                const Vec2 x{Grid(rng, -2048, 2048, 10), Grid(rng, -2048, 2048, 10)};
                if (Cross(e, x - p) > 0)
                {
                    points.push_back(x);
                }
            }
            const Polygon polygon = FromVertices(points);
            Circle circle;
            const double scale = Grid(rng, 1, 32, 4);
            circle.radius = scale * length + tweak;
            // RightPerp(e) = offset: the edge's outward normal, of length `length`.
            circle.center = rng.Chance(0.6) ? p + Grid(rng, 0, 16, 4) * e + scale * offset
                                            : polygon.Vertices()[rng.Int(0, polygon.Count() - 1)] + scale * offset;
            expected = BigPolygonCircleOverlap(BigWorld(polygon, xf), BigWorld(xf, circle.center), circle.radius);
            ref = rng.Chance(0.5) ? ReferenceCollide(MakeShape(polygon), xf, MakeShape(circle), xf)
                                  : ReferenceCollide(MakeShape(circle), xf, MakeShape(polygon), xf);
        }
        REQUIRE(ref.overlap == expected);
        (expected ? overlapping : separated) += 1;
        quadWrong += (ref.separation <= 0) != expected ? 1 : 0;
    }
    WARN(overlapping << " overlapping (touching included), " << separated << " separated; the sign of the quad "
                     << "separation would get " << quadWrong << " wrong");
    REQUIRE(overlapping > kPairs / 2);
    REQUIRE(separated > kPairs / 10);
    REQUIRE(quadWrong > 10); // the pairs are close enough to need the exact path
}

TEST_CASE("The sweep reference decides sliding, touching starts and arrivals at t = 1 exactly", "[exact][sweep]")
{
    // B's vertex farthest into the line of an edge of A put on a point strictly inside the edge, B outside the line,
    // unrotated (at different positions, or far out where quad precision rounds the vertex differences). By
    // construction: sliding along the edge never interpenetrates; moving in from touching enters at exactly t = 0;
    // starting a gap g away and moving in by g arrives at exactly t = 1, and by a hair less arrives after t = 1.
    Rng rng(20260105);
    for (int i = 0; i < 3000; ++i)
    {
        INFO("pair " << i);
        const Polygon a = GridPolygon(rng, rng.Int(3, 10), rng.Uniform(0.2, 1.0));
        const int edge = rng.Int(0, a.Count() - 1);
        const Vec2 e = a.Edge(edge);
        const Vec2 normal = RightPerp(e); // outward
        const std::vector<Vec2> cloud = Vertices(GridPolygon(rng, rng.Int(3, 10), rng.Uniform(0.1, 1.0)));
        size_t deepest = 0;
        for (size_t k = 1; k < cloud.size(); ++k)
        {
            deepest = Cross(e, cloud[k]) > Cross(e, cloud[deepest]) ? k : deepest; // exact on the grid
        }
        const Vec2 target = a.Vertices()[edge] + Grid(rng, 1, 63, 6) * e;
        const int kind = rng.Int(0, 3);
        const double gap = kind >= 2 ? Grid(rng, 1, 64, 6) : 0.0;
        const int placement = rng.Chance(0.5) ? 0 : 2;
        Transform xfA = Placement(rng, placement);
        Transform xfB = xfA;
        // A slide along the edge by a multiple of 2^-40 keeps the contact and needs fine coordinates.
        Vec2 shift = target - cloud[deepest] + gap * normal + Grid(rng, -(1 << 20), 1 << 20, 40) * e;
        if (placement == 0)
        {
            xfB.p = {Grid(rng, -4096, 4096, 10), Grid(rng, -4096, 4096, 10)};
            shift = shift + (xfA.p - xfB.p);
        }
        std::vector<Vec2> moved;
        for (const Vec2& v : cloud)
        {
            moved.push_back(v + shift);
        }
        const Polygon b = FromVertices(moved);
        Vec2 velocity;
        switch (kind)
        {
        case 0:
            velocity = Grid(rng, -64, 64, 4) * e;
            break;
        case 1:
            velocity = -Grid(rng, 1, 64, 6) * normal;
            break;
        case 2:
            velocity = -gap * normal;
            break;
        default:
            velocity = -(gap - std::ldexp(gap, -30)) * normal;
            break;
        }
        INFO("kind " << kind << ", A at " << xfA.p.x << ", " << xfA.p.y);
        const SweepReference ref = ReferenceSweep(a, xfA, b, xfB, velocity);
        REQUIRE(!ref.insideAtStart);
        switch (kind)
        {
        case 0:
            REQUIRE(!ref.crosses);
            break;
        case 1:
            REQUIRE(ref.crosses);
            REQUIRE(ref.enter == 0);
            REQUIRE(ref.leave > 0);
            break;
        case 2:
            REQUIRE(ref.crosses);
            REQUIRE(ref.enter == 1);
            break;
        default:
            REQUIRE(ref.crosses);
            REQUIRE(ref.enter > 1);
            break;
        }
    }
}
