// SPDX-License-Identifier: MIT
// Property tests over random pairs against the quadruple-precision reference (support/reference.h).

#include "bench/textbook_sat.h"
#include "support/random_shapes.h"
#include "support/reference.h"
#include "support/same_bits.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

using namespace satviz;
using namespace satviz::testing;

namespace
{

constexpr int kPairs = 100000;
constexpr uint64_t kSeed = 20261122;
// Pairs whose true separation lies within this band of zero may be decided either way by double rounding.
constexpr double kBand = 1e-12;

double Scale(const RandomPair& pair)
{
    auto radius = [](const Shape& s) { return s.type == ShapeType::Polygon ? Radius(s.polygon) : s.circle.radius; };
    return std::max({radius(pair.a), radius(pair.b), 1.0});
}

Transform Moved(const Transform& xf, Vec2 by)
{
    return {xf.p + by, xf.q};
}

// Distance from a world point to a shape's outline (quad precision).
double OutlineDistance(const Shape& shape, const Transform& xf, Vec2 point)
{
    const QVec p{point.x, point.y};
    if (shape.type == ShapeType::Circle)
    {
        const QVec d = p - QTransform(xf, shape.circle.center);
        return static_cast<double>(fabsq(sqrtq(QDot(d, d)) - shape.circle.radius));
    }
    return static_cast<double>(fabsq(SignedDistance(QWorld(shape.polygon, xf), p)));
}

} // namespace

TEST_CASE("Overlap and Collide agree with the reference on random pairs", "[properties]")
{
    Rng rng(kSeed);
    int decided = 0;
    int overlapping = 0;
    double maxDepthError = 0.0;
    double maxNormalError = 0.0;
    for (int i = 0; i < kPairs; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        const Reference ref = ReferenceCollide(pair.a, pair.xfA, pair.b, pair.xfB);
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        const bool overlap = Overlap(pair.a, pair.xfA, pair.b, pair.xfB);
        const double scale = Scale(pair);
        const double refSeparation = static_cast<double>(ref.separation);
        INFO("pair " << i << ": reference separation " << refSeparation);
        // The two independent reference computations agree with each other.
        if (std::abs(refSeparation) > kBand * scale)
        {
            REQUIRE(ref.overlap == (refSeparation <= 0.0));
            REQUIRE(overlap == ref.overlap);
            REQUIRE(m.overlap == ref.overlap);
            ++decided;
        }
        if (!m.overlap || !ref.overlap)
        {
            continue;
        }
        ++overlapping;
        const double depthError = std::abs(m.depth + refSeparation);
        maxDepthError = std::max(maxDepthError, depthError / scale);
        REQUIRE(depthError <= 1e-14 * scale);
        REQUIRE(std::abs(Length(m.normal) - 1.0) <= 1e-15);
        if (pair.a.type == ShapeType::Polygon && pair.b.type == ShapeType::Polygon)
        {
            // Where another axis is nearly as shallow, either normal is right: compare only clear minima.
            const double normalError = Length(m.normal - Vec2{ref.normalX, ref.normalY});
            if (normalError > 1e-9)
            {
                Reference alternative =
                    ReferenceCollide(pair.a, pair.xfA, pair.b, Moved(pair.xfB, (m.depth + 1e-9 * scale) * m.normal));
                REQUIRE(alternative.separation > 0);
            }
            else
            {
                maxNormalError = std::max(maxNormalError, normalError);
            }
        }
    }
    WARN("decided " << decided << " of " << kPairs << " pairs, " << overlapping << " overlapping; max depth error "
                    << maxDepthError << " (relative to scale), max normal error " << maxNormalError);
    REQUIRE(decided > kPairs * 99 / 100);
    REQUIRE(overlapping > kPairs / 4);
}

TEST_CASE("The minimum translation vector is minimal and sufficient", "[properties]")
{
    Rng rng(kSeed + 1);
    int checked = 0;
    for (int i = 0; i < kPairs; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        if (!m.overlap)
        {
            continue;
        }
        const double scale = Scale(pair);
        const double e = 1e-9 * scale;
        INFO("pair " << i << ": depth " << m.depth);
        // Moving B by (depth + e) along the normal separates the shapes ...
        const Reference out = ReferenceCollide(pair.a, pair.xfA, pair.b, Moved(pair.xfB, (m.depth + e) * m.normal));
        REQUIRE(!out.overlap);
        // ... and by (depth - e) does not (no shorter push along this normal exists).
        if (m.depth > e)
        {
            const Reference in = ReferenceCollide(pair.a, pair.xfA, pair.b, Moved(pair.xfB, (m.depth - e) * m.normal));
            REQUIRE(in.overlap);
        }
        ++checked;
    }
    REQUIRE(checked > kPairs / 4);
}

TEST_CASE("Contact points lie between the two surfaces", "[properties]")
{
    Rng rng(kSeed + 2);
    for (int i = 0; i < kPairs; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        INFO("pair " << i);
        if (!m.overlap)
        {
            REQUIRE(m.contactCount == 0);
            REQUIRE(m.gap > 0.0);
            continue;
        }
        REQUIRE(m.contactCount >= 1);
        REQUIRE(m.contactCount <= 2);
        const double tolerance = 1e-12 * Scale(pair);
        for (int k = 0; k < m.contactCount; ++k)
        {
            const ContactPoint& c = m.contacts[k];
            REQUIRE(c.separation <= 0.0);
            REQUIRE(-c.separation <= m.depth + tolerance);
            REQUIRE(OutlineDistance(pair.a, pair.xfA, c.point) <= 0.5 * m.depth + tolerance);
            REQUIRE(OutlineDistance(pair.b, pair.xfB, c.point) <= 0.5 * m.depth + tolerance);
        }
    }
}

TEST_CASE("A separating axis really separates, with the reported gap", "[properties]")
{
    Rng rng(kSeed + 3);
    for (int i = 0; i < kPairs; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        const Manifold m = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        if (m.overlap)
        {
            continue;
        }
        INFO("pair " << i << ": gap " << m.gap);
        // Project both shapes on the reported normal in quad precision: B lies beyond A by the gap.
        const QVec axis{m.normal.x, m.normal.y};
        auto interval = [&](const Shape& s, const Transform& xf, Quad& lo, Quad& hi) {
            if (s.type == ShapeType::Circle)
            {
                const Quad c = QDot(axis, QTransform(xf, s.circle.center));
                lo = c - s.circle.radius;
                hi = c + s.circle.radius;
                return;
            }
            lo = 1e300Q;
            hi = -1e300Q;
            for (const QVec& v : QWorld(s.polygon, xf))
            {
                const Quad d = QDot(axis, v);
                lo = d < lo ? d : lo;
                hi = d > hi ? d : hi;
            }
        };
        Quad loA, hiA, loB, hiB;
        interval(pair.a, pair.xfA, loA, hiA);
        interval(pair.b, pair.xfB, loB, hiB);
        const double projectedGap = static_cast<double>(loB - hiA);
        REQUIRE(std::abs(projectedGap - m.gap) <= 1e-13 * Scale(pair));
    }
}

TEST_CASE("Collide(B, A) mirrors Collide(A, B)", "[properties]")
{
    Rng rng(kSeed + 4);
    for (int i = 0; i < kPairs; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        const Manifold ab = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        const Manifold ba = Collide(pair.b, pair.xfB, pair.a, pair.xfA);
        const double tolerance = 1e-13 * Scale(pair);
        INFO("pair " << i << ": depth " << ab.depth << " gap " << ab.gap);
        if (std::abs(ab.overlap ? ab.depth : ab.gap) > tolerance)
        {
            REQUIRE(ab.overlap == ba.overlap);
        }
        if (ab.overlap && ba.overlap)
        {
            REQUIRE(std::abs(ab.depth - ba.depth) <= tolerance);
            // The normal may be another axis of equal depth; otherwise it is exactly reversed.
            if (Length(ab.normal + ba.normal) > 1e-9)
            {
                const Reference r =
                    ReferenceCollide(pair.a, pair.xfA, pair.b, Moved(pair.xfB, (ab.depth + 1e-9) * -ba.normal));
                REQUIRE(!r.overlap);
            }
        }
    }
}

TEST_CASE("Results are invariant under translation and rotation of the pair", "[properties]")
{
    Rng rng(kSeed + 5);
    int compared = 0;
    int countsDiffer = 0;
    double maxContactError = 0.0;
    for (int i = 0; i < kPairs; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        const double angle = rng.Uniform(-kPi, kPi);
        const double offsetScale = rng.LogUniform(0.0, 8.0);
        const Vec2 offset{rng.Uniform(-1.0, 1.0) * offsetScale, rng.Uniform(-1.0, 1.0) * offsetScale};
        const Rot q = MakeRot(angle);
        // Rotate the pair about A's position, then translate it.
        auto moved = [&](const Transform& xf) {
            const Vec2 local = xf.p - pair.xfA.p;
            return MakeTransform(pair.xfA.p + offset + Rotate(q, local), std::atan2(xf.q.s, xf.q.c) + angle);
        };
        const Transform xfA = moved(pair.xfA);
        const Transform xfB = moved(pair.xfB);
        const Manifold before = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        const Manifold after = Collide(pair.a, xfA, pair.b, xfB);
        // The moved input is itself rounded, by up to an ulp of the offset's magnitude.
        const double tolerance = 1e-13 * Scale(pair) + 4e-16 * (std::abs(offset.x) + std::abs(offset.y));
        INFO("pair " << i << ": offset " << offset.x << ", " << offset.y << ", angle " << angle);
        if (std::abs(before.overlap ? before.depth : before.gap) > tolerance)
        {
            REQUIRE(before.overlap == after.overlap);
        }
        if (before.overlap && after.overlap)
        {
            REQUIRE(std::abs(before.depth - after.depth) <= tolerance);
        }
        // The same face of a polygon as the deciding axis: its normal turns with the pair, exactly up to the
        // rounding of the rotation, and the contact points move with it (a contact whose separation is within
        // rounding of 0 may be kept on one side and not on the other). An axis through a circle's centre follows
        // the rounded positions instead, so its direction carries their error over the distance.
        const bool sameAxis = before.axis.kind == AxisKind::FaceNormal && after.axis.kind == AxisKind::FaceNormal &&
                              before.axis.shape == after.axis.shape && before.axis.index == after.axis.index;
        if (!(before.overlap && after.overlap && sameAxis))
        {
            continue;
        }
        ++compared;
        const Vec2 turned = Rotate(q, before.normal);
        REQUIRE(Length(after.normal - turned) <= 1e-12);
        if (after.contactCount != before.contactCount)
        {
            ++countsDiffer;
            continue;
        }
        for (int k = 0; k < before.contactCount; ++k)
        {
            const Vec2 expected = pair.xfA.p + offset + Rotate(q, before.contacts[k].point - pair.xfA.p);
            const Vec2 actual = after.contacts[k].point;
            maxContactError = std::max(maxContactError, Length(actual - expected) / tolerance);
            REQUIRE(Length(actual - expected) <= tolerance);
        }
    }
    WARN(compared << " pairs with the same deciding axis both ways; contact counts differ in " << countsDiffer
                  << "; contacts off by at most " << maxContactError << " of the tolerance");
    CHECK(compared > kPairs / 4);
    CHECK(countsDiffer <= compared / 1000);
}

TEST_CASE("Traced and untraced queries are bit-identical", "[properties][trace]")
{
    Rng rng(kSeed + 6);
    Trace trace;
    for (int i = 0; i < kPairs; ++i)
    {
        const RandomPair pair = RandomShapePair(rng, 0.15);
        INFO("pair " << i);
        const Manifold plain = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        const Manifold traced = Collide(pair.a, pair.xfA, pair.b, pair.xfB, &trace);
        REQUIRE(SameBits(plain, traced));
        REQUIRE(SameBits(plain, trace.result));
        REQUIRE(Overlap(pair.a, pair.xfA, pair.b, pair.xfB) == Overlap(pair.a, pair.xfA, pair.b, pair.xfB, &trace));
        // The float instantiation gives the same answer outside its own rounding band.
        if (pair.a.type == ShapeType::Polygon && pair.b.type == ShapeType::Polygon)
        {
            const PolygonResultT<float> fa = ConvertPolygon<float>(pair.a.polygon);
            const PolygonResultT<float> fb = ConvertPolygon<float>(pair.b.polygon);
            if (fa.Ok() && fb.Ok())
            {
                auto toFloat = [](const Transform& xf) {
                    return TransformT<float>{ConvertVec<float>(xf.p), {float(xf.q.c), float(xf.q.s)}};
                };
                const ManifoldT<float> mf = Collide(fa.polygon, toFloat(pair.xfA), fb.polygon, toFloat(pair.xfB));
                if (std::abs(plain.overlap ? plain.depth : plain.gap) > 1e-5 * Scale(pair))
                {
                    REQUIRE(mf.overlap == plain.overlap);
                }
                if (mf.overlap && plain.overlap)
                {
                    REQUIRE(std::abs(double(mf.depth) - plain.depth) <= 1e-5 * Scale(pair));
                }
            }
        }
    }
}

TEST_CASE("Collide picks the first face of largest separation, A's on a tie", "[properties]")
{
    // Lattice shapes with axis-aligned faces, unrotated at whole-number positions: their axis-face separations are
    // exact, so ties are real and the oracle below computes them without rounding. Each shape is a box with up to
    // two corners cut (4 to 6 faces), so the face blocks of the query are both full and partly repeated.
    Rng rng(kSeed + 9);
    auto lattice = [&rng]() {
        const double w = rng.Int(3, 6);
        const double h = rng.Int(3, 6);
        std::vector<Vec2> points{{0, 0}, {w, 0}};
        if (rng.Chance(0.5))
        {
            points.push_back({w, h - 1});
            points.push_back({w - 1, h});
        }
        else
        {
            points.push_back({w, h});
        }
        if (rng.Chance(0.5))
        {
            points.push_back({1, h});
            points.push_back({0, h - 1});
        }
        else
        {
            points.push_back({0, h});
        }
        PolygonResult result = MakePolygon(points);
        REQUIRE(result.Ok());
        return result.polygon;
    };
    // Separation of face i of p (at position at) from q (at position aq): the smallest projection of q's vertices
    // on the face normal, minus the face's.
    auto separation = [](const Polygon& p, Vec2 at, int i, const Polygon& q, Vec2 aq) {
        const Vec2 n = p.Normal(i);
        double low = std::numeric_limits<double>::infinity();
        for (const Vec2& v : q.Vertices())
        {
            low = std::min(low, Dot(n, v + aq - (p.Vertices()[i] + at)));
        }
        return low;
    };
    auto axisAligned = [](Vec2 n) { return n.x == 0.0 || n.y == 0.0; };
    int ties = 0;
    int checked = 0;
    for (int k = 0; k < 20000; ++k)
    {
        const Polygon a = lattice();
        const Polygon b = lattice();
        const Vec2 pa{double(rng.Int(-3, 3)), double(rng.Int(-3, 3))};
        const Vec2 pb{double(rng.Int(-3, 3)), double(rng.Int(-3, 3))};
        const Manifold m = Collide(a, Transform{pa, Rot{}}, b, Transform{pb, Rot{}});
        if (!m.overlap)
        {
            continue;
        }
        // The oracle: A's first face of largest separation, then B's first one if strictly larger. A diagonal face
        // within rounding of the largest makes the choice a matter of rounding: such pairs are skipped.
        int side = 0;
        int face = -1;
        double best = -std::numeric_limits<double>::infinity();
        bool exact = true;
        int maxima = 0;
        for (int s = 0; s < 2; ++s)
        {
            const Polygon& p = s == 0 ? a : b;
            const Polygon& q = s == 0 ? b : a;
            const Vec2 at = s == 0 ? pa : pb;
            const Vec2 aq = s == 0 ? pb : pa;
            for (int i = 0; i < p.Count(); ++i)
            {
                const double d = separation(p, at, i, q, aq);
                if (!axisAligned(p.Normal(i)) && std::abs(d - best) < 1e-9)
                {
                    exact = false;
                }
                maxima += d == best ? 1 : 0;
                if (d > best)
                {
                    maxima = 1;
                    best = d;
                    side = s;
                    face = i;
                }
            }
        }
        if (!exact || !axisAligned((side == 0 ? a : b).Normal(face)))
        {
            continue;
        }
        INFO("pair " << k << ": expected side " << side << " face " << face);
        REQUIRE(m.axis.shape == side);
        REQUIRE(m.axis.index == face);
        ++checked;
        ties += maxima > 1 ? 1 : 0;
    }
    // The test is only worth something if it met many ties.
    REQUIRE(checked > 5000);
    REQUIRE(ties > 1000);
}

TEST_CASE("Large polygons: the pruned walks agree with a full scan of every face", "[properties]")
{
    // The face queries of polygons above the scan limit prune most faces and walk only near the contact; the
    // oracle is the textbook loop, which projects every vertex on every axis in world space.
    Rng rng(kSeed + 1024);
    int decided = 0;
    int overlapping = 0;
    int nested = 0;
    for (int i = 0; i < 1500; ++i)
    {
        const int n = static_cast<int>(std::lround(std::pow(10.0, rng.Uniform(std::log10(17.0), std::log10(2000.0)))));
        RandomPair pair = ContactPair(rng, n, static_cast<PairCategory>(rng.Int(0, 2)), 0.1);
        switch (i % 4)
        {
        case 1:
            // A small polygon (scanned against the large one's faces, walked against its own) or a large one.
            pair.b = MakeShape(RandomPolygon(rng, rng.Int(3, 40), rng.Uniform(0.05, 1.5), rng.Uniform(0.35, 1.0)));
            pair.xfB = MakeTransform(pair.xfA.p + Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)},
                                     rng.Uniform(-kPi, kPi));
            break;
        case 2:
            // One polygon well inside the other, either way round.
            pair.b = MakeShape(RandomPolygon(rng, n, rng.Uniform(0.02, 0.15), rng.Uniform(0.35, 1.0)));
            pair.xfB = MakeTransform(pair.xfA.p + Vec2{rng.Uniform(-0.1, 0.1), rng.Uniform(-0.1, 0.1)},
                                     rng.Uniform(-kPi, kPi));
            if (rng.Chance(0.5))
            {
                std::swap(pair.a, pair.b);
                std::swap(pair.xfA, pair.xfB);
            }
            ++nested;
            break;
        default:
            break;
        }
        const Polygon& a = pair.a.polygon;
        const Polygon& b = pair.b.polygon;
        Vec2 textbookNormal;
        const double textbookDepth = bench::TextbookMtv(a, pair.xfA, b, pair.xfB, textbookNormal);
        const bool overlap = Overlap(a, pair.xfA, b, pair.xfB);
        const Manifold m = Collide(a, pair.xfA, b, pair.xfB);
        const double scale = Scale(pair);
        INFO("pair " << i << ": " << a.Count() << " and " << b.Count() << " vertices, textbook depth "
                     << textbookDepth);
        if (std::abs(textbookDepth) <= kBand * scale)
        {
            continue;
        }
        ++decided;
        REQUIRE(overlap == (textbookDepth > 0.0));
        REQUIRE(m.overlap == overlap);
        if (m.overlap)
        {
            ++overlapping;
            REQUIRE(std::abs(m.depth - textbookDepth) <= 1e-13 * scale);
        }
        else
        {
            // The separating face found leaves the gap it reports between the projections.
            std::vector<Vec2> world;
            double loA, hiA, loB, hiB;
            bench::Project(bench::WorldVertices(a, pair.xfA, world), m.normal, loA, hiA);
            bench::Project(bench::WorldVertices(b, pair.xfB, world), m.normal, loB, hiB);
            REQUIRE(m.gap > 0.0);
            REQUIRE(std::abs((loB - hiA) - m.gap) <= 1e-13 * scale);
        }
    }
    WARN("large polygons: " << decided << " pairs decided, " << overlapping << " overlapping, " << nested << " nested");
    REQUIRE(decided > 1480);
    REQUIRE(overlapping > 600);
}
