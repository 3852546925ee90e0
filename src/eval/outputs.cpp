#include "eval/outputs.hpp"

#include "core/colour.hpp"
#include "core/image_io.hpp"

namespace glintlab {

void write_frame(const std::filesystem::path& dir, const std::string& stem, const Frame& frame, const Film& film) {
  write_exr(dir / (stem + ".exr"), {{"", &frame.total}, {"specular", &frame.specular}});
  write_png(dir / (stem + ".png"), tonemap_for_display(frame.total, film.exposure, film.bloom));
}

}  // namespace glintlab
