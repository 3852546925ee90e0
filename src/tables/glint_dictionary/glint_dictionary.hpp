#pragma once
// The multiscale dictionary of 1D slope marginals of Chermain et al. 2020 (section 4.2; our own
// generator, docs/methods.md#the-glint-dictionary). Marginal k at level l is the density of a
// 1D slope made of 2^l random microfacet slopes mu_i ~ Normal(0, sigma_dict) and their mirror
// images -mu_i, each a Gaussian lobe of standard deviation lobe_sigma:
//
//   P_k,l(s) = 1 / (2 * 2^l) * sum_{i < 2^l} [ G(s; mu_k,i, lobe_sigma) + G(s; -mu_k,i, lobe_sigma) ].
//
// The means are nested: level l uses the first 2^l means of marginal k, so a finer level adds
// facets to a coarser one and glints stay coherent across levels. The last level is close to the
// Gaussian of deviation sigma_dict = alpha_dict / sqrt(2) (the smooth Beckmann marginal).
// Each marginal is even and tabulated for |s| at texel centres s_x = (x + 1/2) / texels * 4 sigma_dict,
// then renormalised so that the table integrates to 1 over the whole line (2 * ds * sum = 1).
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace glintlab {

struct GlintDictionarySettings {
  int marginals = 192;      ///< N: distinct marginal distributions (3 per RGB texel on the GPU)
  int levels = 16;          ///< multiscale levels; level l has 2^l lobe pairs
  int texels = 64;          ///< table resolution over |s| in [0, 4 sigma_dict)
  float alpha = 0.5f;       ///< alpha_dict: Beckmann roughness of the limit (sigma_dict = alpha / sqrt 2)
  float lobe_sigma = 0.02f; ///< standard deviation of one microfacet's lobe, in slope units
  std::uint32_t seed = 1;   ///< of the means (std::mt19937 per marginal, Box-Muller normals)

  [[nodiscard]] float sigma() const;        ///< sigma_dict
  [[nodiscard]] float slope_range() const;  ///< 4 sigma_dict: the tabulated |s| range
  /// Throws InputError naming the bad setting and what is allowed.
  void validate() const;
  bool operator==(const GlintDictionarySettings&) const = default;
};

class GlintDictionary {
 public:
  /// (marginals done, marginals): called after each marginal, one call at a time.
  using ProgressFn = std::function<void(int, int)>;
  /// Generates the tables on every hardware thread. Cached by the table framework
  /// (tables/glint_dictionary_table.cpp), not here.
  static GlintDictionary generate(const GlintDictionarySettings& settings, const ProgressFn& progress = {});
  /// Wraps tables generate() made (e.g. read back from a cache): data() of a dictionary with these
  /// settings. Throws std::invalid_argument if their count does not match the settings.
  static GlintDictionary from_data(const GlintDictionarySettings& settings, std::vector<float> data);
  /// Floats in data(): levels x marginals x texels.
  [[nodiscard]] static std::size_t value_count(const GlintDictionarySettings& settings);

  [[nodiscard]] const GlintDictionarySettings& settings() const { return settings_; }
  /// The means of marginal k (2^(levels-1) of them, nested: level l uses the first 2^l).
  [[nodiscard]] std::vector<float> means(int marginal) const;
  /// The table of marginal k at level l: `texels` densities at the texel centres.
  [[nodiscard]] std::span<const float> table(int level, int marginal) const;
  /// Tabulates level l of a marginal from the given means (what generate() does per table).
  [[nodiscard]] static std::vector<float> tabulate(const GlintDictionarySettings& settings, std::span<const float> means);
  /// Every table, level-major then marginal: table(l, k) starts at (l * marginals + k) * texels.
  [[nodiscard]] std::span<const float> data() const { return data_; }
  /// Moves the tables out (what the cache stores).
  [[nodiscard]] std::vector<float> release() && { return std::move(data_); }

 private:
  explicit GlintDictionary(GlintDictionarySettings settings);
  GlintDictionarySettings settings_;
  std::vector<float> data_;
};

}  // namespace glintlab
