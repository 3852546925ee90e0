// glintlab-shader-stats: the static costs of every method's forward programs, as the markdown
// tables of docs/shader-statistics.md (tools/shader-stats.sh regenerates that file). Needs no GL
// context: the programs are expanded from the shaders, compiled by glslang and counted in SPIR-V.
#include <CLI/CLI.hpp>
#include <iostream>
#include <thread>

#include "core/error.hpp"
#include "render/shader_contract.hpp"
#include "shader_stats/program_statistics.hpp"

int main(int argc, char** argv) {
  using namespace glintlab;
  CLI::App app{"glintlab-shader-stats: operations, texture fetches and dynamically indexed local arrays of every "
               "method's forward programs, counted in SPIR-V (docs/shader-statistics.md)"};
  std::string methods;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--methods", methods, "methods and variants as the rendering commands take them, and 'reference' (default: every method and the reference)");
  app.add_option("-j,--jobs", jobs, "programs compiled at once")->check(CLI::Range(1, 256));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    ShaderLibrary shaders;
    add_contract_sources(shaders);
    const std::vector<ProgramRow> rows = program_rows(shaders, methods);
    std::cout << program_statistics_markdown(shaders, rows, jobs);
  } catch (const InputError& e) {
    std::cerr << "glintlab-shader-stats: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "glintlab-shader-stats: failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
