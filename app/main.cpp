// SPDX-License-Identifier: MIT
// satviz: the interactive app. The only file that touches GLFW: it opens the window, feeds ImGui, runs the frame
// loop, and turns the app's export requests into PNG files with the same drawing and OpenGL2 backend as
// satviz-render. Links GLFW and libGL, never OSMesa.
#include "app.h"
#include "key_queue.h"
#include "panels.h"

#include <satviz/render/figure_drawing.h>
#include <satviz/render/palette.h>
#include <satviz/render/png_file.h>

#include <CLI/CLI.hpp>
#define GLFW_INCLUDE_GLEXT
#include <satviz/scene.h>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <execinfo.h>
#include <filesystem>
#include <memory>
#include <signal.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace
{

// `path` in the XDG base folder named by the environment variable `variable`, or in `fallback` under the home
// folder when it is unset; empty when neither is known.
std::string XdgPath(const char* variable, const char* fallback, const char* path)
{
    if (const char* base = std::getenv(variable); base != nullptr && *base != '\0')
    {
        return std::string(base) + "/" + path;
    }
    if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    {
        return std::string(home) + "/" + fallback + "/" + path;
    }
    return "";
}

std::string RecentFile()
{
    return XdgPath("XDG_CONFIG_HOME", ".config", "satviz/recent.txt");
}

// Where the copies of unsaved scenes are kept (AppOptions::unsavedDir): the XDG state folder, which holds what an
// application keeps between runs that is not configuration.
std::string UnsavedFolder()
{
    return XdgPath("XDG_STATE_HOME", ".local/state", "satviz/unsaved");
}

/// What the app does when it crashes (a fault, an abort): says so on stderr with where the unsaved changes are and
/// the stack of calls, for a report, and ends as the signal would have ended it. The unsaved changes are on disk
/// already (UnsavedCopy): the handler writes nothing else, and calls only what a signal handler may.
class CrashReport
{
  public:
    /// Installs the handler for the signals of a crash, on a stack of its own (a stack overflow leaves none).
    static void Install()
    {
        void* frames[2];
        backtrace(frames, 2); // loads what backtrace needs now: the handler may not allocate
        stack_t alternate{};
        alternate.ss_sp = m_stack;
        alternate.ss_size = sizeof m_stack;
        sigaltstack(&alternate, nullptr);
        struct sigaction action{};
        action.sa_handler = OnCrash;
        action.sa_flags = SA_ONSTACK | SA_RESETHAND;
        sigemptyset(&action.sa_mask);
        for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
        {
            sigaction(signal, &action, nullptr);
        }
    }
    /// Notes where the unsaved changes are now (empty: there are none).
    static void SetUnsavedCopy(const std::string& path)
    {
        const size_t n = std::min(path.size(), sizeof m_copy - 1);
        std::memcpy(m_copy, path.data(), n);
        m_copy[n] = '\0';
    }

  private:
    static void Say(const char* text) { [[maybe_unused]] const ssize_t written = write(2, text, std::strlen(text)); }

    static void OnCrash(int signal)
    {
        char number[16];
        int n = 0;
        for (int v = signal; v > 0 && n < 15; v /= 10)
        {
            number[n++] = static_cast<char>('0' + v % 10);
        }
        std::reverse(number, number + n);
        number[n] = '\0';
        Say("satviz: crashed (signal ");
        Say(number);
        Say(m_copy[0] != '\0' ? "); the unsaved changes are in " : "); there were no unsaved changes");
        Say(m_copy);
        Say("\nsatviz: the calls that led to it:\n");
        void* frames[64];
        backtrace_symbols_fd(frames, backtrace(frames, 64), 2);
        raise(signal); // the default action now (SA_RESETHAND): the process ends by the signal, a core if enabled
    }

    static inline char m_copy[4096] = {};
    static inline char m_stack[1 << 16] = {}; // no destructor: a crash at exit still finds it
};

/// An offscreen RGBA8 colour buffer, the format of satviz-render's OSMesa buffer: the window's own buffer has
/// another format, and blending into it rounds a few pixels differently.
class OffscreenTarget
{
  public:
    OffscreenTarget(int width, int height)
    {
        m_genFramebuffers = reinterpret_cast<PFNGLGENFRAMEBUFFERSPROC>(glfwGetProcAddress("glGenFramebuffers"));
        m_bindFramebuffer = reinterpret_cast<PFNGLBINDFRAMEBUFFERPROC>(glfwGetProcAddress("glBindFramebuffer"));
        m_deleteFramebuffers = reinterpret_cast<PFNGLDELETEFRAMEBUFFERSPROC>(glfwGetProcAddress("glDeleteFramebuffers"));
        m_genRenderbuffers = reinterpret_cast<PFNGLGENRENDERBUFFERSPROC>(glfwGetProcAddress("glGenRenderbuffers"));
        m_bindRenderbuffer = reinterpret_cast<PFNGLBINDRENDERBUFFERPROC>(glfwGetProcAddress("glBindRenderbuffer"));
        m_deleteRenderbuffers =
            reinterpret_cast<PFNGLDELETERENDERBUFFERSPROC>(glfwGetProcAddress("glDeleteRenderbuffers"));
        m_storage = reinterpret_cast<PFNGLRENDERBUFFERSTORAGEPROC>(glfwGetProcAddress("glRenderbufferStorage"));
        m_attach = reinterpret_cast<PFNGLFRAMEBUFFERRENDERBUFFERPROC>(glfwGetProcAddress("glFramebufferRenderbuffer"));
        m_status = reinterpret_cast<PFNGLCHECKFRAMEBUFFERSTATUSPROC>(glfwGetProcAddress("glCheckFramebufferStatus"));
        if (!m_genFramebuffers || !m_bindFramebuffer || !m_deleteFramebuffers || !m_genRenderbuffers ||
            !m_bindRenderbuffer || !m_deleteRenderbuffers || !m_storage || !m_attach || !m_status)
        {
            return;
        }
        m_genFramebuffers(1, &m_framebuffer);
        m_genRenderbuffers(1, &m_renderbuffer);
        m_bindRenderbuffer(GL_RENDERBUFFER, m_renderbuffer);
        m_storage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        m_bindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
        m_attach(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_renderbuffer);
        m_ready = m_status(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    ~OffscreenTarget()
    {
        if (m_bindFramebuffer != nullptr)
        {
            m_bindFramebuffer(GL_FRAMEBUFFER, 0);
        }
        if (m_framebuffer != 0)
        {
            m_deleteFramebuffers(1, &m_framebuffer);
        }
        if (m_renderbuffer != 0)
        {
            m_deleteRenderbuffers(1, &m_renderbuffer);
        }
    }
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;
    /// True when the buffer is bound and complete.
    bool Ready() const { return m_ready; }

  private:
    PFNGLGENFRAMEBUFFERSPROC m_genFramebuffers = nullptr;
    PFNGLBINDFRAMEBUFFERPROC m_bindFramebuffer = nullptr;
    PFNGLDELETEFRAMEBUFFERSPROC m_deleteFramebuffers = nullptr;
    PFNGLGENRENDERBUFFERSPROC m_genRenderbuffers = nullptr;
    PFNGLBINDRENDERBUFFERPROC m_bindRenderbuffer = nullptr;
    PFNGLDELETERENDERBUFFERSPROC m_deleteRenderbuffers = nullptr;
    PFNGLRENDERBUFFERSTORAGEPROC m_storage = nullptr;
    PFNGLFRAMEBUFFERRENDERBUFFERPROC m_attach = nullptr;
    PFNGLCHECKFRAMEBUFFERSTATUSPROC m_status = nullptr;
    GLuint m_framebuffer = 0;
    GLuint m_renderbuffer = 0;
    bool m_ready = false;
};

// The fallback export without satviz-render: draws the figure into an offscreen buffer of this window's OpenGL
// and writes it as a PNG. The pixels can differ from satviz-render's in a few anti-aliased edge pixels by one
// level: the two OpenGL front ends of Mesa round a few fragments differently.
void ExportWithWindowGl(satviz::App& app, satviz::FigureDrawing& drawing, const satviz::FigureSetup& setup,
                        const std::string& path)
{
    const int width = setup.figure.view.width;
    const int height = setup.figure.view.height;
    OffscreenTarget target(width, height);
    if (!target.Ready())
    {
        app.SetStatus(path + ": this OpenGL has no offscreen buffers (framebuffer objects); cannot export", true);
        return;
    }
    glViewport(0, 0, width, height);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL2_RenderDrawData(drawing.DrawData());
    glFinish();
    std::vector<unsigned char> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    std::string error;
    if (satviz::WritePngFile(path, rgb, width, height, true, error))
    {
        app.SetStatus("Exported " + path + " (" + std::to_string(width) + "x" + std::to_string(height) + ")", false);
        std::printf("satviz: exported %s\n", path.c_str());
        std::fflush(stdout);
    }
    else
    {
        app.SetStatus(error, true);
    }
}

// Exports the figure the way satviz-render draws it, by running satviz-render on a snapshot of the scene: the
// PNG is then byte-identical to satviz-render's figure of the saved scene, and this process never loads OSMesa.
bool ExportWithRenderer(satviz::App& app, const std::string& renderer, const std::string& path)
{
    if (renderer.empty() || ::access(renderer.c_str(), X_OK) != 0)
    {
        return false;
    }
    const std::string snapshot =
        (std::filesystem::temp_directory_path() / ("satviz-export-" + std::to_string(::getpid()) + ".json")).string();
    std::string error;
    if (!satviz::SaveScene(app.SceneForSaving(), snapshot, error))
    {
        app.SetStatus(error, true);
        return true;
    }
    std::vector<std::string> arguments = {renderer, "-q", snapshot, "-o", path};
    std::vector<char*> argv;
    for (std::string& argument : arguments)
    {
        argv.push_back(argument.data());
    }
    argv.push_back(nullptr);
    pid_t child = 0;
    int status = 0;
    const bool started = ::posix_spawn(&child, renderer.c_str(), nullptr, nullptr, argv.data(), environ) == 0;
    const bool finished = started && ::waitpid(child, &status, 0) == child;
    std::filesystem::remove(snapshot);
    if (!finished || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    {
        app.SetStatus(path + ": satviz-render failed (see the terminal)", true);
        return true;
    }
    app.SetStatus("Exported " + path, false);
    std::printf("satviz: exported %s\n", path.c_str());
    std::fflush(stdout);
    return true;
}

/// The window's input between frames: key events queued so that no tap is lost (KeyQueue), and whether anything
/// arrived at all, so that the frame loop can wait for events while nothing changes.
class WindowInput
{
  public:
    /// Installs, before ImGui's backend chains its own callbacks to them, the callbacks that only note input.
    static void InstallBeforeBackend(GLFWwindow* window)
    {
        glfwSetMouseButtonCallback(window, [](GLFWwindow*, int, int, int) { m_events = true; });
        glfwSetScrollCallback(window, [](GLFWwindow*, double, double) { m_events = true; });
        glfwSetCharCallback(window, [](GLFWwindow*, unsigned int) { m_events = true; });
        glfwSetWindowFocusCallback(window, [](GLFWwindow*, int) { m_events = true; });
        glfwSetCursorEnterCallback(window, [](GLFWwindow*, int) { m_events = true; });
    }
    /// Installs the other callbacks on `window`, after ImGui's backend: the key callback replaces the backend's,
    /// which is handed the keys from the queue; the others only note that something happened.
    static void Install(GLFWwindow* window)
    {
        glfwSetKeyCallback(window, [](GLFWwindow*, int key, int scancode, int action, int mods) {
            m_events = true;
            if (action != GLFW_REPEAT) // ImGui 1.86 makes its own repeats from the time a key is down
            {
                m_keys.Push({key, scancode, action == GLFW_PRESS, mods});
            }
        });
        glfwSetCursorPosCallback(window, [](GLFWwindow*, double, double) { m_events = true; });
        glfwSetWindowSizeCallback(window, [](GLFWwindow*, int, int) { m_events = true; });
        glfwSetWindowRefreshCallback(window, [](GLFWwindow*) { m_events = true; });
    }
    /// Hands ImGui's backend the key events of this frame.
    static void DeliverKeys(GLFWwindow* window)
    {
        m_keys.TakeFrame([window](const satviz::KeyEvent& event) {
            ImGui_ImplGlfw_KeyCallback(window, event.key, event.scancode, event.press ? GLFW_PRESS : GLFW_RELEASE,
                                       event.mods);
        });
    }
    /// True while key events wait for a frame.
    static bool KeysWaiting() { return m_keys.Waiting(); }
    /// True, once, when input arrived since the last call.
    static bool TakeEvents()
    {
        const bool events = m_events;
        m_events = false;
        return events;
    }

  private:
    static inline satviz::KeyQueue m_keys;
    static inline bool m_events = false;
};

/// The directory of this program's file, from /proc/self/exe; empty where that cannot be read.
std::filesystem::path ProgramDir()
{
    std::error_code code;
    const std::filesystem::path self = std::filesystem::canonical("/proc/self/exe", code);
    return code ? std::filesystem::path() : self.parent_path();
}

// satviz-render: beside this program (an install prefix's bin/), in ../render (the build tree), or on the PATH.
std::string FindRenderer(const std::filesystem::path& programDir)
{
    if (!programDir.empty())
    {
        for (const std::filesystem::path& candidate :
             {programDir / "satviz-render", programDir.parent_path() / "render" / "satviz-render"})
        {
            if (::access(candidate.c_str(), X_OK) == 0)
            {
                return candidate.string();
            }
        }
    }
    if (const char* path = std::getenv("PATH"))
    {
        std::string dirs = path;
        size_t start = 0;
        while (start <= dirs.size())
        {
            const size_t end = std::min(dirs.find(':', start), dirs.size());
            const std::filesystem::path candidate =
                std::filesystem::path(dirs.substr(start, end - start)) / "satviz-render";
            if (::access(candidate.c_str(), X_OK) == 0)
            {
                return candidate.string();
            }
            start = end + 1;
        }
    }
    return "";
}

} // namespace

namespace
{

bool Intersect(const ImVec4& a, const ImVec4& b)
{
    return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w;
}

// True when no command drawn before `command` in this frame reaches into its clip rectangle: every drawing stays
// within its command's clip rectangle.
bool NothingDrawnUnder(const ImDrawList* list, const ImDrawCmd* command)
{
    const ImDrawData* data = ImGui::GetDrawData();
    for (int l = 0; l < data->CmdListsCount; ++l)
    {
        const ImDrawList* earlier = data->CmdLists[l];
        for (const ImDrawCmd& c : earlier->CmdBuffer)
        {
            if (&c == command)
            {
                return true;
            }
            if ((c.ElemCount > 0 || c.UserCallback != nullptr) && Intersect(c.ClipRect, command->ClipRect))
            {
                return false;
            }
        }
        if (earlier == list)
        {
            break;
        }
    }
    return false;
}

// AppOptions::clearRect: fills the command's clip rectangle with the colour in its callback data by a scissored
// clear. The rectangle's pixels are those whose centres it holds, as for the two triangles it replaces.
void ClearRect(const ImDrawList* list, const ImDrawCmd* command)
{
    const ImDrawData* data = ImGui::GetDrawData();
    const ImVec2 scale = data->FramebufferScale;
    const float height = data->DisplaySize.y * scale.y;
    const auto pixel = [](float v) { return static_cast<int>(std::ceil(v - 0.5f)); };
    const int x0 = pixel((command->ClipRect.x - data->DisplayPos.x) * scale.x);
    const int y0 = pixel((command->ClipRect.y - data->DisplayPos.y) * scale.y);
    const int x1 = pixel((command->ClipRect.z - data->DisplayPos.x) * scale.x);
    const int y1 = pixel((command->ClipRect.w - data->DisplayPos.y) * scale.y);
    if (x1 <= x0 || y1 <= y0)
    {
        return;
    }
    const satviz::Color color = satviz::ClearColorOf(*command);
    if (color == satviz::palette::kBackground && NothingDrawnUnder(list, command))
    {
        return; // the frame was cleared to it (the figure's ground, its first drawing)
    }
    glScissor(x0, static_cast<int>(height) - y1, x1 - x0, y1 - y0);
    glClearColor(static_cast<float>((color >> 24) & 0xFFu) / 255.0f, static_cast<float>((color >> 16) & 0xFFu) / 255.0f,
                 static_cast<float>((color >> 8) & 0xFFu) / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

} // namespace

namespace
{

// Keeps the window no smaller than the panels, the lesson column while it is open and a canvas a figure can be
// read on need: the window manager is told the limits, and a window already smaller (a lesson opened in a narrow
// window, or no window manager to hold the limits) is enlarged.
// `barHeight` is the height of the menu and status bars: ImGui::GetFrameHeight() within a frame; before the first, the
// default font's size and the style's padding, which is what it will be.
void KeepMinimumSize(GLFWwindow* window, bool lessonShown, float barHeight)
{
    static ImVec2 applied(0.0f, 0.0f);
    const ImVec2 least = satviz::MinimumWindowSize(lessonShown, barHeight);
    const int width = static_cast<int>(std::ceil(least.x));
    const int height = static_cast<int>(std::ceil(least.y));
    if (least.x != applied.x || least.y != applied.y)
    {
        glfwSetWindowSizeLimits(window, width, height, GLFW_DONT_CARE, GLFW_DONT_CARE);
        applied = least;
    }
    int currentWidth = 0;
    int currentHeight = 0;
    glfwGetWindowSize(window, &currentWidth, &currentHeight);
    if (currentWidth < width || currentHeight < height)
    {
        glfwSetWindowSize(window, std::max(currentWidth, width), std::max(currentHeight, height));
    }
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App cli{"satviz: step through the Separating Axis Theorem, axis by axis"};
    cli.set_version_flag("--version", std::string("satviz ") + SATVIZ_VERSION);
    std::string sceneFile;
    std::string exportPath;
    std::string size = "1280x800";
    int measureFrames = 0;
    cli.add_option("scene", sceneFile, "Scene file to open (default: a bundled example)");
    cli.add_option("--export-to", exportPath,
                   "Where ctrl+e writes the PNG (default: SCENE-stepN.png beside the scene)");
    cli.add_option("--window", size, "Window size WxH in pixels (raised to the smallest the panels need)");
    const CLI::Option* measureOption =
        cli.add_option("--measure-fps", measureFrames,
                       "Run this many frames (at least 1) without waiting for the display, print the frame rate, "
                       "and exit; the scene is not added to the Recent list");
    bool play = false;
    cli.add_flag("--play", play,
                 "Start the scene's simulation playing (with --measure-fps: the frame rate while it plays)");
    int lessonNumber = 0;
    const CLI::Option* lessonOption = cli.add_option(
        "--lesson", lessonNumber, "Open lesson N of tutorials/ (from 1) beside the canvas, with its first scene");
    CLI11_PARSE(cli, argc, argv);
    if (lessonOption->count() > 0 && lessonNumber < 1)
    {
        std::fprintf(stderr, "satviz: --lesson: lessons count from 1, got %d\n", lessonNumber);
        return 2;
    }
    const bool measuring = measureOption->count() > 0;
    if (measuring && measureFrames < 1)
    {
        std::fprintf(stderr, "satviz: --measure-fps: expected a number of frames of at least 1, got %d\n",
                     measureFrames);
        return 2;
    }
    int windowWidth = 1280;
    int windowHeight = 800;
    // Any size of at least a pixel is taken: one smaller than the panels need is raised to it (KeepMinimumSize), as
    // the help says, rather than refused.
    int parsed = 0;
    if (std::sscanf(size.c_str(), "%dx%d%n", &windowWidth, &windowHeight, &parsed) != 2 ||
        parsed != static_cast<int>(size.size()) || windowWidth < 1 || windowHeight < 1)
    {
        std::fprintf(stderr, "satviz: --window: expected WxH, two whole numbers of pixels of at least 1, got \"%s\"\n",
                     size.c_str());
        return 2;
    }

    // The bundled scenes and the lessons, found from where this program is (see FindBundledScenes).
    const std::filesystem::path programDir = ProgramDir();
    const std::string scenesDir =
        programDir.empty() ? std::string() : satviz::FindBundledScenes(programDir, SATVIZ_DATA_FROM_BIN);
    if (sceneFile.empty() && scenesDir.empty())
    {
        std::fprintf(stderr, "satviz: no bundled scenes in %s or a tutorials/scenes above it; name a scene file\n",
                     (programDir / SATVIZ_DATA_FROM_BIN / "scenes").lexically_normal().c_str());
        return 1;
    }

    if (!glfwInit())
    {
        std::fprintf(stderr, "satviz: cannot open a window (no display?); satviz-render draws figures without one\n");
        return 1;
    }
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(windowWidth, windowHeight, "satviz", nullptr, nullptr);
    if (window == nullptr)
    {
        std::fprintf(stderr, "satviz: cannot create an OpenGL window\n");
        glfwTerminate();
        return 1;
    }
    glfwSetWindowPos(window, 0, 0);
    glfwMakeContextCurrent(window);
    glfwSwapInterval(measuring ? 0 : 1);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    ImGui::StyleColorsLight();
    ImGui::GetStyle().WindowRounding = 0.0f;
    // The app's font atlas holds exactly the figure fonts, like satviz-render's: exported PNGs then match its
    // figures byte for byte. The interface uses the figures' body font.
    satviz::FigureFonts fonts;
    std::string error;
    if (!satviz::AddFigureFonts(*io.Fonts, fonts, error))
    {
        std::fprintf(stderr, "satviz: %s\n", error.c_str());
        return 1;
    }
    io.FontDefault = fonts.body;
    WindowInput::InstallBeforeBackend(window);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    WindowInput::Install(window);
    ImGui_ImplOpenGL2_Init();

    satviz::AppOptions options;
    options.scenesDir = scenesDir;
    options.recentFile = RecentFile();
    options.updateRecent = !measuring;
    options.unsavedDir = measuring ? std::string() : UnsavedFolder();
    options.exportPath = exportPath;
    options.clearRect = ClearRect;
    options.keys.s = GLFW_KEY_S;
    options.keys.o = GLFW_KEY_O;
    options.keys.e = GLFW_KEY_E;
    options.keys.q = GLFW_KEY_Q;
    options.keys.f = GLFW_KEY_F;
    options.keys.f1 = GLFW_KEY_F1;
    options.keys.p = GLFW_KEY_P;
    options.keys.period = GLFW_KEY_PERIOD;
    options.keys.comma = GLFW_KEY_COMMA;
    options.keys.d = GLFW_KEY_D;
    options.keys.x = GLFW_KEY_X;
    satviz::App app(fonts, options);
    const std::string renderer = FindRenderer(programDir);
    const std::string initial = sceneFile.empty() ? options.scenesDir + "/overlapping_boxes.json" : sceneFile;
    if (!app.Open(initial))
    {
        std::fprintf(stderr, "satviz: %s\n", app.Status().c_str());
        return 1;
    }
    if (lessonOption->count() > 0 && !app.OpenLesson(lessonNumber - 1))
    {
        std::fprintf(stderr, "satviz: --lesson: there are %zu lessons, no lesson %d\n", app.Lessons().size(),
                     lessonNumber);
        return 2;
    }

    if (app.ReportLeftCopies())
    {
        std::printf("satviz: %s\n", app.Status().c_str());
        std::fflush(stdout);
    }
    CrashReport::Install();

    if (play)
    {
        app.SimPlay(true);
    }
    // The window at its least size before the first frame, so that the first frame already lays out and frames the
    // canvas it will keep (a canvas fitted to a 200 x 150 window would frame the scene for nothing).
    KeepMinimumSize(window, app.LessonShown(), io.FontDefault->FontSize + 2.0f * ImGui::GetStyle().FramePadding.y);

    using Clock = std::chrono::steady_clock;
    Clock::time_point measureStart;
    int frame = 0;
    // Frames still to run after the last input: Dear ImGui places and sizes a window over its first frames, and a
    // click asks a question from the next frame on.
    constexpr int kSettleFrames = 8;
    int settle = kSettleFrames;
    while (true)
    {
        if (measuring)
        {
            glfwPollEvents();
        }
        else if (settle > 0 || WindowInput::KeysWaiting())
        {
            glfwPollEvents();
        }
        else
        {
            // Nothing changes until the user does something or the app's next change (a step played): no frames, no
            // CPU. Woken twice a second all the same, for a text field's blinking cursor.
            const double change = app.SecondsUntilChange();
            glfwWaitEventsTimeout(change >= 0.0 ? std::min(change, 0.5) + 0.001 : 0.5);
        }
        if (WindowInput::TakeEvents())
        {
            settle = kSettleFrames;
        }
        else if (settle > 0)
        {
            --settle;
        }
        WindowInput::DeliverKeys(window);
        if (glfwWindowShouldClose(window))
        {
            if (app.RequestQuit())
            {
                break;
            }
            glfwSetWindowShouldClose(window, GLFW_FALSE);
        }
        if (app.QuitConfirmed())
        {
            break;
        }
        ImGui_ImplOpenGL2_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        app.Frame();
        CrashReport::SetUnsavedCopy(app.UnsavedCopyPath());
        KeepMinimumSize(window, app.LessonShown(), ImGui::GetFrameHeight());
        std::string exportTo;
        std::unique_ptr<satviz::FigureDrawing> drawing;
        satviz::FigureSetup exportSetup;
        if (app.TakeExportRequest(exportTo))
        {
            exportSetup = app.ExportFigure();
            if (exportSetup.Ok() && ExportWithRenderer(app, renderer, exportTo))
            {
                exportSetup = {};
            }
            else if (exportSetup.Ok())
            {
                drawing = std::make_unique<satviz::FigureDrawing>(app.GetDocument().GetScene(), exportSetup.study,
                                                                  exportSetup.figure, fonts);
            }
            else
            {
                app.SetStatus(exportSetup.error, true);
            }
        }
        ImGui::Render();
        int framebufferWidth = 0;
        int framebufferHeight = 0;
        glfwGetFramebufferSize(window, &framebufferWidth, &framebufferHeight);
        if (drawing)
        {
            ExportWithWindowGl(app, *drawing, exportSetup, exportTo);
        }
        glViewport(0, 0, framebufferWidth, framebufferHeight);
        // The figure's ground, so that a canvas drawn first need not fill it again (ClearRect).
        glClearColor(static_cast<float>((satviz::palette::kBackground >> 24) & 0xFFu) / 255.0f,
                     static_cast<float>((satviz::palette::kBackground >> 16) & 0xFFu) / 255.0f,
                     static_cast<float>((satviz::palette::kBackground >> 8) & 0xFFu) / 255.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
        glfwSwapBuffers(window);

        if (measuring)
        {
            ++frame;
            if (frame == 10)
            {
                measureStart = Clock::now();
            }
            if (frame == 10 + measureFrames)
            {
                const double seconds = std::chrono::duration<double>(Clock::now() - measureStart).count();
                std::printf("satviz: %d frames in %.3f s: %.1f frames per second (%zu bodies, %dx%d window%s)\n",
                            measureFrames, seconds, measureFrames / seconds, app.GetDocument().GetScene().bodies.size(),
                            framebufferWidth, framebufferHeight,
                            play ? (", simulation at step " + std::to_string(app.GetSimulation().Shown())).c_str()
                                 : "");
                break;
            }
        }
    }

    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}
