// OpenGL 3.3 core entry points and GLFW, included in this order everywhere in hlens.
// Mesa's libGL exports every core entry point, so no loader is needed: GL_GLEXT_PROTOTYPES makes
// glcorearb.h declare them, and GLFW_INCLUDE_NONE stops GLFW from pulling in the legacy <GL/gl.h>.
// (Dear ImGui's OpenGL3 backend, compiled inside libimgui.a, brings its own tiny loader.)
#pragma once
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
