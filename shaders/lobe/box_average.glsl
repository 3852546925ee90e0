// Slope densities averaged over an axis-aligned slope-space box (Kaplanyan et al. 2016's rectangle
// filter), in closed form where that is accurate and by quadrature where it is not: the box lobes
// of lobe/lobe.glsl and the light images of lobe/light_image.glsl.
#include "core/constants.glsl"
#include "core/erf.glsl"
#include "generated/gpu_contract.glsl"

// Average of a slope density over a slope-space box (Kaplanyan et al. 2016's rectangle filter),
// for axis-aligned A = diag(alpha^2). In units of alpha (u = x / alpha_x, v = y / alpha_y) the
// densities are p(u, v) = 1 / (pi (1 + u^2 + v^2)^2) (GGX) and exp(-u^2 - v^2) / pi (Beckmann).
// Along an axis where the box is at least NARROW_BOX wide the integral is taken in closed form;
// along a narrower axis by 4-point Gauss-Legendre quadrature (exact for degree 7, exact in the
// zero-width limit). The closed forms are differences of O(1) numbers: their float rounding is
// about 1e-7 absolute, so they are used only where the box holds at least TAIL_MASS of the lobe
// (relative error ~1e-4). A box holding less lies in the tails, whatever its width, and is
// integrated by quadrature after substitutions that flatten the tails (ggxTailAverage).
const float NARROW_BOX = 0.5;
const float TAIL_MASS = 1e-3;
const vec4 GL4_NODES = vec4(-0.8611363116, -0.3399810436, 0.3399810436, 0.8611363116);
const vec4 GL4_WEIGHTS = vec4(0.3478548451, 0.6521451549, 0.6521451549, 0.3478548451) * 0.5;  // sum to 1

// GGX in alpha units: mass of p in the quadrant [0,u]x[0,v], odd in each argument, 1/4 at infinity.
float ggxQuadrantMass(float u, float v) {
  float su = sqrt(1.0 + u * u), sv = sqrt(1.0 + v * v);
  return (u / su * atan(v / su) + v / sv * atan(u / sv)) / TWO_PI;
}
// GGX in alpha units: integral of p(u, v) over v in [v0, v1] (d/dv of the bracket is 1/(c^2+v^2)^2).
float ggxStripMass(float u, float v0, float v1) {
  float c2 = 1.0 + u * u, c = sqrt(c2);
  float f1 = v1 / (2.0 * c2 * (c2 + v1 * v1)) + atan(v1 / c) / (2.0 * c2 * c);
  float f0 = v0 / (2.0 * c2 * (c2 + v0 * v0)) + atan(v0 / c) / (2.0 * c2 * c);
  return (f1 - f0) / PI;
}
// (atan(c + h) - atan(c - h)) / (2 h) without cancellation, and its limit 1 / (1 + c^2) at h = 0.
float atanSlope(float c, float h) {
  float q = 1.0 + (c - h) * (c + h);
  return h > 0.0 ? atan(2.0 * h, q) / (2.0 * h) : 1.0 / q;
}

// GGX box average in the tails, by substitutions that make the integrand smooth and bounded:
// the inner axis u = c tan t with c^2 = 1 + v^2 (p du = cos^2 t / (pi c^3) dt), the outer axis
// v = C tan T with C^2 = 1 + u_near^2 (u_near: the box's u closest to the peak), so that the
// marginal of v becomes about cos T / C^2. The outer axis is the one nearer the peak (where the
// density is flattest): 4-point Gauss-Legendre; the inner integral of cos^2 t in closed form.
// Accurate for boxes of any width far from the peak.
float ggxTailAverage(vec2 c, vec2 h) {
  vec2 near = max(abs(c) - h, vec2(0.0));
  bool outerV = near.y <= near.x;
  vec2 co = outerV ? c : c.yx, ho = outerV ? h : h.yx, no = outerV ? near : near.yx;  // x: inner, y: outer
  float C = sqrt(1.0 + no.x * no.x);
  float T0 = atan((co.y - ho.y) / C);
  float outerSlope = atanSlope(co.y / C, ho.y / C) / C;  // (T1 - T0) / (2 h_v)
  float sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    float T = T0 + outerSlope * ho.y * (1.0 + GL4_NODES[i]);
    float v = C * tan(T), cosT = cos(T);
    float cv = sqrt(1.0 + v * v);
    float t0 = atan((co.x - ho.x) / cv);
    float innerSlope = atanSlope(co.x / cv, ho.x / cv) / cv;  // (t1 - t0) / (2 h_u)
    // The mean of cos^2 over [t0, t1] in closed form: 1/2 + cos(t0 + t1) sin(D) / (2 D), D = t1 - t0.
    float span = 2.0 * innerSlope * ho.x;
    float sinc = span > 1e-4 ? sin(span) / span : 1.0 - span * span / 6.0;
    float inner = 0.5 + 0.5 * cos(2.0 * t0 + span) * sinc;
    sum += GL4_WEIGHTS[i] * (C / (cosT * cosT)) * innerSlope * inner / (PI * cv * cv * cv);
  }
  return sum * outerSlope;
}
float ggxDensity(float u, float v) {
  float e = 1.0 + u * u + v * v;
  return 1.0 / (PI * e * e);
}

// Average of p over the box centre c +- half h (alpha units); `relativeTails` as for
// boxAveragedSlopeDensity.
float ggxBoxAverage(vec2 c, vec2 h, const bool relativeTails) {
  bool narrowU = h.x < NARROW_BOX, narrowV = h.y < NARROW_BOX;
  float average = 0.0;
  if (narrowU && narrowV) {
    // Smooth over a box less than an alpha wide: 4x4 Gauss-Legendre on the density.
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        average += GL4_WEIGHTS[i] * GL4_WEIGHTS[j] * ggxDensity(c.x + h.x * GL4_NODES[i], c.y + h.y * GL4_NODES[j]);
    return average;
  }
  if (!narrowU && !narrowV) {
    vec2 lo = c - h, hi = c + h;
    average = (ggxQuadrantMass(hi.x, hi.y) - ggxQuadrantMass(lo.x, hi.y) - ggxQuadrantMass(hi.x, lo.y) +
               ggxQuadrantMass(lo.x, lo.y)) / (4.0 * h.x * h.y);
  } else {
    // Quadrature along the narrow axis, closed form along the wide one (p is symmetric in u, v).
    vec2 cn = narrowU ? c : c.yx, hn = narrowU ? h : h.yx;
    for (int i = 0; i < 4; ++i)
      average += GL4_WEIGHTS[i] * ggxStripMass(cn.x + hn.x * GL4_NODES[i], cn.y - hn.y, cn.y + hn.y);
    average /= 2.0 * hn.y;
  }
  // The box's mass decides, not its average density: a wide box on the peak has a small average.
  return relativeTails && average * 4.0 * h.x * h.y < TAIL_MASS ? ggxTailAverage(c, h) : average;
}

// Beckmann is separable: the average of exp(-u^2) along one axis.
float gaussianAxisAverage(float c, float h) {
  float closed = 0.886226925 * (erfApprox(c + h) - erfApprox(c - h)) / (2.0 * max(h, 1e-30));  // sqrt(pi)/2
  if (h >= NARROW_BOX && 2.0 * h * closed >= TAIL_MASS) return closed;
  vec4 u = c + h * GL4_NODES;
  return dot(GL4_WEIGHTS, exp(-u * u));
}

// atan(x) / x for x >= 0, and its limit 1 at 0.
float atanOverX(float x) { return x > 1e-4 ? atan(x) / x : 1.0 - x * x / 3.0; }

// GGX in alpha units: the average of p over the box of half sides h centred on the peak, the
// quadrant mass over the quadrant's area (ggxQuadrantMass / (h.x h.y)) written so that nothing
// cancels (a sum of positive terms: exact for boxes of any size, 1 / pi as h -> 0).
float ggxPeakBoxAverage(vec2 h) {
  float su2 = 1.0 + h.x * h.x, sv2 = 1.0 + h.y * h.y;
  return (atanOverX(h.y * inversesqrt(su2)) / su2 + atanOverX(h.x * inversesqrt(sv2)) / sv2) / TWO_PI;
}

// `relativeTails` (a constant at every call): whether boxes in the tails need relative precision,
// as a density does (D = P22 / cos^4 magnifies it at grazing half vectors). A mass summed over a
// light's image needs only absolute precision, which the closed forms' ~1e-7 gives everywhere:
// there the GGX tails' quadrature is not compiled (it is a third of the function's work).
float boxAveragedSlopeDensity(int ndf, vec2 centre, vec2 halfSize, vec2 alpha, const bool relativeTails) {
  vec2 c = centre / alpha, h = halfSize / alpha;
  float average = ndf == NDF_BECKMANN ? gaussianAxisAverage(c.x, h.x) * gaussianAxisAverage(c.y, h.y) / PI
                                      : ggxBoxAverage(c, h, relativeTails);
  return max(average, 0.0) / (alpha.x * alpha.y);
}
float boxAveragedSlopeDensity(int ndf, vec2 centre, vec2 halfSize, vec2 alpha) {
  return boxAveragedSlopeDensity(ndf, centre, halfSize, alpha, true);
}

// boxAveragedSlopeDensity of a box centred on the peak (the box lobe's peak density).
float peakBoxAveragedSlopeDensity(int ndf, vec2 halfSize, vec2 alpha) {
  if (ndf == NDF_BECKMANN) return boxAveragedSlopeDensity(ndf, vec2(0.0), halfSize, alpha);
  return ggxPeakBoxAverage(halfSize / alpha) / (alpha.x * alpha.y);
}
