// Tests of the command-line tool hlens-cli (app/cli_main.cpp), run as a separate process.
//
// HLENS_CLI holds the full path of the built binary. Every test writes its meshes into a fresh
// directory, runs the tool with stdout and stderr redirected to files and checks the exit code, the
// single stderr line of errors, and the JSON output (validated by a small JSON checker here, then
// read by key).
#include <gtest/gtest.h>

#include "test_support.h"
#include <sys/wait.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using hlens_test::Outcome;
using hlens_test::quote;
using hlens_test::read_file;
using hlens_test::write_file;

namespace {

const std::string kCli = HLENS_CLI;

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> v;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
}

// ---------------------------------------------------------------- a minimal JSON checker and reader

// Recursive-descent validation of one JSON value (RFC 8259 grammar, no extensions).
struct JsonChecker {
    const std::string& s;
    size_t i = 0;
    void ws() { while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i; }
    bool lit(const char* w) {
        size_t n = std::strlen(w);
        if (s.compare(i, n, w) != 0) return false;
        i += n;
        return true;
    }
    bool string() {
        if (i >= s.size() || s[i] != '"') return false;
        for (++i; i < s.size(); ++i) {
            unsigned char c = s[i];
            if (c == '"') { ++i; return true; }
            if (c < 0x20) return false;
            if (c == '\\') {
                if (++i >= s.size()) return false;
                char e = s[i];
                if (e == 'u') {
                    for (int k = 0; k < 4; ++k)
                        if (++i >= s.size() || !std::isxdigit((unsigned char)s[i])) return false;
                } else if (!std::strchr("\"\\/bfnrt", e)) {
                    return false;
                }
            }
        }
        return false;
    }
    bool number() {
        size_t start = i;
        if (i < s.size() && s[i] == '-') ++i;
        if (i >= s.size() || !std::isdigit((unsigned char)s[i])) return false;
        if (s[i] == '0') ++i;
        else while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i;
        if (i < s.size() && s[i] == '.') {
            ++i;
            if (i >= s.size() || !std::isdigit((unsigned char)s[i])) return false;
            while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i;
        }
        if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
            ++i;
            if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
            if (i >= s.size() || !std::isdigit((unsigned char)s[i])) return false;
            while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i;
        }
        return i > start;
    }
    bool value() {
        ws();
        if (i >= s.size()) return false;
        char c = s[i];
        if (c == '{') {
            ++i;
            ws();
            if (i < s.size() && s[i] == '}') { ++i; return true; }
            for (;;) {
                ws();
                if (!string()) return false;
                ws();
                if (i >= s.size() || s[i++] != ':') return false;
                if (!value()) return false;
                ws();
                if (i < s.size() && s[i] == ',') { ++i; continue; }
                if (i < s.size() && s[i] == '}') { ++i; return true; }
                return false;
            }
        }
        if (c == '[') {
            ++i;
            ws();
            if (i < s.size() && s[i] == ']') { ++i; return true; }
            for (;;) {
                if (!value()) return false;
                ws();
                if (i < s.size() && s[i] == ',') { ++i; continue; }
                if (i < s.size() && s[i] == ']') { ++i; return true; }
                return false;
            }
        }
        if (c == '"') return string();
        if (lit("true") || lit("false") || lit("null")) return true;
        return number();
    }
};

// One JSON object and nothing else on the text (trailing whitespace allowed).
bool is_json_object(const std::string& text) {
    JsonChecker c{text};
    c.ws();
    if (c.i >= text.size() || text[c.i] != '{') return false;
    if (!c.value()) return false;
    c.ws();
    return c.i == text.size();
}

// Position just after `"key": ` at the top level of the object `json` (nested objects are skipped),
// or npos.
size_t value_pos(const std::string& json, const std::string& key) {
    const std::string pat = "\"" + key + "\":";
    int depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < json.size(); ++i) {
        char c = json[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
            continue;
        }
        if (c == '{' || c == '[') ++depth;
        else if (c == '}' || c == ']') --depth;
        else if (c == '"') {
            if (depth == 1 && json.compare(i, pat.size(), pat) == 0) {
                size_t p = i + pat.size();
                while (p < json.size() && json[p] == ' ') ++p;
                return p;
            }
            in_string = true;
        }
    }
    return std::string::npos;
}

bool has_key(const std::string& json, const std::string& key) { return value_pos(json, key) != std::string::npos; }

double num(const std::string& json, const std::string& key) {
    size_t p = value_pos(json, key);
    if (p == std::string::npos) {
        ADD_FAILURE() << "no key " << key << " in " << json;
        return NAN;
    }
    char* end = nullptr;
    double v = std::strtod(json.c_str() + p, &end);
    if (end == json.c_str() + p) ADD_FAILURE() << "key " << key << " is not a number in " << json;
    return v;
}

std::string str(const std::string& json, const std::string& key) {
    size_t p = value_pos(json, key);
    if (p == std::string::npos || json[p] != '"') {
        ADD_FAILURE() << "no string key " << key << " in " << json;
        return "";
    }
    size_t e = p + 1;
    while (e < json.size() && json[e] != '"') e += json[e] == '\\' ? 2 : 1;
    return json.substr(p + 1, e - p - 1);  // raw, escapes kept
}

// The balanced {...} or [...] value of `key`.
std::string sub(const std::string& json, const std::string& key) {
    size_t p = value_pos(json, key);
    if (p == std::string::npos || (json[p] != '{' && json[p] != '[')) {
        ADD_FAILURE() << "no object/array key " << key << " in " << json;
        return "{}";
    }
    int depth = 0;
    bool in_string = false;
    for (size_t i = p; i < json.size(); ++i) {
        char c = json[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
        } else if (c == '"') in_string = true;
        else if (c == '{' || c == '[') ++depth;
        else if ((c == '}' || c == ']') && --depth == 0) return json.substr(p, i - p + 1);
    }
    return "{}";
}

// The text of the value of `key` as written (an object, array, number, true, false or null; not a
// string holding ',' or '}'), or "<missing>".
std::string raw(const std::string& json, const std::string& key) {
    const size_t p = value_pos(json, key);
    if (p == std::string::npos) return "<missing>";
    if (json[p] == '{' || json[p] == '[') return sub(json, key);
    return json.substr(p, json.find_first_of(",}", p) - p);
}

std::vector<double> numbers(const std::string& array) {  // "[x, y, z]"
    std::vector<double> v;
    const char* p = array.c_str() + 1;
    for (;;) {
        char* end = nullptr;
        double x = std::strtod(p, &end);
        if (end == p) break;
        v.push_back(x);
        p = end;
        while (*p == ',' || *p == ' ') ++p;
    }
    return v;
}

// ---------------------------------------------------------------- meshes written by the tests

struct P3 { double x, y, z; };
struct Obj { std::vector<P3> v; std::vector<std::array<int, 3>> f; };

std::string obj_text(const Obj& m) {
    std::string s;
    char buf[128];
    for (const P3& p : m.v) {
        std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
        s += buf;
    }
    for (auto& t : m.f) {
        std::snprintf(buf, sizeof buf, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
        s += buf;
    }
    return s;
}

// An n x n grid of quads over [0, size]^2 (offset by x0, y0) with random heights in [0, amp].
Obj random_grid(int n, double size, double x0, double y0, double amp, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Obj m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.v.push_back({x0 + size * i / n, y0 + size * j / n, amp * u(rng)});
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            m.f.push_back({a, b, d});
            m.f.push_back({a, d, c});
        }
    return m;
}

class Cli : public ::testing::Test {
protected:
    fs::path dir;

    void SetUp() override {
        static const unsigned run = std::random_device{}();
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() / ("hlens_cli_" + std::to_string(run) + "_" + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir);
    }

    std::string write(const std::string& name, const std::string& text) {
        write_file(dir / name, text);
        return (dir / name).string();
    }

    Outcome run(const std::vector<std::string>& args) {
        std::vector<std::string> argv{kCli};
        argv.insert(argv.end(), args.begin(), args.end());
        return hlens_test::run(argv, dir);
    }

    // Exit code 2, nothing on stdout, exactly one line "hlens-cli: ..." on stderr containing `needle`.
    void expect_error(const std::vector<std::string>& args, const std::string& needle) {
        Outcome r = run(args);
        std::string what;
        for (auto& a : args) what += a + " ";
        EXPECT_EQ(r.code, 2) << what << "\nstderr: " << r.err;
        EXPECT_EQ(r.out, "") << what;
        ASSERT_FALSE(r.err.empty()) << what;
        EXPECT_EQ(r.err.rfind("hlens-cli: ", 0), 0u) << what << "\nstderr: " << r.err;
        EXPECT_EQ(r.err.back(), '\n') << what;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
        EXPECT_NE(r.err.find(needle), std::string::npos) << what << "\nstderr: " << r.err << "\nexpected: " << needle;
    }

    // Two small triangle meshes: the unit right triangle in z = 0 and the same one at z = 1.
    std::string tri_a() { return write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }
    std::string tri_b() { return write("b.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n"); }

    // A pair of bumpy grids, overlapping but not equal (a few hundred triangles).
    std::pair<std::string, std::string> random_pair() {
        std::string a = write("ra.obj", obj_text(random_grid(8, 1.0, 0.0, 0.0, 0.25, 12345)));
        std::string b = write("rb.obj", obj_text(random_grid(7, 1.1, -0.05, 0.03, 0.3, 777)));
        return {a, b};
    }

    std::string run_json(const std::vector<std::string>& args) {
        Outcome r = run(args);
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(r.err, "");
        EXPECT_TRUE(is_json_object(r.out)) << r.out;
        EXPECT_EQ(lines(r.out).size(), 1u) << "one object on one line";
        return r.out;
    }
};

// ---------------------------------------------------------------- errors

TEST_F(Cli, MissingFile) {
    std::string missing = (dir / "no_such_mesh.obj").string();
    expect_error({"distance", missing, tri_b()}, missing);
    expect_error({"distance", tri_a(), missing}, missing);
    expect_error({"trace", missing, tri_b(), "--target", "0"}, missing);
}

TEST_F(Cli, TruncatedBinaryStl) {
    // 80-byte header, a count of 2 triangles, and only one 50-byte record.
    std::string stl(80, ' ');
    stl.replace(0, 10, "binary stl");
    uint32_t count = 2;
    stl.append(reinterpret_cast<const char*>(&count), 4);
    stl.append(50, '\0');
    std::string path = write("truncated.stl", stl);
    expect_error({"distance", path, tri_b()}, path);
}

TEST_F(Cli, ObjIndexOutOfRange) {
    std::string path = write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    expect_error({"distance", tri_a(), path}, path);
}

TEST_F(Cli, NanCoordinates) {
    std::string path = write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_error({"distance", path, tri_b()}, path);
}

TEST_F(Cli, EmptyFile) {
    std::string path = write("empty.obj", "");
    expect_error({"distance", path, tri_b()}, path);
}

TEST_F(Cli, UnknownOption) {
    expect_error({"distance", tri_a(), tri_b(), "--bogus"}, "--bogus");
    expect_error({"trace", tri_a(), tri_b(), "--target", "0", "--one-sided"}, "--one-sided");
}

TEST_F(Cli, TargetOutOfRange) {
    std::string a = tri_a(), b = tri_b();
    expect_error({"trace", a, b, "--target", "1"}, a);
    expect_error({"trace", a, b, "--target", "-1"}, a);
}

TEST_F(Cli, BadUsage) {
    std::string a = tri_a(), b = tri_b();
    expect_error({}, "command");
    expect_error({"frobnicate", a, b}, "frobnicate");
    expect_error({"distance", a}, "two mesh files");
    expect_error({"distance", a, b, a}, "two mesh files");
    expect_error({"distance", a, b, "--threads"}, "--threads");
    expect_error({"distance", a, b, "--threads", "0"}, "--threads");
    expect_error({"distance", a, b, "--threads", "two"}, "two");
    expect_error({"distance", a, b, "--threads", "2x"}, "2x");
    expect_error({"distance", a, b, "--mode", "slow"}, "slow");
    expect_error({"trace", a, b}, "--target");
    expect_error({"trace", a, b, "--target", "zero"}, "zero");
    expect_error({"trace", a, b, "--target", "0", "--mode", "fast"}, "--mode");
}

TEST_F(Cli, Help) {
    for (auto args : std::vector<std::vector<std::string>>{{"--help"}, {"help"}, {"distance", "--help"}}) {
        Outcome r = run(args);
        EXPECT_EQ(r.code, 0);
        EXPECT_NE(r.out.find("hlens-cli distance A B"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("hlens-cli trace A B --target I"), std::string::npos) << r.out;
        EXPECT_EQ(r.err, "");
    }
}

// ---------------------------------------------------------------- distance

TEST_F(Cli, DistanceJsonTranslatedTriangle) {
    std::string a = tri_a(), b = tri_b();
    std::string j = run_json({"distance", a, b, "--json"});
    const double diag = std::sqrt(3.0);  // of the union's bounding box [0,1]^3

    std::string ja = sub(j, "a"), jb = sub(j, "b");
    EXPECT_EQ(str(ja, "path"), a);
    EXPECT_EQ(num(ja, "vertices"), 3);
    EXPECT_EQ(num(ja, "triangles"), 1);
    EXPECT_EQ(str(jb, "path"), b);
    EXPECT_EQ(num(jb, "vertices"), 3);
    EXPECT_EQ(num(jb, "triangles"), 1);

    for (const char* dir : {"a_to_b", "b_to_a"}) {
        SCOPED_TRACE(dir);
        std::string d = sub(j, dir);
        double dist = num(d, "distance"), lo = num(d, "lower"), hi = num(d, "upper");
        EXPECT_NEAR(dist, 1.0, 1e-12);
        EXPECT_NEAR(num(d, "relative"), dist / diag, 1e-15);  // the union's diagonal, not A's
        EXPECT_LE(lo, dist);
        EXPECT_LE(dist, hi);
        EXPECT_LE(hi - lo, 1e-9 * diag);
        EXPECT_EQ(num(d, "target"), 0);
        std::vector<double> from = numbers(sub(d, "from_point")), to = numbers(sub(d, "to_point"));
        ASSERT_EQ(from.size(), 3u);
        ASSERT_EQ(to.size(), 3u);
        const double z_from = std::string(dir) == "a_to_b" ? 0.0 : 1.0;
        EXPECT_NEAR(from[2], z_from, 1e-12);
        EXPECT_NEAR(to[2], 1.0 - z_from, 1e-12);
        EXPECT_NEAR(to[0], from[0], 1e-12);  // straight above or below
        EXPECT_NEAR(to[1], from[1], 1e-12);
        EXPECT_GE(num(d, "exact_targets"), 1);
        EXPECT_GE(num(d, "seconds"), 0);
    }
    EXPECT_NEAR(num(j, "hausdorff"), 1.0, 1e-12);
    EXPECT_NEAR(num(j, "diagonal"), diag, 1e-15);
    EXPECT_NEAR(num(j, "relative"), num(j, "hausdorff") / diag, 1e-15);
    EXPECT_FALSE(has_key(j, "units"));
    EXPECT_GE(num(j, "seconds"), 0);
    EXPECT_EQ(str(j, "mode"), "fast");
    EXPECT_GE(num(j, "threads"), 1);
}

TEST_F(Cli, DistanceOneSidedOmitsReverse) {
    std::string j = run_json({"distance", tri_a(), tri_b(), "--json", "--one-sided", "--mode", "paper", "--threads", "1"});
    EXPECT_TRUE(has_key(j, "a_to_b"));
    EXPECT_FALSE(has_key(j, "b_to_a"));
    EXPECT_FALSE(has_key(j, "hausdorff"));
    EXPECT_EQ(j.find("b_to_a"), std::string::npos);
    EXPECT_NEAR(num(sub(j, "a_to_b"), "distance"), 1.0, 1e-12);
    EXPECT_EQ(str(j, "mode"), "paper");
    EXPECT_EQ(num(j, "threads"), 1);
}

TEST_F(Cli, DistanceReadableSummary) {
    Outcome r = run({"distance", tri_a(), tri_b()});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    for (const char* s : {"a.obj", "b.obj", "3 vertices (3 used), 1 triangles", "h(A,B) = 1", "h(B,A) = 1",
                          "Hausdorff distance = 1", "certified interval", "witness: triangle 0", "mode fast"})
        EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
}

TEST_F(Cli, JsonStringsAreEscaped) {
    // A path with a quote and a backslash must come out as a valid JSON string.
    std::string a = write("we\"ird\\name.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::string j = run_json({"distance", a, tri_b(), "--json", "--one-sided"});
    EXPECT_NE(j.find("we\\\"ird\\\\name.obj"), std::string::npos) << j;
}

TEST_F(Cli, ThreadsDoNotChangeTheResult) {
    auto [a, b] = random_pair();
    std::string j1 = run_json({"distance", a, b, "--json", "--threads", "1"});
    std::string j2 = run_json({"distance", a, b, "--json", "--threads", "2"});
    for (const char* dir : {"a_to_b", "b_to_a"}) {
        SCOPED_TRACE(dir);
        std::string d1 = sub(j1, dir), d2 = sub(j2, dir);
        EXPECT_GT(num(d1, "distance"), 0);
        EXPECT_EQ(num(d1, "distance"), num(d2, "distance"));  // bit-identical (17 digits round-trip)
        EXPECT_EQ(num(d1, "target"), num(d2, "target"));
    }
    EXPECT_EQ(num(j1, "threads"), 1);
    EXPECT_EQ(num(j2, "threads"), 2);
}

TEST_F(Cli, PaperModeEqualsFastMode) {
    auto [a, b] = random_pair();
    std::string jp = run_json({"distance", a, b, "--json", "--mode", "paper"});
    std::string jf = run_json({"distance", a, b, "--json", "--mode", "fast"});
    for (const char* dir : {"a_to_b", "b_to_a"}) {
        SCOPED_TRACE(dir);
        double p = num(sub(jp, dir), "distance"), f = num(sub(jf, dir), "distance");
        EXPECT_GT(p, 0);
        EXPECT_NEAR(p, f, 1e-12 * p);
        // Paper mode solves every target exactly; fast mode never more.
        EXPECT_GE(num(sub(jp, dir), "exact_targets"), num(sub(jf, dir), "exact_targets"));
    }
    EXPECT_EQ(num(sub(jp, "a_to_b"), "exact_targets"), 128);
    EXPECT_NEAR(num(jp, "hausdorff"), num(jf, "hausdorff"), 1e-12 * num(jp, "hausdorff"));
}

// Regression: B is a plane and h(A,B) is attained at a vertex of A, so fast mode's lower bound (the
// farthest vertex) equals the result exactly; rounding must not let fast mode skip every target.
TEST_F(Cli, PaperModeEqualsFastModeWhenTheLowerBoundIsTheResult) {
    Obj a = random_grid(16, 3.0, -1.5, -1.5, 0.0, 1), b = random_grid(4, 3.0, -1.5, -1.5, 0.0, 1);
    for (P3& p : a.v) p.z = 0.15 * std::sin(p.x) * std::cos(p.y - 0.3);
    std::string pa = write("bump.obj", obj_text(a)), pb = write("flat.obj", obj_text(b));
    std::string jp = run_json({"distance", pa, pb, "--json", "--mode", "paper"});
    std::string jf = run_json({"distance", pa, pb, "--json", "--mode", "fast"});
    for (const char* dir : {"a_to_b", "b_to_a"}) {
        SCOPED_TRACE(dir);
        double p = num(sub(jp, dir), "distance"), f = num(sub(jf, dir), "distance");
        EXPECT_GT(p, 0.14);
        EXPECT_NEAR(p, f, 1e-12 * p);
        EXPECT_EQ(num(sub(jp, dir), "target"), num(sub(jf, dir), "target"));
        EXPECT_GE(num(sub(jf, dir), "exact_targets"), 1);
    }
}

// ---------------------------------------------------------------- trace

TEST_F(Cli, TraceJsonMatchesDistance) {
    auto [a, b] = random_pair();
    std::string j = run_json({"distance", a, b, "--json", "--one-sided"});
    const double distance = num(sub(j, "a_to_b"), "distance");
    const long target = (long)num(sub(j, "a_to_b"), "target");
    ASSERT_GT(distance, 0);

    Outcome r = run({"trace", a, b, "--target", std::to_string(target), "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    std::vector<std::string> ls = lines(r.out);
    ASSERT_GE(ls.size(), 3u);
    long expected_step = 0;
    int chosen = 0, projected = 0;
    for (size_t k = 0; k < ls.size(); ++k) {
        const std::string& l = ls[k];
        ASSERT_TRUE(is_json_object(l)) << "line " << k << ": " << l;
        ASSERT_TRUE(has_key(l, "event")) << l;
        ASSERT_TRUE(has_key(l, "step")) << l;
        EXPECT_EQ(num(l, "step"), expected_step++) << l;
        std::string ev = str(l, "event");
        if (k == 0) {
            EXPECT_EQ(ev, "target_begun");
            EXPECT_EQ(num(l, "target"), target);
        }
        if (ev == "source_chosen") {
            ++chosen;
            EXPECT_GE(num(l, "source"), 0);
        }
        if (ev == "regions_projected") {
            ++projected;
            EXPECT_TRUE(has_key(l, "regions")) << l;
        }
        if (ev == "domain_split") {
            std::string c = sub(l, "curve");
            for (const char* key : {"a", "b", "c", "d", "e", "f"}) num(c, key);
            EXPECT_FALSE(str(c, "type").empty());
        }
        if (ev == "domain_created") {
            EXPECT_GE(num(sub(l, "label"), "source"), 0);
            EXPECT_TRUE(has_key(l, "old_label"));
        }
        if (ev == "maximum_raised" || ev == "target_finished") {
            EXPECT_EQ(numbers(sub(l, "point")).size(), 2u);
            EXPECT_EQ(numbers(sub(l, "world")).size(), 3u);
            EXPECT_GE(num(l, "value"), 0);
        }
        if (k + 1 < ls.size()) {
            EXPECT_NE(ev, "final");
        }
    }
    EXPECT_GE(chosen, 1);
    EXPECT_GE(projected, 1);
    const std::string& fin = ls.back();
    EXPECT_EQ(str(fin, "event"), "final");
    EXPECT_EQ(num(fin, "target"), target);
    EXPECT_NEAR(num(fin, "max_sq"), distance * distance, 1e-12 * distance * distance);
    EXPECT_NEAR(num(fin, "max"), distance, 1e-12 * distance);
    EXPECT_EQ(numbers(sub(fin, "max_point")).size(), 3u);
    EXPECT_GE(num(fin, "domains"), 1);
    EXPECT_GE(num(fin, "arcs"), 3);
    EXPECT_GE(num(fin, "vertices"), 3);
    EXPECT_EQ(num(fin, "insertions"), chosen);
    EXPECT_NE(fin.find("\"degenerate\": false"), std::string::npos) << fin;
}

TEST_F(Cli, TraceReadable) {
    Outcome r = run({"trace", tri_a(), tri_b(), "--target", "0"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    std::vector<std::string> ls = lines(r.out);
    ASSERT_GE(ls.size(), 3u);
    EXPECT_NE(ls[0].find("target_begun"), std::string::npos) << ls[0];
    EXPECT_NE(r.out.find("source_chosen"), std::string::npos);
    EXPECT_NE(r.out.find("target_finished"), std::string::npos);
    EXPECT_NE(r.out.find("max distance 1 "), std::string::npos) << r.out;
}

TEST_F(Cli, TraceDegenerateTarget) {
    // Target 0 is a zero-area triangle (a segment): no domain mesh.
    std::string a = write("deg.obj", "v 0 0 0\nv 1 0 0\nv 0.5 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    Outcome r = run({"trace", a, tri_b(), "--target", "0", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    std::vector<std::string> ls = lines(r.out);
    ASSERT_GE(ls.size(), 2u);
    for (const std::string& l : ls) ASSERT_TRUE(is_json_object(l)) << l;
    const std::string& fin = ls.back();
    EXPECT_EQ(str(fin, "event"), "final");
    EXPECT_NE(fin.find("\"degenerate\": true"), std::string::npos) << fin;
    EXPECT_EQ(num(fin, "domains"), 0);
    EXPECT_EQ(num(fin, "arcs"), 0);
    EXPECT_EQ(num(fin, "vertices"), 0);
    EXPECT_NEAR(num(fin, "max"), 1.0, 1e-12);  // the segment lies 1 below B
}

}  // namespace

TEST_F(Cli, VerifyBracketsTheExactValue) {
    // The Lipschitz bracket is computed independently of the domain meshes; the exact value must
    // lie in it, and the bracket is no wider than its tolerance (1e-4 of the diagonal).
    auto [a, b] = random_pair();
    std::string j = run_json({"distance", a, b, "--json", "--verify"});
    for (const char* dir : {"a_to_b", "b_to_a"}) {
        SCOPED_TRACE(dir);
        std::string d = sub(j, dir), v = sub(d, "verify");
        double lo = num(v, "lower"), hi = num(v, "upper"), x = num(d, "distance");
        EXPECT_LE(lo, x);
        EXPECT_GE(hi, x);
        EXPECT_LE(hi - lo, 2e-4 * 2.0);  // the grids span about 1.1 x 1.1 x 0.6
        EXPECT_NE(v.find("\"ok\": true"), std::string::npos) << v;
    }
    Outcome r = run({"distance", a, b, "--verify"});
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("holds the exact value"), std::string::npos) << r.out;
}

// ---------------------------------------------------------------- statistics, tolerance, error map (issue 9)

namespace {

// One tilted triangle over a big plane z = 0: d = z, linear, with heights 0.2, 0.5, 0.9 at the corners
// (hand formulas: mean = centroid height, mean of z^2 = (sum z_i^2 + sum z_i z_j) / 6).
const char* kTilted = "v 0.1 0.2 0.2\nv 1.3 0.5 0.5\nv 0.4 1.1 0.9\nf 1 2 3\n";
const char* kPlane = "v -5 -5 0\nv 5 -5 0\nv 5 5 0\nv -5 5 0\nf 1 2 3\nf 1 3 4\n";
const double kZ[3] = {0.2, 0.5, 0.9};
double tilted_area() {
    const double ux = 1.2, uy = 0.3, uz = 0.3, vx = 0.3, vy = 0.9, vz = 0.7;  // edges from the first corner
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    return 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
}
double tilted_above(double t) {  // area where z > t (z linear over the triangle)
    const double A = tilted_area(), a = kZ[0], b = kZ[1], c = kZ[2];
    if (t <= a) return A;
    if (t >= c) return 0;
    if (t >= b) return A * (c - t) * (c - t) / ((c - a) * (c - b));
    return A * (1 - (t - a) * (t - a) / ((c - a) * (b - a)));
}

std::string format_number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// A tiny reader for the ASCII PLY the tool writes: the header's property names per element, and
// the rows of numbers.
struct Ply {
    std::vector<std::string> vertex_props, face_props;
    std::vector<std::vector<double>> vertices, faces;
};
Ply read_ply(const std::string& text) {
    Ply p;
    std::istringstream in(text);
    std::string line, element;
    size_t nv = 0, nf = 0;
    while (std::getline(in, line) && line != "end_header") {
        std::istringstream l(line);
        std::string w;
        l >> w;
        if (w == "element") { l >> element; (element == "vertex" ? nv : nf) = 0; size_t n; l >> n; (element == "vertex" ? nv : nf) = n; }
        if (w == "property") {
            std::string type, name;
            l >> type;
            if (type == "list") { std::string a, b; l >> a >> b; }
            l >> name;
            (element == "vertex" ? p.vertex_props : p.face_props).push_back(type + " " + name);
        }
    }
    auto rows = [&](size_t n, std::vector<std::vector<double>>& out) {
        for (size_t i = 0; i < n && std::getline(in, line); ++i) {
            std::istringstream l(line);
            std::vector<double> row;
            for (double x; l >> x;) row.push_back(x);
            out.push_back(row);
        }
    };
    rows(nv, p.vertices);
    rows(nf, p.faces);
    return p;
}

}  // namespace

TEST_F(Cli, StatsOfATiltedTriangleOverAPlane) {
    std::string a = write("tilt.obj", kTilted), b = write("plane.obj", kPlane);
    Outcome r = run({"distance", a, b, "--json", "--one-sided", "--stats", "--histogram", "3", "--tolerance", "0.6"});
    EXPECT_EQ(r.code, 4) << r.err;  // not within 0.6: the distance is 0.9
    ASSERT_TRUE(is_json_object(r.out)) << r.out;
    const std::string j = r.out;
    std::string d = sub(j, "a_to_b");
    const double A = tilted_area(), m2 = (0.04 + 0.25 + 0.81 + 0.1 + 0.45 + 0.18) / 6;
    EXPECT_NEAR(num(d, "area"), A, 1e-12 * A);
    EXPECT_NEAR(num(d, "mean"), (0.2 + 0.5 + 0.9) / 3, 1e-9 * 0.53);
    EXPECT_NEAR(num(d, "rms"), std::sqrt(m2), 1e-9 * std::sqrt(m2));
    EXPECT_NEAR(num(d, "area_above"), tilted_above(0.6), 1e-9 * A);
    EXPECT_NEAR(num(d, "fraction_above"), tilted_above(0.6) / A, 1e-9);
    std::string pct = sub(d, "percentiles");
    for (double p : {50.0, 90.0, 95.0, 99.0}) {
        double lo = 0.2, hi = 0.9;  // above(t) = (1 - p) A, by bisection on the hand formula
        for (int it = 0; it < 200; ++it) ((tilted_above(0.5 * (lo + hi)) > (1 - p / 100) * A) ? lo : hi) = 0.5 * (lo + hi);
        char key[32];
        std::snprintf(key, sizeof key, "%g", p);
        EXPECT_NEAR(num(pct, key), hi, 1e-9 * std::sqrt(200.81) + 1e-12) << p;  // 1e-9 of the diagonal of [-5,5]^2 x [0,0.9]
    }
    std::string hist = sub(d, "histogram");
    std::vector<double> edges = numbers(sub(hist, "edges")), areas = numbers(sub(hist, "area"));
    ASSERT_EQ(edges.size(), 4u);
    ASSERT_EQ(areas.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(edges[k + 1], 0.9 * (k + 1) / 3, 1e-12);
        EXPECT_NEAR(areas[k], tilted_above(edges[k]) - tilted_above(edges[k + 1]), 1e-9 * A) << k;
    }
    EXPECT_EQ(num(j, "tolerance"), 0.6);
    EXPECT_NE(j.find("\"within_tolerance\": false"), std::string::npos) << j;
}

// A triangle of A whose farthest point from B (B: its three corners, as point triangles) is the
// middle of its hypotenuse, at 2 sqrt 2: no vertex is farther than any tolerance, so the verdict
// needs the whole computation, and a tolerance just below or above the distance flips the exit code.
TEST_F(Cli, ToleranceJustBelowAndAboveTheDistanceFlipsTheExitCode) {
    std::string a = write("big.obj", "v 0 0 0\nv 4 0 0\nv 0 4 0\nf 1 2 3\n");
    std::string b = write("corners.obj", "v 0 0 0\nv 4 0 0\nv 0 4 0\nf 1 1 1\nf 2 2 2\nf 3 3 3\n");
    const double h = 2 * std::sqrt(2.0);
    for (bool stats : {false, true}) {
        SCOPED_TRACE(stats);
        std::vector<std::string> below{"distance", a, b, "--json", "--one-sided", "--tolerance", format_number(h * (1 - 1e-9))};
        std::vector<std::string> above{"distance", a, b, "--json", "--one-sided", "--tolerance", format_number(h * (1 + 1e-9))};
        if (stats) { below.push_back("--stats"); above.push_back("--stats"); }
        Outcome r = run(below);
        EXPECT_EQ(r.code, 4) << r.err;
        EXPECT_NE(r.out.find("\"within_tolerance\": false"), std::string::npos) << r.out;
        EXPECT_NEAR(num(sub(r.out, "a_to_b"), "distance"), h, 1e-12);
        if (!stats) { EXPECT_NE(r.out.find("\"stopped_early\": false"), std::string::npos) << r.out; }
        r = run(above);
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("\"within_tolerance\": true"), std::string::npos) << r.out;
        if (stats) { EXPECT_EQ(num(sub(r.out, "a_to_b"), "fraction_above"), 0.0); }
    }
}

// Two parallel triangles at distance 1: every vertex is farther than 0.5, so the verdict stops at once.
TEST_F(Cli, ToleranceVerdictStopsEarlyAtAFartherVertex) {
    Outcome r = run({"distance", tri_a(), tri_b(), "--json", "--tolerance", "0.5"});
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_TRUE(is_json_object(r.out)) << r.out;
    EXPECT_NE(r.out.find("\"stopped_early\": true"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"within_tolerance\": false"), std::string::npos) << r.out;
    EXPECT_NEAR(num(r.out, "lower"), 1.0, 1e-12);
    std::vector<double> p = numbers(sub(r.out, "point"));
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[2], 0.0);  // a vertex of A
    r = run({"distance", tri_a(), tri_b(), "--tolerance", "0.5"});
    EXPECT_EQ(r.code, 4);
    EXPECT_NE(r.out.find("stopped early"), std::string::npos) << r.out;
    EXPECT_EQ(run({"distance", tri_a(), tri_b(), "--tolerance", "1.000001"}).code, 0);
}

// A mesh against itself is at distance 0, so within a tolerance of 0. The early verdict took a
// vertex's plain point-triangle distance, which rounding puts some 2e-19 off the mesh that has that
// vertex (spot, bunny, camelhead, ...), for a proof that h > 0: "NOT within tolerance 0", exit 4.
TEST_F(Cli, AMeshIsWithinToleranceZeroOfItself) {
    const std::string spot = std::string(HLENS_SHARED_MESHES) + "/spot.obj";
    for (bool stats : {false, true}) {
        SCOPED_TRACE(stats);
        std::vector<std::string> argv{"distance", spot, spot, "--json", "--tolerance", "0"};
        if (stats) argv.push_back("--stats");
        Outcome r = run(argv);
        EXPECT_EQ(r.code, 0) << r.out << r.err;
        EXPECT_NE(r.out.find("\"within_tolerance\": true"), std::string::npos) << r.out;
        EXPECT_EQ(num(r.out, "hausdorff"), 0.0);
    }
}

// The bracket --verify prints holds the exact value as printed: a mesh against itself (h = 0
// exactly) had a lower end of 1.9e-16, the rounding of a computed distance, and was said to hold 0.
TEST_F(Cli, VerifyBracketOfAMeshAgainstItselfHoldsZero) {
    const std::string spot = std::string(HLENS_SHARED_MESHES) + "/spot.obj";
    Outcome r = run({"distance", spot, spot, "--json", "--verify"});
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    for (const char* dir : {"a_to_b", "b_to_a"}) {
        SCOPED_TRACE(dir);
        const std::string d = sub(r.out, dir), v = sub(d, "verify");
        EXPECT_EQ(num(d, "distance"), 0.0);
        EXPECT_EQ(num(v, "lower"), 0.0);
        EXPECT_GT(num(v, "upper"), 0.0);
    }
}

TEST_F(Cli, ExportErrorsWritesPlyWithQuality) {
    std::string a = write("tilt.obj", kTilted), b = write("plane.obj", kPlane);
    const std::string stem = (dir / "err").string();
    Outcome r = run({"distance", a, b, "--export-errors", stem + ".ply"});
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_TRUE(fs::exists(stem + "-ab.ply"));
    ASSERT_TRUE(fs::exists(stem + "-ba.ply"));
    Ply p = read_ply(read_file(stem + "-ab.ply"));
    EXPECT_EQ(p.vertex_props, (std::vector<std::string>{"double x", "double y", "double z", "float quality", "double distance"}));
    EXPECT_EQ(p.face_props, (std::vector<std::string>{"list vertex_indices", "float quality", "double max_distance",
                                                      "double mean_distance", "double rms_distance"}));
    ASSERT_EQ(p.vertices.size(), 3u);
    ASSERT_EQ(p.faces.size(), 1u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(p.vertices[k][4], kZ[k], 1e-12);  // the distance of a corner is its height
        EXPECT_NEAR(p.vertices[k][3], kZ[k], 1e-6);
    }
    const std::vector<double>& f = p.faces[0];
    ASSERT_EQ(f.size(), 8u);
    EXPECT_NEAR(f[5], 0.9, 1e-12);
    EXPECT_NEAR(f[6], (0.2 + 0.5 + 0.9) / 3, 1e-9);
    EXPECT_NEAR(f[7], std::sqrt((0.04 + 0.25 + 0.81 + 0.1 + 0.45 + 0.18) / 6), 1e-9);
    // --one-sided: one file, at the path given.
    r = run({"distance", a, b, "--one-sided", "--export-errors", stem + "1.ply"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(stem + "1.ply"));
    EXPECT_FALSE(fs::exists(stem + "1-ab.ply"));
}

TEST_F(Cli, StatsBadUsage) {
    std::string a = tri_a(), b = tri_b();
    expect_error({"distance", a, b, "--stats", "--histogram", "0"}, "--histogram must be between 1 and 100000");
    expect_error({"distance", a, b, "--stats", "--histogram", "-3"}, "--histogram must be between 1 and 100000");
    expect_error({"distance", a, b, "--histogram", "4"}, "--histogram needs --stats");
    expect_error({"distance", a, b, "--tolerance", "-0.1"}, "--tolerance must be >= 0");
    expect_error({"distance", a, b, "--tolerance", "abc"}, "--tolerance needs a number");
    expect_error({"distance", a, b, "--tolerance", "nan"}, "--tolerance needs a number");
    expect_error({"distance", a, b, "--export-errors", "x.obj"}, "ending in .ply");
    expect_error({"distance", a, b, "--stats=yes"}, "--stats takes no value");
    expect_error({"trace", a, b, "--target", "0", "--stats"}, "unknown option");
}

TEST_F(Cli, StatsReadableSummary) {
    std::string a = write("tilt.obj", kTilted), b = write("plane.obj", kPlane);
    Outcome r = run({"distance", a, b, "--stats", "--tolerance", "0.6"});
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_NE(r.out.find("mean 0.5333333333"), std::string::npos) << r.out;  // (0.2 + 0.5 + 0.9) / 3
    EXPECT_NE(r.out.find("percentiles (by area)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("NOT within tolerance 0.6"), std::string::npos) << r.out;
}

// The statistics and the verdict of distance in the shared report (report.h): with --units and the
// relative values, "within_tolerance" rather than batch's "exceeds"; batch takes none of them.
TEST_F(Cli, StatsAndVerdictInTheSharedReport) {
    std::string a = write("tilt.obj", kTilted), b = write("plane.obj", kPlane);
    Outcome r = run({"distance", a, b, "--json", "--one-sided", "--stats", "--tolerance", "0.6", "--units", "mm"});
    EXPECT_EQ(r.code, 4) << r.err;
    ASSERT_TRUE(is_json_object(r.out)) << r.out;
    std::string d = sub(r.out, "a_to_b");
    EXPECT_NEAR(num(d, "mean"), (0.2 + 0.5 + 0.9) / 3, 1e-9);
    EXPECT_EQ(num(d, "relative"), num(d, "distance") / num(r.out, "diagonal"));
    EXPECT_NE(r.out.find("\"units\": \"mm\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"within_tolerance\": false"), std::string::npos) << r.out;
    EXPECT_FALSE(has_key(r.out, "exceeds")) << r.out;
    // stopped early: the units still pass through
    r = run({"distance", tri_a(), tri_b(), "--json", "--tolerance", "0.5", "--units", "mm"});
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_NE(r.out.find("\"stopped_early\": true"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"units\": \"mm\""), std::string::npos) << r.out;
    expect_error({"batch", a, b, "--export-errors", "x.ply"}, "--export-errors is not available for batch");
    expect_error({"batch", a, b, "--histogram", "3"}, "--histogram needs --stats");
    expect_error({"batch", a, b, "--stats", "--histogram", "0"}, "--histogram must be between 1 and 100000, got 0");
}

// batch --stats gives each pair the statistics `distance --stats` gives that pair, digit for digit
// (17 significant digits: the same doubles), with two pairs at a time (one thread each, where
// distance uses all cores), a histogram and a tolerance.
TEST_F(Cli, BatchStatsEqualDistanceStats) {
    const std::string a = write("ra.obj", obj_text(random_grid(6, 1.0, 0.0, 0.0, 0.25, 12345)));
    const std::vector<std::string> files{write("b0.obj", obj_text(random_grid(5, 1.1, -0.05, 0.03, 0.3, 777))),
                                         write("b1.obj", obj_text(random_grid(4, 0.9, 0.05, 0.0, 0.2, 99)))};
    const std::vector<std::string> opts{"--json", "--stats", "--histogram", "3", "--tolerance", "0.15"};
    std::vector<std::string> args{"batch", a, files[0], files[1], "--jobs", "2"};
    args.insert(args.end(), opts.begin(), opts.end());
    const Outcome batch = run(args);
    const std::vector<std::string> out = lines(batch.out);
    ASSERT_EQ(out.size(), 3u) << batch.out << batch.err;
    int want_code = 0;
    for (size_t k = 0; k < 2; ++k) {
        const std::string& line = out[k];
        ASSERT_TRUE(is_json_object(line)) << line;
        const size_t i = (size_t)num(line, "index");
        ASSERT_LT(i, files.size());
        SCOPED_TRACE(files[i]);
        std::vector<std::string> single{"distance", a, files[i]};
        single.insert(single.end(), opts.begin(), opts.end());
        const Outcome d = run(single);
        ASSERT_TRUE(d.code == 0 || d.code == 4) << d.err;
        if (d.code == 4) want_code = 4;
        EXPECT_EQ(raw(line, "exceeds"), d.code == 4 ? "true" : "false");
        for (const char* dir : {"a_to_b", "b_to_a"}) {
            const std::string got = sub(line, dir), want = sub(d.out, dir);
            for (const char* key : {"area", "mean", "rms", "percentiles", "histogram", "area_above", "fraction_above",
                                    "stats_error", "sliver_triangles", "sliver_area"})
                EXPECT_EQ(raw(got, key), raw(want, key)) << dir << "." << key;
            EXPECT_NE(raw(got, "mean"), "<missing>") << got;
            EXPECT_EQ(numbers(sub(sub(got, "histogram"), "area")).size(), 3u) << got;
            for (const char* key : {"percentile_passes", "rerun_targets"})
                EXPECT_EQ(raw(sub(got, "stats_seconds"), key), raw(sub(want, "stats_seconds"), key)) << dir << "." << key;
        }
    }
    EXPECT_EQ(batch.code, want_code) << batch.err;
    // the readable form shows them too
    const Outcome text = run({"batch", a, files[0], "--stats"});
    EXPECT_EQ(text.code, 0) << text.err;
    EXPECT_NE(text.out.find("h(B,A):\n   area "), std::string::npos) << text.out;
}

// On a pair of bumpy grids: each direction's area is its mesh's area (cross products here), the
// histogram's areas add up to it, the percentiles rise and lie within [0, distance], and the
// fraction above the distance itself is 0.
TEST_F(Cli, StatsOfARandomPairAreConsistent) {
    const Obj ga = random_grid(8, 1.0, 0.0, 0.0, 0.25, 12345), gb = random_grid(7, 1.1, -0.05, 0.03, 0.3, 777);
    const std::string a = write("ra.obj", obj_text(ga)), b = write("rb.obj", obj_text(gb));
    auto area = [](const Obj& m) {
        double s = 0;
        for (auto f : m.f) {
            const P3 &p = m.v[f[0]], &q = m.v[f[1]], &r = m.v[f[2]];
            const double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z, vx = r.x - p.x, vy = r.y - p.y, vz = r.z - p.z;
            const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
            s += 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
        }
        return s;
    };
    std::string j = run_json({"distance", a, b, "--json", "--stats", "--histogram", "5"});
    for (const char* dir : {"a_to_b", "b_to_a"}) {
        SCOPED_TRACE(dir);
        const std::string d = sub(j, dir);
        const double want = std::string(dir) == "a_to_b" ? area(ga) : area(gb), h = num(d, "distance");
        EXPECT_NEAR(num(d, "area"), want, 1e-11 * want);
        double sum = 0;
        for (double x : numbers(sub(sub(d, "histogram"), "area"))) { EXPECT_GE(x, 0.0); sum += x; }
        EXPECT_NEAR(sum, want, 1e-11 * want);
        const std::string p = sub(d, "percentiles");
        const double p50 = num(p, "50"), p90 = num(p, "90"), p95 = num(p, "95"), p99 = num(p, "99");
        EXPECT_LE(0.0, p50);
        EXPECT_LE(p50, p90);
        EXPECT_LE(p90, p95);
        EXPECT_LE(p95, p99);
        EXPECT_LE(p99, h + 1e-9);
        EXPECT_LE(num(d, "mean"), num(d, "rms") * (1 + 1e-12));
        EXPECT_LE(num(d, "rms"), h * (1 + 1e-12));
    }
    Outcome r = run({"distance", a, b, "--json", "--stats", "--one-sided", "--tolerance", format_number(num(sub(j, "a_to_b"), "distance"))});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(num(sub(r.out, "a_to_b"), "fraction_above"), 0.0);
}
