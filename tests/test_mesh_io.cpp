// Tests for core/mesh_io: small files written here with exact expected contents, the shared real
// meshes (counts from /work/shared/meshes/README.md), error messages, and truncation/corruption fuzzing.
#include <hlens/mesh_io.h>

#include <gtest/gtest.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"  // OpenMesh's VectorT() leaves its data uninitialised
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#pragma GCC diagnostic pop

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using hlens::LoadOptions;
using hlens::MeshError;
using hlens::TriangleMesh;
using hlens::Tri;
using hlens::Vec3;

namespace {

const std::string kShared = HLENS_SHARED_MESHES;

// A fresh directory per test, removed afterwards.
class MeshIOTest : public ::testing::Test {
protected:
    fs::path dir;
    void SetUp() override {
        static const unsigned run = std::random_device{}();
        static std::atomic<int> counter{0};
        dir = fs::path(::testing::TempDir()) /
              ("hlens_mesh_io_" + std::to_string(run) + "_" + std::to_string(counter++));
        fs::create_directories(dir);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    std::string write(const std::string& name, const std::string& content) {
        std::string p = (dir / name).string();
        std::ofstream(p, std::ios::binary) << content;
        return p;
    }
};

// EXPECT that loading `path` throws MeshError naming the file and containing `word` (case-insensitive).
void expect_error(const std::string& path, const std::string& word, const LoadOptions& opt = {}) {
    auto low = [](std::string s) {
        for (char& c : s) c = char(std::tolower((unsigned char)c));
        return s;
    };
    try {
        hlens::load_mesh(path, opt);
        ADD_FAILURE() << path << ": expected MeshError containing '" << word << "'";
    } catch (const MeshError& e) {
        std::string msg = e.what();
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_NE(low(msg).find(low(word)), std::string::npos) << "'" << word << "' not in: " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
}

double area(const TriangleMesh& m, size_t t) {
    auto c = m.corners(t);
    return 0.5 * hlens::norm(hlens::cross(c[1] - c[0], c[2] - c[0]));
}

template <class T>
void put(std::string& s, T v, bool big = false) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));  // the test machine is little-endian (checked below)
    if (big) std::reverse(b, b + sizeof(T));
    s.append(reinterpret_cast<const char*>(b), sizeof(T));
}

std::string read_bytes(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::string base64(const std::string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        uint32_t n = uint32_t((unsigned char)in[i]) << 16;
        if (i + 1 < in.size()) n |= uint32_t((unsigned char)in[i + 1]) << 8;
        if (i + 2 < in.size()) n |= uint32_t((unsigned char)in[i + 2]);
        out += t[(n >> 18) & 63];
        out += t[(n >> 12) & 63];
        out += i + 1 < in.size() ? t[(n >> 6) & 63] : '=';
        out += i + 2 < in.size() ? t[n & 63] : '=';
    }
    return out;
}

TEST(MeshIOSetup, LittleEndianHost) {
    uint16_t one = 1;
    unsigned char b;
    std::memcpy(&b, &one, 1);
    ASSERT_EQ(b, 1) << "the binary writers in these tests assume a little-endian host";
}

// ============================================================== OBJ

TEST_F(MeshIOTest, ObjTriangleExact) {
    auto p = write("tri.obj", "# comment\nv 0 0 0\nv 1.5 -2 3e-3\nv 0 1 0 1.0\nf 1 2 3\n");
    TriangleMesh m = hlens::load_mesh(p);
    EXPECT_EQ(m.path, p);
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[1], Vec3(1.5, -2, 3e-3));
    EXPECT_EQ(m.positions[2], Vec3(0, 1, 0));
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));
}

TEST_F(MeshIOTest, ObjUnitQuadGivesTwoTriangles) {
    auto p = write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    TriangleMesh m = hlens::load_mesh(p);
    ASSERT_EQ(m.num_triangles(), 2u);
    EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));  // fan
    EXPECT_EQ(m.triangles[1], (Tri{0, 2, 3}));
    EXPECT_DOUBLE_EQ(area(m, 0) + area(m, 1), 1.0);
}

// An L-shaped hexagon (area 3), every starting corner and both orientations, in the plane z=0 and
// tilted into the plane z=x (area sqrt 2 larger). Ear clipping must keep the area and stay inside.
TEST_F(MeshIOTest, ObjNonConvexPolygonEarClipping) {
    const double L[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    auto inside_L = [](double x, double y) { return x > 0 && y > 0 && (x < 1 || y < 1) && x < 2 && y < 2; };
    int n = 0;
    for (int tilt = 0; tilt < 2; ++tilt)
        for (int rev = 0; rev < 2; ++rev)
            for (int start = 0; start < 6; ++start) {
                std::string obj;
                for (auto& c : L) obj += "v " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " +
                                         (tilt ? std::to_string(c[0]) : "0") + "\n";
                obj += "f";
                for (int k = 0; k < 6; ++k) obj += " " + std::to_string((rev ? start - k + 12 : start + k) % 6 + 1);
                auto p = write("L" + std::to_string(n++) + ".obj", obj + "\n");
                TriangleMesh m = hlens::load_mesh(p);
                ASSERT_EQ(m.num_triangles(), 4u) << obj;
                double sum = 0;
                Vec3 poly_normal(0, 0, rev ? -1 : 1);
                for (size_t t = 0; t < 4; ++t) {
                    auto c = m.corners(t);
                    Vec3 g = (c[0] + c[1] + c[2]) / 3;
                    EXPECT_TRUE(inside_L(g.x, g.y)) << obj << " triangle " << t;
                    Vec3 nrm = hlens::cross(c[1] - c[0], c[2] - c[0]);
                    EXPECT_GE(nrm.z * poly_normal.z, 0) << "triangle flipped: " << obj;
                    sum += area(m, t);
                }
                EXPECT_NEAR(sum, tilt ? 3 * std::sqrt(2.0) : 3.0, 1e-12) << obj;
            }
}

TEST_F(MeshIOTest, ObjNegativeIndicesAndCornerForms) {
    auto p = write("forms.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                   "f -3 -2 -1\n"
                   "f 1/1 2/2 3/3\n"
                   "f 1//1 2//1 3//1\n"
                   "f 1/1/1 2/2/1 3/3/1\n"
                   "v 0 0 5\n"
                   "f -4/-3/-1 -3//-1 -1\n");
    TriangleMesh m = hlens::load_mesh(p, {false});
    ASSERT_EQ(m.num_triangles(), 5u);
    for (int t = 0; t < 4; ++t) EXPECT_EQ(m.triangles[size_t(t)], (Tri{0, 1, 2}));
    EXPECT_EQ(m.triangles[4], (Tri{0, 1, 3}));
}

TEST_F(MeshIOTest, ObjIgnoresOtherStatementsCrlfAndComments) {
    auto p = write("misc.obj",
                   "mtllib a.mtl\r\no thing\r\ng grp\r\ns 1\r\nusemtl red\r\n"
                   "v 0 0 0 # origin\r\nv 1 0 0\r\n\r\n   \r\nv 0 1 0\r\nl 1 2\r\np 3\r\nf 1 2 3 # tri\r\n");
    TriangleMesh m = hlens::load_mesh(p);
    ASSERT_EQ(m.num_triangles(), 1u);
    EXPECT_EQ(m.positions[2], Vec3(0, 1, 0));
}

TEST_F(MeshIOTest, ObjFullDoublePrecision) {
    const char* s = "0.1234567890123456789";
    auto p = write("prec.obj", std::string("v ") + s + " -1e-300 123456789.123456789\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    TriangleMesh m = hlens::load_mesh(p);
    EXPECT_EQ(m.positions[0].x, std::strtod(s, nullptr));
    EXPECT_NE(m.positions[0].x, double(float(m.positions[0].x)));  // not squeezed through float
    EXPECT_EQ(m.positions[0].y, -1e-300);
    EXPECT_EQ(m.positions[0].z, std::strtod("123456789.123456789", nullptr));
}

TEST_F(MeshIOTest, ObjDegenerateAndRepeatedCorners) {
    // A triangle using a vertex twice is kept; a quad with a repeated corner is a triangle;
    // a collinear quad gives degenerate triangles; a polygon with < 3 distinct corners is an error.
    auto p = write("degen.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\n"
                                "f 1 1 2\nf 1 2 2 3\nf 1 2 4 5\n");
    TriangleMesh m = hlens::load_mesh(p, {false});
    ASSERT_EQ(m.num_triangles(), 4u);
    EXPECT_EQ(m.triangles[0], (Tri{0, 0, 1}));
    EXPECT_EQ(m.triangles[1], (Tri{0, 1, 2}));
    EXPECT_EQ(area(m, 2) + area(m, 3), 0.0);
    expect_error(write("two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1 2\n"), "fewer than 3 distinct");
    expect_error(write("bowtie.obj", "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n"), "cannot be triangulated");
}

TEST_F(MeshIOTest, ObjErrors) {
    expect_error(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n"), "face 2: vertex index 9 out of range");
    expect_error(write("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 -2 -1\n"), "out of range");
    expect_error(write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "out of range");
    expect_error(write("num.obj", "v 0 0 0\nv 1 0x 0\nv 0 1 0\nf 1 2 3\n"), "malformed");
    expect_error(write("short.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n"), "malformed");
    expect_error(write("idx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 a\n"), "malformed");
    expect_error(write("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), "fewer than 3 corners");
    expect_error(write("none.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no triangles");
    expect_error(write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"), "NaN");
    expect_error(write("inf.obj", "v 0 0 0\nv 1 1e999 0\nv 0 1 0\nf 1 2 3\n"), "infinite");
    // An unused NaN vertex is not part of the surface.
    TriangleMesh m = hlens::load_mesh(write("nan_unused.obj", "v nan 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n"));
    EXPECT_EQ(m.num_triangles(), 1u);
}

TEST_F(MeshIOTest, WeldOnOff) {
    // Two triangles sharing an edge, the shared corners written twice; -0 and 0 are the same point.
    auto p = write("weld.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nv -0 1 0\nv 5 5 5\nf 1 2 3\nf 4 5 6\n");
    TriangleMesh a = hlens::load_mesh(p);
    EXPECT_EQ(a.positions.size(), 5u);  // unused (5,5,5) kept
    EXPECT_EQ(a.num_used_vertices(), 4u);
    EXPECT_EQ(a.triangles[0], (Tri{0, 1, 2}));
    EXPECT_EQ(a.triangles[1], (Tri{1, 3, 2}));
    TriangleMesh b = hlens::load_mesh(p, {false});
    EXPECT_EQ(b.positions.size(), 7u);
    EXPECT_EQ(b.triangles[1], (Tri{3, 4, 5}));
}

// ============================================================== PLY

TEST_F(MeshIOTest, PlyAsciiWithExtraProperties) {
    auto p = write("a.ply",
                   "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info x\r\n"
                   "element vertex 4\r\nproperty float32 x\r\nproperty float32 y\r\nproperty double z\r\n"
                   "property float confidence\r\nproperty float32 intensity\r\nproperty float nx\r\n"
                   "element face 2\r\nproperty uchar flags\r\nproperty list uint8 int32 vertex_indices\r\n"
                   "property list uchar float texcoord\r\n"
                   "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\n"
                   "end_header\r\n"
                   "0 0 0.1234567890123456789 0.5 0.5 0\r\n1 0 0 0.5 0.5 0\r\n1 1 0 1 1 1\r\n0 1 0 1 1 1\r\n"
                   "7 3 0 1 2 2 0.5 0.5\r\n7 4 0 1 2 3 0\r\n0 1\r\n");
    TriangleMesh m = hlens::load_mesh(p);
    ASSERT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.positions[0], Vec3(0, 0, std::strtod("0.1234567890123456789", nullptr)));
    ASSERT_EQ(m.num_triangles(), 3u);
    EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (Tri{0, 1, 2}));  // the quad, fanned
    EXPECT_EQ(m.triangles[2], (Tri{0, 2, 3}));
}

// Binary PLY with doubles, extra vertex/face properties, int/uchar list types, vertex_index name.
std::string binary_ply(bool big) {
    std::string h = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\ncomment test\nelement vertex 4\nproperty double x\nproperty uchar red\n"
                    "property double y\nproperty double z\nproperty float confidence\n"
                    "element face 2\nproperty list int uint vertex_index\nproperty list uchar short extra\n"
                    "end_header\n";
    const double v[4][3] = {{0.1, 0.2, 0.3}, {1.0 / 3, 0, 0}, {0, 1e-300, 0}, {0, 0, -7.25}};
    for (auto& c : v) {
        put(h, c[0], big);
        put(h, uint8_t(200), big);
        put(h, c[1], big);
        put(h, c[2], big);
        put(h, 0.75f, big);
    }
    put(h, int32_t(3), big);
    for (uint32_t i : {0u, 1u, 2u}) put(h, i, big);
    put(h, uint8_t(2), big);
    put(h, int16_t(-1), big);
    put(h, int16_t(5), big);
    put(h, int32_t(4), big);
    for (uint32_t i : {0u, 1u, 3u, 2u}) put(h, i, big);
    put(h, uint8_t(0), big);
    return h;
}

TEST_F(MeshIOTest, PlyBinaryLittleAndBigEndian) {
    for (bool big : {false, true}) {
        auto p = write(big ? "be.ply" : "le.ply", binary_ply(big));
        TriangleMesh m = hlens::load_mesh(p);
        ASSERT_EQ(m.positions.size(), 4u);
        EXPECT_EQ(m.positions[0], Vec3(0.1, 0.2, 0.3));
        EXPECT_EQ(m.positions[1], Vec3(1.0 / 3, 0, 0));
        EXPECT_EQ(m.positions[2], Vec3(0, 1e-300, 0));
        EXPECT_EQ(m.positions[3], Vec3(0, 0, -7.25));
        ASSERT_EQ(m.num_triangles(), 3u);
        EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));
        std::set<uint32_t> quad_corners;
        for (size_t t = 1; t < 3; ++t)
            for (uint32_t i : m.triangles[t]) quad_corners.insert(i);
        EXPECT_EQ(quad_corners, (std::set<uint32_t>{0, 1, 2, 3}));
    }
}

TEST_F(MeshIOTest, PlyErrors) {
    std::string good = binary_ply(false);
    expect_error(write("trunc.ply", good.substr(0, good.size() - 3)), "truncated");
    std::string hdr_end = "end_header\n";
    std::string header = good.substr(0, good.find(hdr_end) + hdr_end.size());
    expect_error(write("trunc_header_only.ply", header), "truncated");
    expect_error(write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"), "truncated");
    // A lying count must not allocate: 4e9 vertices declared, a few bytes present.
    std::string lie = header;
    lie.replace(lie.find("vertex 4"), 8, "vertex 4000000000");
    expect_error(write("lie.ply", lie + good.substr(header.size())), "truncated");
    std::string lie_face = header;
    lie_face.replace(lie_face.find("face 2"), 6, "face 3000000000");
    expect_error(write("lieface.ply", lie_face + good.substr(header.size())), "truncated");

    const std::string ah = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    expect_error(write("a_trunc.ply", ah + "0 0 0\n1 0 0\n"), "truncated");
    expect_error(write("a_trunc_face.ply", ah + "0 0 0\n1 0 0\n0 1 0\n"), "truncated");
    expect_error(write("a_range.ply", ah + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "face 1: vertex index 3 out of range");
    expect_error(write("a_num.ply", ah + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"), "malformed number");
    expect_error(write("a_nan.ply", ah + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"), "NaN");
    expect_error(write("a_two.ply", ah + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), "fewer than 3 corners");
    expect_error(write("a_noface.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                       "property float z\nend_header\n0 0 0\n"),
                 "no triangles");
    expect_error(write("magic.ply", "plx\n"), "not a PLY");
    expect_error(write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n"),
                 "unknown PLY property type");
}

// Found by fuzz/fuzz_ply.cpp: an ASCII list length is a number like any other, 1e30 included, and was
// converted to an integer unchecked (undefined behaviour). A length must fit its declared count type.
TEST_F(MeshIOTest, PlyListLengthBeyondItsCountType) {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list ";
    const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
    auto ply = [&](const std::string& count_type, const std::string& face) {
        return head + count_type + " int vertex_indices\nend_header\n" + verts + face;
    };
    expect_error(write("huge.ply", ply("uchar", "1e30 0 1 2\n")), "invalid list length in 'face' element 0");
    expect_error(write("uchar.ply", ply("uchar", "256 0 1 2\n")), "invalid list length");
    expect_error(write("float.ply", ply("float", "1e30 0 1 2\n")), "invalid list length");
    expect_error(write("neg.ply", ply("int", "-3 0 1 2\n")), "invalid list length");
    EXPECT_EQ(hlens::load_mesh(write("ok.ply", ply("uchar", "3 0 1 2\n"))).num_triangles(), 1u);
    EXPECT_EQ(hlens::load_mesh(write("okf.ply", ply("float", "3 0 1 2\n"))).num_triangles(), 1u);
    // Binary: a float count that no integer type could hold.
    std::string bin = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list float int vertex_indices\nend_header\n";
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(bin, f);
    put(bin, 1e30f);
    for (int32_t i : {0, 1, 2}) put(bin, i);
    expect_error(write("binf.ply", bin), "invalid list length");
}

// ============================================================== STL

std::string binary_stl(const std::string& header80, const std::vector<std::array<float, 9>>& tris) {
    std::string s = header80;
    s.resize(80, ' ');
    put(s, uint32_t(tris.size()));
    for (auto& t : tris) {
        for (int i = 0; i < 3; ++i) put(s, 0.0f);  // normal
        for (float f : t) put(s, f);
        put(s, uint16_t(0));
    }
    return s;
}

const std::vector<std::array<float, 9>> kStlTris = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0.1f}};

TEST_F(MeshIOTest, StlBinaryWithSolidHeader) {
    for (const char* header : {"solid but actually binary", "binary header"}) {
        auto p = write("b.stl", binary_stl(header, kStlTris));
        TriangleMesh w = hlens::load_mesh(p);
        ASSERT_EQ(w.num_triangles(), 2u);
        EXPECT_EQ(w.positions.size(), 5u);  // (0,1,0) and (0,1,0.1f) differ
        EXPECT_EQ(w.positions[4], Vec3(0, 1, double(0.1f)));
        TriangleMesh s = hlens::load_mesh(p, {false});
        EXPECT_EQ(s.positions.size(), 6u);
        EXPECT_EQ(s.triangles[1], (Tri{3, 4, 5}));
        EXPECT_EQ(w.triangles[1], (Tri{1, 3, 4}));
    }
}

TEST_F(MeshIOTest, StlAscii) {
    const std::string body =
        "facet normal 0 0 1\r\n outer loop\r\n  vertex 0 0 0\r\n  vertex 1 0 0\r\n  vertex 0 1 0.1234567890123456789\r\n"
        " endloop\r\nendfacet\r\n"
        "FACET NORMAL 0 0 1\r\n OUTER LOOP\r\n  VERTEX 1 0 0\r\n  VERTEX 1 1 0\r\n  VERTEX 0 1 0.1234567890123456789\r\n"
        " ENDLOOP\r\nENDFACET\r\n";
    for (std::string text : {"solid vertex\r\n" + body + "endsolid vertex\r\n", body}) {  // "solid" is optional
        auto p = write("a.stl", text);
        TriangleMesh w = hlens::load_mesh(p);
        ASSERT_EQ(w.num_triangles(), 2u);
        EXPECT_EQ(w.positions.size(), 4u);
        EXPECT_EQ(w.positions[2].z, std::strtod("0.1234567890123456789", nullptr));
        EXPECT_EQ(w.triangles[1], (Tri{1, 3, 2}));
        EXPECT_EQ(hlens::load_mesh(p, {false}).positions.size(), 6u);
    }
}

TEST_F(MeshIOTest, StlErrors) {
    std::string good = binary_stl("solid x", kStlTris);
    expect_error(write("trunc.stl", good.substr(0, good.size() - 1)), "truncated");
    expect_error(write("short.stl", good.substr(0, 90)), "truncated");
    expect_error(write("short2.stl", binary_stl("\x01\x02 binary", kStlTris).substr(0, 50)), "truncated");
    std::string lie = good;
    lie[83] = char(0x7f);  // ~2e9 triangles declared
    expect_error(write("lie.stl", lie), "truncated");
    expect_error(write("zero.stl", binary_stl("x", {})), "no triangles");
    expect_error(write("a_trunc.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"), "truncated");
    expect_error(write("a_num.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 O 0\n"),
                 "malformed");
    expect_error(write("a_none.stl", "solid s\nendsolid s\n"), "no triangles");
}

// ============================================================== OFF

TEST_F(MeshIOTest, OffVariants) {
    const std::string body = "4 2 0\r\n# a comment\r\n\r\n0 0 0\r\n1 0 0\r\n1 1 0.1234567890123456789\r\n0 1 0\r\n"
                             "3 0 1 2\r\n3 0 2 3 # trailing comment\r\n";
    TriangleMesh m = hlens::load_mesh(write("a.off", "OFF\r\n" + body));
    ASSERT_EQ(m.num_triangles(), 2u);
    EXPECT_EQ(m.positions[2], Vec3(1, 1, std::strtod("0.1234567890123456789", nullptr)));
    EXPECT_EQ(m.triangles[1], (Tri{0, 2, 3}));
    // Counts on the header line, COFF colours, a quad with a face colour.
    TriangleMesh c = hlens::load_mesh(write("c.off", "COFF 4 1 0\n0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n"
                                                     "1 1 0 0 255 0 255\n0 1 0 0 0 255 255\n4 0 1 2 3 1 0 0\n"));
    ASSERT_EQ(c.num_triangles(), 2u);
    EXPECT_DOUBLE_EQ(area(c, 0) + area(c, 1), 1.0);
    // NOFF: normals after the coordinates.
    TriangleMesh n = hlens::load_mesh(write("n.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"));
    EXPECT_EQ(n.positions[1], Vec3(1, 0, 0));
    EXPECT_EQ(n.num_triangles(), 1u);
}

TEST_F(MeshIOTest, OffErrors) {
    expect_error(write("tv.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n"), "truncated");
    expect_error(write("tf.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n"), "truncated");
    expect_error(write("r.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 5\n"), "vertex index 5 out of range");
    expect_error(write("m.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 x\n3 0 1 2\n"), "malformed");
    expect_error(write("mf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n4 0 1 2\n"), "malformed");
    expect_error(write("h.off", "3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n"), "OFF header");
    expect_error(write("nf.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n1 1 0\n"), "no triangles");
    expect_error(write("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n1 inf 0\n3 0 1 2\n"), "infinite");
}

// ============================================================== glTF / GLB

// One buffer: 4 float positions P0=(0,0,0) P1=(1,0,0) P2=(0,2,0) P3=(0,0,3), then uint8 indices
// 0 1 2 0 2 3, uint16 indices 0 1 2 3 and uint32 indices 0 1 2 3.
std::string gltf_buffer() {
    std::string b;
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 2.f, 0.f, 0.f, 0.f, 3.f}) put(b, f);
    for (uint8_t i : {0, 1, 2, 0, 2, 3}) put(b, i);
    b.append(2, '\0');
    for (uint16_t i : {0, 1, 2, 3}) put(b, i);
    for (uint32_t i : {0u, 1u, 2u, 3u}) put(b, i);
    return b;  // 80 bytes
}

// Root node: rotation +90 degrees about x, then translation (10,0,0) (matrix); child: TRS with
// T=(0,5,0), R=180 degrees about z, S=(2,3,4). Primitives: triangles (uint8), points (skipped),
// strip (uint16), fan (uint32), non-indexed triangles. `idx8` replaces the first uint8 accessor.
std::string gltf_json(const std::string& buffer_uri, int idx8_count = 6) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"children":[1],"matrix":[1,0,0,0, 0,0,1,0, 0,-1,0,0, 10,0,0,1]},
         {"mesh":0,"translation":[0,5,0],"rotation":[0,0,1,0],"scale":[2,3,4]},
         {"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":4},
                         {"attributes":{"POSITION":0},"mode":0},
                         {"attributes":{"POSITION":0},"indices":2,"mode":5},
                         {"attributes":{"POSITION":0},"indices":3,"mode":6},
                         {"attributes":{"POSITION":0}}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,2,3]},
             {"bufferView":1,"componentType":5121,"count":)" +
           std::to_string(idx8_count) + R"(,"type":"SCALAR"},
             {"bufferView":2,"componentType":5123,"count":4,"type":"SCALAR"},
             {"bufferView":3,"componentType":5125,"count":4,"type":"SCALAR"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":6},
               {"buffer":0,"byteOffset":56,"byteLength":8},{"buffer":0,"byteOffset":64,"byteLength":16}],
"buffers":[{"byteLength":80)" +
           (buffer_uri.empty() ? std::string() : ",\"uri\":\"" + buffer_uri + "\"") + "}]}";
}

std::string make_glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string g = "glTF";
    put(g, uint32_t(2));
    put(g, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    put(g, uint32_t(json.size()));
    g += "JSON" + json;
    put(g, uint32_t(bin.size()));
    g += std::string("BIN\0", 4) + bin;
    return g;
}

void check_synthetic_gltf(const std::string& p) {
    // child: p -> R(S p) + T; root: (a,b,c) -> (a+10, -c, b)
    const Vec3 Q[4] = {{10, 0, 5}, {8, 0, 5}, {10, 0, -1}, {10, -12, 5}};
    TriangleMesh m = hlens::load_mesh(p, {false});
    ASSERT_EQ(m.positions.size(), 16u);  // 4 triangle primitives x 4 positions; the points primitive is skipped
    for (size_t i = 0; i < 16; ++i) EXPECT_EQ(m.positions[i], Q[i % 4]) << i;
    const std::vector<Tri> want = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {5, 7, 6}, {9, 10, 8}, {10, 11, 8}, {12, 13, 14}};
    EXPECT_EQ(m.triangles, want);
    TriangleMesh w = hlens::load_mesh(p);
    EXPECT_EQ(w.positions.size(), 4u);
    EXPECT_EQ(w.num_triangles(), 7u);
}

TEST_F(MeshIOTest, GltfEmbeddedTransformsModesAndIndexTypes) {
    check_synthetic_gltf(write("s.gltf", gltf_json("data:application/octet-stream;base64," + base64(gltf_buffer()))));
}

TEST_F(MeshIOTest, GltfExternalBufferAndGlb) {
    write("buf.bin", gltf_buffer());
    check_synthetic_gltf(write("ext.gltf", gltf_json("buf.bin")));
    check_synthetic_gltf(write("s.GLB", make_glb(gltf_json(""), gltf_buffer())));
}

TEST_F(MeshIOTest, GltfErrors) {
    expect_error(write("bad.gltf", "{ this is not json"), "glTF parse error");
    expect_error(write("bad.glb", "glTF but not really a binary gltf file"), "glTF parse error");
    expect_error(write("nobuf.gltf", gltf_json("missing.bin")), "glTF parse error");
    std::string b = gltf_buffer();
    b[48 + 5] = 9;  // uint8 index 9 of 4 vertices
    expect_error(write("range.glb", make_glb(gltf_json(""), b)), "out of range");
    expect_error(write("past.glb", make_glb(gltf_json("", 7), gltf_buffer())), "past the end");
    std::string pts = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":0}]}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"}],
        "bufferViews":[{"buffer":0,"byteLength":48}],"buffers":[{"byteLength":80}]})";
    expect_error(write("points.glb", make_glb(pts, gltf_buffer())), "no triangles");
    std::string cyc = gltf_json("");
    cyc.replace(cyc.find("{\"mesh\":0,\"translation\""), 1, "{\"children\":[0],");
    expect_error(write("cycle.glb", make_glb(cyc, gltf_buffer())), "cycle");
}

// ============================================================== from memory

// EXPECT that load_mesh_from_memory(bytes, name) throws MeshError "<name>: ..." containing `word`.
void expect_memory_error(const std::string& bytes, const std::string& name, const std::string& word) {
    try {
        hlens::load_mesh_from_memory(bytes.data(), bytes.size(), name);
        ADD_FAILURE() << name << ": expected MeshError containing '" << word << "'";
    } catch (const MeshError& e) {
        std::string msg = e.what();
        EXPECT_EQ(msg.rfind(name + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find(word), std::string::npos) << "'" << word << "' not in: " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
}

void expect_same_mesh(const TriangleMesh& a, const TriangleMesh& b, const std::string& what) {
    EXPECT_EQ(a.triangles, b.triangles) << what;
    ASSERT_EQ(a.positions.size(), b.positions.size()) << what;
    for (size_t i = 0; i < a.positions.size(); ++i)
        EXPECT_EQ(std::memcmp(&a.positions[i], &b.positions[i], sizeof(Vec3)), 0) << what << " vertex " << i;
}

TEST_F(MeshIOTest, FromMemoryReadsLikeAFile) {
    const std::vector<std::pair<std::string, std::string>> files = {
        {"m.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf -1 -2 -3\n"},
        {"m.OFF", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n4 0 1 2 3\n"},
        {"m.ply", binary_ply(true)},
        {"m.stl", binary_stl("solid x", kStlTris)},
        {"m.glb", make_glb(gltf_json(""), gltf_buffer())},
        {"m.gltf", gltf_json("data:application/octet-stream;base64," + base64(gltf_buffer()))},
    };
    for (const auto& [name, bytes] : files)
        for (bool weld : {true, false}) {
            const std::string path = write(name, bytes);
            TriangleMesh f = hlens::load_mesh(path, {weld});
            TriangleMesh m = hlens::load_mesh_from_memory(bytes.data(), bytes.size(), name, {weld});
            EXPECT_EQ(m.path, name);
            EXPECT_GT(m.num_triangles(), 0u) << name;
            expect_same_mesh(f, m, name);
        }
}

TEST_F(MeshIOTest, FromMemoryErrors) {
    expect_memory_error("", "a.obj", "empty file");
    expect_memory_error("v 0 0 0\n", "mesh.xyz", "unknown file extension '.xyz'");
    expect_memory_error("v 0 0 0\n", "mesh", "unknown file extension");
    expect_memory_error("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "in memory.obj", "out of range");
    expect_memory_error("plx\n", "x.ply", "not a PLY");
    // Nothing is read from disk: an external buffer is an error even when the file is right there,
    // next to the name given.
    const std::string json = gltf_json("buf.bin");
    write("buf.bin", gltf_buffer());
    check_synthetic_gltf(write("ext.gltf", json));
    expect_memory_error(json, (dir / "ext.gltf").string(), "buf.bin");
    expect_memory_error(json, (dir / "ext.gltf").string(), "when reading from memory");
}

// ============================================================== save / make

TEST_F(MeshIOTest, SaveObjRoundTripsExactly) {
    std::vector<Vec3> pos = {{0.1, 1.0 / 3, -1e-300}, {std::nextafter(1.0, 2.0), 123456789.123456789, -0.0},
                             {5e-324, 1e308, 2.5}, {7, 7, 7}};
    TriangleMesh m = hlens::make_mesh(pos, {{0, 1, 2}, {2, 1, 0}}, "mem");
    EXPECT_EQ(m.path, "mem");
    auto p = (dir / "out.obj").string();
    hlens::save_obj(m, p);
    TriangleMesh r = hlens::load_mesh(p, {false});
    ASSERT_EQ(r.positions.size(), 4u);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(std::memcmp(&r.positions[i], &pos[i], sizeof(Vec3)), 0) << i;
    }
    EXPECT_EQ(r.triangles, m.triangles);
    EXPECT_THROW(hlens::save_obj(m, (dir / "no_such_dir" / "x.obj").string()), MeshError);
}

TEST(MeshIOMakeMesh, Validates) {
    EXPECT_EQ(hlens::make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}).num_triangles(), 1u);
    auto err = [](std::vector<Vec3> p, std::vector<Tri> t) -> std::string {
        try {
            hlens::make_mesh(std::move(p), std::move(t), "m1");
        } catch (const MeshError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_NE(err({{0, 0, 0}}, {}).find("m1: no triangles"), std::string::npos);
    EXPECT_NE(err({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}).find("out of range"), std::string::npos);
    EXPECT_NE(err({{0, 0, 0}, {1, 0, 0}, {NAN, 0, 0}}, {{0, 1, 2}}).find("NaN"), std::string::npos);
    EXPECT_EQ(err({{NAN, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{1, 2, 3}}), "no error");
}

// ============================================================== file-level errors

TEST_F(MeshIOTest, FileErrors) {
    expect_error((dir / "nope.obj").string(), "not found");
    fs::create_directories(dir / "d.obj");
    expect_error((dir / "d.obj").string(), "cannot open");
    if (fs::exists("/dev/zero")) {
        fs::create_symlink("/dev/zero", dir / "zero.stl");
        expect_error((dir / "zero.stl").string(), "cannot open");  // must not read forever
    }
    expect_error(write("x.xyz", "v 0 0 0\n"), "unknown file extension");
    expect_error(write("noext", "v 0 0 0\n"), "unknown file extension");
    for (const char* f : {"e.obj", "e.ply", "e.stl", "e.off", "e.gltf", "e.glb"}) expect_error(write(f, ""), "empty");
    // Extensions are case-insensitive.
    EXPECT_EQ(hlens::load_mesh(write("T.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).num_triangles(), 1u);
}

// ============================================================== real meshes

std::string shared(const std::string& name) {
    std::string p = kShared + "/" + name;
    return p;
}

#define REQUIRE_SHARED(name) \
    if (!fs::exists(shared(name))) GTEST_SKIP() << shared(name) << " not present"

TEST(MeshIOReal, CountsFromReadme) {
    struct Case { const char* file; size_t tris, positions, used; };
    const Case cases[] = {
        {"bunny.ply", 69451, 35947, 34834},          {"suzanne.obj", 968, 505, 505},
        {"counter.unitsmm.STL", 83750, 41837, 41837}, {"1002_tray_bottom.STL", 4520, 2216, 2216},
        {"horse.ply", 96966, 48485, 48485},          {"camelhead.off", 22704, 11381, 11381},
        {"featuretype.STL", 3476, 2010, 2010},       {"beetle.obj", 2053, 1148, 1148},
        {"truck.obj", 4770, 2956, 2956},             {"teapot.obj", 6320, 3241, 3241},
        {"Box.gltf", 12, 8, 8},                      {"Duck.glb", 4212, 2108, 2108},
    };
    for (const Case& c : cases) {
        if (!fs::exists(shared(c.file))) {
            ADD_FAILURE() << "missing " << shared(c.file);
            continue;
        }
        TriangleMesh m = hlens::load_mesh(shared(c.file));
        EXPECT_EQ(m.num_triangles(), c.tris) << c.file;
        EXPECT_EQ(m.positions.size(), c.positions) << c.file;
        EXPECT_EQ(m.num_used_vertices(), c.used) << c.file;
    }
    EXPECT_EQ(hlens::load_mesh(shared("counter.unitsmm.STL"), {false}).positions.size(), 251250u);
    EXPECT_EQ(hlens::load_mesh(shared("suzanne.obj"), {false}).positions.size(), 507u);
}

// Box.gltf: the root node matrix (column-major 1 0 0 0, 0 0 -1 0, 0 1 0 0, 0 0 0 1) maps
// (x,y,z) -> (x, z, -y). The cube maps onto itself, so the box stays [-0.5,0.5]^3 (and is not the
// NORMAL accessor's [-1,1]); the first position, (-0.5,-0.5,0.5) in the buffer, must come out as
// (-0.5,0.5,0.5), and the first face (normal +z in the file) must face +y.
TEST(MeshIOReal, BoxGltfNodeRotation) {
    REQUIRE_SHARED("Box.gltf");
    TriangleMesh m = hlens::load_mesh(shared("Box.gltf"), {false});
    ASSERT_EQ(m.num_triangles(), 12u);
    ASSERT_EQ(m.positions.size(), 24u);
    hlens::Box3 b = m.bounds();
    EXPECT_EQ(b.lo, Vec3(-0.5, -0.5, -0.5));
    EXPECT_EQ(b.hi, Vec3(0.5, 0.5, 0.5));
    EXPECT_EQ(m.positions[0], Vec3(-0.5, 0.5, 0.5));
    auto c = m.corners(0);
    Vec3 n = hlens::cross(c[1] - c[0], c[2] - c[0]);
    EXPECT_EQ(n, Vec3(0, 1, 0));
}

// Duck.glb: node 0 scales by 0.01 (float 0.009999999776482582); the POSITION accessor's min/max are
// (-69.2985, 9.92937, -61.3282) .. (96.1799, 163.97, 53.9252).
TEST(MeshIOReal, DuckGlbNodeScale) {
    REQUIRE_SHARED("Duck.glb");
    TriangleMesh m = hlens::load_mesh(shared("Duck.glb"));
    EXPECT_EQ(m.num_triangles(), 4212u);
    hlens::Box3 b = m.bounds();
    const double s = 0.009999999776482582;
    const Vec3 lo = Vec3(-69.29850006103516, 9.929369926452637, -61.32819747924805) * s;
    const Vec3 hi = Vec3(96.17990112304688, 163.97000122070312, 53.92519760131836) * s;
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b.lo[k], lo[k], 1e-12) << k;
        EXPECT_NEAR(b.hi[k], hi[k], 1e-12) << k;
    }
    EXPECT_LT(b.diagonal(), 3.0);  // raw coordinates span ~±100
}

// OpenMesh is the independent reader: on manifold meshes (which its PolyMesh keeps whole) the face
// and vertex counts must agree with ours (welding does not change these files).
TEST(MeshIOReal, CrossCheckWithOpenMesh) {
    for (const char* f : {"spot.obj", "elephant.off", "fandisk.obj", "fertility.off"}) {
        if (!fs::exists(shared(f))) {
            ADD_FAILURE() << "missing " << shared(f);
            continue;
        }
        OpenMesh::PolyMesh_ArrayKernelT<> om;
        ASSERT_TRUE(OpenMesh::IO::read_mesh(om, shared(f))) << f;
        TriangleMesh m = hlens::load_mesh(shared(f));
        EXPECT_EQ(m.num_triangles(), om.n_faces()) << f;
        EXPECT_EQ(m.positions.size(), om.n_vertices()) << f;
        // OpenMesh holds floats: our doubles must round to its coordinates.
        for (size_t i = 0; i < std::min<size_t>(m.positions.size(), om.n_vertices()); i += 97) {
            auto q = om.point(OpenMesh::VertexHandle(int(i)));
            EXPECT_EQ(float(m.positions[i].x), q[0]) << f << " vertex " << i;
            EXPECT_EQ(float(m.positions[i].z), q[2]) << f << " vertex " << i;
        }
    }
}

// ============================================================== fuzz-ish

// Loading must either succeed or throw MeshError: any other exception fails the test, and a crash or
// out-of-bounds read shows up under -DHLENS_SANITIZE=ON.
void load_any(const std::string& path) {
    try {
        hlens::load_mesh(path);
    } catch (const MeshError&) {
    }
}

TEST_F(MeshIOTest, FuzzTruncationAndCorruption) {
    std::vector<std::pair<std::string, std::string>> seeds = {
        {"f.ply", binary_ply(false)},
        {"f.stl", binary_stl("solid x", kStlTris)},
        {"f.glb", make_glb(gltf_json(""), gltf_buffer())},
        {"f.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf -1 -2 -3\n"},
        {"f.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n4 0 1 2 3\n"},
        {"f.gltf", gltf_json("data:application/octet-stream;base64," + base64(gltf_buffer()))},
    };
    for (const char* real : {"Duck.glb", "featuretype.STL", "horse.ply"})
        if (fs::exists(shared(real))) seeds.push_back({std::string("r_") + real, read_bytes(shared(real))});
    std::mt19937 rng(12345);
    size_t serial = 0;
    auto load_bytes = [&](const std::string& name, const std::string& bytes) {
        // A new file each time: rewriting one file is slow on some file systems.
        std::string p = write(std::to_string(serial++) + "_" + name, bytes);
        load_any(p);
        fs::remove(p);
    };
    for (auto& [name, data] : seeds) {
        // Truncate at every length up to 200 bytes (headers), then at ~150 (big files: ~40) lengths.
        const size_t step = std::max<size_t>(1, data.size() / (data.size() > 100000 ? 40 : 150));
        for (size_t len = 0; len < data.size(); len += (len < 200 ? 1 : step)) load_bytes(name, data.substr(0, len));
        if (data.size() > 5000) continue;
        for (int it = 0; it < 300; ++it) {  // random byte changes
            std::string d = data;
            for (int k = 0; k < 1 + int(rng() % 4); ++k) d[rng() % d.size()] = char(rng() % 256);
            load_bytes(name, d);
        }
    }
}

// The seed corpus of the fuzzers (fuzz/corpus/<format>/, see scripts/fuzz.sh): valid meshes, so that
// fuzzing starts deep inside every reader, and read from memory as from the file.
TEST(MeshIOFuzzCorpus, EverySeedIsAValidMesh) {
    const fs::path root = fs::path(HLENS_SOURCE_DIR) / "fuzz" / "corpus";
    for (const char* format : {"obj", "ply", "stl", "off", "gltf"}) {
        size_t seeds = 0;
        for (const auto& entry : fs::directory_iterator(root / format)) {
            const std::string path = entry.path().string(), bytes = read_bytes(path);
            ++seeds;
            TriangleMesh f, m;
            ASSERT_NO_THROW(f = hlens::load_mesh(path)) << path;
            EXPECT_GT(f.num_triangles(), 0u) << path;
            m = hlens::load_mesh_from_memory(bytes.data(), bytes.size(), path);
            expect_same_mesh(f, m, path);
        }
        EXPECT_GE(seeds, 3u) << format;
    }
}

}  // namespace
