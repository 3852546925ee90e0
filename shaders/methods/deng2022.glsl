// Method `deng2022`: Deng et al. 2022's constant-cost spatio-angular prefiltering, queried in real
// time: the pixel footprint's NDF read from the material's CP-compressed pyramid of NDF images
// (glints/normal-map/prefiltered_ndf.glsl) instead of summed over the map's elements as `yan2016` does.
// Delta lights: a point query at the half vector; lights with extent: a box query over the
// light's half-vector box, by default from its four corners through per-footprint prefix tables
// (`box_queries`). Cost independent of the footprint's size and of the light's; an
// anisotropic footprint is up to `anisotropic_probes` isotropic queries along its major axis
// (glints/normal-map/footprint_probes.glsl). Footprints whose minor axis is finer than the
// pyramid's first level are summed over the map's elements as yan2016 does (the paper's switch,
// sec. 5.1) where that sum costs no more than one of that level's footprints. Other materials are shaded as by
// `conventional` (lights with extent by LTC).
// Descriptor: src/shading/methods/deng2022.cpp; docs/methods.md#deng2022.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#define METHOD_SHADES_ENVIRONMENT   // normal-map-glints by the environment's lobes; others as conventional
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_NORMAL_MAP_GLINTS
// The pyramid's shape compiled in where the parameters fix it (they made the pyramid): 0 where N is
// chosen from sigma_r at precompute (and B with it), read from the header then.
#define PNDF_COMPILED_SHAPE
const int PNDF_FIXED_N = param_ndf_resolution;
const int PNDF_FIXED_B = param_block_size > 0 ? param_block_size : param_ndf_resolution / 4;
const int PNDF_FIXED_RANK = param_rank;
#if !MATERIAL_WANG_TILES  // a Wang-tiled surface's elements are made from its texels (no storage per texel)
#define POSITION_NORMAL_STORED_ELEMENTS  // the fallback's elements, computed once (resource position-normal-elements)
#endif
#include "glints/normal-map/position_normal.glsl"
#include "glints/normal-map/prefiltered_ndf.glsl"
#include "glints/normal-map/footprint_probes.glsl"

// The material's pyramid, read once per pixel: its map's, or on a map of Wang tiles its 16 tiles'
// (sec. 5.5: a footprint's NDF summed over the cells it reaches; glints/normal-map/wang_tile_queries.glsl).
#include "glints/normal-map/wang_tile_queries.glsl"  // (never inside an #if: files expand once, where first included)
#if MATERIAL_WANG_TILES
WangPyramids gPyramid;
void loadPyramid() {
  NormalMapSurface surface = normalMapSurface();
  gPyramid = wangPyramids(uMaterial, surface.tileSize, surface.tiles, surface.seed);
}
float pyramidFirstSigma() { return gPyramid.firstSigma; }
float pyramidDensity(vec2 centre, float sigma, vec2 s) { return wangDensity(gPyramid, centre, sigma, s); }
float pyramidRangeMean(vec2 centre, float sigma, vec2 lo, vec2 hi, bool prefixTables) {
  return wangRangeMean(gPyramid, centre, sigma, lo, hi, prefixTables);
}
#else
PndfHeader gPyramid;
void loadPyramid() { gPyramid = pndfHeader(uMaterial); }
float pyramidFirstSigma() { return pndfFirstSigma(gPyramid); }
float pyramidDensity(vec2 centre, float sigma, vec2 s) { return pndfDensity(gPyramid, centre, sigma, s); }
float pyramidRangeMean(vec2 centre, float sigma, vec2 lo, vec2 hi, bool prefixTables) {
  return pndfRangeMean(gPyramid, centre, sigma, lo, hi, prefixTables);
}
#endif
FootprintProbes gProbes;  // the footprint as isotropic queries of the pyramid (texels of the map)
float gMaskingAlpha;
vec3 gDiffuseNormal;  // the map's filtered normal in the macro frame, for Lambert
// Footprints finer than the pyramid's first level: Yan 2016's sum over the elements, as the paper
// does (sec. 5.1); its loop is empty (count 0) where the pyramid answers. Two elements per texel
// and axis by default, those the pyramid's images are made of (elements_per_texel's default): one
// per texel is 26-83% relative RMSE from the surface at about two texels a pixel (issue 30, item 1).
const int FALLBACK_K = param_small_footprints == SMALL_FOOTPRINTS_YAN2016_K1 ? 1 : 2;
bool gBelowPyramid;
PositionNormalFootprint gElements;
#ifdef METHOD_AS_FOOTPRINT_NDF
#include "glints/normal-map/ndf_sampling.glsl"
#if MATERIAL_WANG_TILES
float pyramidMass(vec2 centre, float sigma) { return wangMass(gPyramid, centre, sigma); }
NdfSample pyramidSample(vec2 centre, float sigma, uint seed, vec2 u) { return wangSample(gPyramid, centre, sigma, seed, u); }
#else
float pyramidMass(vec2 centre, float sigma) { return pndfMass(gPyramid, centre, sigma); }
NdfSample pyramidSample(vec2 centre, float sigma, uint seed, vec2 u) { return pndfSample(gPyramid, centre, sigma, seed, u); }
#endif
float gNdfMass;  // the footprint NDF's mass, the sampler's normaliser
const uint NDF_PROBE_STAGE = 24u;  // the probe's choice: a stage of the sample's seed past pndfSample's (0 .. 17)
float normalGlintsProbesMass();
#endif

float normalGlintsDensity(vec2 s) {
  if (gBelowPyramid) return positionNormalDensity(uNormalMap, gElements, FALLBACK_K, s);
  float sum = 0.0;
  ProbeWeights w = gProbes.weights;
  for (int j = 0; j < gProbes.count; ++j)
    sum += nextProbeWeight(w) * pyramidDensity(probeCentre(gProbes, j), gProbes.sigma, s);
  return sum;
}
float normalGlintsBoxMean(vec2 lo, vec2 hi) {
  if (gBelowPyramid) return positionNormalBoxMean(uNormalMap, gElements, FALLBACK_K, lo, hi);
  float sum = 0.0;
  ProbeWeights w = gProbes.weights;
  for (int j = 0; j < gProbes.count; ++j)
    sum += nextProbeWeight(w) * pyramidRangeMean(probeCentre(gProbes, j), gProbes.sigma, lo, hi,
                                                 param_box_queries == BOX_QUERIES_PREFIX_TABLES);
  return sum;
}
#include "glints/normal-map/shading.glsl"
const int ENVIRONMENT_LOBE_CONES = param_environment_lobe_cones == ENVIRONMENT_LOBE_CONES_THREE ? 3 : 1;
#include "glints/normal-map/environment_lobes.glsl"
// The footprint NDF's queries per pixel beyond one per light, which share the element budget: the
// environment's lobes (the path tracer's footprint material counts its samples instead).
#ifndef NORMAL_GLINTS_EXTRA_QUERIES
#define NORMAL_GLINTS_EXTRA_QUERIES environmentExtraQueries()
#endif

// The pixel footprint's NDF at this point: the pyramid's probes, or the map's elements where the
// footprint is finer than its first level.
void normalGlintsPrepareFootprint(inout Surface s) {
  gDiffuseNormal = normalGlintsMacroFrame(s);
  ivec2 size = normalMapSize();
  mat2 sigmaP = footprintTexelCovariance(s.footprint, size, param_footprint_sigma);
  vec2 centre = fract(s.uv) * vec2(size);
  MaterialData m = materials[uMaterial];
  gMaskingAlpha = normalMapGlintsMaskingAlpha(m);
  loadPyramid();
  float sigma0 = pyramidFirstSigma();
  gProbes = footprintProbes(centre, sigmaP, sigma0, int(param_anisotropic_probes));
  // The switch (sec. 5.1): the pyramid cannot resolve a footprint whose minor axis is finer than
  // sigma_0; such a footprint is summed over the map's elements in its true shape (never shrunk)
  // where that costs no more than a round footprint of sigma_0 does, k^2 (6 sigma_0 + 3)^2 elements
  // (always when its largest axis is under sigma_0), within llvmpipe's loop budget.
  float largest = gProbes.major, smallest = gProbes.minor;
  float side = float(FALLBACK_K) * (6.0 * sigma0 + 3.0), budget = side * side;
  // A box's side is at most 2 k r + 1 elements: every element of a footprint under sigma_0 a side.
  gElements = positionNormalFootprint(centre, sigmaP, size, FALLBACK_K, normalMapGlintsIntrinsicRoughness(m),
                                      positionNormalElementBudget((side + 1.0) * (side + 1.0),
                                                                  NORMAL_GLINTS_EXTRA_QUERIES));
  gBelowPyramid = param_small_footprints != SMALL_FOOTPRINTS_CLAMP &&
                  (largest < sigma0 * sigma0 || (smallest < sigma0 * sigma0 && gElements.boxElements <= budget));
#ifdef POSITION_NORMAL_STORED_ELEMENTS
  gElements.firstElement = positionNormalFirstElement[uMaterial];  // none stored with small_footprints = clamp
#endif
  if (!gBelowPyramid) gElements.cells = ivec2(0);
#ifdef METHOD_AS_FOOTPRINT_NDF
  gNdfMass = gBelowPyramid ? 1.0 : normalGlintsProbesMass();
#endif
}

#ifdef METHOD_AS_FOOTPRINT_NDF
// Importance sampling of the footprint's NDF (sec. 5.2), for the path tracer (`path:deng2022`):
// a probe by its weight times its mass, then that probe's pyramid sampler
// (glints/normal-map/ndf_sampling.glsl), so that the samples' density is the probes' blend that
// normalGlintsDensity evaluates over the blend's mass; below the pyramid, the elements' mixture.
float normalGlintsProbesMass() {
  float sum = 0.0;
  ProbeWeights w = gProbes.weights;
  for (int j = 0; j < gProbes.count; ++j)
    sum += nextProbeWeight(w) * pyramidMass(probeCentre(gProbes, j), gProbes.sigma);
  return sum;
}

float normalGlintsSamplePdf(vec2 s) { return gNdfMass > 0.0 ? normalGlintsDensity(s) / gNdfMass : 0.0; }

NdfSample normalGlintsSampleNdf(uint seed, vec2 u) {
  if (gBelowPyramid) return positionNormalSample(uNormalMap, gElements, FALLBACK_K, seed, u);
  float total = 0.0;
  int chosen = -1;
  ProbeWeights w = gProbes.weights;
  for (int j = 0; j < gProbes.count; ++j) {
    const float m = nextProbeWeight(w) * pyramidMass(probeCentre(gProbes, j), gProbes.sigma);
    if (ndfReservoirTakes(m, total, ndfChoiceUniform(seed, NDF_PROBE_STAGE, uint(j)))) chosen = j;
  }
  if (chosen < 0) return NO_NDF_SAMPLE;
  NdfSample x = pyramidSample(probeCentre(gProbes, chosen), gProbes.sigma, seed, u);
  if (x.pdf > 0.0) x.pdf = normalGlintsSamplePdf(x.s);
  return x.pdf > 0.0 ? x : NO_NDF_SAMPLE;
}
#endif
#endif

#include "glints/normal-map/method_entry_points.glsl"
