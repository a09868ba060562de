// GLSL 3.30 core sources of the renderer (internal to src/render).
#pragma once

namespace stitch::shaders {

inline constexpr const char* surface_vertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in int a_patch;
layout(location = 3) in int a_level;
layout(location = 4) in vec2 a_texcoord;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_texcoord;
flat out int v_patch;
flat out int v_level;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_texcoord = a_texcoord;
  v_patch = a_patch;
  v_level = a_level;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

// Modes: 0 shaded, 1 zebra, 2 isophote, 3 levels, 4 patches, 5 checker (the order of
// ShadingMode).
inline constexpr const char* surface_fragment = R"(#version 330 core
in vec3 v_position;
in vec3 v_normal;
in vec2 v_texcoord;
flat in int v_patch;
flat in int v_level;
uniform int u_mode;
uniform vec3 u_eye;
uniform vec3 u_light;        // unit, towards the light
uniform vec3 u_stripe_x;     // the zebra environment: stripes are the lines of constant angle
uniform vec3 u_stripe_y;     // atan(r.y, r.x) of the reflected ray r in this (x, y) frame
uniform float u_stripes;
uniform vec3 u_base;
uniform float u_checks;      // squares per side of the texture's unit square
uniform vec3 u_checker;      // the colour of the squares that are not u_base
uniform bool u_textured;     // whether v_texcoord holds texture coordinates
out vec4 frag_colour;

const float TAU = 6.28318530718;

vec3 hsv(float h, float s, float v) {
  vec3 k = clamp(abs(mod(h * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
  return v * mix(vec3(1.0), k, s);
}

// A square wave of period 1 in s with edges filtered over `width` (in units of s).
float stripe(float s, float width) {
  float tri = abs(fract(s) - 0.5) * 2.0;
  float w = clamp(width * 2.0, 1e-4, 1.0);
  return smoothstep(0.5 - 0.5 * w, 0.5 + 0.5 * w, tri);
}

// 1 on the squares with an odd sum of cell indices, 0 on the others: the checkerboard of unit
// cells box-filtered over the pixel's footprint, so squares far away or seen at grazing angles
// fade to the mean of the two colours instead of aliasing into moire.
float checker(vec2 p) {
  vec2 w = max(fwidth(p), vec2(1e-4));
  // Per axis, the mean over [p - w/2, p + w/2] of the square wave of period 2 (+1, then -1).
  vec2 a = abs(fract((p - 0.5 * w) * 0.5) - 0.5), b = abs(fract((p + 0.5 * w) * 0.5) - 0.5);
  vec2 i = 2.0 * (a - b) / w;
  return 0.5 - 0.5 * i.x * i.y;
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 v = normalize(u_eye - v_position);
  if (!gl_FrontFacing) n = -n;
  // A key light plus a head light (from the eye), so faces turned from the key are not black.
  float diffuse = 0.65 * max(dot(n, u_light), 0.0) + 0.35 * max(dot(n, v), 0.0);
  float specular = pow(max(dot(n, normalize(u_light + v)), 0.0), 48.0);
  vec3 colour;
  if (u_mode == 1) {
    vec3 r = reflect(-v, n);
    float x = dot(r, u_stripe_x), y = dot(r, u_stripe_y);
    float scale = u_stripes / TAU;
    float s = atan(y, x) * scale;
    // |ds| from the derivatives of x and y (d atan = (x dy - y dx) / (x^2 + y^2)), which has
    // no seam where atan wraps around.
    float q = max(x * x + y * y, 1e-8);
    float ds = (abs(x * dFdx(y) - y * dFdx(x)) + abs(x * dFdy(y) - y * dFdy(x))) / q * scale;
    colour = mix(vec3(0.04), vec3(0.97), stripe(s, ds));
    colour *= 0.85 + 0.15 * diffuse;
  } else if (u_mode == 2) {
    float angle = acos(clamp(dot(n, u_light), -1.0, 1.0));
    float s = angle / 3.14159265 * u_stripes;
    float band = stripe(s, fwidth(s));
    colour = u_base * (0.3 + 0.7 * diffuse) * mix(0.45, 1.0, band);
  } else {
    vec3 base = u_base;
    if (u_mode == 3) {
      vec3 levels[8] = vec3[8](vec3(0.80, 0.82, 0.86), vec3(0.98, 0.62, 0.25),
                               vec3(0.40, 0.75, 0.40), vec3(0.35, 0.55, 0.95),
                               vec3(0.90, 0.35, 0.55), vec3(0.95, 0.85, 0.30),
                               vec3(0.55, 0.40, 0.80), vec3(0.30, 0.80, 0.85));
      base = levels[clamp(v_level, 0, 7)];
    } else if (u_mode == 4) {
      base = hsv(fract(float(v_patch) * 0.6180339887), 0.45, 0.95);
    } else if (u_mode == 5 && u_textured) {
      base = mix(u_base, u_checker, checker(v_texcoord * u_checks));
    }
    colour = base * (0.25 + 0.75 * diffuse) + vec3(0.25 * specular);
  }
  if (!gl_FrontFacing && u_mode != 1) colour *= vec3(1.0, 0.55, 0.55);
  frag_colour = vec4(colour, 1.0);
}
)";

inline constexpr const char* line_vertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_colour;
layout(location = 2) in float a_width;
uniform mat4 u_view_projection;
uniform float u_depth_bias;
out vec3 g_colour;
out float g_width;
void main() {
  g_colour = a_colour;
  g_width = a_width;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
  gl_Position.z -= u_depth_bias * gl_Position.w;
}
)";

// Core profiles do not guarantee lines wider than one pixel: expand each segment into a
// screen-space quad, u_width times the segment's own factor (sharp features are wider) wide.
inline constexpr const char* line_geometry = R"(#version 330 core
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 g_colour[];
in float g_width[];
out vec3 f_colour;
uniform vec2 u_viewport;
uniform float u_width;
void main() {
  float width = u_width * g_width[0];
  vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[1].gl_Position;
  if (p0.w <= 0.0 || p1.w <= 0.0) return;
  vec2 half_viewport = 0.5 * u_viewport;
  vec2 s0 = p0.xy / p0.w * half_viewport, s1 = p1.xy / p1.w * half_viewport;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 along = dir * 0.5 * width, across = vec2(-dir.y, dir.x) * 0.5 * width;
  f_colour = g_colour[0];
  gl_Position = vec4(p0.xy + (-along + across) / half_viewport * p0.w, p0.zw); EmitVertex();
  gl_Position = vec4(p0.xy + (-along - across) / half_viewport * p0.w, p0.zw); EmitVertex();
  f_colour = g_colour[1];
  gl_Position = vec4(p1.xy + (along + across) / half_viewport * p1.w, p1.zw); EmitVertex();
  gl_Position = vec4(p1.xy + (along - across) / half_viewport * p1.w, p1.zw); EmitVertex();
  EndPrimitive();
}
)";

inline constexpr const char* line_fragment = R"(#version 330 core
in vec3 f_colour;
uniform float u_alpha;
out vec4 frag_colour;
void main() { frag_colour = vec4(f_colour, u_alpha); }
)";

inline constexpr const char* marker_vertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_colour;
uniform mat4 u_view_projection;
uniform float u_depth_bias;
uniform float u_size;
out vec3 f_colour;
void main() {
  f_colour = a_colour;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
  gl_Position.z -= u_depth_bias * gl_Position.w;
  gl_PointSize = u_size;
}
)";

inline constexpr const char* marker_fragment = R"(#version 330 core
in vec3 f_colour;
uniform float u_alpha;
out vec4 frag_colour;
void main() {
  float r = length(gl_PointCoord * 2.0 - 1.0);
  if (r > 1.0) discard;
  frag_colour = vec4(r > 0.7 ? vec3(0.1) : f_colour, u_alpha);
}
)";

}  // namespace stitch::shaders
