// The probability that one microfacet reflects a light into the view (Kneiphof & Klein 2024,
// docs/methods.md#kneiphof2024): the NDF's mass over the light's half-vector image Omega_h over its
// total,
//   p = integral over the light of D(h) / (4 |l.h|) dl  /  T,   T = integral over the hemisphere of D(h) dh,
// (dh = dl / (4 |l.h|) is the Jacobian of h = normalize(v + l)), estimated by the D-only LTC (table
// ltc-ndf) for large lights and by the NDF as constant over a small cap for small ones.
#include "core/brdf.glsl"
#include "ltc/ltc_shading.glsl"

// T for the isotropic GGX of roughness alpha: 1 + alpha^2 atanh(s) / s, s = sqrt(1 - alpha^2)
// (= 1 + alpha^2 ln((1 + s) / alpha) / s); 1 at alpha = 0, 2 at alpha = 1 (D = 1 / pi there).
float ggxTotalNdf(float alpha) {
  float a2 = alpha * alpha;
  float s2 = max(1.0 - a2, 0.0), s = sqrt(s2);
  // atanh written out (= Mesa's own): HLSL, which exported shaders translate to, has none.
  float t = min(s, 0.99999994);
  float atanhOverS = s < 1e-2 ? 1.0 + s2 * (1.0 / 3.0 + s2 * 0.2) : 0.5 * log((1.0 + t) / (1.0 - t)) / s;
  return 1.0 + a2 * atanhOverS;
}

// The isotropic roughness the tables and T are read at for an (anisotropic) GGX alpha: the same
// peak density as the lobe's, alpha^2 = sqrt(det A).
float glintIsotropicAlpha(vec2 alpha) { return sqrt(max(alpha.x * alpha.y, MIN_ALPHA * MIN_ALPHA)); }

// The small-cap estimate: D constant over the half-vector image of a light of solid angle
// `solidAngle` seen in local direction wi, p = D(h) solidAngle / (4 |wi.h|) / T.
float glintCapProbability(vec3 wo, vec3 wi, float solidAngle, vec2 alpha, float totalNdf) {
  if (wi.z <= 0.0) return 0.0;
  vec3 h = normalize(wo + wi);
  return ndfGGX(h, max(alpha, vec2(MIN_ALPHA))) * solidAngle / (4.0 * max(abs(dot(wi, h)), 1e-6) * totalNdf);
}

// Where the small-cap estimate gives way to the LTC: the weight of the cap, 1 for lights whose
// half-vector image is small against the lobe (the cap's error at the peak is (rho_h / alpha)^2,
// from D's curvature there), 0 for large ones, smooth in between so that no seam runs across a
// surface; the band is where the two estimates' errors cross (docs/methods.md#kneiphof2024, "Where
// the estimates switch"). rho_h is the half-vector image's largest angular radius: the light's,
// `angularRadius` (the major semi-axis of its outline), over 2 sqrt(|l.h|), the linear scale of
// dh = dl / (4 |l.h|). From the largest extent, not the solid angle: a long thin light subtends a
// small solid angle but reaches far across the lobe, where D is not the centre's.
const vec2 GLINT_CAP_TO_LTC = vec2(0.15, 0.35);  // rho_h / alpha: cap below, LTC above

float glintCapWeight(float angularRadius, float cosLH, float alpha) {
  float rho = angularRadius / (2.0 * sqrt(max(cosLH, 1e-6)));
  return 1.0 - smoothstep(GLINT_CAP_TO_LTC.x, GLINT_CAP_TO_LTC.y, rho / alpha);
}

// The largest angular radius of a compact light with extent seen from p (radians): its outline's
// major semi-axis. For spheres, suns and facing disks, sqrt(solidAngle / pi), as the cone of equal
// solid angle.
float lightLargestAngularRadius(LightData L, vec3 p, vec3 centreDir, float solidAngle) {
  vec3 dl1, dl2;
  lightOutline(L, p, centreDir, sqrt(min(solidAngle / PI, 1.0)), dl1, dl2);
  return outlineMajorRadius(dl1, dl2);
}
