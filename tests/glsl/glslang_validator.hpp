#pragma once
// GLSL validated by glslang, the Khronos reference front end (Debian's glslang-tools): each stage's
// text as the driver would get it (ShaderLibrary::expand: includes resolved, the variant's
// defines), written to a scratch file and checked by glslangValidator as OpenGL GLSL 4.50. A
// check of the language (types, undeclared names, missing functions, bad layouts), not of one
// driver: the programs tests draw are compiled by the GL driver too. Cheap (tens of milliseconds
// a stage, where llvmpipe spends seconds turning a program into machine code), so tests that
// only ask "does every module compile in every variant" ask it here.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "gl/shader_library.hpp"
#include "scratch_directory.hpp"

namespace glintlab::test {

class GlslangValidator {
 public:
  /// Expects `path` (a .vert, .frag or .comp) with `defines` to be valid; `label` names it in failures.
  void expect_valid(const ShaderLibrary& shaders, const std::string& path, const ShaderDefines& defines,
                    const std::string& label) {
    const std::string stage = std::filesystem::path(path).extension().string();  // ".frag"
    const std::filesystem::path file = scratch_.path() / ("stage" + std::to_string(count_++) + stage);
    std::ofstream(file) << shaders.expand(path, defines);
    const std::filesystem::path log = scratch_.path() / "glslang.log";
    const std::string command = "glslangValidator '" + file.string() + "' >'" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(log);
    std::stringstream output;
    output << in.rdbuf();
    EXPECT_EQ(status, 0) << label << " (" << path << "): glslangValidator says\n" << output.str();
  }
  [[nodiscard]] int count() const { return count_; }
  /// Whether glslangValidator can be run (make test installs it: tools/install-deps.sh).
  static bool available() { return std::system("glslangValidator --version >/dev/null 2>&1") == 0; }

 private:
  ScratchDirectory scratch_;
  int count_ = 0;
};

}  // namespace glintlab::test
