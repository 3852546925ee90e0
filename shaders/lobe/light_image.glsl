// The lobe convolved with a light: the fraction of a lobe's slope distribution inside the light's
// image in slope space, which carries every lobe method's integral over a light with extent
// (lobe/lobe_shading.glsl, podee/reflection_space_shading.glsl, glints/chermain/light_kernel.glsl).
#include "lobe/lobe.glsl"

// Mass of the unit GGX slope density p(u) = 1 / (pi (1 + |u|^2)^2) (alpha units) in the disk of
// radius r centred at distance d from the peak. The ring integral of p at radius q about the
// disk's centre is 2 q a / (a^2 - b^2)^(3/2), a = 1 + d^2 + q^2, b = 2 d q; with w = q^2 it
// integrates to M = 1/2 + N / (2 S), N = r^2 - 1 - d^2, S = sqrt((r^2 + 1 - d^2)^2 + 4 d^2)
// (d = 0: the GGX slope CDF r^2 / (1 + r^2)). Where N < 0 the sum cancels; there
// M = 2 r^2 / (S (S - N)), from S^2 - N^2 = 4 r^2. M is homogeneous of degree 0 in (1, d, r),
// so it is evaluated in units of m = max(1, d, r), where nothing overflows (a huge light seen by
// a mirror-like lobe has d and r near 1e15 in alpha units).
float ggxDiskMass(float d, float r) {
  float m = max(1.0, max(d, r));
  float dm = d / m, rm = r / m, e = 1.0 / m;
  float r2 = rm * rm, e2 = e * e, d2 = dm * dm;
  float n = r2 - e2 - d2;
  float k = r2 + e2 - d2;
  float s = max(sqrt(k * k + 4.0 * d2 * e2), 1e-30);
  return n >= 0.0 ? (s + n) / (2.0 * s) : 2.0 * r2 * e2 / (s * (s - n));
}

// The light's image in the lobe's slope space. A light whose outline, seen from p, is to first
// order the ellipse lc + dl1 x1 + dl2 x2 about the direction lc to its centre, is seen through
// the half vector h = (wo + l) / |wo + l| as the ellipse centre + J x, |x| <= 1: dh = (I - h h^T) dl / |wo + l| (in-plane changes of l are halved,
// the others scaled by 1 / (2 cos theta_d)), and the slope s = -h.xy / h.z changes by
// ds = -(dh.xy + s dh.z) / h.z (lightImage in lobe/lobe_shading.glsl).
struct LightImage {
  vec2 centre;  // slope of the half vector towards the light's centre
  mat2 J;       // columns: the image's semi-axes (conjugate) in slope space
};
// Fraction of the lobe's slope distribution inside the light's image: the light's radiance
// weighted by the lobe, integrated over the light (the lobe convolved with the light). It tends
// to the mirror's all-or-nothing as the lobe narrows and to P22 x (image area) as the light
// shrinks, and its integral over image positions is the image's area for every lobe (energy).
// Matrix lobes: in the lobe's whitened space (u = A^-1/2 s, where p is isotropic) the image is an
// ellipse c + K x, |x| <= 1, taken as a disk at distance d = |c| from the peak (GGX in closed form,
// ggxDiskMass; Beckmann as the square of equal area, separable erf). Its radius: where the image
// is small against the lobe, that of equal area (|det K|), so the small-light limit is exact;
// where it is large, the ellipse's radius towards the peak (1 / |K^-1 c/|c||), so the edge a
// narrow lobe crosses is the ellipse's own; geometric interpolation by the weight
// 1 / (1 + |det K|) between them, and towards equal area as d -> 0 (where the direction is lost).
// Box lobes (the box average of Kaplanyan et al.'s GGX filter, axis-aligned in alpha units):
// the image as the box of equal area and the aspect of its bounding box, convolved with the
// footprint box; the limits are the box average as the light shrinks and the image's box as the
// footprint vanishes.
float lobeMassOnImage(Lobe lobe, LightImage image) {
  float detJ = abs(determinant(image.J));
  if (lobe.footprint != vec2(0.0)) {
    vec2 alpha = sqrt(vec2(lobe.A[0][0], lobe.A[1][1]));
    mat2 K = mat2(image.J[0] / alpha, image.J[1] / alpha);  // alpha units
    float area = PI * detJ / (alpha.x * alpha.y);
    vec2 extent = sqrt(K[0] * K[0] + K[1] * K[1]) + 1e-20;  // bounding half sides
    vec2 imageHalf = extent * sqrt(0.25 * area / (extent.x * extent.y));
    // The box-averaged density averaged again over the image's box: per axis the larger of the
    // two boxes in closed form, the smaller by 2-point Gauss-Legendre (exact for cubics); a mass,
    // so the tails need no relative precision (boxAveragedSlopeDensity). The
    // convolution of the footprint box with anything normalised keeps its partition of unity
    // over neighbouring pixels, so the image's energy is kept however the boxes compare.
    vec2 b = lobe.footprint / alpha;
    vec2 large = max(b, imageHalf), small = min(b, imageHalf);
    float sum = 0.0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        vec2 offset = small * vec2(i == 0 ? -0.5773503 : 0.5773503, j == 0 ? -0.5773503 : 0.5773503);
        sum += 0.25 * boxAveragedSlopeDensity(lobe.ndf, image.centre + offset * alpha, large * alpha, alpha, false);
      }
    return min(area * sum * alpha.x * alpha.y, 1.0);
  }
  float sqrtDet;
  float d2 = inverseQuadratic(lobe.A, image.centre, sqrtDet);
  float areaR2 = detJ / sqrtDet;  // |det K|
  // Direction from the image's centre to the peak, in whitened space, and K^-1 along it:
  // K = A^-1/2 J, so K^-1 e = J^-1 A^1/2 e with A^1/2 e = -A^1/2 A^-1/2 c / |c| = -s / |A^-1/2 s|.
  vec2 toPeak = -image.centre * inversesqrt(max(d2, 1e-30));
  mat2 adjJ = mat2(image.J[1][1], -image.J[0][1], -image.J[1][0], image.J[0][0]);
  vec2 kInvE = adjJ * toPeak / max(detJ, 1e-30);
  float dirR2 = 1.0 / max(dot(kInvE, kInvE), 1e-30);
  float t = d2 / (1.0 + d2) * (1.0 - 1.0 / (1.0 + areaR2));
  float r = sqrt(areaR2 * exp2(t * (log2(dirR2) - log2(max(areaR2, 1e-30)))));
  if (lobe.ndf == NDF_BECKMANN) {
    float h = 0.886226925 * r;  // sqrt(pi)/2 r: the square of equal area, at (d, 0)
    float d = sqrt(d2);
    return 0.25 * (erfApprox(d + h) - erfApprox(d - h)) * 2.0 * erfApprox(h);
  }
  return ggxDiskMass(sqrt(d2), r);
}
