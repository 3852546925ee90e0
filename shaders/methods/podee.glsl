// Method `podee`: micro-specular highlights (Podee, Max, Iwasaki, Dobashi): the pixel's four
// corner reflection vectors span a reflection space on the light plane; the direction to its
// point closest to the light's centre is shaded and weighted by the fraction of the reflection
// space the light covers. Extended to sphere lights and suns, and to glossy lobes by convolving
// the light with the lobe in the light plane (equal-energy disk) and blending with the smooth
// shading when the lobe is wider than the pixel's reflection space.
// Descriptor: src/shading/methods/podee.cpp; derivations: docs/methods.md#podee.
#include "common/lobe_shading.glsl"
#include "common/pixel_corners.glsl"
#include "common/reflection_space.glsl"

uniform float param_mirror_alpha;
uniform float param_corners;  // 0: interpolated (exact), 1: from derivatives
uniform float param_origin;   // 0: rays from the corners' surface points, 1: from the centre (the paper)
uniform float param_area;     // 0: exact (ellipse), 1: light as a circle, 2: light and quad as circles
uniform float param_glossy;   // 1: the lobe extension; 0: every material shaded as a mirror (the paper)

CornerRays gCorners;  // this pixel's corner rays, set by prepareSurface

void prepareSurface(inout Surface s) {
  // Both variants in uniform control flow (the derivative one needs it); one is kept.
  CornerRays interpolated = interpolatedCornerRays(s);
  CornerRays firstOrder = derivativeCornerRays(s);
  gCorners = param_corners < 0.5 ? interpolated : firstOrder;
  if (param_origin > 0.5)
    for (int i = 0; i < 4; ++i) gCorners.origin[i] = s.position;
}

// The light as seen from p, on the light plane: through the light's centre c, normal l (the
// unit direction from p to c), with orthonormal axes u, w along which the projected light is an
// ellipse of semi-axes `axes`. valid is false when p does not see the emitting side.
struct LightPlane {
  vec3 centre, l, u, w;
  vec2 axes;
  float distance;  // from p to the plane; 1 for a sun (its plane is placed at unit distance)
  bool valid;
};

LightPlane lightPlane(LightData L, vec3 p) {
  LightPlane plane;
  int type = lightType(L);
  plane.l = lightCentreDirection(L, p);
  float radius = L.position_radius.w;
  if (type == LIGHT_SUN) {
    // A disk at infinity: its cone's section at unit distance, radius tan(theta).
    float cosT = L.direction_cos.w, sinT = sqrt(max(1.0 - cosT * cosT, 0.0));
    plane.distance = 1.0;
    plane.centre = p + plane.l;
    plane.axes = vec2(sinT / max(cosT, 1e-6));
    basisAround(plane.l, plane.u, plane.w);
    plane.valid = true;
    return plane;
  }
  plane.centre = L.position_radius.xyz;
  plane.distance = length(plane.centre - p);
  if (type == LIGHT_SPHERE) {
    // The cone tangent to the sphere cuts the plane in a circle of radius R d / sqrt(d^2 - R^2).
    float d2 = plane.distance * plane.distance;
    plane.valid = d2 > radius * radius * 1.0001;
    plane.axes = vec2(radius * plane.distance * inversesqrt(max(d2 - radius * radius, 1e-12)));
    basisAround(plane.l, plane.u, plane.w);
    return plane;
  }
  // Disk: to first order in R/d the central projection of the disk is its orthographic
  // projection along l: semi-axes R along u = n_L x l (in both planes) and R |n_L . l| along w.
  vec3 n = L.direction_cos.xyz;
  float cosL = -dot(n, plane.l);
  plane.valid = cosL > 0.0;  // one-sided emitter
  vec3 u = cross(n, plane.l);
  float len = length(u);
  vec3 t, b;
  basisAround(plane.l, t, b);
  plane.u = len > 1e-6 ? u / len : t;
  plane.w = cross(plane.l, plane.u);
  plane.axes = radius * vec2(1.0, max(cosL, 1e-6));
  return plane;
}

// Probability that the lobe, aimed at the light's centre, reflects into the light: slope-space
// mass within the light's image in half-vector slopes, a disk of radius tan(theta_L / 2) stretched
// by 1 / cos(theta_d) across the plane of incidence (reflection halves in-plane angles and
// compresses the others by cos theta_d), taken as the circle of equal area. Isotropic
// GGX: t^2 / (alpha^2 + t^2); Beckmann: 1 - exp(-t^2 / alpha^2).
float lobeMassOnLight(Surface s, float angularRadius, float cosThetaD) {
  float alpha2 = s.alpha.x * s.alpha.y;
  if (alpha2 <= 0.0) return 1.0;
  float t = tan(0.5 * angularRadius);
  float t2 = t * t / max(cosThetaD, 1e-4);
  return s.ndf == NDF_BECKMANN ? 1.0 - exp(-t2 / alpha2) : t2 / (alpha2 + t2);
}

Radiance shadeLight(Surface s, LightData L) {
  int type = lightType(L);
  if (!(type == LIGHT_DISK || type == LIGHT_SPHERE || type == LIGHT_SUN))
    return shadeLobe(s, L, materialLobe(s), param_mirror_alpha);  // delta and quad lights: the baseline

  // The smooth shading of `conventional` (never the mirror path): the diffuse term, and the
  // specular term where the lobe is wider than the reflection space.
  Radiance result = shadeLobe(s, L, materialLobe(s), 0.0);
  LightPlane plane = lightPlane(L, s.position);
  if (!plane.valid || dot(s.view, s.vertexNormal) <= 0.0) return result;

  // Lobe extension: the light convolved with the lobe is approximated by the light scaled by
  // 1/sqrt(P) with radiance P L (same energy, same peak). P = 1 for a mirror (the paper).
  float angularRadius = atan(sqrt(plane.axes.x * plane.axes.y) / plane.distance);
  float cosThetaD = dot(s.view, normalize(s.view + plane.l));
  float mass = param_glossy > 0.5 ? lobeMassOnLight(s, angularRadius, cosThetaD) : 1.0;
  float scale = inversesqrt(max(mass, 1e-8));
  vec2 axes = param_area > 0.5 ? vec2(sqrt(plane.axes.x * plane.axes.y)) : plane.axes;  // circle of equal area
  axes *= scale;

  // Reflection space: the corner rays' hits with the light plane, in coordinates where the
  // (scaled) light is the unit disk. Rays pointing away from the light (r . l <= 0) hit at
  // infinity in the direction of their tangential part; they are clamped to 1e4 plane distances.
  vec2 q[4];
  for (int i = 0; i < 4; ++i) {
    vec3 o = type == LIGHT_SUN ? s.position : gCorners.origin[i];
    vec3 r = gCorners.direction[i];
    float t = dot(plane.centre - o, plane.l) / max(dot(r, plane.l), 1e-4);
    vec3 x = o + t * r - plane.centre;
    q[i] = vec2(dot(x, plane.u), dot(x, plane.w)) / axes;
  }
  convexHullQuad(q);

  // Reflection vector selection (sec. 3.1): the point closest to the light's centre.
  vec2 closest = closestPointInConvexQuad(q, vec2(0.0));
  vec3 selected = plane.centre + closest.x * axes.x * plane.u + closest.y * axes.y * plane.w;
  vec3 l = normalize(selected - s.position);
  if (dot(l, s.vertexNormal) <= 0.0) return result;  // the light is below this surface

  // Result weighting (sec. 3.2): the covered fraction of the reflection space.
  float coverage = unitDiskCoverage(q, param_area > 1.5 ? COVERAGE_LENS : COVERAGE_EXACT);
  vec3 h = normalize(s.view + l);
  float cosD = max(dot(s.view, h), 1e-4);
  float lambda = smithLambdaOfT2(s.ndf, s.alpha.x * s.alpha.y * (1.0 - cosD * cosD) / (cosD * cosD));
  float masking = param_glossy > 0.5 ? 1.0 / (1.0 + 2.0 * lambda) : 1.0;
  vec3 podee = fresnelSchlick(s.f0, cosD) * masking * mass * coverage * lightRadiance(L);

  // Where the lobe is wider than the reflection space the highlight is resolved and the smooth
  // shading is right: weight by the areas (in the unscaled light's units) of the reflection
  // space and of the lobe's blur, pi (1/P - 1). A mirror has no blur: podee alone.
  float spaceArea = quadArea(q) * scale * scale;
  float blurArea = PI * (scale * scale - 1.0);
  float podeeWeight = blurArea > 0.0 ? spaceArea / (spaceArea + blurArea) : 1.0;
  result.specular = mix(result.specular, podee, podeeWeight);
  return result;
}
