// Shading of one light with a given specular lobe: exact for delta lights, and for lights with
// extent the approximations of the `conventional` baseline (docs/methods.md#conventional), so
// that every NDF-filtering method differs from the baseline only in the lobe it passes in.
#include "common/brdf.glsl"
#include "common/delta_lights.glsl"
#include "common/lights.glsl"
#include "common/lobe.glsl"
#include "common/surface.glsl"

// Closest direction to r inside the cone (axis, sinHalf/cosHalf): the representative point of
// a sphere or distant disk (Karis 2013).
vec3 closestInCone(vec3 r, vec3 axis, float cosHalf, float sinHalf) {
  float c = dot(r, axis);
  if (c >= cosHalf) return r;
  vec3 side = r - c * axis;
  float len = length(side);
  if (len < 1e-6) return axis;
  return normalize(cosHalf * axis + sinHalf * (side / len));
}

// Closest point of a disk or quad to the reflected ray, via the ray's hit with the light plane.
vec3 closestOnPlanarLight(LightData L, vec3 p, vec3 r) {
  vec3 c = L.position_radius.xyz;
  vec3 n = L.direction_cos.xyz;
  float denom = dot(r, n);
  vec3 q = c;
  if (denom < -1e-6) {
    float t = dot(c - p, n) / denom;
    if (t > 0.0) q = p + t * r;
  }
  vec3 d = q - c;
  if (lightType(L) == LIGHT_DISK) {
    float rad = L.position_radius.w;
    float len = length(d);
    return len > rad ? c + d * (rad / len) : q;
  }
  vec3 u = L.axisU.xyz, v = L.axisV.xyz;
  float su = clamp(dot(d, u) / dot(u, u), -1.0, 1.0);
  float sv = clamp(dot(d, v) / dot(v, v), -1.0, 1.0);
  return c + su * u + sv * v;
}

// Solid angle of a light with extent seen from p (centreDir: unit direction to its centre);
// 0 when p is behind a one-sided emitter.
float lightSolidAngle(LightData L, vec3 p, vec3 centreDir) {
  int type = lightType(L);
  if (type == LIGHT_SUN) return PI * (1.0 - L.direction_cos.w * L.direction_cos.w);  // projected-disk
  vec3 d = L.position_radius.xyz - p;
  float d2 = max(dot(d, d), 1e-12);
  if (type == LIGHT_SPHERE) {
    float r = L.position_radius.w;
    return PI * min(r * r / d2, 1.0);
  }
  float cosL = -dot(centreDir, L.direction_cos.xyz);
  return cosL <= 0.0 ? 0.0 : lightArea(L) * cosL / d2;
}

// mirrorAlpha: lobes narrower than this (lobeWidth) see lights with extent as a mirror would.
Radiance shadeLobe(Surface s, LightData L, Lobe lobe, float mirrorAlpha) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  if (!lightHasExtent(L)) return shadeDeltaLight(s, lobe, L, wo);

  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (solidAngle <= 0.0) return result;
  float sinHalf = sqrt(min(solidAngle / PI, 1.0));  // sine of the cone of equal solid angle
  float cosHalf = sqrt(1.0 - sinHalf * sinHalf);
  vec3 radiance = lightRadiance(L);
  vec3 irradiance = radiance * solidAngle;  // at normal incidence

  // Diffuse: the light as a point at its centre.
  result.diffuse = diffuseCos(s.diffuse, toLocal(s, centreDir)) * irradiance;

  vec3 r = reflect(-s.view, s.normal);
  if (lobeWidth(lobe) < mirrorAlpha) {
    // Mirror-like: the radiance seen along the reflected ray, all or nothing per pixel.
    float dist;
    if (lightHit(L, s.position, r, dist)) result.specular = fresnelSchlick(s.f0, wo.z) * radiance;
    return result;
  }
  // Rough: representative point (Karis 2013) with the lobe widened by half the light's angular
  // radius and renormalised so that the peak does not gain energy.
  int type = lightType(L);
  vec3 l = type == LIGHT_SUN || type == LIGHT_SPHERE ? closestInCone(r, centreDir, cosHalf, sinHalf)
                                                     : normalize(closestOnPlanarLight(L, s.position, r) - s.position);
  float normalisation;
  Lobe widened = widenLobe(lobe, 0.5 * sinHalf, normalisation);
  result.specular = lobeSpecularCos(widened, wo, toLocal(s, l), s.f0) * irradiance * normalisation;
  return result;
}
