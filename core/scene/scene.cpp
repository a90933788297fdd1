// SPDX-License-Identifier: MIT
// satviz: scene files. Every error names the file, the JSON path of the offending value and what is wrong.

#include <satviz/layers.h>
#include <satviz/scene.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <unistd.h>

namespace satviz
{

struct SceneSource
{
    nlohmann::ordered_json root; // the parsed file
    std::string file;            // the name it was parsed under, for a relative "$schema"
};

namespace
{

// Ordered, so that the parsed file keeps its key order for SceneToJson (and errors name the first bad key in file
// order).
using Json = nlohmann::ordered_json;

// Thrown inside the parser only; ParseScene turns it into the error string.
struct SceneFault
{
    std::string path;
    std::string message;
};

// Error messages are one line: control characters that came from the input (a key with a newline in it) are
// written as escapes.
std::string OneLine(const std::string& text)
{
    std::string out;
    for (const char c : text)
    {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n')
        {
            out += "\\n";
        }
        else if (c == '\t')
        {
            out += "\\t";
        }
        else if (u < 0x20 || u == 0x7f)
        {
            static const char* const kHex = "0123456789abcdef";
            out += "\\x";
            out += kHex[u >> 4];
            out += kHex[u & 15];
        }
        else
        {
            out += c;
        }
    }
    return out;
}

[[noreturn]] void Fail(const std::string& path, const std::string& message)
{
    throw SceneFault{path, message};
}

std::string TypeName(const Json& value)
{
    switch (value.type())
    {
    case Json::value_t::null:
        return "null";
    case Json::value_t::object:
        return "an object";
    case Json::value_t::array:
        return "an array";
    case Json::value_t::string:
        return "a string";
    case Json::value_t::boolean:
        return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
        return "a number";
    default:
        return "an unsupported value";
    }
}

size_t EditDistance(const std::string& a, const std::string& b)
{
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
    {
        row[j] = j;
    }
    for (size_t i = 1; i <= a.size(); ++i)
    {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
        {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// Rejects keys that are neither known nor namespaced ("tool:field"), suggesting the closest known key.
void CheckKeys(const Json& object, const std::string& path, const std::vector<std::string>& known)
{
    for (const auto& item : object.items())
    {
        const std::string& key = item.key();
        if (key.find(':') != std::string::npos || std::find(known.begin(), known.end(), key) != known.end())
        {
            continue;
        }
        std::string hint;
        size_t best = 3;
        for (const std::string& candidate : known)
        {
            const size_t distance = EditDistance(key, candidate);
            if (distance < best)
            {
                best = distance;
                hint = candidate;
            }
        }
        std::string message = "unknown field \"" + key + "\"";
        if (!hint.empty())
        {
            message += " (did you mean \"" + hint + "\"?)";
        }
        else
        {
            std::string list;
            for (const std::string& candidate : known)
            {
                list += (list.empty() ? "" : ", ") + candidate;
            }
            message += " (known fields: " + list + "; namespace your own as \"tool:field\")";
        }
        Fail(path.empty() ? key : path + "." + key, message);
    }
}

double Number(const Json& value, const std::string& path, double limit = kMaxSceneValue)
{
    if (!value.is_number())
    {
        Fail(path, "expected a number, got " + TypeName(value));
    }
    const double number = value.get<double>();
    if (!std::isfinite(number))
    {
        Fail(path, "is not a finite number");
    }
    if (std::abs(number) > limit)
    {
        std::ostringstream text;
        text << "magnitude exceeds " << limit;
        Fail(path, text.str());
    }
    return number;
}

Vec2 Point(const Json& value, const std::string& path)
{
    if (!value.is_array() || value.size() != 2)
    {
        Fail(path, "expected a pair of numbers [x, y], got " +
                       (value.is_array() ? "an array of " + std::to_string(value.size()) : TypeName(value)));
    }
    return {Number(value[0], path + "[0]"), Number(value[1], path + "[1]")};
}

double PositiveNumber(const Json& value, const std::string& path, double limit = kMaxSceneValue)
{
    const double number = Number(value, path, limit);
    if (number <= 0.0)
    {
        Fail(path, "must be greater than 0");
    }
    return number;
}

double NonNegativeNumber(const Json& value, const std::string& path)
{
    const double number = Number(value, path);
    if (number < 0.0)
    {
        Fail(path, "must be 0 or greater");
    }
    return number;
}

// The name of a body without one: A, B, ... Z by its place in the file, then body26, body27, ...
std::string DefaultBodyName(size_t index)
{
    return index < 26 ? std::string(1, static_cast<char>('A' + index)) : "body" + std::to_string(index);
}

Shape PolygonShape(const PolygonResult& result, const std::string& path)
{
    if (!result.Ok())
    {
        Fail(path, DescribePolygonError(result.error, result.vertex));
    }
    return MakeShape(result.polygon);
}

// A polygon that MakePolygon refuses for its shape (not convex, crossing itself, clockwise, or a vertex repeated or
// on a line with its neighbours), read as a concave outline: decomposed, or refused naming the edges that cross.
// A vertex repeated or on the line through its neighbours is a corner of no piece (a piece's corners turn), but
// the outline keeps it as written: a floor written with the ends of its tiles along its top loads, even when it is
// one convex piece. Any other outline that is one convex piece keeps MakePolygon's error (a clockwise triangle is
// written counter-clockwise).
bool ReadConcave(Body& body, const std::vector<Vec2>& vertices, const PolygonResult& made, const std::string& path)
{
    switch (made.error)
    {
    case PolygonError::NotConvex:
    case PolygonError::SelfIntersecting:
    case PolygonError::Clockwise:
    case PolygonError::DuplicateVertex:
    case PolygonError::CollinearVertex:
        break;
    default:
        return false;
    }
    const Decomposition pieces = Decompose(vertices, body.decompose);
    if (!pieces.Ok())
    {
        Fail(path, DescribeDecomposeError(pieces, vertices));
    }
    const bool straight = made.error == PolygonError::CollinearVertex || made.error == PolygonError::DuplicateVertex;
    if (pieces.pieces.size() < 2 && !straight)
    {
        return false;
    }
    body.concave = MakeConcave(pieces.pieces);
    body.outline = vertices;
    body.shape = MakeShape(ComputeHull(vertices).polygon);
    return true;
}

Body ParseBody(const Json& value, const std::string& path, size_t index, const SceneOptions& options)
{
    if (!value.is_object())
    {
        Fail(path, "expected a body object, got " + TypeName(value));
    }
    CheckKeys(value, path,
              {"name", "polygon", "box", "regular", "circle", "position", "angle", "velocity", "angular_velocity",
               "static", "density", "restitution", "friction", "static_friction", "decompose"});

    Body body;
    if (value.contains("decompose"))
    {
        const Json& method = value["decompose"];
        if (!value.contains("polygon"))
        {
            Fail(path + ".decompose", "applies to a \"polygon\" only");
        }
        if (!method.is_string() || (method.get<std::string>() != "fast" && method.get<std::string>() != "fewest"))
        {
            Fail(path + ".decompose",
                 "expected \"fast\" or \"fewest\", got " +
                     (method.is_string() ? "\"" + method.get<std::string>() + "\"" : TypeName(method)));
        }
        body.decompose = method.get<std::string>() == "fast" ? DecomposeMethod::Fast : DecomposeMethod::Fewest;
    }
    if (value.contains("name"))
    {
        if (!value["name"].is_string() || value["name"].get<std::string>().empty())
        {
            Fail(path + ".name", "expected a non-empty string");
        }
        body.name = value["name"].get<std::string>();
    }
    else
    {
        body.name = DefaultBodyName(index);
    }

    int shapes = 0;
    for (const char* key : {"polygon", "box", "regular", "circle"})
    {
        shapes += value.contains(key) ? 1 : 0;
    }
    if (shapes != 1)
    {
        Fail(path, shapes == 0 ? "has no shape (give one of \"polygon\", \"box\", \"regular\", \"circle\")"
                               : "has more than one shape (give exactly one of \"polygon\", \"box\", \"regular\", "
                                 "\"circle\")");
    }
    if (value.contains("polygon"))
    {
        const std::string p = path + ".polygon";
        const Json& points = value["polygon"];
        if (!points.is_array())
        {
            Fail(p, "expected an array of [x, y] vertices, got " + TypeName(points));
        }
        std::vector<Vec2> vertices;
        for (size_t i = 0; i < points.size(); ++i)
        {
            vertices.push_back(Point(points[i], p + "[" + std::to_string(i) + "]"));
        }
        const PolygonResult made = MakePolygon(vertices);
        if (made.Ok() || !options.concave || !ReadConcave(body, vertices, made, p))
        {
            body.shape = PolygonShape(made, p);
        }
    }
    else if (value.contains("box"))
    {
        const std::string p = path + ".box";
        const Vec2 size = Point(value["box"], p);
        if (size.x <= 0.0 || size.y <= 0.0)
        {
            Fail(p, "width and height must be greater than 0");
        }
        body.shape = PolygonShape(MakeBox(0.5 * size.x, 0.5 * size.y), p);
    }
    else if (value.contains("regular"))
    {
        const std::string p = path + ".regular";
        const Json& regular = value["regular"];
        if (!regular.is_object())
        {
            Fail(p, "expected {\"sides\": n, \"radius\": r}, got " + TypeName(regular));
        }
        CheckKeys(regular, p, {"sides", "radius", "phase"});
        if (!regular.contains("sides") || !regular["sides"].is_number_integer() || regular["sides"].get<long>() < 3 ||
            regular["sides"].get<long>() > 1000000)
        {
            Fail(p + ".sides", "expected a whole number of sides from 3 to 1000000");
        }
        if (!regular.contains("radius"))
        {
            Fail(p + ".radius", "is missing");
        }
        const double radius = PositiveNumber(regular["radius"], p + ".radius");
        const double phase = regular.contains("phase") ? Number(regular["phase"], p + ".phase", 1e6) : 0.0;
        body.shape = PolygonShape(MakeRegularPolygon(regular["sides"].get<int>(), radius, phase), p);
    }
    else
    {
        const std::string p = path + ".circle";
        const Json& circle = value["circle"];
        if (!circle.is_object())
        {
            Fail(p, "expected {\"radius\": r}, got " + TypeName(circle));
        }
        CheckKeys(circle, p, {"radius", "center"});
        if (!circle.contains("radius"))
        {
            Fail(p + ".radius", "is missing");
        }
        Circle shape;
        shape.radius = PositiveNumber(circle["radius"], p + ".radius");
        if (circle.contains("center"))
        {
            shape.center = Point(circle["center"], p + ".center");
        }
        body.shape = MakeShape(shape);
    }

    if (value.contains("position"))
    {
        body.position = Point(value["position"], path + ".position");
    }
    if (value.contains("angle"))
    {
        body.angle = Number(value["angle"], path + ".angle", 1e6);
    }
    if (value.contains("velocity"))
    {
        body.velocity = Point(value["velocity"], path + ".velocity");
    }
    if (value.contains("angular_velocity"))
    {
        body.angularVelocity = Number(value["angular_velocity"], path + ".angular_velocity");
    }
    if (value.contains("static"))
    {
        const Json& fixed = value["static"];
        if (!fixed.is_boolean())
        {
            Fail(path + ".static", "expected true or false, got " + TypeName(fixed));
        }
        body.isStatic = fixed.get<bool>();
    }
    if (value.contains("density"))
    {
        // A static body has no mass, but a density it gives must still be one a dynamic body could have.
        body.density = PositiveNumber(value["density"], path + ".density");
    }
    if (value.contains("restitution"))
    {
        const std::string p = path + ".restitution";
        body.material.restitution = Number(value["restitution"], p);
        if (body.material.restitution < 0.0 || body.material.restitution > 1.0)
        {
            Fail(p, "expected a restitution in [0, 1] (0: no bounce, 1: a perfectly elastic one)");
        }
    }
    if (value.contains("friction"))
    {
        body.material.friction = NonNegativeNumber(value["friction"], path + ".friction");
    }
    // Static friction defaults to the body's friction: a file that gives one coefficient gets Coulomb's plain law.
    body.material.staticFriction = value.contains("static_friction")
                                       ? NonNegativeNumber(value["static_friction"], path + ".static_friction")
                                       : body.material.friction;
    return body;
}

std::string String(const Json& value, const std::string& path)
{
    if (!value.is_string())
    {
        Fail(path, "expected a string, got " + TypeName(value));
    }
    return value.get<std::string>();
}

int WholeNumber(const Json& value, const std::string& path, int low, int high)
{
    const double number = Number(value, path);
    if (number != std::floor(number) || number < low || number > high)
    {
        Fail(path, "expected a whole number from " + std::to_string(low) + " to " + std::to_string(high));
    }
    return static_cast<int>(number);
}

std::string BodyName(const Json& value, const std::string& path, const Scene& scene)
{
    std::string name = String(value, path);
    for (const Body& body : scene.bodies)
    {
        if (body.name == name)
        {
            return name;
        }
    }
    Fail(path, "no body is named \"" + name + "\"");
}

SceneView ParseView(const Json& value, const Scene& scene)
{
    const std::string path = "view";
    if (!value.is_object())
    {
        Fail(path, "expected an object, got " + TypeName(value));
    }
    CheckKeys(value, path,
              {"center", "zoom", "size", "layers", "pair", "query", "steps", "pitfall", "step", "time", "caption",
               "precision", "sim_steps", "figure", "cut"});
    SceneView view;
    if (value.contains("zoom"))
    {
        const Json& zoom = value["zoom"];
        if (zoom.is_string() && zoom.get<std::string>() == "fit")
        {
            view.fit = true;
        }
        else
        {
            view.zoom = PositiveNumber(zoom, path + ".zoom", std::numeric_limits<double>::max());
            if (view.zoom < kMinViewZoom || view.zoom > kMaxViewZoom)
            {
                Fail(path + ".zoom", "expected pixels per world unit from 1e-9 to 1e12, or \"fit\"");
            }
            view.fit = false;
        }
    }
    if (value.contains("center"))
    {
        view.center = Point(value["center"], path + ".center");
        if (!value.contains("zoom"))
        {
            Fail(path + ".center", "needs a \"zoom\" (pixels per unit) beside it");
        }
    }
    if (value.contains("size"))
    {
        const Json& size = value["size"];
        if (!size.is_array() || size.size() != 2)
        {
            Fail(path + ".size", "expected [width, height] in pixels, got " + TypeName(size));
        }
        view.width = WholeNumber(size[0], path + ".size[0]", 16, kMaxViewSize);
        view.height = WholeNumber(size[1], path + ".size[1]", 16, kMaxViewSize);
    }
    if (value.contains("layers"))
    {
        const Json& layers = value["layers"];
        if (!layers.is_array())
        {
            Fail(path + ".layers", "expected an array of layer names, got " + TypeName(layers));
        }
        for (size_t i = 0; i < layers.size(); ++i)
        {
            const std::string p = path + ".layers[" + std::to_string(i) + "]";
            std::string name = String(layers[i], p);
            if (FindLayer(name) == nullptr)
            {
                std::string list;
                for (const LayerInfo& known : kLayerTable)
                {
                    list += (list.empty() ? "" : ", ") + std::string(known.name);
                }
                Fail(p, "unknown layer \"" + name + "\" (known layers: " + list + ")");
            }
            view.layers.push_back(std::move(name));
        }
    }
    if (value.contains("pair"))
    {
        const Json& pair = value["pair"];
        if (!pair.is_array() || pair.size() != 2)
        {
            Fail(path + ".pair", "expected two body names [\"A\", \"B\"], got " + TypeName(pair));
        }
        view.bodyA = BodyName(pair[0], path + ".pair[0]", scene);
        view.bodyB = BodyName(pair[1], path + ".pair[1]", scene);
        if (view.bodyA == view.bodyB)
        {
            Fail(path + ".pair", "names the same body twice");
        }
    }
    if (value.contains("query"))
    {
        const std::string query = String(value["query"], path + ".query");
        if (query == "collide")
        {
            view.query = ViewQuery::Collide;
        }
        else if (query == "sweep")
        {
            view.query = ViewQuery::Sweep;
        }
        else if (query != "auto")
        {
            Fail(path + ".query", "expected \"collide\", \"sweep\" or \"auto\", got \"" + query + "\"");
        }
    }
    if (value.contains("pitfall"))
    {
        const std::string name = String(value["pitfall"], path + ".pitfall");
        if (!PitfallFromName(name, view.pitfall))
        {
            Fail(path + ".pitfall", "expected \"none\", \"unnormalised-axes\", \"unchecked-direction\", "
                                    "\"one-shapes-axes\", \"sampled-motion\" or \"float-world\", got \"" +
                                        name + "\"");
        }
    }
    if (value.contains("steps"))
    {
        const std::string steps = String(value["steps"], path + ".steps");
        if (steps != "textbook" && steps != "faces")
        {
            Fail(path + ".steps", "expected \"textbook\" or \"faces\", got \"" + steps + "\"");
        }
        view.steps = steps == "faces" ? StepView::Faces : StepView::Textbook;
    }
    if (value.contains("step"))
    {
        const Json& step = value["step"];
        if (!(step.is_string() && step.get<std::string>() == "last"))
        {
            view.step = std::max(0, WholeNumber(step, path + ".step", 0, 1000000) - 1);
        }
    }
    if (value.contains("time"))
    {
        view.time = Number(value["time"], path + ".time");
        if (view.time < 0.0 || view.time > 1.0)
        {
            Fail(path + ".time", "expected a time in [0, 1] (a fraction of the step)");
        }
    }
    if (value.contains("caption"))
    {
        view.caption = String(value["caption"], path + ".caption");
    }
    if (value.contains("precision"))
    {
        const std::string precision = String(value["precision"], path + ".precision");
        if (precision != "double" && precision != "float")
        {
            Fail(path + ".precision", "expected \"double\" or \"float\", got \"" + precision + "\"");
        }
        view.singlePrecision = precision == "float";
    }
    if (value.contains("sim_steps"))
    {
        view.simSteps = WholeNumber(value["sim_steps"], path + ".sim_steps", 0, kMaxViewSimSteps);
    }
    if (value.contains("figure"))
    {
        const std::string name = String(value["figure"], path + ".figure");
        if (!FigureKindFromName(name, view.figure))
        {
            Fail(path + ".figure", "expected " + FigureKindList() + ", got \"" + name + "\"");
        }
        // A figure of one body draws the pair's first: checked here, so that a scene the figure cannot draw fails
        // on load.
        const Body* body = nullptr;
        for (const Body& b : scene.bodies)
        {
            if (view.bodyA.empty() || b.name == view.bodyA)
            {
                body = &b;
                break;
            }
        }
        const std::string kind = view.figure == FigureKind::Decomposition ? "a decomposition" : "a slice";
        if ((view.figure == FigureKind::Decomposition || view.figure == FigureKind::Slice) && body == nullptr)
        {
            Fail(path + ".figure", kind + " figure cuts the pair's first body: the scene has no body");
        }
        if ((view.figure == FigureKind::Decomposition || view.figure == FigureKind::Slice) &&
            body->shape.type != ShapeType::Polygon)
        {
            Fail(path + ".figure", kind + " figure cuts the pair's first body, \"" + body->name +
                                       "\", which is a circle, not a polygon");
        }
        if (view.figure == FigureKind::DiscCast)
        {
            // The disc is the pair's second body, cast against the first.
            const Body* disc = nullptr;
            for (size_t i = 0; i < scene.bodies.size(); ++i)
            {
                const Body& b = scene.bodies[i];
                if (view.bodyB.empty() ? (i == 1) : b.name == view.bodyB)
                {
                    disc = &b;
                }
            }
            if (disc == nullptr)
            {
                Fail(path + ".figure", "a disc-cast figure casts the pair's second body against its first: the scene "
                                       "has " + std::to_string(scene.bodies.size()) +
                                           (scene.bodies.size() == 1 ? " body" : " bodies"));
            }
            if (disc->shape.type != ShapeType::Circle)
            {
                Fail(path + ".figure", "a disc-cast figure casts the pair's second body, \"" + disc->name +
                                           "\", which is a polygon, not a circle");
            }
            if (disc->velocity == Vec2{})
            {
                Fail(path + ".figure", "a disc-cast figure casts the pair's second body, \"" + disc->name +
                                           "\", along its velocity, which is zero");
            }
        }
        if (view.figure == FigureKind::Pieces)
        {
            // The pair: view.pair's bodies, else the first two.
            const Body* first = nullptr;
            const Body* second = nullptr;
            for (size_t i = 0; i < scene.bodies.size(); ++i)
            {
                const Body& b = scene.bodies[i];
                first = (view.bodyA.empty() ? i == 0 : b.name == view.bodyA) ? &b : first;
                second = (view.bodyB.empty() ? i == 1 : b.name == view.bodyB) ? &b : second;
            }
            if (first == nullptr || second == nullptr)
            {
                Fail(path + ".figure", "a pieces figure tests a pair: the scene has " +
                                           std::to_string(scene.bodies.size()) +
                                           (scene.bodies.size() == 1 ? " body" : " bodies"));
            }
            if (!first->IsConcave() && !second->IsConcave())
            {
                Fail(path + ".figure", "a pieces figure tests a pair with a concave body piece by piece: neither \"" +
                                           first->name + "\" nor \"" + second->name + "\" is concave");
            }
        }
        if (view.figure == FigureKind::Slice && !value.contains("cut"))
        {
            Fail(path + ".figure", "a slice figure needs a \"cut\": [[x, y], [x, y]], the segment to cut along");
        }
    }
    if (value.contains("cut"))
    {
        const Json& cut = value["cut"];
        if (view.figure != FigureKind::Slice)
        {
            Fail(path + ".cut", "only a slice figure (\"figure\": \"slice\") cuts along a segment");
        }
        if (!cut.is_array() || cut.size() != 2)
        {
            Fail(path + ".cut", "expected two points [[x, y], [x, y]], got " + TypeName(cut));
        }
        view.cut[0] = Point(cut[0], path + ".cut[0]");
        view.cut[1] = Point(cut[1], path + ".cut[1]");
        if (view.cut[0] == view.cut[1])
        {
            Fail(path + ".cut", "the segment's two ends are the same point");
        }
    }
    return view;
}

SceneWorld ParseWorld(const Json& value)
{
    const std::string path = "world";
    if (!value.is_object())
    {
        Fail(path, "expected an object {\"gravity\": [x, y], \"dt\": s}, got " + TypeName(value));
    }
    CheckKeys(value, path, {"gravity", "dt"});
    SceneWorld world;
    if (value.contains("gravity"))
    {
        world.gravity = Point(value["gravity"], path + ".gravity");
    }
    if (value.contains("dt"))
    {
        world.dt = PositiveNumber(value["dt"], path + ".dt");
    }
    return world;
}

Scene ParseRoot(const Json& root, const SceneOptions& options)
{
    if (!root.is_object())
    {
        Fail("(root)", "expected an object with \"bodies\", got " + TypeName(root));
    }
    CheckKeys(root, "", {"$schema", "description", "bodies", "view", "world"});
    Scene scene;
    if (root.contains("description"))
    {
        if (!root["description"].is_string())
        {
            Fail("description", "expected a string, got " + TypeName(root["description"]));
        }
        scene.description = root["description"].get<std::string>();
    }
    if (!root.contains("bodies"))
    {
        Fail("bodies", "is missing (a scene lists its bodies in \"bodies\": [...])");
    }
    const Json& bodies = root["bodies"];
    if (!bodies.is_array())
    {
        Fail("bodies", "expected an array of bodies, got " + TypeName(bodies));
    }
    std::set<std::string> names;
    for (size_t i = 0; i < bodies.size(); ++i)
    {
        const std::string path = "bodies[" + std::to_string(i) + "]";
        Body body = ParseBody(bodies[i], path, i, options);
        if (!names.insert(body.name).second)
        {
            Fail(path + ".name", "\"" + body.name + "\" is already the name of another body");
        }
        scene.bodies.push_back(std::move(body));
    }
    if (root.contains("view"))
    {
        scene.view = ParseView(root["view"], scene);
        scene.hasView = true;
    }
    if (root.contains("world"))
    {
        scene.world = ParseWorld(root["world"]);
        scene.hasWorld = true;
    }
    return scene;
}

// Line and column of a byte offset, for JSON syntax errors.
std::string Location(std::string_view text, size_t offset)
{
    size_t line = 1;
    size_t column = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i)
    {
        if (text[i] == '\n')
        {
            ++line;
            column = 1;
        }
        else
        {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

} // namespace

SceneResult ParseScene(std::string_view text, const std::string& file, SceneOptions options)
{
    SceneResult result;
    Json root;
    try
    {
        root = Json::parse(text.begin(), text.end());
    }
    catch (const Json::parse_error& error)
    {
        // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line 1, column 2: ".
        std::string what = error.what();
        const size_t colon = what.find(": ");
        what = colon == std::string::npos ? what : what.substr(colon + 2);
        result.error = file + ":" + Location(text, error.byte == 0 ? 0 : error.byte - 1) + ": malformed JSON: " + what;
        return result;
    }
    catch (const Json::exception& error)
    {
        // A number beyond the range of a double: "[json.exception.out_of_range.406] number overflow parsing '1e400'".
        std::string what = error.what();
        const size_t bracket = what.find("] ");
        what = bracket == std::string::npos ? what : what.substr(bracket + 2);
        std::string where;
        const size_t open = what.find('\'');
        const size_t close = what.rfind('\'');
        if (open != std::string::npos && close > open)
        {
            const size_t at = text.find(what.substr(open + 1, close - open - 1));
            where = at == std::string_view::npos ? "" : ":" + Location(text, at);
        }
        result.error = OneLine(file + where + ": malformed JSON: " + what);
        return result;
    }
    try
    {
        result.scene = ParseRoot(root, options);
        result.scene.source = std::make_shared<const SceneSource>(SceneSource{std::move(root), file});
    }
    catch (const SceneFault& fault)
    {
        result.error = OneLine(file + ": " + fault.path + ": " + fault.message);
    }
    catch (const Json::exception& error)
    {
        result.error = OneLine(file + ": " + error.what());
    }
    return result;
}

SceneResult LoadScene(const std::string& file, SceneOptions options)
{
    std::error_code code;
    if (std::filesystem::is_directory(file, code))
    {
        SceneResult result;
        result.error = file + ": cannot open: is a directory";
        return result;
    }
    std::ifstream stream(file, std::ios::binary);
    if (!stream)
    {
        SceneResult result;
        result.error = file + ": cannot open: " + std::strerror(errno);
        return result;
    }
    std::ostringstream text;
    text << stream.rdbuf();
    if (stream.bad())
    {
        SceneResult result;
        result.error = file + ": cannot read: " + std::strerror(errno);
        return result;
    }
    return ParseScene(text.str(), file, options);
}

namespace
{

// A field of an object being written: its key and value.
struct Field
{
    std::string key;
    Json value;
};

// The field `key` of `object`, or null when it has none (or is not an object).
const Json* Member(const Json* object, const char* key)
{
    if (object == nullptr || !object->is_object())
    {
        return nullptr;
    }
    const auto it = object->find(key);
    return it == object->end() ? nullptr : &*it;
}

bool SameDouble(double a, double b)
{
    return a == b && std::signbit(a) == std::signbit(b);
}

// The number as the file wrote it when it still has that value (1 stays 1, not 1.0), else the value.
Json NumberJson(const Json* old, double value)
{
    if (old != nullptr && old->is_number() && SameDouble(old->get<double>(), value))
    {
        return *old;
    }
    return value;
}

Json PointJson(const Json* old, Vec2 p)
{
    const bool pair = old != nullptr && old->is_array() && old->size() == 2;
    return Json::array({NumberJson(pair ? &(*old)[0] : nullptr, p.x), NumberJson(pair ? &(*old)[1] : nullptr, p.y)});
}

// The place of a key among the file's keys: the four shape keys share one place, so that a box that became a
// polygon is written where the box was.
std::string Slot(const std::string& key)
{
    return key == "polygon" || key == "box" || key == "regular" || key == "circle" ? "shape" : key;
}

// The fields as one object in the file's order: fields the file had take its places, keys the file had that are
// not the scene's (namespaced fields, "$schema") come back as they were, new fields follow in the given order.
Json Arrange(const std::vector<Field>& fields, const Json* old, const std::vector<std::string>& known)
{
    Json out = Json::object();
    std::vector<bool> written(fields.size(), false);
    if (old != nullptr && old->is_object())
    {
        for (const auto& item : old->items())
        {
            const std::string& key = item.key();
            if (std::find(known.begin(), known.end(), key) == known.end())
            {
                out[key] = item.value();
                continue;
            }
            for (size_t i = 0; i < fields.size(); ++i)
            {
                if (!written[i] && Slot(fields[i].key) == Slot(key))
                {
                    out[fields[i].key] = fields[i].value;
                    written[i] = true;
                }
            }
        }
    }
    for (size_t i = 0; i < fields.size(); ++i)
    {
        if (!written[i])
        {
            out[fields[i].key] = fields[i].value;
        }
    }
    return out;
}

bool SameVertices(const Polygon& polygon, const std::vector<Vec2>& points)
{
    if (polygon.Count() != static_cast<int>(points.size()))
    {
        return false;
    }
    for (int i = 0; i < polygon.Count(); ++i)
    {
        if (!SameDouble(polygon.Vertices()[i].x, points[static_cast<size_t>(i)].x) ||
            !SameDouble(polygon.Vertices()[i].y, points[static_cast<size_t>(i)].y))
        {
            return false;
        }
    }
    return true;
}

bool SameVertices(const Polygon& polygon, const PolygonResult& made)
{
    return made.Ok() &&
           SameVertices(polygon, std::vector<Vec2>(made.polygon.Vertices().begin(), made.polygon.Vertices().end()));
}

// The file's own shape field when it still describes the body's shape: a "box" or "regular" shorthand, or the
// polygon's vertices as written. Null when the shape changed or the file had none.
const Json* KeptShape(const Polygon& polygon, const Json* old, std::string& key)
{
    if (const Json* box = Member(old, "box");
        box != nullptr && box->is_array() && box->size() == 2 && (*box)[0].is_number() && (*box)[1].is_number())
    {
        key = "box";
        const PolygonResult made = MakeBox(0.5 * (*box)[0].get<double>(), 0.5 * (*box)[1].get<double>());
        return SameVertices(polygon, made) ? box : nullptr;
    }
    if (const Json* regular = Member(old, "regular"); regular != nullptr)
    {
        const Json* sides = Member(regular, "sides");
        const Json* radius = Member(regular, "radius");
        const Json* phase = Member(regular, "phase");
        if (sides == nullptr || !sides->is_number_integer() || radius == nullptr || !radius->is_number() ||
            (phase != nullptr && !phase->is_number()) || sides->get<long>() != polygon.Count())
        {
            return nullptr;
        }
        key = "regular";
        const PolygonResult made =
            MakeRegularPolygon(polygon.Count(), radius->get<double>(), phase == nullptr ? 0.0 : phase->get<double>());
        return SameVertices(polygon, made) ? regular : nullptr;
    }
    if (const Json* points = Member(old, "polygon");
        points != nullptr && points->is_array() && points->size() == static_cast<size_t>(polygon.Count()))
    {
        key = "polygon";
        for (int i = 0; i < polygon.Count(); ++i)
        {
            const Json& p = (*points)[static_cast<size_t>(i)];
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number() ||
                !SameDouble(p[0].get<double>(), polygon.Vertices()[i].x) ||
                !SameDouble(p[1].get<double>(), polygon.Vertices()[i].y))
            {
                return nullptr;
            }
        }
        return points;
    }
    return nullptr;
}

// The keys of a body that the scene holds, in the order a new body writes them.
const std::vector<std::string> kBodyKeys = {"name",     "polygon",  "decompose",   "box",      "regular",
                                            "circle",   "position", "angle",       "velocity", "angular_velocity",
                                            "static",   "density",  "restitution", "friction", "static_friction"};

// One body. `old` is the body of the same name in the source file, null for a new body or a scene built in code;
// `index` is the body's place in the scene.
Json BodyJson(const Body& body, const Json* old, size_t index, bool fromFile)
{
    std::vector<Field> fields;
    if (!fromFile || old == nullptr || Member(old, "name") != nullptr || body.name != DefaultBodyName(index))
    {
        fields.push_back({"name", body.name});
    }
    if (body.IsConcave())
    {
        // A concave body writes its outline as read, not the hull that bounds it, and how it was cut.
        const Json* points = Member(old, "polygon");
        bool same = points != nullptr && points->is_array() && points->size() == body.outline.size();
        for (size_t i = 0; same && i < body.outline.size(); ++i)
        {
            const Json& p = (*points)[i];
            same = p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number() &&
                   SameDouble(p[0].get<double>(), body.outline[i].x) && SameDouble(p[1].get<double>(), body.outline[i].y);
        }
        if (same)
        {
            fields.push_back({"polygon", *points});
        }
        else
        {
            Json vertices = Json::array();
            for (const Vec2& v : body.outline)
            {
                vertices.push_back(Json::array({v.x, v.y}));
            }
            fields.push_back({"polygon", std::move(vertices)});
        }
        if (Member(old, "decompose") != nullptr || body.decompose != DecomposeMethod::Fast)
        {
            fields.push_back({"decompose", body.decompose == DecomposeMethod::Fast ? "fast" : "fewest"});
        }
    }
    else if (body.shape.type == ShapeType::Polygon)
    {
        std::string key;
        if (const Json* kept = KeptShape(body.shape.polygon, old, key); kept != nullptr)
        {
            fields.push_back({key, *kept});
        }
        else
        {
            Json vertices = Json::array();
            for (const Vec2& v : body.shape.polygon.Vertices())
            {
                vertices.push_back(Json::array({v.x, v.y}));
            }
            fields.push_back({"polygon", std::move(vertices)});
        }
    }
    else
    {
        const Json* oldCircle = Member(old, "circle");
        std::vector<Field> circle{{"radius", NumberJson(Member(oldCircle, "radius"), body.shape.circle.radius)}};
        if (Member(oldCircle, "center") != nullptr || body.shape.circle.center != Vec2{})
        {
            circle.push_back({"center", PointJson(Member(oldCircle, "center"), body.shape.circle.center)});
        }
        fields.push_back({"circle", Arrange(circle, oldCircle, {"radius", "center"})});
    }
    // A scene built in code always names the position; a file's body keeps the fields it had.
    if (!fromFile || Member(old, "position") != nullptr || body.position != Vec2{})
    {
        fields.push_back({"position", PointJson(Member(old, "position"), body.position)});
    }
    if (Member(old, "angle") != nullptr || body.angle != 0.0)
    {
        fields.push_back({"angle", NumberJson(Member(old, "angle"), body.angle)});
    }
    if (Member(old, "velocity") != nullptr || body.velocity != Vec2{})
    {
        fields.push_back({"velocity", PointJson(Member(old, "velocity"), body.velocity)});
    }
    // The physical fields: each written when the file had it or its value is not the default (-0 counts as 0, as
    // for the angle).
    const Body defaults;
    auto number = [&](const char* key, double value, double fallback) {
        if (Member(old, key) != nullptr || value != fallback)
        {
            fields.push_back({key, NumberJson(Member(old, key), value)});
        }
    };
    number("angular_velocity", body.angularVelocity, defaults.angularVelocity);
    if (Member(old, "static") != nullptr || body.isStatic)
    {
        fields.push_back({"static", body.isStatic});
    }
    number("density", body.density, defaults.density);
    number("restitution", body.material.restitution, defaults.material.restitution);
    number("friction", body.material.friction, defaults.material.friction);
    // Static friction's default is the body's own friction.
    number("static_friction", body.material.staticFriction, body.material.friction);
    return Arrange(fields, old, kBodyKeys);
}

// The view block. `old` is the file's, null for a scene built in code (which writes zoom, size, query and step
// always) or a file without one.
Json ViewJson(const SceneView& v, const Json* old, bool fromFile)
{
    auto had = [&](const char* key) { return !fromFile || Member(old, key) != nullptr; };
    std::vector<Field> fields;
    if (v.fit)
    {
        if (had("zoom"))
        {
            fields.push_back({"zoom", "fit"});
        }
    }
    else
    {
        fields.push_back({"center", PointJson(Member(old, "center"), v.center)});
        fields.push_back({"zoom", NumberJson(Member(old, "zoom"), v.zoom)});
    }
    if (had("size") || v.width != SceneView{}.width || v.height != SceneView{}.height)
    {
        const Json* size = Member(old, "size");
        const bool same = size != nullptr && size->is_array() && size->size() == 2 && (*size)[0].is_number() &&
                          (*size)[1].is_number() && (*size)[0].get<double>() == v.width &&
                          (*size)[1].get<double>() == v.height;
        fields.push_back({"size", same ? *size : Json::array({v.width, v.height})});
    }
    if (!v.layers.empty())
    {
        fields.push_back({"layers", v.layers});
    }
    if (!v.bodyA.empty() && !v.bodyB.empty())
    {
        fields.push_back({"pair", Json::array({v.bodyA, v.bodyB})});
    }
    if (had("query") || v.query != ViewQuery::Automatic)
    {
        fields.push_back(
            {"query", v.query == ViewQuery::Collide ? "collide" : (v.query == ViewQuery::Sweep ? "sweep" : "auto")});
    }
    if (had("pitfall") || v.pitfall != Pitfall::None)
    {
        fields.push_back({"pitfall", std::string(PitfallName(v.pitfall))});
    }
    if (had("steps") || v.steps == StepView::Faces)
    {
        fields.push_back({"steps", v.steps == StepView::Faces ? "faces" : "textbook"});
    }
    if (had("step") || v.step >= 0)
    {
        // Files count steps from 1, as every view does; a step 0 from an older file is written back as it was.
        const Json* previous = Member(old, "step");
        const bool legacyFirst =
            previous != nullptr && previous->is_number() && previous->get<double>() == 0.0 && v.step == 0;
        fields.push_back({"step", v.step >= 0 ? Json(legacyFirst ? 0 : v.step + 1) : Json("last")});
    }
    if (v.time >= 0.0)
    {
        fields.push_back({"time", NumberJson(Member(old, "time"), v.time)});
    }
    if (!v.caption.empty())
    {
        fields.push_back({"caption", v.caption});
    }
    if (v.singlePrecision || (fromFile && Member(old, "precision") != nullptr))
    {
        fields.push_back({"precision", v.singlePrecision ? "float" : "double"});
    }
    if (v.simSteps > 0 || (fromFile && Member(old, "sim_steps") != nullptr))
    {
        fields.push_back({"sim_steps", v.simSteps});
    }
    if (v.figure != FigureKind::Pair || (fromFile && Member(old, "figure") != nullptr))
    {
        fields.push_back({"figure", std::string(FigureKindName(v.figure))});
    }
    if (v.figure == FigureKind::Slice)
    {
        const Json* cut = Member(old, "cut");
        const bool keep = cut != nullptr && cut->is_array() && cut->size() == 2;
        fields.push_back({"cut", Json::array({PointJson(keep ? &(*cut)[0] : nullptr, v.cut[0]),
                                              PointJson(keep ? &(*cut)[1] : nullptr, v.cut[1])})});
    }
    return Arrange(fields, old,
                   {"center", "zoom", "size", "layers", "pair", "query", "steps", "pitfall", "step", "time", "caption",
                    "precision", "sim_steps", "figure", "cut"});
}

// The world block. `old` is the file's, null for a scene built in code (which writes both fields) or a file
// without one.
Json WorldJson(const SceneWorld& world, const Json* old, bool fromFile)
{
    const SceneWorld defaults;
    std::vector<Field> fields;
    if (!fromFile || Member(old, "gravity") != nullptr || world.gravity != defaults.gravity)
    {
        fields.push_back({"gravity", PointJson(Member(old, "gravity"), world.gravity)});
    }
    if (!fromFile || Member(old, "dt") != nullptr || world.dt != defaults.dt)
    {
        fields.push_back({"dt", NumberJson(Member(old, "dt"), world.dt)});
    }
    return Arrange(fields, old, {"gravity", "dt"});
}

// The whole file; `schema` replaces a kept "$schema" when not null.
std::string SceneText(const Scene& scene, const std::string* schema)
{
    const bool fromFile = scene.source != nullptr;
    const Json* old = fromFile ? &scene.source->root : nullptr;

    // Bodies of the file by name, to find each body's own fields.
    std::vector<std::pair<std::string, const Json*>> oldBodies;
    if (const Json* bodies = Member(old, "bodies"); bodies != nullptr && bodies->is_array())
    {
        for (size_t i = 0; i < bodies->size(); ++i)
        {
            const Json* body = &(*bodies)[i];
            const Json* name = Member(body, "name");
            oldBodies.emplace_back(name != nullptr && name->is_string() ? name->get<std::string>() : DefaultBodyName(i),
                                   body);
        }
        std::sort(oldBodies.begin(), oldBodies.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    auto oldBody = [&](const std::string& name) -> const Json* {
        const auto it = std::lower_bound(oldBodies.begin(), oldBodies.end(), name,
                                         [](const auto& entry, const std::string& key) { return entry.first < key; });
        return it != oldBodies.end() && it->first == name ? it->second : nullptr;
    };

    std::vector<Field> fields;
    if (!scene.description.empty() || Member(old, "description") != nullptr)
    {
        fields.push_back({"description", scene.description});
    }
    fields.push_back({"bodies", Json::array()});
    if (scene.hasView)
    {
        fields.push_back({"view", ViewJson(scene.view, Member(old, "view"), fromFile)});
    }
    // A scene built in code that sets a world without saying so gets its block too.
    if (scene.hasWorld || scene.world.gravity != SceneWorld{}.gravity || scene.world.dt != SceneWorld{}.dt)
    {
        fields.push_back({"world", WorldJson(scene.world, Member(old, "world"), fromFile)});
    }
    Json root = Arrange(fields, old, {"description", "bodies", "view", "world"});
    if (schema != nullptr && root.contains("$schema"))
    {
        root["$schema"] = *schema;
    }

    // One body per line keeps saved scenes readable and diffable.
    std::string text = "{";
    bool first = true;
    for (const auto& item : root.items())
    {
        text += first ? "\n  " : ",\n  ";
        first = false;
        text += Json(item.key()).dump() + ": ";
        if (item.key() != "bodies")
        {
            text += item.value().dump();
            continue;
        }
        text += "[\n";
        for (size_t i = 0; i < scene.bodies.size(); ++i)
        {
            const Body& body = scene.bodies[i];
            text += "    " + BodyJson(body, oldBody(body.name), i, fromFile).dump() +
                    (i + 1 < scene.bodies.size() ? ",\n" : "\n");
        }
        text += "  ]";
    }
    text += "\n}\n";
    return text;
}

// The source's "$schema" as seen from `target`'s folder, when it is a relative path and the folder changes; null
// when it stays as it is.
std::unique_ptr<std::string> MovedSchema(const Scene& scene, const std::filesystem::path& target)
{
    if (scene.source == nullptr)
    {
        return nullptr;
    }
    const Json* schema = Member(&scene.source->root, "$schema");
    if (schema == nullptr || !schema->is_string())
    {
        return nullptr;
    }
    const std::filesystem::path path(schema->get<std::string>());
    if (path.empty() || path.is_absolute() || schema->get<std::string>().find(':') != std::string::npos)
    {
        return nullptr; // absolute, or a URL
    }
    std::error_code code;
    const std::filesystem::path from =
        std::filesystem::weakly_canonical(std::filesystem::absolute(scene.source->file, code).parent_path(), code);
    const std::filesystem::path to =
        std::filesystem::weakly_canonical(std::filesystem::absolute(target, code).parent_path(), code);
    if (code || from == to)
    {
        return nullptr;
    }
    const std::filesystem::path moved = (from / path).lexically_normal().lexically_relative(to);
    return moved.empty() ? nullptr : std::make_unique<std::string>(moved.generic_string());
}

} // namespace

namespace
{

// The one list of pitfalls and their scene-file names.
constexpr std::pair<Pitfall, std::string_view> kPitfallNames[] = {
    {Pitfall::None, "none"},
    {Pitfall::UnnormalisedAxes, "unnormalised-axes"},
    {Pitfall::UncheckedDirection, "unchecked-direction"},
    {Pitfall::OneShapesAxes, "one-shapes-axes"},
    {Pitfall::SampledMotion, "sampled-motion"},
    {Pitfall::FloatWorld, "float-world"},
};

} // namespace

std::string_view PitfallName(Pitfall pitfall)
{
    for (const auto& [value, name] : kPitfallNames)
    {
        if (value == pitfall)
        {
            return name;
        }
    }
    return "none";
}

bool PitfallFromName(std::string_view name, Pitfall& pitfall)
{
    for (const auto& [value, known] : kPitfallNames)
    {
        if (known == name)
        {
            pitfall = value;
            return true;
        }
    }
    return false;
}

namespace
{

// The one list of figure kinds and their scene-file names.
constexpr std::pair<FigureKind, std::string_view> kFigureKindNames[] = {
    {FigureKind::Pair, "pair"},
    {FigureKind::Decomposition, "decomposition"},
    {FigureKind::Slice, "slice"},
    {FigureKind::DiscCast, "disc-cast"},
    {FigureKind::Pieces, "pieces"},
};

} // namespace

std::string_view FigureKindName(FigureKind kind)
{
    for (const auto& [value, name] : kFigureKindNames)
    {
        if (value == kind)
        {
            return name;
        }
    }
    return "pair";
}

bool FigureKindFromName(std::string_view name, FigureKind& kind)
{
    for (const auto& [value, known] : kFigureKindNames)
    {
        if (known == name)
        {
            kind = value;
            return true;
        }
    }
    return false;
}

std::string FigureKindList()
{
    std::string list;
    const size_t count = sizeof kFigureKindNames / sizeof kFigureKindNames[0];
    for (size_t i = 0; i < count; ++i)
    {
        list += std::string(i == 0 ? "" : (i + 1 == count ? " or " : ", ")) + "\"" +
                std::string(kFigureKindNames[i].second) + "\"";
    }
    return list;
}

std::string SceneToJson(const Scene& scene)
{
    return SceneText(scene, nullptr);
}

bool SaveScene(const Scene& scene, const std::string& file, std::string& error)
{
    const std::filesystem::path target(file);
    const std::unique_ptr<std::string> schema = MovedSchema(scene, target);
    const std::string text = SceneText(scene, schema.get());
    const std::filesystem::path temporary =
        target.parent_path() / ("." + target.filename().string() + ".tmp." + std::to_string(::getpid()));
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
        {
            error = file + ": cannot write: " + std::strerror(errno);
            return false;
        }
        out << text;
        out.flush();
        if (!out)
        {
            error = file + ": write failed: " + std::strerror(errno);
            out.close();
            std::filesystem::remove(temporary);
            return false;
        }
    }
    std::error_code code;
    std::filesystem::rename(temporary, target, code);
    if (code)
    {
        error = file + ": cannot replace the file: " + code.message();
        std::filesystem::remove(temporary, code);
        return false;
    }
    return true;
}

} // namespace satviz
