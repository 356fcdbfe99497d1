// Flat shading with a headlight (two-sided), an optional colour map over the per-triangle value,
// a highlight for the selected triangle, and the three drawing modes of a mesh. A negative value
// means the triangle's exact maximum is not known yet: it is drawn "not yet exact", grey in
// diagonal stripes (screen space), never on the colour scale. With a tolerance, the triangles
// whose exact maximum exceeds it get a red band along their edges.
#version 330 core
in vec3 v_position;
flat in vec3 v_normal;
flat in float v_value;
flat in float v_max;
in vec3 v_corner;

uniform vec3 u_eye;            // camera position (scene-local coordinates)
uniform vec3 u_color;          // mesh colour when the colour map is off
uniform float u_opacity;
uniform int u_use_map;         // 1: colour by v_value through u_colormap over [u_lo, u_hi]
uniform float u_lo;
uniform float u_hi;
uniform sampler2D u_colormap;  // 256 x 1, RGB
uniform float u_hatch;         // stripe period of "not yet exact" triangles (pixels)
uniform vec2 u_grey;           // their two greys
uniform int u_selected;        // triangle index to highlight, -1 for none
uniform float u_tolerance;     // >= 0: outline triangles whose maximum v_max exceeds it
uniform float u_outline;       // the outline's width (pixels)
uniform int u_mode;            // 0: lit fill, 1: edge overlay (darkened lines), 2: wireframe (unlit lines)

out vec4 frag_color;

void main() {
    vec3 base = u_color;
    if (u_use_map == 1 && v_value < 0.0) {
        float s = mod(gl_FragCoord.x + gl_FragCoord.y, u_hatch);
        base = vec3(s < 0.5 * u_hatch ? u_grey.x : u_grey.y);
    } else if (u_use_map == 1) {
        // (a range of one value, e.g. only the tied maxima known yet: they are its top; but where
        // that value is 0, a mesh against a copy of itself, nothing is off: the bottom)
        float t = u_hi > u_lo ? clamp((v_value - u_lo) / (u_hi - u_lo), 0.0, 1.0) : (v_value >= u_hi && u_hi > 0.0 ? 1.0 : 0.0);
        base = texture(u_colormap, vec2((t * 255.0 + 0.5) / 256.0, 0.5)).rgb;
    }
    // Above the tolerance: a red band along the triangle's edges, inside it.
    if (u_tolerance >= 0.0 && v_max > u_tolerance && u_mode == 0) {
        vec3 px = v_corner / max(fwidth(v_corner), vec3(1e-6));
        if (min(px.x, min(px.y, px.z)) < u_outline) base = vec3(1.0, 0.12, 0.1);
    }
    bool selected = gl_PrimitiveID == u_selected;
    if (selected) base = vec3(1.0, 0.25, 0.85);
    vec3 c;
    if (u_mode == 1) {   // edges: the face colour darkened, so dense meshes keep their colours
        c = selected ? vec3(1.0) : base * 0.55;
    } else if (u_mode == 2) {
        c = base;
    } else {
        float ndv = abs(dot(normalize(v_normal), normalize(u_eye - v_position)));
        c = base * (0.38 + 0.62 * ndv);
    }
    frag_color = vec4(c, u_opacity);
}
