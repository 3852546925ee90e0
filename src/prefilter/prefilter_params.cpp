#include "prefilter/prefilter_params.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace glintlab {

namespace {

/// One setting: its parameter (without the default, taken from PrefilterSettings) and how it reads
/// and writes the settings (an enumeration's value is its choice's index).
struct PrefilterParam {
  const char* name;
  float min, max;
  const char* description;
  int (*get)(const PrefilterSettings&);
  void (*set)(PrefilterSettings&, int);
  std::vector<std::string> choices = {};
};

// A setting held in one int field of PrefilterSettings.
#define PREFILTER_INT_FIELD(field) \
  [](const PrefilterSettings& s) { return s.field; }, [](PrefilterSettings& s, int v) { s.field = v; }

const std::vector<PrefilterParam>& prefilter_param_table() {
  static const std::vector<PrefilterParam> table = {
      {"rank", 1.0f, 64.0f, "CP rank of every group's tensor (the paper: 16, 32 for flakes)", PREFILTER_INT_FIELD(cp.rank)},
      {"ndf_resolution", 0.0f, 256.0f,
       "N: the NDF images are N x N over the map's normals; 0: from the material's sigma_r, the smallest multiple "
       "of 16 (32 .. 256) whose pixel is at most sigma_r / 2 (pays on sharp anisotropic maps: a third of the "
       "point error on the brushed map for 6x the precompute; docs/results.md)",
       PREFILTER_INT_FIELD(ndf_resolution)},
      {"block_size", 0.0f, 64.0f,
       "B: angular blocks of B x B pixels, a divisor of ndf_resolution with at most 8 blocks a side; 0: N / 4",
       PREFILTER_INT_FIELD(block_size)},
      {"base_stride", 1.0f, 64.0f,
       "texels between the finest level's footprints, and their sigma: fixed whatever the map's size (the paper's "
       "choice), so that the element fallback below it costs the same on any map; storage grows with the map's area",
       PREFILTER_INT_FIELD(base_stride)},
      {"group_footprints", 1.0f, 16.0f,
       "footprints per side of a group: the blocks of group_footprints^2 neighbouring footprints share one tensor",
       PREFILTER_INT_FIELD(group_footprints)},
      {"elements_per_texel", 1.0f, 2.0f, "Yan 2016's elements per texel and axis behind the NDF images",
       PREFILTER_INT_FIELD(elements_per_texel)},
      {"decomposition", 0.0f, 1.0f,
       "how each group's tensor is fitted: hals (nonnegative HALS, at most 200 sweeps, stopping at a change below "
       "1e-4: no value below 0) or als (unconstrained ALS, 500 sweeps as the paper: a lower error, values may dip "
       "below 0 and are clamped by the queries)",
       [](const PrefilterSettings& s) { return s.cp.nonnegative ? 0 : 1; },
       [](PrefilterSettings& s, int v) { s.cp = v == 0 ? PrefilterSettings::kHals : PrefilterSettings::kAls(s.cp.rank, s.cp.restarts); },
       {"hals", "als"}},
      {"cp_restarts", 1.0f, 8.0f, "random starts of each group's fit, the best kept (its time grows with them)",
       PREFILTER_INT_FIELD(cp.restarts)},
  };
  return table;
}

#undef PREFILTER_INT_FIELD

}  // namespace

std::vector<ParamDecl> prefilter_params() {
  std::vector<ParamDecl> params;
  PrefilterSettings defaults;
  for (const PrefilterParam& p : prefilter_param_table()) {
    ParamDecl d{p.name, static_cast<float>(p.get(defaults)), p.min, p.max, p.description, p.choices};
    d.host_only = true;
    d.integer = true;
    // The query's shape: compiled in, so that its loops unroll and its divisions fold.
    const std::string name = p.name;
    d.specialises = name == "rank" || name == "ndf_resolution" || name == "block_size";
    params.push_back(std::move(d));
  }
  return params;
}

PrefilterSettings prefilter_settings_from(const std::map<std::string, float>& params) {
  PrefilterSettings s;
  // The decomposition first: choosing one resets the fit's settings that the others then refine.
  std::vector<const PrefilterParam*> order;
  for (const PrefilterParam& p : prefilter_param_table()) order.push_back(&p);
  std::stable_partition(order.begin(), order.end(), [](const PrefilterParam* p) { return std::string(p->name) == "decomposition"; });
  for (const PrefilterParam* p : order)
    if (auto it = params.find(p->name); it != params.end()) p->set(s, static_cast<int>(std::lround(it->second)));
  return s;
}

}  // namespace glintlab
