// Tests of the interactive debugger hlens (app/hlens/), run as a separate process in headless
// screenshot mode on an Xvfb server (Mesa's llvmpipe renders OpenGL without a GPU).
//
// Compiled only when the hlens target exists (CMake then defines HLENS_GUI as its path); every
// test that needs a display is skipped when Xvfb is not on PATH. Each run writes a PNG, which
// is read back with stb_image and checked pixel by pixel, and prints the state behind the picture
// as one JSON line, which is checked against hlens-cli (HLENS_CLI).
#ifdef HLENS_GUI

#include <gtest/gtest.h>

#include "test_support.h"
#include "test_meshes.h"
#include <hlens/integrals.h>
#include <hlens/target_maxima.h>
#include <hlens/mesh_io.h>
#include <hlens/target_solver.h>
#include <hlens/voxel_grid.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace fs = std::filesystem;
using hlens_test::Outcome;
using hlens_test::quote;
using hlens_test::read_file;
using hlens_test::run;
using hlens_test::write_file;

namespace {

const std::string kGui = HLENS_GUI;
const std::string kCli = HLENS_CLI;
const std::string kDemoA = std::string(HLENS_SOURCE_DIR) + "/assets/demo_a.obj";
const std::string kDemoB = std::string(HLENS_SOURCE_DIR) + "/assets/demo_b.obj";

// The colours hlens promises (app/hlens/panels.h, app/hlens/colormap.cpp), as 8-bit RGB.
constexpr std::array<int, 3> kClear = {41, 43, 51};        // kClearColor (0.16, 0.17, 0.20)
constexpr std::array<int, 3> kErrorBg = {128, 23, 23};     // kErrorBg (0.50, 0.09, 0.09)
constexpr std::array<int, 3> kMapLow = {71, 1, 85};        // viridis at 0
constexpr std::array<int, 3> kMapHigh = {252, 231, 33};    // viridis at 1
constexpr std::array<int, 3> kSelected = {255, 64, 217};   // the selected target (1, 0.25, 0.85)

// The scratch directories of the running test. When the test ends they are removed, passed or
// failed (a failed attempt that a rerun passes, as the sanitizer stage allows, must not leave them
// in /tmp either); with HLENS_KEEP_GUI_SCRATCH set, a failed test's are kept for inspection
// (screenshots, logs) and their paths printed.
std::vector<fs::path>& scratch_dirs() {
    static std::vector<fs::path> dirs;
    return dirs;
}

struct ScratchCleanup : ::testing::EmptyTestEventListener {
    void OnTestEnd(const ::testing::TestInfo& info) override {
        const bool keep = info.result()->Failed() && std::getenv("HLENS_KEEP_GUI_SCRATCH");
        for (const fs::path& d : scratch_dirs()) {
            if (keep) {
                std::printf("[ info ] kept %s\n", d.c_str());
            } else {
                std::error_code ec;
                fs::remove_all(d, ec);
            }
        }
        scratch_dirs().clear();
    }
};

[[maybe_unused]] const bool kScratchCleanupInstalled = [] {
    ::testing::UnitTest::GetInstance()->listeners().Append(new ScratchCleanup);  // gtest owns it
    return true;
}();

fs::path scratch_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    fs::path d = fs::temp_directory_path() /
                 ("hlens_gui_" + std::to_string(::getpid()) + "_" + (info ? info->name() : "x"));
    fs::remove_all(d);
    fs::create_directories(d);
    if (std::find(scratch_dirs().begin(), scratch_dirs().end(), d) == scratch_dirs().end()) scratch_dirs().push_back(d);
    return d;
}

// A fresh X server for each run of hlens (no pointer position or focus left over from the previous
// run), started by hand with Xvfb -displayfd, which takes a free display number atomically. Not
// xvfb-run -a: it races other runs for a display number, and once in CI its clean-up of its
// temporary directory failed and turned the application's exit code 2 into its own 5.
class XServer {
  public:
    XServer(const XServer&) = delete;
    XServer& operator=(const XServer&) = delete;
    const std::string& display() const { return display_; }
    ~XServer() {
        if (pid_ > 0) {
            ::kill(pid_, SIGTERM);
            ::waitpid(pid_, nullptr, 0);
        }
    }
    XServer() {
        int fds[2];
        if (::pipe(fds) != 0) return;
        pid_ = ::fork();
        if (pid_ == 0) {
            ::close(fds[0]);
            const int null = ::open("/dev/null", O_WRONLY);
            if (null >= 0) ::dup2(null, 2);
            const std::string fd = std::to_string(fds[1]);
            ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "2600x1600x24", "-nolisten", "tcp",
                     (char*)nullptr);
            ::_exit(127);
        }
        ::close(fds[1]);
        std::string number;
        char c;
        while (pid_ > 0 && ::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        ::close(fds[0]);
        if (!number.empty()) display_ = ":" + number;
    }
  private:
    pid_t pid_ = -1;
    std::string display_;  // empty when Xvfb could not start
};

bool have_xvfb() { return std::system("command -v Xvfb >/dev/null 2>&1") == 0; }

// hlens <args> --screenshot <png> --size 800x600 on a fresh X server.
Outcome run_gui(std::vector<std::string> args, const fs::path& png, const fs::path& dir, const fs::path& cwd = {},
                const std::string& size = "800x600") {
    XServer server;
    EXPECT_FALSE(server.display().empty()) << "Xvfb did not start";
    std::vector<std::string> argv = {"env", "DISPLAY=" + server.display(), kGui};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"--screenshot", png.string(), "--size", size});
    return run(argv, dir, cwd);
}

struct Image {
    int w = 0, h = 0;
    std::vector<unsigned char> rgb;
    std::array<int, 3> at(int x, int y) const {
        const unsigned char* p = &rgb[((size_t)y * w + x) * 3];
        return {p[0], p[1], p[2]};
    }
};

Image load_png(const fs::path& p) {
    Image im;
    int n = 0;
    unsigned char* data = stbi_load(p.string().c_str(), &im.w, &im.h, &n, 3);
    if (data) {
        im.rgb.assign(data, data + (size_t)im.w * im.h * 3);
        stbi_image_free(data);
    }
    return im;
}

bool near(const std::array<int, 3>& p, const std::array<int, 3>& c, int tol) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(p[i] - c[i]) > tol) return false;
    return true;
}

// p is colour c under some shading factor s in [0.3, 1.05] (the view is lit), channel by channel.
bool shaded(const std::array<int, 3>& p, const std::array<int, 3>& c, int tol) {
    double pc = 0, cc = 0;
    for (int i = 0; i < 3; ++i) {
        pc += double(p[i]) * c[i];
        cc += double(c[i]) * c[i];
    }
    double s = pc / cc;
    if (s < 0.3 || s > 1.05) return false;
    for (int i = 0; i < 3; ++i)
        if (std::fabs(p[i] - s * c[i]) > tol) return false;
    return true;
}

int count(const Image& im, int x0, int y0, int x1, int y1, const std::function<bool(std::array<int, 3>)>& pred) {
    int n = 0;
    for (int y = std::max(0, y0); y < std::min(im.h, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(im.w, x1); ++x) n += pred(im.at(x, y));
    return n;
}

// ---- reading the flat JSON line of hlens and the one-line JSON of hlens-cli, by key
std::string raw_value(const std::string& json, const std::string& key, size_t from = 0) {
    size_t k = json.find("\"" + key + "\": ", from);
    if (k == std::string::npos) return "";
    size_t b = k + key.size() + 4, e = b;
    int depth = 0;
    for (; e < json.size(); ++e) {
        char c = json[e];
        if (c == '[' || c == '{') ++depth;
        if (c == ']' || c == '}') {
            if (depth == 0) break;
            --depth;
        }
        if (c == ',' && depth == 0) break;
    }
    return json.substr(b, e - b);
}
double num(const std::string& json, const std::string& key, size_t from = 0) {
    std::string v = raw_value(json, key, from);
    return v.empty() || v == "null" ? NAN : std::strtod(v.c_str(), nullptr);
}
std::vector<double> num_list(const std::string& json, const std::string& key, size_t from = 0) {
    std::string v = raw_value(json, key, from);
    std::vector<double> r;
    for (size_t i = 0; i < v.size();) {
        if (std::isdigit((unsigned char)v[i]) || v[i] == '-') {
            char* end = nullptr;
            r.push_back(std::strtod(v.c_str() + i, &end));
            i = end - v.c_str();
        } else {
            ++i;
        }
    }
    return r;
}
std::vector<int> int_list(const std::string& json, const std::string& key) {
    std::string v = raw_value(json, key);
    std::vector<int> r;
    for (size_t i = 0; i < v.size();) {
        if (std::isdigit((unsigned char)v[i])) {
            size_t e = i;
            r.push_back(std::stoi(v.substr(i), &e));
            i += e;
        } else {
            ++i;
        }
    }
    return r;
}

struct CliDistance {
    double a_to_b = NAN, b_to_a = NAN, hausdorff = NAN;
    long target_ab = -1, target_ba = -1;
};

CliDistance cli_distance(const fs::path& dir) {
    Outcome o = run({kCli, "distance", kDemoA, kDemoB, "--json"}, dir);
    EXPECT_EQ(o.code, 0) << o.err;
    CliDistance c;
    size_t ab = o.out.find("\"a_to_b\": {"), ba = o.out.find("\"b_to_a\": {");
    EXPECT_NE(ab, std::string::npos);
    EXPECT_NE(ba, std::string::npos);
    c.a_to_b = num(o.out, "distance", ab);
    c.b_to_a = num(o.out, "distance", ba);
    c.target_ab = (long)num(o.out, "target", ab);
    c.target_ba = (long)num(o.out, "target", ba);
    c.hausdorff = num(o.out, "hausdorff", o.out.rfind("\"hausdorff\": "));
    return c;
}

#define REQUIRE_XVFB() \
    if (!have_xvfb()) GTEST_SKIP() << "Xvfb is not on PATH"

// The event lines of the demo's B-to-A target 22, from hlens-cli trace (A against B: the meshes
// swapped). Tests pick their steps from it by what the event is, not by a fixed number, so that a
// change of the search order (e.g. of the grid) does not silently move them.
std::vector<std::string> demo_trace_lines(const fs::path& dir) {
    Outcome t = run({kCli, "trace", kDemoB, kDemoA, "--target", "22", "--json"}, dir);
    EXPECT_EQ(t.code, 0) << t.err;
    std::vector<std::string> lines;
    std::istringstream in(t.out);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

bool is_event(const std::string& line, const std::string& name) { return line.find("\"" + name + "\"") != std::string::npos; }

// The first step >= from whose event is `name`; -1 if none.
long first_event(const std::vector<std::string>& lines, const std::string& name, size_t from) {
    for (size_t i = from; i < lines.size(); ++i)
        if (is_event(lines[i], name)) return (long)i;
    return -1;
}

}  // namespace

TEST(Gui, UsageErrorsExitTwoWithoutADisplay) {
    fs::path dir = scratch_dir();
    Outcome o = run({kGui, "--size", "3"}, dir);
    EXPECT_EQ(o.code, 2);
    EXPECT_NE(o.err.find("hlens: --size"), std::string::npos) << o.err;
    o = run({kGui, "only_one.obj"}, dir);
    EXPECT_EQ(o.code, 2);
    o = run({kGui, "--direction", "up"}, dir);
    EXPECT_EQ(o.code, 2);
    o = run({kGui, "--help"}, dir);
    EXPECT_EQ(o.code, 0);
    EXPECT_NE(o.out.find("--screenshot"), std::string::npos);
}

TEST(Gui, DemoScreenshotShowsTheMeshesAndTheColourMap) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "demo.png";
    Outcome o = run_gui({}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    ASSERT_EQ(im.h, 600);

    // One JSON line: the state behind the picture, with the view rectangle in image pixels.
    EXPECT_EQ(std::count(o.out.begin(), o.out.end(), '\n'), 1) << o.out;
    EXPECT_EQ(raw_value(o.out, "direction"), "\"ab\"");
    EXPECT_EQ(raw_value(o.out, "target"), "null");
    EXPECT_EQ(raw_value(o.out, "units"), "null");
    std::vector<int> vp = int_list(o.out, "viewport");
    ASSERT_EQ(vp.size(), 4u) << o.out;
    const int vx = vp[0], vw = vp[2], vh = vp[3];
    EXPECT_GT(vx, 0);            // the sidebar is on the left
    EXPECT_EQ(vx + vw, im.w);
    EXPECT_EQ(vh, im.h);

    // The clear colour at the bottom-right corner of the view.
    EXPECT_TRUE(near(im.at(im.w - 3, im.h - 3), kClear, 2));
    // The meshes are drawn: most of the view's centre is not background.
    const int cx = vx + vw / 2, cy = vh / 2, r = std::min(vw, vh) / 8;
    int drawn = count(im, cx - r, cy - r, cx + r, cy + r, [](auto p) { return !near(p, kClear, 6); });
    EXPECT_GT(drawn, (2 * r) * (2 * r) * 3 / 4);
    // The colour map is applied to the measured mesh (A): both ends of it appear, lit, in the
    // view (below the target panel at the top right; the colour bar is in the sidebar).
    const int x0 = vx + vw / 20, x1 = vx + vw - vw / 20, y0 = vh * 3 / 10, y1 = vh * 19 / 20;
    int low = count(im, x0, y0, x1, y1, [](auto p) { return shaded(p, kMapLow, 8); });
    int high = count(im, x0, y0, x1, y1, [](auto p) { return shaded(p, kMapHigh, 8); });
    EXPECT_GT(low, 30) << "low end of the colour map on the mesh";
    EXPECT_GT(high, 30) << "high end of the colour map on the mesh";
    // ... and the colour bar in the sidebar shows both ends unlit.
    EXPECT_GT(count(im, 0, 0, vx, im.h, [](auto p) { return near(p, kMapLow, 3); }), 10);
    EXPECT_GT(count(im, 0, 0, vx, im.h, [](auto p) { return near(p, kMapHigh, 3); }), 10);
    // No error panel.
    EXPECT_EQ(count(im, 0, 0, im.w, im.h, [](auto p) { return near(p, kErrorBg, 2); }), 0);

    // The distances behind the picture are hlens-cli's.
    CliDistance cli = cli_distance(dir);
    EXPECT_NEAR(num(o.out, "hausdorff"), cli.hausdorff, 1e-12);
    EXPECT_NEAR(num(o.out, "a_to_b"), cli.a_to_b, 1e-12);
    EXPECT_NEAR(num(o.out, "b_to_a"), cli.b_to_a, 1e-12);
}

TEST(Gui, MissingMeshShowsTheErrorPanelAndExitsTwo) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "error.png";
    const std::string missing = (dir / "no_such_mesh.obj").string();
    Outcome o = run_gui({missing, kDemoB}, png, dir);
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_NE(o.err.find("hlens: " + missing + ": "), std::string::npos) << o.err;
    EXPECT_EQ(o.out, "");
    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    ASSERT_EQ(im.h, 600);
    EXPECT_GT(count(im, 0, 0, im.w, im.h, [](auto p) { return near(p, kErrorBg, 2); }), 5000);
}

TEST(Gui, MalformedMeshShowsTheErrorPanelAndExitsTwo) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "error.png";
    const fs::path bad = dir / "bad.obj";
    std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nf 1 2 9\n";
    Outcome o = run_gui({kDemoA, bad.string()}, png, dir);
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_NE(o.err.find("hlens: " + bad.string() + ": "), std::string::npos) << o.err;
    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    EXPECT_GT(count(im, 0, 0, im.w, im.h, [](auto p) { return near(p, kErrorBg, 2); }), 5000);
}

TEST(Gui, TargetStateMatchesTheCli) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "target.png";
    CliDistance cli = cli_distance(dir);
    ASSERT_GE(cli.target_ab, 0);
    Outcome o = run_gui({"--target", std::to_string(cli.target_ab)}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(raw_value(o.out, "direction"), "\"ab\"");
    EXPECT_EQ((long)num(o.out, "target"), cli.target_ab);
    EXPECT_NEAR(num(o.out, "hausdorff"), cli.hausdorff, 1e-12);
    // The witness target's maximum is h(A,B), and the trace's maximum agrees.
    EXPECT_NEAR(num(o.out, "target_max"), cli.a_to_b, 1e-12);
    EXPECT_NEAR(num(o.out, "trace_max"), cli.a_to_b, 1e-12);
    // The trace summary is hlens-cli trace's (same grid, same side, same target).
    Outcome t = run({kCli, "trace", kDemoA, kDemoB, "--target", std::to_string(cli.target_ab), "--json"}, dir);
    ASSERT_EQ(t.code, 0) << t.err;
    std::string last = t.out.substr(t.out.rfind("{\"event\": \"final\""));
    EXPECT_EQ(num(o.out, "insertions"), num(last, "insertions"));
    EXPECT_EQ(num(o.out, "domains"), num(last, "domains"));
    EXPECT_EQ(num(o.out, "arcs"), num(last, "arcs"));
    EXPECT_EQ(num(o.out, "vertices"), num(last, "vertices"));
    // The selected target is highlighted.
    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    std::vector<int> vp = int_list(o.out, "viewport");
    ASSERT_EQ(vp.size(), 4u);
    EXPECT_GT(count(im, vp[0], 0, im.w, im.h, [](auto p) { return shaded(p, kSelected, 10); }), 5);
}

TEST(Gui, DirectionBaColoursAndTargetsB) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "ba.png";
    CliDistance cli = cli_distance(dir);
    ASSERT_GE(cli.target_ba, 0);
    Outcome o = run_gui({"--direction", "ba", "--target", std::to_string(cli.target_ba)}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(raw_value(o.out, "direction"), "\"ba\"");
    EXPECT_EQ((long)num(o.out, "target"), cli.target_ba);
    EXPECT_NEAR(num(o.out, "target_max"), cli.b_to_a, 1e-12);
    EXPECT_NEAR(num(o.out, "trace_max"), cli.b_to_a, 1e-12);
    EXPECT_GT(num(o.out, "insertions"), 0);
    EXPECT_GT(num(o.out, "domains"), 0);
    EXPECT_NEAR(num(o.out, "hausdorff"), cli.hausdorff, 1e-12);
    Image im = load_png(png);
    ASSERT_EQ(im.h, 600);
    std::vector<int> vp = int_list(o.out, "viewport");
    ASSERT_EQ(vp.size(), 4u);
    EXPECT_GT(count(im, vp[0], 0, im.w, im.h, [](auto p) { return shaded(p, kSelected, 10); }), 20);
}

// Mouse input, played through Dear ImGui's input state in headless runs (--click, --drag,
// --double-click): a click picks through the ID buffer, a drag orbits and does not pick, a
// double-click recentres on the surface point under the mouse.
struct DemoView {
    Image im;
    int vx = 0, vw = 0, vh = 0;
    double yaw = NAN;
};

DemoView plain_demo(const fs::path& dir) {
    DemoView d;
    Outcome o = run_gui({}, dir / "plain.png", dir);
    EXPECT_EQ(o.code, 0) << o.err;
    d.im = load_png(dir / "plain.png");
    std::vector<int> vp = int_list(o.out, "viewport");
    if (vp.size() == 4) {
        d.vx = vp[0];
        d.vw = vp[2];
        d.vh = vp[3];
    }
    d.yaw = num(o.out, "yaw");
    return d;
}

int selected_near(const Image& im, int x, int y, int r) {
    return count(im, x - r, y - r, x + r + 1, y + r + 1, [](auto p) { return shaded(p, kSelected, 10); });
}

TEST(Gui, ClickPicksTheTriangleUnderTheMouse) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir();
    DemoView d = plain_demo(dir);
    ASSERT_EQ(d.im.w, 800);
    const int x = d.vx + d.vw / 2, y = d.vh / 2;
    ASSERT_FALSE(near(d.im.at(x, y), kClear, 6)) << "the view centre should show the mesh";
    Outcome o = run_gui({"--click", std::to_string(x) + "," + std::to_string(y)}, dir / "click.png", dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const double t = num(o.out, "target");
    ASSERT_GE(t, 0) << o.out;
    EXPECT_LT(t, 512);
    // The picked triangle is the one drawn under the mouse: it is highlighted there.
    EXPECT_GT(selected_near(load_png(dir / "click.png"), x, y, 4), 5);
    // Its trace ran; an exact target_max is the trace's maximum, a skipped one bounds it.
    const double tm = num(o.out, "target_max"), trm = num(o.out, "trace_max");
    if (raw_value(o.out, "target_exact") == "true")
        EXPECT_NEAR(trm, tm, 1e-12);
    else
        EXPECT_LE(trm, tm * (1 + 1e-12));
    EXPECT_GT(num(o.out, "insertions"), 0);
    EXPECT_NEAR(num(o.out, "yaw"), d.yaw, 1e-12);   // a click does not orbit
}

TEST(Gui, DragOrbitsAndDoesNotPick) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir();
    DemoView d = plain_demo(dir);
    const int x = d.vx + d.vw / 2, y = d.vh / 2;
    Outcome o = run_gui({"--drag", std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(x + 120) + "," +
                                       std::to_string(y - 20)},
                        dir / "drag.png", dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(raw_value(o.out, "target"), "null") << "a click that ended a drag must not pick";
    EXPECT_GT(std::fabs(num(o.out, "yaw") - d.yaw), 0.3) << "left-drag orbits";
}

TEST(Gui, ClickOnTheBackgroundClearsTheSelection) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir();
    DemoView d = plain_demo(dir);
    // A background pixel of the view, left of the mesh, below the target panel.
    int bx = -1, by = d.vh / 4;
    for (int x = d.vx + 5; x < d.vx + d.vw / 3; ++x)
        if (near(d.im.at(x, by), kClear, 1) && near(d.im.at(x, by + 6), kClear, 1) && near(d.im.at(x, by - 6), kClear, 1)) {
            bx = x + 4;
            break;
        }
    ASSERT_GE(bx, 0);
    Outcome o = run_gui({"--target", "258", "--click", std::to_string(bx) + "," + std::to_string(by)}, dir / "bg.png", dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(raw_value(o.out, "target"), "null");
}

TEST(Gui, DoubleClickRecentresOnTheSurfacePoint) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir();
    DemoView d = plain_demo(dir);
    // A point of the mesh away from the view centre.
    const int x = d.vx + d.vw * 7 / 10, y = d.vh * 55 / 100;
    ASSERT_FALSE(near(d.im.at(x, y), kClear, 6)) << "the test point should be on the mesh";
    Outcome o = run_gui({"--double-click", std::to_string(x) + "," + std::to_string(y)}, dir / "dbl.png", dir);
    ASSERT_EQ(o.code, 0) << o.err;
    // The first click picked the triangle there; the double-click moved that point to the view
    // centre (and its release did not pick again), so the selected triangle is now at the centre.
    ASSERT_GE(num(o.out, "target"), 0) << o.out;
    EXPECT_GT(selected_near(load_png(dir / "dbl.png"), d.vx + d.vw / 2, d.vh / 2, 4), 5);
}

TEST(Gui, HomeResetsTheCameraAfterADrag) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir();
    DemoView d = plain_demo(dir);
    const int x = d.vx + d.vw / 2, y = d.vh / 2;
    Outcome o = run_gui({"--drag", std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(x - 150) + "," +
                                       std::to_string(y + 40),
                         "--key", "home"},
                        dir / "home.png", dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_NEAR(num(o.out, "yaw"), d.yaw, 1e-6);
    // The same picture as without the drag (up to the status line, which is not drawn here).
    Image a = d.im, b = load_png(dir / "home.png");
    ASSERT_EQ(b.w, a.w);
    int differ = 0;
    for (int yy = 0; yy < a.h; ++yy)
        for (int xx = d.vx; xx < a.w; ++xx) differ += !near(a.at(xx, yy), b.at(xx, yy), 2);
    EXPECT_LT(differ, 50);
}

TEST(Gui, F12SavesAPngInTheCurrentDirectory) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), cwd = dir / "cwd";
    fs::create_directories(cwd);
    Outcome o = run_gui({kDemoA, kDemoB, "--key", "f12"}, dir / "final.png", dir, cwd);
    ASSERT_EQ(o.code, 0) << o.err;
    std::vector<fs::path> saved;
    for (const auto& e : fs::directory_iterator(cwd)) saved.push_back(e.path());
    ASSERT_EQ(saved.size(), 1u);
    const std::string name = saved[0].filename().string();
    EXPECT_EQ(name.rfind("hlens-", 0), 0u) << name;
    EXPECT_EQ(saved[0].extension(), ".png");
    Image im = load_png(saved[0]);
    EXPECT_EQ(im.w, 800);
    EXPECT_EQ(im.h, 600);
}

TEST(Gui, TargetOutOfRangeShowsTheErrorPanelAndExitsTwo) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "range.png";
    Outcome o = run_gui({"--target", "100000"}, png, dir);
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_NE(o.err.find("out of range"), std::string::npos) << o.err;
    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    EXPECT_GT(count(im, 0, 0, im.w, im.h, [](auto p) { return near(p, kErrorBg, 2); }), 5000);
}

// --step N opens the timeline and the domain view of the target after event N of its
// construction. hlens-cli trace measures A against B, so the B-to-A target is traced with the
// meshes swapped (the same grid over the same two meshes: the same event stream).
TEST(Gui, StepShowsTheTargetMidConstruction) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "step.png";
    // Independently: replay hlens-cli's event stream. The view shows the state at event k itself
    // (the debugger keeps a snapshot at each event inside an insertion): one domain (T') plus what
    // every split up to event k added, minus every merge up to it. k: the first event inside an
    // insertion (a split, a relabel or a merge) from 40 on with at least 20 domains to colour.
    const std::vector<std::string> lines = demo_trace_lines(dir);
    long k = -1, created = 0, expect = 1;
    for (size_t i = 0; i < lines.size() && k < 0; ++i) {
        const std::string& l = lines[i];
        if (is_event(l, "domain_created") || is_event(l, "domain_split")) ++created;
        if (is_event(l, "domain_split")) expect += (long)int_list(l, "faces").size() - 1;
        if (is_event(l, "domain_merged")) --expect;
        if (i >= 40 && expect >= 20 && l.find("\"domain_") != std::string::npos) k = (long)i;
    }
    ASSERT_GE(k, 40);
    Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", std::to_string(k)}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ((long)num(o.out, "step"), k);
    EXPECT_EQ(raw_value(o.out, "step_finished"), "false");
    const size_t at = o.out.find("\"step_state\"");
    ASSERT_NE(at, std::string::npos) << o.out;
    const long domains = (long)num(o.out, "domains", at), insertions = (long)num(o.out, "insertions", at);
    EXPECT_EQ((long)num(o.out, "inserting", at), (long)num(lines[k], "source"));
    EXPECT_GT(created, 0);
    EXPECT_EQ(insertions, (long)num(lines[k], "insertion"));
    EXPECT_EQ(domains, expect);
    EXPECT_GT(domains, 1);

    // The domain view shows the domains in distinct colours.
    std::vector<int> r = int_list(o.out, "domain_view");
    ASSERT_EQ(r.size(), 4u);
    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    EXPECT_GT(r[2], 100);
    EXPECT_GT(r[3], 100);
    std::vector<int> colours;
    for (int y = r[1]; y < std::min(im.h, r[1] + r[3]); y += 2)
        for (int x = r[0]; x < std::min(im.w, r[0] + r[2]); x += 2) {
            auto p = im.at(x, y);
            colours.push_back((p[0] / 8) << 10 | (p[1] / 8) << 5 | (p[2] / 8));
        }
    std::sort(colours.begin(), colours.end());
    // Colours covering at least 100 sampled pixels: the background plus the domains' fills.
    int big = 0;
    for (size_t i = 0; i < colours.size();) {
        size_t j = i;
        while (j < colours.size() && colours[j] == colours[i]) ++j;
        big += j - i >= 100;
        i = j;
    }
    EXPECT_GE(big, 5) << "too few distinct fills in the domain view";

    // --step end: the finished target, the same state as the trace summary.
    fs::path png2 = dir / "end.png";
    Outcome e = run_gui({"--direction", "ba", "--target", "22", "--step", "end"}, png2, dir);
    ASSERT_EQ(e.code, 0) << e.err;
    EXPECT_EQ(raw_value(e.out, "step_finished"), "true");
    const size_t at2 = e.out.find("\"step_state\"");
    ASSERT_NE(at2, std::string::npos);
    EXPECT_EQ(num(e.out, "domains", at2), num(e.out, "domains"));
    EXPECT_EQ(num(e.out, "arcs", at2), num(e.out, "arcs"));
    EXPECT_EQ(num(e.out, "insertions", at2), num(e.out, "insertions"));
    EXPECT_EQ((long)num(e.out, "step") + 1, (long)num(lines.back(), "step"));
}

// Right steps one event forward, Left one back (a replay from the start).
TEST(Gui, ArrowKeysStepTheTimeline) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "keys.png";
    Outcome f = run_gui({"--direction", "ba", "--target", "22", "--step", "40", "--key", "right", "--key", "right"}, png, dir);
    ASSERT_EQ(f.code, 0) << f.err;
    EXPECT_EQ((long)num(f.out, "step"), 42);
    // Back from the step after a merge: the view names the merge (the trace's event there).
    const long merge = first_event(demo_trace_lines(dir), "domain_merged", 20);
    ASSERT_GT(merge, 0);
    Outcome b = run_gui({"--direction", "ba", "--target", "22", "--step", std::to_string(merge + 1), "--key", "left"}, png, dir);
    ASSERT_EQ(b.code, 0) << b.err;
    EXPECT_EQ((long)num(b.out, "step"), merge);
    EXPECT_EQ(raw_value(b.out, "step_event"), "\"domain_merged\"");
}

TEST(Gui, StepNeedsTarget) {
    fs::path dir = scratch_dir();
    Outcome o = run({kGui, "--step", "3", "--screenshot", (dir / "x.png").string()}, dir);
    EXPECT_EQ(o.code, 2);
    EXPECT_NE(o.err.find("--step needs --target"), std::string::npos) << o.err;
}


// --event-log opens the event log with the timeline: every event of the target's construction
// (as many as hlens-cli trace prints, less its final summary line), all shown with no filter.
TEST(Gui, EventLogListsEveryEventOfTheTarget) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "event_log.png";
    Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", "100", "--event-log"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ((long)num(o.out, "step"), 100);
    const size_t at = o.out.find("\"event_log\"");
    ASSERT_NE(at, std::string::npos) << o.out;
    const long shown = (long)num(o.out, "shown", at), total = (long)num(o.out, "total", at);
    const std::vector<std::string> trace = demo_trace_lines(dir);
    const long lines = (long)std::count_if(trace.begin(), trace.end(), [](const std::string& l) { return !l.empty(); });
    EXPECT_EQ(total, lines - 1);
    EXPECT_EQ(shown, total);
    EXPECT_GT(total, 100);
}

// --case NAME loads a built-in degenerate configuration. shared_edge: A = T0 (the unit right
// triangle in z = 0), B = (1,0,0),(0,1,0),(0,0,1). d(., B) is convex, so h(A,B) is at a vertex
// of A: the origin projects to B's centroid at 1/sqrt3; (1,0,0) and (0,1,0) are B's corners.
// With --epsilon E, B moves by E along its normal: 1/sqrt3 + E.
TEST(Gui, BuiltinCaseHasItsHandValue) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "case.png";
    Outcome o = run_gui({"--case", "shared_edge", "--target", "0"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_NEAR(num(o.out, "a_to_b"), 1 / std::sqrt(3.0), 1e-12) << o.out;
    EXPECT_EQ((long)num(o.out, "target"), 0);
    Outcome e = run_gui({"--case", "shared_edge", "--epsilon", "1e-3", "--target", "0"}, png, dir);
    ASSERT_EQ(e.code, 0) << e.err;
    EXPECT_NEAR(num(e.out, "a_to_b"), 1 / std::sqrt(3.0) + 1e-3, 1e-12) << e.out;
    // Other hand values: perpendicular (B in y = 0.25 crossing A): 0.75; target_in_source_plane: 2.
    Outcome p = run_gui({"--case", "perpendicular", "--target", "0"}, png, dir);
    ASSERT_EQ(p.code, 0) << p.err;
    EXPECT_NEAR(num(p.out, "a_to_b"), 0.75, 1e-12);
    Outcome q = run_gui({"--case", "target_in_source_plane", "--target", "0"}, png, dir);
    ASSERT_EQ(q.code, 0) << q.err;
    EXPECT_NEAR(num(q.out, "a_to_b"), 2.0, 1e-12);
    Outcome bad = run({kGui, "--case", "nonsense", "--screenshot", (dir / "x.png").string()}, dir);
    EXPECT_EQ(bad.code, 2);
}

// A target without a domain mesh says what it is and how it is measured, in the state JSON and in
// the domain view. The sliver case's A is (0,0,0), (1,0,0), (0.5,eps,0): its longest edge is 1 and
// its height over it eps (below 1e-7: a sliver); at eps = 0 it is a segment. shared_edge's T0 has a
// domain mesh. The view's note runs over several lines (the old one-line note had none below its
// first line).
TEST(Gui, DegenerateTargetSaysWhatItIs) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "sliver.png";
    Outcome o = run_gui({"--case", "sliver", "--epsilon", "1e-9", "--target", "0", "--step", "end"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const size_t at = o.out.find("\"degenerate_target\": {\"kind\": \"sliver\"");
    ASSERT_NE(at, std::string::npos) << o.out;
    EXPECT_NEAR(num(o.out, "height", at), 1e-9, 1e-18);
    EXPECT_NEAR(num(o.out, "longest_edge", at), 1, 1e-15);
    const std::vector<int> r = int_list(o.out, "domain_view");
    ASSERT_EQ(r.size(), 4u);
    const int em = (int)num(o.out, "font_size");
    ASSERT_GT(em, 5);
    Image im = load_png(png);
    const int text = count(im, r[0], r[1] + 2 * em + em / 2, r[0] + r[2], r[1] + 6 * em,
                           [](std::array<int, 3> p) { return near(p, {220, 220, 220}, 60); });
    EXPECT_GT(text, 100) << "the note's further lines are missing";

    Outcome z = run_gui({"--case", "sliver", "--epsilon", "0", "--target", "0", "--step", "end"}, png, dir);
    ASSERT_EQ(z.code, 0) << z.err;
    const size_t at2 = z.out.find("\"degenerate_target\": {\"kind\": \"segment\"");
    ASSERT_NE(at2, std::string::npos) << z.out;
    EXPECT_EQ(num(z.out, "height", at2), 0.0);
    EXPECT_EQ(num(z.out, "longest_edge", at2), 1.0);

    Outcome n = run_gui({"--case", "shared_edge", "--target", "0", "--step", "end"}, png, dir);
    ASSERT_EQ(n.code, 0) << n.err;
    EXPECT_EQ(raw_value(n.out, "degenerate_target"), "null") << n.out;
}

// --export-case DIR writes the selected target and its relevant sources; the pair alone has the
// same one-sided distance as the target's maximum in the whole meshes.
TEST(Gui, ExportCaseReproducesTheTargetMaximum) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "export.png", out = dir / "exported";
    fs::create_directories(out);
    Outcome o = run_gui({"--target", "258", "--export-case", out.string()}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const double target_max = num(o.out, "target_max");
    const fs::path t = out / "hlens-case-258-target.obj", s = out / "hlens-case-258-sources.obj";
    ASSERT_TRUE(fs::exists(t));
    ASSERT_TRUE(fs::exists(s));
    Outcome c = run({kCli, "distance", t.string(), s.string(), "--one-sided", "--json"}, dir);
    ASSERT_EQ(c.code, 0) << c.err;
    const size_t ab = c.out.find("\"a_to_b\": {");
    ASSERT_NE(ab, std::string::npos) << c.out;
    EXPECT_EQ(num(c.out, "distance", ab), target_max);
    // An unwritable directory is an error (exit 2).
    Outcome bad = run_gui({"--target", "258", "--export-case", (dir / "no" / "such" / "dir").string()}, png, dir);
    EXPECT_EQ(bad.code, 2);
}

// A click on a line of the event log jumps the timeline to that step (here back from 100 to 97,
// a replay), and the arrow keys still step from there.
TEST(Gui, EventLogClickJumpsToTheStep) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "event_log_click.png";
    // Where the log shows step 100 (all kinds shown: one line per step); three lines up is step 97.
    Outcome p = run_gui({"--direction", "ba", "--target", "22", "--step", "100", "--event-log"}, png, dir);
    ASSERT_EQ(p.code, 0) << p.err;
    const size_t at = p.out.find("\"event_log\"");
    ASSERT_NE(at, std::string::npos) << p.out;
    const double x = num(p.out, "current_x", at), y = num(p.out, "current_y", at), h = num(p.out, "row_h", at);
    ASSERT_GT(y, 3 * h) << p.out;
    const std::string click = std::to_string((int)x) + "," + std::to_string((int)std::lround(y - 3 * h));
    Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", "100", "--event-log", "--click", click}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ((long)num(o.out, "step"), 97);
    Outcome k = run_gui({"--direction", "ba", "--target", "22", "--step", "100", "--event-log", "--click", click, "--key",
                         "right", "--key", "right"},
                        png, dir);
    ASSERT_EQ(k.code, 0) << k.err;
    EXPECT_EQ((long)num(k.out, "step"), 99);
}

// The 3D view highlights the sources inserted up to the current step, and the timeline plots the
// search radius after each insertion: as many sources and points as insertions so far.
TEST(Gui, SearchRadiusFollowsTheInsertions) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "radius.png";
    Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", "1500"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const size_t at = o.out.find("\"step_state\"");
    ASSERT_NE(at, std::string::npos) << o.out;
    const long ins = (long)num(o.out, "insertions", at);
    EXPECT_GT(ins, 10);
    EXPECT_EQ((long)num(o.out, "highlighted", at), ins);
    EXPECT_EQ((long)num(o.out, "radius_plot", at), ins);
    EXPECT_EQ(num(o.out, "search_radius", at), num(o.out, "max", at));
}

// --graph: the graph of d^2 over T' is sampled with TargetSolver::direct_d2 (exact, frame units)
// and reported in world units (times scale^2). Its maximum includes the marked maximum
// (direct_d2 at max_point_2d), so it must equal the solver's max_sq (world units) to rounding,
// and no grid sample may lie above it.
TEST(Gui, GraphMaximumIsTheSolversMaximum) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "graph.png";
    // Mid-construction: the last event of an insertion (the one before the next source is chosen).
    const long mid = first_event(demo_trace_lines(dir), "source_chosen", 50) - 1;
    ASSERT_GT(mid, 0);
    for (const std::string& step : {std::string("end"), std::to_string(mid)}) {
        Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", step, "--graph"}, png, dir);
        ASSERT_EQ(o.code, 0) << o.err;
        const size_t at = o.out.find("\"graph\"");
        ASSERT_NE(at, std::string::npos) << o.out;
        const double samples = num(o.out, "samples", at), z_max = num(o.out, "z_max", at), grid = num(o.out, "grid_max", at);
        const double max = num(o.out, "max", o.out.find("\"step_state\""));
        EXPECT_EQ(samples, 65 * 66 / 2);
        EXPECT_NEAR(z_max, max * max, 1e-12 * max * max) << step;
        EXPECT_LE(grid, z_max * (1 + 1e-12)) << step;
        EXPECT_GT(grid, 0.5 * z_max) << step;
    }
}

// --overlay colours T' by the nearest source feature, computed from the inserted sources alone
// (a point-triangle region test per source, double precision) and compares it with the domain
// mesh's label at every overlay pixel (256 along T''s longer side). Pixels within 2 of a change of
// either labelling are not compared: a pixel centre that close to a boundary may fall on either
// side of the exact curve versus its sampled drawing, which says nothing about the labels. Away
// from changes the labels must agree exactly (a tie between sources sharing an edge or a corner
// counts as agreement), so disagree must be 0, at the end and mid construction.
TEST(Gui, OverlayAgreesWithTheDomainMesh) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "overlay.png";
    for (const char* step : {"end", "200"}) {
        Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", step, "--overlay"}, png, dir);
        ASSERT_EQ(o.code, 0) << o.err;
        const size_t at = o.out.find("\"overlay\"");
        ASSERT_NE(at, std::string::npos) << o.out;
        const double samples = num(o.out, "samples", at), disagree = num(o.out, "disagree", at),
                     ignored = num(o.out, "ignored", at);
        EXPECT_EQ(disagree, 0) << step << ": " << o.out;
        EXPECT_GT(samples, 5000) << step;
        EXPECT_GT(samples, ignored) << step;   // most of T' is compared
    }
}

// A left-drag inside the graph window orbits the graph (its yaw and pitch change), not the 3D view.
TEST(Gui, DragInTheGraphOrbitsTheGraph) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "graph_drag.png";
    Outcome a = run_gui({"--direction", "ba", "--target", "22", "--step", "end", "--graph"}, png, dir);
    ASSERT_EQ(a.code, 0) << a.err;
    const size_t ga = a.out.find("\"graph\"");
    ASSERT_NE(ga, std::string::npos) << a.out;
    std::vector<int> r = int_list(a.out.substr(ga), "rect");
    ASSERT_EQ(r.size(), 4u) << a.out;
    const int cx = r[0] + r[2] / 2, cy = r[1] + r[3] / 2;
    const std::string drag = std::to_string(cx) + "," + std::to_string(cy) + "," + std::to_string(cx + 80) + "," +
                             std::to_string(cy - 30);
    Outcome b = run_gui({"--direction", "ba", "--target", "22", "--step", "end", "--graph", "--drag", drag}, png, dir);
    ASSERT_EQ(b.code, 0) << b.err;
    const size_t gb = b.out.find("\"graph\"");
    ASSERT_NE(gb, std::string::npos) << b.out;
    EXPECT_NE(num(a.out, "yaw", ga), num(b.out, "yaw", gb));
    EXPECT_NE(num(a.out, "pitch", ga), num(b.out, "pitch", gb));
    EXPECT_EQ(num(a.out, "yaw", a.out.find("\"camera\"")), num(b.out, "yaw", b.out.find("\"camera\"")));
    EXPECT_EQ(num(a.out, "z_max", ga), num(b.out, "z_max", gb));
}

// "voxels & radius": the voxels seen up to the current step, by state. Visited and culled are
// the voxel_visited / voxel_culled events of hlens-cli trace up to that step (B to A: swapped).
TEST(Gui, VoxelsFollowTheEventStream) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir();
    const std::vector<std::string> lines = demo_trace_lines(dir);
    ASSERT_FALSE(lines.empty());
    for (const char* step : {"40", "end"}) {
        fs::path png = dir / (std::string("voxels-") + step + ".png");
        Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", step}, png, dir);
        ASSERT_EQ(o.code, 0) << o.err;
        const size_t at = o.out.find("\"voxels\"");
        ASSERT_NE(at, std::string::npos) << o.out;
        const long cur = (long)num(o.out, "step");
        long visited = 0, culled = 0;
        for (const std::string& l : lines) {
            if (l.find("\"event\": \"final\"") != std::string::npos || (long)num(l, "step") > cur) continue;
            visited += l.find("\"voxel_visited\"") != std::string::npos;
            culled += l.find("\"voxel_culled\"") != std::string::npos;
        }
        EXPECT_GT((long)num(o.out, "visited", at), 0) << step;
        EXPECT_EQ((long)num(o.out, "visited", at), visited) << step;
        EXPECT_EQ((long)num(o.out, "culled", at), culled) << step;
        EXPECT_GE((long)num(o.out, "pending", at), 0) << step;
    }
}

// F1 opens the Help window; no shortcut acts while a text field has the keyboard (here the
// target window's index field, clicked first).
TEST(Gui, F1ShowsHelpButNotWhileTyping) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "help.png";
    Outcome a = run_gui({"--direction", "ba", "--target", "22", "--key", "f1"}, png, dir);
    ASSERT_EQ(a.code, 0) << a.err;
    EXPECT_EQ(raw_value(a.out, "help"), "true");
    Outcome b = run_gui({"--direction", "ba", "--target", "22", "--click", "620,42", "--key", "f1"}, png, dir);
    ASSERT_EQ(b.code, 0) << b.err;
    EXPECT_EQ(raw_value(b.out, "help"), "false");
    EXPECT_EQ((long)num(b.out, "target"), 22);
}

// ---- Layout, DPI, mouse in both views, play, hover, and the state inside an insertion

// With the timeline open the window is tiled: the domain view left of the 3D view, the graph and
// the event log in a strip under the 3D view, the timeline along the bottom. No two overlap, they
// cover the area right of the sidebar, and the 3D view really renders into its tile.
TEST(Gui, TiledLayoutKeepsEveryViewVisible) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "tiles.png";
    for (const char* size : {"800x600", "1200x760"}) {
        Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", "300", "--graph", "--event-log"}, png, dir, {}, size);
        ASSERT_EQ(o.code, 0) << o.err;
        const int W = std::atoi(size), H = std::atoi(std::strchr(size, 'x') + 1);
        const size_t at = o.out.find("\"tiles\"");
        ASSERT_NE(at, std::string::npos) << o.out;
        auto D = num_list(o.out, "domain", at), T = num_list(o.out, "timeline", at), G = num_list(o.out, "graph", at),
             L = num_list(o.out, "log", at), V = num_list(o.out, "view", at);
        ASSERT_EQ(D.size(), 4u);
        ASSERT_EQ(T.size(), 4u);
        ASSERT_EQ(G.size(), 4u);
        ASSERT_EQ(L.size(), 4u);
        ASSERT_EQ(V.size(), 4u);
        const double sb = num(o.out, "sidebar"), font = num(o.out, "font_size");
        // Domain | 3D view over graph | log, timeline below all of them.
        EXPECT_NEAR(D[0], sb, 0.5);
        EXPECT_NEAR(D[0] + D[2], V[0], 0.5);
        EXPECT_NEAR(V[0] + V[2], W, 0.5);
        EXPECT_NEAR(V[1] + V[3], G[1], 0.5);
        EXPECT_NEAR(G[0], V[0], 0.5);
        EXPECT_NEAR(G[0] + G[2], L[0], 0.5);
        EXPECT_NEAR(L[0] + L[2], W, 0.5);
        EXPECT_NEAR(G[1] + G[3], T[1], 0.5);
        EXPECT_NEAR(D[1] + D[3], T[1], 0.5);
        EXPECT_NEAR(T[0], sb, 0.5);
        EXPECT_NEAR(T[1] + T[3], H, 0.5);
        for (const auto* r : {&D, &T, &G, &L, &V}) {
            EXPECT_GE((*r)[2], 6 * font) << size;
            EXPECT_GE((*r)[3], 5 * font) << size;
        }
        // The 3D view's GL viewport is that tile (x, y from the top, w, h).
        std::vector<int> vp = int_list(o.out, "viewport");
        ASSERT_EQ(vp.size(), 4u);
        EXPECT_NEAR(vp[0], V[0], 1);
        EXPECT_NEAR(vp[1], V[1], 1);
        EXPECT_NEAR(vp[2], V[2], 1);
        EXPECT_NEAR(vp[3], V[3], 1);
        // Its top-left corner shows the 3D view's clear colour, not a window.
        Image im = load_png(png);
        ASSERT_EQ(im.w, W);
        const std::array<int, 3> clear{41, 43, 51};
        EXPECT_GT(count(im, (int)V[0] + 2, (int)V[1] + 2, (int)V[0] + 12, (int)V[1] + 12,
                        [&](std::array<int, 3> p) { return near(p, clear, 3); }),
                  80);
    }
}

// --layout-file: the width the user drags the domain view to is written to the layout file and
// comes back on the next run (interactive runs use ~/.config/hlens/imgui.ini the same way).
TEST(Gui, DraggedLayoutIsRememberedBetweenRuns) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "layout.png", ini = dir / "layout.ini";
    const std::vector<std::string> base = {"--direction", "ba", "--target", "22", "--step", "300", "--layout-file", ini.string()};
    Outcome first = run_gui(base, png, dir);
    ASSERT_EQ(first.code, 0) << first.err;
    auto D0 = num_list(first.out, "domain", first.out.find("\"tiles\""));
    ASSERT_EQ(D0.size(), 4u);
    // Drag the domain view's right edge 60 px to the right.
    const int x = (int)(D0[0] + D0[2]) - 2, y = (int)(D0[1] + 0.5 * D0[3]);
    std::vector<std::string> drag = base;
    drag.insert(drag.end(), {"--drag", std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(x + 60) + "," + std::to_string(y)});
    Outcome dragged = run_gui(drag, png, dir);
    ASSERT_EQ(dragged.code, 0) << dragged.err;
    auto D1 = num_list(dragged.out, "domain", dragged.out.find("\"tiles\""));
    ASSERT_EQ(D1.size(), 4u);
    EXPECT_NEAR(D1[2], D0[2] + 60, 3);
    const std::string text = read_file(ini);
    EXPECT_NE(text.find("[Window][Domain view]"), std::string::npos) << text;
    Outcome again = run_gui(base, png, dir);
    ASSERT_EQ(again.code, 0) << again.err;
    auto D2 = num_list(again.out, "domain", again.out.find("\"tiles\""));
    ASSERT_EQ(D2.size(), 4u);
    EXPECT_NEAR(D2[2], D1[2], 1);
    // Without the file the default comes back.
    Outcome fresh = run_gui({"--direction", "ba", "--target", "22", "--step", "300"}, png, dir);
    auto D3 = num_list(fresh.out, "domain", fresh.out.find("\"tiles\""));
    ASSERT_EQ(D3.size(), 4u);
    EXPECT_NEAR(D3[2], D0[2], 1);
}

// A change of content scale while running (--dpi-scale: as when the window moves to another
// screen) rebuilds the font at that scale, and every size, being a multiple of it, follows.
TEST(Gui, ContentScaleChangeScalesFontAndLayout) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "dpi.png";
    Outcome one = run_gui({"--direction", "ba", "--target", "22", "--step", "300"}, png, dir, {}, "1600x1200");
    Outcome two = run_gui({"--direction", "ba", "--target", "22", "--step", "300", "--dpi-scale", "2"}, png, dir, {}, "1600x1200");
    ASSERT_EQ(one.code, 0) << one.err;
    ASSERT_EQ(two.code, 0) << two.err;
    EXPECT_EQ(num(two.out, "font_size"), 2 * num(one.out, "font_size"));
    EXPECT_NEAR(num(two.out, "sidebar"), 2 * num(one.out, "sidebar"), 1);
    auto T1 = num_list(one.out, "timeline", one.out.find("\"tiles\"")), T2 = num_list(two.out, "timeline", two.out.find("\"tiles\""));
    ASSERT_EQ(T1.size(), 4u);
    ASSERT_EQ(T2.size(), 4u);
    EXPECT_GT(T2[3], 1.5 * T1[3]);   // the timeline's rows are twice as tall
}

// The 3D view: the wheel zooms (the camera comes closer, it does not turn) and a right-drag pans
// (the pivot moves, the camera does not turn). The domain view: the wheel zooms about the mouse
// (every point moves away from it by the zoom factor) and a right-drag moves T' with the mouse.
TEST(Gui, WheelZoomsAndRightDragPansBothViews) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "panzoom.png";
    const std::vector<std::string> base = {"--direction", "ba", "--target", "22", "--step", "end"};
    Outcome o = run_gui(base, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    auto V = num_list(o.out, "view", o.out.find("\"tiles\""));
    ASSERT_EQ(V.size(), 4u);
    const std::string in3d = std::to_string((int)(V[0] + 0.3 * V[2])) + "," + std::to_string((int)(V[1] + 0.7 * V[3]));
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> a = base;
        a.insert(a.end(), extra.begin(), extra.end());
        Outcome r = run_gui(a, png, dir);
        EXPECT_EQ(r.code, 0) << r.err;
        return r;
    };
    Outcome zoomed = with({"--wheel", in3d + ",3"});
    EXPECT_LT(num(zoomed.out, "distance"), 0.8 * num(o.out, "distance"));
    EXPECT_EQ(num(zoomed.out, "yaw"), num(o.out, "yaw"));
    EXPECT_EQ(num(zoomed.out, "pitch"), num(o.out, "pitch"));
    const int x0 = (int)(V[0] + 0.3 * V[2]), y0 = (int)(V[1] + 0.7 * V[3]);
    Outcome panned = with({"--right-drag", std::to_string(x0) + "," + std::to_string(y0) + "," + std::to_string(x0 + 40) + "," + std::to_string(y0)});
    EXPECT_EQ(num(panned.out, "yaw"), num(o.out, "yaw"));
    EXPECT_EQ(num(panned.out, "distance"), num(o.out, "distance"));
    auto p0 = num_list(o.out, "pivot"), p1 = num_list(panned.out, "pivot");
    ASSERT_EQ(p0.size(), 3u);
    ASSERT_EQ(p1.size(), 3u);
    EXPECT_GT(std::fabs(p1[0] - p0[0]) + std::fabs(p1[1] - p0[1]) + std::fabs(p1[2] - p0[2]), 1e-3);

    // Domain view: zoom 2 wheel steps about a point inside T'.
    auto c = num_list(o.out, "corners_on_screen");
    ASSERT_EQ(c.size(), 6u);
    EXPECT_EQ(num(o.out, "domain_zoom"), 1);
    const double mx = std::round((c[0] + c[2] + c[4]) / 3), my = std::round((c[1] + c[3] + c[5]) / 3);
    Outcome dz = with({"--wheel", std::to_string((int)mx) + "," + std::to_string((int)my) + ",2"});
    auto cz = num_list(dz.out, "corners_on_screen");
    ASSERT_EQ(cz.size(), 6u);
    const double f = num(dz.out, "domain_zoom");
    EXPECT_GT(f, 1.2);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(cz[2 * k], mx + f * (c[2 * k] - mx), 1.0);
        EXPECT_NEAR(cz[2 * k + 1], my + f * (c[2 * k + 1] - my), 1.0);
    }
    Outcome dp = with({"--right-drag", std::to_string((int)mx) + "," + std::to_string((int)my) + "," + std::to_string((int)mx + 50) + "," +
                                           std::to_string((int)my + 20)});
    auto cp = num_list(dp.out, "corners_on_screen");
    ASSERT_EQ(cp.size(), 6u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(cp[2 * k], c[2 * k] + 50, 1.0);
        EXPECT_NEAR(cp[2 * k + 1], c[2 * k + 1] + 20, 1.0);
    }
}

// Space plays the timeline at the chosen speed (10 events a second; a headless frame is 1/60 s),
// and without it the step stays put.
TEST(Gui, PlayAdvancesTheTimeline) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "play.png";
    Outcome still = run_gui({"--direction", "ba", "--target", "22", "--step", "100", "--wait", "60"}, png, dir);
    ASSERT_EQ(still.code, 0) << still.err;
    EXPECT_EQ((long)num(still.out, "step"), 100);
    EXPECT_EQ(raw_value(still.out, "playing"), "false");
    Outcome play = run_gui({"--direction", "ba", "--target", "22", "--step", "100", "--key", "space", "--wait", "60"}, png, dir);
    ASSERT_EQ(play.code, 0) << play.err;
    EXPECT_EQ(raw_value(play.out, "playing"), "true");
    const long step = (long)num(play.out, "step");
    EXPECT_GE(step, 108);   // 60 frames at 10 events/s: 10 events, plus the frames before the picture
    EXPECT_LE(step, 115);
}

// Hovering the domain view names what is under the mouse: inside a domain, the domain the
// solver has there (run independently here); on the middle of an edge of T', an arc of the
// target's boundary.
TEST(Gui, HoverNamesTheDomainAndTheArc) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "hover.png";
    Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", "end"}, png, dir, {}, "1400x900");
    ASSERT_EQ(o.code, 0) << o.err;
    auto c = num_list(o.out, "corners_on_screen");
    ASSERT_EQ(c.size(), 6u);

    hlens::TriangleMesh A = hlens::load_mesh(kDemoA), B = hlens::load_mesh(kDemoB);
    hlens::VoxelGrid grid(A, B);
    hlens::TargetSolver ts(grid, 1, 22);
    ts.run();
    const auto& fr = ts.frame();
    const hlens::DomainMesh& dm = *ts.domain_mesh();
    // Frame -> screen: the similarity taking the corners of T' to where the view drew them.
    const double scale = std::hypot(c[2] - c[0], c[3] - c[1]) / hlens::norm(fr.corners[1] - fr.corners[0]);
    auto screen = [&](hlens::Vec2 p) {
        hlens::Vec2 d = p - fr.corners[0];
        return std::array<double, 2>{c[0] + d.x * scale, c[1] - d.y * scale};
    };
    // A point of T' whose domain reaches 10 px around it (away from every arc).
    hlens::Vec2 pick;
    int face = -1;
    const double r = 6 / scale;
    for (int i = 1; i < 12 && face < 0; ++i)
        for (int j = 1; i + j < 12 && face < 0; ++j) {
            hlens::Vec2 p = fr.corners[0] + (fr.corners[1] - fr.corners[0]) * (i / 12.0) + (fr.corners[2] - fr.corners[0]) * (j / 12.0);
            const int f = dm.face_at(p);
            bool clear = f >= 0;
            for (int k = 0; k < 16 && clear; ++k) {
                const double a = k * 3.14159265358979 / 8;
                clear = dm.face_at(p + hlens::Vec2(r * std::cos(a), r * std::sin(a))) == f;
            }
            if (clear) pick = p, face = f;
        }
    ASSERT_GE(face, 0);
    auto q = screen(pick);
    Outcome hov = run_gui({"--direction", "ba", "--target", "22", "--step", "end", "--hover",
                           std::to_string((int)std::lround(q[0])) + "," + std::to_string((int)std::lround(q[1]))},
                          png, dir, {}, "1400x900");
    ASSERT_EQ(hov.code, 0) << hov.err;
    const size_t h = hov.out.find("\"hover\"");
    ASSERT_NE(h, std::string::npos) << hov.out;
    EXPECT_EQ((long)num(hov.out, "source", h), (long)dm.faces()[face].label.source) << hov.out.substr(h, 80);
    EXPECT_EQ(raw_value(hov.out, "region", h), "\"" + std::string(hlens::region_name(dm.faces()[face].label.region)) + "\"");

    const double ex = 0.5 * (c[0] + c[2]), ey = 0.5 * (c[1] + c[3]);
    Outcome arc = run_gui({"--direction", "ba", "--target", "22", "--step", "end", "--hover",
                           std::to_string((int)std::lround(ex)) + "," + std::to_string((int)std::lround(ey))},
                          png, dir, {}, "1400x900");
    ASSERT_EQ(arc.code, 0) << arc.err;
    const size_t ha = arc.out.find("\"hover\"");
    ASSERT_NE(ha, std::string::npos) << arc.out;
    EXPECT_EQ(raw_value(arc.out, "kind", ha), "\"target boundary\"");
}

// Inside an insertion the domain view shows the mesh as it is at that event, and the independent
// overlay still agrees with it: domains the source has taken against all sources, the others
// against the sources before it. Stepping back into an insertion gives the same state again.
TEST(Gui, StateInsideAnInsertionAgreesWithTheOverlay) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "inside.png";
    for (const char* step : {"1490", "1500", "40"}) {
        Outcome o = run_gui({"--direction", "ba", "--target", "22", "--step", step, "--overlay"}, png, dir);
        ASSERT_EQ(o.code, 0) << o.err;
        const size_t at = o.out.find("\"step_state\"");
        EXPECT_GE((long)num(o.out, "inserting", at), 0) << step;
        const size_t ov = o.out.find("\"overlay\": {");
        ASSERT_NE(ov, std::string::npos) << o.out;
        EXPECT_GT((long)num(o.out, "samples", ov), 1000);
        EXPECT_EQ((long)num(o.out, "disagree", ov), 0) << step;
    }
    Outcome at40 = run_gui({"--direction", "ba", "--target", "22", "--step", "40"}, png, dir);
    Outcome back = run_gui({"--direction", "ba", "--target", "22", "--step", "41", "--key", "left"}, png, dir);
    ASSERT_EQ(at40.code, 0) << at40.err;
    ASSERT_EQ(back.code, 0) << back.err;
    EXPECT_EQ((long)num(back.out, "step"), 40);
    for (const char* k : {"domains", "arcs", "vertices", "insertions", "inserting"})
        EXPECT_EQ(num(back.out, k, back.out.find("\"step_state\"")), num(at40.out, k, at40.out.find("\"step_state\""))) << k;
}

// Opening a target's timeline frames the target and the sphere of its largest distance (the
// search region is small on a real mesh); Home goes back to the whole scene.
TEST(Gui, OpeningTheTimelineFramesTheTarget) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "focus.png";
    Outcome whole = run_gui({"--direction", "ba", "--target", "22"}, png, dir);
    Outcome focused = run_gui({"--direction", "ba", "--target", "22", "--step", "10"}, png, dir);
    Outcome home = run_gui({"--direction", "ba", "--target", "22", "--step", "10", "--key", "home"}, png, dir);
    ASSERT_EQ(whole.code, 0) << whole.err;
    ASSERT_EQ(focused.code, 0) << focused.err;
    ASSERT_EQ(home.code, 0) << home.err;
    EXPECT_LT(num(focused.out, "distance"), num(whole.out, "distance"));
    auto p0 = num_list(whole.out, "pivot"), p1 = num_list(focused.out, "pivot"), p2 = num_list(home.out, "pivot");
    auto o = num_list(focused.out, "origin");
    ASSERT_EQ(p1.size(), 3u);
    ASSERT_EQ(p2.size(), 3u);
    ASSERT_EQ(o.size(), 3u);
    // The pivot is the centroid of triangle 22 of B (world = pivot + origin).
    hlens::TriangleMesh B = hlens::load_mesh(kDemoB);
    const auto c = B.corners(22);
    const hlens::Vec3 g = (c[0] + c[1] + c[2]) / 3.0;
    EXPECT_NEAR(p1[0] + o[0], g.x, 1e-5);
    EXPECT_NEAR(p1[1] + o[1], g.y, 1e-5);
    EXPECT_NEAR(p1[2] + o[2], g.z, 1e-5);
    // Home frames the whole scene again (in the 3D tile, a little narrower than the full view).
    EXPECT_GT(num(home.out, "distance"), 0.9 * num(whole.out, "distance"));
    EXPECT_NEAR(p2[0], p0[0], 1e-5);
    EXPECT_NEAR(p2[1], p0[1], 1e-5);
}

#endif  // HLENS_GUI

// ---- The exact colour map (issue 7, item 4): the distances show first, then the exact maximum of
// every triangle fast mode skipped is filled in the background; until then a triangle is drawn
// "not yet exact" (two greys in diagonal stripes), never coloured by its upper bound.
#ifdef HLENS_GUI
#include <hlens/target_maxima.h>

namespace {

// The hatch's greys (app/hlens/colormap.h kNotExactGrey 0.62, 0.46) and their ratio.
constexpr int kHatchLight = 158, kHatchDark = 117;

struct Probe {
    long triangle = -1;
    bool exact = false;
    double value = NAN, bound = NAN;
    int x = -1, y = -1, clear = 0;
};

// The "probes" of the state's "exact_colormap": pixels well inside triangles of the measured mesh.
std::vector<Probe> probes(const std::string& json) {
    std::vector<Probe> r;
    const std::string list = raw_value(json, "probes");
    for (size_t at = list.find("{\"triangle\": "); at != std::string::npos; at = list.find("{\"triangle\": ", at + 1)) {
        Probe p;
        p.triangle = (long)num(list, "triangle", at);
        p.exact = raw_value(list, "exact", at) == "true";
        p.value = num(list, "value", at);
        p.bound = num(list, "bound", at);
        std::vector<double> px = num_list(list, "pixel", at);
        if (px.size() == 2) p.x = (int)px[0], p.y = (int)px[1];
        p.clear = (int)num(list, "clear", at);
        r.push_back(p);
    }
    return r;
}

// Grey: the three channels equal (up to rounding), not black.
bool grey(const std::array<int, 3>& p) {
    return std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) <= 3 && p[0] > 25;
}

// The pixels of the square of radius r around (x, y).
std::vector<std::array<int, 3>> square(const Image& im, int x, int y, int r) {
    std::vector<std::array<int, 3>> v;
    for (int yy = y - r; yy <= y + r; ++yy)
        for (int xx = x - r; xx <= x + r; ++xx)
            if (xx >= 0 && yy >= 0 && xx < im.w && yy < im.h) v.push_back(im.at(xx, yy));
    return v;
}

// The demo pair zoomed in (5 wheel steps at the view's centre) so its triangles are large enough
// for a probe's square to hold both stripes of the hatch.
const std::vector<std::string> kZoomed = {"--wheel", "550,300,5"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}


// Every probe of the state (exact, on the demo's A) has the value expected(triangle) and is
// coloured as the colour bar at (value - lo) / (hi - lo), not as the bar 0.4 away.
void expect_probes_on_the_bar(const std::string& json, const Image& im, double lo, double hi,
                              const std::function<double(long)>& expected) {
    std::vector<int> bar = int_list(json, "bar");
    ASSERT_EQ(bar.size(), 4u);
    ASSERT_GT(bar[2], 100);
    // The colour bar's colour at t in [0, 1] (its middle row).
    auto bar_colour = [&](double t) {
        return im.at(bar[0] + 1 + (int)std::lround(std::clamp(t, 0.0, 1.0) * (bar[2] - 3)), bar[1] + bar[3] / 2);
    };
    std::vector<Probe> ps = probes(json);
    ASSERT_GE(ps.size(), 3u) << json;
    for (const Probe& p : ps) {
        ASSERT_GE(p.triangle, 0);
        ASSERT_LT(p.triangle, 512);
        EXPECT_TRUE(p.exact);
        EXPECT_EQ(p.value, expected(p.triangle)) << "triangle " << p.triangle;
        const double t = (p.value - lo) / (hi - lo);
        const std::array<int, 3> want = bar_colour(t), other = bar_colour(t < 0.5 ? t + 0.4 : t - 0.4);
        std::vector<std::array<int, 3>> px = square(im, p.x, p.y, std::min(p.clear, 4));
        const long match = std::count_if(px.begin(), px.end(), [&](auto c) { return shaded(c, want, 12); });
        const long wrong = std::count_if(px.begin(), px.end(), [&](auto c) { return shaded(c, other, 12); });
        EXPECT_GT(match, (long)px.size() * 3 / 4)
            << "triangle " << p.triangle << " (t = " << t << ") at " << p.x << "," << p.y << ": " << im.at(p.x, p.y)[0]
            << " " << im.at(p.x, p.y)[1] << " " << im.at(p.x, p.y)[2] << " vs " << want[0] << " " << want[1] << " " << want[2];
        EXPECT_LT(wrong, (long)px.size() / 4) << "triangle " << p.triangle << " looks like t = " << (t < 0.5 ? t + 0.4 : t - 0.4);
    }
}
}  // namespace

// Fill-in disabled: fast mode solved only the triangles that can reach h(A,B); every other one is
// grey and hatched (both greys, equal channels, their ratio), not on the colour scale, and the
// exact ones are coloured (the tied maxima: the top of the map). The legend shows the hatch.
TEST(GuiExactMap, OffDrawsSkippedTrianglesNotYetExact) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "off.png";
    Outcome o = run_gui(with({"--exact-colormap", "off"}, kZoomed), png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const size_t em = o.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos) << o.out;
    EXPECT_EQ(raw_value(o.out, "mode", em), "\"off\"");
    // Only fast mode's exact triangles are known (which ones besides the maxima may depend on
    // the timing of its threads): on the demo pair, few.
    const long fast_exact = (long)num(o.out, "exact", em);
    EXPECT_GE(fast_exact, 1);
    EXPECT_LT(fast_exact, 512 / 4) << "the demo pair: fast mode skips most triangles";
    EXPECT_EQ((long)num(o.out, "triangles", em), 512);
    EXPECT_EQ(raw_value(o.out, "complete", em), "false");
    EXPECT_EQ(raw_value(o.out, "running", em), "false");
    EXPECT_EQ(raw_value(o.out, "complete_at", em), "null");
    CliDistance cli = cli_distance(dir);
    EXPECT_NEAR(num(o.out, "a_to_b"), cli.a_to_b, 1e-12);
    // The range is that of the exact values only: here the tied maxima, h(A,B) (as a float).
    EXPECT_NEAR(num(o.out, "hi", em), cli.a_to_b, 1e-7);
    EXPECT_NEAR(num(o.out, "lo", em), cli.a_to_b, 1e-7) << "a bound must not stretch the range";

    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    std::vector<Probe> ps = probes(o.out);
    int not_exact = 0, exact = 0;
    for (const Probe& p : ps) {
        ASSERT_GE(p.x, 0);
        ASSERT_GE(p.clear, 2);
        const int r = std::min(p.clear, 6);
        std::vector<std::array<int, 3>> px = square(im, p.x, p.y, r);
        if (!p.exact) {
            ++not_exact;
            EXPECT_TRUE(std::isnan(p.value));
            EXPECT_GT(p.bound, 0) << "fast mode has a bound for it, which must not be shown";
            // Every pixel grey; two levels (the stripes), both present, in the hatch's ratio.
            int lo = 255, hi = 0;
            for (const auto& c : px) {
                EXPECT_TRUE(grey(c)) << "triangle " << p.triangle << " at " << p.x << "," << p.y << ": " << c[0] << " "
                                     << c[1] << " " << c[2];
                lo = std::min(lo, c[0]);
                hi = std::max(hi, c[0]);
            }
            if (p.clear >= 4) {   // the square spans a stripe period (8 pixels at this font size)
                EXPECT_NEAR(double(hi) / std::max(lo, 1), double(kHatchLight) / kHatchDark, 0.12)
                    << "triangle " << p.triangle << ": the two greys of the hatch";
                const int mid = (lo + hi) / 2;
                const long light = std::count_if(px.begin(), px.end(), [&](auto c) { return c[0] > mid; });
                EXPECT_GT(light, (long)px.size() / 5);
                EXPECT_LT(light, (long)px.size() * 4 / 5);
            }
        } else {
            ++exact;
            EXPECT_NEAR(p.value, cli.a_to_b, 1e-12) << "fast mode's exact triangles here are the tied maxima";
            const long top = std::count_if(px.begin(), px.end(), [](auto c) { return shaded(c, kMapHigh, 12); });
            EXPECT_GT(top, (long)px.size() * 3 / 4) << "exact triangle " << p.triangle << " is coloured at once";
        }
    }
    EXPECT_GE(not_exact, 2) << o.out;
    EXPECT_GE(exact, 1) << o.out;
    // Most of the mesh is grey, hatched; nothing is a bright spot but the exact maxima (few pixels).
    std::vector<int> vp = int_list(o.out, "viewport");
    ASSERT_EQ(vp.size(), 4u);
    const int y0 = vp[3] / 6, y1 = vp[3] * 9 / 10;
    const int greys = count(im, vp[0], y0, im.w, y1, [](auto p) { return grey(p); });
    EXPECT_GT(greys, (im.w - vp[0]) * (y1 - y0) / 3);
    // The legend shows the hatch, unlit, in the sidebar.
    EXPECT_GT(count(im, 0, 0, vp[0], im.h, [](auto p) { return near(p, {kHatchLight, kHatchLight, kHatchLight}, 2); }), 20);
    EXPECT_GT(count(im, 0, 0, vp[0], im.h, [](auto p) { return near(p, {kHatchDark, kHatchDark, kHatchDark}, 2); }), 20);
}

// Waiting for the fill-in: every triangle is exact, nothing is grey, the range is the exact
// values' (core's exact_target_maxima), and a triangle's colour is its exact value through the
// colour map (read from the colour bar in the same picture), not a colour elsewhere on the map.
TEST(GuiExactMap, WaitColoursEveryTriangleByItsExactMaximum) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "wait.png";
    Outcome o = run_gui(with({"--exact-colormap", "wait"}, kZoomed), png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const size_t em = o.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos) << o.out;
    EXPECT_EQ((long)num(o.out, "exact", em), 512);
    EXPECT_EQ((long)num(o.out, "triangles", em), 512);
    EXPECT_EQ(raw_value(o.out, "complete", em), "true");

    // The exact per-triangle maxima, computed here by the core.
    hlens::TriangleMesh A = hlens::load_mesh(kDemoA), B = hlens::load_mesh(kDemoB);
    hlens::VoxelGrid grid(A, B);
    hlens::TargetMaxima exact = hlens::exact_target_maxima(grid, 0);
    ASSERT_EQ(exact.max.size(), 512u);
    const double lo = *std::min_element(exact.max.begin(), exact.max.end());
    const double hi = *std::max_element(exact.max.begin(), exact.max.end());
    EXPECT_NEAR(num(o.out, "lo", em), lo, 1e-7 * hi);
    EXPECT_NEAR(num(o.out, "hi", em), hi, 1e-7 * hi);
    EXPECT_NEAR(hi, cli_distance(dir).a_to_b, 1e-12);

    Image im = load_png(png);
    ASSERT_EQ(im.w, 800);
    expect_probes_on_the_bar(o.out, im, lo, hi, [&](long t) { return exact.max[t]; });
    // No triangle is left grey (the hatch's greys do not appear on the mesh).
    std::vector<int> vp = int_list(o.out, "viewport");
    ASSERT_EQ(vp.size(), 4u);
    const int y0 = vp[3] / 6, y1 = vp[3] * 9 / 10;
    EXPECT_LT(count(im, vp[0], y0, im.w, y1, [](auto p) { return grey(p) && p[0] > 90; }), 60);
}

// A mesh against itself: every triangle a copy (core/copies.h), every distance 0 exactly, and
// the colour map's range of one value, 0: the mesh is drawn in the map's bottom colour (nothing is
// off), not its top, which a range of one positive value (the tied maxima) gets.
TEST(GuiExactMap, MeshAgainstItselfIsTheBottomColour) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "same.png";
    Outcome o = run_gui(with({kDemoA, kDemoA, "--exact-colormap", "wait"}, kZoomed), png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(num(o.out, "a_to_b"), 0.0);
    EXPECT_EQ(num(o.out, "b_to_a"), 0.0);
    const size_t em = o.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos) << o.out;
    EXPECT_EQ(raw_value(o.out, "complete", em), "true");
    EXPECT_EQ(num(o.out, "hi", em), 0.0);
    Image im = load_png(png);
    std::vector<Probe> ps = probes(o.out);
    ASSERT_GE(ps.size(), 2u) << o.out;
    for (const Probe& p : ps) {
        ASSERT_GE(p.clear, 2);
        EXPECT_EQ(p.value, 0.0);
        const std::vector<std::array<int, 3>> px = square(im, p.x, p.y, std::min(p.clear, 6));
        const long low = std::count_if(px.begin(), px.end(), [](auto c) { return shaded(c, kMapLow, 12); });
        EXPECT_GT(low, (long)px.size() * 3 / 4) << "triangle " << p.triangle;
    }
}

// The distances do not wait for the exact colour map: they are shown when the fast computation
// ends, and the fill-in completes later; a screenshot taken as soon as the distances are known
// has them (hlens-cli's), with the map still being filled or complete, and its picture agrees.
TEST(GuiExactMap, DistancesShowBeforeTheFillInCompletes) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "order.png";
    CliDistance cli = cli_distance(dir);
    // h(B,A) of the demo: 32 large triangles of B over the bumpy A, slow to solve exactly.
    Outcome w = run_gui({"--direction", "ba", "--exact-colormap", "wait"}, png, dir);
    ASSERT_EQ(w.code, 0) << w.err;
    const size_t wem = w.out.find("\"exact_colormap\"");
    ASSERT_NE(wem, std::string::npos);
    const double shown = num(w.out, "distances_at"), complete = num(w.out, "complete_at", wem);
    ASSERT_TRUE(std::isfinite(shown)) << w.out;
    ASSERT_TRUE(std::isfinite(complete)) << w.out;
    EXPECT_LT(shown, complete) << "the distances were shown only with the complete colour map";
    EXPECT_NEAR(num(w.out, "b_to_a"), cli.b_to_a, 1e-12);

    Outcome o = run_gui({"--direction", "ba", "--exact-colormap", "on"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const size_t em = o.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos);
    EXPECT_NEAR(num(o.out, "a_to_b"), cli.a_to_b, 1e-12);
    EXPECT_NEAR(num(o.out, "b_to_a"), cli.b_to_a, 1e-12);
    EXPECT_NEAR(num(o.out, "hausdorff"), cli.hausdorff, 1e-12);
    const long n = (long)num(o.out, "triangles", em), known = (long)num(o.out, "exact", em);
    EXPECT_EQ(n, 32);
    EXPECT_GE(known, 1);   // at least the witness
    EXPECT_LE(known, n);
    const bool done = raw_value(o.out, "complete", em) == "true";
    EXPECT_EQ(done, known == n);
    // Not complete: it is still running (not stalled) and the picture shows grey triangles.
    if (!done) {
        EXPECT_EQ(raw_value(o.out, "running", em), "true");
    }
    Image im = load_png(png);
    std::vector<int> vp = int_list(o.out, "viewport");
    ASSERT_EQ(vp.size(), 4u);
    const int greys = count(im, vp[0], vp[3] / 6, im.w, vp[3] * 9 / 10, [](auto p) { return grey(p) && p[0] > 90; });
    if (done) {
        EXPECT_LT(greys, 60);
    } else {
        EXPECT_GT(greys, 200);
    }
    std::printf("[ info ] screenshot as soon as the distances were known (%.2f s): %ld / %ld triangles exact\n",
                num(o.out, "distances_at"), known, n);
}

// The sidebar's Cancel stops the fill-in (the values found so far stay, the rest stays grey) and
// Continue, in the same place, finishes it. (800x600 demo, B measured: the button's position.)
TEST(GuiExactMap, CancelStopsTheFillInAndContinueFinishesIt) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "cancel.png";
    const std::string button = "240,461";
    // Paced (50 ms a triangle), so that the click comes before the fill-in ends on any machine.
    Outcome c = run_gui({"--direction", "ba", "--exact-colormap", "wait", "--exact-map-pace", "50", "--click", button}, png, dir);
    ASSERT_EQ(c.code, 0) << c.err;
    size_t em = c.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos);
    EXPECT_EQ(raw_value(c.out, "stopped", em), "true") << c.out;
    EXPECT_EQ(raw_value(c.out, "complete", em), "false");
    EXPECT_EQ(raw_value(c.out, "running", em), "false");
    EXPECT_LT((long)num(c.out, "exact", em), 32);
    Image im = load_png(png);
    std::vector<int> vp = int_list(c.out, "viewport");
    ASSERT_EQ(vp.size(), 4u);
    EXPECT_GT(count(im, vp[0], vp[3] / 6, im.w, vp[3] * 9 / 10, [](auto p) { return grey(p) && p[0] > 90; }), 200)
        << "the triangles not reached stay not yet exact";

    Outcome r = run_gui({"--direction", "ba", "--exact-colormap", "wait", "--exact-map-pace", "50", "--click", button, "--wait", "3", "--click", button},
                        png, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    em = r.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos);
    EXPECT_EQ(raw_value(r.out, "stopped", em), "false") << r.out;
    EXPECT_EQ(raw_value(r.out, "complete", em), "true");
    EXPECT_EQ((long)num(r.out, "exact", em), 32);
}

// Switching the direction ("Measure: B to A") fills in the other mesh's map.
TEST(GuiExactMap, SwitchingTheDirectionFillsInTheOtherMesh) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "switch.png";
    Outcome o = run_gui({"--exact-colormap", "wait", "--click", "150,297"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(raw_value(o.out, "direction"), "\"ba\"");
    const size_t em = o.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos);
    EXPECT_EQ((long)num(o.out, "triangles", em), 32);
    EXPECT_EQ((long)num(o.out, "exact", em), 32);
    // Its range is h(B,A)'s exact values: the top is h(B,A).
    EXPECT_NEAR(num(o.out, "hi", em), cli_distance(dir).b_to_a, 1e-7);
}

TEST(GuiExactMap, BadModeIsAUsageError) {
    fs::path dir = scratch_dir();
    Outcome o = run({kGui, "--exact-colormap", "maybe"}, dir);
    EXPECT_EQ(o.code, 2);
    EXPECT_NE(o.err.find("--exact-colormap expects on, off or wait"), std::string::npos) << o.err;
}

#endif  // HLENS_GUI

// --units NAME: passed through to the state and drawn after the colour bar's top value (the label
// is the drawn text: the range's top with 4 digits, then the unit).
TEST(Gui, UnitsLabelTheColourBar) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "units.png";
    Outcome o = run_gui({"--units", "mm"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(raw_value(o.out, "units"), "\"mm\"");
    const size_t em = o.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos) << o.out;
    char want[64];
    std::snprintf(want, sizeof want, "\"%.4g mm\"", num(o.out, "hi", em));
    EXPECT_EQ(raw_value(o.out, "hi_label", em), want);
}

// ---- Exact surface statistics in the debugger (issue 9, item 3)

namespace {
constexpr std::array<int, 3> kPlotBars = {230, 179, 0};   // ImGui's PlotHistogram colour (dark style)

// hlens-cli distance demo_a demo_b --stats --histogram 20 --json [extra...]: the GUI's options.
Outcome cli_stats(const fs::path& dir, std::vector<std::string> extra = {}) {
    std::vector<std::string> argv = {kCli, "distance", kDemoA, kDemoB, "--stats", "--histogram", "20", "--json"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    Outcome c = run(argv, dir);
    EXPECT_TRUE(c.code == 0 || c.code == 4) << c.err;
    return c;
}
}  // namespace

// --stats: the sidebar's statistics of both directions are hlens-cli's, digit for digit (the state
// line prints them as hlens-cli does), and the histograms are drawn; without it nothing is computed.
TEST(GuiStats, StatisticsAreTheClisToTheDigit) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "stats.png";
    Outcome o = run_gui({"--stats"}, png, dir, {}, "800x900");
    ASSERT_EQ(o.code, 0) << o.err;
    const size_t st = o.out.find("\"stats\": {");
    ASSERT_NE(st, std::string::npos) << o.out;
    EXPECT_EQ(raw_value(o.out, "wanted", st), "true");
    EXPECT_EQ(raw_value(o.out, "ready", st), "true");
    Outcome c = cli_stats(dir);
    for (const char* d : {"a_to_b", "b_to_a"}) {
        const std::string gui = raw_value(o.out, d, st), cli = raw_value(c.out, d);
        ASSERT_FALSE(gui.empty()) << o.out;
        for (const char* key : {"area", "mean", "rms", "percentiles", "histogram"}) {
            EXPECT_FALSE(raw_value(cli, key).empty()) << key;
            EXPECT_EQ(raw_value(gui, key), raw_value(cli, key)) << d << " " << key;
        }
    }
    Image im = load_png(png);
    const int vx = int_list(o.out, "viewport")[0];
    EXPECT_GT(count(im, 0, 0, vx, im.h, [](auto p) { return near(p, kPlotBars, 3); }), 400) << "the histograms";

    fs::path png2 = dir / "default.png";
    Outcome d = run_gui({}, png2, dir, {}, "800x900");
    ASSERT_EQ(d.code, 0) << d.err;
    const size_t st2 = d.out.find("\"stats\": {");
    EXPECT_EQ(raw_value(d.out, "wanted", st2), "false");
    EXPECT_EQ(raw_value(d.out, "ready", st2), "false");
    Image im2 = load_png(png2);
    EXPECT_EQ(count(im2, 0, 0, vx, im2.h, [](auto p) { return near(p, kPlotBars, 3); }), 0);
}

namespace {
// The faces of an error map written by hlens-cli --export-errors (ASCII PLY): per face, its
// max, mean and RMS distance; per vertex, its distance.
struct ErrorMap {
    std::vector<std::array<double, 3>> face;   // max, mean, rms
    std::vector<double> vertex;
    std::string header;
};
ErrorMap read_error_ply(const fs::path& p) {
    ErrorMap m;
    std::ifstream in(p);
    size_t nv = 0, nf = 0;
    for (std::string line; std::getline(in, line) && line != "end_header";) {
        m.header += line + "\n";
        std::istringstream ls(line);
        std::string w, what;
        ls >> w >> what;
        if (w == "element" && what == "vertex") ls >> nv;
        if (w == "element" && what == "face") ls >> nf;
    }
    for (size_t v = 0; v < nv; ++v) {
        double x, y, z, q, d;
        in >> x >> y >> z >> q >> d;
        m.vertex.push_back(d);
    }
    for (size_t f = 0; f < nf; ++f) {
        int n, a, b, c;
        double q, mx, mean, rms;
        in >> n >> a >> b >> c >> q >> mx >> mean >> rms;
        m.face.push_back({mx, mean, rms});
    }
    return in ? m : ErrorMap{};
}
}  // namespace

// --color-by mean: every triangle is coloured by its exact mean distance (the mean_distance of
// hlens-cli --export-errors), on a range from the least to the largest mean; the picture differs
// from --color-by max (the default).
TEST(GuiStats, ColourByMeanFollowsEachTrianglesMean) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "mean.png", png_max = dir / "max.png";
    Outcome o = run_gui(with({"--color-by", "mean"}, kZoomed), png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    Outcome m = run_gui(with({"--color-by", "max"}, kZoomed), png_max, dir);
    ASSERT_EQ(m.code, 0) << m.err;
    const size_t em = o.out.find("\"exact_colormap\"");
    ASSERT_NE(em, std::string::npos) << o.out;
    EXPECT_EQ(raw_value(o.out, "color_by", em), "\"mean\"");
    EXPECT_EQ(raw_value(o.out, "shows", em), "\"mean\"");
    EXPECT_EQ(raw_value(m.out, "shows"), "\"max\"");

    Outcome c = run({kCli, "distance", kDemoA, kDemoB, "--export-errors", (dir / "cli.ply").string()}, dir);
    ASSERT_EQ(c.code, 0) << c.err;
    const ErrorMap cli = read_error_ply(dir / "cli-ab.ply");
    ASSERT_EQ(cli.face.size(), 512u);
    double lo = HUGE_VAL, hi = 0;
    for (const auto& f : cli.face) lo = std::min(lo, f[1]), hi = std::max(hi, f[1]);
    EXPECT_NEAR(num(o.out, "lo", em), lo, 1e-7 * hi);
    EXPECT_NEAR(num(o.out, "hi", em), hi, 1e-7 * hi);

    Image im = load_png(png), im_max = load_png(png_max);
    expect_probes_on_the_bar(o.out, im, lo, hi, [&](long t) { return cli.face[t][1]; });
    // The pictures differ where the mesh is (the means are below the maxima, on another range).
    std::vector<int> vp = int_list(o.out, "viewport");
    ASSERT_EQ(vp.size(), 4u);
    long differ = 0, total = 0;
    for (int y = vp[3] / 5; y < vp[3] * 9 / 10; ++y)
        for (int x = vp[0]; x < im.w; ++x, ++total)
            differ += !near(im.at(x, y), im_max.at(x, y), 12);
    EXPECT_GT(differ, total / 5) << "--color-by mean looks like --color-by max";
}

namespace {
// The points of the state's "tolerance"."curve" (world coordinates).
std::vector<hlens::Vec3> curve_points(const std::string& json) {
    const size_t tol = json.find("\"tolerance\": {");
    std::vector<double> v = num_list(json, "curve", tol == std::string::npos ? 0 : tol);
    std::vector<hlens::Vec3> p;
    for (size_t i = 0; i + 2 < v.size(); i += 3) p.push_back({v[i], v[i + 1], v[i + 2]});
    return p;
}
const std::vector<std::string> kTolerance22 = {"--direction", "ba", "--target", "22", "--step", "end", "--tolerance", "0.14"};
constexpr std::array<int, 3> kCurve = {255, 60, 50};      // the curve d = T in the domain view
constexpr std::array<int, 3> kOutline = {255, 31, 26};    // triangles above T in the 3D view (1, 0.12, 0.1)
}  // namespace

// The tolerance in the domain view of target 22 of B (46 domains): every point the state gives on
// the drawn curve d = T is at distance T from A (brute force over A's triangles), to 1e-9; the
// target's area above T is the core's (area_above_levels on its finished domain mesh); the curve
// and the shading are drawn, and the 3D view outlines the triangles whose maximum exceeds T.
TEST(GuiStats, ToleranceCurveLiesWhereTheDistanceIsT) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "tolerance.png";
    Outcome o = run_gui(kTolerance22, png, dir, {}, "1200x800");
    ASSERT_EQ(o.code, 0) << o.err;
    const double T = 0.14;
    const size_t tol = o.out.find("\"tolerance\": {");
    ASSERT_NE(tol, std::string::npos) << o.out;
    EXPECT_EQ(num(o.out, "value", tol), T);
    EXPECT_GE(num(o.out, "curve_arcs", tol), 4);
    const hlens::TriangleMesh A = hlens::load_mesh(kDemoA), B = hlens::load_mesh(kDemoB);
    const std::vector<hlens::Vec3> pts = curve_points(o.out);
    ASSERT_GE(pts.size(), 12u) << o.out;
    for (const hlens::Vec3& p : pts) EXPECT_NEAR(hlens_test::brute_distance(p, A), T, 1e-9 * T) << p.x << " " << p.y << " " << p.z;

    hlens::VoxelGrid grid(A, B);
    hlens::TargetSolver ts(grid, 1, 22);
    ts.run();
    const double sc = ts.frame().scale;
    const double core = hlens::area_above_levels(*ts.domain_mesh(), {T * T / (sc * sc)})[0] * sc * sc;
    const double gui = num(raw_value(o.out, "target", tol), "area_above"), view = num(raw_value(o.out, "view", tol), "area_above");
    EXPECT_NEAR(gui, core, 1e-12 * sc * sc);
    EXPECT_NEAR(view, core, 1e-12 * sc * sc);
    EXPECT_GT(core, 0.1 * num(raw_value(o.out, "target", tol), "area"));
    EXPECT_LT(core, 0.9 * num(raw_value(o.out, "target", tol), "area"));

    Image im = load_png(png);
    std::vector<int> dv = int_list(o.out, "domain_view"), vp = int_list(o.out, "viewport");
    ASSERT_EQ(dv.size(), 4u);
    EXPECT_GT(count(im, dv[0], dv[1], dv[0] + dv[2], dv[1] + dv[3], [](auto p) { return near(p, kCurve, 4); }), 60) << "the curve";
    EXPECT_GT(count(im, vp[0], vp[1], vp[0] + vp[2], vp[1] + vp[3], [](auto p) { return shaded(p, kOutline, 10); }), 60)
        << "the outlines of the triangles above T";
}

// The measured mesh's area above T: with --stats it is hlens-cli's --stats --tolerance T, to the
// digit; the triangles outlined are those whose exact maximum exceeds T; without a tolerance none.
TEST(GuiStats, MeshAreaAboveTIsTheClis) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "mesh.png";
    Outcome o = run_gui({"--direction", "ba", "--tolerance", "0.14", "--stats"}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const size_t tol = o.out.find("\"tolerance\": {");
    ASSERT_NE(tol, std::string::npos) << o.out;
    const std::string mesh = raw_value(o.out, "mesh", tol);
    Outcome c = cli_stats(dir, {"--tolerance", "0.14"});
    EXPECT_EQ(raw_value(mesh, "area_above"), raw_value(raw_value(c.out, "b_to_a"), "area_above")) << mesh;
    EXPECT_EQ(raw_value(mesh, "fraction_above"), raw_value(raw_value(c.out, "b_to_a"), "fraction_above"));
    const hlens::TriangleMesh A = hlens::load_mesh(kDemoA), B = hlens::load_mesh(kDemoB);
    hlens::VoxelGrid grid(A, B);
    const hlens::TargetMaxima mx = hlens::exact_target_maxima(grid, 1);
    EXPECT_EQ((long)num(mesh, "triangles_above"), std::count_if(mx.max.begin(), mx.max.end(), [](double v) { return v > 0.14; }));
    EXPECT_GT(num(mesh, "triangles_above"), 0);

    Outcome d = run_gui({"--direction", "ba"}, dir / "plain.png", dir);
    ASSERT_EQ(d.code, 0) << d.err;
    EXPECT_EQ(raw_value(d.out, "tolerance"), "null");
    Image with = load_png(png), without = load_png(dir / "plain.png");
    std::vector<int> vp = int_list(o.out, "viewport");
    auto outlined = [&](const Image& im) {
        return count(im, vp[0], vp[1], vp[0] + vp[2], vp[1] + vp[3], [](auto p) { return shaded(p, kOutline, 10); });
    };
    EXPECT_GT(outlined(with), 60);
    EXPECT_EQ(outlined(without), 0);
}

// --export-errors PATH.ply: the debugger writes the error maps of both directions, byte for byte
// hlens-cli --export-errors's, and they read back as PLY with every face's max, mean and RMS
// (the statistics the sidebar shows) and every vertex's distance.
TEST(GuiStats, ExportWritesTheClisErrorMaps) {
    REQUIRE_XVFB();
    fs::path dir = scratch_dir(), png = dir / "export.png";
    const std::string path = (dir / "gui.ply").string();
    Outcome o = run_gui({"--export-errors", path}, png, dir);
    ASSERT_EQ(o.code, 0) << o.err;
    const std::string maps = raw_value(o.out, "error_maps");
    EXPECT_EQ(raw_value(maps, "ok"), "true") << o.out;
    Outcome c = run({kCli, "distance", kDemoA, kDemoB, "--export-errors", (dir / "cli.ply").string()}, dir);
    ASSERT_EQ(c.code, 0) << c.err;
    for (const char* side : {"ab", "ba"}) {
        const fs::path gui = dir / ("gui-" + std::string(side) + ".ply"), cli = dir / ("cli-" + std::string(side) + ".ply");
        ASSERT_TRUE(fs::exists(gui)) << gui;
        EXPECT_EQ(read_file(gui), read_file(cli)) << side;
        const ErrorMap m = read_error_ply(gui);
        ASSERT_EQ(m.face.size(), std::string(side) == "ab" ? 512u : 32u);
        EXPECT_NE(m.header.find("property float quality"), std::string::npos);
        EXPECT_EQ(m.vertex.size(), std::string(side) == "ab" ? 289u : 25u);
        for (const auto& f : m.face) {
            EXPECT_GE(f[0], f[2]);   // max >= RMS >= mean >= 0
            EXPECT_GE(f[2], f[1]);
            EXPECT_GE(f[1], 0);
        }
    }
    // The file's maxima are the exact maxima of the colour map.
    const hlens::TriangleMesh A = hlens::load_mesh(kDemoA), B = hlens::load_mesh(kDemoB);
    hlens::VoxelGrid grid(A, B);
    const hlens::TargetMaxima mx = hlens::exact_target_maxima(grid, 0);
    const ErrorMap ab = read_error_ply(dir / "gui-ab.ply");
    for (size_t t = 0; t < ab.face.size(); ++t) EXPECT_NEAR(ab.face[t][0], mx.max[t], 1e-12) << t;
    // A bad path is a usage error.
    Outcome bad = run({kGui, "--export-errors", "x.obj"}, dir);
    EXPECT_EQ(bad.code, 2);
}
