// Makes the benchmark's mesh pairs with OpenMesh: a simplified copy (quadric decimater), a
// perturbed copy, or a Loop-subdivided copy of a mesh, written as OBJ (used by bench/compare.sh).
//   make_pairs simplify IN OUT FRACTION      keep about FRACTION of the triangles (quadric error,
//                                            collapses that flip a face normal refused)
//   make_pairs loop IN OUT N                 N rounds of Loop subdivision
//   make_pairs perturb IN OUT AMPLITUDE SEED move every vertex along its normal by u * AMPLITUDE *
//                                            bounding-box diagonal, u in [-1, 1] pseudo-random
//                                            from SEED and the vertex index (deterministic)
//   make_pairs copy IN OUT                   the same mesh written again (a re-export; these three
//                                            read and write doubles with the project's own reader)
//   make_pairs edit IN OUT RADIUS AMPLITUDE  a local edit: the vertices within RADIUS * diagonal of
//                                            vertex 0 moved along their normals by AMPLITUDE * diagonal
//   make_pairs float IN OUT                  every coordinate rounded to float (an STL export)
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <hlens/mesh_io.h>

// Double-precision points, so subdivision and perturbation add no float rounding of their own.
struct Traits : OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
    typedef OpenMesh::Vec3d Normal;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// copy, float and edit: read and written in full double precision by the project's own reader
// (OpenMesh's readers take coordinates as float: its "copy" would be the float one).
static int exact_copy(const std::string& op, int argc, char** argv) {
    try {
        hlens::TriangleMesh m = hlens::load_mesh(argv[2]);
        if (op == "float")
            for (hlens::Vec3& p : m.positions) p = hlens::Vec3((float)p.x, (float)p.y, (float)p.z);
        if (op == "edit" && argc == 6 && !m.positions.empty()) {
            const double diag = m.bounds().diagonal(), radius = std::atof(argv[4]) * diag, offset = std::atof(argv[5]) * diag;
            std::vector<hlens::Vec3> normal(m.positions.size(), hlens::Vec3(0, 0, 0));
            for (size_t t = 0; t < m.num_triangles(); ++t) {  // area-weighted vertex normals
                const auto c = m.corners(t);
                const hlens::Vec3 n = hlens::cross(c[1] - c[0], c[2] - c[0]);
                for (uint32_t i : m.triangles[t]) normal[i] += n;
            }
            const hlens::Vec3 centre = m.positions[0];
            for (size_t v = 0; v < m.positions.size(); ++v) {
                const double l = hlens::norm(normal[v]);
                if (l > 0 && hlens::norm(m.positions[v] - centre) <= radius) m.positions[v] += normal[v] * (offset / l);
            }
        }
        hlens::save_obj(m, argv[3]);
        std::printf("%s: %zu vertices, %zu triangles\n", argv[3], m.positions.size(), m.num_triangles());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_pairs: %s\n", e.what());
        return 2;
    }
}

static double diagonal(const Mesh& m) {
    Mesh::Point lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (auto v : m.vertices()) {
        lo.minimize(m.point(v));
        hi.maximize(m.point(v));
    }
    return (hi - lo).norm();
}

int main(int argc, char** argv) {
    std::string op = argc > 1 ? argv[1] : "";
    if (!((argc == 5 && (op == "simplify" || op == "loop")) || (argc == 6 && (op == "perturb" || op == "edit")) ||
          (argc == 4 && (op == "copy" || op == "float")))) {
        std::fprintf(stderr,
                     "usage: make_pairs simplify IN OUT FRACTION\n"
                     "       make_pairs loop IN OUT N\n"
                     "       make_pairs perturb IN OUT AMPLITUDE SEED\n"
                     "       make_pairs copy IN OUT\n"
                     "       make_pairs edit IN OUT RADIUS AMPLITUDE\n"
                     "       make_pairs float IN OUT\n");
        return 2;
    }
    if (op == "copy" || op == "float" || op == "edit") return exact_copy(op, argc, argv);
    Mesh m;
    if (!OpenMesh::IO::read_mesh(m, argv[2])) {
        std::fprintf(stderr, "make_pairs: cannot read %s\n", argv[2]);
        return 2;
    }
    if (op == "simplify") {
        double fraction = std::atof(argv[4]);
        OpenMesh::Decimater::DecimaterT<Mesh> dec(m);
        OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
        OpenMesh::Decimater::ModNormalFlippingT<Mesh>::Handle no_flips;  // no folded-over faces
        dec.add(quadric);
        dec.add(no_flips);
        dec.initialize();
        dec.decimate_to_faces(0, size_t(fraction * m.n_faces()));
        m.garbage_collection();
    } else if (op == "loop") {
        OpenMesh::Subdivider::Uniform::LoopT<Mesh> loop;
        loop.attach(m);
        loop(std::atoi(argv[4]));
        loop.detach();
    } else if (op == "perturb") {
        double amplitude = std::atof(argv[4]);
        uint64_t seed = std::strtoull(argv[5], nullptr, 10);
        double offset = amplitude * diagonal(m);
        m.request_face_normals();
        m.request_vertex_normals();
        m.update_normals();
        for (auto v : m.vertices()) {
            uint64_t x = seed * 0x100000000ull + (uint64_t)v.idx() + 0x9E3779B97F4A7C15ull;  // splitmix64
            x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
            x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
            x ^= x >> 31;
            double u = (double)(x >> 11) * 0x1.0p-53 * 2.0 - 1.0;
            m.set_point(v, m.point(v) + m.normal(v) * (u * offset));
        }
    }
    if (!OpenMesh::IO::write_mesh(m, argv[3], OpenMesh::IO::Options::Default, 17)) {
        std::fprintf(stderr, "make_pairs: cannot write %s\n", argv[3]);
        return 2;
    }
    std::printf("%s: %zu vertices, %zu triangles\n", argv[3], m.n_vertices(), m.n_faces());
    return 0;
}
