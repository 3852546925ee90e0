#include "prefilter/prefilter_params.hpp"

#include <cmath>

namespace glintlab {

namespace {

/// One setting: its parameter (without the default, taken from PrefilterSettings) and its field.
struct PrefilterParam {
  const char* name;
  float min, max;
  const char* description;
  int& (*field)(PrefilterSettings&);
};

const std::vector<PrefilterParam>& prefilter_param_table() {
  static const std::vector<PrefilterParam> table = {
      {"rank", 1.0f, 64.0f, "CP rank of every group's tensor (the paper: 16, 32 for flakes)",
       [](PrefilterSettings& s) -> int& { return s.cp.rank; }},
      {"ndf_resolution", 16.0f, 256.0f, "N: the NDF images are N x N over the map's normals",
       [](PrefilterSettings& s) -> int& { return s.ndf_resolution; }},
      {"block_size", 4.0f, 64.0f,
       "B: angular blocks of B x B pixels, a divisor of ndf_resolution with at most 8 blocks a side",
       [](PrefilterSettings& s) -> int& { return s.block_size; }},
      {"base_footprints", 16.0f, 1024.0f,
       "footprints per side of the finest level (at most the map's size): its sigma and stride are map size / "
       "this texels, so storage does not grow with the map",
       [](PrefilterSettings& s) -> int& { return s.base_footprints; }},
      {"group_footprints", 1.0f, 16.0f,
       "footprints per side of a group: the blocks of group_footprints^2 neighbouring footprints share one tensor",
       [](PrefilterSettings& s) -> int& { return s.group_footprints; }},
      {"elements_per_texel", 1.0f, 2.0f, "Yan 2016's elements per texel and axis behind the NDF images",
       [](PrefilterSettings& s) -> int& { return s.elements_per_texel; }},
  };
  return table;
}

}  // namespace

std::vector<ParamDecl> prefilter_params() {
  std::vector<ParamDecl> params;
  PrefilterSettings defaults;
  for (const PrefilterParam& p : prefilter_param_table()) {
    ParamDecl d{p.name, static_cast<float>(p.field(defaults)), p.min, p.max, p.description};
    d.host_only = true;
    d.integer = true;
    params.push_back(std::move(d));
  }
  return params;
}

PrefilterSettings prefilter_settings_from(const std::map<std::string, float>& params) {
  PrefilterSettings s;
  for (const PrefilterParam& p : prefilter_param_table())
    if (auto it = params.find(p.name); it != params.end()) p.field(s) = static_cast<int>(std::lround(it->second));
  return s;
}

}  // namespace glintlab
