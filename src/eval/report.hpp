#pragma once
// `glintlab report`: one static HTML page of the outputs of compare, animate, bench and converge, with copies
// of the images and videos it shows, opened from disk without a network (docs/report.md).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace glintlab {

struct ReportSummary {
  int runs = 0;
  int assets = 0;
  std::uintmax_t bytes = 0;  ///< index.html and the assets
};

/// Reads every input (read_report_inputs: bad input throws InputError before anything is
/// written), then writes <out>/index.html and <out>/assets/<run>/... into a staging folder and
/// publishes them as a unit: the old report, if any, stays whole until the new one replaces it.
/// Skipped files are warned about on stderr.
ReportSummary run_report(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& out);

}  // namespace glintlab
