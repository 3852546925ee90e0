// Shading of one light with a given specular lobe: exact for delta lights, and for lights with
// extent the lobe integrated over the light's image (below), so that every NDF-filtering method
// differs from the `conventional` baseline only in the lobe it passes in.
#include "generated/gpu_contract.glsl"
#include "core/driver_profile.glsl"
#include "core/brdf.glsl"
#include "lobe/delta_lights.glsl"
#include "lobe/environment_shading.glsl"
#include "lights/lights.glsl"
#include "lobe/light_image.glsl"
#include "lobe/lobe.glsl"
#include "ltc/ltc_shading.glsl"
#include "core/surface.glsl"

// Whether the lobes given to the area-light shadeLobe below can be anisotropic. A module whose
// lobes are isotropic wherever the material's is says so (`#define METHOD_LOBES_KEEP_ISOTROPY`:
// the material's own lobe, or its alpha widened alike along both axes); then only an anisotropic
// material's lobes can be (the program variant MATERIAL_ANISOTROPIC), and an isotropic material's
// program compiles no hand-over to the representative point, which llvmpipe would otherwise run
// for every light whatever its weight.
#if defined(METHOD_LOBES_KEEP_ISOTROPY) && !MATERIAL_ANISOTROPIC
const bool LOBES_MAY_BE_ANISOTROPIC = false;
#else
const bool LOBES_MAY_BE_ANISOTROPIC = true;
#endif

// dl1, dl2: conjugate semi-axes of the light's outline as seen from p, as changes of the unit
// direction lc to its centre (perpendicular to lc; local frame).
//
// The image is first order about the half vector h to the light's centre, except for its edge
// towards the lobe's peak, which is exact. Along the meridian through h the slope is tan(theta),
// whose derivative 1 / cos^2(theta) grows without bound towards the horizon: the first-order
// ellipse reaches beta / cos^2(theta_c) towards the peak (beta: the half vectors' angular extent
// along the meridian), which exceeds the distance tan(theta_c) to the peak as soon as
// beta > sin(theta_c) cos(theta_c), i.e. for every grazing half vector (h.z -> 0) under a light
// wider than about 2 h.z, although the half vectors then come no closer to the normal than
// theta_c - beta (a silhouette seen with the light behind the viewer: the peak of a mirror-like
// lobe inside its image, and the representative point's (o.h) / (h.z o.z) ~ 1 / h.z^2 on top).
// The exact edge is tan(theta_c - beta) = (tan theta_c - tan beta) / (1 + tan theta_c tan beta);
// the ellipse is moved outward along the meridian so that its edge lies there. Its axes stay
// first order, so its area and the small-light limit do not change, and the move,
// beta^2 tan(theta_c) / cos^2(theta_c) to second order, is the exact image's own outward shift
// (its ends tan(theta_c -+ beta)): the ellipse agrees with the exact radial extent to second
// order and its near edge to every order.
LightImage lightImage(vec3 wo, vec3 lc, vec3 dl1, vec3 dl2) {
  vec3 sum = wo + lc;
  float len = max(length(sum), 1e-6);
  vec3 h = sum / len;
  float hz = max(h.z, 1e-4);
  LightImage image;
  image.centre = -h.xy / hz;
  vec3 d1 = (dl1 - h * dot(h, dl1)) / len, d2 = (dl2 - h * dot(h, dl2)) / len;
  image.J = mat2(-(d1.xy + image.centre * d1.z) / hz, -(d2.xy + image.centre * d2.z) / hz);
  float tanC = length(image.centre);  // tan(theta_c), the distance from the peak
  if (tanC > 1e-6) {
    vec2 outward = image.centre / tanC;
    // The meridian's unit tangent at h, towards the normal: (n - h h.z) / sin(theta_c).
    vec3 meridian = vec3(-h.xy * hz, length(h.xy) * length(h.xy)) / max(length(h.xy), 1e-20);
    float beta = min(length(vec2(dot(d1, meridian), dot(d2, meridian))), 1.5);
    float tanB = tan(beta);
    float nearEdge = (tanC - tanB) / (1.0 + tanC * tanB);  // tan(theta_c - beta), signed
    float reach = length(vec2(dot(image.J[0], outward), dot(image.J[1], outward)));  // the ellipse's, radially
    image.centre = outward * max(nearEdge + reach, tanC);
  }
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

// The representative point's share of the specular of a lobe shaded under LTC, for two lobes the
// isotropic table cannot hold (docs/methods.md, "Area lights by LTC"):
// - A box lobe (Kaplanyan et al.'s rectangle filter). Its shading is the material's lobe integrated
//   against the light convolved with the footprint box, K = (1_image * 1_box) / |box| in slope
//   space. No GGX stands for the box: the boxes of neighbouring pixels, whose half-vector slopes
//   step by the box's own width, tile slope space, so a highlight keeps its energy wherever it
//   falls in a pixel; a GGX of any width aliases. K is taken as two parts in the proportion of the
//   two areas, the box's weight |box|^2 / (|box|^2 + |image|^2): where the box is the larger (a
//   light smaller than the box), the box average convolved with the image, the lobe's mass over it
//   in closed form (shadeLobe's lobeMassOnImage), which keeps the boxes' partition of unity
//   exactly; where the light is the larger, the LTC of the box lobe's peak density
//   (ltcLobeMatrix) over the light's exact shape, clipped at the horizon.
// - An anisotropic lobe whose wide axis is rough: the stretched LTC (ltcLobe) cannot bend with the
//   reflection of an elongated NDF far from the mirror direction, while the representative point's
//   mass of the lobe over the light's image is exact in slope space. Measured against the
//   reference on planes under sphere and quad lights (ratios 1:1 to 20:1, axes turned 0 to 90
//   degrees): the stretched LTC is the closer below a largest alpha of 0.5 at any ratio, the
//   representative point above 0.6 from 2:1; isotropic lobes stay with the LTC. The representative
//   point does not know the horizon (it overshoots several times where a light reaches down to
//   it), so this share also falls to 0 as the light's lowest point comes down to the horizon (its
//   elevation's sine from 0.1 to 0). Smooth in all three, so no seam runs across a surface.
// The two shares combine as independent: 1 - (1 - box)(1 - anisotropic).
// A: the LTC's roughness matrix (ltcLobeMatrix of the lobe).
float ltcRepresentativePointWeight(Surface s, LightData L, Lobe lobe, mat2 A, vec3 wo) {
  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  vec3 dl1, dl2;
  lightOutline(L, s.position, centreDir, sqrt(min(solidAngle / PI, 1.0)), dl1, dl2);
  float box = 0.0;
  if (lobe.footprint != vec2(0.0)) {  // a constant for the methods without a box: folded away
    LightImage image = lightImage(wo, toLocal(s, centreDir), toLocal(s, dl1), toLocal(s, dl2));
    float imageArea = PI * abs(determinant(image.J));
    float boxArea = 4.0 * lobe.footprint.x * lobe.footprint.y;
    box = boxArea * boxArea / max(boxArea * boxArea + imageArea * imageArea, 1e-37);
  }
  float halfTrace = 0.5 * (A[0][0] + A[1][1]), halfDiff = 0.5 * (A[0][0] - A[1][1]);
  float root = sqrt(halfDiff * halfDiff + A[0][1] * A[0][1]);
  float largest = halfTrace + root, smallest = max(halfTrace - root, 1e-36);
  float lowest = dot(centreDir, s.normal) - length(vec2(dot(dl1, s.normal), dot(dl2, s.normal)));
  float anisotropic = LOBES_MAY_BE_ANISOTROPIC ? smoothstep(1.25, 2.0, sqrt(largest / smallest)) *
                                                    smoothstep(0.45, 0.6, sqrt(largest)) * smoothstep(0.0, 0.1, lowest)
                                              : 0.0;
  return 1.0 - (1.0 - box) * (1.0 - anisotropic);
}

// The area-light integration a lobe method chose (its compile-time enumeration `area_lights`,
// src/shading/methods/shared_params.hpp; the AREA_LIGHTS_* choices come from the generated
// contract): AREA_LIGHTS_LTC integrates GGX lobes' linearly transformed cosines over the light
// (ltc/ltc_shading.glsl), its specular shared with the representative point's where
// ltcRepresentativePointWeight says (box lobes, rough anisotropic lobes); computed where its
// weight is not 0 (core/driver_profile.glsl). AREA_LIGHTS_REPRESENTATIVE_POINT is shadeLobe above.
// An environment takes the split sum (lobe/environment_shading.glsl) at the same lobe.
Radiance shadeLobe(Surface s, LightData L, Lobe lobe, int areaLights) {
  if (!lightIsCompact(L)) return shadeLobeEnvironment(s, L, lobe);
  if (areaLights == AREA_LIGHTS_LTC && lightHasExtent(L) && lobe.ndf == NDF_GGX) {
    vec3 wo = toLocal(s, s.view);
    if (wo.z <= 0.0) return Radiance(vec3(0.0), vec3(0.0));
    // Box lobes and anisotropic ones: where neither can come, a constant false, and the lobe is the
    // table's own LTC, handing nothing over.
    bool mayHandOver = LOBES_MAY_BE_ANISOTROPIC || lobe.footprint != vec2(0.0);
    mat2 A = ltcLobeMatrix(lobe);
    Radiance result = shadeLobeLtc(s, L, A, wo, mayHandOver);
    if (mayHandOver) {
      float w = ltcRepresentativePointWeight(s, L, lobe, A, wo);
      result.specular *= 1.0 - w;
      if (blendSideNeeded(w > 0.0)) result.specular += w * shadeLobe(s, L, lobe).specular;
    }
    return result;
  }
  return shadeLobe(s, L, lobe);
}
