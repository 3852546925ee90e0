// Lights (a std140 uniform buffer, binding 1; see src/render/gpu_scene.cpp) and their exact geometry:
// ray hits, sampling and densities. Approximations of a light belong to the methods, not here.
#include "common/constants.glsl"

// Light kinds. Values mirror GpuLightKind in src/render/gpu_scene.hpp; the light buffer is sorted
// by kind (shaders/common/light_loop.glsl).
#define LIGHT_POINT 0
#define LIGHT_DIRECTIONAL 1  // delta directional
#define LIGHT_DISK 2
#define LIGHT_SPHERE 3
#define LIGHT_QUAD 4
#define LIGHT_SUN 5          // directional with an angular radius: a distant disk
#define LIGHT_KIND_COUNT 6

struct LightData {
  vec4 colour_type;      // rgb: intensity (point), irradiance (directional, sun) or radiance; a: kind
  vec4 position_radius;  // xyz: centre; w: radius (disk, sphere)
  vec4 direction_cos;    // xyz: travel direction (directional, sun) or emitting normal (disk, quad);
                         // w: cos(angular radius) of a sun
  vec4 axisU;            // xyz: quad: half edge vectors; w: sun: 1 - cos(angular radius), exact
  vec4 axisV;
};
// A uniform buffer, not a storage buffer: its loads are scalar, and drivers that mask storage
// loads in helper invocations (llvmpipe) would otherwise break screen-space derivatives of
// anything computed from a light. MAX_LIGHTS mirrors kMaxLights in src/scene/scene.hpp.
#define MAX_LIGHTS 128
layout(std140, binding = 1) uniform LightBlock { LightData lights[MAX_LIGHTS]; };

const float FAR_AWAY = 1e30;

int lightType(LightData L) { return int(L.colour_type.a); }

// Lights with extent: a delta-free integral over solid angle (area lights and suns).
bool lightHasExtent(LightData L) { return lightType(L) >= LIGHT_DISK; }

// 1 - cos(angular radius) of a sun, computed in double on the CPU (src/render/gpu_scene.cpp):
// 1 - direction_cos.w in float keeps only ~160 steps at 0.25 degrees. Hand-built records (tests)
// must set it too.
float sunOneMinusCos(LightData L) { return L.axisU.w; }

// sin^2 of a cone's half-angle from 1 - cos, without cancellation: (1 - c)(1 + c).
float coneSin2(float oneMinusCos) { return oneMinusCos * (2.0 - oneMinusCos); }

// Smallest 1 - cos of a cone that densities and radiances use (below 1e-7 degrees): keeps a cone's
// pdf under 2e17, so that MIS weights built from squared pdfs stay finite.
const float MIN_CONE_ONE_MINUS_COS = 1e-18;

// Is the direction dir inside the cone of half-angle acos(1 - oneMinusCos) (< 90 degrees) around
// axis? Compares sin^2 from the cross product, exact near the axis, not cosines near 1.
bool inCone(vec3 dir, vec3 axis, float oneMinusCos) {
  float c = dot(dir, axis);
  if (c <= 0.0) return false;
  vec3 x = cross(dir, axis);
  return dot(x, x) <= coneSin2(oneMinusCos) * dot(dir, dir) * dot(axis, axis);
}

// Radiance of lights with extent. A sun of angular radius theta with irradiance E at normal
// incidence has radiance E / (pi sin^2 theta).
vec3 lightRadiance(LightData L) {
  if (lightType(L) == LIGHT_SUN) return L.colour_type.rgb / (PI * coneSin2(max(sunOneMinusCos(L), MIN_CONE_ONE_MINUS_COS)));
  return L.colour_type.rgb;
}

float lightArea(LightData L) {
  int t = lightType(L);
  float r = L.position_radius.w;
  if (t == LIGHT_DISK) return PI * r * r;
  if (t == LIGHT_QUAD) return 4.0 * length(L.axisU.xyz) * length(L.axisV.xyz);
  return 4.0 * PI * r * r;
}

// Unit direction from p towards the light's centre (for directional lights and suns, against
// their travel direction).
vec3 lightCentreDirection(LightData L, vec3 p) {
  int t = lightType(L);
  if (t == LIGHT_DIRECTIONAL || t == LIGHT_SUN) return -L.direction_cos.xyz;
  vec3 d = L.position_radius.xyz - p;
  return d * inversesqrt(max(dot(d, d), 1e-24));
}

// Unit direction from p to a point or delta directional light, and its irradiance at normal incidence.
void deltaLightIncidence(LightData L, vec3 p, out vec3 l, out vec3 irradiance) {
  if (lightType(L) == LIGHT_POINT) {
    vec3 d = L.position_radius.xyz - p;
    float d2 = max(dot(d, d), 1e-12);
    l = d * inversesqrt(d2);
    irradiance = L.colour_type.rgb / d2;
  } else {
    l = -L.direction_cos.xyz;
    irradiance = L.colour_type.rgb;
  }
}

// Does the ray (origin, unit dir) reach the emitting side of the light? dist: hit distance.
bool lightHit(LightData L, vec3 origin, vec3 dir, out float dist) {
  int t = lightType(L);
  dist = FAR_AWAY;
  if (t == LIGHT_SUN) return inCone(dir, -L.direction_cos.xyz, sunOneMinusCos(L));
  if (t == LIGHT_POINT || t == LIGHT_DIRECTIONAL) return false;
  vec3 c = L.position_radius.xyz;
  if (t == LIGHT_SPHERE) {
    float r = L.position_radius.w;
    vec3 oc = origin - c;
    float b = dot(oc, dir);
    vec3 perp = oc - b * dir;  // r^2 - |perp|^2, not b^2 - |oc|^2 + r^2: no cancellation far away
    float disc = r * r - dot(perp, perp);
    if (disc < 0.0) return false;
    float s = sqrt(disc);
    dist = -b - s;
    if (dist <= 0.0) dist = -b + s;
    return dist > 0.0;
  }
  if (t == LIGHT_DISK || t == LIGHT_QUAD) {
    vec3 n = L.direction_cos.xyz;
    float cosL = dot(dir, n);
    if (cosL >= 0.0) return false;  // one-sided: only the front face emits
    dist = dot(c - origin, n) / cosL;
    if (dist <= 0.0) return false;
    vec3 d = origin + dist * dir - c;
    if (t == LIGHT_DISK) return dot(d, d) <= L.position_radius.w * L.position_radius.w;
    vec3 u = L.axisU.xyz, v = L.axisV.xyz;
    return abs(dot(d, u)) <= dot(u, u) && abs(dot(d, v)) <= dot(v, v);
  }
  return false;
}

// Orthonormal basis around unit n (Duff et al. 2017).
void basisAround(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Uniform direction in the cone of half-angle acos(1 - oneMinusCosMax) around axis;
// pdf = 1 / (2 pi oneMinusCosMax). Samples 1 - cos directly, so small cones keep their resolution.
vec3 sampleCone(vec3 axis, float oneMinusCosMax, vec2 u) {
  float oneMinusCosT = u.x * oneMinusCosMax;
  float cosT = 1.0 - oneMinusCosT;
  float sinT = sqrt(max(0.0, coneSin2(oneMinusCosT)));
  float phi = TWO_PI * u.y;
  vec3 t, b;
  basisAround(axis, t, b);
  return normalize(sinT * cos(phi) * t + sinT * sin(phi) * b + cosT * axis);
}

// 1 - cos of the half-angle a sphere light subtends from p, as sin^2 / (1 + cos): no
// cancellation for small or distant spheres.
float sphereConeOneMinusCos(LightData L, vec3 p) {
  vec3 d = L.position_radius.xyz - p;
  float r = L.position_radius.w;
  float sin2 = min(r * r / max(dot(d, d), 1e-30), 1.0);
  return sin2 / (1.0 + sqrt(1.0 - sin2));
}

// Solid-angle density with which sampleLightDirection picks `dir` (which hits at `dist`).
float lightPdf(LightData L, vec3 p, vec3 dir, float dist) {
  int t = lightType(L);
  if (t == LIGHT_SUN) return 1.0 / (TWO_PI * max(sunOneMinusCos(L), MIN_CONE_ONE_MINUS_COS));
  if (t == LIGHT_SPHERE) return 1.0 / (TWO_PI * max(sphereConeOneMinusCos(L, p), MIN_CONE_ONE_MINUS_COS));
  float cosL = abs(dot(dir, L.direction_cos.xyz));
  return dist * dist / max(lightArea(L) * cosL, 1e-20);
}

// Samples a direction towards the light from p; returns false if the sample is unusable.
bool sampleLightDirection(LightData L, vec3 p, vec2 u, out vec3 dir, out float dist, out float pdf) {
  int t = lightType(L);
  dist = FAR_AWAY;
  if (t == LIGHT_SUN) {
    dir = sampleCone(-L.direction_cos.xyz, sunOneMinusCos(L), u);
    pdf = lightPdf(L, p, dir, dist);
    return true;
  }
  vec3 c = L.position_radius.xyz;
  if (t == LIGHT_SPHERE) {
    vec3 toC = c - p;
    dir = sampleCone(normalize(toC), sphereConeOneMinusCos(L, p), u);
    pdf = lightPdf(L, p, dir, dist);
    return lightHit(L, p, dir, dist);
  }
  vec3 q;
  if (t == LIGHT_DISK) {
    // Concentric square-to-disk mapping (Shirley & Chiu 1997).
    vec2 s = 2.0 * u - 1.0;
    float r, phi;
    if (s == vec2(0.0)) { r = 0.0; phi = 0.0; }
    else if (abs(s.x) > abs(s.y)) { r = s.x; phi = (PI / 4.0) * (s.y / s.x); }
    else { r = s.y; phi = PI / 2.0 - (PI / 4.0) * (s.x / s.y); }
    vec3 tx, ty;
    basisAround(L.direction_cos.xyz, tx, ty);
    q = c + L.position_radius.w * r * (cos(phi) * tx + sin(phi) * ty);
  } else {
    q = c + (2.0 * u.x - 1.0) * L.axisU.xyz + (2.0 * u.y - 1.0) * L.axisV.xyz;
  }
  vec3 d = q - p;
  dist = length(d);
  if (dist <= 0.0) return false;
  dir = d / dist;
  if (dot(dir, L.direction_cos.xyz) >= 0.0) return false;  // behind the emitting face
  pdf = lightPdf(L, p, dir, dist);
  return true;
}
