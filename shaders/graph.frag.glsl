// Surface: the domain colour, lit by the facet normal from screen-space derivatives (no normals
// needed in the vertex data). Lines (u_lit = 0): the colour as is.
#version 330 core
in vec3 v_position;
in vec3 v_colour;

uniform int u_lit;
uniform vec3 u_light;

out vec4 frag_colour;

void main() {
    if (u_lit == 0) {
        frag_colour = vec4(v_colour, 1.0);
        return;
    }
    vec3 n = normalize(cross(dFdx(v_position), dFdy(v_position)));
    float l = 0.45 + 0.55 * abs(dot(n, normalize(u_light)));
    frag_colour = vec4(v_colour * l, 1.0);
}
