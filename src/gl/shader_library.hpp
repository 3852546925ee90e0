#pragma once
// GLSL sources by path (relative to shaders/), with #include resolution, #define variants and a
// cache of linked programs. Sources are embedded in the binary; GLINTLAB_SHADER_DIR points the
// library at a source tree instead (for editing shaders without rebuilding). Every program it
// expands is compiled in one driver profile (gl/driver_profile.hpp): the define DRIVER_PROFILE.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gl/driver_profile.hpp"
#include "gl/objects.hpp"

namespace glintlab {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

class ShaderLibrary {
 public:
  explicit ShaderLibrary(DriverProfile profile = DriverProfile::Software);

  /// The profile every program is expanded in; set before the first program is linked (throws
  /// std::logic_error after: the linked programs would be of the other profile).
  void set_driver_profile(DriverProfile profile);
  [[nodiscard]] DriverProfile driver_profile() const { return profile_; }

  /// Adds (or replaces) an in-memory source file, e.g. a test harness; it takes precedence.
  void add_source(const std::string& path, std::string text) { virtual_[path] = std::move(text); }

  /// Raw text of one file; throws RuntimeFailure if there is none.
  [[nodiscard]] std::string source(const std::string& path) const;
  [[nodiscard]] bool exists(const std::string& path) const;
  /// Every path the library knows (sorted).
  [[nodiscard]] std::vector<std::string> paths() const;

  /// Full GLSL 4.50 text of `path` with defines and includes expanded (each file once). A define
  /// whose name starts with '$' is not emitted; it names the file for `#include "$NAME"`. The
  /// library's driver profile comes first, as `#define DRIVER_PROFILE`.
  [[nodiscard]] std::string expand(const std::string& path, const ShaderDefines& defines) const;

  /// Linked program from a vertex and a fragment shader; cached by paths and defines.
  GLuint graphics(const std::string& vertex, const std::string& fragment, const ShaderDefines& defines = {});
  /// Linked compute program; cached by path and defines.
  GLuint compute(const std::string& path, const ShaderDefines& defines = {});

  /// Hash of every source the library holds (part of cache keys of rendered results).
  [[nodiscard]] std::uint64_t sources_hash() const;

 private:
  GLuint link(const std::string& key, const std::vector<std::pair<GLenum, std::string>>& stages,
              const ShaderDefines& defines);
  void expand_into(const std::string& path, std::string& out, std::vector<std::string>& files, int depth,
                   const ShaderDefines& defines) const;

  std::string directory_;  // empty: embedded sources
  DriverProfile profile_;
  std::map<std::string, gl::Program> programs_;
  std::map<std::string, std::string> virtual_;
};

}  // namespace glintlab
