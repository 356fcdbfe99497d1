// The body shared by the libFuzzer harnesses in this folder: one input is read as a mesh file by
// load_mesh_from_memory (core/mesh_io.h), welded and not welded. A MeshError is the expected answer
// to bad input; its message must name the input ("<name>: ...") on one line. Anything else is a
// bug and ends the run: a crash, a sanitizer report, another exception escaping (libFuzzer reports
// it as a deadly signal), or a mesh that breaks the promises of TriangleMesh (checked below).
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <hlens/mesh_io.h>

namespace hlens_fuzz {

[[noreturn]] inline void bug(const std::string& name, const std::string& what) {
    std::fprintf(stderr, "fuzz %s: %s\n", name.c_str(), what.c_str());
    std::abort();
}

inline void load(const uint8_t* data, size_t size, const std::string& name) {
    for (bool weld : {true, false}) {
        hlens::LoadOptions opt;
        opt.weld = weld;
        try {
            const hlens::TriangleMesh m = hlens::load_mesh_from_memory(data, size, name, opt);
            if (m.path != name) bug(name, "path is '" + m.path + "'");
            if (m.triangles.empty()) bug(name, "a mesh without triangles");
            for (const hlens::Tri& t : m.triangles)
                for (uint32_t i : t) {
                    if (i >= m.positions.size()) bug(name, "vertex index out of range");
                    const hlens::Vec3& p = m.positions[i];
                    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                        bug(name, "a used vertex is not finite");
                }
        } catch (const hlens::MeshError& e) {
            const std::string msg = e.what();
            if (msg.rfind(name + ": ", 0) != 0) bug(name, "error message does not start with the name: " + msg);
            if (msg.find('\n') != std::string::npos) bug(name, "error message has more than one line: " + msg);
        }
    }
}

}  // namespace hlens_fuzz
