#include "core/label_font.hpp"

#include <stb/stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

namespace glintlab {

struct LabelFont::Font {
  std::vector<unsigned char> bytes;  // stbtt_fontinfo points into them
  stbtt_fontinfo info{};
  int ascent = 0, descent = 0;  // font units

  [[nodiscard]] float scale(float pixel_height) const { return pixel_height / static_cast<float>(ascent - descent); }
};

namespace {

int printable(char c) { return c >= 32 && c < 127 ? c : '?'; }

}  // namespace

std::optional<LabelFont> LabelFont::load(const std::filesystem::path& file, std::string& error) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    error = file.string() + ": cannot be read";
    return std::nullopt;
  }
  auto font = std::make_shared<Font>();
  font->bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const int offset = font->bytes.empty() ? -1 : stbtt_GetFontOffsetForIndex(font->bytes.data(), 0);
  if (offset < 0 || !stbtt_InitFont(&font->info, font->bytes.data(), offset)) {
    error = file.string() + ": not a TrueType font";
    return std::nullopt;
  }
  int line_gap = 0;
  stbtt_GetFontVMetrics(&font->info, &font->ascent, &font->descent, &line_gap);
  if (font->ascent <= font->descent) {
    error = file.string() + ": a font without vertical metrics";
    return std::nullopt;
  }
  return LabelFont(std::move(font));
}

float LabelFont::text_width(std::string_view text, float pixel_height) const {
  const float scale = font_->scale(pixel_height);
  float width = 0.0f;
  for (std::size_t i = 0; i < text.size(); ++i) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font_->info, printable(text[i]), &advance, &bearing);
    width += scale * static_cast<float>(advance);
    if (i + 1 < text.size())
      width += scale * static_cast<float>(
                           stbtt_GetCodepointKernAdvance(&font_->info, printable(text[i]), printable(text[i + 1])));
  }
  return width;
}

void LabelFont::draw(Image& image, float x, int y, float pixel_height, std::string_view text, glm::vec3 colour) const {
  const float scale = font_->scale(pixel_height);
  const int baseline = y + static_cast<int>(std::lround(scale * static_cast<float>(font_->ascent)));
  std::vector<unsigned char> coverage;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const int c = printable(text[i]);
    // Each glyph at its own sub-pixel offset, so that spacing follows the advances exactly.
    const float shift = x - std::floor(x);
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBitmapBoxSubpixel(&font_->info, c, scale, scale, shift, 0.0f, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      coverage.assign(static_cast<std::size_t>(w) * h, 0);
      stbtt_MakeCodepointBitmapSubpixel(&font_->info, coverage.data(), w, h, w, scale, scale, shift, 0.0f, c);
      const int left = static_cast<int>(std::floor(x)) + x0, top = baseline + y0;
      for (int gy = 0; gy < h; ++gy)
        for (int gx = 0; gx < w; ++gx) {
          const int px = left + gx, py = top + gy;
          if (px < 0 || py < 0 || px >= image.width() || py >= image.height()) continue;
          const float a = static_cast<float>(coverage[static_cast<std::size_t>(gy) * w + gx]) / 255.0f;
          image.at(px, py) = glm::mix(image.at(px, py), colour, a);
        }
    }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font_->info, c, &advance, &bearing);
    x += scale * static_cast<float>(advance);
    if (i + 1 < text.size())
      x += scale * static_cast<float>(stbtt_GetCodepointKernAdvance(&font_->info, c, printable(text[i + 1])));
  }
}

}  // namespace glintlab
