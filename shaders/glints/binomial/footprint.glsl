// The pixel's footprint as Deliot & Belcour 2023 use it (docs/methods.md#deliot2023): the ellipse
// of the uv Jacobian (core/footprint.glsl), its level of detail (cells screen_space_scale pixels
// across its minor axis) and anisotropy, and the four anisotropic grids whose weights interpolate it
// tetrahedrally in (angle, log2 anisotropy, level of detail), so that every grid enters and
// leaves with weight 0 as the footprint changes.
#include "core/random.glsl"
#include "core/constants.glsl"
#include "core/footprint.glsl"

// Anisotropy levels: level j has cells 2^j times longer than wide, at 2^(j+1) angles over 180
// degrees (one unrotated grid at level 0, where the cells are square). Footprints more eccentric
// than 2^BINOMIAL_MAX_LEVEL are widened along their minor axis (pbrt's EWA clamp).
const int BINOMIAL_MAX_LEVEL = 4;

// One grid of cells: short side cellSize along `minor`, long side cellSize * ratio along `major`.
struct BinomialGrid {
  float weight;    // its interpolation weight (the four sum to 1)
  vec2 major;      // unit uv direction of the cells' long side
  float cellSize;  // uv length of their short side, 2^lod
  float ratio;     // 2^level
  uint seed;       // the grid's own random numbers (core/random.glsl)
};

struct BinomialFootprint {
  BinomialGrid grids[4];
};

// The grid of one lattice point: anisotropy level, angle index (any integer: taken modulo
// 2^(level + 1), i.e. 180 degrees, so that the grids at 0 and 180 degrees are one) and lod.
BinomialGrid binomialGrid(int level, int angle, int lod, float weight) {
  int bins = 2 << level;
  int wrapped = angle & (bins - 1);  // bins is a power of 2; & is defined on negative ints
  float theta = level == 0 ? 0.0 : float(wrapped) * PI / float(bins);
  uint seed = pcg4d(uvec4(uint(level), uint(wrapped), uint(lod + 1024), 0x51ed270bu)).x;
  return BinomialGrid(weight, vec2(cos(theta), sin(theta)), exp2(float(lod)), exp2(float(level)), seed);
}

// The (angle, anisotropy) triangle around the footprint: three lattice points (level, angle
// index) in a fixed global order (level, then angle) and their barycentric weights. Band j lies
// between levels j and j + 1, whose angle step is half as long: over one angle cell of level j
// [i, i + 1] at u in [0, 1) it is the fan of triangles (B0, T0, Tm), (B0, Tm, B1), (B1, Tm, T1)
// on B0 = (j, i), B1 = (j, i + 1), T0, Tm, T1 = (j + 1, 2i .. 2i + 2); band 0, whose bottom
// is the single unrotated grid, is the triangle (B, T0, T1).
void anisotropyTriangle(float theta, float level, out ivec2 vertex[3], out vec3 weight) {
  int j = min(int(level), BINOMIAL_MAX_LEVEL - 1);
  float v = level - float(j);
  float cell = theta * float(2 << max(j, 1)) / PI;  // in angle steps of level j (of level 1 in band 0)
  int i = int(floor(cell));
  float u = cell - float(i);
  if (j == 0) {
    vertex = ivec2[3](ivec2(0, 0), ivec2(1, i), ivec2(1, i + 1));
    weight = vec3(1.0 - v, v * (1.0 - u), v * u);
  } else if (u < 0.5 * v) {
    vertex = ivec2[3](ivec2(j, i), ivec2(j + 1, 2 * i), ivec2(j + 1, 2 * i + 1));
    weight = vec3(1.0 - v, v - 2.0 * u, 2.0 * u);
  } else if (u > 1.0 - 0.5 * v) {
    vertex = ivec2[3](ivec2(j, i + 1), ivec2(j + 1, 2 * i + 1), ivec2(j + 1, 2 * i + 2));
    weight = vec3(1.0 - v, 2.0 * (1.0 - u), v - 2.0 * (1.0 - u));
  } else {
    vertex = ivec2[3](ivec2(j, i), ivec2(j, i + 1), ivec2(j + 1, 2 * i + 1));
    weight = vec3(1.0 - u - 0.5 * v, u - 0.5 * v, v);
  }
}

// The grids of a pixel footprint (in the glint uv: footprintInUnits), from its ellipse (majorAxis,
// majorLength, minorLength: J's singular values, core/footprint.glsl). The triangle above times the
// lod interval [floor(lod), floor(lod) + 1] is a prism; its tetrahedron around the footprint
// couples the triangle's weights with the lod's (1 - t, t) monotonically (a staircase: the
// triangle's cumulative weights against the split point 1 - t), which picks four of the prism's
// six grids.
// With the global vertex order, neighbouring prisms agree on their shared faces: continuous.
BinomialFootprint binomialFootprint(Footprint footprint, float screenSpaceScale) {
  vec2 major = footprint.majorAxis;
  float majorLength = footprint.majorLength, minorLength = footprint.minorLength;
  float maxRatio = exp2(float(BINOMIAL_MAX_LEVEL));
  minorLength = max(minorLength, majorLength / maxRatio);
  // Cells screenSpaceScale pixels across the minor axis (the paper halves this: Kneiphof & Klein's
  // fix); clamped so that grid coordinates stay integers in fp32 on any sane uv.
  float lod = clamp(log2(max(minorLength * screenSpaceScale, 1e-30)), -20.0, 30.0);
  float level = minorLength > 0.0 ? clamp(log2(majorLength / minorLength), 0.0, float(BINOMIAL_MAX_LEVEL)) : 0.0;
  float theta = atan(major.y, major.x);
  theta = theta < 0.0 ? theta + PI : theta;  // the axis, not a direction: [0, pi]

  ivec2 vertex[3];
  vec3 w;
  anisotropyTriangle(theta, level, vertex, w);
  int lod0 = int(floor(lod));
  float split = 1.0 - (lod - float(lod0));  // the finer lod's share
  float cumulative[3] = float[3](w.x, w.x + w.y, 1.0);
  int k = cumulative[0] >= split ? 0 : (cumulative[1] >= split ? 1 : 2);  // the vertex split in two
  BinomialFootprint f;
  for (int q = 0; q < 4; ++q) {
    bool fine = q <= k;
    // Grid q is vertex n = q at the finer lod or n = q - 1 at the coarser: two candidates that are
    // constants once the loop is unrolled, chosen by a select, so that no array here is indexed at
    // run time (a GPU would keep vertex[] and cumulative[] in local memory; docs/shader-statistics.md).
    int fineN = q < 2 ? q : 2, coarseN = q > 0 ? q - 1 : 0;
    ivec2 at = fine ? vertex[fineN] : vertex[coarseN];
    float upTo = fine ? cumulative[fineN] : cumulative[coarseN];
    float below = fine ? (fineN > 0 ? cumulative[fineN > 0 ? fineN - 1 : 0] : 0.0)
                       : (coarseN > 0 ? cumulative[coarseN > 0 ? coarseN - 1 : 0] : 0.0);
    float weight = fine ? min(upTo, split) - below : upTo - max(below, split);
    f.grids[q] = binomialGrid(at.x, at.y, fine ? lod0 : lod0 + 1, max(weight, 0.0));
  }
  return f;
}
