#include "scene.h"

#include <glm/gtc/type_ptr.hpp>

#include "colormap.h"
#include "shader.h"

namespace hlens::gui {

// ---------------------------------------------------------------- GpuMesh

void GpuMesh::upload(const TriangleMesh& m, const Vec3& origin) {
    destroy();
    std::vector<float> data;   // per vertex: position (3), normal (3)
    data.reserve(m.triangles.size() * 18);
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        auto c = m.corners(t);
        Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
        double len = norm(n);
        n = len > 0 ? n / len : Vec3(0, 0, 1);   // degenerate triangle: any normal
        for (const Vec3& p : c) {
            Vec3 q = p - origin;
            data.insert(data.end(), {float(q.x), float(q.y), float(q.z), float(n.x), float(n.y), float(n.z)});
        }
    }
    vertex_count_ = (GLsizei)(m.triangles.size() * 3);
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, data.size() * sizeof(float), data.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
    std::vector<float> unknown(vertex_count_, -1.0f);   // not yet exact until values are set
    GLuint* per_triangle[2] = {&vbo_value_, &vbo_max_};   // attributes 2 and 3
    for (int k = 0; k < 2; ++k) {
        glGenBuffers(1, per_triangle[k]);
        glBindBuffer(GL_ARRAY_BUFFER, *per_triangle[k]);
        glBufferData(GL_ARRAY_BUFFER, unknown.size() * sizeof(float), unknown.data(), GL_DYNAMIC_DRAW);
        glEnableVertexAttribArray(2 + k);
        glVertexAttribPointer(2 + k, 1, GL_FLOAT, GL_FALSE, sizeof(float), (void*)0);
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GpuMesh::upload_values(GLuint vbo, const std::vector<double>& per_triangle) {
    if (!vbo) return;
    std::vector<float> v(vertex_count_, -1.0f);
    for (size_t t = 0; t < per_triangle.size() && 3 * t + 2 < v.size(); ++t)
        v[3 * t] = v[3 * t + 1] = v[3 * t + 2] = per_triangle[t] >= 0 ? float(per_triangle[t]) : -1.0f;
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferSubData(GL_ARRAY_BUFFER, 0, v.size() * sizeof(float), v.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GpuMesh::destroy() {
    if (vbo_value_) glDeleteBuffers(1, &vbo_value_);
    if (vbo_max_) glDeleteBuffers(1, &vbo_max_);
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
    vao_ = vbo_ = vbo_value_ = vbo_max_ = 0;
    vertex_count_ = 0;
}

void GpuMesh::draw() const {
    if (!vao_) return;
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
    glBindVertexArray(0);
}

// ---------------------------------------------------------------- Scene

Scene::~Scene() {
    if (program_) glDeleteProgram(program_);
    if (colormap_tex_) glDeleteTextures(1, &colormap_tex_);
}

bool Scene::init(std::string& error) {
    program_ = load_program("mesh.vert.glsl", "mesh.frag.glsl", error);
    if (!program_) return false;
    const auto& table = colormap_table();
    glGenTextures(1, &colormap_tex_);
    glBindTexture(GL_TEXTURE_2D, colormap_tex_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, kColormapSize, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, table.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return true;
}

void Scene::set_meshes(const TriangleMesh& a, const TriangleMesh& b) {
    Box3 box = a.bounds();
    box.add(b.bounds());
    origin_ = box.empty() ? Vec3() : 0.5 * (box.lo + box.hi);
    mesh_[0].upload(a, origin_);
    mesh_[1].upload(b, origin_);
    lo_ = local(box.lo);
    hi_ = local(box.hi);
    loaded_ = true;
}

void Scene::clear() {
    mesh_[0].destroy();
    mesh_[1].destroy();
    loaded_ = false;
}

void Scene::draw_mesh(const ViewParams& p, int side, bool transparent_pass) const {
    const MeshStyle& st = p.style[side];
    if (!st.visible || mesh_[side].empty()) return;
    const bool transparent = st.opacity < 0.999f;
    if (transparent != transparent_pass) return;
    const bool measured = side == p.measured;
    glUniform3fv(glGetUniformLocation(program_, "u_color"), 1, st.color);
    glUniform1f(glGetUniformLocation(program_, "u_opacity"), st.opacity);
    glUniform1i(glGetUniformLocation(program_, "u_use_map"), measured && p.use_map ? 1 : 0);
    glUniform1i(glGetUniformLocation(program_, "u_selected"), measured ? p.selected : -1);
    glUniform1f(glGetUniformLocation(program_, "u_tolerance"), measured ? p.tolerance : -1.0f);
    glUniform1f(glGetUniformLocation(program_, "u_outline"), p.outline);
    GLint mode = glGetUniformLocation(program_, "u_mode");
    glDepthMask(transparent ? GL_FALSE : GL_TRUE);
    if (st.mode == DrawMode::Wireframe) {
        glUniform1i(mode, 2);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        mesh_[side].draw();
    } else {
        glUniform1i(mode, 0);
        glEnable(GL_POLYGON_OFFSET_FILL);   // push the fill back so its edges win the depth test
        glPolygonOffset(1.0f, 1.0f);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        mesh_[side].draw();
        glDisable(GL_POLYGON_OFFSET_FILL);
        if (st.mode == DrawMode::SolidEdges) {
            glUniform1i(mode, 1);
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            mesh_[side].draw();
        }
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthMask(GL_TRUE);
}

void Scene::draw(const ViewParams& p) const {
    if (!loaded_ || !program_) return;
    glViewport(p.viewport[0], p.viewport[1], p.viewport[2], p.viewport[3]);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(program_);
    glUniformMatrix4fv(glGetUniformLocation(program_, "u_mvp"), 1, GL_FALSE, glm::value_ptr(p.mvp));
    glUniform3fv(glGetUniformLocation(program_, "u_eye"), 1, glm::value_ptr(p.eye));
    glUniform1f(glGetUniformLocation(program_, "u_lo"), p.lo);
    glUniform1f(glGetUniformLocation(program_, "u_hi"), p.hi);
    glUniform1f(glGetUniformLocation(program_, "u_hatch"), p.hatch);
    glUniform2f(glGetUniformLocation(program_, "u_grey"), kNotExactGrey[0], kNotExactGrey[1]);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, colormap_tex_);
    glUniform1i(glGetUniformLocation(program_, "u_colormap"), 0);
    // Opaque meshes first, then translucent ones without depth writes, measured mesh last.
    for (int pass = 0; pass < 2; ++pass)
        for (int side : {1 - p.measured, p.measured}) draw_mesh(p, side, pass == 1);
    glUseProgram(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace hlens::gui
