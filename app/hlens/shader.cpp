#include "shader.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace hlens::gui {

namespace fs = std::filesystem;

std::string shader_dir() {
#ifdef HLENS_SHADER_DIR
    if (fs::is_directory(HLENS_SHADER_DIR)) return HLENS_SHADER_DIR;
#endif
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) return (exe.parent_path() / "shaders").string();
    return "shaders";
}

namespace {

bool read_text(const std::string& path, std::string& out) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    std::stringstream ss;
    ss << f.rdbuf();
    out = ss.str();
    return true;
}

GLuint compile(GLenum kind, const std::string& path, std::string& error) {
    std::string src;
    if (!read_text(path, src)) {
        error = path + ": cannot read the shader";
        return 0;
    }
    GLuint s = glCreateShader(kind);
    const char* p = src.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint n = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &n);
        std::vector<char> log(std::max(n, 1));
        glGetShaderInfoLog(s, (GLsizei)log.size(), nullptr, log.data());
        error = path + ": " + log.data();
        glDeleteShader(s);
        return 0;
    }
    return s;
}

}  // namespace

GLuint load_program(const std::string& vertex_file, const std::string& fragment_file, std::string& error) {
    const std::string dir = shader_dir() + "/";
    GLuint vs = compile(GL_VERTEX_SHADER, dir + vertex_file, error);
    if (!vs) return 0;
    GLuint fs_ = compile(GL_FRAGMENT_SHADER, dir + fragment_file, error);
    if (!fs_) {
        glDeleteShader(vs);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs_);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs_);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint n = 0;
        glGetProgramiv(p, GL_INFO_LOG_LENGTH, &n);
        std::vector<char> log(std::max(n, 1));
        glGetProgramInfoLog(p, (GLsizei)log.size(), nullptr, log.data());
        error = vertex_file + " + " + fragment_file + ": " + log.data();
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

}  // namespace hlens::gui
