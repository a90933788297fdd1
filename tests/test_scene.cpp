// SPDX-License-Identifier: MIT
// Scene files: what loads, and the one-line error for everything that does not.

#include "support/scene_files.h"

#include <satviz/collide.h>
#include <satviz/concave.h>
#include <satviz/scene.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <limits>

using namespace satviz;

namespace
{

std::string ErrorOf(const std::string& text)
{
    return ParseScene(text, "s.json").error;
}

} // namespace

TEST_CASE("A scene with every shape kind loads", "[scene]")
{
    const SceneResult r = ParseScene(R"({
        "$schema": "scene.schema.json", "description": "all kinds",
        "bodies": [
          {"name": "p", "polygon": [[0, 0], [1, 0], [0, 1]], "position": [1, 2], "angle": 0.5, "velocity": [3, 4]},
          {"box": [2, 1]},
          {"regular": {"sides": 7, "radius": 0.5, "phase": 0.1}},
          {"name": "c", "circle": {"radius": 0.25, "center": [0.1, 0]}, "tool:color": "red"}
        ]})",
                                     "s.json");
    REQUIRE(r.Ok());
    REQUIRE(r.scene.bodies.size() == 4);
    const Body& p = r.scene.bodies[0];
    CHECK(p.name == "p");
    CHECK(p.shape.type == ShapeType::Polygon);
    CHECK(p.position == Vec2{1, 2});
    CHECK(p.angle == 0.5);
    CHECK(p.velocity == Vec2{3, 4});
    CHECK(r.scene.bodies[1].name == "B");
    CHECK(r.scene.bodies[1].shape.polygon.Vertices()[2] == Vec2{1.0, 0.5});
    CHECK(r.scene.bodies[2].shape.polygon.Count() == 7);
    CHECK(r.scene.bodies[3].shape.type == ShapeType::Circle);
    CHECK(r.scene.bodies[3].shape.circle.radius == 0.25);
    CHECK(r.scene.description == "all kinds");
}

TEST_CASE("Errors name the file, the JSON path and what is wrong", "[scene]")
{
    CHECK(ErrorOf(R"({"bodies": [{"polygon": [[0,0],[1,0],[1,1],[0.9,0.2]]}]})") ==
          "s.json: bodies[0].polygon: polygon is not convex at vertex 3 (use a convex decomposition)");
    CHECK(ErrorOf(R"({"bodies": [{"circle": {"radius": 1}}, {"polygon": [[0,0],[1,0],"x"]}]})") ==
          "s.json: bodies[1].polygon[2]: expected a pair of numbers [x, y], got a string");
    CHECK(ErrorOf(R"({"bodies": [{"polygon": [[0,0],[1,0],[0,1]], "positon": [0, 0]}]})") ==
          "s.json: bodies[0].positon: unknown field \"positon\" (did you mean \"position\"?)");
    CHECK(ErrorOf(R"({"bodies": [{"polygon": [[0,0],[1,0],[0,1]], "colour": "red"}]})")
              .find("unknown field \"colour\" (known fields: name, polygon") != std::string::npos);
    CHECK(ErrorOf(R"({"bodies": [{"polygon": [[0,0],[0,1],[1,0]]}]})") ==
          "s.json: bodies[0].polygon: polygon winds clockwise (list the vertices counter-clockwise, y up)");
    CHECK(ErrorOf(R"({"bodies": [{"circle": {"radius": -1}}]})") ==
          "s.json: bodies[0].circle.radius: must be greater than 0");
    CHECK(ErrorOf(R"({"bodies": [{"circle": {"radius": 1}, "position": [1e400, 0]}]})") ==
          "s.json:1:52: malformed JSON: number overflow parsing '1e400'");
    CHECK(ErrorOf(R"({"bodies": [{"circle": {"radius": 1}, "position": [1e13, 0]}]})") ==
          "s.json: bodies[0].position[0]: magnitude exceeds 1e+12");
    CHECK(ErrorOf(R"({"bodies": [{"circle": {"radius": 1}, "box": [1, 1]}]})").find("more than one shape") !=
          std::string::npos);
    CHECK(ErrorOf(R"({"bodies": [{"name": "A", "box": [1, 1]}, {"name": "A", "box": [1, 1]}]})") ==
          "s.json: bodies[1].name: \"A\" is already the name of another body");
    CHECK(ErrorOf(R"({"bodies": [{"regular": {"sides": 2, "radius": 1}}]})") ==
          "s.json: bodies[0].regular.sides: expected a whole number of sides from 3 to 1000000");
    CHECK(ErrorOf(R"({"bodies": {}})") == "s.json: bodies: expected an array of bodies, got an object");
    CHECK(ErrorOf(R"([1, 2])") == "s.json: (root): expected an object with \"bodies\", got an array");
    CHECK(ErrorOf(R"({})") == "s.json: bodies: is missing (a scene lists its bodies in \"bodies\": [...])");
}

TEST_CASE("Malformed JSON reports line and column", "[scene]")
{
    const std::string error = ErrorOf("{\"bodies\": [\n  {\"box\": [1, 1]},\n  {\"box\": [1 1]}\n]}");
    CHECK(error.rfind("s.json:3:", 0) == 0);
    CHECK(error.find("malformed JSON") != std::string::npos);
    CHECK(ErrorOf("").find("malformed JSON") != std::string::npos);
    CHECK(ErrorOf("{\"bodies\": [{\"box\": [NaN, 1]}]}").find("malformed JSON") != std::string::npos);
}

TEST_CASE("Missing files and directories are errors, not crashes", "[scene]")
{
    CHECK(LoadScene("does/not/exist.json").error == "does/not/exist.json: cannot open: No such file or directory");
    CHECK(LoadScene(".").error == ".: cannot open: is a directory");
}

TEST_CASE("Every bundled scene loads", "[scene]")
{
    int count = 0;
    // The examples of concave shapes, in a folder of their own, load as the tools that draw them read them.
    SceneOptions concave;
    concave.concave = true;
    for (const std::string& file : testing::TutorialSceneFiles(true))
    {
        const SceneResult r = LoadScene(file, concave);
        INFO(r.error);
        CHECK(r.Ok());
        ++count;
    }
    CHECK(count >= 4);
}

TEST_CASE("A view block sets the camera, size, layers, pair, query, step, time and caption", "[scene]")
{
    const SceneResult result = ParseScene(R"({"bodies": [{"name": "P", "box": [1, 1]}, {"name": "Q", "box": [1, 1]},
        {"name": "R", "circle": {"radius": 1}}],
        "view": {"center": [1.5, -2], "zoom": 80, "size": [640, 480], "layers": ["shapes", "mtv"],
                 "pair": ["R", "P"], "query": "sweep", "steps": "faces", "step": 3, "time": 0.25,
                 "caption": "Hello"}})",
                                          "s.json");
    INFO(result.error);
    REQUIRE(result.Ok());
    const Scene& scene = result.scene;
    CHECK(scene.hasView);
    CHECK(!scene.view.fit);
    CHECK(scene.view.center == Vec2{1.5, -2.0});
    CHECK(scene.view.zoom == 80.0);
    CHECK(scene.view.width == 640);
    CHECK(scene.view.height == 480);
    CHECK(scene.view.layers == std::vector<std::string>{"shapes", "mtv"});
    CHECK(scene.view.bodyA == "R");
    CHECK(scene.view.bodyB == "P");
    CHECK(scene.view.query == ViewQuery::Sweep);
    // A file counts steps from 1, as every view does; the scene holds the index from 0.
    CHECK(scene.view.step == 2);
    CHECK(scene.view.steps == StepView::Faces);
    CHECK(scene.view.time == 0.25);
    CHECK(scene.view.caption == "Hello");

    // The step numbering round trip: written back as 3, read again as index 2; 0 from older files is the first.
    const SceneResult again = ParseScene(SceneToJson(scene), "again.json");
    REQUIRE(again.Ok());
    CHECK(again.scene.view.step == 2);
    CHECK(again.scene.view.steps == StepView::Faces);
    CHECK(SceneToJson(scene).find("\"step\":3") != std::string::npos);
    const SceneResult legacy = ParseScene(R"({"bodies": [], "view": {"step": 0}})", "old.json");
    REQUIRE(legacy.Ok());
    CHECK(legacy.scene.view.step == 0);
    const SceneResult first = ParseScene(R"({"bodies": [], "view": {"step": 1}})", "new.json");
    REQUIRE(first.Ok());
    CHECK(first.scene.view.step == 0);
    CHECK(first.scene.view.steps == StepView::Textbook);
    CHECK(ErrorOf(R"({"bodies": [], "view": {"steps": "edges"}})") ==
          "s.json: view.steps: expected \"textbook\" or \"faces\", got \"edges\"");

    const SceneResult defaults = ParseScene(R"({"bodies": [], "view": {"zoom": "fit", "step": "last"}})", "s.json");
    REQUIRE(defaults.Ok());
    CHECK(defaults.scene.view.fit);
    CHECK(defaults.scene.view.step == -1);
    CHECK(defaults.scene.view.width == 800);
    CHECK(!ParseScene(R"({"bodies": []})", "s.json").scene.hasView);
}

TEST_CASE("View block errors name the field", "[scene]")
{
    const std::string two = R"({"bodies": [{"name": "P", "box": [1, 1]}, {"name": "Q", "box": [1, 1]}], "view": )";
    CHECK(ErrorOf(two + R"({"layers": ["shapes", "mvt"]}})").find("s.json: view.layers[1]: unknown layer \"mvt\"") ==
          0);
    CHECK(ErrorOf(two + R"({"pair": ["P", "Z"]}})") == "s.json: view.pair[1]: no body is named \"Z\"");
    CHECK(ErrorOf(two + R"({"pair": ["P", "P"]}})") == "s.json: view.pair: names the same body twice");
    CHECK(ErrorOf(two + R"({"size": [800, 9]}})") == "s.json: view.size[1]: expected a whole number from 16 to 8192");
    CHECK(ErrorOf(two + R"({"size": [800.5, 600]}})") ==
          "s.json: view.size[0]: expected a whole number from 16 to 8192");
    CHECK(ErrorOf(two + R"({"time": 1.5}})") ==
          "s.json: view.time: expected a time in [0, 1] (a fraction of the step)");
    CHECK(ErrorOf(two + R"({"zoom": -3}})") == "s.json: view.zoom: must be greater than 0");
    CHECK(ErrorOf(two + R"({"zoom": 1e-300}})") ==
          "s.json: view.zoom: expected pixels per world unit from 1e-9 to 1e12, or \"fit\"");
    CHECK(ErrorOf(two + R"({"zoom": 2e12}})") ==
          "s.json: view.zoom: expected pixels per world unit from 1e-9 to 1e12, or \"fit\"");
    CHECK(ErrorOf(two + R"({"zoom": "far"}})") == "s.json: view.zoom: expected a number, got a string");
    CHECK(ParseScene(two + R"({"zoom": 1e-9}})", "s.json").Ok());
    CHECK(ParseScene(two + R"({"zoom": 1e12}})", "s.json").Ok());
    CHECK(ErrorOf(two + R"({"center": [0, 0]}})") ==
          "s.json: view.center: needs a \"zoom\" (pixels per unit) beside it");
    CHECK(ErrorOf(two + R"({"query": "raycast"}})") ==
          "s.json: view.query: expected \"collide\", \"sweep\" or \"auto\", got \"raycast\"");
    CHECK(ErrorOf(two + R"({"step": -1}})") == "s.json: view.step: expected a whole number from 0 to 1000000");
    CHECK(ErrorOf(two + R"({"zoom": 10, "centre": [0, 0]}})") ==
          "s.json: view.centre: unknown field \"centre\" (did you mean \"center\"?)");
    CHECK(ErrorOf(two + R"([1, 2]})") == "s.json: view: expected an object, got an array");
    CHECK(ErrorOf(two + R"({"precision": "half"}})") ==
          "s.json: view.precision: expected \"double\" or \"float\", got \"half\"");
    const SceneResult single = ParseScene(two + R"({"precision": "float"}})", "s.json");
    REQUIRE(single.Ok());
    CHECK(single.scene.view.singlePrecision);
    CHECK(ParseScene(SceneToJson(single.scene), "s.json").scene.view.singlePrecision);
}

TEST_CASE("A view's figure loads, saves back, and is refused for a body it cannot draw, naming the field", "[scene]")
{
    const std::string one = R"({"bodies": [{"name": "L", "polygon": [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]},
        {"name": "ball", "circle": {"radius": 1}}], "view": )";
    SceneOptions concave;
    concave.concave = true;
    const SceneResult cut = ParseScene(one + R"({"figure": "decomposition"}})", "s.json", concave);
    INFO(cut.error);
    REQUIRE(cut.Ok());
    CHECK(cut.scene.view.figure == FigureKind::Decomposition);
    CHECK(ParseScene(SceneToJson(cut.scene), "again.json", concave).scene.view.figure == FigureKind::Decomposition);
    // Absent stays absent: the pair's figure is the default.
    const SceneResult plain = ParseScene(one + "{}}", "s.json", concave);
    CHECK(plain.scene.view.figure == FigureKind::Pair);
    CHECK(SceneToJson(plain.scene).find("figure") == std::string::npos);
    CHECK(ParseScene(one + R"({"figure": "cut"}})", "s.json", concave).error ==
          "s.json: view.figure: expected \"pair\", \"decomposition\", \"slice\", \"disc-cast\" or \"pieces\", got \"cut\"");
    CHECK(ParseScene(one + R"({"pair": ["ball", "L"], "figure": "decomposition"}})", "s.json", concave).error ==
          "s.json: view.figure: a decomposition figure cuts the pair's first body, \"ball\", which is a circle, "
          "not a polygon");
    CHECK(ErrorOf(R"({"bodies": [], "view": {"figure": "decomposition"}})") ==
          "s.json: view.figure: a decomposition figure cuts the pair's first body: the scene has no body");
}

TEST_CASE("A slice figure's cut loads, saves back, and is refused where it cannot be drawn, naming the field",
          "[scene]")
{
    const std::string box = R"({"bodies": [{"name": "box", "box": [2, 1]}, {"name": "ball", "circle": {"radius": 1}}],
        "view": )";
    const SceneResult cut = ParseScene(box + R"({"figure": "slice", "cut": [[-2, 0.25], [2, -0.5]]}})", "s.json");
    INFO(cut.error);
    REQUIRE(cut.Ok());
    CHECK(cut.scene.view.figure == FigureKind::Slice);
    CHECK(cut.scene.view.cut[0] == Vec2{-2.0, 0.25});
    CHECK(cut.scene.view.cut[1] == Vec2{2.0, -0.5});
    const SceneResult again = ParseScene(SceneToJson(cut.scene), "again.json");
    INFO(again.error);
    REQUIRE(again.Ok());
    CHECK(again.scene.view.cut[1] == Vec2{2.0, -0.5});
    CHECK(ErrorOf(box + R"({"figure": "slice"}})") ==
          "s.json: view.figure: a slice figure needs a \"cut\": [[x, y], [x, y]], the segment to cut along");
    CHECK(ErrorOf(box + R"({"cut": [[0, 0], [1, 1]]}})") ==
          "s.json: view.cut: only a slice figure (\"figure\": \"slice\") cuts along a segment");
    CHECK(ErrorOf(box + R"({"figure": "slice", "cut": [[0, 0], [0, 0]]}})") ==
          "s.json: view.cut: the segment's two ends are the same point");
    CHECK(ErrorOf(box + R"({"figure": "slice", "cut": [[0, 0]]}})") ==
          "s.json: view.cut: expected two points [[x, y], [x, y]], got an array");
    CHECK(ErrorOf(box + R"({"figure": "slice", "cut": [[0, 0], [1, "a"]]}})") ==
          "s.json: view.cut[1][1]: expected a number, got a string");
    CHECK(ErrorOf(box + R"({"pair": ["ball", "box"], "figure": "slice", "cut": [[0, 0], [1, 1]]}})") ==
          "s.json: view.figure: a slice figure cuts the pair's first body, \"ball\", which is a circle, not a "
          "polygon");
}

TEST_CASE("A disc-cast figure needs a moving circle as the pair's second body, naming the field", "[scene]")
{
    const std::string bodies = R"({"bodies": [{"name": "wall", "box": [1, 3]},
        {"name": "bullet", "circle": {"radius": 0.4}, "position": [-3, 1.8], "velocity": [6, 0]},
        {"name": "still", "circle": {"radius": 0.4}}], "view": )";
    const SceneResult cast = ParseScene(bodies + R"({"figure": "disc-cast"}})", "s.json");
    INFO(cast.error);
    REQUIRE(cast.Ok());
    CHECK(cast.scene.view.figure == FigureKind::DiscCast);
    CHECK(ParseScene(SceneToJson(cast.scene), "again.json").scene.view.figure == FigureKind::DiscCast);
    CHECK(ErrorOf(bodies + R"({"pair": ["bullet", "wall"], "figure": "disc-cast"}})") ==
          "s.json: view.figure: a disc-cast figure casts the pair's second body, \"wall\", which is a polygon, not "
          "a circle");
    CHECK(ErrorOf(bodies + R"({"pair": ["wall", "still"], "figure": "disc-cast"}})") ==
          "s.json: view.figure: a disc-cast figure casts the pair's second body, \"still\", along its velocity, "
          "which is zero");
    CHECK(ErrorOf(R"({"bodies": [{"name": "wall", "box": [1, 3]}], "view": {"figure": "disc-cast"}})") ==
          "s.json: view.figure: a disc-cast figure casts the pair's second body against its first: the scene has 1 "
          "body");
}

TEST_CASE("A pieces figure needs a pair with a concave body, naming the field", "[scene]")
{
    SceneOptions concave;
    concave.concave = true;
    const std::string bodies = R"({"bodies": [{"name": "L", "polygon": [[0, 0], [4, 0], [4, 1], [1, 1], [1, 3],
        [0, 3]]}, {"name": "box", "box": [1, 1]}, {"name": "ball", "circle": {"radius": 1}}], "view": )";
    const SceneResult pieces = ParseScene(bodies + R"({"figure": "pieces"}})", "s.json", concave);
    INFO(pieces.error);
    REQUIRE(pieces.Ok());
    CHECK(pieces.scene.view.figure == FigureKind::Pieces);
    CHECK(ParseScene(bodies + R"({"pair": ["box", "ball"], "figure": "pieces"}})", "s.json", concave).error ==
          "s.json: view.figure: a pieces figure tests a pair with a concave body piece by piece: neither \"box\" "
          "nor \"ball\" is concave");
    CHECK(ParseScene(R"({"bodies": [{"name": "box", "box": [1, 1]}], "view": {"figure": "pieces"}})", "s.json",
                     concave)
              .error == "s.json: view.figure: a pieces figure tests a pair: the scene has 1 body");
}

TEST_CASE("A view's sim_steps loads, saves back and refuses a negative or fractional count", "[scene]")
{
    const std::string two = R"({"bodies": [{"name": "P", "box": [1, 1]}, {"name": "Q", "box": [1, 1]}], "view": )";
    const SceneResult stepped = ParseScene(two + R"({"sim_steps": 120}})", "s.json");
    INFO(stepped.error);
    REQUIRE(stepped.Ok());
    CHECK(stepped.scene.view.simSteps == 120);
    CHECK(ParseScene(SceneToJson(stepped.scene), "again.json").scene.view.simSteps == 120);
    CHECK(ParseScene(two + "{}}", "s.json").scene.view.simSteps == 0);
    // Absent stays absent; a file's explicit 0 is kept as written.
    CHECK(SceneToJson(ParseScene(two + "{}}", "s.json").scene).find("sim_steps") == std::string::npos);
    CHECK(SceneToJson(ParseScene(two + R"({"sim_steps": 0}})", "s.json").scene).find("\"sim_steps\":0") !=
          std::string::npos);
    CHECK(ErrorOf(two + R"({"sim_steps": -1}})") ==
          "s.json: view.sim_steps: expected a whole number from 0 to 1000000");
    CHECK(ErrorOf(two + R"({"sim_steps": 2.5}})") ==
          "s.json: view.sim_steps: expected a whole number from 0 to 1000000");
    CHECK(ErrorOf(two + R"({"sim_steps": "many"}})") == "s.json: view.sim_steps: expected a number, got a string");
    CHECK(ErrorOf(two + R"({"sim_step": 3}})").find("unknown field \"sim_step\" (did you mean \"sim_steps\"?)") !=
          std::string::npos);
}

TEST_CASE("A saved scene reads back as the same scene, bit for bit", "[scene]")
{
    int scenes = 0;
    SceneOptions concave;
    concave.concave = true;
    for (const std::string& file : testing::TutorialSceneFiles(true))
    {
        const SceneResult original = LoadScene(file, concave);
        REQUIRE(original.Ok());
        const SceneResult again = ParseScene(SceneToJson(original.scene), "saved.json", concave);
        INFO(file << "\n" << again.error);
        REQUIRE(again.Ok());
        const Scene& a = original.scene;
        const Scene& b = again.scene;
        CHECK(a.description == b.description);
        REQUIRE(a.bodies.size() == b.bodies.size());
        for (size_t i = 0; i < a.bodies.size(); ++i)
        {
            const Body& x = a.bodies[i];
            const Body& y = b.bodies[i];
            CHECK(x.name == y.name);
            CHECK(x.position == y.position);
            CHECK(x.angle == y.angle);
            CHECK(x.velocity == y.velocity);
            REQUIRE(x.shape.type == y.shape.type);
            if (x.shape.type == ShapeType::Polygon)
            {
                REQUIRE(x.shape.polygon.Count() == y.shape.polygon.Count());
                for (int k = 0; k < x.shape.polygon.Count(); ++k)
                {
                    CHECK(x.shape.polygon.Vertices()[k] == y.shape.polygon.Vertices()[k]);
                    CHECK(x.shape.polygon.Normal(k) == y.shape.polygon.Normal(k));
                }
            }
            else
            {
                CHECK(x.shape.circle.radius == y.shape.circle.radius);
                CHECK(x.shape.circle.center == y.shape.circle.center);
            }
        }
        CHECK(a.hasView == b.hasView);
        CHECK(a.view.fit == b.view.fit);
        CHECK(a.view.center == b.view.center);
        CHECK(a.view.zoom == b.view.zoom);
        CHECK(a.view.layers == b.view.layers);
        CHECK(a.view.step == b.view.step);
        CHECK(a.view.time == b.view.time);
        CHECK(a.view.caption == b.view.caption);
        CHECK(a.view.singlePrecision == b.view.singlePrecision);
        CHECK(a.view.simSteps == b.view.simSteps);
        CHECK(a.view.figure == b.view.figure);
        CHECK(a.view.cut[0] == b.view.cut[0]);
        CHECK(a.view.cut[1] == b.view.cut[1]);
        CHECK(a.bodies.size() == b.bodies.size());
        for (size_t i = 0; i < a.bodies.size(); ++i)
        {
            CHECK(a.bodies[i].outline == b.bodies[i].outline);
        }
        ++scenes;
    }
    CHECK(scenes >= 8);
}

TEST_CASE("SaveScene replaces the file atomically and reports failures with the file name", "[scene]")
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "satviz-save-test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const SceneResult loaded = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    REQUIRE(loaded.Ok());
    std::string error;
    const std::string file = (dir / "scene.json").string();
    REQUIRE(SaveScene(loaded.scene, file, error));
    REQUIRE(LoadScene(file).Ok());
    for (const auto& entry : std::filesystem::directory_iterator(dir))
    {
        CHECK(entry.path().filename() == "scene.json"); // no temporary file left
    }
    CHECK(!SaveScene(loaded.scene, (dir / "missing" / "scene.json").string(), error));
    CHECK(error.find((dir / "missing" / "scene.json").string() + ": cannot write") == 0);
    std::filesystem::remove_all(dir);
}

TEST_CASE("Errors stay on one line whatever the input holds", "[scene]")
{
    const std::string error = ErrorOf("{\"bodies\": [], \"vi\\nyew\": 1}");
    CHECK(error.find('\n') == std::string::npos);
    CHECK(error == "s.json: vi\\nyew: unknown field \"vi\\nyew\" (did you mean \"view\"?)");
    CHECK(ErrorOf("{\"bodies\": [{\"name\": \"a\\tb\", \"box\": [1, 1]}, {\"name\": \"a\\tb\", \"box\": [1, 1]}]}")
              .find('\t') == std::string::npos);
}

TEST_CASE("Zoom and center beyond the accepted range are refused with the field named", "[scene]")
{
    const std::string two = R"({"bodies": [{"name": "P", "box": [1, 1]}, {"name": "Q", "box": [1, 1]}], "view": )";
    CHECK(ErrorOf(two + R"({"zoom": 0}})") == "s.json: view.zoom: must be greater than 0");
    CHECK(ErrorOf(two + R"({"zoom": 5e-10, "center": [0, 0]}})") ==
          "s.json: view.zoom: expected pixels per world unit from 1e-9 to 1e12, or \"fit\"");
    CHECK(ErrorOf(two + R"({"zoom": 10, "center": [0, -2e12]}})") == "s.json: view.center[1]: magnitude exceeds 1e+12");
    const SceneResult edge = ParseScene(two + R"({"zoom": 1e-9, "center": [1e12, 0]}})", "s.json");
    REQUIRE(edge.Ok());
    CHECK(edge.scene.view.zoom == kMinViewZoom);
}

TEST_CASE("Saving a loaded scene keeps the file's form: $schema, shorthands, key order, numbers", "[scene]")
{
    const std::string file = R"({
  "bodies": [
    {"box": [2, 1], "name": "A", "tool:color": "red"},
    {"name": "B", "regular": {"radius": 0.5, "sides": 7, "tool:note": 1}, "angle": 0, "position": [1.5, 0]},
    {"polygon": [[0, 0], [1, 0], [0, 1]], "velocity": [0.25, 0]},
    {"name": "D", "circle": {"center": [0, 1], "radius": 2}}
  ],
  "$schema": "../schema/scene.schema.json",
  "view": {"size": [640, 480], "zoom": "fit", "x:y": true},
  "description": "form"
})";
    const SceneResult loaded = ParseScene(file, "dir/form.json");
    INFO(loaded.error);
    REQUIRE(loaded.Ok());
    // Unchanged: the same keys in the same order, the same numbers as written, one body per line.
    const std::string same = R"({
  "bodies": [
    {"box":[2,1],"name":"A","tool:color":"red"},
    {"name":"B","regular":{"radius":0.5,"sides":7,"tool:note":1},"angle":0,"position":[1.5,0]},
    {"polygon":[[0,0],[1,0],[0,1]],"velocity":[0.25,0]},
    {"name":"D","circle":{"center":[0,1],"radius":2}}
  ],
  "$schema": "../schema/scene.schema.json",
  "view": {"size":[640,480],"zoom":"fit","x:y":true},
  "description": "form"
}
)";
    CHECK(SceneToJson(loaded.scene) == same);

    // Edited: a moved box stays a box; a reshaped regular polygon becomes vertices in its place; new fields are
    // added after the file's own; an unnamed body that keeps its default name stays unnamed.
    Scene edited = loaded.scene;
    edited.bodies[0].position = {0.5, -1};
    std::vector<Vec2> points(edited.bodies[1].shape.polygon.Vertices().begin(),
                             edited.bodies[1].shape.polygon.Vertices().end());
    points[0] = 1.5 * points[0];
    const PolygonResult reshaped = MakePolygon(points);
    REQUIRE(reshaped.Ok());
    edited.bodies[1].shape = MakeShape(reshaped.polygon);
    edited.bodies[3].shape.circle.radius = 2.5;
    edited.view.fit = false;
    edited.view.center = {1, 2};
    edited.view.zoom = 40;
    edited.view.step = 3;
    const std::string text = SceneToJson(edited);
    const SceneResult again = ParseScene(text, "again.json");
    INFO(text);
    REQUIRE(again.Ok());
    const nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
    CHECK(json.begin().key() == "bodies");
    CHECK(json["$schema"] == "../schema/scene.schema.json");
    CHECK(json["bodies"][0].dump() == R"({"box":[2,1],"name":"A","tool:color":"red","position":[0.5,-1.0]})");
    const nlohmann::ordered_json& b = json["bodies"][1];
    CHECK(!b.contains("regular"));
    REQUIRE(b.contains("polygon"));
    CHECK(std::next(b.begin()).key() == "polygon");
    CHECK(b["polygon"].size() == 7);
    CHECK(again.scene.bodies[1].shape.polygon.Vertices()[0] == reshaped.polygon.Vertices()[0]);
    CHECK(json["bodies"][2].dump() == R"({"polygon":[[0,0],[1,0],[0,1]],"velocity":[0.25,0]})");
    CHECK(json["bodies"][3].dump() == R"({"name":"D","circle":{"center":[0,1],"radius":2.5}})");
    CHECK(json["view"].dump() == R"({"size":[640,480],"zoom":40.0,"x:y":true,"center":[1.0,2.0],"step":4})");
    CHECK(again.scene.view.center == Vec2{1, 2});
    CHECK(again.scene.bodies[0].position == Vec2{0.5, -1});

    // A renamed body has no fields of the file: its shape is written as vertices, its zero position left out.
    edited.bodies[2].name = "E";
    CHECK(nlohmann::ordered_json::parse(SceneToJson(edited))["bodies"][2].dump() ==
          R"({"name":"E","polygon":[[0.0,0.0],[1.0,0.0],[0.0,1.0]],"velocity":[0.25,0.0]})");
}

TEST_CASE("Every bundled scene saves back to the same JSON, key for key and number for number", "[scene]")
{
    int scenes = 0;
    SceneOptions concave;
    concave.concave = true;
    for (const std::string& scenePath : testing::TutorialSceneFiles(true))
    {
        const SceneResult original = LoadScene(scenePath, concave);
        REQUIRE(original.Ok());
        std::ifstream in(scenePath);
        const nlohmann::ordered_json file = nlohmann::ordered_json::parse(in);
        const std::string saved = SceneToJson(original.scene);
        INFO(scenePath << "\n" << saved);
        CHECK(nlohmann::ordered_json::parse(saved).dump() == file.dump());
        // Saving the saved file changes nothing.
        CHECK(SceneToJson(ParseScene(saved, "saved.json", concave).scene) == saved);
        ++scenes;
    }
    CHECK(scenes >= 8);
}

TEST_CASE("SaveScene points a relative $schema at the same schema from the new folder", "[scene]")
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "satviz-schema-test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "deeper");
    const SceneResult loaded = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/overlapping_boxes.json");
    REQUIRE(loaded.Ok());
    std::string error;
    const std::string file = (dir / "deeper" / "scene.json").string();
    REQUIRE(SaveScene(loaded.scene, file, error));
    std::ifstream in(file);
    const nlohmann::ordered_json saved = nlohmann::ordered_json::parse(in);
    const std::filesystem::path schema = saved["$schema"].get<std::string>();
    CHECK(schema.is_relative());
    CHECK(std::filesystem::equivalent(dir / "deeper" / schema,
                                      std::string(SATVIZ_SOURCE_DIR) + "/core/scene/scene.schema.json"));
    CHECK(saved["bodies"][0]["box"].dump() == "[2.0,1.0]");
    // Saved again where it now is, the path stays.
    const SceneResult reloaded = LoadScene(file);
    REQUIRE(reloaded.Ok());
    REQUIRE(SaveScene(reloaded.scene, file, error));
    std::ifstream again(file);
    CHECK(nlohmann::ordered_json::parse(again)["$schema"] == saved["$schema"]);
    std::filesystem::remove_all(dir);
}

TEST_CASE("A scene body's physical fields and the world block load, with their defaults", "[scene][world]")
{
    const SceneResult r = ParseScene(R"({"bodies": [
          {"name": "ground", "box": [10, 1], "static": true, "friction": 0.8},
          {"name": "ball", "circle": {"radius": 0.5}, "position": [0, 3], "velocity": [1, -2],
           "angular_velocity": -0.75, "density": 2.5, "restitution": 0.9, "friction": 0.2, "static_friction": 0.3},
          {"name": "plain", "box": [1, 1]}],
        "world": {"gravity": [0, -9.81], "dt": 0.0166666}})",
                                     "s.json");
    INFO(r.error);
    REQUIRE(r.Ok());
    const Body& ground = r.scene.bodies[0];
    CHECK(ground.isStatic);
    CHECK(ground.density == 1.0);
    CHECK(ground.material.friction == 0.8);
    CHECK(ground.material.staticFriction == 0.8); // static friction defaults to the body's friction
    CHECK(ground.material.restitution == 0.0);
    const Body& ball = r.scene.bodies[1];
    CHECK(!ball.isStatic);
    CHECK(ball.velocity == Vec2{1, -2});
    CHECK(ball.angularVelocity == -0.75);
    CHECK(ball.density == 2.5);
    CHECK(ball.material.restitution == 0.9);
    CHECK(ball.material.friction == 0.2);
    CHECK(ball.material.staticFriction == 0.3);
    const Body& plain = r.scene.bodies[2];
    CHECK(!plain.isStatic);
    CHECK(plain.angularVelocity == 0.0);
    CHECK(plain.density == 1.0);
    CHECK(plain.material.restitution == 0.0);
    CHECK(plain.material.friction == 0.5);
    CHECK(plain.material.staticFriction == 0.5);
    CHECK(r.scene.hasWorld);
    CHECK(r.scene.world.gravity == Vec2{0, -9.81});
    CHECK(r.scene.world.dt == 0.0166666);

    // Without a world block: no gravity, and a step of 1, so a velocity is still the displacement over one step.
    const SceneResult none = ParseScene(R"({"bodies": []})", "s.json");
    REQUIRE(none.Ok());
    CHECK(!none.scene.hasWorld);
    CHECK(none.scene.world.gravity == Vec2{});
    CHECK(none.scene.world.dt == 1.0);
    const SceneResult partial = ParseScene(R"({"bodies": [], "world": {"dt": 0.5}})", "s.json");
    REQUIRE(partial.Ok());
    CHECK(partial.scene.hasWorld);
    CHECK(partial.scene.world.gravity == Vec2{});
    CHECK(partial.scene.world.dt == 0.5);
    // A static body may give a density, which it ignores; the edges of the ranges are accepted.
    CHECK(ParseScene(R"({"bodies": [{"box": [1, 1], "static": true, "density": 3}]})", "s.json").Ok());
    CHECK(ParseScene(R"({"bodies": [{"box": [1, 1], "static": false, "restitution": 1, "friction": 0,
        "static_friction": 0}]})",
                     "s.json")
              .Ok());
}

TEST_CASE("Scene errors in the physical fields and the world block name the file and the field", "[scene][world]")
{
    const std::string body = R"({"bodies": [{"name": "P", "box": [1, 1]}, {"name": "Q", "box": [1, 1], )";
    CHECK(ErrorOf(body + R"("density": 0}]})") == "s.json: bodies[1].density: must be greater than 0");
    CHECK(ErrorOf(body + R"("density": -2}]})") == "s.json: bodies[1].density: must be greater than 0");
    CHECK(ErrorOf(body + R"("static": true, "density": 0}]})") == "s.json: bodies[1].density: must be greater than 0");
    CHECK(ErrorOf(body + R"("static": true, "density": 2e12}]})") ==
          "s.json: bodies[1].density: magnitude exceeds 1e+12");
    CHECK(ErrorOf(body + R"("density": "heavy"}]})") == "s.json: bodies[1].density: expected a number, got a string");
    CHECK(ErrorOf(body + R"("restitution": -0.1}]})") ==
          "s.json: bodies[1].restitution: expected a restitution in [0, 1] (0: no bounce, 1: a perfectly elastic one)");
    CHECK(ErrorOf(body + R"("restitution": 1.5}]})") ==
          "s.json: bodies[1].restitution: expected a restitution in [0, 1] (0: no bounce, 1: a perfectly elastic one)");
    CHECK(ErrorOf(body + R"("friction": -0.5}]})") == "s.json: bodies[1].friction: must be 0 or greater");
    CHECK(ErrorOf(body + R"("friction": 1e13}]})") == "s.json: bodies[1].friction: magnitude exceeds 1e+12");
    CHECK(ErrorOf(body + R"("static_friction": -1}]})") == "s.json: bodies[1].static_friction: must be 0 or greater");
    CHECK(ErrorOf(body + R"("static_friction": null}]})") ==
          "s.json: bodies[1].static_friction: expected a number, got null");
    CHECK(ErrorOf(body + R"("angular_velocity": 2e12}]})") ==
          "s.json: bodies[1].angular_velocity: magnitude exceeds 1e+12");
    CHECK(ErrorOf(body + R"("angular_velocity": [1]}]})") ==
          "s.json: bodies[1].angular_velocity: expected a number, got an array");
    CHECK(ErrorOf(body + R"("static": 1}]})") == "s.json: bodies[1].static: expected true or false, got a number");
    CHECK(ErrorOf(body + R"("static": "yes"}]})") == "s.json: bodies[1].static: expected true or false, got a string");
    CHECK(ErrorOf(body + R"("statik": true}]})") ==
          "s.json: bodies[1].statik: unknown field \"statik\" (did you mean \"static\"?)");
    CHECK(ErrorOf(body + R"("angular_velocity": 1e400}]})").find("malformed JSON: number overflow") !=
          std::string::npos);

    const std::string two = R"({"bodies": [{"name": "P", "box": [1, 1]}], "world": )";
    CHECK(ErrorOf(two + R"({"dt": 0}})") == "s.json: world.dt: must be greater than 0");
    CHECK(ErrorOf(two + R"({"dt": -0.01}})") == "s.json: world.dt: must be greater than 0");
    CHECK(ErrorOf(two + R"({"dt": 1e13}})") == "s.json: world.dt: magnitude exceeds 1e+12");
    CHECK(ErrorOf(two + R"({"dt": "fast"}})") == "s.json: world.dt: expected a number, got a string");
    CHECK(ErrorOf(two + R"({"gravity": [0, -2e12]}})") == "s.json: world.gravity[1]: magnitude exceeds 1e+12");
    CHECK(ErrorOf(two + R"({"gravity": [0]}})") ==
          "s.json: world.gravity: expected a pair of numbers [x, y], got an array of 1");
    CHECK(ErrorOf(two + R"({"gravity": [0, null]}})") == "s.json: world.gravity[1]: expected a number, got null");
    CHECK(ErrorOf(two + R"({"gravty": [0, -1]}})") ==
          "s.json: world.gravty: unknown field \"gravty\" (did you mean \"gravity\"?)");
    CHECK(ErrorOf(two + R"([0, -9.81]})") ==
          "s.json: world: expected an object {\"gravity\": [x, y], \"dt\": s}, got an array");
    CHECK(ErrorOf(two + R"({"gravity": [0, -1], "dt": 0.5, "sim:substeps": 4}})").empty());
}

TEST_CASE("A scene's physical fields and world block save and load back, absent ones staying absent", "[scene][world]")
{
    const std::string file = R"({
  "world": {"dt": 0.5, "sim:note": "kept"},
  "bodies": [
    {"name": "ground", "box": [10, 1], "static": true},
    {"name": "ball", "circle": {"radius": 0.5}, "position": [0, 3], "friction": 0.25, "restitution": 0.5},
    {"name": "crate", "box": [1, 1], "static": false, "density": 1, "static_friction": 0.5, "angular_velocity": 0}
  ]
})";
    const SceneResult loaded = ParseScene(file, "phys.json");
    INFO(loaded.error);
    REQUIRE(loaded.Ok());
    // Unchanged: the file's fields as written, in its order; nothing added.
    const std::string same = R"({
  "world": {"dt":0.5,"sim:note":"kept"},
  "bodies": [
    {"name":"ground","box":[10,1],"static":true},
    {"name":"ball","circle":{"radius":0.5},"position":[0,3],"friction":0.25,"restitution":0.5},
    {"name":"crate","box":[1,1],"static":false,"density":1,"static_friction":0.5,"angular_velocity":0}
  ]
}
)";
    CHECK(SceneToJson(loaded.scene) == same);
    // A world hands back -0 for a body that stopped turning: still the default, not a new field.
    Scene stopped = loaded.scene;
    stopped.bodies[0].angularVelocity = -0.0;
    CHECK(SceneToJson(stopped) == same);

    // Edited: a changed field is written in its place, a field changed from its default is added after the file's
    // own, a static friction that no longer equals the friction is written.
    Scene edited = loaded.scene;
    edited.bodies[0].isStatic = false;
    edited.bodies[1].angularVelocity = -1.25;
    edited.bodies[1].material.friction = 0.75; // its static friction stays 0.25
    edited.bodies[2].density = 3;
    edited.world.gravity = {0, -9.81};
    const std::string text = SceneToJson(edited);
    INFO(text);
    const nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
    CHECK(json["world"].dump() == R"({"dt":0.5,"sim:note":"kept","gravity":[0.0,-9.81]})");
    CHECK(json["bodies"][0].dump() == R"({"name":"ground","box":[10,1],"static":false})");
    CHECK(json["bodies"][1].dump() == R"({"name":"ball","circle":{"radius":0.5},"position":[0,3],"friction":0.75,)"
                                      R"("restitution":0.5,"angular_velocity":-1.25,"static_friction":0.25})");
    CHECK(json["bodies"][2].dump() ==
          R"({"name":"crate","box":[1,1],"static":false,"density":3.0,"static_friction":0.5,"angular_velocity":0})");
    const SceneResult again = ParseScene(text, "again.json");
    REQUIRE(again.Ok());
    for (size_t i = 0; i < edited.bodies.size(); ++i)
    {
        const Body& x = edited.bodies[i];
        const Body& y = again.scene.bodies[i];
        CHECK(x.isStatic == y.isStatic);
        CHECK(x.density == y.density);
        CHECK(x.angularVelocity == y.angularVelocity);
        CHECK(x.material.restitution == y.material.restitution);
        CHECK(x.material.friction == y.material.friction);
        CHECK(x.material.staticFriction == y.material.staticFriction);
    }
    CHECK(again.scene.world.gravity == Vec2{0, -9.81});
    CHECK(again.scene.world.dt == 0.5);

    // A scene built in code writes only what differs from the defaults, and its world block whole.
    Scene built;
    Body body;
    body.name = "A";
    body.shape = MakeShape(Circle{{0, 0}, 1});
    built.bodies.push_back(body);
    body.name = "B";
    body.isStatic = true;
    body.material = {0.25, 0.125, 0.5};
    body.angularVelocity = 2;
    built.bodies.push_back(body);
    CHECK(SceneToJson(built).find("world") == std::string::npos);
    built.hasWorld = true;
    const std::string builtText = SceneToJson(built);
    INFO(builtText);
    const nlohmann::ordered_json builtJson = nlohmann::ordered_json::parse(builtText);
    CHECK(builtJson["bodies"][0].dump() == R"({"name":"A","circle":{"radius":1.0},"position":[0.0,0.0]})");
    CHECK(builtJson["bodies"][1].dump() ==
          R"({"name":"B","circle":{"radius":1.0},"position":[0.0,0.0],"angular_velocity":2.0,"static":true,)"
          R"("restitution":0.25,"friction":0.125,"static_friction":0.5})");
    CHECK(builtJson["world"].dump() == R"({"gravity":[0.0,0.0],"dt":1.0})");
    const SceneResult builtAgain = ParseScene(builtText, "built.json");
    REQUIRE(builtAgain.Ok());
    CHECK(builtAgain.scene.bodies[1].material.staticFriction == 0.5);
    CHECK(builtAgain.scene.bodies[1].isStatic);

    // A file that had a world block and a scene that dropped it: the block goes.
    Scene dropped = loaded.scene;
    dropped.hasWorld = false;
    dropped.world = SceneWorld{};
    CHECK(nlohmann::ordered_json::parse(SceneToJson(dropped)).count("world") == 0);
}

TEST_CASE("Saving a scene with NaN or infinite values built in code does not crash, and the result is refused",
          "[scene][world]")
{
    Scene scene;
    Body body;
    body.name = "A";
    body.shape = MakeShape(Circle{{0, 0}, 1});
    body.angularVelocity = std::numeric_limits<double>::quiet_NaN();
    body.material.friction = std::numeric_limits<double>::infinity();
    scene.bodies.push_back(body);
    scene.world.dt = std::numeric_limits<double>::quiet_NaN();
    const std::string text = SceneToJson(scene);
    const SceneResult r = ParseScene(text, "nan.json");
    CHECK(!r.Ok());
    CHECK(r.error == "nan.json: bodies[0].angular_velocity: expected a number, got null");
}

TEST_CASE("A concave polygon is decomposed on load when the reader takes concave bodies", "[scene][concave]")
{
    const std::string text =
        R"({"bodies": [{"name": "L", "polygon": [[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]], "decompose": "fewest"},
                       {"name": "W", "polygon": [[0,4],[1,4],[1,1],[4,1],[4,0],[0,0]]},
                       {"name": "T", "polygon": [[0,0],[1,0],[0,1]], "decompose": "fast"}]})";
    // Without the option, as before: refused as not convex.
    const SceneResult plain = ParseScene(text, "s.json");
    CHECK(plain.error == "s.json: bodies[0].polygon: polygon is not convex at vertex 3 (use a convex decomposition)");
    SceneOptions options;
    options.concave = true;
    const SceneResult r = ParseScene(text, "s.json", options);
    REQUIRE(r.Ok());
    const Body& ell = r.scene.bodies[0];
    REQUIRE(ell.IsConcave());
    CHECK(ell.decompose == DecomposeMethod::Fewest);
    CHECK(ell.concave.parts.size() == 2);
    CHECK(ell.outline.size() == 6);
    // The hull stands in as the shape: the L's outer corners.
    CHECK(ell.shape.polygon.Count() == 5);
    // Clockwise is accepted for a concave outline, and the decomposition is the same L's.
    CHECK(r.scene.bodies[1].IsConcave());
    CHECK(r.scene.bodies[1].concave.parts.size() == 2);
    // A convex polygon stays a plain polygon.
    CHECK(!r.scene.bodies[2].IsConcave());
    CHECK(r.scene.bodies[2].shape.polygon.Count() == 3);

    auto errorOf = [&](const std::string& body) {
        return ParseScene(R"({"bodies": [)" + body + "]}", "s.json", options).error;
    };
    CHECK(errorOf(R"({"polygon": [[0,0],[2,0],[0,2],[2,2]]})") ==
          "s.json: bodies[0].polygon: polygon is not simple: edge 1 (vertex 1 to 2) meets edge 3 (vertex 3 to 0)");
    CHECK(errorOf(R"({"polygon": [[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]], "decompose": "best"})") ==
          "s.json: bodies[0].decompose: expected \"fast\" or \"fewest\", got \"best\"");
    CHECK(errorOf(R"({"polygon": [[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]], "decompose": 2})") ==
          "s.json: bodies[0].decompose: expected \"fast\" or \"fewest\", got a number");
    CHECK(errorOf(R"({"box": [1, 1], "decompose": "fast"})") ==
          "s.json: bodies[0].decompose: applies to a \"polygon\" only");
    // A convex outline written clockwise keeps its own error: one piece is not a concave body.
    CHECK(errorOf(R"({"polygon": [[0,0],[0,1],[1,0]]})") ==
          "s.json: bodies[0].polygon: polygon winds clockwise (list the vertices counter-clockwise, y up)");
}

TEST_CASE("A floor written with the ends of its tiles along its top loads as one piece, its outline as written",
          "[scene][concave]")
{
    // Three tiles 1 wide, written as one outline whose top keeps the tiles' ends: vertices on the line through
    // their neighbours. Refused as a convex polygon (MakePolygon's rule); read as an outline, it is one convex piece
    // whose straight vertices are corners of no piece, and the file keeps them.
    const std::string text =
        R"({"bodies": [{"name": "floor", "polygon": [[0, 0], [3, 0], [3, 1], [2, 1], [1, 1], [0, 1]], "static": true},
                       {"name": "box", "box": [0.8, 0.8], "position": [1.0, 1.3]}]})";
    CHECK(ParseScene(text, "s.json").error ==
          "s.json: bodies[0].polygon: vertex 3 lies on the line through its neighbours (remove it)");
    SceneOptions options;
    options.concave = true;
    const SceneResult r = ParseScene(text, "s.json", options);
    REQUIRE(r.Ok());
    const Body& floor = r.scene.bodies[0];
    REQUIRE(floor.IsConcave());
    CHECK(floor.concave.parts.size() == 1);
    CHECK(floor.concave.parts[0].shape.polygon.Count() == 4);
    CHECK(floor.outline.size() == 6);
    // Written back as read, and read again the same.
    const std::string saved = SceneToJson(r.scene);
    CHECK(nlohmann::json::parse(saved)["bodies"][0]["polygon"] ==
          nlohmann::json::parse("[[0, 0], [3, 0], [3, 1], [2, 1], [1, 1], [0, 1]]"));
    const SceneResult again = ParseScene(saved, "saved.json", options);
    REQUIRE(again.Ok());
    CHECK(SceneToJson(again.scene) == saved);
    // The box straddling the tiles' end at x = 1 meets the floor's top, as it meets the rectangle without them:
    // no seam there to catch on.
    const SceneResult rectangle = ParseScene(
        R"({"bodies": [{"name": "floor", "polygon": [[0, 0], [3, 0], [3, 1], [0, 1]], "static": true},
                       {"name": "box", "box": [0.8, 0.8], "position": [1.0, 1.3]}]})",
        "r.json");
    REQUIRE(rectangle.Ok());
    const Body& box = r.scene.bodies[1];
    const ConcaveManifold m = Collide(floor.concave, floor.Xf(), box.shape, box.Xf());
    const Manifold plain = Collide(rectangle.scene.bodies[0].shape, rectangle.scene.bodies[0].Xf(), box.shape,
                                   box.Xf());
    REQUIRE(m.manifold.overlap);
    CHECK(m.manifold.depth == plain.depth);
    CHECK(m.manifold.normal == plain.normal);
    CHECK(m.manifold.contactCount == plain.contactCount);
    // A repeated vertex is read the same way.
    const SceneResult repeated = ParseScene(
        R"({"bodies": [{"polygon": [[0, 0], [3, 0], [3, 1], [3, 1], [0, 1]]}]})", "s.json", options);
    REQUIRE(repeated.Ok());
    CHECK(repeated.scene.bodies[0].concave.parts.size() == 1);
}
