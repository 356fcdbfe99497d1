// Uses the installed package as any other project would: two unit right triangles, B the copy of A
// lifted by 0.5, so every point of one is 0.5 from the other (its nearest point is straight above
// or below it) and h(A,B) = h(B,A) = 0.5. A is read from OBJ text (core/mesh_io.cpp, which also
// brings in tinygltf for the link), B is built in code.
#include <hlens/hausdorff.h>
#include <hlens/mesh_io.h>

#include <cmath>
#include <cstdio>
#include <string>

int main() {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    hlens::TriangleMesh A = hlens::load_mesh_from_memory(obj.data(), obj.size(), "a.obj");
    hlens::TriangleMesh B = hlens::make_mesh({{0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}}, {{0, 1, 2}}, "b");
    hlens::HausdorffResult r = hlens::hausdorff(A, B);
    std::printf("h(A,B) = %.17g, h(B,A) = %.17g, Hausdorff = %.17g\n", r.a_to_b.distance, r.b_to_a.distance,
                r.hausdorff);
    const double tol = 1e-12;
    bool ok = std::fabs(r.a_to_b.distance - 0.5) <= tol && std::fabs(r.b_to_a.distance - 0.5) <= tol &&
              std::fabs(r.hausdorff - 0.5) <= tol && r.a_to_b.lower <= 0.5 + tol && 0.5 - tol <= r.a_to_b.upper;
    if (!ok) std::fprintf(stderr, "package_test: expected 0.5\n");
    return ok ? 0 : 1;
}
