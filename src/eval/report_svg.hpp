#pragma once
// The report's plots as inline SVG text, drawn here so the page needs no plotting library:
// per-frame lines (an animation's error), horizontal bars (flicker, milliseconds per frame), with
// the floors a measurement cannot go below drawn as dashed lines.
#include <string>
#include <vector>

namespace glintlab {

/// The colour of the i-th method in every plot of a run (hues a golden angle apart).
std::string series_colour(std::size_t index);

/// Text safe inside SVG/HTML elements and attributes.
std::string xml_escaped(const std::string& text);

struct PlotSeries {
  std::string name;
  std::vector<double> values;
};

/// A value marked across the plot: a floor such as the reference's noise.
struct PlotMark {
  std::string label;
  double value = 0;
};

/// Frame index on x, value on y from 0 to above the largest value or mark; one polyline per
/// series in series_colour order (values that are not finite left out), a legend, and each mark
/// as a dashed line.
std::string line_plot_svg(const std::string& title, const std::string& y_label, const std::vector<PlotSeries>& series,
                          const std::vector<PlotMark>& marks);

/// A point of a curve on two measured axes, e.g. (seconds, error).
struct PlotPoint {
  double x = 0, y = 0;
  std::string note;  ///< shown on hover, e.g. "64 spp"
};
struct PointSeries {
  std::string name;
  std::vector<PlotPoint> points;
};

/// x and y on log10 axes spanning the positive points and marks, decades ticked: convergence
/// curves (error against samples or seconds), whose slopes are their rates. One polyline with
/// dots per series in series_colour order (points not both positive and finite left out), a
/// legend, each mark a dashed horizontal line. Styled inline, so it reads alone as a file too.
std::string log_log_plot_svg(const std::string& title, const std::string& x_label, const std::string& y_label,
                             const std::vector<PointSeries>& series, const std::vector<PlotMark>& marks);

struct PlotBar {
  std::string label;
  double value = 0;
  std::string note;    ///< written after the value, e.g. "x1.35 of conventional"
  bool muted = false;  ///< drawn grey: a row that is not a method (a floor)
  std::size_t colour = 0;
};

/// One horizontal bar per entry from 0, the value and note beside it, the marks as dashed lines.
std::string bar_chart_svg(const std::string& title, const std::string& unit, const std::vector<PlotBar>& bars,
                          const std::vector<PlotMark>& marks);

}  // namespace glintlab
