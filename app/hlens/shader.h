// GLSL programs, read at run time from the shaders/ directory.
//
// Why files rather than embedded strings: a shader can be edited and tried without rebuilding
// (the debugger's panels to come will add a "reload shaders" action), and compile errors point at
// real file names and lines. The directory is the source tree's shaders/ (compile definition
// HLENS_SHADER_DIR) when it exists, otherwise shaders/ next to the executable (CMake copies it
// there after each build, so an installed or moved build keeps working).
#pragma once
#include <string>

#include "gl.h"

namespace hlens::gui {

std::string shader_dir();
// Compiles and links; returns 0 and sets `error` (file name and the driver's log) on failure.
GLuint load_program(const std::string& vertex_file, const std::string& fragment_file, std::string& error);

}  // namespace hlens::gui
