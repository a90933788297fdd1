// SPDX-License-Identifier: MIT
// satviz-render: scene files to PNG figures, headless. OSMesa (software OpenGL, no display) renders the painter's
// ImGui draw lists through the ImGui OpenGL2 backend; stb_image_write encodes the PNG. This program links OSMesa
// and never libGL: the app, which draws in a window, is a separate executable.
#include <satviz/render/atomic_file.h>
#include <satviz/render/describe.h>
#include <satviz/render/figure.h>
#include <satviz/render/figure_drawing.h>
#include <satviz/render/imgui_canvas.h>
#include <satviz/layers.h>
#include <satviz/render/png_file.h>
#include <satviz/render/svg_canvas.h>
#include <satviz/scene.h>
#include <satviz/scene_world.h>
#include <satviz/sim_record.h>

#include <CLI/CLI.hpp>
#include <GL/osmesa.h>
#include <imgui.h>

#include <algorithm>
#include <backends/imgui_impl_opengl2.h>
#include <cctype>
#include <cfloat>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace
{

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d)
{
    return std::chrono::duration<double>(d).count();
}

/// One OSMesa context and one ImGui context, shared by every figure of the run.
class HeadlessRenderer
{
  public:
    ~HeadlessRenderer()
    {
        if (m_imgui != nullptr)
        {
            ImGui_ImplOpenGL2_Shutdown();
            ImGui::DestroyContext(m_imgui);
        }
        if (m_context != nullptr)
        {
            OSMesaDestroyContext(m_context);
        }
    }

    bool Init(std::string& error)
    {
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  0,
                                  OSMESA_STENCIL_BITS,
                                  0,
                                  OSMESA_PROFILE,
                                  OSMESA_COMPAT_PROFILE,
                                  0};
        m_context = OSMesaCreateContextAttribs(attributes, nullptr);
        if (m_context == nullptr)
        {
            error = "OSMesa: cannot create an OpenGL context";
            return false;
        }
        if (!Resize(64, 64))
        {
            error = "OSMesa: cannot make the context current";
            return false;
        }
        IMGUI_CHECKVERSION();
        m_imgui = ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.LogFilename = nullptr;
        io.DeltaTime = 1.0f / 60.0f;
        if (!satviz::AddFigureFonts(*io.Fonts, m_fonts, error))
        {
            return false;
        }
        // Built now, so that SVG figures can measure text before any PNG is drawn.
        io.Fonts->Build();
        if (!ImGui_ImplOpenGL2_Init())
        {
            error = "ImGui: the OpenGL2 backend did not initialise";
            return false;
        }
        return true;
    }

    /// Paints one figure and reads it back as RGB rows, bottom row first (the same drawing as the app's export).
    bool Render(const satviz::Scene& scene, const satviz::FigureSetup& setup, std::vector<unsigned char>& rgb,
                std::string& error)
    {
        const int width = setup.figure.view.width;
        const int height = setup.figure.view.height;
        if ((width != m_width || height != m_height) && !Resize(width, height))
        {
            error = "OSMesa: cannot resize the frame buffer";
            return false;
        }
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
        ImGui_ImplOpenGL2_NewFrame();
        ImGui::NewFrame();
        satviz::FigureDrawing drawing(scene, setup.study, setup.figure, m_fonts);
        ImGui::Render();
        glViewport(0, 0, width, height);
        glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL2_RenderDrawData(drawing.DrawData());
        glFinish();
        rgb.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        return true;
    }

    /// Paints one figure as an SVG document, its text measured by the figure fonts (the PNG's layout).
    std::string RenderSvg(const satviz::Scene& scene, const satviz::FigureSetup& setup) const
    {
        const satviz::FigureFonts fonts = m_fonts;
        satviz::SvgCanvas canvas(
            setup.figure.view.width, setup.figure.view.height, [fonts](std::string_view text, satviz::TextStyle style) {
                ImFont* font = style == satviz::TextStyle::Label
                                   ? fonts.label
                                   : (style == satviz::TextStyle::Heading ? fonts.heading : fonts.body);
                const ImVec2 size =
                    font->CalcTextSizeA(font->FontSize, FLT_MAX, 0.0f, text.data(), text.data() + text.size());
                return satviz::ScreenPoint{size.x, size.y};
            });
        satviz::PaintFigure(canvas, scene, setup.study, setup.figure);
        return canvas.Document();
    }

  private:
    bool Resize(int width, int height)
    {
        m_buffer.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * 4, 0);
        if (!OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, width, height))
        {
            return false;
        }
        m_width = width;
        m_height = height;
        return true;
    }

    OSMesaContext m_context = nullptr;
    ImGuiContext* m_imgui = nullptr;
    satviz::FigureFonts m_fonts;
    std::vector<unsigned char> m_buffer;
    int m_width = 0;
    int m_height = 0;
};

// Pairs with more vertices than this (both shapes together) get a progress line while they are traced.
constexpr size_t kSlowTrace = 4096;

struct Job
{
    std::string scene;
    int step = -1; // -1: the scene's own choice
    std::string output;
};

/// A step of a strip, zero-padded to the digits of the last, so that the files sort in step order.
std::string StepNumber(int step, int last)
{
    const std::string digits = std::to_string(step);
    return std::string(std::to_string(last).size() - digits.size(), '0') + digits;
}

/// Figures in a directory: "name.png" or "name.svg".
std::string FigureName(const std::string& name, bool svg)
{
    return name + (svg ? ".svg" : ".png");
}

bool ParseSize(const std::string& text, int& width, int& height)
{
    int consumed = 0;
    if (std::sscanf(text.c_str(), "%dx%d%n", &width, &height, &consumed) != 2 ||
        consumed != static_cast<int>(text.size()))
    {
        return false;
    }
    return width >= 16 && height >= 16 && width <= satviz::kMaxViewSize && height <= satviz::kMaxViewSize;
}

bool ParseLayers(const std::string& text, satviz::LayerMask& mask, std::string& error)
{
    mask = 0;
    size_t start = 0;
    while (start <= text.size())
    {
        size_t end = text.find(',', start);
        if (end == std::string::npos)
        {
            end = text.size();
        }
        const std::string name = text.substr(start, end - start);
        if (name == "all")
        {
            mask |= satviz::kAllLayers;
        }
        else if (name == "default")
        {
            mask |= satviz::kDefaultLayers;
        }
        else if (const satviz::LayerMask layer = satviz::LayerFromName(name))
        {
            mask |= layer;
        }
        else
        {
            error = "--layers: unknown layer \"" + name + "\" (known: " + satviz::LayerNameList() + ", all, default)";
            return false;
        }
        start = end + 1;
    }
    return true;
}

/// The extension of `output` in lower case (".png", ".svg", or anything else).
std::string LowerExtension(const std::string& output)
{
    std::string extension = std::filesystem::path(output).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

/// True when `output` names one figure file rather than a directory: its extension is .png or .svg in any case.
bool IsFigureFile(const std::string& output)
{
    const std::string extension = LowerExtension(output);
    return extension == ".png" || extension == ".svg";
}

/// Figures in a directory are named after their scene file: two scenes of one file name (a/x.json and b/x.json,
/// or one file given twice) would write the same figures. Returns a one-line reason naming both, or "".
std::string SameFigureNames(const std::vector<std::string>& scenes, const std::string& output, bool allSteps, bool svg)
{
    std::map<std::string, std::string> byStem;
    for (const std::string& file : scenes)
    {
        const std::string stem = std::filesystem::path(file).stem().string();
        const auto [first, inserted] = byStem.emplace(stem, file);
        if (!inserted)
        {
            return first->second + " and " + file + " would both write " +
                   FigureName(allSteps ? stem + "-stepN" : stem, svg) + " in " + output +
                   "; figures are named after the scene file: render them to separate directories";
        }
    }
    return "";
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"satviz-render: draws scene files and each step of their SAT trace to PNG or SVG, without a display"};
    app.set_version_flag("--version", std::string("satviz-render ") + SATVIZ_VERSION);
    std::vector<std::string> scenes;
    std::string output;
    int step = -1;
    bool allSteps = false;
    std::string size;
    std::string layers;
    bool quiet = false;
    app.add_option("scenes", scenes, "Scene files (JSON)")->required();
    app.add_option("-o,--output", output,
                   "Output: a .png or .svg file (any case: .PNG too) for a single figure, its format from the "
                   "extension, else a directory (created if missing) that receives SCENE.png, or SCENE-stepN.png (N "
                   "from 1) with --all-steps, named after each scene file without its extension; two scenes of the "
                   "same file name (a/x.json, b/x.json) are refused")
        ->required();
    std::string format;
    app.add_option("--format", format,
                   "png or svg: the format of the figures written to a directory (default png); a single file's "
                   "format is its extension's. SVG keeps text as text, in the same font and layout as the PNG");
    std::string viewName;
    auto* stepOption = app.add_option(
        "--step", step, "Trace step to draw, counted from 1 (1 = the first axis; the last is the verdict)");
    app.add_option("--view", viewName,
                   "Which algorithm the steps show: textbook (both intervals on each distinct axis, the default) or "
                   "faces (the face tests as the fast queries run them); default: the scene's");
    app.add_flag("--all-steps", allSteps, "One figure per trace step")->excludes(stepOption);
    app.add_option("--size", size, "Image size WxH in pixels (default: the scene's, else 800x600)");
    app.add_option("--layers", layers, "Comma-separated layers: " + satviz::LayerNameList() + ", or all, default");
    app.add_flag("-q,--quiet", quiet, "No progress lines, only errors and the summary");
    int simSteps = 0;
    auto* simOption = app.add_option("--sim-steps", simSteps,
                                     "Step each scene's rigid-body world N times (by its world.dt) before drawing it, "
                                     "then draw the bodies where the world leaves them; default: the scene's "
                                     "view.sim_steps, else 0")
                          ->type_name("N");
    int simEvery = 0;
    auto* everyOption =
        app.add_option("--sim-every", simEvery,
                       "With --sim-steps N (or the scene's view.sim_steps): a strip of figures, one every K steps from "
                       "step 0 to N (and N), each named SCENE-simS.png with S the step, zero-padded to N's digits")
            ->type_name("K");
    CLI11_PARSE(app, argc, argv);

    satviz::FigureOptions options;
    if (stepOption->count() > 0 && step < 1)
    {
        std::fprintf(stderr, "satviz-render: --step: steps count from 1 (1 = the first axis), got %d\n", step);
        return 2;
    }
    if (simOption->count() > 0 && (simSteps < 0 || simSteps > satviz::kMaxViewSimSteps))
    {
        std::fprintf(stderr, "satviz-render: --sim-steps: expected a whole number of steps from 0 to %d, got %d\n",
                     satviz::kMaxViewSimSteps, simSteps);
        return 2;
    }
    if (everyOption->count() > 0 && (simEvery < 1 || simEvery > satviz::kMaxViewSimSteps))
    {
        std::fprintf(stderr, "satviz-render: --sim-every: expected a whole number of steps from 1 to %d, got %d\n",
                     satviz::kMaxViewSimSteps, simEvery);
        return 2;
    }
    if (!viewName.empty())
    {
        if (viewName != "textbook" && viewName != "faces")
        {
            std::fprintf(stderr, "satviz-render: --view: expected textbook or faces, got \"%s\"\n", viewName.c_str());
            return 2;
        }
        options.setSteps = true;
        options.steps = viewName == "faces" ? satviz::StepView::Faces : satviz::StepView::Textbook;
    }
    if (!size.empty() && !ParseSize(size, options.width, options.height))
    {
        std::fprintf(stderr, "satviz-render: --size: expected WxH with sides from 16 to %d, got \"%s\"\n",
                     satviz::kMaxViewSize, size.c_str());
        return 2;
    }
    if (!layers.empty())
    {
        std::string error;
        if (!ParseLayers(layers, options.layers, error))
        {
            std::fprintf(stderr, "satviz-render: %s\n", error.c_str());
            return 2;
        }
        options.setLayers = true;
    }
    const bool singleFile = IsFigureFile(output);
    if (!format.empty() && format != "png" && format != "svg")
    {
        std::fprintf(stderr, "satviz-render: --format: expected png or svg, got \"%s\"\n", format.c_str());
        return 2;
    }
    if (singleFile && !format.empty() && "." + format != LowerExtension(output))
    {
        std::fprintf(stderr,
                     "satviz-render: --format %s: the output %s says otherwise; give a directory, or a file "
                     "name ending in .%s\n",
                     format.c_str(), output.c_str(), format.c_str());
        return 2;
    }
    const bool svg = singleFile ? LowerExtension(output) == ".svg" : format == "svg";
    if (singleFile && (scenes.size() != 1 || allSteps || simEvery > 0))
    {
        std::fprintf(stderr,
                     "satviz-render: -o %s: a %s output takes exactly one figure; give a directory for "
                     "several scenes, --all-steps or --sim-every\n",
                     output.c_str(), svg ? ".svg" : ".png");
        return 2;
    }
    if (const std::string clash = singleFile ? "" : SameFigureNames(scenes, output, allSteps, svg); !clash.empty())
    {
        std::fprintf(stderr, "satviz-render: %s\n", clash.c_str());
        return 2;
    }
    {
        const std::filesystem::path directory =
            singleFile ? std::filesystem::path(output).parent_path() : std::filesystem::path(output);
        std::error_code code;
        if (!directory.empty())
        {
            std::filesystem::create_directories(directory, code);
        }
        if (code)
        {
            std::fprintf(stderr, "satviz-render: %s: cannot create the directory (%s)\n", directory.c_str(),
                         code.message().c_str());
            return 1;
        }
    }

    HeadlessRenderer renderer;
    std::string error;
    if (!renderer.Init(error))
    {
        std::fprintf(stderr, "satviz-render: %s\n", error.c_str());
        return 1;
    }

    const auto start = Clock::now();
    int written = 0;
    int failedScenes = 0;
    double paintAndGl = 0.0;
    double png = 0.0;
    std::vector<unsigned char> rgb;
    for (size_t s = 0; s < scenes.size(); ++s)
    {
        const std::string& file = scenes[s];
        // A polygon may be concave: it is drawn by its pieces and stepped as one body.
        satviz::SceneOptions sceneOptions;
        sceneOptions.concave = true;
        satviz::SceneResult loaded = satviz::LoadScene(file, sceneOptions);
        if (!loaded.Ok())
        {
            std::fprintf(stderr, "satviz-render: %s\n", loaded.error.c_str());
            ++failedScenes;
            continue;
        }
        // The world first, when asked: the figure then shows the bodies where the steps leave them. With
        // --sim-every, one figure every K steps from 0 to N, each named by its step.
        const int sceneSteps = simOption->count() > 0 ? simSteps : loaded.scene.view.simSteps;
        const bool worldLayers =
            (options.setLayers ? options.layers : satviz::LayersFromNames(loaded.scene.view.layers)) &
            (satviz::kLayerBroadphase | satviz::kLayerResponse | satviz::kLayerHits | satviz::kLayerPlots);
        if (const std::string invalid = satviz::ValidateSceneWorld(loaded.scene);
            !invalid.empty() && (sceneSteps > 0 || worldLayers))
        {
            std::fprintf(stderr, "satviz-render: %s: %s\n", file.c_str(), invalid.c_str());
            ++failedScenes;
            continue;
        }
        std::vector<int> frames;
        for (int k = 0; simEvery > 0 && k < sceneSteps; k += simEvery)
        {
            frames.push_back(k);
        }
        frames.push_back(sceneSteps);
        int pairA = -1, pairB = -1;
        satviz::FigurePair(loaded.scene, pairA, pairB);
        const bool recorded = worldLayers || simEvery > 0;
        satviz::SimRecord record;
        if (recorded)
        {
            record = satviz::StartRecord(loaded.scene, pairA, pairB);
        }
        const satviz::Scene original = loaded.scene;
        bool sceneFailed = false;
        for (const int frame : frames)
        {
            if (recorded)
            {
                while (record.steps < frame)
                {
                    satviz::StepRecord(record);
                }
                loaded.scene = original;
                satviz::CopyWorldState(record.world, loaded.scene);
            }
            else if (const std::string simError = satviz::SimulateScene(loaded.scene, sceneSteps); !simError.empty())
            {
                std::fprintf(stderr, "satviz-render: %s: %s\n", file.c_str(), simError.c_str());
                sceneFailed = true;
                break;
            }
            satviz::FigureOptions first = options;
            first.sim = recorded ? &record : nullptr;
            if (step >= 1)
            {
                first.setStep = true;
                first.step = step - 1;
            }
            // A trace records every face's intervals, so its cost grows with the square of the vertex count: say so
            // before a long one, and how long it took after.
            size_t largest = 0;
            size_t second = 0;
            for (const satviz::Body& body : loaded.scene.bodies)
            {
                const size_t n =
                    body.shape.type == satviz::ShapeType::Polygon ? body.shape.polygon.Vertices().size() : 1;
                second = std::max(second, std::min(largest, n));
                largest = std::max(largest, n);
            }
            const bool slow = !quiet && largest + second > kSlowTrace;
            const auto traceStart = Clock::now();
            if (slow)
            {
                std::fprintf(stderr,
                             "satviz-render: %s: tracing polygons of up to %zu vertices (every face's intervals)\n",
                             file.c_str(), largest);
            }
            satviz::FigureSetup setup = satviz::SetUpFigure(loaded.scene, first);
            if (slow)
            {
                std::fprintf(stderr, "satviz-render: %s: traced in %.1f s\n", file.c_str(),
                             Seconds(Clock::now() - traceStart));
            }
            if (!setup.Ok())
            {
                std::fprintf(stderr, "satviz-render: %s: %s\n", file.c_str(), setup.error.c_str());
                sceneFailed = true;
                break;
            }
            std::vector<int> steps;
            if (allSteps)
            {
                for (int k = 0; k < satviz::FigureStepCount(loaded.scene, setup); ++k)
                {
                    steps.push_back(k);
                }
            }
            else
            {
                steps.push_back(setup.figure.step);
            }
            const std::string stem = std::filesystem::path(file).stem().string() +
                                     (simEvery > 0 ? "-sim" + StepNumber(frame, sceneSteps) : "");
            for (int k : steps)
            {
                setup.figure.step = k;
                const std::string path =
                    singleFile ? output
                               : (std::filesystem::path(output) /
                                  FigureName(allSteps ? stem + "-step" + std::to_string(k + 1) : stem, svg))
                                     .string();
                const auto t0 = Clock::now();
                std::string document;
                if (svg)
                {
                    document = renderer.RenderSvg(loaded.scene, setup);
                }
                else if (!renderer.Render(loaded.scene, setup, rgb, error))
                {
                    std::fprintf(stderr, "satviz-render: %s: %s\n", file.c_str(), error.c_str());
                    sceneFailed = true;
                    break;
                }
                const auto t1 = Clock::now();
                if (svg ? !satviz::WriteFileAtomically(path, document, error)
                        : !satviz::WritePngFile(path, rgb, setup.figure.view.width, setup.figure.view.height, true,
                                                error))
                {
                    std::fprintf(stderr, "satviz-render: %s\n", error.c_str());
                    sceneFailed = true;
                    break;
                }
                const auto t2 = Clock::now();
                if (written > 0)
                {
                    paintAndGl += Seconds(t1 - t0);
                    png += Seconds(t2 - t1);
                }
                ++written;
                if (!quiet && (scenes.size() > 1 || steps.size() > 1 || frames.size() > 1))
                {
                    std::fprintf(stderr, "satviz-render: [%zu/%zu] %s\n", s + 1, scenes.size(), path.c_str());
                }
            }
            if (sceneFailed)
            {
                break;
            }
        }
        failedScenes += sceneFailed ? 1 : 0;
    }
    const double total = Seconds(Clock::now() - start);
    const int timed = written > 1 ? written - 1 : 0;
    std::fprintf(stderr, "satviz-render: %d figure%s written in %.2f s", written, written == 1 ? "" : "s", total);
    if (timed > 0)
    {
        std::fprintf(stderr, "; after the first, per figure: %.1f ms drawing, %.1f ms %s, %.1f ms in all",
                     1e3 * paintAndGl / timed, 1e3 * png / timed, svg ? "SVG" : "PNG",
                     1e3 * (paintAndGl + png) / timed);
    }
    if (failedScenes > 0)
    {
        std::fprintf(stderr, "; %d of %zu scene%s failed", failedScenes, scenes.size(), scenes.size() == 1 ? "" : "s");
    }
    std::fprintf(stderr, "\n");
    return failedScenes > 0 ? 1 : 0;
}
