// A light's half-vector region as a slope-space kernel of the glinty BRDF's filtered lookups
// (docs/methods.md, "Area lights: the light's half-vector region as a slope-space kernel"), the
// `light_extent = half-vector-kernel` choice of `chermain2020` and `chermain2021`: each cell's
// slope distribution averaged over the slopes of the half vectors towards the light, through the
// same dictionary lookups that GGAA filters with its pixel kernel (Chermain et al. 2021, eq. 19).
#include "glints/chermain/shading.glsl"

// Variance of a filtered dictionary lookup along one marginal, per squared kernel length: a texel
// of mip level k averages 2^k texels (a box, variance 4^k / 12) and linear interpolation between
// texels adds a tent of the same half-width (4^k / 6); textureGrad picks k = log2 of the kernel's
// length in texels, so a kernel of length w has variance w^2 / 4 (exact at whole levels, up to
// 25% more between them).
const float GLINT_KERNEL_VARIANCE = 0.25;

// The kernel U = [kernelDx kernelDy] widened by the light's half-vector region. The light's
// outline (conjugate semi-axes dl1, dl2 of the unit direction to its centre) maps to slope space
// through the Jacobian of h = (wo + l) / |wo + l| and s = -h.xy / h.z (lightImage,
// lobe/lobe_shading.glsl): an ellipse of semi-axes a, b, whose uniform density has covariance
// (a a^T + b b^T) / 4. Second moments add under convolution, so the combined kernel has
//   U' U'^T = U U^T + (a a^T + b b^T) / (4 GLINT_KERNEL_VARIANCE),
// factored as U' = C^1/2 R with R the rotation of U's polar decomposition (U = (U U^T)^1/2 R), so
// that U' -> U as the light shrinks. The lookups see only |components|: flipping kernelDy to make
// det U >= 0 changes nothing and makes R a rotation.
void addLightRegionToKernel(Surface s, LightData L, vec3 l, inout vec2 kernelDx, inout vec2 kernelDy) {
  float solidAngle = lightSolidAngle(L, s.position, l);
  vec3 dl1, dl2;
  lightOutline(L, s.position, l, sqrt(min(solidAngle / PI, 1.0)), dl1, dl2);
  LightImage image = lightImage(toLocal(s, s.view), toLocal(s, l), toLocal(s, dl1), toLocal(s, dl2));
  vec2 a = image.J[0], b = image.J[1];

  if (kernelDx.x * kernelDy.y - kernelDx.y * kernelDy.x < 0.0) kernelDy = -kernelDy;
  mat2 c = outerProduct(kernelDx, kernelDx) + outerProduct(kernelDy, kernelDy) +
           (outerProduct(a, a) + outerProduct(b, b)) * (0.25 / GLINT_KERNEL_VARIANCE);
  // C^1/2 = (C + sqrt(det C) I) / sqrt(tr C + 2 sqrt(det C)) for a symmetric 2x2 C >= 0.
  float rootDet = sqrt(max(determinant(c), 0.0));
  mat2 root = (c + mat2(rootDet)) * inversesqrt(max(c[0][0] + c[1][1] + 2.0 * rootDet, 1e-30));
  // R: U's conformal part normalised (the identity when U has none, e.g. chermain2020's U = 0).
  vec2 cs = vec2(kernelDx.x + kernelDy.y, kernelDx.y - kernelDy.x);
  float n2 = dot(cs, cs);
  cs = n2 > 1e-30 ? cs * inversesqrt(n2) : vec2(1.0, 0.0);
  mat2 widened = root * mat2(cs.x, cs.y, -cs.y, cs.x);
  kernelDx = widened[0];
  kernelDy = widened[1];
}
