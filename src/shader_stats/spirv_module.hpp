#pragma once
// A SPIR-V module read for inspection: its instructions, and the ids that name types, constants,
// variables and pointers (SPIR-V specification 1.6, sec. 2.3-2.4: a 5-word header, then
// instructions of `word count << 16 | opcode`). Opcodes from Khronos' spirv-headers.
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/spirv.hpp11>

namespace glintlab {

/// Calls visit(offset of the instruction's first word, opcode, word count) for every instruction
/// after the header. Throws RuntimeFailure on a header or a word count that does not fit.
void for_each_instruction(const std::vector<std::uint32_t>& words,
                          const std::function<void(std::size_t, spv::Op, std::size_t)>& visit);

class SpirvModule {
 public:
  explicit SpirvModule(std::vector<std::uint32_t> words);

  struct Instruction {
    spv::Op op;
    std::uint32_t result_type = 0;  ///< 0: none
    std::uint32_t result = 0;       ///< 0: none
    std::vector<std::uint32_t> operands;  ///< the words after the result type and id
  };
  [[nodiscard]] const std::vector<Instruction>& instructions() const { return instructions_; }

  /// A type's description, as GLSL would write it where it can ("float[3]", "vec3", "struct").
  [[nodiscard]] std::string type_name(std::uint32_t type) const;
  [[nodiscard]] bool is_constant(std::uint32_t id) const { return constants_.contains(id); }
  [[nodiscard]] bool is_array_type(std::uint32_t type) const;
  /// The storage class of a pointer id (a variable, or an access chain into one); nullopt-like
  /// spv::StorageClass::Max when `id` is no pointer this module made.
  [[nodiscard]] spv::StorageClass storage_class_of_pointer(std::uint32_t id) const;
  /// The type a pointer id points to (0 if unknown).
  [[nodiscard]] std::uint32_t pointee_type(std::uint32_t id) const;
  /// The variable an access chain (or the variable itself) is rooted in (0 if none).
  [[nodiscard]] std::uint32_t root_variable(std::uint32_t pointer) const;
  /// OpName's name of an id, or "".
  [[nodiscard]] std::string name_of(std::uint32_t id) const;
  /// The type's member at `index` (struct member, array element, vector component, matrix column).
  [[nodiscard]] std::uint32_t member_type(std::uint32_t type, std::uint32_t index_id) const;

 private:
  std::vector<Instruction> instructions_;
  std::map<std::uint32_t, const Instruction*> types_;
  std::set<std::uint32_t> constants_;
  std::map<std::uint32_t, std::uint32_t> constant_values_;  // scalar integer constants
  std::map<std::uint32_t, std::pair<spv::StorageClass, std::uint32_t>> pointer_types_;  // class, pointee
  std::map<std::uint32_t, std::uint32_t> pointer_of_;  // pointer id -> its pointer type
  std::map<std::uint32_t, std::uint32_t> root_of_;     // pointer id -> variable
  std::map<std::uint32_t, std::string> names_;
};

}  // namespace glintlab
