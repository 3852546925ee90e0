#pragma once
// GLSL 4.50 to SPIR-V for OpenGL, in process, by glslang (the Khronos reference front end,
// Debian's glslang-dev): what the driver's own compiler starts from, for counting what a program
// asks of a GPU (shader_stats/shader_statistics.hpp) without one. Loose uniforms get locations and
// bindings assigned, as ARB_gl_spirv requires and glintlab's programs leave to the GL.
#include <cstdint>
#include <string>
#include <vector>

namespace glintlab {

enum class GlslStage { Vertex, Fragment, Compute };

/// SPIR-V words of `text` (a whole GLSL 4.50 stage). Throws RuntimeFailure with glslang's log.
std::vector<std::uint32_t> compile_glsl_to_spirv(const std::string& text, GlslStage stage);

}  // namespace glintlab
