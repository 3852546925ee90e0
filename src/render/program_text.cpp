#include "render/program_text.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "render/shader_contract.hpp"
#include "scene/lights/light_kind.hpp"

namespace glintlab {

namespace {
constexpr int kMaxLightsOfAKind = 64;

std::string kind_ids() {
  std::string ids;
  for (const LightKind& k : all_light_kinds()) ids += (ids.empty() ? "" : ", ") + k.id;
  return ids;
}
}  // namespace

LightRanges light_ranges_of(const LightCounts& counts) {
  LightRanges ranges;
  int next = 0;
  for (int count : counts) {
    ranges.emplace_back(next, next + count);
    next += count;
  }
  return ranges;
}

LightCounts parse_light_counts(const std::string& text, const std::string& flag) {
  const auto& kinds = all_light_kinds();
  LightCounts counts(kinds.size(), 0);
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string entry = text.substr(start, end - start);
    const std::size_t eq = entry.find('=');
    const std::string id = entry.substr(0, eq);
    const auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const LightKind& k) { return k.id == id; });
    if (kind == kinds.end())
      throw InputError(flag + " " + text + ": '" + entry + "' names no light kind; allowed: KIND=COUNT with KIND one of " +
                       kind_ids());
    int count = 1;
    if (eq != std::string::npos) {
      const std::string number = entry.substr(eq + 1);
      const bool digits = !number.empty() && number.size() <= 2 &&
                          std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; });
      count = digits ? std::stoi(number) : -1;
      if (count < 0 || count > kMaxLightsOfAKind)
        throw InputError(flag + " " + text + ": count '" + number + "' of " + id + ": allowed: 0 .. " +
                         std::to_string(kMaxLightsOfAKind));
    }
    counts[static_cast<std::size_t>(kind - kinds.begin())] = count;
    start = end + 1;
  }
  return counts;
}

std::string light_counts_text(const LightCounts& counts) {
  std::string text;
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (counts[k] > 0) text += (text.empty() ? "" : ",") + all_light_kinds()[k].id + "=" + std::to_string(counts[k]);
  return text.empty() ? "none" : text;
}

std::string forward_program_text(const ShaderLibrary& shaders, const std::string& module, MaterialVariant material,
                                 const LightCounts& lights, ProgramStage stage, const ShaderDefines& extra) {
  if (lights.size() != all_light_kinds().size())
    throw std::logic_error("forward_program_text: one light count per kind expected");
  ShaderDefines defines = forward_variant(module, light_ranges_of(lights), material);
  defines.insert(defines.end(), extra.begin(), extra.end());
  return shaders.expand(stage == ProgramStage::Vertex ? "passes/forward.vert" : "passes/forward.frag", defines);
}

std::string exported_program_text(const ShaderLibrary& shaders, const std::string& module, MaterialVariant material,
                                  const LightKind& light, const ShaderDefines& extra) {
  const auto& kinds = all_light_kinds();
  LightCounts counts(kinds.size(), 0);
  for (std::size_t k = 0; k < kinds.size(); ++k)
    if (kinds[k].id == light.id) counts[k] = 1;
  ShaderDefines defines = forward_variant(module, light_ranges_of(counts), material);
  defines.insert(defines.end(), {{"EXPORTED_SHADER", "1"},
                                 {"EXPORTED_LIGHT_KIND", light_code_name(light)},
                                 {"EXPORTED_LIGHT_COMPACT", light.compact ? "1" : "0"}});
  defines.insert(defines.end(), extra.begin(), extra.end());
  return shaders.expand("export/shade_pixel.frag", defines);
}

}  // namespace glintlab
