// Per fragment: the nearest feature of the inserted sources (Ericson's point-triangle region test,
// the seven regions abc, ab, bc, ca, a, b, c), independent of the domain mesh. u_sources has one
// row per source: texels 0..2 the corners in the target's frame (frame units, z along the
// target's normal), texels 3..9 the colours of its seven regions (the domain view's colours).
// The first minimum wins (ties keep the earlier insertion). Outside T' transparent.
#version 330 core
in vec2 v_frame;

uniform sampler2D u_sources;
uniform int u_count;
uniform vec2 u_t0, u_t1, u_t2;   // T''s corners (frame)
uniform vec4 u_none;             // colour when no source is inserted

out vec4 frag_colour;

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

void closest(vec3 p, vec3 a, vec3 b, vec3 c, out float dist2, out int region) {
    vec3 ab = b - a, ac = c - a, ap = p - a;
    float d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) { dist2 = dot(ap, ap); region = 4; return; }
    vec3 bp = p - b;
    float d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) { dist2 = dot(bp, bp); region = 5; return; }
    float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) { vec3 q = a + ab * (d1 / (d1 - d3)); dist2 = dot(p - q, p - q); region = 1; return; }
    vec3 cp = p - c;
    float d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) { dist2 = dot(cp, cp); region = 6; return; }
    float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) { vec3 q = a + ac * (d2 / (d2 - d6)); dist2 = dot(p - q, p - q); region = 3; return; }
    float va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        vec3 q = b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
        dist2 = dot(p - q, p - q); region = 2; return;
    }
    float den = 1.0 / (va + vb + vc);
    vec3 q = a + ab * (vb * den) + ac * (vc * den);
    dist2 = dot(p - q, p - q); region = 0;
}

void main() {
    vec2 p = v_frame;
    float s0 = cross2(u_t1 - u_t0, p - u_t0), s1 = cross2(u_t2 - u_t1, p - u_t1), s2 = cross2(u_t0 - u_t2, p - u_t2);
    if (!((s0 >= 0.0 && s1 >= 0.0 && s2 >= 0.0) || (s0 <= 0.0 && s1 <= 0.0 && s2 <= 0.0))) discard;
    if (u_count == 0) { frag_colour = u_none; return; }
    float best = 1e38;
    int bs = 0, br = 0;
    vec3 q = vec3(p, 0.0);
    for (int s = 0; s < u_count; ++s) {
        vec3 a = texelFetch(u_sources, ivec2(0, s), 0).xyz;
        vec3 b = texelFetch(u_sources, ivec2(1, s), 0).xyz;
        vec3 c = texelFetch(u_sources, ivec2(2, s), 0).xyz;
        float d; int r;
        closest(q, a, b, c, d, r);
        if (d < best) { best = d; bs = s; br = r; }
    }
    frag_colour = texelFetch(u_sources, ivec2(3 + br, bs), 0);
}
