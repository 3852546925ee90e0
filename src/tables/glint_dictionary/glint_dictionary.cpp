#include "tables/glint_dictionary/glint_dictionary.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <random>
#include <stdexcept>
#include <thread>

#include "core/error.hpp"

namespace glintlab {
namespace {

// Lobes are summed over +-kLobeReach standard deviations (the rest is below 1e-7 of the peak).
constexpr double kLobeReach = 6.0;

// Adds the even pair of lobes at +-mean (unnormalised Gaussians) to a table over |s|. Texels
// outside |mean| +- reach get nothing from either lobe (the mirror lobe at -|mean| only reaches
// them when |mean| < reach, and then the window starts at 0).
void add_lobe_pair(const GlintDictionarySettings& st, double mean, std::span<double> acc) {
  const double ds = st.slope_range() / st.texels;
  const double inv2s2 = 1.0 / (2.0 * double(st.lobe_sigma) * st.lobe_sigma);
  const double reach = kLobeReach * st.lobe_sigma;
  const double m = std::abs(mean);  // G(s; m) + G(s; -m) depends on |m| only
  const int first = std::max(0, static_cast<int>(std::floor((m - reach) / ds - 0.5)));
  const int last = std::min(st.texels - 1, static_cast<int>(std::ceil((m + reach) / ds - 0.5)));
  for (int x = first; x <= last; ++x) {
    const double s = (x + 0.5) * ds;
    acc[static_cast<std::size_t>(x)] += std::exp(-(s - m) * (s - m) * inv2s2) + std::exp(-(s + m) * (s + m) * inv2s2);
  }
}

// Scales a table so that the even density it tabulates integrates to 1: 2 ds sum = 1.
void normalise(const GlintDictionarySettings& st, std::span<float> table, std::span<const double> acc) {
  double sum = 0.0;
  for (double v : acc) sum += v;
  const double ds = st.slope_range() / st.texels;
  const double scale = sum > 0.0 ? 1.0 / (2.0 * ds * sum) : 0.0;
  for (std::size_t x = 0; x < table.size(); ++x) table[x] = static_cast<float>(acc[x] * scale);
}

std::vector<float> generate_means(const GlintDictionarySettings& st, int marginal) {
  std::seed_seq seq{st.seed, static_cast<std::uint32_t>(marginal), 0x9e3779b9u};
  std::mt19937 rng(seq);
  const std::size_t count = std::size_t{1} << (st.levels - 1);
  std::vector<float> means(count);
  const double to_unit = 1.0 / 4294967296.0;
  for (std::size_t i = 0; i < count; i += 2) {
    // Box-Muller (specified exactly, unlike std::normal_distribution): two normals per draw.
    const double u1 = (static_cast<double>(rng()) + 1.0) * to_unit;  // (0, 1]
    const double u2 = static_cast<double>(rng()) * to_unit;
    const double r = std::sqrt(-2.0 * std::log(u1)) * st.sigma();
    means[i] = static_cast<float>(r * std::cos(2.0 * std::numbers::pi * u2));
    if (i + 1 < count) means[i + 1] = static_cast<float>(r * std::sin(2.0 * std::numbers::pi * u2));
  }
  return means;
}

}  // namespace

float GlintDictionarySettings::sigma() const { return alpha / std::numbers::sqrt2_v<float>; }
float GlintDictionarySettings::slope_range() const { return 4.0f * sigma(); }

void GlintDictionarySettings::validate() const {
  auto fail = [](const std::string& what) { throw InputError("glint dictionary: " + what); };
  if (marginals < 1 || marginals % 3 != 0 || marginals > 3 * 2048)
    fail("marginals " + std::to_string(marginals) + ": allowed: a multiple of 3 (three per RGB texel) up to 6144");
  if (levels < 1 || levels > 20) fail("levels " + std::to_string(levels) + ": allowed: 1 .. 20");
  if (texels < 4 || texels > 4096 || (texels & (texels - 1)))
    fail("texels " + std::to_string(texels) + ": allowed: a power of two in 4 .. 4096 (full mip chains)");
  if (!(alpha > 0.0f && alpha <= 2.0f)) fail("alpha " + std::to_string(alpha) + ": allowed: (0, 2]");
  if (!(lobe_sigma > 0.0f && lobe_sigma <= alpha)) fail("lobe_sigma " + std::to_string(lobe_sigma) + ": allowed: (0, alpha]");
  if (static_cast<long long>(levels) * (marginals / 3) > 2048)
    fail("levels x marginals / 3 = " + std::to_string(levels * (marginals / 3)) +
         " texture layers; allowed: at most 2048 (GL_MAX_ARRAY_TEXTURE_LAYERS guaranteed by OpenGL 4.5)");
}

GlintDictionary::GlintDictionary(GlintDictionarySettings settings) : settings_(settings) {}

std::vector<float> GlintDictionary::means(int marginal) const { return generate_means(settings_, marginal); }

std::span<const float> GlintDictionary::table(int level, int marginal) const {
  const auto offset = (static_cast<std::size_t>(level) * settings_.marginals + marginal) * settings_.texels;
  return std::span<const float>(data_).subspan(offset, static_cast<std::size_t>(settings_.texels));
}

std::vector<float> GlintDictionary::tabulate(const GlintDictionarySettings& settings, std::span<const float> means) {
  std::vector<double> acc(static_cast<std::size_t>(settings.texels), 0.0);
  for (float m : means) add_lobe_pair(settings, m, acc);
  std::vector<float> table(acc.size());
  normalise(settings, table, acc);
  return table;
}

std::size_t GlintDictionary::value_count(const GlintDictionarySettings& settings) {
  return static_cast<std::size_t>(settings.levels) * settings.marginals * settings.texels;
}

GlintDictionary GlintDictionary::from_data(const GlintDictionarySettings& settings, std::vector<float> data) {
  settings.validate();
  if (data.size() != value_count(settings))
    throw std::invalid_argument("glint dictionary: " + std::to_string(data.size()) + " values; the settings need " +
                                std::to_string(value_count(settings)));
  GlintDictionary dict(settings);
  dict.data_ = std::move(data);
  return dict;
}

GlintDictionary GlintDictionary::generate(const GlintDictionarySettings& settings, const ProgressFn& progress) {
  settings.validate();
  GlintDictionary dict(settings);
  const auto texels = static_cast<std::size_t>(settings.texels);
  dict.data_.assign(value_count(settings), 0.0f);

  // One marginal at a time per thread: its means are accumulated once, and level l is a snapshot
  // after the first 2^l of them (the nesting makes the whole pyramid cost one pass).
  auto build = [&](int marginal) {
    const std::vector<float> means = generate_means(settings, marginal);
    std::vector<double> acc(texels, 0.0);
    std::size_t done = 0;
    for (int level = 0; level < settings.levels; ++level) {
      const std::size_t count = std::size_t{1} << level;
      for (; done < count; ++done) add_lobe_pair(settings, means[done], acc);
      const auto offset = (static_cast<std::size_t>(level) * settings.marginals + marginal) * texels;
      normalise(settings, std::span<float>(dict.data_).subspan(offset, texels), acc);
    }
  };
  const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
  std::mutex progress_mutex;
  int marginals_done = 0;
  std::vector<std::jthread> threads;
  for (unsigned w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      for (int k = static_cast<int>(w); k < settings.marginals; k += static_cast<int>(workers)) {
        build(k);
        if (!progress) continue;
        const std::lock_guard lock(progress_mutex);
        progress(++marginals_done, settings.marginals);
      }
    });
  threads.clear();  // joins
  return dict;
}

}  // namespace glintlab
