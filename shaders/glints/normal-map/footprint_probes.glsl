// An anisotropic Gaussian footprint N(c, Sigma_p) as a few isotropic ones along its major axis,
// for a pyramid that stores isotropic footprints only (deng2022; docs/methods.md#deng2022).
// Sigma_p = sigma^2 I + v a a^T (a: the major axis, v = lambda_max - sigma^2), so the footprint is an
// isotropic Gaussian of variance sigma^2 convolved with a line Gaussian of variance v along a; the
// line is sampled at M evenly spaced probes with Gaussian weights over +-2 of its deviations, the
// spacing scaled so that the probes' weighted variance is exactly v (the mixture's covariance is
// Sigma_p) and kept at most 2 sigma (sums of Gaussians 2 sigma apart ripple by under 1%). With more
// probes needed than allowed, sigma grows until M probes suffice: the minor axis is then blurred,
// as anisotropic texture filtering does past its limit. sigma is never below the pyramid's first
// level (minSigma). The weights come in order from a recurrence set up once per pixel (no exp per
// probe and light): with z_j = z_0 + j h, w_{j+1} = w_j exp(-z_j h - h^2 / 2), and that ratio
// shrinks by exp(-h^2) a step.

// The probes' weights in order: nextProbeWeight returns w_0, w_1, ... (they sum to 1).
struct ProbeWeights {
  float weight;  // the next probe's
  float ratio;   // the one after it over it
  float shrink;  // the ratio's own factor a step, exp(-h^2)
};

float nextProbeWeight(inout ProbeWeights w) {
  float current = w.weight;
  w.weight *= w.ratio;
  w.ratio *= w.shrink;
  return current;
}

struct FootprintProbes {
  vec2 centre;      // c (texels)
  vec2 step;        // texels from one probe to the next, along the major axis
  float sigma;      // every probe's isotropic sigma (texels)
  float gridStep;   // the probes' spacing in deviations of the weights' Gaussian
  float weightSum;  // of the M weights
  int count;        // M
  ProbeWeights weights;  // the first probe's weight and its recurrence
  float major, minor;    // Sigma_p's eigenvalues (texels^2)
};

const float PROBE_SPAN = 2.0;  // the probes cover +-2 deviations of the line Gaussian

// The M weights' sum and their variance in grid units (z_j = (j - (M - 1) / 2) h).
void probeMoments(int count, float h, out float weightSum, out float variance) {
  weightSum = 0.0;
  float second = 0.0;
  for (int j = 0; j < count; ++j) {
    float z = (float(j) - 0.5 * float(count - 1)) * h;
    float w = exp(-0.5 * z * z);
    weightSum += w;
    second += w * z * z;
  }
  variance = second / weightSum;
}

// maxProbes 1: the isotropic footprint of the same area, sigma^4 = det Sigma_p (deng2022 before probes).
FootprintProbes footprintProbes(vec2 centre, mat2 sigmaP, float minSigma, int maxProbes) {
  FootprintProbes p;
  p.centre = centre;
  p.step = vec2(0.0);
  p.gridStep = 0.0;
  p.weightSum = 1.0;
  p.count = 1;
  float m = 0.5 * (sigmaP[0][0] + sigmaP[1][1]), q = 0.5 * (sigmaP[0][0] - sigmaP[1][1]), b = sigmaP[0][1];
  float r = sqrt(q * q + b * b);
  float major = m + r, minor = max(m - r, 0.0);
  p.major = major;
  p.minor = minor;
  p.weights = ProbeWeights(1.0, 1.0, 1.0);
  if (maxProbes <= 1) {
    p.sigma = max(sqrt(sqrt(major * minor)), minSigma);
    return p;
  }
  p.sigma = max(sqrt(minor), minSigma);
  float line = major - p.sigma * p.sigma;  // v
  if (line <= 1e-4 * major) {  // round enough: one probe of the major axis' sigma
    p.sigma = max(sqrt(major), minSigma);
    return p;
  }
  // The fewest probes whose spacing h sqrt(v / variance) is at most 2 sigma (the weights' variance
  // depends on M: 4 for two probes, about 0.85 beyond).
  float variance = 1.0;
  bool enough = false;
  for (int count = 2; count <= maxProbes && !enough; ++count) {
    p.count = count;
    p.gridStep = 2.0 * PROBE_SPAN / float(count - 1);
    probeMoments(count, p.gridStep, p.weightSum, variance);
    enough = p.gridStep * p.gridStep * line <= 4.0 * p.sigma * p.sigma * variance;
  }
  if (!enough) {
    // Spacing h sqrt(v / variance) = 2 sigma with v = major - sigma^2.
    float c2 = p.gridStep * p.gridStep / variance;
    p.sigma = max(p.sigma, sqrt(c2 * major / (4.0 + c2)));
    line = major - p.sigma * p.sigma;
  }
  vec2 axis = q >= 0.0 ? vec2(r + q, b) : vec2(b, r - q);
  p.step = normalize(axis) * (p.gridStep * sqrt(line / variance));
  float h = p.gridStep, z0 = -0.5 * float(p.count - 1) * h;
  p.weights = ProbeWeights(exp(-0.5 * z0 * z0) / p.weightSum, exp(-z0 * h - 0.5 * h * h), exp(-h * h));
  return p;
}

vec2 probeCentre(FootprintProbes p, int j) { return p.centre + (float(j) - 0.5 * float(p.count - 1)) * p.step; }
