// NDF filtering over the pixel footprint in half-vector space, per light: the half vector's
// derivatives per pixel (in the raster pass quad finite differences, taken by the method in
// uniform control flow; from the footprint alone, core/footprint.glsl's half-vector
// differentials) span the set of half vectors a pixel sees, and the NDF is convolved with that set.
// Pure functions of the derivatives, so that tests can call them with any footprint.
#include "lobe/lobe.glsl"
#include "core/surface.glsl"

// Slope-space ("plane-plane") half vector h / (h . n) in the shading frame (Kaplanyan et al.
// 2016). h . n is kept above 1e-3 so that grazing half vectors give large, finite footprints.
vec2 slopeHalfVector(Surface s, vec3 l) {
  vec3 h = s.view + l;
  float hn = max(dot(h, s.normal), 1e-3 * length(h) + 1e-12);
  return vec2(dot(h, s.tangent), dot(h, s.bitangent)) / hn;
}

// Projected half vector: the unit half vector's tangent-plane part (Tokuyoshi & Kaplanyan 2019).
vec2 projectedHalfVector(Surface s, vec3 l) {
  vec3 h = normalize(s.view + l + vec3(0.0, 0.0, 1e-12));
  return vec2(dot(h, s.tangent), dot(h, s.bitangent));
}

// C scaled down so that its largest eigenvalue is at most limit (shape kept).
mat2 clampCovariance(mat2 c, float limit) {
  float top = maxEigenvalue(c);
  return top > limit ? c * (limit / top) : c;
}

// Kaplanyan et al. 2016, Beckmann: the Gaussian pixel filter (sigma = PIXEL_FILTER_SIGMA, the
// talk's "standard deviation of 0.5 pixel", "Filtering Beckmann"; docs/methods.md#kaplanyan-beckmann)
// mapped to slope space by the whole-pixel derivatives U = [dx dy] has covariance
// C = sigma^2 U U^T; the lobe convolved with it is R' = R + 2C, full (non-axis-aligned). fpMax
// bounds the footprint's standard deviation (sqrt of C's largest eigenvalue) as the rectangle
// variants bound fp, which keeps grazing angles finite.
Lobe kaplanyanBeckmannLobe(Lobe base, vec2 dx, vec2 dy, float fpMax) {
  float sigma2 = PIXEL_FILTER_SIGMA * PIXEL_FILTER_SIGMA;
  mat2 c = clampCovariance(sigma2 * derivativeCovariance(dx, dy), fpMax * fpMax);
  return Lobe(base.ndf, base.A + 2.0 * c, base.footprint);
}

// Half sides of the footprint's axis-aligned bounding rectangle, (|dx| + |dy|) / 2, clamped above:
// per axis at least the covariance's standard deviation sigma sqrt(dx_i^2 + dy_i^2) for sigma = 1/2
// (the rectangle is the talk's code: the half extent of the pixel's box, not the filter's width).
vec2 footprintRectangle(vec2 dx, vec2 dy, float fpMax) { return min(0.5 * (abs(dx) + abs(dy)), vec2(fpMax)); }

// Kaplanyan et al. 2016, axis-aligned: R' = R + 2 diag(fp^2) with the bounding rectangle.
Lobe kaplanyanRectLobe(Lobe base, vec2 dx, vec2 dy, float fpMax) {
  vec2 fp = footprintRectangle(dx, dy, fpMax);
  return Lobe(base.ndf, base.A + 2.0 * mat2(fp.x * fp.x, 0.0, 0.0, fp.y * fp.y), base.footprint);
}

// Kaplanyan et al. 2016, GGX: the NDF averaged over the bounding rectangle in slope space
// (closed form in lobe/lobe.glsl; Beckmann materials get the separable erf form).
Lobe kaplanyanBoxLobe(Lobe base, vec2 dx, vec2 dy, float fpMax) {
  return Lobe(base.ndf, base.A, footprintRectangle(dx, dy, fpMax));
}

// GGX alpha^2 <-> projected-space roughness beta^2 = alpha^2 / (1 - alpha^2) (Tokuyoshi &
// Kaplanyan 2021, eq. 4); alpha^2 is kept below 1 - 1e-6 so that beta^2 stays finite.
vec2 projectedRoughness(vec2 alpha2) {
  vec2 a2 = min(alpha2, vec2(1.0 - 1e-6));
  return a2 / (1.0 - a2);
}
// Inverse for a full matrix: A = (P + det(P) I) / (1 + tr(P) + det(P)) (supplement sec. 5.2).
mat2 alphaMatrixFromProjected(mat2 p) {
  float det = determinant(p);
  return (p + mat2(det)) / (1.0 + p[0][0] + p[1][1] + det);
}

// Tokuyoshi & Kaplanyan 2019/2021, projected-space NDF filtering: kernel K = 2 sigma2 J J^T
// from the derivatives J of the projected half vector, clamped to kappa, added to the
// projected roughness and mapped back. Beckmann materials add K to alpha^2 directly.
Lobe tokuyoshiLobe(Lobe base, vec2 dx, vec2 dy, float sigma2, float kappa) {
  mat2 k = clampCovariance(2.0 * sigma2 * derivativeCovariance(dx, dy), kappa);
  if (base.ndf == NDF_BECKMANN) return Lobe(base.ndf, base.A + k, base.footprint);
  vec2 beta2 = projectedRoughness(vec2(base.A[0][0], base.A[1][1]));  // material lobes are diagonal
  return Lobe(base.ndf, alphaMatrixFromProjected(mat2(beta2.x, 0.0, 0.0, beta2.y) + k), base.footprint);
}
