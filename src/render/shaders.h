#pragma once
// GLSL 3.30 sources of the scene renderer's programs (renderer.cpp): a gradient background,
// the lit wall with its cut face, blood particles as ray-cast spheres on camera-facing
// rectangles, and plain lines. kLighting holds shade(), linked into the lit fragment shaders
// as a shader object of its own (with kSphereHit of fluid_shaders.h for the spheres).

namespace hs::render::shaders {

inline constexpr const char* kLighting = R"(
uniform vec3 uKey, uFill;
uniform float uAmbient, uKeyStrength, uFillStrength, uSpecular, uShininess;
// Blinn-Phong with two directional lights in view space; v points from the surface to the eye.
vec3 shade(vec3 base, vec3 n, vec3 v) {
  float diffuse = uAmbient + uKeyStrength * max(dot(n, uKey), 0.0) + uFillStrength * max(dot(n, uFill), 0.0);
  float spec = uSpecular * pow(max(dot(n, normalize(uKey + v)), 0.0), uShininess);
  return base * diffuse + vec3(spec);
}
)";

inline constexpr const char* kBackgroundVs = R"(#version 330 core
out float vHeight;
void main() {
  // One triangle covering the screen.
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
  vHeight = p.y * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";
inline constexpr const char* kBackgroundFs = R"(#version 330 core
in float vHeight;
uniform vec3 uTop, uBottom;
out vec4 colour;
void main() { colour = vec4(mix(uBottom, uTop, vHeight), 1.0); }
)";

inline constexpr const char* kWallVs = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
uniform mat4 uView, uProjection;
uniform vec4 uClip;  // view space; the cut keeps dot(xyz, p) + w <= 0
uniform bool uClipOn;
out vec3 vViewPos, vNormal, vColour;
void main() {
  vec4 p = uView * vec4(aPosition, 1.0);
  vViewPos = p.xyz;
  vNormal = mat3(uView) * aNormal;
  vColour = aColour;
  // The cut as a clip distance: the rasteriser clips the triangles, so the fragment shader
  // has no discard and a software rasteriser can test depth before shading (several wall
  // layers overlap on screen; only the front one is shaded).
  gl_ClipDistance[0] = uClipOn ? -(dot(uClip.xyz, p.xyz) + uClip.w) : 1.0;
  gl_Position = uProjection * p;
}
)";
inline constexpr const char* kWallFs = R"(#version 330 core
in vec3 vViewPos, vNormal, vColour;
uniform float uOpacity;
uniform vec3 uCutColour;
out vec4 colour;
vec3 shade(vec3 base, vec3 n, vec3 v);
void main() {
  vec3 v = normalize(-vViewPos);
  if (gl_FrontFacing) {
    colour = vec4(shade(vColour, normalize(vNormal), v), uOpacity);
  } else {
    // Inside the wall's material: the cut face, lit as if it faced the viewer.
    colour = vec4(uCutColour * (0.75 + 0.25 * abs(dot(normalize(vNormal), v))), uOpacity);
  }
}
)";

inline constexpr const char* kParticleVs = R"(#version 330 core
layout(location = 0) in vec3 aCentre;
layout(location = 1) in vec3 aColour;
uniform mat4 uView, uProjection;
uniform float uRadius;
out vec3 vViewPos, vCentre, vColour;
void main() {
  // A camera-facing rectangle at the centre's depth that just holds the sphere's perspective
  // outline, so few fragments miss the sphere (each one that does still costs a ray test).
  // Screen x is x / -z: its extremes over the sphere lie on the planes x = k (-z) through the
  // eye tangent to it, i.e. the tangents from the origin to the circle of radius r around
  // (c.x, -c.z) in the xz plane; the same for y. With the eye in or at the sphere a generous
  // square stands in.
  vec2 corner = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1) * 2.0 - 1.0;
  vec3 c = (uView * vec4(aCentre, 1.0)).xyz;
  float depth = -c.z;
  vec2 offset = corner * uRadius * 1.5;
  if (depth > uRadius * 1.01) {
    for (int a = 0; a < 2; ++a) {
      float spread = asin(uRadius / length(vec2(c[a], depth)));
      float angle = clamp(atan(c[a], depth) + corner[a] * spread, -1.5, 1.5);
      offset[a] = depth * tan(angle) - c[a];
    }
  }
  vec3 p = c + vec3(offset, 0.0);
  vViewPos = p;
  vCentre = c;
  vColour = aColour;
  gl_Position = uProjection * vec4(p, 1.0);
}
)";
inline constexpr const char* kParticleFs = R"(#version 330 core
in vec3 vViewPos, vCentre, vColour;
uniform mat4 uProjection;
uniform float uOpacity;
out vec4 colour;
vec3 shade(vec3 base, vec3 n, vec3 v);
bool sphereHit(vec3 d, vec3 c, out vec3 hit, out vec3 normal, out float chord);
void main() {
  // Ray from the eye through this fragment against the sphere (cut by the clipping plane,
  // fluid_shaders.h): the nearest kept hit.
  vec3 d = normalize(vViewPos);
  vec3 hit, n;
  float chord;
  if (!sphereHit(d, vCentre, hit, n, chord)) discard;
  vec4 clipPos = uProjection * vec4(hit, 1.0);
  gl_FragDepth = clipPos.z / clipPos.w * 0.5 + 0.5;
  colour = vec4(shade(vColour, n, -d), uOpacity);
}
)";

inline constexpr const char* kLineVs = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uView, uProjection;
void main() { gl_Position = uProjection * uView * vec4(aPosition, 1.0); }
)";
inline constexpr const char* kLineFs = R"(#version 330 core
uniform vec3 uColour;
out vec4 colour;
void main() { colour = vec4(uColour, 1.0); }
)";

}  // namespace hs::render::shaders
