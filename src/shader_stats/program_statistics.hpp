#pragma once
// The static costs of glintlab's forward programs (docs/shader-statistics.md): every method at
// its defaults (and the raster reference) on each material variant it has code of its own for,
// per light kind, in both driver profiles. What `glintlab-shader-stats` prints and its test checks.
#include <functional>
#include <string>
#include <vector>

#include "gl/driver_profile.hpp"
#include "render/program_text.hpp"
#include "shader_stats/shader_statistics.hpp"

namespace glintlab {

/// A shading module in one material variant: a row of the tables.
struct ProgramRow {
  std::string name;    ///< the method's id, or "(reference)"
  std::string module;  ///< its forward module (the method's generated one, or kReferenceModule)
  MaterialVariant material;
  [[nodiscard]] std::string material_label() const;  ///< "binomial-glints", "microfacet + normal map"
};

/// Every method at its defaults on its own material kinds (MethodDescriptor::material_kinds; the
/// default kind with and without a normal map for methods that treat every kind alike), then the
/// reference on every kind. `methods`: a --methods list (variants too; "reference" for the
/// reference's rows), or empty for every method and the reference. Adds the methods' generated
/// modules to `shaders`; throws InputError as resolve_methods does.
std::vector<ProgramRow> program_rows(ShaderLibrary& shaders, const std::string& methods = "");

/// One light of every kind: what the check of dynamically indexed arrays compiles per row.
LightCounts one_light_of_every_kind();

/// Runs `work(i)` for i in [0, count) on `jobs` threads.
void run_in_parallel(int count, int jobs, const std::function<void(int)>& work);

/// The markdown of docs/shader-statistics.md's tables for `rows`: operations per pixel and per
/// light of each kind, texture fetches and transcendentals per light (the software profile:
/// loops unrolled, so a light's cost is the difference between one and two lights of its kind),
/// then each profile's program with one light of every kind (operations, loops, branches, accesses
/// into dynamically indexed local arrays).
std::string program_statistics_markdown(ShaderLibrary& shaders, const std::vector<ProgramRow>& rows, int jobs);

}  // namespace glintlab
