// The graph of d^2 over T' (graph view): positions already normalised (x, y in the target's frame
// scaled to about unit size, z = d^2 scaled), one colour per vertex.
#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_colour;

uniform mat4 u_mvp;

out vec3 v_position;
out vec3 v_colour;

void main() {
    v_position = a_position;
    v_colour = a_colour;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
