// Picking pass: writes (mesh index + 1, triangle index + 1) into an RGBA32UI target; 0 is "nothing".
#version 330 core
uniform uint u_mesh;
out uvec4 frag_id;

void main() {
    frag_id = uvec4(u_mesh + 1u, uint(gl_PrimitiveID) + 1u, 0u, 0u);
}
