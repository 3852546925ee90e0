#include "export/texture_file.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>

#include "core/error.hpp"

namespace glintlab {

namespace {

std::uint32_t level_extent(std::uint32_t base, int level) { return std::max<std::uint32_t>(1, base >> level); }

// Texels of `level`: array layers keep their count; a 1D array's layers are its rows.
std::size_t level_texels(const TextureFileHeader& h, int level) {
  const bool rows_are_layers = h.target == GL_TEXTURE_1D_ARRAY;
  const bool layered = h.target == GL_TEXTURE_2D_ARRAY || h.target == GL_TEXTURE_CUBE_MAP_ARRAY;
  const std::size_t w = level_extent(h.width, level);
  const std::size_t rows = rows_are_layers ? h.height : level_extent(h.height, level);
  const std::size_t d = layered ? h.depth : level_extent(h.depth, level);
  return w * rows * d;
}

GLint parameter(GLuint texture, GLenum name) {
  GLint value = 0;
  glGetTextureParameteriv(texture, name, &value);
  return value;
}

}  // namespace

TextureFile read_texture(GLuint texture) {
  TextureFile t;
  TextureFileHeader& h = t.header;
  h.target = static_cast<std::uint32_t>(parameter(texture, GL_TEXTURE_TARGET));
  GLint value = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &value);
  h.internal_format = static_cast<std::uint32_t>(value);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &value);
  h.width = static_cast<std::uint32_t>(value);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &value);
  h.height = static_cast<std::uint32_t>(value);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &value);
  h.depth = static_cast<std::uint32_t>(value);
  // The levels the texture holds: its immutable count, or those with texels.
  GLint levels = parameter(texture, GL_TEXTURE_IMMUTABLE_LEVELS);
  if (levels <= 0) {
    levels = 0;
    for (GLint w = 1; levels < 32; ++levels) {
      glGetTextureLevelParameteriv(texture, levels, GL_TEXTURE_WIDTH, &w);
      if (w == 0) break;
    }
  }
  h.levels = static_cast<std::uint32_t>(levels);
  h.min_filter = static_cast<std::uint32_t>(parameter(texture, GL_TEXTURE_MIN_FILTER));
  h.mag_filter = static_cast<std::uint32_t>(parameter(texture, GL_TEXTURE_MAG_FILTER));
  h.wrap_s = static_cast<std::uint32_t>(parameter(texture, GL_TEXTURE_WRAP_S));
  h.wrap_t = static_cast<std::uint32_t>(parameter(texture, GL_TEXTURE_WRAP_T));
  for (int level = 0; level < levels; ++level) {
    std::vector<float>& texels = t.levels.emplace_back(level_texels(h, level) * 4);
    glGetTextureImage(texture, level, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)),
                      texels.data());
  }
  if (glGetError() != GL_NO_ERROR) throw RuntimeFailure("reading a table's texture back from the GL failed");
  return t;
}

void write_texture_file(const std::filesystem::path& path, const TextureFile& texture) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(&texture.header), sizeof texture.header);
  for (const auto& level : texture.levels)
    out.write(reinterpret_cast<const char*>(level.data()), static_cast<std::streamsize>(level.size() * sizeof(float)));
  if (!out) throw RuntimeFailure(path.string() + ": cannot write the table file");
}

TextureFile read_texture_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open the table file");
  TextureFile t;
  in.read(reinterpret_cast<char*>(&t.header), sizeof t.header);
  const TextureFileHeader expected;
  if (!in || std::memcmp(t.header.magic, expected.magic, sizeof expected.magic) != 0)
    throw InputError(path.string() + ": not a glintlab table file (its first 8 bytes must be \"GLNTTEX\\0\")");
  if (t.header.version != 1 || t.header.channels != 4 || t.header.levels == 0 || t.header.levels > 32)
    throw InputError(path.string() + ": version " + std::to_string(t.header.version) + ", channels " +
                     std::to_string(t.header.channels) + ", levels " + std::to_string(t.header.levels) +
                     ": allowed: version 1, 4 channels, 1 .. 32 levels");
  for (std::uint32_t level = 0; level < t.header.levels; ++level) {
    std::vector<float>& texels = t.levels.emplace_back(level_texels(t.header, static_cast<int>(level)) * 4);
    in.read(reinterpret_cast<char*>(texels.data()), static_cast<std::streamsize>(texels.size() * sizeof(float)));
    if (!in) throw InputError(path.string() + ": ends inside level " + std::to_string(level));
  }
  if (in.peek() != std::ifstream::traits_type::eof()) throw InputError(path.string() + ": bytes after the last level");
  return t;
}

}  // namespace glintlab
