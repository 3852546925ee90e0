// Renders a built-in scene with the installed glintlab and measures the method against the
// reference: what docs/library.md shows. Prints "rmse <value>" and the image's mean; exit 1 when
// something is off, 2 on bad input (the library's InputError), as the CLI.
#include <glintlab/glintlab.hpp>

#include <cmath>
#include <iostream>

int main(int argc, char** argv) {
  const std::string scene = argc > 1 ? argv[1] : "builtin:spheres";
  try {
    glintlab::LabOptions options;
    options.width = 32;
    options.height = 18;
    options.spp = "16";
    glintlab::Lab lab(scene, options);
    const glintlab::Rendering frame = lab.render("conventional");
    double sum = 0;
    for (float v : frame.total.pixels) sum += v;
    const double mean = sum / static_cast<double>(frame.total.pixels.size());
    const glintlab::Comparison c = lab.compare("conventional");
    const double rmse = c.methods.at("conventional").at("rmse");
    std::cout << "mean " << mean << "\nrmse " << rmse << "\n";
    return std::isfinite(mean) && mean > 0 && std::isfinite(rmse) ? 0 : 1;
  } catch (const glintlab::InputError& e) {
    std::cerr << "render_a_scene: " << e.what() << "\n";
    return 2;
  }
}
