#include "eval/report.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_stage.hpp"
#include "eval/outputs.hpp"
#include "eval/report_html.hpp"
#include "eval/report_inputs.hpp"

namespace glintlab {

namespace fs = std::filesystem;

namespace {

/// OutputStage moves entries by rename(), which cannot replace a folder that is not empty: the
/// old assets/ steps aside first, under a temporary name the next stage removes if this process
/// dies, and comes back if publishing fails. index.html moves last: the new page never names an
/// asset not yet there (the old page lacks its assets only between the two renames).
void publish_replacing_assets(OutputStage& stage, const fs::path& out) {
  const fs::path assets = out / "assets";
  const fs::path aside = out / (".tmp-" + std::to_string(::getpid()) + "-assets");
  std::error_code ec;
  const bool had_assets = fs::exists(assets, ec);
  if (had_assets) {
    fs::rename(assets, aside, ec);
    if (ec) throw RuntimeFailure(assets.string() + ": cannot be replaced: " + ec.message());
  }
  try {
    stage.publish({"index.html"});
  } catch (...) {
    if (had_assets && !fs::exists(assets, ec)) fs::rename(aside, assets, ec);
    throw;
  }
  if (had_assets) fs::remove_all(aside, ec);
}

}  // namespace

ReportSummary run_report(const std::vector<fs::path>& inputs, const fs::path& out) {
  check_output_directory(out, "-o");
  const ReportInputs read = read_report_inputs(inputs);
  for (const auto& w : read.warnings) std::cerr << "glintlab: warning: " << w << "\n";
  const std::string page = report_page(read);

  ReportSummary summary;
  OutputStage stage(out);
  for (const auto& run : read.runs) {
    const fs::path folder = stage.path() / report_asset_folder(run);
    fs::create_directories(folder);
    for (const auto& asset : report_assets(run)) {
      std::error_code ec;
      fs::copy_file(run.dir / asset, folder / asset, fs::copy_options::overwrite_existing, ec);
      if (ec)
        throw RuntimeFailure((folder / asset).string() + ": cannot copy " + (run.dir / asset).string() + ": " +
                             ec.message());
      summary.bytes += fs::file_size(folder / asset);
      ++summary.assets;
    }
    ++summary.runs;
  }
  write_text_file(stage.path() / "index.html", page);
  summary.bytes += page.size();
  publish_replacing_assets(stage, out);
  std::printf("report of %d runs, %d images and videos, %.1f MB: %s\n", summary.runs, summary.assets,
              static_cast<double>(summary.bytes) / 1e6, (out / "index.html").c_str());
  return summary;
}

}  // namespace glintlab
