// The two meshes on the GPU and how they are drawn.
//
// Triangles are uploaded unindexed (three vertices each, with the triangle's normal and value), so
// gl_PrimitiveID is the triangle index in both the shading pass (selection highlight) and the
// picking pass. Coordinates are taken relative to the scene origin (the centre of both meshes'
// bounding box) before the conversion to float, so large coordinates keep their precision.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl.h"
#include <hlens/mesh.h>

namespace hlens::gui {

enum class DrawMode : int { Solid = 0, SolidEdges = 1, Wireframe = 2 };

struct MeshStyle {
    bool visible = true;
    DrawMode mode = DrawMode::SolidEdges;
    float opacity = 1.0f;
    float color[3] = {0.75f, 0.75f, 0.78f};
    bool touched = false;   // the user changed mode or opacity: keep them on direction switches
};

class GpuMesh {
public:
    ~GpuMesh() { destroy(); }
    void upload(const TriangleMesh& m, const Vec3& origin);
    // The colour map's scalar per triangle; a negative value: not yet exact (drawn hatched grey).
    void set_values(const std::vector<double>& per_triangle) { upload_values(vbo_value_, per_triangle); }
    // The exact maximum per triangle (negative: unknown), compared with the tolerance.
    void set_maxima(const std::vector<double>& per_triangle) { upload_values(vbo_max_, per_triangle); }
    void destroy();
    bool empty() const { return vertex_count_ == 0; }
    void draw() const;

private:
    void upload_values(GLuint vbo, const std::vector<double>& per_triangle);
    GLuint vao_ = 0, vbo_ = 0, vbo_value_ = 0, vbo_max_ = 0;
    GLsizei vertex_count_ = 0;
};

// Everything one frame of the 3D view needs.
struct ViewParams {
    glm::mat4 mvp{1.0f};
    glm::vec3 eye{0.0f};
    int viewport[4] = {0, 0, 1, 1};   // framebuffer pixels, GL convention (origin bottom-left)
    MeshStyle style[2];
    int measured = 0;                 // the mesh the colour map is drawn on
    bool use_map = false;
    float lo = 0, hi = 1;             // colour map range
    float hatch = 8;                  // period of the "not yet exact" stripes (framebuffer pixels)
    int selected = -1;                // selected triangle of the measured mesh
    float tolerance = -1;             // >= 0: outline the measured mesh's triangles whose maximum exceeds it
    float outline = 3;                // their outline's width (framebuffer pixels)
};

class Scene {
public:
    ~Scene();
    bool init(std::string& error);    // shaders and the colour map texture (needs a GL context)
    void set_meshes(const TriangleMesh& a, const TriangleMesh& b);
    void clear();
    void set_values(int side, const std::vector<double>& per_triangle) { mesh_[side].set_values(per_triangle); }
    void set_maxima(int side, const std::vector<double>& per_triangle) { mesh_[side].set_maxima(per_triangle); }
    bool loaded() const { return loaded_; }
    const Vec3& origin() const { return origin_; }
    glm::vec3 local(const Vec3& world) const {
        return {float(world.x - origin_.x), float(world.y - origin_.y), float(world.z - origin_.z)};
    }
    glm::vec3 box_lo() const { return lo_; }
    glm::vec3 box_hi() const { return hi_; }
    void draw(const ViewParams& p) const;
    const GpuMesh& mesh(int side) const { return mesh_[side]; }

private:
    void draw_mesh(const ViewParams& p, int side, bool transparent_pass) const;
    GpuMesh mesh_[2];
    Vec3 origin_;
    glm::vec3 lo_{-1.0f}, hi_{1.0f};
    bool loaded_ = false;
    GLuint program_ = 0, colormap_tex_ = 0;
};

}  // namespace hlens::gui
