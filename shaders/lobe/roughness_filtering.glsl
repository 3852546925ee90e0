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

// The part of a filtered normal-map lookup's spread that lies inside the pixel (docs/methods.md,
// "toksvig"): 1 where the footprint covers a texel or more (minification: the mip level averages
// what the pixel sees), rho^2 where it covers rho < 1 texels. A magnified lookup blends texels a
// whole texel apart bilinearly, so the spread it reports (a shortened normal, a variance of the
// moments) is that of the texels it blends, t (1 - t) |n1 - n2|^2 at weight t, while the surface
// inside the pixel is the interpolated field (the reference's), whose normals there differ by
// rho |n1 - n2|: variance ~ rho^2 of it. Left whole, a rim between a flat texel and a steep one
// reads as roughness alpha ~ 0.5 a magnified mirror does not have, which smears its highlights
// into rings. rho is the GL's lod scale, the longer footprint axis in texels.
float magnifiedSpreadShare(vec2 dUVdx, vec2 dUVdy, vec2 texels) {
  vec2 x = dUVdx * texels, y = dUVdy * texels;
  return min(max(dot(x, x), dot(y, y)), 1.0);
}

// Toksvig 2005: a mip-filtered normal of length N < 1 means a spread of normals of Gaussian
// variance (1 - N) / N, which adds to the Blinn-Phong lobe's 1/s. With s = 2/alpha^2 - 2 this is
// beta'^2 = beta^2 + 2 (1 - N) / N for beta^2 = alpha^2 / (1 - alpha^2), per axis. spreadShare:
// the part of that spread inside the pixel (magnifiedSpreadShare).
vec2 toksvigAlpha(vec2 alpha, float normalLength, float spreadShare) {
  float n = clamp(normalLength, 1e-4, 1.0);
  vec2 a2 = min(alpha * alpha, vec2(1.0 - 1e-6));
  vec2 beta2 = a2 / (1.0 - a2) + 2.0 * spreadShare * (1.0 - n) / n;
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
