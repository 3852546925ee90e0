// The glint dictionary generator (src/tables/glint_dictionary/glint_dictionary.hpp): normalisation, evenness,
// nesting of the levels, convergence to the Gaussian, determinism, progress and bad settings.
// Its generation time is a benchmark (benchmarks/bench_tables.cpp); its caching is the table
// framework's (tests/tables).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "tables/glint_dictionary/glint_dictionary.hpp"

namespace glintlab {
namespace {

const GlintDictionary& full_dictionary() {
  static const GlintDictionary dict = GlintDictionary::generate({});
  return dict;
}

TEST(GlintDictionary, TheSameSettingsGiveTheSameTablesBitForBit) {
  // Rendered images depend on every bit of the tables; threads must not change them.
  int calls = 0, last_done = 0, last_total = 0;
  const GlintDictionary dict = GlintDictionary::generate({}, [&](int done, int total) {
    ++calls;
    EXPECT_EQ(done, last_done + 1) << "one call per marginal, in order";
    last_done = done;
    last_total = total;
  });
  EXPECT_EQ(dict.data().size(), std::size_t{16} * 192 * 64);
  EXPECT_EQ(dict.data().size(), GlintDictionary::value_count(dict.settings()));
  EXPECT_TRUE(std::ranges::equal(dict.data(), full_dictionary().data())) << "the same settings must give the same tables";
  EXPECT_EQ(calls, 192);
  EXPECT_EQ(last_total, 192);
}

TEST(GlintDictionary, WrapsTablesReadBackAndRejectsAWrongCount) {
  const auto& st = full_dictionary().settings();
  const auto data = full_dictionary().data();
  const GlintDictionary copy = GlintDictionary::from_data(st, std::vector<float>(data.begin(), data.end()));
  EXPECT_TRUE(std::ranges::equal(copy.table(3, 17), full_dictionary().table(3, 17)));
  EXPECT_THROW(GlintDictionary::from_data(st, std::vector<float>(data.begin(), data.end() - 1)), std::invalid_argument);
}

// Integral over the whole line of the even density the table holds, with linear interpolation
// between texel centres (what the GPU's filtering reads) and the value held flat in the half
// texels at both ends of [0, 4 sigma).
double integral(const GlintDictionarySettings& st, std::span<const float> table) {
  const double ds = st.slope_range() / st.texels;
  double sum = 0.5 * ds * (table.front() + table.back());
  for (std::size_t x = 0; x + 1 < table.size(); ++x) sum += 0.5 * ds * (table[x] + table[x + 1]);
  return 2.0 * sum;
}

TEST(GlintDictionary, EveryMarginalAtEveryLevelIntegratesToOne) {
  const auto& dict = full_dictionary();
  const auto& st = dict.settings();
  double worst = 0.0;
  for (int level = 0; level < st.levels; ++level)
    for (int k = 0; k < st.marginals; ++k) worst = std::max(worst, std::abs(integral(st, dict.table(level, k)) - 1.0));
  EXPECT_LT(worst, 0.005);
}

TEST(GlintDictionary, LevelsAreNestedSubsetsOfTheFinestLevelsMeans) {
  const auto& dict = full_dictionary();
  const auto& st = dict.settings();
  for (int k : {0, 17, 191}) {
    const std::vector<float> means = dict.means(k);
    ASSERT_EQ(means.size(), std::size_t{1} << (st.levels - 1));
    for (int level : {0, 3, 9, 15}) {
      const auto first = std::span<const float>(means).first(std::size_t{1} << level);
      const std::vector<float> expected = GlintDictionary::tabulate(st, first);
      const auto table = dict.table(level, k);
      for (int x = 0; x < st.texels; ++x)
        ASSERT_NEAR(table[static_cast<std::size_t>(x)], expected[static_cast<std::size_t>(x)], 1e-5f * (1.0f + expected[static_cast<std::size_t>(x)]))
            << "marginal " << k << " level " << level << " texel " << x;
      // ...and a different subset does not give the same table (the test can fail).
      if (level >= 3 && level < st.levels - 1) {  // level 15 holds every mean
        const std::vector<float> other = GlintDictionary::tabulate(st, std::span<const float>(means).last(first.size()));
        double diff = 0.0;
        for (int x = 0; x < st.texels; ++x) diff += std::abs(other[static_cast<std::size_t>(x)] - table[static_cast<std::size_t>(x)]);
        EXPECT_GT(diff, 1e-3) << "level " << level;
      }
    }
  }
}

TEST(GlintDictionary, MarginalsAreEvenSumsOfLobesAtTheMeans) {
  // One mean m: the table is G(s; m) + G(s; -m) normalised, so it peaks at the texel nearest |m|
  // and the density at s equals that at -s by construction of a table over |s|; check the peak
  // and that the first level holds two lobes of the right width.
  GlintDictionarySettings st;
  const float m = 0.5f;
  const std::vector<float> t = GlintDictionary::tabulate(st, std::vector<float>{m});
  const double ds = st.slope_range() / st.texels;
  const auto peak = std::max_element(t.begin(), t.end()) - t.begin();
  EXPECT_NEAR((static_cast<double>(peak) + 0.5) * ds, m, ds);
  // The peak of a normalised pair of Gaussians of deviation sigma_lobe is 1 / (2 sqrt(2 pi) sigma_lobe).
  const double expected_peak = 1.0 / (2.0 * std::sqrt(2.0 * std::numbers::pi) * st.lobe_sigma);
  EXPECT_NEAR(*std::max_element(t.begin(), t.end()), expected_peak, 0.15 * expected_peak);
  EXPECT_NEAR(t.front(), 0.0f, 1e-6f) << "no mass near 0 from lobes at +-0.5";
  const std::vector<float> mirrored = GlintDictionary::tabulate(st, std::vector<float>{-m});
  EXPECT_EQ(t, mirrored) << "a mean and its mirror image give one even marginal";
}

TEST(GlintDictionary, TheFinestLevelApproachesTheDictionarysGaussian) {
  const auto& dict = full_dictionary();
  const auto& st = dict.settings();
  const double ds = st.slope_range() / st.texels;
  const double sigma = std::sqrt(st.sigma() * st.sigma() + st.lobe_sigma * st.lobe_sigma);
  double average_error = 0.0;
  for (int k = 0; k < st.marginals; ++k) {
    const auto table = dict.table(st.levels - 1, k);
    for (int x = 0; x < st.texels; ++x) {
      const double s = (x + 0.5) * ds;
      const double gauss = std::exp(-s * s / (2 * sigma * sigma)) / (std::sqrt(2 * std::numbers::pi) * sigma);
      average_error += std::abs(table[static_cast<std::size_t>(x)] - gauss) * ds * 2.0;
    }
  }
  average_error /= st.marginals;
  EXPECT_LT(average_error, 0.02) << "L1 distance to the Gaussian, averaged over the marginals";
  // The coarsest level is far from it (two lobes).
  const auto coarse = dict.table(0, 0);
  EXPECT_GT(*std::max_element(coarse.begin(), coarse.end()), 5.0f);
}

TEST(GlintDictionary, BadSettingsNameTheSettingAndWhatIsAllowed) {
  GlintDictionarySettings st;
  st.texels = 48;
  try {
    st.validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("texels 48"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("power of two"), std::string::npos) << e.what();
  }
  st = {};
  st.marginals = 100;
  EXPECT_THROW(st.validate(), InputError);
  st = {};
  st.levels = 40;
  EXPECT_THROW(st.validate(), InputError);
}

}  // namespace
}  // namespace glintlab
