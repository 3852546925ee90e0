#pragma once
// A resource (docs/extending.md, "A resource"): data one unit owns on the GPU, whatever the unit
// is: a method (deng2022's NDF pyramids), a material kind (glinty's glint dictionary), a light kind
// (an environment's maps and CDFs). A unit names the resources it reads by id; each id is one
// ResourceType, which knows what the resource's contents depend on (its key), how large it will be
// (before it is made, for the memory budget) and how to make it (from the disk cache where it has
// one). A scene's ResourceSet makes each one on first use, keeps it while the scene lives and
// binds it before the draws that read it. The precomputed tables (src/tables/registry.cpp) are the
// resources "table:<id>".
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "shading/method.hpp"
#include "tables/table_cache.hpp"

namespace glintlab {

/// What a resource is made from: the scene, the requesting method's parameters (none for a kind's
/// resources) and the disk cache.
struct ResourceContext {
  const Scene& scene;
  const ParamValues& params;
  const TableCache& cache;
};

/// A resident resource.
class GpuResource {
 public:
  virtual ~GpuResource() = default;
  /// Binds it where the shaders read it (its units or buffer bindings: the contract's).
  virtual void bind() const = 0;
  /// Its size on the GPU (host memory, with llvmpipe).
  [[nodiscard]] virtual std::uint64_t gpu_bytes() const = 0;
};

struct ResourceType {
  std::string id;       ///< what units name: "prefiltered-ndf", "table:ltc-ggx"
  std::string title;    ///< one line, for listings and docs
  std::string binding;  ///< where the shaders read it (the contract's names)
  /// What its contents depend on in this context; with the id, the resident resource's identity.
  std::function<std::string(const ResourceContext&)> key;
  /// Its size, known without making it.
  std::function<std::uint64_t(const ResourceContext&)> estimate_bytes;
  /// Makes it (a current GL context is needed); may read and write the disk cache.
  std::function<std::unique_ptr<GpuResource>(const ResourceContext&)> make;
};

/// The resource id of a precomputed table: "table:<id>".
std::string table_resource_id(const std::string& table_id);

/// Every resource type: one per precomputed table, then those of resource_types.cpp's list.
const std::vector<ResourceType>& all_resource_types();
/// Throws InputError for an unknown id, listing the known ones.
const ResourceType& find_resource_type(const std::string& id);

/// The resources every draw of `scene` reads whatever the method: those of its materials' kinds
/// and its lights' kinds (the reference reads these alone). Ids, sorted, each once.
std::vector<std::string> scene_resources(const Scene& scene);
/// The resources `method` reads with `params`: its tables (with those of its chosen choices) and
/// its other resources.
std::vector<std::string> method_resources(const MethodDescriptor& method, const ParamValues& params);

/// The summed estimates of `ids` in `context`.
std::uint64_t estimate_resource_bytes(const std::vector<std::string>& ids, const ResourceContext& context);

}  // namespace glintlab
