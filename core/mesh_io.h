// Reading and writing triangle meshes.
//
// load_mesh() reads .obj .ply .stl .off .gltf .glb (extension is case-insensitive) in full double
// precision, triangulates polygons (fan for convex ones, ear clipping otherwise) and, by default,
// welds vertices whose coordinates are identical. Every problem with the input is reported as a
// MeshError whose one-line message starts with "<path>: ".
#pragma once
#include <string>
#include <vector>

#include "mesh.h"

namespace hlens {

struct LoadOptions {
    // Merge vertices with bit-identical x,y,z (-0 and +0 count as equal) and remap the triangles.
    // With weld=false every vertex is kept as read; an STL then has 3 vertices per triangle.
    bool weld = true;
};

// Throws MeshError: missing/unreadable/empty file, unknown extension, truncated or malformed
// data, NaN/infinite coordinates on a used vertex, index out of range, no triangles, ...
// Vertices no triangle uses are kept in positions.
TriangleMesh load_mesh(const std::string& path, const LoadOptions& opt = {});

// Reads a mesh from the `size` bytes at `data` exactly as load_mesh reads a file with that content
// named `name`: the extension of `name` picks the format (e.g. "scan.ply"), `name` starts every
// MeshError message and becomes TriangleMesh::path. Nothing is read from disk: a glTF whose buffers
// are external files (a uri that is not a data: URI) is a MeshError.
TriangleMesh load_mesh_from_memory(const void* data, size_t size, const std::string& name, const LoadOptions& opt = {});

// Builds a mesh from memory. Checks that there is at least one triangle, that every index is in
// range and that every used vertex is finite; throws MeshError ("<name>: ...") otherwise.
// No welding. name becomes TriangleMesh::path.
TriangleMesh make_mesh(std::vector<Vec3> positions, std::vector<Tri> tris, const std::string& name = "");

// Writes "v x y z" (all positions, %.17g, so they read back bit-exactly) and "f a b c" lines.
// Throws MeshError if the file cannot be written.
void save_obj(const TriangleMesh& m, const std::string& path);

}  // namespace hlens
