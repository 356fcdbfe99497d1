// The nearest-feature overlay of the domain view: one quad over T''s bounding box, in the
// target's frame; the framebuffer is exactly that box.
#version 330 core
layout(location = 0) in vec2 a_frame;

uniform vec2 u_lo, u_hi;

out vec2 v_frame;

void main() {
    v_frame = a_frame;
    gl_Position = vec4((a_frame - u_lo) / (u_hi - u_lo) * 2.0 - 1.0, 0.0, 1.0);
}
