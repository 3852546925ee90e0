#include "eval/crop_strip.hpp"

#include <algorithm>

namespace glintlab {

namespace {
constexpr float kLabelPixelHeight = 14.0f;  // DejaVu Sans at 14 px: "kaplanyan-beckmann" is about 140 px
constexpr float kLabelPadding = 3.0f;       // free pixels left and right of the text
const glm::vec3 kLabelInk(0.0f);            // black on the strip's white
}  // namespace

CropStrip::CropStrip(int columns, CropWindow window, int zoom, bool labelled)
    : window_(window),
      zoom_(zoom),
      labelled_(labelled),
      image_(columns * (window.size * zoom + kGap) - kGap, window.size * zoom + (labelled ? kLabelHeight : 0),
             glm::vec3(1.0f)) {}

void CropStrip::paste(int column, const Image& display) {
  const Image crop = display.crop(window_.x, window_.y, window_.size, window_.size).upscale(zoom_);
  const int left = column_x(column);
  for (int y = 0; y < crop.height(); ++y)
    for (int x = 0; x < crop.width(); ++x) image_.at(left + x, y) = crop.at(x, y);
}

void CropStrip::label(int column, const std::string& name, const LabelFont& font) {
  if (!labelled_) return;
  const float room = static_cast<float>(cell()) - 2.0f * kLabelPadding;
  float size = kLabelPixelHeight;
  const float width = font.text_width(name, size);
  if (width > room) size *= room / width;
  const float text_width = std::min(font.text_width(name, size), room);
  // Drawn into a band of its own, so that a glyph can never reach the crop or the next column.
  Image band(cell(), kLabelHeight, glm::vec3(1.0f));
  font.draw(band, 0.5f * (static_cast<float>(cell()) - text_width),
            static_cast<int>((static_cast<float>(kLabelHeight) - size) / 2.0f), size, name, kLabelInk);
  for (int by = 0; by < kLabelHeight; ++by)
    for (int bx = 0; bx < cell(); ++bx) image_.at(column_x(column) + bx, cell() + by) = band.at(bx, by);
}

}  // namespace glintlab
