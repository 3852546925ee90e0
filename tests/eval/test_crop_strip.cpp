// The worst-region strips (src/eval/crop_strip.hpp): each crop is its window of its image,
// untouched by the labels, and each name is drawn in the band below its own crop, shrunk to fit.
#include <gtest/gtest.h>

#include <fstream>

#include "eval/crop_strip.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;

namespace {

/// A display image whose every pixel differs from its neighbours, distinct per `seed`.
Image pattern(int seed) {
  Image img(40, 30);
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      img.at(x, y) = glm::vec3((x * 7 + seed * 3) % 40 / 40.0f, (y * 5 + seed) % 30 / 30.0f, ((x + y) % 2) * 0.5f);
  return img;
}

LabelFont label_font() {
  std::string error;
  std::optional<LabelFont> font = LabelFont::load(kLabelFontFile, error);
  if (!font) throw std::runtime_error(error + " (tools/install-deps.sh installs fonts-dejavu-core)");
  return *font;
}

bool white(glm::vec3 c) { return c == glm::vec3(1.0f); }

}  // namespace

TEST(LabelFont, AMissingOrBrokenFileIsAnErrorNamingIt) {
  const test::ScratchDirectory scratch;
  std::string error;
  EXPECT_FALSE(LabelFont::load(scratch / "none.ttf", error).has_value());
  EXPECT_NE(error.find((scratch / "none.ttf").string()), std::string::npos) << error;
  std::ofstream(scratch / "text.ttf") << "not a font";
  EXPECT_FALSE(LabelFont::load(scratch / "text.ttf", error).has_value());
  EXPECT_NE(error.find("not a TrueType font"), std::string::npos) << error;
}

TEST(CropStrip, CropsAreTheirWindowsAndEachNameIsInTheBandBelowItsCrop) {
  const LabelFont font = label_font();
  const CropWindow window{5, 7, 12};
  const int zoom = 4, cell = window.size * zoom;
  // The longest method name is wider than a 48-px cell at the label's size: it must shrink to fit.
  const std::vector<std::string> names{"reference", "kaplanyan-beckmann", "lean"};
  const int columns = static_cast<int>(names.size());
  CropStrip labelled(columns, window, zoom, true), plain(columns, window, zoom, false);
  for (int c = 0; c < columns; ++c) {
    labelled.paste(c, pattern(c));
    plain.paste(c, pattern(c));
    labelled.label(c, names[static_cast<std::size_t>(c)], font);
    plain.label(c, names[static_cast<std::size_t>(c)], font);  // no band: nothing to draw into
  }
  ASSERT_EQ(plain.image().height(), cell);
  ASSERT_EQ(labelled.image().height(), cell + CropStrip::kLabelHeight);
  ASSERT_EQ(labelled.image().width(), plain.image().width());
  ASSERT_EQ(labelled.image().width(), columns * (cell + CropStrip::kGap) - CropStrip::kGap);

  std::vector<std::vector<glm::vec3>> bands;
  for (int c = 0; c < columns; ++c) {
    const Image source = pattern(c);
    const int left = labelled.column_x(c);
    // The crop: its window of its image, nearest-neighbour enlarged, in both strips alike.
    for (int y = 0; y < cell; ++y)
      for (int x = 0; x < cell; ++x) {
        const glm::vec3 expected = source.at(window.x + x / zoom, window.y + y / zoom);
        ASSERT_EQ(labelled.image().at(left + x, y), expected)
            << names[static_cast<std::size_t>(c)] << " " << x << "," << y;
        ASSERT_EQ(plain.image().at(left + x, y), expected);
      }
    // The band below it: ink (a name) that keeps clear of the band's left and right edges.
    int ink = 0, leftmost = cell, rightmost = -1;
    std::vector<glm::vec3>& band = bands.emplace_back();
    for (int y = cell; y < cell + CropStrip::kLabelHeight; ++y)
      for (int x = 0; x < cell; ++x) {
        const glm::vec3 p = labelled.image().at(left + x, y);
        band.push_back(p);
        if (white(p)) continue;
        ++ink;
        leftmost = std::min(leftmost, x);
        rightmost = std::max(rightmost, x);
      }
    EXPECT_GT(ink, 20) << "no name under " << names[static_cast<std::size_t>(c)];
    EXPECT_GE(leftmost, 1) << names[static_cast<std::size_t>(c)] << " reaches the band's left edge";
    EXPECT_LE(rightmost, cell - 2) << names[static_cast<std::size_t>(c)] << " reaches the band's right edge";
  }
  EXPECT_NE(bands[0], bands[1]);
  EXPECT_NE(bands[1], bands[2]);
  // The gaps between the crops stay white all the way down.
  for (int c = 0; c + 1 < columns; ++c)
    for (int y = 0; y < labelled.image().height(); ++y)
      for (int x = labelled.column_x(c) + cell; x < labelled.column_x(c + 1); ++x)
        EXPECT_TRUE(white(labelled.image().at(x, y))) << x << "," << y;
}
