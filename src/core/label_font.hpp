#pragma once
// Text for labelling images people look at (the worst-region crops), drawn with stb_truetype
// (Debian libstb-dev) from a TrueType font read at run time: DejaVu Sans from fonts-dejavu-core.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/image.hpp"

namespace glintlab {

/// Where Debian's fonts-dejavu-core installs DejaVu Sans.
inline constexpr const char* kLabelFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

class LabelFont {
 public:
  /// Reads a TrueType file; std::nullopt with `error` saying why when it is missing or not a font.
  static std::optional<LabelFont> load(const std::filesystem::path& file, std::string& error);

  /// Advance width of `text` in pixels at a font size of `pixel_height` (ascent to descent).
  [[nodiscard]] float text_width(std::string_view text, float pixel_height) const;
  /// Draws `text` with the top of its line box at (x, y), blending `colour` over the image by
  /// each pixel's glyph coverage; clipped to the image. Characters outside printable ASCII are '?'.
  void draw(Image& image, float x, int y, float pixel_height, std::string_view text, glm::vec3 colour) const;

 private:
  struct Font;
  explicit LabelFont(std::shared_ptr<const Font> font) : font_(std::move(font)) {}
  std::shared_ptr<const Font> font_;
};

}  // namespace glintlab
