#include "shader_stats/spirv_module.hpp"

#include <cstring>

#include "core/error.hpp"

namespace glintlab {

void for_each_instruction(const std::vector<std::uint32_t>& words,
                          const std::function<void(std::size_t, spv::Op, std::size_t)>& visit) {
  constexpr std::size_t kHeaderWords = 5;
  if (words.size() < kHeaderWords || words[0] != spv::MagicNumber) throw RuntimeFailure("not a SPIR-V module");
  for (std::size_t at = kHeaderWords; at < words.size();) {
    const std::size_t count = words[at] >> 16;
    if (count == 0 || at + count > words.size()) throw RuntimeFailure("SPIR-V instruction runs past the module");
    visit(at, static_cast<spv::Op>(words[at] & 0xffff), count);
    at += count;
  }
}

SpirvModule::SpirvModule(std::vector<std::uint32_t> words) {
  for_each_instruction(words, [&](std::size_t at, spv::Op op, std::size_t count) {
    bool has_result = false, has_type = false;
    spv::HasResultAndType(op, &has_result, &has_type);
    Instruction in{op};
    std::size_t next = at + 1;
    if (has_type && next < at + count) in.result_type = words[next++];
    if (has_result && next < at + count) in.result = words[next++];
    in.operands.assign(words.begin() + static_cast<std::ptrdiff_t>(next),
                       words.begin() + static_cast<std::ptrdiff_t>(at + count));
    instructions_.push_back(std::move(in));
  });
  for (const Instruction& in : instructions_) {
    switch (in.op) {
      case spv::Op::OpName:
        if (!in.operands.empty()) {
          const auto* bytes = reinterpret_cast<const char*>(in.operands.data() + 1);
          names_[in.operands[0]] = std::string(bytes, strnlen(bytes, 4 * (in.operands.size() - 1)));
        }
        break;
      case spv::Op::OpTypePointer:
        pointer_types_[in.result] = {static_cast<spv::StorageClass>(in.operands.at(0)), in.operands.at(1)};
        types_[in.result] = &in;
        break;
      case spv::Op::OpConstant:
        if (!in.operands.empty()) constant_values_[in.result] = in.operands[0];
        [[fallthrough]];
      case spv::Op::OpConstantTrue:
      case spv::Op::OpConstantFalse:
      case spv::Op::OpConstantComposite:
      case spv::Op::OpConstantNull:
      case spv::Op::OpSpecConstant:
      case spv::Op::OpSpecConstantTrue:
      case spv::Op::OpSpecConstantFalse:
      case spv::Op::OpSpecConstantComposite:
      case spv::Op::OpSpecConstantOp:
        constants_.insert(in.result);
        break;
      case spv::Op::OpVariable:
        pointer_of_[in.result] = in.result_type;
        root_of_[in.result] = in.result;
        break;
      case spv::Op::OpAccessChain:
      case spv::Op::OpInBoundsAccessChain:
      case spv::Op::OpPtrAccessChain:
      case spv::Op::OpInBoundsPtrAccessChain:
        pointer_of_[in.result] = in.result_type;
        if (auto root = root_of_.find(in.operands.at(0)); root != root_of_.end()) root_of_[in.result] = root->second;
        break;
      default:
        if (in.result != 0 && in.result_type == 0) types_[in.result] = &in;  // OpType*
        break;
    }
  }
}

bool SpirvModule::is_array_type(std::uint32_t type) const {
  auto it = types_.find(type);
  return it != types_.end() &&
         (it->second->op == spv::Op::OpTypeArray || it->second->op == spv::Op::OpTypeRuntimeArray);
}

spv::StorageClass SpirvModule::storage_class_of_pointer(std::uint32_t id) const {
  auto p = pointer_of_.find(id);
  if (p == pointer_of_.end()) return spv::StorageClass::Max;
  auto t = pointer_types_.find(p->second);
  return t == pointer_types_.end() ? spv::StorageClass::Max : t->second.first;
}

std::uint32_t SpirvModule::pointee_type(std::uint32_t id) const {
  auto p = pointer_of_.find(id);
  if (p == pointer_of_.end()) return 0;
  auto t = pointer_types_.find(p->second);
  return t == pointer_types_.end() ? 0 : t->second.second;
}

std::uint32_t SpirvModule::root_variable(std::uint32_t pointer) const {
  auto it = root_of_.find(pointer);
  return it == root_of_.end() ? 0 : it->second;
}

std::string SpirvModule::name_of(std::uint32_t id) const {
  auto it = names_.find(id);
  return it == names_.end() ? "" : it->second;
}

std::uint32_t SpirvModule::member_type(std::uint32_t type, std::uint32_t index_id) const {
  auto it = types_.find(type);
  if (it == types_.end()) return 0;
  const Instruction& t = *it->second;
  switch (t.op) {
    case spv::Op::OpTypeArray:
    case spv::Op::OpTypeRuntimeArray:
    case spv::Op::OpTypeVector:
    case spv::Op::OpTypeMatrix:
      return t.operands.at(0);
    case spv::Op::OpTypeStruct: {
      auto value = constant_values_.find(index_id);
      return value != constant_values_.end() && value->second < t.operands.size() ? t.operands[value->second] : 0;
    }
    default:
      return 0;
  }
}

std::string SpirvModule::type_name(std::uint32_t type) const {
  auto it = types_.find(type);
  if (it == types_.end()) return "?";
  const Instruction& t = *it->second;
  auto length_of = [&](std::uint32_t id) {
    auto value = constant_values_.find(id);
    return value == constant_values_.end() ? std::string() : std::to_string(value->second);
  };
  switch (t.op) {
    case spv::Op::OpTypeBool: return "bool";
    case spv::Op::OpTypeInt: return t.operands.at(1) ? "int" : "uint";
    case spv::Op::OpTypeFloat: return "float";
    case spv::Op::OpTypeVector: {
      const std::string element = type_name(t.operands.at(0));
      const std::string prefix = element == "float" ? "" : element == "int" ? "i" : element == "uint" ? "u" : "b";
      return prefix + "vec" + std::to_string(t.operands.at(1));
    }
    case spv::Op::OpTypeMatrix: return "mat" + std::to_string(t.operands.at(1));
    case spv::Op::OpTypeArray: return type_name(t.operands.at(0)) + "[" + length_of(t.operands.at(1)) + "]";
    case spv::Op::OpTypeRuntimeArray: return type_name(t.operands.at(0)) + "[]";
    case spv::Op::OpTypeStruct: {
      const std::string name = name_of(type);
      return name.empty() ? "struct" : name;
    }
    default: return "?";
  }
}

}  // namespace glintlab
