#include "shader_stats/glsl_to_spirv.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <mutex>

#include "core/error.hpp"

namespace glintlab {

namespace {

EShLanguage language_of(GlslStage stage) {
  switch (stage) {
    case GlslStage::Vertex: return EShLangVertex;
    case GlslStage::Fragment: return EShLangFragment;
    case GlslStage::Compute: return EShLangCompute;
  }
  return EShLangFragment;
}

/// glslang's process-wide tables, made once (InitializeProcess is not reentrant).
void initialise_glslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

}  // namespace

std::vector<std::uint32_t> compile_glsl_to_spirv(const std::string& text, GlslStage stage) {
  initialise_glslang();
  const EShLanguage language = language_of(stage);
  glslang::TShader shader(language);
  const char* source = text.c_str();
  shader.setStrings(&source, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientOpenGL, 450);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules);
  if (!shader.parse(GetDefaultResources(), 450, ECoreProfile, false, false, messages))
    throw RuntimeFailure(std::string("glslang cannot compile the program:\n") + shader.getInfoLog());
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages) || !program.mapIO())
    throw RuntimeFailure(std::string("glslang cannot link the program:\n") + program.getInfoLog());
  std::vector<std::uint32_t> words;
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // shader_stats/spirv_optimiser.hpp optimises, as a driver would
  glslang::GlslangToSpv(*program.getIntermediate(language), words, &options);
  return words;
}

}  // namespace glintlab
