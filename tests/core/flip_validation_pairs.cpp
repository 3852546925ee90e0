// Writes the FLIP validation pairs (flip_validation_pairs.hpp) into a directory, for
// tools/flip-validation.sh: <name>-test.{png,exr}, <name>-reference.{png,exr} and pairs.txt (one
// line per pair: name, kind, and the HDR exposures start stop count or "auto").
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/colour.hpp"
#include "core/image_io.hpp"
#include "core/flip_validation_pairs.hpp"

int main(int argc, char** argv) {
  using namespace glintlab;
  if (argc != 2) {
    std::cerr << "usage: flip_validation_pairs DIRECTORY\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  std::ofstream list(dir / "pairs.txt");
  for (const test::FlipPair& pair : test::flip_validation_pairs()) {
    for (const auto& [role, image] : {std::pair{"test", &pair.test}, std::pair{"reference", &pair.reference}}) {
      const std::filesystem::path stem = dir / (pair.name + "-" + role);
      if (pair.hdr) {
        write_exr(stem.string() + ".exr", {{"", image}});
      } else {
        Image encoded(image->width(), image->height());
        for (std::size_t i = 0; i < image->pixel_count(); ++i)
          for (int c = 0; c < 3; ++c) encoded.pixels()[i][c] = srgb_encode(image->pixels()[i][c]);
        write_png(stem.string() + ".png", encoded);
      }
    }
    list << pair.name << ' ' << (pair.hdr ? "hdr" : "ldr");
    if (pair.exposures) list << ' ' << pair.exposures->start << ' ' << pair.exposures->stop << ' ' << pair.exposures->count;
    else list << " auto";
    list << '\n';
  }
  return 0;
}
