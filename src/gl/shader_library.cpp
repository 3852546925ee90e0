#include "gl/shader_library.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "core/hash.hpp"

namespace glintlab {

const std::map<std::string, std::string_view>& embedded_shaders();  // generated at build time

ShaderLibrary::ShaderLibrary(DriverProfile profile) : profile_(profile) {
  if (const char* dir = std::getenv("GLINTLAB_SHADER_DIR")) directory_ = dir;
}

void ShaderLibrary::set_driver_profile(DriverProfile profile) {
  if (profile != profile_ && !programs_.empty())
    throw std::logic_error("ShaderLibrary::set_driver_profile after programs were linked");
  profile_ = profile;
}

bool ShaderLibrary::exists(const std::string& path) const {
  if (virtual_.contains(path)) return true;
  if (!directory_.empty()) return std::filesystem::is_regular_file(std::filesystem::path(directory_) / path);
  return embedded_shaders().contains(path);
}

std::string ShaderLibrary::source(const std::string& path) const {
  if (auto it = virtual_.find(path); it != virtual_.end()) return it->second;
  if (!directory_.empty()) {
    std::ifstream in(std::filesystem::path(directory_) / path, std::ios::binary);
    if (!in) throw RuntimeFailure("shader '" + path + "' not found in GLINTLAB_SHADER_DIR=" + directory_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  const auto& files = embedded_shaders();
  auto it = files.find(path);
  if (it == files.end()) throw RuntimeFailure("shader '" + path + "' is not part of this build");
  return std::string(it->second);
}

std::vector<std::string> ShaderLibrary::paths() const {
  std::vector<std::string> out;
  if (!directory_.empty()) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(directory_))
      if (e.is_regular_file()) out.push_back(std::filesystem::relative(e.path(), directory_).generic_string());
    std::sort(out.begin(), out.end());
  } else {
    for (const auto& [k, v] : embedded_shaders()) out.push_back(k);
  }
  return out;
}

std::uint64_t ShaderLibrary::sources_hash() const {
  Hasher h;
  for (const auto& p : paths()) {
    h.text(p);
    h.text(source(p));
  }
  return h.digest();
}

void ShaderLibrary::expand_into(const std::string& path, std::string& out, std::vector<std::string>& files,
                                int depth, const ShaderDefines& defines) const {
  if (depth > 32) throw RuntimeFailure("shader includes nested deeper than 32 at '" + path + "'");
  if (std::find(files.begin(), files.end(), path) != files.end()) return;  // each file once
  files.push_back(path);
  const auto index = files.size() - 1;
  std::istringstream in(source(path));
  std::string line;
  int number = 0;
  out += "#line 1 " + std::to_string(index) + "\n";
  while (std::getline(in, line)) {
    ++number;
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
      const auto a = line.find('"', first), b = line.rfind('"');
      if (a == std::string::npos || b <= a)
        throw RuntimeFailure(path + ":" + std::to_string(number) + ": malformed #include");
      std::string include = line.substr(a + 1, b - a - 1);
      if (!include.empty() && include[0] == '$') {  // a module chosen by the caller
        auto it = std::find_if(defines.begin(), defines.end(), [&](const auto& d) { return d.first == include; });
        if (it == defines.end()) throw RuntimeFailure(path + ":" + std::to_string(number) + ": " + include + " is not set");
        include = it->second;
      }
      expand_into(include, out, files, depth + 1, defines);
      out += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
      continue;
    }
    if (first != std::string::npos && line.compare(first, 8, "#version") == 0) {
      out += "\n";  // the library writes the version line
      continue;
    }
    out += line;
    out += '\n';
  }
}

std::string ShaderLibrary::expand(const std::string& path, const ShaderDefines& defines) const {
  std::string body;
  std::vector<std::string> files;
  expand_into(path, body, files, 0, defines);
  std::string out = "#version 450 core\n#define DRIVER_PROFILE " + driver_profile_define_value(profile_) + "\n";
  for (const auto& [k, v] : defines)
    if (!k.starts_with("$")) out += "#define " + k + " " + v + "\n";
  out += "// files: ";
  for (std::size_t i = 0; i < files.size(); ++i) out += std::to_string(i) + "=" + files[i] + " ";
  out += "\n";
  return out + body;
}

namespace {
std::string annotate_log(const std::string& log, const std::string& expanded) {
  // Map "0:LINE" / "FILE:LINE" prefixes back to names using the "// files:" line.
  const auto pos = expanded.find("// files: ");
  std::string table = pos == std::string::npos ? "" : expanded.substr(pos + 10, expanded.find('\n', pos) - pos - 10);
  return log + (table.empty() ? "" : "(file indices: " + table + ")");
}
}  // namespace

GLuint ShaderLibrary::link(const std::string& key, const std::vector<std::pair<GLenum, std::string>>& stages,
                           const ShaderDefines& defines) {
  if (auto it = programs_.find(key); it != programs_.end()) return it->second.id();
  gl::Program program(glCreateProgram());
  std::vector<gl::Shader> shaders;
  for (const auto& [stage, path] : stages) {
    const std::string text = expand(path, defines);
    gl::Shader shader(glCreateShader(stage));
    const char* src = text.c_str();
    glShaderSource(shader.id(), 1, &src, nullptr);
    glCompileShader(shader.id());
    GLint ok = 0;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint len = 0;
      glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &len);
      std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
      glGetShaderInfoLog(shader.id(), len, nullptr, log.data());
      throw RuntimeFailure("cannot compile shader '" + path + "':\n" + annotate_log(log, text));
    }
    glAttachShader(program.id(), shader.id());
    shaders.push_back(std::move(shader));
  }
  glLinkProgram(program.id());
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program.id(), len, nullptr, log.data());
    throw RuntimeFailure("cannot link program " + key + ":\n" + log);
  }
  for (auto& s : shaders) glDetachShader(program.id(), s.id());
  const GLuint id = program.id();
  programs_.emplace(key, std::move(program));
  return id;
}

namespace {
std::string defines_key(const ShaderDefines& defines) {
  std::string k;
  for (const auto& [a, b] : defines) k += a + "=" + b + ";";
  return k;
}
}  // namespace

GLuint ShaderLibrary::graphics(const std::string& vertex, const std::string& fragment, const ShaderDefines& defines) {
  return link(vertex + "|" + fragment + "|" + defines_key(defines),
              {{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, defines);
}

GLuint ShaderLibrary::compute(const std::string& path, const ShaderDefines& defines) {
  return link(path + "|" + defines_key(defines), {{GL_COMPUTE_SHADER, path}}, defines);
}

}  // namespace glintlab
