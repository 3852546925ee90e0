// Method `conventional`: the BRDF evaluated once at the pixel centre (the baseline to beat).
// Descriptor: src/shading/methods/conventional.cpp; docs/methods.md#conventional.
#include "common/brdf.glsl"
#include "common/delta_lights.glsl"
#include "common/lights.glsl"
#include "common/surface.glsl"

uniform float param_mirror_alpha;

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

Radiance shadeLight(Surface s, LightData L) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  if (!lightHasExtent(L)) return shadeDeltaLight(s, L, wo);
  int type = lightType(L);

  // Lights with extent: centre direction, solid angle and the sine of the equivalent cone.
  vec3 centreDir;
  float solidAngle;
  if (type == LIGHT_SUN) {
    centreDir = -L.direction_cos.xyz;
    solidAngle = PI * (1.0 - L.direction_cos.w * L.direction_cos.w);  // projected-disk solid angle
  } else {
    vec3 d = L.position_radius.xyz - s.position;
    float d2 = max(dot(d, d), 1e-12);
    centreDir = d * inversesqrt(d2);
    if (type == LIGHT_SPHERE) {
      float r = L.position_radius.w;
      solidAngle = PI * min(r * r / d2, 1.0);
    } else {
      float cosL = -dot(centreDir, L.direction_cos.xyz);
      if (cosL <= 0.0) return result;  // we are behind the emitting face
      solidAngle = lightArea(L) * cosL / d2;
    }
  }
  float sinHalf = sqrt(min(solidAngle / PI, 1.0));
  float cosHalf = sqrt(1.0 - sinHalf * sinHalf);
  vec3 radiance = lightRadiance(L);
  vec3 irradiance = radiance * solidAngle;  // at normal incidence

  // Diffuse: the light as a point at its centre.
  result.diffuse = diffuseCos(s.diffuse, toLocal(s, centreDir)) * irradiance;

  vec3 r = reflect(-s.view, s.normal);
  if (max(s.alpha.x, s.alpha.y) < param_mirror_alpha) {
    // Mirror-like: the radiance seen along the reflected ray, all or nothing per pixel.
    float dist;
    if (lightHit(L, s.position, r, dist)) result.specular = fresnelSchlick(s.f0, wo.z) * radiance;
    return result;
  }
  // Rough: representative point (Karis 2013) with the lobe widened by the light's half-angle
  // and renormalised by (alpha / alpha')^2 so the peak does not gain energy.
  vec3 l;
  if (type == LIGHT_SUN || type == LIGHT_SPHERE) {
    l = closestInCone(r, centreDir, cosHalf, sinHalf);
  } else {
    l = normalize(closestOnPlanarLight(L, s.position, r) - s.position);
  }
  vec2 widened = min(s.alpha + 0.5 * sinHalf, vec2(1.0));
  float normalisation = (max(s.alpha.x, MIN_ALPHA) * max(s.alpha.y, MIN_ALPHA)) / (widened.x * widened.y);
  result.specular = specularCos(s.ndf, wo, toLocal(s, l), s.alpha, s.f0) * irradiance * normalisation;
  return result;
}
