// SPDX-License-Identifier: MIT
// Fuzz target for the scene loader: any bytes as a scene file. Malformed input must give a one-line error that
// names the file; a scene that loads must write out and read back to the same JSON, and its pairs must answer.
// Read as satviz-query reads it (a polygon may be concave), it must answer as satviz-query does, a slice's cut too.
#include <satviz/collide.h>
#include <satviz/query_json.h>
#include <satviz/scene.h>
#include <satviz/sweep.h>

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    const satviz::SceneResult concave = satviz::ParseScene(text, "fuzz.json", satviz::SceneOptions{true});
    if (concave.Ok())
    {
        satviz::QuerySceneJson(concave.scene, "fuzz.json", false).dump();
    }
    else if (concave.error.rfind("fuzz.json", 0) != 0 || concave.error.find('\n') != std::string::npos)
    {
        std::abort();
    }
    const satviz::SceneResult result = satviz::ParseScene(text, "fuzz.json");
    if (!result.Ok())
    {
        if (result.error.rfind("fuzz.json", 0) != 0 || result.error.find('\n') != std::string::npos)
        {
            std::abort(); // errors are one line and name the file
        }
        return 0;
    }
    const std::string saved = satviz::SceneToJson(result.scene);
    const satviz::SceneResult again = satviz::ParseScene(saved, "saved.json");
    if (!again.Ok() || satviz::SceneToJson(again.scene) != saved)
    {
        std::abort(); // a loaded scene round-trips
    }
    if (!concave.Ok())
    {
        std::abort(); // a scene that loads as convex loads as concave
    }
    const auto& bodies = result.scene.bodies;
    for (size_t i = 0; i < bodies.size() && i < 6; ++i)
    {
        for (size_t j = i + 1; j < bodies.size() && j < 6; ++j)
        {
            const satviz::Manifold m =
                satviz::Collide(bodies[i].shape, bodies[i].Xf(), bodies[j].shape, bodies[j].Xf());
            const bool overlap = satviz::Overlap(bodies[i].shape, bodies[i].Xf(), bodies[j].shape, bodies[j].Xf());
            if (m.overlap != overlap)
            {
                std::abort();
            }
            satviz::Sweep(bodies[i].shape, bodies[i].Xf(), bodies[i].velocity, bodies[j].shape, bodies[j].Xf(),
                          bodies[j].velocity);
        }
    }
    return 0;
}
