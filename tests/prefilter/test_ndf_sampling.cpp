// The NDF samplers of deng2022 and yan2016 (src/prefilter/ndf_sampling.hpp): chi-square tests of
// their samples against the densities their methods evaluate, the pdf integrating to 1, and a
// histogram that the test can tell from a wrong density.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <sstream>

#include "chi_square.hpp"
#include "prefilter/ndf_precompute.hpp"
#include "prefilter/ndf_sampling.hpp"

namespace glintlab {
namespace {

using test::chi_square;

constexpr int kSamples = 50000;

const NormalMap& bumps() {
  static const NormalMap map = generate_bumps(32, 0.3f, 48, 6, 17);
  return map;
}

const PrefilteredNdf& pyramid() {
  static const PrefilteredNdf p = [] {
    PrefilterSettings s;
    s.ndf_resolution = 32;
    s.block_size = 8;
    s.base_stride = 1;
    return precompute_prefiltered_ndf(bumps(), 0.03, s);
  }();
  return p;
}

// Bins: the cells between the NDF image's pixel centres, (N + 1)^2 of them over the square widened
// by half a pixel, where the pyramid's density is bilinear, so that its value at a cell's centre
// times the cell's area is the cell's exact integral.
struct DualCells {
  const NdfGrid& grid;
  [[nodiscard]] int side() const { return grid.resolution + 1; }
  [[nodiscard]] int index(glm::dvec2 s) const {
    const glm::dvec2 x = grid.to_pixels(s) + 0.5;
    const int i = static_cast<int>(std::floor(x.x)), j = static_cast<int>(std::floor(x.y));
    return i < 0 || j < 0 || i >= side() || j >= side() ? -1 : j * side() + i;
  }
  [[nodiscard]] glm::dvec2 centre(int cell) const {
    return glm::dvec2(cell % side(), cell / side()) * grid.pixel_size() - grid.extent;
  }
};

TEST(NdfSampling, PrefilteredNdfSamplesFollowTheBilinearDensityItEvaluates) {
  const PrefilteredNdf& p = pyramid();
  const DualCells cells{p.grid};
  const double area = p.grid.pixel_area();
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // Between stored footprints and between levels (8 footprints blended), and on a level's own.
  for (const auto& [centre, sigma] : {std::pair{glm::dvec2(11.3, 20.6), 1.7}, {glm::dvec2(4.5, 4.5), 2.0}}) {
    std::vector<double> observed(static_cast<std::size_t>(cells.side() * cells.side()), 0.0), expected(observed.size());
    int outside = 0;
    for (int i = 0; i < kSamples; ++i) {
      const auto sample = sample_prefiltered_ndf(p, centre, sigma, {u(rng), u(rng), u(rng)});
      ASSERT_TRUE(sample.has_value());
      ASSERT_NEAR(sample->pdf, prefiltered_ndf_pdf(p, centre, sigma, sample->s), 1e-12 * sample->pdf);
      const int cell = cells.index(sample->s);
      if (cell < 0) {
        ++outside;
        continue;
      }
      observed[static_cast<std::size_t>(cell)] += 1;
    }
    double integral = 0.0;
    for (std::size_t c = 0; c < expected.size(); ++c) {
      const double pdf = prefiltered_ndf_pdf(p, centre, sigma, cells.centre(static_cast<int>(c)));
      integral += pdf * area;
      expected[c] = pdf * area * kSamples;
    }
    const auto chi = chi_square(observed, expected);
    std::printf("deng2022 sampler at sigma %.2f: %s, pdf integral %.9f\n", sigma, (std::ostringstream() << chi).str().c_str(),
                integral);
    EXPECT_EQ(outside, 0) << "samples beyond half a pixel outside the square";
    EXPECT_NEAR(integral, 1.0, 1e-6);  // the factors are float
    EXPECT_TRUE(chi.passes(3)) << chi;
    // The same histogram against the density of a footprint twice as wide: told apart.
    std::vector<double> wrong(expected.size());
    for (std::size_t c = 0; c < wrong.size(); ++c)
      wrong[c] = prefiltered_ndf_pdf(p, centre, 2.0 * sigma, cells.centre(static_cast<int>(c))) * area * kSamples;
    EXPECT_LT(chi_square(observed, wrong).p, 1e-6);
  }
}

TEST(NdfSampling, PositionNormalSamplesFollowTheElementMixture) {
  const PositionNormalDistribution pnd(bumps(), 0.03, 2);
  const Footprint footprint{{9.2, 17.7}, glm::dmat2(4.0, 1.5, 1.5, 2.0)};
  const NdfGrid grid{24, pnd.suggested_extent()};
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> observed(grid.pixel_count(), 0.0), expected(grid.pixel_count());
  double outside_expected = kSamples, outside = 0;
  for (int i = 0; i < kSamples; ++i) {
    const auto sample = sample_position_normal(pnd, footprint, {u(rng), u(rng), u(rng)});
    ASSERT_TRUE(sample.has_value());
    ASSERT_NEAR(sample->pdf, pnd.density(footprint, sample->s), 1e-12 * sample->pdf);
    const glm::dvec2 x = grid.to_pixels(sample->s);
    const int ix = static_cast<int>(std::floor(x.x)), iy = static_cast<int>(std::floor(x.y));
    if (ix < 0 || iy < 0 || ix >= grid.resolution || iy >= grid.resolution) {
      ++outside;
      continue;
    }
    observed[static_cast<std::size_t>(iy * grid.resolution + ix)] += 1;
  }
  for (int j = 0; j < grid.resolution; ++j)
    for (int i = 0; i < grid.resolution; ++i) {
      const glm::dvec2 lo = grid.pixel_centre(i, j) - 0.5 * grid.pixel_size(), hi = lo + grid.pixel_size();
      const double e = pnd.range_mean(footprint, lo, hi) * grid.pixel_area() * kSamples;
      expected[static_cast<std::size_t>(j * grid.resolution + i)] = e;
      outside_expected -= e;
    }
  observed.push_back(outside);
  expected.push_back(std::max(outside_expected, 0.0));
  const auto chi = chi_square(observed, expected);
  std::printf("yan2016 sampler: %s\n", (std::ostringstream() << chi).str().c_str());
  EXPECT_TRUE(chi.passes(3)) << chi;
}

}  // namespace
}  // namespace glintlab
