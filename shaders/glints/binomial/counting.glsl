// The binomial counting model of Deliot & Belcour 2023 (docs/methods.md#deliot2023): of the n
// microfacets a surface cell holds, how many reflect the light, each with probability p. The
// count is drawn as a gate (at least one facet reflects, probability P1) times one plus the
// others that reflect, so that E[count] = n p: what makes E[D_glint] = D(h).

// The models of the others' count given the first are the methods' enumeration `remaining_count`
// (src/shading/methods/shared_params.hpp), REMAINING_COUNT_LOGNORMAL (glintlab: the exact
// conditional mean and variance) and REMAINING_COUNT_GAUSSIAN (the paper: binomial(n - 1, p) as a
// Gaussian, clamped), from the generated contract.
#include "generated/gpu_contract.glsl"

// ln(1 - p) for p in [0, 1): its series below 0.01, where fp32 would round 1 - p (to 1 below
// p ~ 6e-8: the paper's pow(1 - p, n) then loses every facet of a dense surface).
float logOneMinus(float p) {
  return p < 0.01 ? -p * (1.0 + p * (0.5 + p * (1.0 / 3.0 + 0.25 * p))) : log(1.0 - p);
}

// 1 - exp(x) for x <= 0: its series above -0.01, where 1 - exp(x) would cancel to 0.
float oneMinusExp(float x) {
  return x > -0.01 ? -x * (1.0 + x * (0.5 + x * (1.0 / 6.0 + x / 24.0))) : 1.0 - exp(x);
}

// 1 - (1 - p)^n, the probability that at least one of n >= 1 facets reflects, accurate in fp32
// for any p (relative error ~1e-6 where the direct form returns 0 or loses every digit).
float anyOfReflects(float p, float n) {
  return oneMinusExp(n * logOneMinus(clamp(p, 0.0, 0.99999994)));
}

// P1: at least one facet reflects. Below one expected facet (n < 1), a facet is there with
// probability n and reflects with probability p: P1 = p n, continuous with 1 - (1 - p)^n at
// n = 1 (the fix of Kneiphof & Klein's code; the paper's 1 - (1 - p)^n over-counts there).
float probabilityAnyReflects(float p, float n) { return n < 1.0 ? p * n : anyOfReflects(p, n); }

// The paper's gate: the cell reflects when its uniform number u is below P1, as a ramp of
// half-width w around P1 (paper: w = 0.1, narrowed near 0 and 1) so that the count varies
// continuously with P1; the ramp stays inside [0, 1], so E[gate] = P1 exactly.
float reflectionGateHalfWidth(float p1) { return 0.1 * clamp(10.0 * p1, 0.0, 1.0) * clamp(10.0 * (1.0 - p1), 0.0, 1.0); }

float reflectionGate(float p1, float u) {
  float w = reflectionGateHalfWidth(p1);
  return w > 0.0 ? clamp((p1 - u) / (2.0 * w) + 0.5, 0.0, 1.0) : (u < p1 ? 1.0 : 0.0);
}

// E[gate^2] = P1 - w / 3 (the ramp's square integrates to 2w / 3 over its width 2w, where the step
// would give w).
float reflectionGateSecondMoment(float p1) { return p1 - reflectionGateHalfWidth(p1) / 3.0; }

// The P1 whose gate has second moment m2 in [0, 1]: the inverse of reflectionGateSecondMoment, by
// its three pieces (w = P1 below 0.1, 0.1 up to 0.9, 1 - P1 above).
float reflectionGateWithSecondMoment(float m2) {
  return m2 <= 0.2 / 3.0 ? 1.5 * m2 : (m2 <= 2.6 / 3.0 ? m2 + 0.1 / 3.0 : 0.25 * (3.0 * m2 + 1.0));
}

// The law of the facets that reflect besides the first, for n facets of probability p with
// P1 = probabilityAnyReflects(p, n): (the Gaussian's mean, deviation) or (the lognormal's mean,
// the deviation of its logarithm).
//  - REMAINING_COUNT_GAUSSIAN (the paper, with Kneiphof & Klein's fixes): the other n - 1 facets as
//    binomial(n - 1, p) ~ N((n - 1) p, (n - 1) p (1 - p)), clamped to [0, n - 1], not floored.
//    E[count] = P1 (1 + (n - 1) p) + the clamp's bias: 26% over n p at n p = 1.
//  - REMAINING_COUNT_LOGNORMAL: the count given k >= 1 has mean r = n p / P1 and variance
//    r (1 + (n - 1) p - r) (from E[k] = n p, E[k^2] = n p (1 - p) + n^2 p^2); the others, k - 1,
//    as a lognormal of that mean and variance: never negative, so no clamp at 0 biases it.
vec2 remainingLaw(float p, float n, float p1, int model) {
  float others = max(n - 1.0, 0.0);
  if (model == REMAINING_COUNT_GAUSSIAN) return vec2(others * p, sqrt(others * p * (1.0 - p)));
  float r = n * p / max(p1, 1e-37);
  float mean = max(r - 1.0, 0.0);
  float variance = max(r * (1.0 + others * p - r), 0.0);
  // (Below a mean of 1e-12 the others are 0: mean^2 would underflow fp32.)
  float s2 = mean > 1e-12 ? min(log(1.0 + variance / (mean * mean)), 30.0) : 0.0;
  return vec2(mean, sqrt(s2));  // the lognormal's mean and the deviation of its logarithm
}

// The facets that reflect given that one does: 1 + the others, drawn with standard normal g,
// at most n in all.
float countGivenAny(vec2 law, float n, float g, int model) {
  float others = max(n - 1.0, 0.0);
  float k = model == REMAINING_COUNT_GAUSSIAN ? law.x + law.y * g : law.x * exp(law.y * g - 0.5 * law.y * law.y);
  return 1.0 + clamp(k, 0.0, others);
}
