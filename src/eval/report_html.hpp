#pragma once
// index.html of `glintlab report`: the page template (src/eval/report/, embedded at build time)
// with every run's data as JSON inside it, so the page needs nothing but its assets/ folder, and
// opens from disk (browsers refuse fetch() of file:// URLs).
#include <string>

#include "eval/report_inputs.hpp"

namespace glintlab {

/// Where a run's images and videos are, relative to index.html: "assets/<id>".
std::string report_asset_folder(const ReportRun& run);

/// The whole page. Columns of each table, which floor each is judged by, the plots (SVG) and the
/// assets' URLs are decided here; sorting, the slider and the crops' labels are the page's script.
std::string report_page(const ReportInputs& inputs);

}  // namespace glintlab
