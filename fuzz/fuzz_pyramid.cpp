// Fuzz target: deng2022's pyramid cache entries (PrefilteredNdf::read, the bytes inside the cache
// entry's checksum frame: a checksum would stop the fuzzer at the door, and a consistent frame
// around bad bytes is what a bug or a hostile writer makes). RuntimeFailure is the expected outcome
// for a damaged entry (the cache reports it and rebuilds); anything else is a finding. A pyramid
// that reads must answer every query without leaving its arrays (docs/fuzzing.md).
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "prefilter/prefiltered_ndf.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const glintlab::PrefilteredNdf p = glintlab::PrefilteredNdf::read(in);
    for (const double sigma : {0.5, 3.0, 40.0})
      for (const glm::dvec2 centre : {glm::dvec2(0.0), glm::dvec2(p.width * 0.5, p.height * 0.7)}) {
        (void)p.density(centre, sigma, glm::dvec2(0.1, -0.2));
        (void)p.range_mean(centre, sigma, glm::dvec2(-0.3, -0.3), glm::dvec2(0.2, 0.4));
      }
  } catch (const glintlab::RuntimeFailure&) {
  }
  return 0;
}
