#pragma once
// GLSL 3.30 sources of the blood's liquid surface (fluid_surface.cpp) and of the flow lines
// (renderer.cpp). The liquid surface is screen-space fluid rendering after Simon Green 2010,
// "Screen Space Fluid Rendering for Games" (GDC), and van der Laan, Green & Sainz 2009,
// "Screen Space Fluid Rendering with Curvature Flow" (I3D): the particles' spheres are drawn
// to a depth image (nearest sphere per pixel) and, added up, to a thickness image; the depth
// is smoothed with a bilateral filter, normals are rebuilt from the smoothed depth, and the
// surface is shaded with an opacity from its thickness (Beer-Lambert).

namespace hs::render::shaders {

// The ray from the eye through a fragment against one particle's sphere, cut by the clipping
// plane: shared by the sphere look (shaders.h) and the liquid's depth and thickness passes.
// The cut keeps dot(n, x) + w <= 0 (view space). A particle within a radius of the plane
// shows a disc of the full radius on it (the cut face: normal n toward the removed side, i.e.
// toward the eye), so the blood is cut flat with the wall instead of bulging out of the opened
// heart; the full radius, not the sphere's own cross-section, so that the discs of the
// particles near the plane close up into one face instead of leaving holes into the blood.
inline constexpr const char* kSphereHit = R"(
uniform float uRadius;
uniform vec4 uClip;
uniform bool uClipOn;
// d: unit ray direction from the eye (view space); c: the sphere's centre. Returns false on a
// miss; else the nearest kept point, its unit normal and the kept chord's length.
bool sphereHit(vec3 d, vec3 c, out vec3 hit, out vec3 normal, out float chord) {
  float b = dot(d, c);
  float disc = b * b - dot(c, c) + uRadius * uRadius;
  hit = vec3(0.0);
  normal = vec3(0.0, 0.0, 1.0);
  chord = 0.0;
  if (uClipOn) {
    float fc = dot(uClip.xyz, c) + uClip.w;  // signed distance of the centre from the plane
    float nd = dot(uClip.xyz, d);
    if (abs(fc) < uRadius && abs(nd) > 1e-6) {
      float tp = -uClip.w / nd;
      vec3 onPlane = d * tp;
      vec3 centreOnPlane = c - fc * uClip.xyz;
      if (tp > 0.0 && distance(onPlane, centreOnPlane) < uRadius) {
        hit = onPlane;
        normal = normalize(uClip.xyz);
        chord = uRadius - fc;  // from the plane to the sphere's far side along the normal
        return true;
      }
    }
  }
  if (disc < 0.0) return false;
  float s = sqrt(disc);
  float t0 = b - s, t1 = b + s;
  normal = (d * t0 - c) / uRadius;
  if (uClipOn) {
    float nd = dot(uClip.xyz, d);
    float f0 = nd * t0 + uClip.w, f1 = nd * t1 + uClip.w;  // > 0: removed
    if (f0 > 0.0 && f1 > 0.0) return false;
    if (f0 > 0.0) {
      t0 = -uClip.w / nd;
      normal = normalize(uClip.xyz);
    } else if (f1 > 0.0) {
      t1 = -uClip.w / nd;
    }
  }
  hit = d * t0;
  chord = t1 - t0;
  return true;
}
)";

// Pass 1: the nearest sphere's linear depth (-z of the hit, view space) and its colour.
inline constexpr const char* kLiquidDepthFs = R"(#version 330 core
in vec3 vViewPos, vCentre, vColour;
uniform mat4 uProjection;
layout(location = 0) out float depthOut;
layout(location = 1) out vec4 colourOut;
bool sphereHit(vec3 d, vec3 c, out vec3 hit, out vec3 normal, out float chord);
void main() {
  vec3 hit, n;
  float chord;
  if (!sphereHit(normalize(vViewPos), vCentre, hit, n, chord)) discard;
  vec4 clipPos = uProjection * vec4(hit, 1.0);
  gl_FragDepth = clipPos.z / clipPos.w * 0.5 + 0.5;
  depthOut = -hit.z;
  colourOut = vec4(vColour, 1.0);
}
)";

// Pass 2: thickness, the sum over spheres of the chord each ray crosses (additive blending).
inline constexpr const char* kLiquidThicknessFs = R"(#version 330 core
in vec3 vViewPos, vCentre, vColour;
out float thicknessOut;
bool sphereHit(vec3 d, vec3 c, out vec3 hit, out vec3 normal, out float chord);
void main() {
  vec3 hit, n;
  float chord;
  if (!sphereHit(normalize(vViewPos), vCentre, hit, n, chord)) discard;
  thicknessOut = chord;
}
)";

inline constexpr const char* kFullScreenVs = R"(#version 330 core
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Pass 3 (twice: along x, then y): the bilateral filter of Green 2010, separated:
//   d'(p) = sum_q d(q) w_s(|p - q|) w_r(d(q) - d(p)) / sum_q w_s w_r,
//   w_s = exp(-x^2 / (2 sigma^2)), w_r = exp(-(delta d / falloff)^2).
// The spatial radius is a world length (a few particle radii) projected at the pixel's depth,
// capped; the range weight keeps separate layers (blood behind blood) from being blended. The
// colour is filtered with the same weights, so it follows the surface.
inline constexpr const char* kLiquidBlurFs = R"(#version 330 core
uniform sampler2D uDepth, uColour;
uniform ivec2 uStep;
uniform float uWorldRadius, uPixelsPerUnit, uFalloff;
uniform int uMaxRadius;
layout(location = 0) out float depthOut;
layout(location = 1) out vec4 colourOut;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uDepth, 0);
  float d = texelFetch(uDepth, p, 0).r;
  if (d <= 0.0) {
    depthOut = 0.0;
    colourOut = vec4(0.0);
    return;
  }
  int r = clamp(int(uWorldRadius * uPixelsPerUnit / d), 1, uMaxRadius);
  float inv2Sigma2 = 2.0 / float(r * r);  // sigma = r / 2
  float sum = 0.0, weight = 0.0;
  vec3 colour = vec3(0.0);
  // Beyond 6 pixels every other pixel is taken: the Gaussian is still sampled at least 3 times
  // per sigma, and a software renderer pays per tap.
  int stride = r > 6 ? 2 : 1;
  for (int i = -r; i <= r; i += stride) {
    ivec2 q = clamp(p + i * uStep, ivec2(0), size - 1);
    float dq = texelFetch(uDepth, q, 0).r;
    if (dq <= 0.0) continue;
    float dz = (dq - d) / uFalloff;
    float w = exp(-float(i * i) * inv2Sigma2 - dz * dz);
    sum += dq * w;
    colour += texelFetch(uColour, q, 0).rgb * w;
    weight += w;
  }
  depthOut = sum / weight;
  colourOut = vec4(colour / weight, 1.0);
}
)";

// Pass 4: the surface from the smoothed depth, shaded and blended into the scene. Normals come
// from the view-space positions of the neighbouring pixels, taking on each axis the smaller of
// the forward and backward differences (Green 2010), so a silhouette does not bend the normal.
// Shading keeps the colour key exact: a surface facing the eye has exactly the blood's colour
// (diffuse from a light at the eye), darker toward the outline, with a small specular highlight
// of the key light. Opacity from the thickness T (Beer-Lambert): alpha = 1 - exp(-k T).
inline constexpr const char* kLiquidCompositeFs = R"(#version 330 core
uniform sampler2D uDepth, uColour, uThickness;
uniform mat4 uProjection;
uniform vec2 uTanHalf;  // tan of half the field of view, x and y
uniform float uScale;   // liquid pixels per screen pixel
uniform float uOpacity, uAbsorption;
uniform vec3 uKey;
out vec4 colour;
vec3 viewPosition(ivec2 p, float d, vec2 size) {
  vec2 ndc = (vec2(p) + 0.5) / size * 2.0 - 1.0;
  return vec3(ndc * uTanHalf * d, -d);
}
// The difference toward the nearer neighbour along `step` that has liquid.
vec3 difference(ivec2 p, ivec2 step, vec3 centre, vec2 size) {
  ivec2 hi = ivec2(size) - 1;
  ivec2 a = clamp(p + step, ivec2(0), hi), b = clamp(p - step, ivec2(0), hi);
  float da = texelFetch(uDepth, a, 0).r, db = texelFetch(uDepth, b, 0).r;
  vec3 forward = da > 0.0 ? viewPosition(a, da, size) - centre : vec3(0.0);
  vec3 backward = db > 0.0 ? centre - viewPosition(b, db, size) : vec3(0.0);
  if (da <= 0.0) return backward;
  if (db <= 0.0) return forward;
  return abs(forward.z) < abs(backward.z) ? forward : backward;
}
void main() {
  vec2 size = vec2(textureSize(uDepth, 0));
  ivec2 hi = ivec2(size) - 1;
  vec2 q = gl_FragCoord.xy * uScale;
  ivec2 p = min(ivec2(q), hi);
  float d = texelFetch(uDepth, p, 0).r;
  if (d <= 0.0) discard;
  vec3 pos = viewPosition(p, d, size);
  vec3 dx = difference(p, ivec2(1, 0), pos, size), dy = difference(p, ivec2(0, 1), pos, size);
  vec3 n = cross(dx, dy);
  n = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);
  vec3 base = texelFetch(uColour, p, 0).rgb;
  float thickness = texelFetch(uThickness, p, 0).r;
  // Below full resolution, depth, colour and thickness are interpolated between the four
  // nearest texels where all four hold liquid (at the outline the nearest one is kept), so the
  // upscaled surface shows no blocks.
  if (uScale < 1.0) {
    vec2 c = q - 0.5;
    ivec2 i0 = clamp(ivec2(floor(c)), ivec2(0), hi), i1 = min(i0 + 1, hi);
    vec2 f = clamp(c - vec2(i0), 0.0, 1.0);
    vec4 ds = vec4(texelFetch(uDepth, i0, 0).r, texelFetch(uDepth, ivec2(i1.x, i0.y), 0).r,
                   texelFetch(uDepth, ivec2(i0.x, i1.y), 0).r, texelFetch(uDepth, i1, 0).r);
    if (all(greaterThan(ds, vec4(0.0)))) {
      vec4 w = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
      d = dot(ds, w);
      base = w.x * texelFetch(uColour, i0, 0).rgb + w.y * texelFetch(uColour, ivec2(i1.x, i0.y), 0).rgb +
             w.z * texelFetch(uColour, ivec2(i0.x, i1.y), 0).rgb + w.w * texelFetch(uColour, i1, 0).rgb;
      thickness = dot(w, vec4(texelFetch(uThickness, i0, 0).r, texelFetch(uThickness, ivec2(i1.x, i0.y), 0).r,
                              texelFetch(uThickness, ivec2(i0.x, i1.y), 0).r, texelFetch(uThickness, i1, 0).r));
      vec2 ndc = q / size * 2.0 - 1.0;
      pos = vec3(ndc * uTanHalf * d, -d);
    }
  }
  vec3 v = normalize(-pos);
  if (dot(n, v) < 0.0) n = -n;
  float facing = dot(n, v);
  float spec = 0.3 * pow(max(dot(n, normalize(uKey + v)), 0.0), 90.0);
  vec3 lit = base * (0.55 + 0.45 * facing) + vec3(spec);
  colour = vec4(lit, uOpacity * (1.0 - exp(-uAbsorption * thickness)));
  vec4 clipPos = uProjection * vec4(pos, 1.0);
  gl_FragDepth = clipPos.z / clipPos.w * 0.5 + 0.5;
}
)";

// Flow lines: each segment an instance, a screen-space ribbon between its two ends of the given
// widths (pixels), in its own flat colour (no lighting: the colour key reads true), cut by the
// clipping plane like the wall.
inline constexpr const char* kFlowLineVs = R"(#version 330 core
layout(location = 0) in vec3 aFrom;
layout(location = 1) in vec3 aTo;
layout(location = 2) in vec3 aColour;
layout(location = 3) in vec2 aWidth;  // pixels at from, at to
uniform mat4 uView, uProjection;
uniform vec2 uViewport;
uniform vec4 uClip;
uniform bool uClipOn;
flat out vec3 vColour;
void main() {
  int end = gl_VertexID >> 1;             // 0: from, 1: to
  float side = float(gl_VertexID & 1) * 2.0 - 1.0;
  vec4 a = uView * vec4(aFrom, 1.0), b = uView * vec4(aTo, 1.0);
  vec4 ca = uProjection * a, cb = uProjection * b;
  vec2 sa = ca.xy / ca.w * uViewport, sb = cb.xy / cb.w * uViewport;
  vec2 along = sb - sa;
  along = dot(along, along) > 1e-8 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec4 c = end == 0 ? ca : cb;
  float width = end == 0 ? aWidth.x : aWidth.y;
  // Half a pixel past each end, so that consecutive segments of a streak meet without gaps.
  vec2 offset = across * side * width * 0.5 + along * (float(end) * 2.0 - 1.0) * 0.5;
  c.xy += offset / uViewport * c.w;
  vec3 p = end == 0 ? a.xyz : b.xyz;
  gl_ClipDistance[0] = uClipOn ? -(dot(uClip.xyz, p) + uClip.w) : 1.0;
  vColour = aColour;
  gl_Position = c;
}
)";
inline constexpr const char* kFlowLineFs = R"(#version 330 core
flat in vec3 vColour;
out vec4 colour;
void main() { colour = vec4(vColour, 1.0); }
)";

}  // namespace hs::render::shaders
