// Per-pixel roughness filtering: the material's alpha widened once per pixel from the normals'
// screen-space change (Vlachos) or from the spread of a normal map's normals inside the texture
// footprint (Toksvig; LEAN's slope moments). Pure functions, so that tests can call them.
#include "core/constants.glsl"

// Vlachos 2015: perceptual roughness r = sqrt(alpha) clamped from below by
// scale * max(|dn/dx|^2, |dn/dy|^2)^exponent (exponent 1/3 in the talk); alpha' = max(alpha, floor^2).
vec2 vlachosAlpha(vec2 alpha, vec3 dNdx, vec3 dNdy, float scale, float exponent) {
  float change = clamp(max(dot(dNdx, dNdx), dot(dNdy, dNdy)), 0.0, 1.0);
  float floorRoughness = scale * pow(change, exponent);
  return max(alpha, vec2(floorRoughness * floorRoughness));
}

// Toksvig 2005: a mip-filtered normal of length N < 1 means a spread of normals of Gaussian
// variance (1 - N) / N, which adds to the Blinn-Phong lobe's 1/s. With s = 2/alpha^2 - 2 this is
// beta'^2 = beta^2 + 2 (1 - N) / N for beta^2 = alpha^2 / (1 - alpha^2), per axis.
vec2 toksvigAlpha(vec2 alpha, float normalLength) {
  float n = clamp(normalLength, 1e-4, 1.0);
  vec2 a2 = min(alpha * alpha, vec2(1.0 - 1e-6));
  vec2 beta2 = a2 / (1.0 - a2) + 2.0 * (1.0 - n) / n;
  return sqrt(beta2 / (1.0 + beta2));
}

// LEAN mapping (Olano & Baker 2010): from the filtered first moments B = E[n.xy / n.z] and second
// moments M = (E[Bx^2], E[By^2], E[Bx By]) of the normal map's slopes, the slope covariance
// Sigma = M - B B^T (correlation included), kept positive semi-definite against rounding. The
// lobe's roughness matrix is diag(alpha^2) + 2 Sigma (a Beckmann lobe of roughness alpha has
// slope variance alpha^2 / 2).
mat2 leanSlopeCovariance(vec2 b, vec3 m) {
  float sxx = max(m.x - b.x * b.x, 0.0), syy = max(m.y - b.y * b.y, 0.0);
  float bound = sqrt(sxx * syy);
  float sxy = clamp(m.z - b.x * b.y, -bound, bound);
  return mat2(sxx, sxy, sxy, syy);
}
