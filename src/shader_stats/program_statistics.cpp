#include "shader_stats/program_statistics.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <cstdio>
#include <thread>

#include "shading/method_list.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/materials/material_kind.hpp"
#include "shading/registry.hpp"

namespace glintlab {

std::string ProgramRow::material_label() const {
  std::string label = all_material_kinds().at(static_cast<std::size_t>(material.kind)).id;
  if (material.normal_map) label += " + normal map";
  if (material.textures) label += ", textured";
  if (material.anisotropic) label += ", anisotropic";
  return label;
}

namespace {

MaterialVariant variant_of(const MaterialKind& kind, bool normal_map) {
  return {kind.code(), normal_map || kind.requires_normal_map, false};
}

}  // namespace

std::vector<ProgramRow> program_rows(ShaderLibrary& shaders, const std::string& methods) {
  std::vector<MethodChoice> choices;
  bool reference = methods.empty();
  if (methods.empty()) {
    for (const MethodDescriptor& m : all_methods()) choices.push_back({&m, resolve_params(m, {}), "", ""});
  } else {
    // The entries other than "reference", as --methods takes them (variants too).
    std::string list;
    for (std::size_t start = 0; start <= methods.size();) {
      const std::size_t end = std::min(methods.find(',', start), methods.size());
      const std::string entry = methods.substr(start, end - start);
      if (entry == "reference") reference = true;
      else list += (list.empty() ? "" : ",") + entry;
      start = end + 1;
    }
    if (!list.empty()) choices = resolve_methods(list, {});
  }
  std::vector<ProgramRow> rows;
  for (const MethodChoice& c : choices) {
    const std::string module = method_program_module(shaders, *c.method, c.params);
    if (c.method->material_kinds.empty()) {
      for (bool normal_map : {false, true})
        rows.push_back({c.display_name(), module, variant_of(default_material_kind(), normal_map)});
    } else {
      for (const std::string& id : c.method->material_kinds)
        rows.push_back({c.display_name(), module, variant_of(find_material_kind(id), false)});
    }
  }
  if (reference)
    for (const MaterialKind& kind : all_material_kinds()) rows.push_back({"(reference)", kReferenceModule, variant_of(kind, false)});
  return rows;
}

LightCounts one_light_of_every_kind() { return LightCounts(all_light_kinds().size(), 1); }

void run_in_parallel(int count, int jobs, const std::function<void(int)>& work) {
  std::atomic<int> next{0};
  std::vector<std::thread> threads;
  std::exception_ptr failure;
  std::mutex failure_mutex;
  for (int t = 0; t < std::max(1, jobs); ++t)
    threads.emplace_back([&] {
      for (int i; (i = next++) < count;) {
        try {
          work(i);
        } catch (...) {
          const std::lock_guard lock(failure_mutex);
          if (!failure) failure = std::current_exception();
        }
      }
    });
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

namespace {

// Each kind's light loop written out (lights/light_loop.glsl): a light's operations are the
// difference of one and two lights even where shadeLight holds a loop.
const ShaderDefines kWrittenOutLightLoops = {{"LIGHT_LOOPS_WRITTEN_OUT", "1"}};

std::string cell(int value) { return std::to_string(value); }

std::string dynamic_arrays_cell(const ShaderStatistics& s) {
  if (s.dynamic_local_arrays.empty()) return "0";
  std::string text = std::to_string(s.dynamic_local_array_accesses()) + ":";
  for (const auto& [array, count] : s.dynamic_local_arrays) text += " " + array + " x" + std::to_string(count) + ";";
  text.pop_back();
  return text;
}

}  // namespace

std::string program_statistics_markdown(ShaderLibrary& shaders, const std::vector<ProgramRow>& rows, int jobs) {
  const auto& kinds = all_light_kinds();
  const std::size_t k_count = kinds.size();
  // The texts first (a library is not shared between threads), then the compiles in parallel.
  // Per row: one and two lights of each kind (software profile), then one of every kind per profile.
  const std::size_t per_row = 2 * k_count + 2;
  std::vector<std::string> texts(rows.size() * per_row);
  const DriverProfile before = shaders.driver_profile();
  for (DriverProfile profile : {DriverProfile::Software, DriverProfile::Hardware}) {
    shaders.set_driver_profile(profile);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const auto text = [&](const LightCounts& lights, const ShaderDefines& extra = {}) {
        return forward_program_text(shaders, rows[r].module, rows[r].material, lights, ProgramStage::Fragment, extra);
      };
      if (profile == DriverProfile::Software)
        for (std::size_t k = 0; k < k_count; ++k)
          for (int n : {1, 2}) {
            LightCounts lights(k_count, 0);
            lights[k] = n;
            texts[r * per_row + 2 * k + static_cast<std::size_t>(n - 1)] = text(lights, kWrittenOutLightLoops);
          }
      texts[r * per_row + 2 * k_count + (profile == DriverProfile::Hardware ? 1 : 0)] = text(one_light_of_every_kind());
    }
  }
  shaders.set_driver_profile(before);
  std::vector<ShaderStatistics> stats(texts.size());
  run_in_parallel(static_cast<int>(texts.size()), jobs, [&](int i) {
    stats[static_cast<std::size_t>(i)] = shader_statistics_of(texts[static_cast<std::size_t>(i)]);
    texts[static_cast<std::size_t>(i)].clear();
  });
  const auto at = [&](std::size_t r, std::size_t slot) -> const ShaderStatistics& { return stats[r * per_row + slot]; };

  std::string kind_header, kind_rule;
  for (const LightKind& k : kinds) kind_header += " " + k.id + " |", kind_rule += " ---: |";
  std::string out;
  out += "### Operations per pixel and per light\n\n"
         "Software profile, every loop with a constant count unrolled and each light loop written out: a light's "
         "cost is the program with two lights of its kind less the program with one; the pixel's, the program "
         "with one point light less one light's cost. A loop with a per-pixel count (the glinty BRDF's cells, "
         "yan2016's texels, the reference's light samples) counts its body once.\n\n| method | material | per pixel |" + kind_header + "\n| --- | --- | ---: |" + kind_rule + "\n";
  const std::size_t point = static_cast<std::size_t>(
      std::find_if(kinds.begin(), kinds.end(), [](const LightKind& k) { return k.id == "point"; }) - kinds.begin());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto per_light = [&](std::size_t k, int ShaderStatistics::*field) {
      return at(r, 2 * k + 1).*field - at(r, 2 * k).*field;
    };
    out += "| " + rows[r].name + " | " + rows[r].material_label() + " | " +
           cell(at(r, 2 * point).operations - per_light(point, &ShaderStatistics::operations)) + " |";
    for (std::size_t k = 0; k < k_count; ++k) out += " " + cell(per_light(k, &ShaderStatistics::operations)) + " |";
    out += "\n";
  }
  for (const auto& [title, field] : {std::pair{"Texture fetches per light", &ShaderStatistics::texture_fetches},
                                     std::pair{"Buffer loads per light", &ShaderStatistics::buffer_loads},
                                     std::pair{"Transcendental functions per light", &ShaderStatistics::transcendentals}}) {
    out += std::string("\n### ") + title + "\n\n| method | material |" + kind_header + "\n| --- | --- |" + kind_rule + "\n";
    for (std::size_t r = 0; r < rows.size(); ++r) {
      out += "| " + rows[r].name + " | " + rows[r].material_label() + " |";
      for (std::size_t k = 0; k < k_count; ++k) out += " " + cell(at(r, 2 * k + 1).*field - at(r, 2 * k).*field) + " |";
      out += "\n";
    }
  }
  out += "\n### One light of every kind, per driver profile\n\n"
         "Operations, loops left and conditional branches of the program with one light of each kind; "
         "accesses into function-local or private arrays whose index is not a constant, by array (local memory "
         "on a GPU).\n\n"
         "| method | material | software ops | loops | branches | dynamic local arrays | hardware ops | loops | "
         "branches | dynamic local arrays |\n| --- | --- | ---: | ---: | ---: | --- | ---: | ---: | ---: | --- |\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out += "| " + rows[r].name + " | " + rows[r].material_label() + " |";
    for (std::size_t p : {0, 1}) {
      const ShaderStatistics& s = at(r, 2 * k_count + p);
      out += " " + cell(s.operations) + " | " + cell(s.loops) + " | " + cell(s.branches) + " | " +
             dynamic_arrays_cell(s) + " |";
    }
    out += "\n";
  }
  return out;
}

}  // namespace glintlab
