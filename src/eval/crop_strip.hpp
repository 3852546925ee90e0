#pragma once
// The worst-region strips compare writes (worst-region-N.png): the same window cropped from the
// reference and from each method, enlarged, side by side, each with its name in a band below it.
// metrics.json's crops[] describe the layout (cell, gap, label_height) so that `glintlab report`
// can cut the crops out again.
#include <string>

#include "core/image.hpp"
#include "core/label_font.hpp"

namespace glintlab {

/// A square window of the film: [x, x + size) x [y, y + size).
struct CropWindow {
  int x = 0, y = 0, size = 0;
};

class CropStrip {
 public:
  /// White pixels between neighbouring crops.
  static constexpr int kGap = 2;
  /// The height of the label band below the crops (0 without labels).
  static constexpr int kLabelHeight = 20;

  /// An empty (white) strip of `columns` crops of `window`, each enlarged `zoom` times, with a
  /// label band when `labelled`.
  CropStrip(int columns, CropWindow window, int zoom, bool labelled);

  /// Fills column `column` with `window` of `display` (a display-encoded image of the film).
  void paste(int column, const Image& display);
  /// Writes `name` centred in the band below column `column` (shrunk to fit the crop's width).
  void label(int column, const std::string& name, const LabelFont& font);

  [[nodiscard]] const Image& image() const { return image_; }
  [[nodiscard]] int zoom() const { return zoom_; }
  /// The side of one enlarged crop.
  [[nodiscard]] int cell() const { return window_.size * zoom_; }
  [[nodiscard]] int label_height() const { return labelled_ ? kLabelHeight : 0; }
  /// The left edge of column `column`.
  [[nodiscard]] int column_x(int column) const { return column * (cell() + kGap); }

 private:
  CropWindow window_;
  int zoom_;
  bool labelled_;
  Image image_;
};

}  // namespace glintlab
