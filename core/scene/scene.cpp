// SPDX-License-Identifier: MIT
// satviz: scene files. Every error names the file, the JSON path of the offending value and what is wrong.

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
namespace
{

using Json = nlohmann::json;

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

Shape PolygonShape(const PolygonResult& result, const std::string& path)
{
    if (!result.Ok())
    {
        Fail(path, DescribePolygonError(result.error, result.vertex));
    }
    return MakeShape(result.polygon);
}

Body ParseBody(const Json& value, const std::string& path, size_t index)
{
    if (!value.is_object())
    {
        Fail(path, "expected a body object, got " + TypeName(value));
    }
    CheckKeys(value, path, {"name", "polygon", "box", "regular", "circle", "position", "angle", "velocity"});

    Body body;
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
        body.name = index < 26 ? std::string(1, static_cast<char>('A' + index)) : "body" + std::to_string(index);
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
        body.shape = PolygonShape(MakePolygon(vertices), p);
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
              {"center", "zoom", "size", "layers", "pair", "query", "step", "time", "caption", "precision"});
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
        const std::vector<std::string>& known = ViewLayerNames();
        for (size_t i = 0; i < layers.size(); ++i)
        {
            const std::string p = path + ".layers[" + std::to_string(i) + "]";
            std::string name = String(layers[i], p);
            if (std::find(known.begin(), known.end(), name) == known.end())
            {
                std::string list;
                for (const std::string& candidate : known)
                {
                    list += (list.empty() ? "" : ", ") + candidate;
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
    if (value.contains("step"))
    {
        const Json& step = value["step"];
        if (!(step.is_string() && step.get<std::string>() == "last"))
        {
            view.step = WholeNumber(step, path + ".step", 0, 1000000);
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
    return view;
}

Scene ParseRoot(const Json& root)
{
    if (!root.is_object())
    {
        Fail("(root)", "expected an object with \"bodies\", got " + TypeName(root));
    }
    CheckKeys(root, "", {"$schema", "description", "bodies", "view"});
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
        Body body = ParseBody(bodies[i], path, i);
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

SceneResult ParseScene(std::string_view text, const std::string& file)
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
        result.scene = ParseRoot(root);
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

SceneResult LoadScene(const std::string& file)
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
    return ParseScene(text.str(), file);
}

namespace
{

nlohmann::ordered_json PointJson(Vec2 p)
{
    return nlohmann::ordered_json::array({p.x, p.y});
}

} // namespace

std::string SceneToJson(const Scene& scene)
{
    using Ordered = nlohmann::ordered_json;
    Ordered root = Ordered::object();
    if (!scene.description.empty())
    {
        root["description"] = scene.description;
    }
    Ordered bodies = Ordered::array();
    for (const Body& body : scene.bodies)
    {
        Ordered item = Ordered::object();
        item["name"] = body.name;
        if (body.shape.type == ShapeType::Polygon)
        {
            Ordered vertices = Ordered::array();
            for (const Vec2& v : body.shape.polygon.vertices)
            {
                vertices.push_back(PointJson(v));
            }
            item["polygon"] = vertices;
        }
        else
        {
            Ordered circle = Ordered::object();
            circle["radius"] = body.shape.circle.radius;
            if (body.shape.circle.center != Vec2{})
            {
                circle["center"] = PointJson(body.shape.circle.center);
            }
            item["circle"] = circle;
        }
        item["position"] = PointJson(body.position);
        if (body.angle != 0.0)
        {
            item["angle"] = body.angle;
        }
        if (body.velocity != Vec2{})
        {
            item["velocity"] = PointJson(body.velocity);
        }
        bodies.push_back(item);
    }
    root["bodies"] = bodies;
    if (scene.hasView)
    {
        const SceneView& v = scene.view;
        Ordered view = Ordered::object();
        if (v.fit)
        {
            view["zoom"] = "fit";
        }
        else
        {
            view["center"] = PointJson(v.center);
            view["zoom"] = v.zoom;
        }
        view["size"] = Ordered::array({v.width, v.height});
        if (!v.layers.empty())
        {
            view["layers"] = v.layers;
        }
        if (!v.bodyA.empty() && !v.bodyB.empty())
        {
            view["pair"] = Ordered::array({v.bodyA, v.bodyB});
        }
        view["query"] = v.query == ViewQuery::Collide ? "collide" : (v.query == ViewQuery::Sweep ? "sweep" : "auto");
        if (v.step >= 0)
        {
            view["step"] = v.step;
        }
        else
        {
            view["step"] = "last";
        }
        if (v.time >= 0.0)
        {
            view["time"] = v.time;
        }
        if (!v.caption.empty())
        {
            view["caption"] = v.caption;
        }
        if (v.singlePrecision)
        {
            view["precision"] = "float";
        }
        root["view"] = view;
    }
    // One body per line keeps saved scenes readable and diffable.
    std::string text = "{\n";
    if (root.contains("description"))
    {
        text += "  \"description\": " + root["description"].dump() + ",\n";
    }
    text += "  \"bodies\": [\n";
    for (size_t i = 0; i < bodies.size(); ++i)
    {
        text += "    " + bodies[i].dump() + (i + 1 < bodies.size() ? ",\n" : "\n");
    }
    text += "  ]";
    if (root.contains("view"))
    {
        text += ",\n  \"view\": " + root["view"].dump();
    }
    text += "\n}\n";
    return text;
}

bool SaveScene(const Scene& scene, const std::string& file, std::string& error)
{
    const std::string text = SceneToJson(scene);
    const std::filesystem::path target(file);
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
