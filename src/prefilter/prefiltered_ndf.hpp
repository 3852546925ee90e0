#pragma once
// Deng et al. 2022's spatio-angular prefiltering of a normal map's NDFs ("Constant-Cost
// Spatio-Angular Prefiltering of Glinty Appearance Using Tensor Decomposition", ACM TOG 2022):
// NDF images of Gaussian footprints on a pyramid of levels (sec. 4.1), cut into angular blocks,
// grouped by position and level, each group's blocks a CP-decomposed 3-way tensor (sec. 4.2,
// eq. 5); point queries (sec. 4.3, eq. 6) and box queries through the angular factors' prefix sums
// (sec. 4.4, eq. 7). The layout below is also the GPU's (src/render/prefiltered_ndf_buffers.cpp,
// shaders/glints/normal-map/prefiltered_ndf.glsl); docs/methods.md#deng2022 explains every choice.
#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "prefilter/cp_decomposition.hpp"
#include "prefilter/ndf_image.hpp"

namespace glintlab {

struct PrefilterSettings {
  int elements_per_texel = 2;      ///< Yan 2016's elements per texel and axis (the NDF images' source)
  int ndf_resolution = 64;         ///< N: an NDF image is N x N; 0: from sigma_r (choose_ndf_grid)
  int block_size = 16;             ///< B: angular blocks of B x B pixels (N / B per side, at most 8); 0: N / 4
  int base_stride = 2;             ///< level 0's footprints lie this many texels apart (and sigma_0 is
                                   ///< this), whatever the map's size (sec. 4.1: a fixed stride)
  int group_footprints = 4;        ///< a group (one tensor) holds up to this squared footprints of a level
  double stop_tolerance = 0.05;    ///< stop adding levels when one differs from the level below by less
                                   ///< (relative L2 of the NDF images)
  int max_levels = 12;
  double empty_block_mass = 1e-5;  ///< a block holding less of the NDF's mass is dropped (stored as 0)
  /// The fit of each group's tensor (the `decomposition` parameter). HALS, the default: every
  /// factor >= 0; stops when the relative error changes by less than 1e-4 in a sweep (1e-5 costs 3x
  /// the time for 0.003 lower error), at most 200 sweeps. ALS: the paper's, unconstrained, 500
  /// sweeps (docs/methods.md#deng2022 compares them).
  static constexpr CpSettings kHals{.rank = 16, .max_iterations = 200, .tolerance = 1e-4};
  static constexpr CpSettings kAls(int rank, int restarts) {
    return {.rank = rank, .max_iterations = 500, .tolerance = 1e-9, .nonnegative = false, .restarts = restarts};
  }
  /// Rank 16 by default (32 for flakes, as in the paper).
  CpSettings cp = kHals;

  /// Every setting as "name=value" separated by spaces: the cache key's and the docs' text.
  [[nodiscard]] std::string describe() const;
  /// Throws InputError naming the setting, its value and what is allowed.
  void validate() const;
};

/// N and B of a map's NDF images over [-extent, extent]^2 at intrinsic roughness sigma_r (issue 30,
/// item 5): the settings' own where set; ndf_resolution 0: the smallest multiple of 16 whose pixel
/// 2 extent / N is at most sigma_r / 2, within 32 .. 256; block_size 0: N / 4 (4 blocks a side, so
/// that a finer grid costs no more per query and stores only longer angular factors).
struct NdfGridChoice {
  int resolution = 0, block_size = 0;
};
[[nodiscard]] NdfGridChoice choose_ndf_grid(const PrefilterSettings& settings, double extent, double sigma_r);

/// Level 0's footprints along a side of `texels` texels: one every base_stride texels (at least one).
[[nodiscard]] inline int base_footprints(int texels, const PrefilterSettings& settings) {
  return texels / settings.base_stride > 0 ? texels / settings.base_stride : 1;
}

/// An upper bound of a pyramid's storage_bytes() for a width x height map under `settings`, known
/// before precomputing it: every level the settings allow, no block dropped; with
/// `box_prefix_tables`, their (N/B)^2 (2R + 1) floats per footprint too (box_prefix_tables.hpp).
std::uint64_t prefiltered_ndf_bytes_bound(const PrefilterSettings& settings, int width, int height,
                                          bool box_prefix_tables = false);

/// The bound above for a pyramid of levels of level_footprints[l] = {nx, ny} footprints.
std::uint64_t pyramid_bytes_bound(const PrefilterSettings& settings,
                                  const std::vector<std::array<std::uint64_t, 2>>& level_footprints,
                                  bool box_prefix_tables);

/// One level of the pyramid: nx x ny footprints of standard deviation sigma texels, centred at
/// origin + ((i + 0.5) spacing.x, (j + 0.5) spacing.y), grouped in groups_x x groups_y tensors.
/// A map's pyramid has origin 0 and its centres tile the map; a Wang tile's (`partial`) reaches
/// past the tile on every side.
struct PrefilterLevel {
  double sigma = 0.0;
  int nx = 0, ny = 0;
  glm::dvec2 spacing{0.0};
  glm::dvec2 origin{0.0};
  int groups_x = 0, groups_y = 0;
  std::uint32_t first_footprint = 0;
  std::uint32_t first_group = 0;
  // What building it measured (not needed to query):
  double distance_to_level_below = 0.0;  ///< mean relative L2 of its NDF images to the level below's
  double compression_error = 0.0;        ///< ||X - X^|| / ||X|| over all of its kept blocks
  std::size_t kept_blocks = 0;
  double ndf_seconds = 0.0, compress_seconds = 0.0;  ///< summed over threads
};

/// Per footprint: which of its (N/B)^2 blocks are kept (bit by * (N/B) + bx), where their rows of
/// the long factor start (in bit order), and its group.
struct FootprintRecord {
  std::uint32_t mask_lo = 0, mask_hi = 0;
  std::uint32_t first_row = 0;
  std::uint32_t group = 0;
};

class PrefilteredNdf {
 public:
  PrefilterSettings settings;
  NdfGrid grid;
  int width = 0, height = 0;         ///< the map's texels
  double intrinsic_roughness = 0.0;
  /// A Wang tile's pyramid (prefilter/wang_tile_pyramids.hpp), not a map's: each footprint's image
  /// sums only the tile's elements, over the weight of the whole surface's (so that the images of
  /// the tiles a footprint reaches add up to the surface's); its centres reach past the tile, the
  /// grid does not wrap, and a footprint off the grid's centres sees none of the tile (0). Wider
  /// than the last level, a footprint is the last level's footprint at the tile's centre scaled by
  /// the share of the footprint's Gaussian that falls on the tile (interpolation()).
  bool partial = false;
  std::vector<PrefilterLevel> levels;
  std::vector<FootprintRecord> footprints;
  /// Per group, the offset into `angular` of its a (B x R), b (B x R) and their exclusive prefix
  /// sums SA, SB ((B + 1) x R each), row-major (pixel, rank).
  std::vector<std::uint32_t> group_offsets;
  std::vector<float> angular;
  std::vector<float> rows;  ///< R floats per kept block: the long factor c, weights included
  double precompute_seconds = 0.0;

  [[nodiscard]] int rank() const { return settings.cp.rank; }
  [[nodiscard]] int blocks_per_side() const { return grid.resolution / settings.block_size; }
  [[nodiscard]] std::size_t storage_bytes() const;

  /// A footprint's group's angular factors: a and b (B x R each) and their exclusive prefix sums SA
  /// and SB ((B + 1) x R each; row B the column's total), row-major (pixel, rank).
  struct AngularFactors {
    const float *a, *b, *sa, *sb;
  };
  [[nodiscard]] AngularFactors angular_factors(std::uint32_t footprint) const;
  /// The R values of the long factor for block `bit` (by * (N/B) + bx) of a footprint, or null
  /// where the block was dropped (it is 0).
  [[nodiscard]] const float* block_factor(std::uint32_t footprint, int bit) const;

  /// The reconstructed NDF image pixel (i, j) of a stored footprint (global index).
  [[nodiscard]] double pixel(std::uint32_t footprint, int i, int j) const;
  [[nodiscard]] NdfImage image(std::uint32_t footprint) const;
  /// The integral of the reconstructed pixels over [x0, x1] x [y0, y1] (continuous pixel
  /// coordinates, inside the image) of a stored footprint, in pixel units (times pixel_area for P's).
  [[nodiscard]] double pixel_range_sum(std::uint32_t footprint, glm::dvec2 x0, glm::dvec2 x1) const;

  /// The stored footprints and weights that stand for a footprint N(centre, sigma^2 I) (texels):
  /// bilinear between the four nearest centres of the two levels around log2(sigma / sigma_0)
  /// (trilinear, sec. 4.1), clamped to the pyramid's first and last level. A partial pyramid's
  /// centres off its grid weigh 0, and past its last level the footprint is that level's at the
  /// tile's centre times tile_share(centre, sigma) / tile_share(tile centre, last sigma).
  struct Weighted {
    std::uint32_t footprint;
    double weight;
  };
  [[nodiscard]] std::vector<Weighted> interpolation(glm::dvec2 centre, double sigma) const;
  /// The share of N(centre, (sigma^2 + the elements' variance) I) that falls on the map's square
  /// [0, width] x [0, height] (a partial pyramid's tile).
  [[nodiscard]] double tile_share(glm::dvec2 centre, double sigma) const;

  /// P(s) of the footprint: pixels bilinearly interpolated (0 outside the image), never negative.
  [[nodiscard]] double density(glm::dvec2 centre, double sigma, glm::dvec2 s) const;
  /// The mean of P over the box [lo, hi] of s (0 outside the image), O(R) per block it overlaps.
  [[nodiscard]] double range_mean(glm::dvec2 centre, double sigma, glm::dvec2 lo, glm::dvec2 hi) const;

  void write(std::ostream& out) const;
  /// Throws RuntimeFailure if the stream (seekable: array sizes are checked against what is left)
  /// does not hold a complete, consistent pyramid (check_consistent()).
  static PrefilteredNdf read(std::istream& in);
  /// Throws RuntimeFailure unless every level, index and value is one a precompute can produce:
  /// levels that follow each other, indices inside their arrays, finite values.
  void check_consistent() const;
};

}  // namespace glintlab
