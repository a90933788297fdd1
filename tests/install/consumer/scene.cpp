// SPDX-License-Identifier: MIT
// A program built against the installed satviz (satviz::scene, with nlohmann_json found by the package): loads an
// installed scene and tests its first two bodies. Usage: consumer_scene SCENE.json (the scene must overlap).
#include <satviz/sat.h>
#include <satviz/scene.h>

#include <cstdio>

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: consumer_scene SCENE.json\n");
        return 2;
    }
    const satviz::SceneResult result = satviz::LoadScene(argv[1]);
    if (!result.Ok() || result.scene.bodies.size() < 2)
    {
        std::fprintf(stderr, "consumer_scene: %s\n", result.Ok() ? "fewer than two bodies" : result.error.c_str());
        return 1;
    }
    const satviz::Body& a = result.scene.bodies[0];
    const satviz::Body& b = result.scene.bodies[1];
    const bool hit = satviz::Overlap(a.shape, a.Xf(), b.shape, b.Xf());
    std::printf("consumer_scene: %s and %s %s\n", a.name.c_str(), b.name.c_str(), hit ? "overlap" : "do not overlap");
    return hit ? 0 : 1;
}
