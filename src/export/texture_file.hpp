#pragma once
// A GL texture as a plain binary file (`glintlab export`'s tables; layout in docs/export.md): a
// 64-byte little-endian header, then every mip level's texels as RGBA float32, level 0 first,
// each level layer by layer, rows from v = 0. What an engine uploads as the texture the exported
// shader samples, with the filters and wraps it was sampled with.
#include <epoxy/gl.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace glintlab {

struct TextureFileHeader {
  char magic[8] = {'G', 'L', 'N', 'T', 'T', 'E', 'X', '\0'};
  std::uint32_t version = 1;
  std::uint32_t target = 0;           ///< GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_1D_ARRAY, ...
  std::uint32_t internal_format = 0;  ///< the GL format it was sampled in (GL_RGBA16F, ...)
  std::uint32_t width = 0, height = 0, depth = 0;  ///< of level 0 (depth: layers of an array)
  std::uint32_t levels = 0;
  std::uint32_t min_filter = 0, mag_filter = 0, wrap_s = 0, wrap_t = 0;
  std::uint32_t channels = 4;  ///< the stored texels: RGBA float32 whatever the format
  std::uint32_t reserved[2] = {0, 0};
};
static_assert(sizeof(TextureFileHeader) == 64);

struct TextureFile {
  TextureFileHeader header;
  std::vector<std::vector<float>> levels;  ///< RGBA float32 texels of each level
};

/// The texture as the GL holds it (glGetTextureImage of every level; a current context).
TextureFile read_texture(GLuint texture);
/// Writes it; throws RuntimeFailure naming the file when it cannot.
void write_texture_file(const std::filesystem::path& path, const TextureFile& texture);
/// Reads a file write_texture_file wrote; throws InputError naming the file and what is wrong.
TextureFile read_texture_file(const std::filesystem::path& path);

}  // namespace glintlab
