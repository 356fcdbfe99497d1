// Both meshes: non-indexed triangles (3 vertices per triangle, so gl_PrimitiveID is the triangle
// index), each vertex carrying its triangle's normal and its triangle's scalar (the per-target
// maximum of the colour map; negative: not yet exact). Positions are relative to the scene origin.
#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_value;
layout(location = 3) in float a_max;      // the triangle's exact maximum (negative: unknown)

uniform mat4 u_mvp;

out vec3 v_position;
flat out vec3 v_normal;
flat out float v_value;
flat out float v_max;
out vec3 v_corner;                        // barycentric: (1,0,0), (0,1,0), (0,0,1) at the corners

void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_value = a_value;
    v_max = a_max;
    int k = gl_VertexID % 3;              // (unindexed triangles: three vertices each)
    v_corner = vec3(k == 0, k == 1, k == 2);
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
