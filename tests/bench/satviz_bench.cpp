// SPDX-License-Identifier: MIT
// satviz-bench: run time and error of the SAT queries on random contact pairs, beside Box2D 2.4.1 in the same
// process on the same pairs. A benchmark program, not a test: it prints figures and ratios measured in this run.
//
// Method: per vertex count, a pool of `slices` x `pairs` fresh pairs, a random mix of overlapping, touching (within
// 1e-9) and separated pairs. A pass runs one query over every pair of one slice in storage order. Per round (each
// at another stack placement, AtStackShift): a warm pass of every query over every slice, then `reps` sweeps, a
// sweep being one pass of every query in turn on the next slice, so that consecutive passes of a query see other
// slices and no outcome sequence is learnt by the branch predictor. A query's figure is the median of its passes;
// a ratio is the median over the sweeps of the ratio of two passes of one sweep, taken moments apart, so that it
// holds still while the machine's speed drifts. Native shapes are built before timing.
// Accuracy: a separate pool, against the __float128 reference of tests/support/reference.h.

#include "near_contact.h"
#include "support/random_shapes.h"
#include "support/reference.h"
#include "support/reference_ray.h"
#include "textbook_sat.h"
#include "box2d_v3.h"
#include "concave_bench.h"
#include "world_bench.h"

// White-box: the benchmark instantiates the algorithm with some of its choices turned off (the variants).
#include "sat/polygon_polygon.h"

#include <satviz/sat.h>

#include <CLI/CLI.hpp>

#ifdef SATVIZ_HAVE_BOX2D
#include <box2d/b2_time_of_impact.h>
#include <box2d/box2d.h>
#endif

#ifdef SATVIZ_HAVE_CHIPMUNK
#include <chipmunk/chipmunk.h>
#include <chipmunk/chipmunk_structs.h>

#include <cstdarg>
#include <memory>

// Debian builds Chipmunk without NDEBUG: its EPA prints "High EPA iterations" warnings from inside the timed
// loops. This definition takes the place of the library's (symbol interposition), counts them, and still prints
// real errors.
namespace
{
long g_chipmunkWarnings = 0;
}
extern "C" void cpMessage(const char* condition, const char* file, int line, int isError, int isHardError,
                          const char* message, ...)
{
    if (!isError)
    {
        ++g_chipmunkWarnings;
        return;
    }
    std::va_list args;
    va_start(args, message);
    std::fprintf(stderr, "chipmunk %s (%s:%d, %s): ", isHardError ? "hard error" : "error", file, line, condition);
    std::vfprintf(stderr, message, args);
    std::fprintf(stderr, "\n");
    va_end(args);
}
#endif

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

struct Settings
{
    int slices = 4;
    int pairs = 1000;
    int rounds = 9;
    int reps = 7;
    int accuracyPairs = 3000;
    uint64_t seed = 20240601;
    std::vector<int> counts = {3, 4, 8, 16, 64, 1024, 4096};
    // Near-contact pairs (TimeNear): pairs per pool, rounds (one fresh pool each), vertex counts, placement.
    int nearPairs = 12000;
    int nearRounds = 15;
    std::vector<int> nearCounts = {3, 4, 5, 6, 7, 8};
    // "direction": along a random direction, at a uniform distance from touching (bench::NearContactPair);
    // "face": as the main pool, against a point of A's outline along A's normal there (ContactPair).
    std::string placement = "direction";
    bool nearOnly = false;
};

// A pair in every representation a query needs, built before timing.
struct BenchPair
{
    Transform xfA, xfB;
    Shape sa, sb;  // the polygons, as shapes (Sweep takes shapes; Overlap and Collide use sa.polygon, sb.polygon)
    Vec2 velocity; // B's displacement over the step; A stands still
    PolygonT<float> fa, fb;
    TransformT<float> fxfA, fxfB;
    bool floatOk = false;
#ifdef SATVIZ_HAVE_BOX2D
    b2PolygonShape ba, bb;
    b2Transform bxfA, bxfB;
    b2Sweep bsweepA, bsweepB; // the motion over the step, as a Box2D body stores it
#endif
};

// What each library's queries read during timing, stored apart per library as an engine stores its own shapes:
// a pass streams through one library's records only, not through every representation of every pair.
struct SatvizRecord
{
    Shape sa, sb;
    Transform xfA, xfB;
    Vec2 velocity;
    Vec2 rayFrom, rayTo; // a segment cast at A: from behind B's centroid towards A's
};

// The segment cast of a pair: from B's centroid, moved back along its velocity, to A's centroid.
void RaySegment(const Shape& sa, const Transform& xfA, const Shape& sb, const Transform& xfB, Vec2 velocity, Vec2& from,
                Vec2& to)
{
    from = TransformPoint(xfB, sb.polygon.Centroid()) - 0.5 * velocity;
    to = TransformPoint(xfA, sa.polygon.Centroid());
}

struct FloatRecord
{
    ShapeT<float> sa, sb; // the polygons, as shapes
    TransformT<float> fxfA, fxfB;
    Vec2T<float> velocity;
    Vec2T<float> rayFrom, rayTo;
};

#ifdef SATVIZ_HAVE_BOX2D
struct Box2DRecord
{
    b2PolygonShape ba, bb;
    b2Transform bxfA, bxfB;
    b2Sweep bsweepA, bsweepB;
    Vec2 velocity;
    b2RayCastInput ray;
    b2PolygonShape skinA, skinB; // ba, bb with Box2D's default skin (b2_polygonRadius), as its world uses them
};
#endif

#ifdef SATVIZ_HAVE_CHIPMUNK
/// A Chipmunk pair: two polygon shapes built in place (their planes may point into the shape itself, so a record
/// is never copied), radius 0, no body, world planes cached by cpShapeUpdate before timing.
struct ChipmunkRecord
{
    cpPolyShape a{};
    cpPolyShape b{};
    bool ready = false;
    ChipmunkRecord() = default;
    ChipmunkRecord(const ChipmunkRecord&) = delete;
    ChipmunkRecord& operator=(const ChipmunkRecord&) = delete;
    ~ChipmunkRecord()
    {
        if (ready)
        {
            cpShapeDestroy(reinterpret_cast<cpShape*>(&a));
            cpShapeDestroy(reinterpret_cast<cpShape*>(&b));
        }
    }
    void Init(const Polygon& pa, const Transform& xfA, const Polygon& pb, const Transform& xfB)
    {
        auto build = [](cpPolyShape& shape, const Polygon& polygon, const Transform& xf) {
            std::vector<cpVect> vertices;
            for (const Vec2& v : polygon.Vertices())
            {
                vertices.push_back(cpv(v.x, v.y));
            }
            cpPolyShapeInitRaw(&shape, nullptr, polygon.Count(), vertices.data(), 0.0);
            cpTransform t = {xf.q.c, xf.q.s, -xf.q.s, xf.q.c, xf.p.x, xf.p.y};
            cpShapeUpdate(reinterpret_cast<cpShape*>(&shape), t);
        };
        build(a, pa, xfA);
        build(b, pb, xfB);
        ready = true;
    }
};

/// Chipmunk's answer for a pair: overlapping when it reports contacts; depth = minus the smallest contact
/// distance.
double ChipmunkDepth(const ChipmunkRecord& r, bool& overlap, double normal[2])
{
    const cpContactPointSet set =
        cpShapesCollide(reinterpret_cast<const cpShape*>(&r.a), reinterpret_cast<const cpShape*>(&r.b));
    overlap = set.count > 0;
    normal[0] = set.normal.x;
    normal[1] = set.normal.y;
    double smallest = 0.0;
    for (int i = 0; i < set.count; ++i)
    {
        smallest = i == 0 ? set.points[i].distance : std::min(smallest, set.points[i].distance);
    }
    return -smallest;
}
#endif

// Reading what a pass will read, before timing it, brings the pass's data into the caches without running the
// query (so without teaching the branch predictor its outcomes). Every query then starts from the same cache
// state: otherwise the first query of a sweep loads the slice from memory for the queries after it, which on a
// shared host made it up to three times slower than the same query later in the sweep.
volatile unsigned char g_touched = 0;

void TouchBytes(const void* data, size_t bytes)
{
    const auto* p = static_cast<const unsigned char*>(data);
    unsigned char sum = 0;
    for (size_t i = 0; i < bytes; i += 64)
    {
        sum = static_cast<unsigned char>(sum + p[i]);
    }
    g_touched = static_cast<unsigned char>(g_touched + sum);
}

template <typename S>
void TouchPolygon(const PolygonT<S>& polygon)
{
    TouchBytes(polygon.Vertices().data, sizeof(Vec2T<S>) * static_cast<size_t>(2 * polygon.Count() + 1));
}

void TouchRecord(const SatvizRecord& r)
{
    TouchBytes(&r, sizeof r);
    TouchPolygon(r.sa.polygon);
    TouchPolygon(r.sb.polygon);
}

void TouchRecord(const FloatRecord& r)
{
    TouchBytes(&r, sizeof r);
    TouchPolygon(r.sa.polygon);
    TouchPolygon(r.sb.polygon);
}

#ifdef SATVIZ_HAVE_BOX2D
void TouchRecord(const Box2DRecord& r)
{
    TouchBytes(&r, sizeof r);
}
#endif

#ifdef SATVIZ_HAVE_CHIPMUNK
void TouchRecord(const ChipmunkRecord& r)
{
    TouchBytes(&r, sizeof r);
    for (const cpPolyShape* shape : {&r.a, &r.b})
    {
        TouchBytes(shape->planes, sizeof(cpSplittingPlane) * static_cast<size_t>(2 * shape->count));
    }
}
#endif

template <typename Record>
void Touch(const Record* records, size_t count)
{
    for (size_t i = 0; i < count; ++i)
    {
        TouchRecord(records[i]);
    }
}

/// One slice of the timing pool, in each library's records; `apart` holds the pairs that start apart (sweeps).
struct Slice
{
    /// Box2D's records (none above 8 vertices).
    size_t Box2DCount() const
    {
#ifdef SATVIZ_HAVE_BOX2D
        return box2d.size();
#else
        return 0;
#endif
    }

    std::vector<SatvizRecord> satviz, satvizApart;
    std::vector<FloatRecord> single, singleApart;
#ifdef SATVIZ_HAVE_BOX2D
    std::vector<Box2DRecord> box2d, box2dApart;
#endif
#ifdef SATVIZ_HAVE_CHIPMUNK
    std::unique_ptr<ChipmunkRecord[]> chipmunk;
    size_t chipmunkCount = 0;
#endif
};

TransformT<float> ToFloat(const Transform& xf)
{
    return {ConvertVec<float>(xf.p), {static_cast<float>(xf.q.c), static_cast<float>(xf.q.s)}};
}

#ifdef SATVIZ_HAVE_BOX2D
// Box2D's Set() welds close vertices and recomputes the hull, which would alter slivers: fill the fields it would
// compute for a valid hull directly, with the skin radius set to 0 so the polygon is the input polygon.
b2PolygonShape ToBox2D(const Polygon& polygon)
{
    b2PolygonShape shape;
    shape.m_count = polygon.Count();
    b2Vec2 centroid(0.0f, 0.0f);
    for (int i = 0; i < polygon.Count(); ++i)
    {
        shape.m_vertices[i].Set(static_cast<float>(polygon.Vertices()[i].x),
                                static_cast<float>(polygon.Vertices()[i].y));
        shape.m_normals[i].Set(static_cast<float>(polygon.Normal(i).x), static_cast<float>(polygon.Normal(i).y));
        centroid += shape.m_vertices[i];
    }
    shape.m_centroid = (1.0f / static_cast<float>(polygon.Count())) * centroid;
    shape.m_radius = 0.0f;
    return shape;
}

b2Transform ToBox2D(const Transform& xf)
{
    b2Transform out;
    out.p.Set(static_cast<float>(xf.p.x), static_cast<float>(xf.p.y));
    out.q.c = static_cast<float>(xf.q.c);
    out.q.s = static_cast<float>(xf.q.s);
    return out;
}

// Penetration depth from a Box2D manifold: minus the smallest separation of its world points (`radius`: the skin
// of both polygons, which the separations include).
double Box2DDepth(const b2Manifold& manifold, const BenchPair& p, double normal[2], float radius = 0.0f)
{
    b2WorldManifold world;
    world.Initialize(&manifold, p.bxfA, radius, p.bxfB, radius);
    normal[0] = world.normal.x;
    normal[1] = world.normal.y;
    float smallest = 1e30f;
    for (int i = 0; i < manifold.pointCount; ++i)
    {
        smallest = std::min(smallest, world.separations[i]);
    }
    return -static_cast<double>(smallest);
}
#endif

#ifdef SATVIZ_HAVE_BOX2D
// The input of a pure translation sweep, built per query as Box2D's own world does: proxies that point into the
// shapes and the sweeps the bodies store (the centre of mass at the body origin, the angle constant, B moving by
// the pair's velocity; see Box2DSweeps).
template <typename Pair>
const b2TOIInput& Box2DTOIInput(const Pair& p, const b2PolygonShape& a, const b2PolygonShape& b)
{
    static b2TOIInput input;
    input.proxyA.Set(&a, 0);
    input.proxyB.Set(&b, 0);
    input.sweepA = p.bsweepA;
    input.sweepB = p.bsweepB;
    input.tMax = 1.0f;
    return input;
}

// The sweeps of a pair's bodies over the step, computed once per pair (a body keeps its angle, so no query pays for
// an arctangent).
void Box2DSweeps(BenchPair& p)
{
    const float angleA = std::atan2(p.bxfA.q.s, p.bxfA.q.c);
    const float angleB = std::atan2(p.bxfB.q.s, p.bxfB.q.c);
    p.bsweepA = {b2Vec2(0.0f, 0.0f), p.bxfA.p, p.bxfA.p, angleA, angleA, 0.0f};
    const b2Vec2 end(p.bxfB.p.x + static_cast<float>(p.velocity.x), p.bxfB.p.y + static_cast<float>(p.velocity.y));
    p.bsweepB = {b2Vec2(0.0f, 0.0f), p.bxfB.p, end, angleB, angleB, 0.0f};
}
#endif

BenchPair MakeBenchPair(const RandomPair& r, Rng& rng)
{
    BenchPair p;
    p.sa = r.a;
    p.sb = r.b;
    p.xfA = r.xfA;
    p.xfB = r.xfB;
    // B heads roughly towards A and sometimes misses: v = k (cA - cB) + s perp(cA - cB).
    const Vec2 toward = TransformPoint(p.xfA, p.sa.polygon.Centroid()) - TransformPoint(p.xfB, p.sb.polygon.Centroid());
    p.velocity = rng.Uniform(0.2, 1.5) * toward + rng.Uniform(-0.5, 0.5) * LeftPerp(toward);
    const PolygonResultT<float> fa = ConvertPolygon<float>(p.sa.polygon);
    const PolygonResultT<float> fb = ConvertPolygon<float>(p.sb.polygon);
    p.floatOk = fa.Ok() && fb.Ok();
    p.fa = fa.polygon;
    p.fb = fb.polygon;
    p.fxfA = ToFloat(p.xfA);
    p.fxfB = ToFloat(p.xfB);
#ifdef SATVIZ_HAVE_BOX2D
    if (p.sa.polygon.Count() <= b2_maxPolygonVertices)
    {
        p.ba = ToBox2D(p.sa.polygon);
        p.bb = ToBox2D(p.sb.polygon);
        p.bxfA = ToBox2D(p.xfA);
        p.bxfB = ToBox2D(p.xfB);
        Box2DSweeps(p);
    }
#endif
    return p;
}

// The pair with A and B swapped half of the time: ContactPair places B against a face of A, which would favour
// a query that tests A's faces first.
RandomPair EitherWay(RandomPair pair, Rng& rng)
{
    if (rng.Chance(0.5))
    {
        std::swap(pair.a, pair.b);
        std::swap(pair.xfA, pair.xfB);
    }
    return pair;
}

std::vector<BenchPair> MakePool(Rng& rng, int n, int count)
{
    std::vector<BenchPair> pool;
    pool.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i)
    {
        const PairCategory category = static_cast<PairCategory>(rng.Int(0, 2));
        BenchPair p = MakeBenchPair(EitherWay(ContactPair(rng, n, category), rng), rng);
        if (p.floatOk)
        {
            pool.push_back(std::move(p));
        }
    }
    return pool;
}

// A query under test: returns a value folded into a sink so the work cannot be optimised away.
struct Query
{
    std::string name;
    bool box2d = false; // needs n <= 8
    bool sweep = false; // runs on the pairs that start apart (a time of impact needs a start)
    // Visits the pairs in a new random order on every pass, so no branch history from earlier passes helps.
    bool randomOrder = false;
    // Runs up to this vertex count: the traced queries and the textbook loop cost O(n^2) and would take minutes
    // at 4096 vertices.
    int maxCount = 1 << 30;
    double (*satviz)(const SatvizRecord&) = nullptr;
    double (*single)(const FloatRecord&) = nullptr;
#ifdef SATVIZ_HAVE_BOX2D
    double (*box2dRun)(const Box2DRecord&) = nullptr;
#endif
#ifdef SATVIZ_HAVE_CHIPMUNK
    double (*chipmunkRun)(const ChipmunkRecord&) = nullptr;
#endif
};

volatile double g_sink = 0.0;

// A yes/no answer as a number for the sink, without a branch on it. A branch here, mispredicted on the pairs whose
// answer differs from the last ones, would make each library pay the whole latency of its query (the processor
// cannot start the next query early): a cost of the caller, not of the query.
inline double AsNumber(bool answer)
{
    return static_cast<double>(static_cast<int>(answer));
}

// Variants of Overlap, each with one of the algorithm's choices turned off, to measure what the choice buys.
struct NoEarlyExit : detail::NullTracer
{
    static constexpr bool kEarlyExit = false;
};
struct NoParallelSkip : detail::NullTracer
{
    static constexpr bool kSkipParallel = false;
};
struct NoWalkedPruning : detail::NullTracer
{
    static constexpr bool kPruneWalked = false;
};
struct WalkOnly : detail::NullTracer
{
    static constexpr int kScanLimit = 0;
};

template <typename Variant>
double OverlapVariant(const SatvizRecord& p)
{
    Variant variant;
    return AsNumber(detail::OverlapPolygons(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, variant));
}

template <typename Variant>
double CollideVariant(const SatvizRecord& p)
{
    Variant variant;
    return detail::CollidePolygons(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, variant).depth;
}

// Frames per moving-pair query: its time is divided by this to give ns per frame.
constexpr int kFrames = 8;

double Median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

Query SatvizQuery(const std::string& name, bool sweep, double (*run)(const SatvizRecord&))
{
    Query q;
    q.name = name;
    q.sweep = sweep;
    q.satviz = run;
    return q;
}

// The same query over the pairs in a new random order on every pass.
Query InRandomOrder(Query q)
{
    q.name += ", random order";
    q.randomOrder = true;
    return q;
}

Query FloatQuery(const std::string& name, bool sweep, double (*run)(const FloatRecord&))
{
    Query q;
    q.name = name;
    q.sweep = sweep;
    q.single = run;
    return q;
}

std::vector<Query> Queries()
{
    static Trace trace;
    static SweepTrace sweepTrace;
    std::vector<Query> queries = {
        SatvizQuery("satviz Overlap", false,
                    [](const SatvizRecord& p) { return AsNumber(Overlap(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB)); }),
        SatvizQuery(
            "satviz Overlap traced", false,
            [](const SatvizRecord& p) { return AsNumber(Overlap(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, &trace)); }),
        FloatQuery("satviz Overlap float", false,
                   [](const FloatRecord& p) { return AsNumber(Overlap(p.sa.polygon, p.fxfA, p.sb.polygon, p.fxfB)); }),
        SatvizQuery("satviz Collide", false,
                    [](const SatvizRecord& p) { return Collide(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB).depth; }),
        SatvizQuery(
            "satviz Collide traced", false,
            [](const SatvizRecord& p) { return Collide(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, &trace).depth; }),
        FloatQuery("satviz Collide float", false,
                   [](const FloatRecord& p) {
                       return static_cast<double>(Collide(p.sa.polygon, p.fxfA, p.sb.polygon, p.fxfB).depth);
                   }),
        SatvizQuery("satviz Sweep", true,
                    [](const SatvizRecord& p) { return Sweep(p.sa, p.xfA, Vec2{}, p.sb, p.xfB, p.velocity).toi; }),
        SatvizQuery("satviz SweepTime", true,
                    [](const SatvizRecord& p) { return SweepTime(p.sa, p.xfA, Vec2{}, p.sb, p.xfB, p.velocity).toi; }),
        FloatQuery("satviz Sweep float", true,
                   [](const FloatRecord& p) {
                       return static_cast<double>(Sweep(p.sa, p.fxfA, Vec2T<float>{}, p.sb, p.fxfB, p.velocity).toi);
                   }),
        SatvizQuery("satviz Overlap, as compiled here", false, OverlapVariant<detail::NullTracer>),
        SatvizQuery("satviz Overlap, no early exit", false, OverlapVariant<NoEarlyExit>),
        SatvizQuery("satviz Overlap, no parallel skip", false, OverlapVariant<NoParallelSkip>),
        SatvizQuery("satviz Overlap, walk only", false, OverlapVariant<WalkOnly>),
        SatvizQuery("satviz Overlap, walked unpruned", false, OverlapVariant<NoWalkedPruning>),
        SatvizQuery("satviz Collide, as compiled here", false, CollideVariant<detail::NullTracer>),
        SatvizQuery("satviz Collide, no early exit", false, CollideVariant<NoEarlyExit>),
        SatvizQuery("satviz Collide, no parallel skip", false, CollideVariant<NoParallelSkip>),
        SatvizQuery("satviz Collide, walk only", false, CollideVariant<WalkOnly>),
        // Frame coherence: pairs that start apart (most of what a broadphase hands over), B moving a little per
        // frame for 8 frames, across the line between them; ns per frame, with and without a cache.
        SatvizQuery("satviz Overlap, moving", true,
                    [](const SatvizRecord& p) {
                        double hits = 0.0;
                        for (int frame = 0; frame < kFrames; ++frame)
                        {
                            const Transform xfB{p.xfB.p + (0.005 * frame) * LeftPerp(p.velocity), p.xfB.q};
                            hits += AsNumber(Overlap(p.sa.polygon, p.xfA, p.sb.polygon, xfB));
                        }
                        return hits;
                    }),
        SatvizQuery("satviz Overlap, moving, cached axis", true,
                    [](const SatvizRecord& p) {
                        SatCache cache;
                        double hits = 0.0;
                        for (int frame = 0; frame < kFrames; ++frame)
                        {
                            const Transform xfB{p.xfB.p + (0.005 * frame) * LeftPerp(p.velocity), p.xfB.q};
                            hits += AsNumber(Overlap(p.sa.polygon, p.xfA, p.sb.polygon, xfB, cache));
                        }
                        return hits;
                    }),
        SatvizQuery("textbook Overlap", false,
                    [](const SatvizRecord& p) {
                        return AsNumber(bench::TextbookOverlap(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB));
                    }),
        SatvizQuery("textbook MTV", false,
                    [](const SatvizRecord& p) {
                        Vec2 normal;
                        return bench::TextbookMtv(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, normal);
                    }),
        SatvizQuery("textbook TOI", true,
                    [](const SatvizRecord& p) {
                        return bench::TextbookToi(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, p.velocity);
                    }),
        SatvizQuery("satviz RayCast", false,
                    [](const SatvizRecord& p) { return RayCast(p.sa.polygon, p.xfA, p.rayFrom, p.rayTo).fraction; }),
        FloatQuery("satviz RayCast float", false,
                   [](const FloatRecord& p) {
                       return static_cast<double>(RayCast(p.sa.polygon, p.fxfA, p.rayFrom, p.rayTo).fraction);
                   }),
        SatvizQuery(
            "satviz Sweep traced", true,
            [](const SatvizRecord& p) { return Sweep(p.sa, p.xfA, Vec2{}, p.sb, p.xfB, p.velocity, &sweepTrace).toi; }),
    };
    // The query of this name in the list (the names are the literals above, so it is there).
    const auto named = [&queries](const char* name) {
        const auto it = std::find_if(queries.begin(), queries.end(), [name](const Query& q) { return q.name == name; });
        if (it == queries.end())
        {
            std::fprintf(stderr, "satviz-bench: no query named %s\n", name);
            std::abort();
        }
        return it;
    };
    for (const char* name : {"satviz Overlap traced", "satviz Collide traced", "satviz Sweep traced",
                             "textbook Overlap", "textbook MTV", "textbook TOI"})
    {
        named(name)->maxCount = 1024;
    }
    queries.push_back(InRandomOrder(*named("satviz Overlap")));
    queries.push_back(InRandomOrder(*named("satviz Collide")));
#ifdef SATVIZ_HAVE_BOX2D
    auto box2d = [](const std::string& name, bool sweep, double (*run)(const Box2DRecord&)) {
        Query q;
        q.name = name;
        q.box2d = true;
        q.sweep = sweep;
        q.box2dRun = run;
        return q;
    };
    queries.push_back(box2d("box2d b2TestOverlap", false, [](const Box2DRecord& p) {
        return AsNumber(b2TestOverlap(&p.ba, 0, &p.bb, 0, p.bxfA, p.bxfB));
    }));
    queries.push_back(box2d("box2d b2CollidePolygons", false, [](const Box2DRecord& p) {
        b2Manifold manifold;
        b2CollidePolygons(&manifold, &p.ba, p.bxfA, &p.bb, p.bxfB);
        return static_cast<double>(manifold.pointCount);
    }));
    queries.push_back(InRandomOrder(*named("box2d b2TestOverlap")));
    queries.push_back(InRandomOrder(*named("box2d b2CollidePolygons")));
    queries.push_back(box2d("box2d b2PolygonShape::RayCast", false, [](const Box2DRecord& p) {
        b2RayCastOutput output;
        return p.ba.RayCast(&output, p.ray, p.bxfA, 0) ? static_cast<double>(output.fraction) : 2.0;
    }));
    queries.push_back(box2d("box2d b2TimeOfImpact", true, [](const Box2DRecord& p) {
        b2TOIOutput output;
        b2TimeOfImpact(&output, &Box2DTOIInput(p, p.ba, p.bb));
        return static_cast<double>(output.t);
    }));
    // What Box2D's world does to get the contact points of a time of impact: sweep the shapes with their skin
    // (b2_polygonRadius; the sweep stops a little short of the skins touching), move both bodies to t and collide
    // there, where the skins overlap and give the contact points. Like for like with satviz Sweep, which returns
    // the contact points at t.
    queries.push_back(box2d("box2d b2TimeOfImpact + b2CollidePolygons at t", true, [](const Box2DRecord& p) {
        b2TOIOutput output;
        b2TimeOfImpact(&output, &Box2DTOIInput(p, p.skinA, p.skinB));
        if (output.state != b2TOIOutput::e_touching)
        {
            return static_cast<double>(output.t);
        }
        b2Transform xfA;
        b2Transform xfB;
        p.bsweepA.GetTransform(&xfA, output.t);
        p.bsweepB.GetTransform(&xfB, output.t);
        b2Manifold manifold;
        b2CollidePolygons(&manifold, &p.skinA, xfA, &p.skinB, xfB);
        return static_cast<double>(output.t) + manifold.pointCount;
    }));
#endif
#ifdef SATVIZ_HAVE_CHIPMUNK
    auto chipmunk = [](const std::string& name, double (*run)(const ChipmunkRecord&)) {
        Query q;
        q.name = name;
        q.chipmunkRun = run;
        return q;
    };
    queries.push_back(chipmunk("chipmunk cpShapesCollide count>0", [](const ChipmunkRecord& r) {
        return cpShapesCollide(reinterpret_cast<const cpShape*>(&r.a), reinterpret_cast<const cpShape*>(&r.b)).count > 0
                   ? 1.0
                   : 0.0;
    }));
    queries.push_back(chipmunk("chipmunk cpShapesCollide", [](const ChipmunkRecord& r) {
        bool overlap = false;
        double normal[2];
        return ChipmunkDepth(r, overlap, normal);
    }));
#endif
    return queries;
}

// Runs `body` with the stack moved down by `shift` bytes. Where the stack lies modulo the 4096-byte page decides
// which of its addresses the CPU takes as possibly aliasing the data a query reads (Mytkowicz et al., "Producing
// Wrong Data Without Doing Anything Obviously Wrong!", ASPLOS 2009); on the machine of the committed results it
// moved some queries' times by up to a factor of two. Each round runs at another shift, so the median over the
// rounds rests on no single placement, lucky or unlucky, and every library meets the same placements.
template <typename Body>
[[gnu::noinline]] void AtStackShift(size_t shift, Body&& body)
{
    volatile char* pad = static_cast<volatile char*>(__builtin_alloca(shift + 64));
    pad[0] = 0;
    body();
    pad[shift] = 0; // the pad is used after the call, so the call cannot become a jump that drops the pad
}

// One pass of a query over `count` records: the sum of its results. `run` arrives by value, so the loop calls it
// from a register: read from the Query object in every call, it was a load from a fixed address that the CPU may
// take as depending on the stack stores of the query before it (addresses equal modulo 4096), which made one
// library's times swing by up to a factor of two with the stack's position.
template <typename Record>
double Stream(const Record* records, size_t count, double (*run)(const Record&))
{
    double sink = 0.0;
    for (size_t i = 0; i < count; ++i)
    {
        sink += run(records[i]);
    }
    return sink;
}

// Stream over the records in the order `order` gives.
template <typename Record>
double StreamInOrder(const Record* records, const std::vector<uint32_t>& order, double (*run)(const Record&))
{
    double sink = 0.0;
    for (const uint32_t i : order)
    {
        sink += run(records[i]);
    }
    return sink;
}

// Pass times of every query at one vertex count: passes[name][k] is ns per query in sweep k, and the sweeps run
// one pass of every query in turn, so equal k are measured moments apart.
struct Timing
{
    std::map<std::string, std::vector<double>> passes;

    // ns per query: the median over the passes.
    double Ns(const std::string& name) const
    {
        const double frames = name.find(", moving") != std::string::npos ? kFrames : 1;
        return Median(passes.at(name)) / frames;
    }
    bool Has(const std::string& name) const { return passes.count(name) != 0; }
    // The time of one query over another's: the median over the sweeps of the ratio of their passes in the sweep.
    // Paired so, the ratio does not drift with the machine's speed, which on a shared host changes from second to
    // second by more than the differences measured.
    double Ratio(const std::string& numerator, const std::string& denominator) const
    {
        const std::vector<double>& a = passes.at(numerator);
        const std::vector<double>& b = passes.at(denominator);
        std::vector<double> ratios;
        for (size_t k = 0; k < std::min(a.size(), b.size()); ++k)
        {
            ratios.push_back(a[k] / b[k]);
        }
        return Median(ratios);
    }
};

// The records of a pair for satviz's queries.
SatvizRecord MakeSatvizRecord(const BenchPair& p)
{
    SatvizRecord record{p.sa, p.sb, p.xfA, p.xfB, p.velocity, {}, {}};
    RaySegment(p.sa, p.xfA, p.sb, p.xfB, p.velocity, record.rayFrom, record.rayTo);
    return record;
}

#ifdef SATVIZ_HAVE_BOX2D
// The records of a pair for Box2D's queries (n <= 8), with the segment cast of satviz's record.
Box2DRecord MakeBox2DRecord(const BenchPair& p, const SatvizRecord& record)
{
    Box2DRecord box{p.ba, p.bb, p.bxfA, p.bxfB, p.bsweepA, p.bsweepB, p.velocity, {}, p.ba, p.bb};
    box.ray.p1.Set(static_cast<float>(record.rayFrom.x), static_cast<float>(record.rayFrom.y));
    box.ray.p2.Set(static_cast<float>(record.rayTo.x), static_cast<float>(record.rayTo.y));
    box.ray.maxFraction = 1.0f;
    box.skinA.m_radius = b2_polygonRadius;
    box.skinB.m_radius = b2_polygonRadius;
    return box;
}
#endif

Timing Time(const Settings& s, int n, const std::vector<Query>& queries, Rng& rng)
{
    const int perSlice = n >= 1024 ? std::max(1, s.pairs / 10) : s.pairs;
    std::vector<Slice> slices(static_cast<size_t>(s.slices));
    for (Slice& slice : slices)
    {
        const std::vector<BenchPair> pool = MakePool(rng, n, perSlice);
#ifdef SATVIZ_HAVE_CHIPMUNK
        slice.chipmunk = std::make_unique<ChipmunkRecord[]>(pool.size());
        slice.chipmunkCount = pool.size();
        for (size_t i = 0; i < pool.size(); ++i)
        {
            slice.chipmunk[i].Init(pool[i].sa.polygon, pool[i].xfA, pool[i].sb.polygon, pool[i].xfB);
        }
#endif
        for (const BenchPair& p : pool)
        {
            const bool apart = !Overlap(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB);
            const SatvizRecord record = MakeSatvizRecord(p);
            slice.satviz.push_back(record);
            const FloatRecord single{MakeShape(p.fa),
                                     MakeShape(p.fb),
                                     p.fxfA,
                                     p.fxfB,
                                     ConvertVec<float>(p.velocity),
                                     ConvertVec<float>(record.rayFrom),
                                     ConvertVec<float>(record.rayTo)};
            slice.single.push_back(single);
            if (apart)
            {
                slice.satvizApart.push_back(record);
                slice.singleApart.push_back(single);
            }
#ifdef SATVIZ_HAVE_BOX2D
            if (n <= b2_maxPolygonVertices)
            {
                const Box2DRecord box = MakeBox2DRecord(p, record);
                slice.box2d.push_back(box);
                if (apart)
                {
                    slice.box2dApart.push_back(box);
                }
            }
#endif
        }
    }
    Timing timing;
    int sweep = 0;
    std::vector<uint32_t> order;
    std::mt19937 shuffler(static_cast<uint32_t>(s.seed + static_cast<uint64_t>(n)));
    for (int round = 0; round < s.rounds; ++round)
    {
        const size_t shift = static_cast<size_t>(round * 4096 / s.rounds) & ~size_t(63);
        AtStackShift(shift, [&]() {
            auto pass = [&](const Query& q, const Slice& data) {
                double sink = 0.0;
                size_t count = 0;
                if (q.satviz)
                {
                    const std::vector<SatvizRecord>& records = q.sweep ? data.satvizApart : data.satviz;
                    Touch(records.data(), records.size());
                }
                else if (q.single)
                {
                    const std::vector<FloatRecord>& records = q.sweep ? data.singleApart : data.single;
                    Touch(records.data(), records.size());
                }
#ifdef SATVIZ_HAVE_CHIPMUNK
                else if (q.chipmunkRun)
                {
                    Touch(data.chipmunk.get(), data.chipmunkCount);
                }
#endif
#ifdef SATVIZ_HAVE_BOX2D
                else
                {
                    const std::vector<Box2DRecord>& records = q.sweep ? data.box2dApart : data.box2d;
                    Touch(records.data(), records.size());
                }
#endif
                // A random order, drawn before the clock starts (the satviz and Box2D records are in the same
                // order, one per pair, except that Box2D's stop at 8 vertices).
                if (q.randomOrder)
                {
                    order.resize(q.satviz ? data.satviz.size() : data.Box2DCount());
                    std::iota(order.begin(), order.end(), uint32_t(0));
                    std::shuffle(order.begin(), order.end(), shuffler);
                }
                const auto start = std::chrono::steady_clock::now();
                if (q.satviz && q.randomOrder)
                {
                    sink = StreamInOrder(data.satviz.data(), order, q.satviz);
                    count = order.size();
                }
                else if (q.satviz)
                {
                    const std::vector<SatvizRecord>& records = q.sweep ? data.satvizApart : data.satviz;
                    sink = Stream(records.data(), records.size(), q.satviz);
                    count = records.size();
                }
                else if (q.single)
                {
                    const std::vector<FloatRecord>& records = q.sweep ? data.singleApart : data.single;
                    sink = Stream(records.data(), records.size(), q.single);
                    count = records.size();
                }
#ifdef SATVIZ_HAVE_CHIPMUNK
                else if (q.chipmunkRun)
                {
                    sink = Stream(data.chipmunk.get(), data.chipmunkCount, q.chipmunkRun);
                    count = data.chipmunkCount;
                }
#endif
#ifdef SATVIZ_HAVE_BOX2D
                else if (q.randomOrder)
                {
                    sink = StreamInOrder(data.box2d.data(), order, q.box2dRun);
                    count = order.size();
                }
                else
                {
                    const std::vector<Box2DRecord>& records = q.sweep ? data.box2dApart : data.box2d;
                    sink = Stream(records.data(), records.size(), q.box2dRun);
                    count = records.size();
                }
#endif
                const auto stop = std::chrono::steady_clock::now();
                g_sink = g_sink + sink;
                return std::chrono::duration<double, std::nano>(stop - start).count() /
                       static_cast<double>(std::max<size_t>(1, count));
            };
            const auto runs = [n](const Query& q) { return !(q.box2d && n > 8) && n <= q.maxCount; };
            // Warm: every query over every slice.
            for (const Query& q : queries)
            {
                for (const Slice& data : slices)
                {
                    if (runs(q))
                    {
                        pass(q, data);
                    }
                }
            }
            // Sweeps: one pass of every query in turn, each sweep on the next slice.
            for (int r = 0; r < s.reps; ++r, ++sweep)
            {
                const Slice& data = slices[static_cast<size_t>(sweep % s.slices)];
                for (const Query& q : queries)
                {
                    if (runs(q))
                    {
                        timing.passes[q.name].push_back(pass(q, data));
                    }
                }
            }
        });
    }
    return timing;
}

// The queries timed on near-contact pairs: satviz's four beside Box2D's and the textbook loop's.
const char* const kNearQueries[] = {"satviz Overlap",
                                    "satviz Collide",
                                    "satviz Sweep",
                                    "satviz SweepTime",
                                    "textbook Overlap",
                                    "textbook MTV",
                                    "textbook TOI",
                                    "box2d b2TestOverlap",
                                    "box2d b2CollidePolygons",
                                    "box2d b2TimeOfImpact",
                                    "box2d b2TimeOfImpact + b2CollidePolygons at t"};

// The kinds of near-contact pair, in the order of PairCategory, as the breakdown names them.
const char* const kNearKinds[] = {"overlapping", "touching", "apart"};

// Where the time of Collide and SweepTime goes on near-contact pairs (the breakdown after the near-contact table):
// each timed on the pairs of one kind alone, beside Box2D's peer, so that the branch on the kind of pair is
// predicted as well as it can be; and satviz's again on the whole pool, chained: each query waits for the result of
// the one before (B's position moved by 0 times its depth or time), so that the processor cannot start a query
// before the one before has finished. As fast chained as not: the processor overlaps nothing of one query with the
// next even when it could, and a query's time is its latency, the chain of dependent instructions from the
// transforms to the result. `kinds[i]` is the kind of pair i.
#ifdef SATVIZ_HAVE_BOX2D
void TimeBreakdown(const std::vector<SatvizRecord>& satviz, const std::vector<Box2DRecord>& box2d,
                   const std::vector<int>& kinds, Timing& timing)
#else
void TimeBreakdown(const std::vector<SatvizRecord>& satviz, const std::vector<int>& kinds, Timing& timing)
#endif
{
    double sink = 0.0;
    // Each pass over records in the cache (Touch), as the near-contact table times them.
    const auto time = [&](const std::string& name, const auto& records, auto&& pass) {
        Touch(records.data(), records.size());
        const auto start = std::chrono::steady_clock::now();
        pass();
        const auto stop = std::chrono::steady_clock::now();
        timing.passes[name].push_back(std::chrono::duration<double, std::nano>(stop - start).count() /
                                      static_cast<double>(std::max<size_t>(1, records.size())));
    };
    for (int kind = 0; kind < 3; ++kind)
    {
        // The pairs of this kind, in the pool's order, side by side in memory.
        std::vector<SatvizRecord> chosen;
#ifdef SATVIZ_HAVE_BOX2D
        std::vector<Box2DRecord> chosenBox2D;
#endif
        for (size_t i = 0; i < kinds.size(); ++i)
        {
            if (kinds[i] == kind)
            {
                chosen.push_back(satviz[i]);
#ifdef SATVIZ_HAVE_BOX2D
                if (!box2d.empty())
                {
                    chosenBox2D.push_back(box2d[i]);
                }
#endif
            }
        }
        const std::string suffix = std::string(": ") + kNearKinds[kind];
        time("satviz Collide" + suffix, chosen, [&]() {
            for (const SatvizRecord& p : chosen)
            {
                sink += Collide(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB).depth;
            }
        });
        time("satviz SweepTime" + suffix, chosen, [&]() {
            for (const SatvizRecord& p : chosen)
            {
                sink += SweepTime(p.sa, p.xfA, Vec2{}, p.sb, p.xfB, p.velocity).toi;
            }
        });
#ifdef SATVIZ_HAVE_BOX2D
        if (!chosenBox2D.empty())
        {
            time("box2d b2CollidePolygons" + suffix, chosenBox2D, [&]() {
                for (const Box2DRecord& p : chosenBox2D)
                {
                    b2Manifold manifold;
                    b2CollidePolygons(&manifold, &p.ba, p.bxfA, &p.bb, p.bxfB);
                    sink += static_cast<double>(manifold.pointCount);
                }
            });
            time("box2d b2TimeOfImpact" + suffix, chosenBox2D, [&]() {
                for (const Box2DRecord& p : chosenBox2D)
                {
                    b2TOIOutput output;
                    b2TimeOfImpact(&output, &Box2DTOIInput(p, p.ba, p.bb));
                    sink += static_cast<double>(output.t);
                }
            });
        }
#endif
    }
    time("satviz Collide, chained", satviz, [&]() {
        double wait = 0.0;
        for (const SatvizRecord& p : satviz)
        {
            const Transform xfB{p.xfB.p + Vec2{wait, 0.0}, p.xfB.q};
            const double depth = Collide(p.sa.polygon, p.xfA, p.sb.polygon, xfB).depth;
            sink += depth;
            wait = 0.0 * depth;
        }
    });
    time("satviz SweepTime, chained", satviz, [&]() {
        double wait = 0.0;
        for (const SatvizRecord& p : satviz)
        {
            const Transform xfB{p.xfB.p + Vec2{wait, 0.0}, p.xfB.q};
            const double toi = SweepTime(p.sa, p.xfA, Vec2{}, p.sb, xfB, p.velocity).toi;
            sink += toi;
            wait = 0.0 * toi;
        }
    });
    g_sink = g_sink + sink;
}

// Near-contact pairs from pools that no pass replays: each round draws a fresh pool of `pairs` pairs per vertex
// count, and every query makes one pass over it, in an order shuffled per round, so no query meets a pair twice and
// no branch predictor learns a pool. The sweeps run on every pair (B moving roughly towards A; a third of the pairs
// start overlapped). passes[name][k] is ns per query in round k: the rounds pair the queries for the ratios.
Timing TimeNear(const Settings& s, int n, const std::vector<Query>& queries, Rng& rng)
{
    std::vector<const Query*> timed;
    for (const char* name : kNearQueries)
    {
        for (const Query& q : queries)
        {
            if (q.name == name && !(q.box2d && n > 8))
            {
                timed.push_back(&q);
            }
        }
    }
    Timing timing;
    std::mt19937 shuffler(static_cast<uint32_t>(s.seed + 7919 * static_cast<uint64_t>(n)));
    for (int round = 0; round < s.nearRounds; ++round)
    {
        std::vector<SatvizRecord> satviz;
#ifdef SATVIZ_HAVE_BOX2D
        std::vector<Box2DRecord> box2d;
#endif
        for (int i = 0; i < s.nearPairs; ++i)
        {
            const PairCategory category = static_cast<PairCategory>(i % 3);
            const RandomPair drawn = s.placement == "direction" ? bench::NearContactPair(rng, n, category)
                                                                : EitherWay(ContactPair(rng, n, category), rng);
            const BenchPair p = MakeBenchPair(drawn, rng);
            satviz.push_back(MakeSatvizRecord(p));
#ifdef SATVIZ_HAVE_BOX2D
            if (n <= b2_maxPolygonVertices)
            {
                box2d.push_back(MakeBox2DRecord(p, satviz.back()));
            }
#endif
        }
        // The categories in a random order along the pool.
        std::vector<uint32_t> order(satviz.size());
        std::iota(order.begin(), order.end(), uint32_t(0));
        std::shuffle(order.begin(), order.end(), shuffler);
        std::vector<SatvizRecord> satvizShuffled;
        for (const uint32_t i : order)
        {
            satvizShuffled.push_back(satviz[i]);
        }
        satviz.swap(satvizShuffled);
#ifdef SATVIZ_HAVE_BOX2D
        if (!box2d.empty())
        {
            std::vector<Box2DRecord> box2dShuffled;
            for (const uint32_t i : order)
            {
                box2dShuffled.push_back(box2d[i]);
            }
            box2d.swap(box2dShuffled);
        }
#endif
        std::vector<int> kinds;
        for (const uint32_t i : order)
        {
            kinds.push_back(static_cast<int>(i % 3));
        }
        std::shuffle(timed.begin(), timed.end(), shuffler);
        const size_t shift = static_cast<size_t>(round * 4096 / s.nearRounds) & ~size_t(63);
        AtStackShift(shift, [&]() {
            for (const Query* q : timed)
            {
                double sink = 0.0;
                size_t count = 0;
                std::chrono::steady_clock::time_point start;
                if (q->satviz)
                {
                    Touch(satviz.data(), satviz.size());
                    start = std::chrono::steady_clock::now();
                    sink = Stream(satviz.data(), satviz.size(), q->satviz);
                    count = satviz.size();
                }
#ifdef SATVIZ_HAVE_BOX2D
                else if (q->box2dRun)
                {
                    Touch(box2d.data(), box2d.size());
                    start = std::chrono::steady_clock::now();
                    sink = Stream(box2d.data(), box2d.size(), q->box2dRun);
                    count = box2d.size();
                }
#endif
                const auto stop = std::chrono::steady_clock::now();
                g_sink = g_sink + sink;
                timing.passes[q->name].push_back(std::chrono::duration<double, std::nano>(stop - start).count() /
                                                 static_cast<double>(std::max<size_t>(1, count)));
            }
        });
#ifdef SATVIZ_HAVE_BOX2D
        TimeBreakdown(satviz, box2d, kinds, timing);
#else
        TimeBreakdown(satviz, kinds, timing);
#endif
    }
    return timing;
}

// A query name as a CSV field: its commas become semicolons.
std::string CsvName(std::string name)
{
    std::replace(name.begin(), name.end(), ',', ';');
    return name;
}

// The median and the largest of a list of errors as two CSV fields, empty for none.
void CsvFigures(std::ostream& out, const std::vector<double>& v)
{
    if (!v.empty())
    {
        out << Median(v) << ',' << *std::max_element(v.begin(), v.end());
    }
    else
    {
        out << ',';
    }
}

// Wrong answers within this distance of touching (reference separation) are counted apart: a band where the
// rounding of the input itself may decide.
constexpr double kBand = 1e-12;

struct Accuracy
{
    bool sweep = false; // errors are times of impact, not depths
    int pairs = 0;
    int wrong = 0;
    int falsePositives = 0;
    int falseNegatives = 0;
    int wrongOutsideBand = 0; // wrong answers on pairs farther than kBand from touching
    std::vector<double> depthErrors;
    std::vector<double> angleErrors;    // angle between the normal and the reference's, radians
    std::vector<double> relativeErrors; // depth errors over the pair's coordinate scale, max(1, |position|)
    std::vector<double> signedErrors;   // sweeps: t - reference t (Box2D stops short of contact: negative)
    int failures = 0;                   // sweeps: the library's own failure state (b2TOIOutput::e_failed)
};

// The angle between two directions, in radians (0 to pi), from their cross and dot products.
double AngleBetween(double ax, double ay, double bx, double by)
{
    return std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by);
}

// One static answer: yes/no against the reference and, on pairs both call overlapping, the depth error and, when
// `normal` is given, the angle of the normal (from A to B) to the reference normal.
void Record(Accuracy& acc, bool answer, const Reference& ref, double depth, bool withDepth,
            const double* normal = nullptr, double scale = 1.0)
{
    acc.pairs += 1;
    if (answer != ref.overlap)
    {
        acc.wrong += 1;
        (answer ? acc.falsePositives : acc.falseNegatives) += 1;
        if (std::abs(static_cast<double>(ref.separation)) >= kBand)
        {
            acc.wrongOutsideBand += 1;
        }
    }
    if (withDepth && answer && ref.overlap)
    {
        acc.depthErrors.push_back(std::abs(depth + static_cast<double>(ref.separation)));
        acc.relativeErrors.push_back(acc.depthErrors.back() / scale);
        if (normal != nullptr)
        {
            // To the nearest co-minimal axis of the reference (any of them is a right answer), else its normal.
            double angle = AngleBetween(normal[0], normal[1], ref.normalX, ref.normalY);
            for (const Vec2& tie : ref.ties)
            {
                angle = std::min(angle, AngleBetween(normal[0], normal[1], tie.x, tie.y));
            }
            acc.angleErrors.push_back(angle);
        }
    }
}

// One sweep answer against the reference. Besides |t error|, the relative error is the distance the error in t
// moves the shapes along the contact normal (|t error| times the closing speed `rate` along it), over the pair's
// scale: the backward error, which input rounding alone bounds, where |t error| itself grows without bound as the
// motion turns parallel to the face.
void RecordSweep(Accuracy& acc, bool hit, double t, bool refHit, double refT, double rate = 0.0, double scale = 1.0)
{
    acc.sweep = true;
    acc.pairs += 1;
    if (hit != refHit)
    {
        acc.wrong += 1;
        acc.wrongOutsideBand += 1;
        (hit ? acc.falsePositives : acc.falseNegatives) += 1;
    }
    else if (hit)
    {
        acc.signedErrors.push_back(t - refT);
        acc.depthErrors.push_back(std::abs(t - refT));
        acc.relativeErrors.push_back(acc.depthErrors.back() * std::abs(rate) / scale);
    }
}

// One segment cast against the reference: hit or not (a wrong answer counts outside the band when the segment is
// farther than kBand from grazing, ending on or starting on the outline), and on hits both call entering from
// outside, the error of the entry point along the segment, and the normal's angle. The relative error is, as for
// sweeps, the backward error: the entry point's error along the face normal (the error along the segment times
// the cosine between segment and normal), over the pair's scale.
void RecordRay(Accuracy& acc, bool hit, bool startsInside, double fraction, const double normal[2],
               const ReferenceRay& ref, Vec2 segment, double scale)
{
    acc.pairs += 1;
    if (hit != ref.hit || (hit && startsInside != ref.inside))
    {
        acc.wrong += 1;
        (hit ? acc.falsePositives : acc.falseNegatives) += hit != ref.hit ? 1 : 0;
        if (static_cast<double>(ref.margin) >= kBand)
        {
            acc.wrongOutsideBand += 1;
        }
        return;
    }
    if (hit && !startsInside)
    {
        const double error = std::abs(fraction - static_cast<double>(ref.enter));
        acc.depthErrors.push_back(error * Length(segment));
        const double closing =
            static_cast<double>(ref.normal.x) * segment.x + static_cast<double>(ref.normal.y) * segment.y;
        acc.relativeErrors.push_back(error * std::abs(closing) / scale);
        acc.angleErrors.push_back(
            AngleBetween(normal[0], normal[1], static_cast<double>(ref.normal.x), static_cast<double>(ref.normal.y)));
    }
}

// Every query's answer on one pair of n-gons, recorded against the reference.
void RecordPair(std::map<std::string, Accuracy>& acc, const BenchPair& p, int n, Rng& rng)
{
    const Reference ref = ReferenceCollide(p.sa, p.xfA, p.sb, p.xfB);
    Record(acc["satviz Overlap"], Overlap(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB), ref, 0.0, false);
    Record(acc["satviz Overlap float"], Overlap(p.fa, p.fxfA, p.fb, p.fxfB), ref, 0.0, false);
    const Manifold m = Collide(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB);
    // Far from the origin, float can only be as precise as its positions: errors relative to their magnitude.
    const double scale =
        std::max({1.0, std::abs(p.xfA.p.x), std::abs(p.xfA.p.y), std::abs(p.xfB.p.x), std::abs(p.xfB.p.y)});
    const double normal[2] = {m.normal.x, m.normal.y};
    Record(acc["satviz Collide"], m.overlap, ref, m.depth, true, normal, scale);
    const ManifoldT<float> mf = Collide(p.fa, p.fxfA, p.fb, p.fxfB);
    const double normalFloat[2] = {mf.normal.x, mf.normal.y};
    Record(acc["satviz Collide float"], mf.overlap, ref, mf.depth, true, normalFloat, scale);
    // The variants, each with one of the algorithm's choices turned off: the same answers, or the cost of a choice
    // in accuracy would show here.
    const SatvizRecord record{p.sa, p.sb, p.xfA, p.xfB, p.velocity, {}, {}};
    Record(acc["satviz Overlap, no early exit"], OverlapVariant<NoEarlyExit>(record) != 0.0, ref, 0.0, false);
    Record(acc["satviz Overlap, no parallel skip"], OverlapVariant<NoParallelSkip>(record) != 0.0, ref, 0.0, false);
    Record(acc["satviz Overlap, walk only"], OverlapVariant<WalkOnly>(record) != 0.0, ref, 0.0, false);
    Record(acc["satviz Overlap, walked unpruned"], OverlapVariant<NoWalkedPruning>(record) != 0.0, ref, 0.0, false);
    const auto collideVariant = [&](const char* name, auto variant) {
        const Manifold mv = detail::CollidePolygons(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, variant);
        const double normalV[2] = {mv.normal.x, mv.normal.y};
        Record(acc[name], mv.overlap, ref, mv.depth, true, normalV, scale);
    };
    collideVariant("satviz Collide, no early exit", NoEarlyExit{});
    collideVariant("satviz Collide, no parallel skip", NoParallelSkip{});
    collideVariant("satviz Collide, walk only", WalkOnly{});
    // The cached axis: the moving frames of the timed query, each against its own reference (small polygons: the
    // reference costs O(n m) per frame).
    if (n <= 64)
    {
        SatCache cache;
        for (int frame = 0; frame < kFrames; ++frame)
        {
            const Transform xfB{p.xfB.p + (0.005 * frame) * LeftPerp(p.velocity), p.xfB.q};
            const Reference moved = ReferenceCollide(p.sa, p.xfA, p.sb, xfB);
            Record(acc["satviz Overlap, moving, cached axis"], Overlap(p.sa.polygon, p.xfA, p.sb.polygon, xfB, cache),
                   moved, 0.0, false);
        }
    }
    Record(acc["textbook Overlap"], bench::TextbookOverlap(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB), ref, 0.0, false);
    Vec2 textbookNormal;
    const double textbookDepth = bench::TextbookMtv(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, textbookNormal);
    const double textbookNormalXY[2] = {textbookNormal.x, textbookNormal.y};
    Record(acc["textbook MTV"], textbookDepth >= 0.0, ref, textbookDepth, true, textbookNormalXY);
    // Times of impact against the Minkowski-difference cast (its hull of n * n points limits it to n <= 64).
    const bool sweepRef = n <= 64 && !Overlap(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB);
    SweepReference sr;
    bool refHit = false;
    double refT = 0.0;
    double rate = 0.0;
    if (sweepRef)
    {
        sr = ReferenceSweep(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, p.velocity);
        refHit = sr.insideAtStart || (sr.crosses && sr.enter <= 1 && sr.leave > 0);
        refT = sr.insideAtStart ? 0.0 : std::max(0.0, static_cast<double>(sr.enter));
        const SweepResult sw = Sweep(p.sa, p.xfA, Vec2{}, p.sb, p.xfB, p.velocity);
        // The closing speed along the contact normal, for the backward error (the double normal is exact to
        // rounding).
        rate = Dot(sw.normal, p.velocity);
        RecordSweep(acc["satviz Sweep"], sw.status != SweepStatus::Miss, sw.toi, refHit, refT, rate, scale);
        const SweepResult swTime = SweepTime(p.sa, p.xfA, Vec2{}, p.sb, p.xfB, p.velocity);
        RecordSweep(acc["satviz SweepTime"], swTime.status != SweepStatus::Miss, swTime.toi, refHit, refT, rate, scale);
        const SweepResultT<float> swFloat =
            Sweep(MakeShape(p.fa), p.fxfA, Vec2T<float>{}, MakeShape(p.fb), p.fxfB, ConvertVec<float>(p.velocity));
        RecordSweep(acc["satviz Sweep float"], swFloat.status != SweepStatus::Miss, swFloat.toi, refHit, refT, rate,
                    scale);
        const double textbookT = bench::TextbookToi(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB, p.velocity);
        RecordSweep(acc["textbook TOI"], textbookT >= 0.0, textbookT, refHit, refT, rate, scale);
    }
    // Segment casts at A: the timed one (from behind B's centroid to A's), and one aimed past a vertex of A by up
    // to a tenth of A's size either side, which grazes, hits near a corner or misses.
    Vec2 rayFrom;
    Vec2 rayTo;
    RaySegment(p.sa, p.xfA, p.sb, p.xfB, p.velocity, rayFrom, rayTo);
    const Vec2 corner = TransformPoint(p.xfA, p.sa.polygon.Vertices()[static_cast<size_t>(rng.Int(0, n - 1))]);
    const Vec2 past = corner + (Radius(p.sa.polygon) * rng.Uniform(-0.1, 0.1)) * Normalize(LeftPerp(corner - rayFrom));
    const Vec2 rays[2][2] = {{rayFrom, rayTo}, {rayFrom, rayFrom + 1.5 * (past - rayFrom)}};
    for (const auto& ray : rays)
    {
        const ReferenceRay refRay = ReferencePolygonRay(p.sa.polygon, p.xfA, ray[0], ray[1]);
        const Vec2 segment = ray[1] - ray[0];
        const RayHit hit = RayCast(p.sa.polygon, p.xfA, ray[0], ray[1]);
        const double hitNormal[2] = {hit.normal.x, hit.normal.y};
        RecordRay(acc["satviz RayCast"], hit.hit, hit.startsInside, hit.fraction, hitNormal, refRay, segment, scale);
        const RayHitT<float> hitFloat = RayCast(p.fa, p.fxfA, ConvertVec<float>(ray[0]), ConvertVec<float>(ray[1]));
        const double floatNormal[2] = {hitFloat.normal.x, hitFloat.normal.y};
        RecordRay(acc["satviz RayCast float"], hitFloat.hit, hitFloat.startsInside, hitFloat.fraction, floatNormal,
                  refRay, segment, scale);
#ifdef SATVIZ_HAVE_BOX2D
        // Box2D reports no hit for a segment that starts inside: such segments are left out of its row.
        if (n <= b2_maxPolygonVertices && !refRay.inside)
        {
            b2RayCastInput input;
            input.p1.Set(static_cast<float>(ray[0].x), static_cast<float>(ray[0].y));
            input.p2.Set(static_cast<float>(ray[1].x), static_cast<float>(ray[1].y));
            input.maxFraction = 1.0f;
            b2RayCastOutput output;
            const bool box2dHit = p.ba.RayCast(&output, input, p.bxfA, 0);
            const double box2dNormal[2] = {output.normal.x, output.normal.y};
            RecordRay(acc["box2d b2PolygonShape::RayCast"], box2dHit, false, output.fraction, box2dNormal, refRay,
                      segment, scale);
        }
#endif
    }
#ifdef SATVIZ_HAVE_CHIPMUNK
    {
        ChipmunkRecord r;
        r.Init(p.sa.polygon, p.xfA, p.sb.polygon, p.xfB);
        bool overlap = false;
        double chipmunkNormal[2];
        const double depth = ChipmunkDepth(r, overlap, chipmunkNormal);
        Record(acc["chipmunk cpShapesCollide"], overlap, ref, depth, true, chipmunkNormal);
    }
#endif
#ifdef SATVIZ_HAVE_BOX2D
    if (n <= b2_maxPolygonVertices)
    {
        Record(acc["box2d b2TestOverlap"], b2TestOverlap(&p.ba, 0, &p.bb, 0, p.bxfA, p.bxfB), ref, 0.0, false);
        b2Manifold manifold;
        b2CollidePolygons(&manifold, &p.ba, p.bxfA, &p.bb, p.bxfB);
        double box2dNormal[2] = {0.0, 0.0};
        const double box2dDepth = manifold.pointCount > 0 ? Box2DDepth(manifold, p, box2dNormal) : 0.0;
        Record(acc["box2d b2CollidePolygons"], manifold.pointCount > 0, ref, box2dDepth, true, box2dNormal, scale);
        if (sweepRef)
        {
            b2TOIOutput output;
            b2TimeOfImpact(&output, &Box2DTOIInput(p, p.ba, p.bb));
            const bool hit = output.state == b2TOIOutput::e_touching || output.state == b2TOIOutput::e_overlapped ||
                             output.state == b2TOIOutput::e_failed;
            Accuracy& box2dToi = acc["box2d b2TimeOfImpact"];
            RecordSweep(box2dToi, hit, output.state == b2TOIOutput::e_overlapped ? 0.0 : static_cast<double>(output.t),
                        refHit, refT, rate, scale);
            box2dToi.failures += output.state == b2TOIOutput::e_failed ? 1 : 0;
        }
        // The quirks of peer-benchmark.md shown, not handled: Box2D's default skin (every pair closer than 0.02
        // overlaps, depths 0.02 too large), and a floating origin (the pair moved in double so A's first vertex is
        // at the origin before it becomes float).
        b2PolygonShape skinA = p.ba;
        b2PolygonShape skinB = p.bb;
        skinA.m_radius = b2_polygonRadius;
        skinB.m_radius = b2_polygonRadius;
        Record(acc["box2d+skin b2TestOverlap"], b2TestOverlap(&skinA, 0, &skinB, 0, p.bxfA, p.bxfB), ref, 0.0, false);
        b2CollidePolygons(&manifold, &skinA, p.bxfA, &skinB, p.bxfB);
        const double skinDepth = manifold.pointCount > 0 ? Box2DDepth(manifold, p, box2dNormal, b2_polygonRadius) : 0.0;
        Record(acc["box2d+skin b2CollidePolygons"], manifold.pointCount > 0, ref, skinDepth, true, box2dNormal, scale);
        BenchPair recentred = p;
        const Vec2 origin = TransformPoint(p.xfA, p.sa.polygon.Vertices()[0]);
        recentred.bxfA = ToBox2D(Transform{p.xfA.p - origin, p.xfA.q});
        recentred.bxfB = ToBox2D(Transform{p.xfB.p - origin, p.xfB.q});
        Record(acc["box2d+recenter b2TestOverlap"], b2TestOverlap(&p.ba, 0, &p.bb, 0, recentred.bxfA, recentred.bxfB),
               ref, 0.0, false);
        b2CollidePolygons(&manifold, &p.ba, recentred.bxfA, &p.bb, recentred.bxfB);
        const double recentredDepth = manifold.pointCount > 0 ? Box2DDepth(manifold, recentred, box2dNormal) : 0.0;
        Record(acc["box2d+recenter b2CollidePolygons"], manifold.pointCount > 0, ref, recentredDepth, true, box2dNormal,
               scale);
    }
#endif
}

std::map<std::string, Accuracy> MeasureAccuracy(const Settings& s, const std::vector<int>& counts, Rng& rng)
{
    std::map<std::string, Accuracy> acc;
    for (int n : counts)
    {
        const int count =
            n >= 1024 ? std::max(1, s.accuracyPairs / 300) : (n >= 64 ? s.accuracyPairs / 10 : s.accuracyPairs);
        for (const BenchPair& p : MakePool(rng, n, count))
        {
            RecordPair(acc, p, n, rng);
        }
    }
    return acc;
}

// The categories of the accuracy tables: the three placements, then one of them far from the origin, or with
// slivers (aspect 1e-4 to 1e-2) among the polygons.
const char* const kCategories[] = {"overlap", "touch (gap <= 1e-9)", "separated", "far (1e6)", "far (1e8)", "sliver"};

// Pairs of one category: as MakePool, then moved far from the origin or built with slivers.
std::vector<BenchPair> MakeCategoryPool(Rng& rng, int n, int count, int category)
{
    std::vector<BenchPair> pool;
    for (int i = 0; i < count; ++i)
    {
        const PairCategory placement = static_cast<PairCategory>(category <= 2 ? category : rng.Int(0, 2));
        RandomPair pair = ContactPair(rng, n, placement, category == 5 ? 1.0 : 0.0);
        if (category == 3 || category == 4)
        {
            const double far = category == 3 ? 1e6 : 1e8;
            const Vec2 offset{rng.Chance(0.5) ? far : -far, rng.Chance(0.5) ? far : -far};
            pair.xfA.p = pair.xfA.p + offset;
            pair.xfB.p = pair.xfB.p + offset;
        }
        BenchPair p = MakeBenchPair(EitherWay(pair, rng), rng);
        if (p.floatOk)
        {
            pool.push_back(std::move(p));
        }
    }
    return pool;
}

// Accuracy per category, over the vertex counts up to 16 (Box2D: up to 8).
std::vector<std::map<std::string, Accuracy>> MeasureByCategory(const Settings& s, Rng& rng)
{
    std::vector<std::map<std::string, Accuracy>> byCategory(std::size(kCategories));
    for (size_t c = 0; c < byCategory.size(); ++c)
    {
        for (int n : {3, 4, 8, 16})
        {
            for (const BenchPair& p : MakeCategoryPool(rng, n, s.accuracyPairs / 6, static_cast<int>(c)))
            {
                RecordPair(byCategory[c], p, n, rng);
            }
        }
    }
    return byCategory;
}

// The machine, the build and the command line, so that a results file says where its figures come from.
void PrintMachine(int argc, char** argv)
{
    std::string cpu = "unknown CPU";
    std::string model;
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
    {
        const auto field = [&line](const char* key) {
            return line.rfind(key, 0) == 0 && line.find(':') != std::string::npos ? line.substr(line.find(':') + 2)
                                                                                  : std::string();
        };
        if (const std::string name = field("model name"); !name.empty())
        {
            cpu = name;
        }
        if (const std::string family = field("cpu family"); !family.empty() && model.empty())
        {
            model = "family " + family;
        }
        if (const std::string number = field("model\t"); !number.empty() && model.find("model") == std::string::npos)
        {
            model += ", model " + number;
        }
        if (line.empty() && !model.empty())
        {
            break;
        }
    }
    std::printf("machine: %s (%s), %u logical CPUs\n", cpu.c_str(), model.c_str(), std::thread::hardware_concurrency());
    std::printf("build: GCC %s, %s; satviz %s\n", __VERSION__, SATVIZ_BENCH_FLAGS,
#if SATVIZ_WIDE
                "with its AVX2/AVX-512 paths chosen at run time"
#else
                "without wide paths"
#endif
    );
#ifdef SATVIZ_HAVE_BOX2D
    // The package's version (2.4.1 reports b2_version 2.4.0).
    std::printf("peers: Box2D %s", SATVIZ_BOX2D_VERSION);
#else
    std::printf("peers: no Box2D");
#endif
#ifdef SATVIZ_HAVE_CHIPMUNK
    std::printf(", Chipmunk %s", cpVersionString);
#else
    std::printf(", no Chipmunk");
#endif
    std::printf(bench::HaveBox2DV3() ? ", Box2D v3 %s\n" : ", no Box2D v3%s\n", bench::Box2DV3Version().c_str());
    std::printf("command:");
    for (int i = 0; i < argc; ++i)
    {
        std::printf(" %s", i == 0 ? "satviz-bench" : argv[i]);
    }
    std::printf("\n\n");
}

// The head of a near-contact table: "query", then a column per vertex count.
void PrintNearHeader(const Settings& s)
{
    std::printf("%-46s", "query");
    for (int n : s.nearCounts)
    {
        std::printf(" %7s", ("n=" + std::to_string(n)).c_str());
    }
    std::printf("\n");
}

// A row of a near-contact table: `label`, then the ns per query of `name` at each vertex count ("-" where not timed).
void PrintNearRow(const Settings& s, const std::map<int, Timing>& timings, const std::string& name,
                  const std::string& label)
{
    std::printf("%-46s", label.c_str());
    for (int n : s.nearCounts)
    {
        const Timing& t = timings.at(n);
        if (t.Has(name))
        {
            std::printf(" %7.1f", t.Ns(name));
        }
        else
        {
            std::printf(" %7s", "-");
        }
    }
    std::printf("\n");
}

// The breakdown after the near-contact table (TimeBreakdown): Collide and SweepTime, satviz's and Box2D's, on the
// pairs of each kind alone and on all of them, then satviz's chained, and its time chained over its time unchained.
void PrintBreakdown(const Settings& s, const std::map<int, Timing>& timings)
{
    std::printf("\nwhere the time goes: ns per query on the pairs of one kind alone (same rounds and pools), and\n"
                "satviz's chained (each query waits for the result of the one before; as fast as unchained:\n"
                "the processor overlaps nothing of one query with the next, so a query's time is its latency)\n\n");
    PrintNearHeader(s);
    const auto row = [&](const std::string& name, const std::string& label) { PrintNearRow(s, timings, name, label); };
    for (const std::string query : {"Collide", "SweepTime"})
    {
        const std::string peer = query == "Collide" ? "box2d b2CollidePolygons" : "box2d b2TimeOfImpact";
        for (const std::string& who : {"satviz " + query, peer})
        {
            for (const char* kind : kNearKinds)
            {
                row(who + ": " + kind, who + ": " + kind);
            }
            row(who, who + ": all (as above)");
        }
        row("satviz " + query + ", chained", "satviz " + query + ", chained");
    }
    std::printf("%-46s", "chained / unchained: Collide, SweepTime");
    for (int n : s.nearCounts)
    {
        const Timing& t = timings.at(n);
        std::printf(" %3.2f,%3.2f", t.Ratio("satviz Collide, chained", "satviz Collide"),
                    t.Ratio("satviz SweepTime, chained", "satviz SweepTime"));
    }
    std::printf("\n");
}

// The near-contact table: ns per query, then satviz's ratios to Box2D and to the textbook loop with the goals they
// are held to, at every vertex count of the run. Returns whether every goal was met.
bool PrintNear(const Settings& s, const std::map<int, Timing>& timings)
{
    std::printf("\nnear-contact pairs, placed %s: ns per query, median of %d rounds, each a fresh pool of %d pairs\n"
                "that every query passes over once (no pass replays a pair); a third overlapping by up to half a\n"
                "width, a third touching within 1e-9, a third apart by up to half a width; sweeps on every pair,\n"
                "B moving roughly towards A; ratios: median over the rounds of the ratio of two passes\n\n",
                s.placement == "direction" ? "along a random direction" : "along A's normal (as above)", s.nearRounds,
                s.nearPairs);
    PrintNearHeader(s);
    for (const char* name : kNearQueries)
    {
        PrintNearRow(s, timings, name, name);
    }
    bool met = true;
    std::printf("\n%-40s %6s", "ratio (<1: faster)", "goal");
    for (int n : s.nearCounts)
    {
        std::printf(" %7s", ("n=" + std::to_string(n)).c_str());
    }
    std::printf("\n");
    auto goal = [&](const char* label, const char* numerator, const char* denominator, double limit) {
        std::printf("%-40s %6.2f", label, limit);
        bool rowMet = true;
        for (int n : s.nearCounts)
        {
            const Timing& t = timings.at(n);
            if (!t.Has(numerator) || !t.Has(denominator))
            {
                std::printf(" %7s", "-");
                continue;
            }
            const double ratio = t.Ratio(numerator, denominator);
            rowMet = rowMet && ratio <= limit;
            std::printf(" %7.2f", ratio);
        }
        std::printf("  %s\n", rowMet ? "met" : "MISSED");
        met = met && rowMet;
    };
#ifdef SATVIZ_HAVE_BOX2D
    goal("Overlap / b2TestOverlap", "satviz Overlap", "box2d b2TestOverlap", 0.25);
    goal("Collide / b2CollidePolygons", "satviz Collide", "box2d b2CollidePolygons", 0.6);
    goal("SweepTime / b2TimeOfImpact (both: time)", "satviz SweepTime", "box2d b2TimeOfImpact", 0.25);
    goal("Sweep (contacts) / b2TimeOfImpact (time)", "satviz Sweep", "box2d b2TimeOfImpact", 0.35);
    goal("Sweep / b2TimeOfImpact + collide at t", "satviz Sweep", "box2d b2TimeOfImpact + b2CollidePolygons at t",
         0.35);
#endif
    goal("Overlap / textbook Overlap", "satviz Overlap", "textbook Overlap", 1.0);
    goal("Collide / textbook MTV", "satviz Collide", "textbook MTV", 1.0);
    goal("Sweep / textbook TOI", "satviz Sweep", "textbook TOI", 1.0);
    PrintBreakdown(s, timings);
    return met;
}

// Writes the near-contact figures as query,n,ns lines; false when writing failed.
bool WriteNearCsv(const std::string& directory, const std::map<int, Timing>& timings)
{
    std::ofstream out(std::filesystem::path(directory) / "timing_near.csv");
    out << "query,n,ns\n";
    for (const auto& [n, timing] : timings)
    {
        for (const auto& [name, passes] : timing.passes)
        {
            out << CsvName(name) << ',' << n << ',' << timing.Ns(name) << '\n';
        }
    }
    out.close();
    return static_cast<bool>(out);
}

// A list of vertex counts given to `option` with one below 3: the reason, naming the option; else "".
std::string CheckVertexCounts(const std::string& option, const std::vector<int>& counts)
{
    for (int n : counts)
    {
        if (n < 3)
        {
            return option + ": a polygon has at least 3 vertices, got " + std::to_string(n);
        }
    }
    return "";
}

// The settings' own mistakes, found before anything runs: a one-line reason naming the option, or "" when the
// settings can be run. A polygon of fewer than 3 vertices is never made (the pool would be drawn for ever), and no
// pairs or no rounds would leave no pass to take a median of.
std::string CheckSettings(const Settings& s)
{
    if (s.counts.empty())
    {
        return "--counts: give at least one vertex count";
    }
    if (std::string error = CheckVertexCounts("--counts", s.counts); !error.empty())
    {
        return error;
    }
    if (s.pairs < 1)
    {
        return "--pairs: at least 1 pair per slice, got " + std::to_string(s.pairs);
    }
    if (s.rounds < 1)
    {
        return "--rounds: at least 1 round, got " + std::to_string(s.rounds);
    }
    if (std::string error = CheckVertexCounts("--near-counts", s.nearCounts); !error.empty())
    {
        return error;
    }
    if (s.nearPairs < 3)
    {
        return "--near-pairs: at least 3 pairs per pool (one of each kind), got " + std::to_string(s.nearPairs);
    }
    if (s.nearRounds < 1)
    {
        return "--near-rounds: at least 1 round, got " + std::to_string(s.nearRounds);
    }
    if (s.placement != "direction" && s.placement != "face")
    {
        return "--near-placement: 'direction' or 'face', got '" + s.placement + "'";
    }
    return "";
}

// Makes sure the results can be written to `directory` (creating it if missing) before the run, which takes
// minutes; a file is created there and removed to prove it. Returns a one-line reason, or "" when it can.
std::string CheckCsvDirectory(const std::string& directory)
{
    const std::filesystem::path path(directory);
    std::error_code code;
    std::filesystem::create_directories(path, code);
    if (code)
    {
        return "--csv " + directory + ": cannot create the directory (" + code.message() + ")";
    }
    if (!std::filesystem::is_directory(path, code))
    {
        return "--csv " + directory + ": not a directory";
    }
    const std::filesystem::path probe = path / (".satviz-bench-probe-" + std::to_string(::getpid()));
    std::FILE* file = std::fopen(probe.c_str(), "w");
    if (file == nullptr)
    {
        return "--csv " + directory + ": cannot write there (" + std::strerror(errno) + ")";
    }
    std::fclose(file);
    std::filesystem::remove(probe, code);
    return "";
}

// Printed by --quick, with the figures: they come from tiny pools and one round.
constexpr const char* kQuickNotice =
    "--quick: tiny pools and one round: these figures only show that the benchmark runs; they are not measurements";

// Before a run: the settings' mistake (`settingsError`) or, with --csv, the directory's, as one line naming it on
// stderr; true when there is none and the run may start.
bool ReadyToRun(const std::string& settingsError, const std::string& csv)
{
    std::string error = settingsError;
    if (error.empty() && !csv.empty())
    {
        error = CheckCsvDirectory(csv);
    }
    if (!error.empty())
    {
        std::fprintf(stderr, "satviz-bench: %s\n", error.c_str());
        return false;
    }
    return true;
}

// The heading of a run: the machine and the command, then with --quick `quickNotice`, that its figures are not
// measurements.
void PrintHeading(int argc, char** argv, bool quick, const char* quickNotice)
{
    PrintMachine(argc, argv);
    if (quick)
    {
        std::printf("%s\n\n", quickNotice);
    }
}

// What --help says the benchmark compares satviz with; the last line tells which peers this build has.
std::string PeersHelp()
{
    std::string text =
        "Compared, on the same random pairs in this process:\n"
        "  Box2D (libbox2d-dev, up to 8 vertices): b2TestOverlap, b2CollidePolygons,\n"
        "    b2PolygonShape::RayCast, b2TimeOfImpact, b2TimeOfImpact + b2CollidePolygons at t\n"
        "  Chipmunk (libchipmunk-dev): cpShapesCollide (as a yes/no and with its contacts)\n"
        "  the textbook SAT loop (tests/bench/textbook_sat.h, up to 1024 vertices): Overlap, MTV, TOI\n"
        "  --world: Box2D's b2World (libbox2d-dev), and Box2D v3 when built with -DSATVIZ_BOX2D_V3_ROOT=PREFIX\n"
        "  satviz itself with some of its choices turned off (early exit, parallel skip, pruning, walk)\n"
        "Accuracy: against a __float128 reference (tests/support/reference.h).\n"
        "This build: ";
#ifdef SATVIZ_HAVE_BOX2D
    text += std::string("Box2D ") + SATVIZ_BOX2D_VERSION;
#else
    text += "no Box2D";
#endif
#ifdef SATVIZ_HAVE_CHIPMUNK
    text += std::string(", Chipmunk ") + cpVersionString;
#else
    text += ", no Chipmunk";
#endif
    text += bench::HaveBox2DV3() ? ", Box2D v3 " + bench::Box2DV3Version() : std::string(", no Box2D v3");
    return text + ".";
}

} // namespace

int main(int argc, char** argv)
{
    Settings s;
    bool quick = false;
    CLI::App app{"satviz-bench: ns per query and error against a quad-precision reference, beside Box2D, "
                 "Chipmunk and the textbook SAT loop."};
    app.set_version_flag("--version", std::string("satviz-bench ") + SATVIZ_VERSION);
    app.footer(PeersHelp());
    app.add_flag("--quick", quick, "Tiny pools and few rounds: checks that the benchmark runs, measures nothing");
    app.add_option("--pairs", s.pairs, "Pairs per slice (at least 1)");
    app.add_option("--rounds", s.rounds, "Rounds (the figure is their median; at least 1)");
    app.add_option("--seed", s.seed, "Random seed");
    app.add_option("--counts", s.counts, "Vertex counts (each at least 3)");
    app.add_option("--near-pairs", s.nearPairs, "Near-contact pairs: pairs per pool (each round draws a fresh one)");
    app.add_option("--near-rounds", s.nearRounds, "Near-contact pairs: rounds (the figure is their median)");
    app.add_option("--near-counts", s.nearCounts, "Near-contact pairs: vertex counts (each at least 3)");
    app.add_option("--near-placement", s.placement,
                   "Near-contact pairs: 'direction' (B along a random direction from A, the default) or 'face' (B "
                   "against A's outline along A's normal, as the main pool places them)");
    app.add_flag("--near-only", s.nearOnly, "Time only the near-contact pairs");
    std::string csv;
    app.add_option("--csv", csv,
                   "Also write timing.csv, accuracy.csv and accuracy_by_category.csv into this directory (for the "
                   "plots); created if missing, checked before the run");
    bool world = false;
    bench::WorldBenchSettings w;
    app.add_flag("--world", world,
                 "Time the rigid-body world instead of the queries: ms per step of a pile and a rain of mixed "
                 "shapes beside Box2D's b2World, with penetration and energy drift (--csv: world.csv)");
    app.add_option("--bodies", w.bodies, "--world: dynamic bodies per scene (each at least 1)");
    app.add_option("--steps", w.steps, "--world: steps per run (at least 4; the last quarter is the tail)");
    app.add_option("--scenes", w.scenes, "--world: the scenes to run: pile, rain (default: both)");
    app.add_option("--threads", w.threads,
                   "--world: threads satviz's world steps on, the caller's included (default 1; above 1 its figures "
                   "are by the wall clock)");
    app.add_flag("--soft-step", w.softStep,
                 "--world: satviz steps with the soft step (sub-steps of soft contacts, WorldSettings::softStep) in "
                 "place of its velocity and position passes");
    std::string scenesDirectory;
    app.add_option("--write-scenes", scenesDirectory,
                   "--world: write the scenes as scene files DIR/SCENE-N.json for satviz-sim (created if missing) "
                   "and run nothing")
        ->type_name("DIR");
    bool concave = false;
    app.add_flag("--concave", concave,
                 "Time the convex decomposition instead of the queries: ms and pieces per method from 10 to 10 000 "
                 "vertices, and the concave pair queries against the same pieces collided all against all")
        ->excludes("--world");
    CLI11_PARSE(app, argc, argv);
    if (concave)
    {
        bench::ConcaveBenchSettings c;
        c.seed = s.seed;
        if (app.count("--rounds") > 0)
        {
            c.rounds = s.rounds;
        }
        if (!ReadyToRun(bench::CheckConcaveBenchSettings(c), ""))
        {
            return 2;
        }
        if (quick)
        {
            c = bench::QuickConcaveBenchSettings(c);
        }
        PrintHeading(argc, argv, quick, kQuickNotice);
        bench::RunConcaveBench(c);
        return 0;
    }
    if (world)
    {
        w.seed = s.seed;
        w.csvDirectory = csv;
        if (app.count("--rounds") > 0)
        {
            w.rounds = s.rounds;
        }
        if (!ReadyToRun(bench::CheckWorldBenchSettings(w), csv))
        {
            return 2;
        }
        if (quick)
        {
            w = bench::QuickWorldBenchSettings(w);
        }
        if (!scenesDirectory.empty())
        {
            std::error_code code;
            std::filesystem::create_directories(scenesDirectory, code);
            if (code)
            {
                std::fprintf(stderr, "satviz-bench: --write-scenes %s: cannot create the directory (%s)\n",
                             scenesDirectory.c_str(), code.message().c_str());
                return 2;
            }
            std::string error;
            if (!bench::WriteWorldScenes(w, scenesDirectory, error))
            {
                std::fprintf(stderr, "satviz-bench: --write-scenes: %s\n", error.c_str());
                return 1;
            }
            return 0;
        }
        PrintHeading(argc, argv, quick,
                     "--quick: tiny scenes, few steps and one round: these figures only show that the benchmark "
                     "runs; they are not measurements");
        return bench::RunWorldBench(w) ? 0 : 1;
    }
    if (!ReadyToRun(CheckSettings(s), csv))
    {
        return 2;
    }
    if (quick)
    {
        s.pairs = 20;
        s.rounds = 1;
        s.reps = 1;
        s.accuracyPairs = 300;
        s.nearPairs = 300;
        s.nearRounds = 1;
    }

    PrintHeading(argc, argv, quick, kQuickNotice);
    Rng rng(s.seed);
    const std::vector<Query> queries = Queries();
    std::map<int, Timing> nearTimings;
    if (s.nearOnly)
    {
        Rng nearRng(s.seed + 1);
        for (int n : s.nearCounts)
        {
            nearTimings[n] = TimeNear(s, n, queries, nearRng);
        }
        PrintNear(s, nearTimings);
        if (!csv.empty() && !WriteNearCsv(csv, nearTimings))
        {
            std::fprintf(stderr, "satviz-bench: --csv %s: writing timing_near.csv failed\n", csv.c_str());
            return 1;
        }
        return 0;
    }
    std::map<int, Timing> timings;
    std::map<int, std::map<std::string, double>> ns;
    for (int n : s.counts)
    {
        timings[n] = Time(s, n, queries, rng);
        for (const auto& [name, passes] : timings[n].passes)
        {
            ns[n][name] = timings[n].Ns(name);
        }
    }

    std::printf("satviz-bench: ns per query, median of %d rounds x %d sweeps, a sweep being one pass of every query\n"
                "over one %d-pair slice; ratios: median over the sweeps of the ratio of two passes of the sweep\n",
                s.rounds, s.reps, s.pairs);
    std::printf("(mix of overlapping, touching within 1e-9 and separated pairs; both polygons have n vertices;\n"
                " sweeps: the pairs that start apart, B moving roughly towards A, sometimes missing)\n\n");
    std::printf("%-36s", "query");
    for (int n : s.counts)
    {
        std::printf(" %9s", ("n=" + std::to_string(n)).c_str());
    }
    std::printf("\n");
    for (const Query& q : queries)
    {
        std::printf("%-36s", q.name.c_str());
        for (int n : s.counts)
        {
            const auto it = ns[n].find(q.name);
            if (it == ns[n].end())
            {
                std::printf(" %9s", "-");
            }
            else
            {
                std::printf(" %9.1f", it->second);
            }
        }
        std::printf("\n");
    }

    auto ratioRow = [&](const char* label, const char* numerator, const char* denominator) {
        std::printf("%-44s", label);
        for (int n : s.counts)
        {
            if (!timings[n].Has(numerator) || !timings[n].Has(denominator))
            {
                std::printf(" %7s", "-");
            }
            else
            {
                std::printf(" %7.2f", timings[n].Ratio(numerator, denominator));
            }
        }
        std::printf("\n");
    };
    std::printf("\nratios measured in this run (<1: faster)     ");
    for (int n : s.counts)
    {
        std::printf(" %7s", ("n=" + std::to_string(n)).c_str());
    }
    std::printf("\n");
    ratioRow("Overlap traced / Overlap", "satviz Overlap traced", "satviz Overlap");
    ratioRow("Collide traced / Collide", "satviz Collide traced", "satviz Collide");
    ratioRow("Sweep traced / Sweep", "satviz Sweep traced", "satviz Sweep");
    ratioRow("Overlap float / Overlap double", "satviz Overlap float", "satviz Overlap");
    ratioRow("Collide float / Collide double", "satviz Collide float", "satviz Collide");
    ratioRow("Sweep float / Sweep double", "satviz Sweep float", "satviz Sweep");
    ratioRow("RayCast float / RayCast double", "satviz RayCast float", "satviz RayCast");
    ratioRow("Collide, random order / same order", "satviz Collide, random order", "satviz Collide");
    ratioRow("Overlap / Collide", "satviz Overlap", "satviz Collide");
    ratioRow("satviz Overlap / textbook Overlap", "satviz Overlap", "textbook Overlap");
    // The variants are instantiated in this file: they compare with the default compiled here too.
    ratioRow("Overlap without early exit / Overlap", "satviz Overlap, no early exit",
             "satviz Overlap, as compiled here");
    ratioRow("Overlap without parallel skip / Overlap", "satviz Overlap, no parallel skip",
             "satviz Overlap, as compiled here");
    ratioRow("Overlap walking, not scanning / Overlap", "satviz Overlap, walk only",
             "satviz Overlap, as compiled here");
    ratioRow("Overlap walking every face / pruned walk", "satviz Overlap, walked unpruned",
             "satviz Overlap, as compiled here");
    ratioRow("Collide without early exit / Collide", "satviz Collide, no early exit",
             "satviz Collide, as compiled here");
    ratioRow("Collide without parallel skip / Collide", "satviz Collide, no parallel skip",
             "satviz Collide, as compiled here");
    ratioRow("Collide walking, not scanning / Collide", "satviz Collide, walk only",
             "satviz Collide, as compiled here");
    ratioRow("moving pairs: cached axis / no cache", "satviz Overlap, moving, cached axis", "satviz Overlap, moving");
    ratioRow("satviz Collide / textbook MTV", "satviz Collide", "textbook MTV");
    ratioRow("satviz Sweep / textbook TOI", "satviz Sweep", "textbook TOI");
#ifdef SATVIZ_HAVE_BOX2D
    ratioRow("satviz Overlap / box2d b2TestOverlap", "satviz Overlap", "box2d b2TestOverlap");
    ratioRow("satviz Collide / box2d b2CollidePolygons", "satviz Collide", "box2d b2CollidePolygons");
    ratioRow("the same, pairs in random order: Overlap", "satviz Overlap, random order",
             "box2d b2TestOverlap, random order");
    ratioRow("the same, pairs in random order: Collide", "satviz Collide, random order",
             "box2d b2CollidePolygons, random order");
    ratioRow("satviz Sweep / box2d b2TimeOfImpact", "satviz Sweep", "box2d b2TimeOfImpact");
    ratioRow("satviz SweepTime / box2d b2TimeOfImpact", "satviz SweepTime", "box2d b2TimeOfImpact");
    ratioRow("satviz Sweep / box2d TOI + collide at t", "satviz Sweep",
             "box2d b2TimeOfImpact + b2CollidePolygons at t");
    ratioRow("satviz RayCast / box2d RayCast", "satviz RayCast", "box2d b2PolygonShape::RayCast");
#endif
#ifdef SATVIZ_HAVE_CHIPMUNK
    ratioRow("satviz Overlap / chipmunk count>0", "satviz Overlap", "chipmunk cpShapesCollide count>0");
    ratioRow("satviz Collide / chipmunk cpShapesCollide", "satviz Collide", "chipmunk cpShapesCollide");
#endif

    // The near-contact pools draw from their own generator, so that the accuracy pools below are the same with or
    // without them.
    Rng nearRng(s.seed + 1);
    for (int n : s.nearCounts)
    {
        nearTimings[n] = TimeNear(s, n, queries, nearRng);
    }
    PrintNear(s, nearTimings);

    std::printf("\nscaling with the vertex count (time / time at n=8)\n");
    for (const char* name : {"satviz Overlap", "satviz Collide", "satviz Sweep", "satviz SweepTime", "satviz RayCast"})
    {
        std::printf("%-36s", name);
        for (int n : s.counts)
        {
            const bool have = ns[n].count(name) && ns[8].count(name);
            std::printf(" %9s", have ? std::to_string(ns[n][name] / ns[8][name]).substr(0, 6).c_str() : "-");
        }
        std::printf("\n");
    }

    const std::map<std::string, Accuracy> acc = MeasureAccuracy(s, s.counts, rng);
    std::printf("\naccuracy against the __float128 reference (all vertex counts; box2d: n <= 8)\n");
    std::printf("(errors: |depth error| for the static queries, |t error| for the sweeps, on pairs both call a hit;\n"
                " box2d b2TimeOfImpact stops 0.005 short of contact by design, so its t is early)\n");
    std::printf("%-36s %7s %14s %12s %12s\n", "query", "pairs", "wrong (fp,fn)", "error med", "error max");
    for (const auto& [name, a] : acc)
    {
        std::string wrong = std::to_string(a.wrong) + " (" + std::to_string(a.falsePositives) + "," +
                            std::to_string(a.falseNegatives) + ")";
        if (a.depthErrors.empty())
        {
            std::printf("%-36s %7d %14s %12s %12s\n", name.c_str(), a.pairs, wrong.c_str(), "-", "-");
        }
        else
        {
            std::printf("%-36s %7d %14s %12.1e %12.1e\n", name.c_str(), a.pairs, wrong.c_str(), Median(a.depthErrors),
                        *std::max_element(a.depthErrors.begin(), a.depthErrors.end()));
        }
    }

    std::printf("\nsweeps: signed t error (t - reference t) on pairs both call a hit, and failure states\n");
    std::printf("%-36s %7s %12s %12s %9s\n", "query", "hits", "signed med", "signed min", "failures");
    for (const auto& [name, a] : acc)
    {
        if (a.sweep && !a.signedErrors.empty())
        {
            std::printf("%-36s %7zu %12.1e %12.1e %9d\n", name.c_str(), a.signedErrors.size(), Median(a.signedErrors),
                        *std::min_element(a.signedErrors.begin(), a.signedErrors.end()), a.failures);
        }
    }

    const std::vector<std::map<std::string, Accuracy>> byCategory = MeasureByCategory(s, rng);
    std::printf("\naccuracy per category (n = 3, 4, 8, 16; box2d: n <= 8; sweeps: pairs that start apart)\n");
    std::printf(
        "(wrong: all wrong yes/no answers, and those farther than %g from touching; error: |depth error|,\n"
        " |t error| or, for ray casts, the distance along the segment; rel. max: the largest error over the pair's\n"
        " scale, max(1, |position|), for sweeps and ray casts the backward error (the error along the contact\n"
        " normal); angle: of the normal to the reference normal, radians, on pairs both call overlapping or a hit)\n",
        kBand);
    for (size_t c = 0; c < byCategory.size(); ++c)
    {
        std::printf("\n%s\n", kCategories[c]);
        std::printf("%-36s %6s %7s %8s %10s %10s %10s %10s %10s\n", "query", "pairs", "wrong", "outside", "error med",
                    "error max", "rel. max", "angle med", "angle max");
        for (const auto& [name, a] : byCategory[c])
        {
            // A figure of a list of errors, or "-" for none.
            const auto figure = [](const std::vector<double>& v, bool largest) {
                if (v.empty())
                {
                    return std::string("-");
                }
                char text[32];
                std::snprintf(text, sizeof text, "%.1e", largest ? *std::max_element(v.begin(), v.end()) : Median(v));
                return std::string(text);
            };
            std::printf("%-36s %6d %7d %8d %10s %10s %10s %10s %10s\n", name.c_str(), a.pairs, a.wrong,
                        a.wrongOutsideBand, figure(a.depthErrors, false).c_str(), figure(a.depthErrors, true).c_str(),
                        figure(a.relativeErrors, true).c_str(), figure(a.angleErrors, false).c_str(),
                        figure(a.angleErrors, true).c_str());
        }
    }

    bool csvFailed = false;
    if (!csv.empty())
    {
        std::ofstream byCategoryCsv(std::filesystem::path(csv) / "accuracy_by_category.csv");
        byCategoryCsv << "category,query,pairs,wrong,wrong_outside_band,error_median,error_max,relative_max,"
                         "angle_median,angle_max\n";
        for (size_t c = 0; c < byCategory.size(); ++c)
        {
            for (const auto& [name, a] : byCategory[c])
            {
                byCategoryCsv << CsvName(kCategories[c]) << ',' << CsvName(name) << ',' << a.pairs << ',' << a.wrong
                              << ',' << a.wrongOutsideBand << ',';
                CsvFigures(byCategoryCsv, a.depthErrors);
                byCategoryCsv << ',';
                if (!a.relativeErrors.empty())
                {
                    byCategoryCsv << *std::max_element(a.relativeErrors.begin(), a.relativeErrors.end());
                }
                byCategoryCsv << ',';
                CsvFigures(byCategoryCsv, a.angleErrors);
                byCategoryCsv << '\n';
            }
        }
        std::ofstream timing(std::filesystem::path(csv) / "timing.csv");
        timing << "query,n,ns\n";
        for (const auto& [n, row] : ns)
        {
            for (const auto& [name, value] : row)
            {
                timing << CsvName(name) << ',' << n << ',' << value << '\n';
            }
        }
        std::ofstream accuracy(std::filesystem::path(csv) / "accuracy.csv");
        accuracy << "query,pairs,wrong,false_positives,false_negatives,error_median,error_max,ns_n8,"
                    "wrong_outside_band,angle_median,angle_max\n";
        for (const auto& [name, a] : acc)
        {
            accuracy << CsvName(name) << ',' << a.pairs << ',' << a.wrong << ',' << a.falsePositives << ','
                     << a.falseNegatives << ',';
            CsvFigures(accuracy, a.depthErrors);
            accuracy << ',' << (ns.count(8) && ns[8].count(name) ? ns[8][name] : 0.0) << ',' << a.wrongOutsideBand
                     << ',';
            CsvFigures(accuracy, a.angleErrors);
            accuracy << '\n';
        }
        byCategoryCsv.close();
        timing.close();
        accuracy.close();
        const bool nearWritten = WriteNearCsv(csv, nearTimings);
        if (byCategoryCsv && timing && accuracy && nearWritten)
        {
            std::fprintf(stderr, "satviz-bench: CSV files written to %s\n", csv.c_str());
        }
        else
        {
            std::fprintf(stderr, "satviz-bench: --csv %s: writing the CSV files failed\n", csv.c_str());
            csvFailed = true;
        }
    }

#ifdef SATVIZ_HAVE_CHIPMUNK
    std::printf("\nchipmunk: %ld warnings (\"High EPA iterations\") counted instead of printed\n", g_chipmunkWarnings);
#endif
    std::printf("\ntargets (8-gons unless said)\n");
    if (quick)
    {
        std::printf("  %s\n", kQuickNotice);
    }
    auto target = [&](const char* label, double value, double limit) {
        std::printf("  %-52s %10.3g  (target <= %g)  %s\n", label, value, limit, value <= limit ? "met" : "MISSED");
    };
#ifdef SATVIZ_HAVE_BOX2D
    if (ns.count(8) && ns[8].count("box2d b2TestOverlap"))
    {
        const Timing& t = timings[8];
        target("satviz Overlap / box2d b2TestOverlap", t.Ratio("satviz Overlap", "box2d b2TestOverlap"), 0.25);
        target("satviz Collide / box2d b2CollidePolygons", t.Ratio("satviz Collide", "box2d b2CollidePolygons"), 0.6);
        // b2TimeOfImpact returns the time alone; satviz Sweep the time, the normal and the contact points. The
        // first line compares them as they are; the next two like for like: the time alone on both sides, then
        // the contact points on both sides (Box2D colliding at the time of impact, as its world does).
        target("satviz Sweep (contacts) / box2d b2TimeOfImpact (time)", t.Ratio("satviz Sweep", "box2d b2TimeOfImpact"),
               0.25);
        target("satviz SweepTime / box2d b2TimeOfImpact (both: time)",
               t.Ratio("satviz SweepTime", "box2d b2TimeOfImpact"), 0.25);
        target("satviz Sweep / box2d TOI + collide at t (both: contacts)",
               t.Ratio("satviz Sweep", "box2d b2TimeOfImpact + b2CollidePolygons at t"), 0.25);
    }
#else
    std::printf("  (built without Box2D: no peer ratios)\n");
#endif
    for (const char* name : {"satviz Overlap", "satviz Collide", "satviz Sweep", "satviz SweepTime", "satviz RayCast"})
    {
        if (ns.count(8) && ns.count(1024) && ns[8].count(name) && ns[1024].count(name))
        {
            target((std::string(name) + " at 1024 vertices / at 8").c_str(), ns[1024][name] / ns[8][name], 100.0);
        }
    }
    if (acc.count("satviz Collide") && !acc.at("satviz Collide").depthErrors.empty())
    {
        const auto& e = acc.at("satviz Collide").depthErrors;
        target("satviz Collide depth error, max (double)", *std::max_element(e.begin(), e.end()), 1e-14);
    }
    if (acc.count("satviz Sweep") && !acc.at("satviz Sweep").depthErrors.empty())
    {
        const auto& e = acc.at("satviz Sweep").depthErrors;
        target("satviz Sweep |t error|, max (double)", *std::max_element(e.begin(), e.end()), 1e-12);
    }
    // Every category, far from the origin included.
    int wrongOutside = 0;
    for (const auto& category : byCategory)
    {
        for (const char* name : {"satviz Overlap", "satviz Collide", "satviz Sweep", "satviz RayCast"})
        {
            wrongOutside += category.count(name) ? category.at(name).wrongOutsideBand : 0;
        }
    }
    // The largest relative error of a query over every category. Shapes are of size 0.5 to 1.5 (slivers thinner),
    // so near the origin the error is relative to a size of 1; far from it, to the magnitude of the positions.
    const auto worstRelative = [&](const char* name) {
        double worst = 0.0;
        for (const auto& category : byCategory)
        {
            if (category.count(name) && !category.at(name).relativeErrors.empty())
            {
                const auto& e = category.at(name).relativeErrors;
                worst = std::max(worst, *std::max_element(e.begin(), e.end()));
            }
        }
        return worst;
    };
    target("wrong yes/no outside the band (double, every category)", wrongOutside, 0);
    target("satviz Collide depth error, relative, every category (double)", worstRelative("satviz Collide"), 1e-14);
    target("satviz Collide depth error, relative, every category (float)", worstRelative("satviz Collide float"), 1e-5);
    // Sweeps and casts: the backward error (along the contact normal), relative as above.
    target("satviz Sweep error, relative, every category (float)", worstRelative("satviz Sweep float"), 1e-5);
    target("satviz RayCast error, relative, every category (float)", worstRelative("satviz RayCast float"), 1e-5);
    std::printf("  (double, the same measure: Sweep %.3g, RayCast %.3g)\n", worstRelative("satviz Sweep"),
                worstRelative("satviz RayCast"));
    return csvFailed ? 1 : 0;
}
