#include "shader_stats/shader_statistics.hpp"

#include <spirv/unified1/GLSL.std.450.h>

#include <cstring>

#include "shader_stats/glsl_to_spirv.hpp"
#include "shader_stats/spirv_optimiser.hpp"

namespace glintlab {

namespace {

bool is_bookkeeping(spv::Op op) {
  switch (op) {
    case spv::Op::OpLabel:
    case spv::Op::OpBranch:
    case spv::Op::OpBranchConditional:
    case spv::Op::OpSwitch:
    case spv::Op::OpSelectionMerge:
    case spv::Op::OpLoopMerge:
    case spv::Op::OpPhi:
    case spv::Op::OpVariable:
    case spv::Op::OpFunction:
    case spv::Op::OpFunctionParameter:
    case spv::Op::OpFunctionEnd:
    case spv::Op::OpReturn:
    case spv::Op::OpReturnValue:
    case spv::Op::OpNop:
    case spv::Op::OpLine:
    case spv::Op::OpNoLine:
    case spv::Op::OpUndef:
    case spv::Op::OpUnreachable:
    case spv::Op::OpKill:
      return true;
    default:
      return false;
  }
}

bool is_texture_fetch(spv::Op op) {
  switch (op) {
    case spv::Op::OpImageSampleImplicitLod:
    case spv::Op::OpImageSampleExplicitLod:
    case spv::Op::OpImageSampleDrefImplicitLod:
    case spv::Op::OpImageSampleDrefExplicitLod:
    case spv::Op::OpImageSampleProjImplicitLod:
    case spv::Op::OpImageSampleProjExplicitLod:
    case spv::Op::OpImageFetch:
    case spv::Op::OpImageGather:
    case spv::Op::OpImageDrefGather:
    case spv::Op::OpImageRead:
      return true;
    default:
      return false;
  }
}

bool is_transcendental(std::uint32_t glsl_instruction) {
  switch (glsl_instruction) {
    case GLSLstd450Sin: case GLSLstd450Cos: case GLSLstd450Tan: case GLSLstd450Asin: case GLSLstd450Acos:
    case GLSLstd450Atan: case GLSLstd450Atan2: case GLSLstd450Sinh: case GLSLstd450Cosh: case GLSLstd450Tanh:
    case GLSLstd450Asinh: case GLSLstd450Acosh: case GLSLstd450Atanh: case GLSLstd450Exp: case GLSLstd450Log:
    case GLSLstd450Exp2: case GLSLstd450Log2: case GLSLstd450Pow: case GLSLstd450Sqrt: case GLSLstd450InverseSqrt:
      return true;
    default:
      return false;
  }
}

bool is_local(spv::StorageClass c) { return c == spv::StorageClass::Function || c == spv::StorageClass::Private; }
bool is_buffer(spv::StorageClass c) {
  return c == spv::StorageClass::Uniform || c == spv::StorageClass::StorageBuffer ||
         c == spv::StorageClass::PushConstant;
}

}  // namespace

int ShaderStatistics::dynamic_local_array_accesses() const {
  int sum = 0;
  for (const auto& [array, count] : dynamic_local_arrays) sum += count;
  return sum;
}

ShaderStatistics count_shader_statistics(const SpirvModule& module) {
  ShaderStatistics s;
  std::uint32_t glsl_set = 0;
  bool in_function = false;
  for (const SpirvModule::Instruction& in : module.instructions()) {
    if (in.op == spv::Op::OpExtInstImport) {
      const auto* name = reinterpret_cast<const char*>(in.operands.data());
      if (std::string(name, strnlen(name, 4 * in.operands.size())) == "GLSL.std.450") glsl_set = in.result;
    }
    if (in.op == spv::Op::OpFunction) in_function = true;
    if (in.op == spv::Op::OpFunctionEnd) in_function = false;
    if (!in_function) continue;
    if (in.op == spv::Op::OpBranchConditional || in.op == spv::Op::OpSwitch) ++s.branches;
    if (in.op == spv::Op::OpLoopMerge) ++s.loops;
    if (in.op == spv::Op::OpVectorExtractDynamic || in.op == spv::Op::OpVectorInsertDynamic)
      ++s.dynamically_indexed_vectors;
    if (is_bookkeeping(in.op)) continue;
    ++s.operations;
    if (is_texture_fetch(in.op)) ++s.texture_fetches;
    if (in.op == spv::Op::OpExtInst && in.operands.size() >= 2 && in.operands[0] == glsl_set &&
        is_transcendental(in.operands[1]))
      ++s.transcendentals;
    if (in.op == spv::Op::OpLoad && is_buffer(module.storage_class_of_pointer(in.operands.at(0)))) ++s.buffer_loads;
    const bool chain = in.op == spv::Op::OpAccessChain || in.op == spv::Op::OpInBoundsAccessChain;
    if (!chain || !is_local(module.storage_class_of_pointer(in.operands.at(0)))) continue;
    // Walk the indices from the base's type: an array level indexed by a non-constant is dynamic.
    std::uint32_t type = module.pointee_type(in.operands[0]);
    for (std::size_t i = 1; i < in.operands.size() && type != 0; ++i) {
      const std::uint32_t index = in.operands[i];
      if (module.is_array_type(type) && !module.is_constant(index)) {
        const std::uint32_t root = module.root_variable(in.operands[0]);
        const std::string name = module.name_of(root);
        const bool function = module.storage_class_of_pointer(root) == spv::StorageClass::Function;
        ++s.dynamic_local_arrays[module.type_name(type) + " " +
                                 (name.empty() ? (function ? "(function-local)" : "(private)") : name)];
        break;
      }
      type = module.member_type(type, index);
    }
  }
  return s;
}

ShaderStatistics shader_statistics_of(const std::string& glsl, bool fragment) {
  const auto words = compile_glsl_to_spirv(glsl, fragment ? GlslStage::Fragment : GlslStage::Vertex);
  return count_shader_statistics(SpirvModule(optimise_as_a_driver_would(words)));
}

}  // namespace glintlab
