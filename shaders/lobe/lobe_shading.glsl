// Shading of one light with a given specular lobe: exact for delta lights, and for lights with
// extent the lobe integrated over the light's image (below), so that every NDF-filtering method
// differs from the `conventional` baseline only in the lobe it passes in.
#include "generated/gpu_contract.glsl"
#include "core/brdf.glsl"
#include "lobe/delta_lights.glsl"
#include "lobe/environment_shading.glsl"
#include "lights/lights.glsl"
#include "lobe/light_image.glsl"
#include "lobe/lobe.glsl"
#include "ltc/ltc_shading.glsl"
#include "core/surface.glsl"

// dl1, dl2: conjugate semi-axes of the light's outline as seen from p, as changes of the unit
// direction lc to its centre (perpendicular to lc; local frame).
LightImage lightImage(vec3 wo, vec3 lc, vec3 dl1, vec3 dl2) {
  vec3 sum = wo + lc;
  float len = max(length(sum), 1e-6);
  vec3 h = sum / len;
  float hz = max(h.z, 1e-4);
  LightImage image;
  image.centre = -h.xy / hz;
  vec3 d1 = (dl1 - h * dot(h, dl1)) / len, d2 = (dl2 - h * dot(h, dl2)) / len;
  image.J = mat2(-(d1.xy + image.centre * d1.z) / hz, -(d2.xy + image.centre * d2.z) / hz);
  return image;
}

// The diffuse term of a light with extent, the light as a point at its centre (of direction
// centreDir and projected solid angle solidAngle).
vec3 centreDiffuse(Surface s, LightData L, vec3 centreDir, float solidAngle) {
  return diffuseCos(s.diffuse, toLocal(s, centreDir)) * lightRadiance(L) * solidAngle;
}

// One light with a given lobe: exact for delta lights. For lights with extent (docs/methods.md,
// "Lobes"), the integral over the light of f cos = D G F (wo.h) / wo.z per unit half-vector solid
// angle, which in slope space (d omega_h = h.z^3 ds, D = P22 / h.z^4) is
//   L  integral over the light's image of  P22(s) G F (wo.h) / (h.z wo.z) ds.
// The lobe's mass over the image (lobeMassOnImage) carries the integral; G, F and the factor
// (wo.h) / (h.z wo.z) are taken at the representative point (Karis 2013: the light's point
// closest to the reflected ray), where a narrow lobe's mass lies: there h = n and the factor is 1.
// So a narrow lobe gives F L where the reflected ray meets the light (the mirror), a small light
// gives the point light of irradiance L Omega, and every lobe in between is continuous.
Radiance shadeLobe(Surface s, LightData L, Lobe lobe) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  if (!lightHasExtent(L)) return shadeDeltaLight(s, lobe, L, wo);

  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (solidAngle <= 0.0) return result;
  float sinHalf = sqrt(min(solidAngle / PI, 1.0));  // sine of the cone of equal (projected) solid angle
  vec3 radiance = lightRadiance(L);

  result.diffuse = centreDiffuse(s, L, centreDir, solidAngle);

  vec3 r = reflect(-s.view, s.normal);
  vec3 l = lightRepresentativeDirection(L, s.position, r, centreDir, sinHalf);
  vec3 wi = toLocal(s, l);
  if (wi.z <= 0.0) return result;
  vec3 h = normalize(wo + wi);
  vec3 dl1, dl2;
  lightOutline(L, s.position, centreDir, sinHalf, dl1, dl2);
  float mass = lobeMassOnImage(lobe, lightImage(wo, toLocal(s, centreDir), toLocal(s, dl1), toLocal(s, dl2)));
  // G2 (o.h) / (h_z o_z), with G2 / o_z in its bounded form.
  float geometry = lobeG2OverCos(lobe, wo, wi) * dot(wo, h) / max(h.z, 1e-4);
  result.specular = fresnelSchlick(s.f0, dot(wo, h)) * (mass * geometry) * radiance;
  return result;
}

// The direction a method filters its lobe towards (its half vector's screen-space derivatives):
// the light's centre. For a light that is not compact (an environment), the view mirrored about
// the triangle's face normal: a direction held fixed across the pixel (within a triangle), so that
// the half vector seen from the turning shading frame spreads by the surface's curvature and its
// normal map, as a distant light's would (the mirror direction itself has h = n: no spread).
vec3 lobeLightDirection(Surface s, LightData L) {
  if (lightIsCompact(L)) return lightCentreDirection(L, s.position);
  vec3 face = cross(s.footprint.dPdx, s.footprint.dPdy);
  vec3 n = dot(face, face) > 0.0 ? normalize(dot(face, s.vertexNormal) < 0.0 ? -face : face) : s.vertexNormal;
  return reflect(-s.view, n);
}

// The area-light integration a lobe method chose (its compile-time enumeration `area_lights`,
// src/shading/methods/shared_params.hpp; the AREA_LIGHTS_* choices come from the generated
// contract): AREA_LIGHTS_LTC integrates GGX lobes' linearly transformed cosines over the light
// (ltc/ltc_shading.glsl); AREA_LIGHTS_REPRESENTATIVE_POINT is shadeLobe above. An environment
// takes the split sum (lobe/environment_shading.glsl) at the same lobe.
Radiance shadeLobe(Surface s, LightData L, Lobe lobe, int areaLights) {
  if (!lightIsCompact(L)) return shadeLobeEnvironment(s, L, lobe);
  if (areaLights == AREA_LIGHTS_LTC && lightHasExtent(L) && lobe.ndf == NDF_GGX) {
    vec3 wo = toLocal(s, s.view);
    if (wo.z <= 0.0) return Radiance(vec3(0.0), vec3(0.0));
    return shadeLobeLtc(s, L, lobe, wo);
  }
  return shadeLobe(s, L, lobe);
}
