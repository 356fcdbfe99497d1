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

// Saves the GL state an offscreen pass changes (framebuffer, viewport, program, vertex array and
// the depth/blend/cull/scissor switches) and restores it when it goes out of scope.
struct GlStateGuard {
    GLint fbo = 0, viewport[4] = {0, 0, 0, 0}, program = 0, vao = 0;
    GLboolean depth, blend, cull, scissor;
    GlStateGuard() {
        glGetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
        glGetIntegerv(GL_VIEWPORT, viewport);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
        depth = glIsEnabled(GL_DEPTH_TEST);
        blend = glIsEnabled(GL_BLEND);
        cull = glIsEnabled(GL_CULL_FACE);
        scissor = glIsEnabled(GL_SCISSOR_TEST);
    }
    ~GlStateGuard() {
        glBindVertexArray((GLuint)vao);
        glUseProgram((GLuint)program);
        glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)fbo);
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        (depth ? glEnable : glDisable)(GL_DEPTH_TEST);
        (blend ? glEnable : glDisable)(GL_BLEND);
        (cull ? glEnable : glDisable)(GL_CULL_FACE);
        (scissor ? glEnable : glDisable)(GL_SCISSOR_TEST);
    }
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;
};
