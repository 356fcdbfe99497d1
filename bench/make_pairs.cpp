// Makes the benchmark's mesh pairs with OpenMesh: a simplified copy (quadric decimater), a
// perturbed copy, or a Loop-subdivided copy of a mesh, written as OBJ.
//   make_pairs simplify IN OUT FRACTION     keep about FRACTION of the triangles
//   make_pairs loop IN OUT N                N rounds of Loop subdivision
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <cstdio>
#include <cstdlib>
#include <string>

using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: make_pairs simplify|loop IN OUT ARG\n");
        return 2;
    }
    std::string op = argv[1];
    Mesh m;
    if (!OpenMesh::IO::read_mesh(m, argv[2])) {
        std::fprintf(stderr, "make_pairs: cannot read %s\n", argv[2]);
        return 2;
    }
    if (op == "simplify") {
        double fraction = std::atof(argv[4]);
        OpenMesh::Decimater::DecimaterT<Mesh> dec(m);
        OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
        dec.add(quadric);
        dec.initialize();
        dec.decimate_to_faces(0, size_t(fraction * m.n_faces()));
        m.garbage_collection();
    } else if (op == "loop") {
        OpenMesh::Subdivider::Uniform::LoopT<Mesh> loop;
        loop.attach(m);
        loop(std::atoi(argv[4]));
        loop.detach();
    } else {
        std::fprintf(stderr, "make_pairs: unknown operation %s\n", op.c_str());
        return 2;
    }
    if (!OpenMesh::IO::write_mesh(m, argv[3], OpenMesh::IO::Options::Default, 17)) {
        std::fprintf(stderr, "make_pairs: cannot write %s\n", argv[3]);
        return 2;
    }
    std::printf("%s: %zu vertices, %zu triangles\n", argv[3], m.n_vertices(), m.n_faces());
    return 0;
}
