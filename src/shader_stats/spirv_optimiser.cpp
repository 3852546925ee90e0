#include "shader_stats/spirv_optimiser.hpp"

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/spirv.hpp11>
#include <spirv-tools/optimizer.hpp>

#include <string>

#include "core/error.hpp"
#include "shader_stats/spirv_module.hpp"

namespace glintlab {

namespace {

std::vector<std::uint32_t> run(spvtools::Optimizer& optimizer, const std::vector<std::uint32_t>& words, const char* what) {
  std::string messages;
  optimizer.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* text) {
    if (level <= SPV_MSG_ERROR) messages += std::string(text) + "\n";
  });
  std::vector<std::uint32_t> out;
  if (!optimizer.Run(words.data(), words.size(), &out))
    throw RuntimeFailure(std::string("SPIRV-Tools could not ") + what + ":\n" + messages);
  return out;
}

}  // namespace

int mark_loops_for_unrolling(std::vector<std::uint32_t>& words) {
  int marked = 0;
  for_each_instruction(words, [&](std::size_t at, spv::Op op, std::size_t) {
    if (op != spv::Op::OpLoopMerge) return;
    // Operands: merge block, continue target, loop control mask (then its parameters).
    std::uint32_t& control = words[at + 3];
    control = (control | static_cast<std::uint32_t>(spv::LoopControlMask::Unroll)) &
              ~static_cast<std::uint32_t>(spv::LoopControlMask::DontUnroll);
    ++marked;
  });
  return marked;
}

std::vector<std::uint32_t> optimise_as_a_driver_would(const std::vector<std::uint32_t>& words) {
  // Optimised first: inlined and in SSA form, loop bounds that are constants become literals, so
  // that the unroller sees their trip counts.
  spvtools::Optimizer first(SPV_ENV_OPENGL_4_5);
  first.RegisterPerformancePasses();
  std::vector<std::uint32_t> optimised = run(first, words, "optimise the program");
  mark_loops_for_unrolling(optimised);
  // Then unrolled, and what unrolling made constant folded (indices, branches on them) and the
  // dead code dropped: the full passes again would fold a little more at several times the cost.
  spvtools::Optimizer second(SPV_ENV_OPENGL_4_5);
  second.RegisterPass(spvtools::CreateLoopUnrollPass(/*fully_unroll=*/true))
      .RegisterPass(spvtools::CreateCCPPass())
      .RegisterPass(spvtools::CreateSimplificationPass())
      .RegisterPass(spvtools::CreateAggressiveDCEPass());
  return run(second, optimised, "unroll the program's loops");
}

}  // namespace glintlab
