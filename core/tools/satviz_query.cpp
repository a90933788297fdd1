// SPDX-License-Identifier: MIT
// satviz-query: answers every pair of bodies of each scene file with one JSON line (or, with --touching, lists the
// pairs that touch). No graphics.

#include <satviz/query_json.h>
#include <satviz/scene.h>

#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

// Names and messages quote the input, which may hold bytes that are not UTF-8: print them replaced, never throw.
constexpr auto kReplace = nlohmann::ordered_json::error_handler_t::replace;

int main(int argc, char** argv)
{
    CLI::App app{"Collide every pair of bodies of each scene file; print one JSON line per file."};
    app.set_version_flag("--version", std::string("satviz-query ") + SATVIZ_VERSION);
    std::vector<std::string> files;
    bool withTrace = false;
    app.add_option("files", files, "Scene files (JSON)")->required();
    std::string view = "textbook";
    app.add_flag("--trace", withTrace,
                 "Add the step trace of each pair (its \"view\" field says which): by default the textbook test's "
                 "axes and intervals");
    app.add_option("--view", view,
                   "The trace to print: textbook (both intervals on each distinct axis, the MTV) or faces (the face "
                   "tests as the fast queries run them, with the contact clipping)")
        ->check(CLI::IsMember({"textbook", "faces"}));
    bool touching = false;
    app.add_flag("--touching", touching,
                 "Only list the pairs of bodies that touch or overlap, found through the broadphase: "
                 "{\"scene\", \"touching\": [[\"A\", \"B\"], ...], \"bodies\"}, fast for many bodies")
        ->excludes("--trace");
    CLI11_PARSE(app, argc, argv);
    const satviz::StepView steps = view == "faces" ? satviz::StepView::Faces : satviz::StepView::Textbook;

    int failures = 0;
    for (const std::string& file : files)
    {
        // A polygon may be concave here: it is answered piece by piece.
        satviz::SceneOptions options;
        options.concave = true;
        const satviz::SceneResult loaded = satviz::LoadScene(file, options);
        if (!loaded.Ok())
        {
            std::cerr << "satviz-query: " << loaded.error << "\n";
            std::cout << nlohmann::ordered_json{{"scene", file}, {"error", loaded.error}}.dump(-1, ' ', false, kReplace)
                      << "\n";
            ++failures;
            continue;
        }
        const nlohmann::ordered_json answer =
            touching ? satviz::TouchingSceneJson(loaded.scene, file)
                     : satviz::QuerySceneJson(loaded.scene, file, withTrace, steps, &std::cerr);
        std::cout << answer.dump(-1, ' ', false, kReplace) << "\n";
    }
    std::cout.flush();
    return failures == 0 ? 0 : 1;
}
