#include "eval/report_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

namespace glintlab {

namespace {

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f", v);
  return s;
}

std::string value_text(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.4g", v);
  return s;
}

/// A round step for about `count` ticks up to `top`: 1, 2 or 5 times a power of ten.
double tick_step(double top, int count) {
  const double raw = top / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

/// The axis top: the largest value or mark, rounded up to a tick; 1 when everything is 0.
double axis_top(double largest) {
  if (!(largest > 0) || !std::isfinite(largest)) return 1.0;
  const double step = tick_step(largest, 5);
  return std::ceil(largest / step - 1e-9) * step;
}

void dashed_mark(std::ostringstream& s, double x1, double y1, double x2, double y2, const std::string& label,
                 double value) {
  s << "<g class=\"mark\"><title>" << xml_escaped(label) << ": " << value_text(value) << "</title><line x1=\""
    << num(x1) << "\" y1=\"" << num(y1) << "\" x2=\"" << num(x2) << "\" y2=\"" << num(y2)
    << "\" stroke=\"#444\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"/></g>\n";
}

}  // namespace

std::string series_colour(std::size_t index) {
  const double hue = std::fmod(210.0 + 137.508 * static_cast<double>(index), 360.0);
  return "hsl(" + std::to_string(static_cast<int>(hue)) + ",70%," + (index % 2 ? "38%" : "48%") + ")";
}

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string line_plot_svg(const std::string& title, const std::string& y_label, const std::vector<PlotSeries>& series,
                          const std::vector<PlotMark>& marks) {
  const double left = 64, top = 34, plot_w = 520, legend_x = left + plot_w + 24;
  const double plot_h = std::max(220.0, 18.0 * static_cast<double>(series.size() + marks.size()) - 10.0);
  const double width = legend_x + 180, height = top + plot_h + 46;
  std::size_t frames = 1;
  double largest = 0;
  for (const auto& p : series) {
    frames = std::max(frames, p.values.size());
    for (const double v : p.values) largest = std::max(largest, std::isfinite(v) ? v : 0.0);
  }
  for (const auto& m : marks) largest = std::max(largest, m.value);
  const double y_top = axis_top(largest);
  const double x_span = static_cast<double>(std::max<std::size_t>(frames - 1, 1));
  auto px = [&](double frame) { return left + plot_w * frame / x_span; };
  auto py = [&](double v) { return top + plot_h * (1.0 - std::clamp(v / y_top, 0.0, 1.0)); };

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" viewBox=\"0 0 " << num(width) << " " << num(height)
    << "\" role=\"img\" aria-label=\"" << xml_escaped(title) << "\">\n<text x=\"" << num(left)
    << "\" y=\"20\" class=\"title\">" << xml_escaped(title) << "</text>\n";
  const double step = tick_step(y_top, 5);
  for (double v = 0; v <= y_top * (1 + 1e-9); v += step)
    s << "<line x1=\"" << num(left) << "\" x2=\"" << num(left + plot_w) << "\" y1=\"" << num(py(v)) << "\" y2=\""
      << num(py(v)) << "\" class=\"grid\"/><text x=\"" << num(left - 6) << "\" y=\"" << num(py(v) + 4)
      << "\" class=\"tick\" text-anchor=\"end\">" << value_text(v) << "</text>\n";
  const std::size_t frame_step = std::max<std::size_t>(1, frames / 12);
  for (std::size_t f = 0; f < frames; f += frame_step)
    s << "<text x=\"" << num(px(static_cast<double>(f))) << "\" y=\"" << num(top + plot_h + 16)
      << "\" class=\"tick\" text-anchor=\"middle\">" << f << "</text>\n";
  s << "<text x=\"" << num(left + plot_w / 2) << "\" y=\"" << num(top + plot_h + 36)
    << "\" class=\"axis\" text-anchor=\"middle\">frame</text>\n<text x=\"14\" y=\"" << num(top + plot_h / 2)
    << "\" class=\"axis\" text-anchor=\"middle\" transform=\"rotate(-90 14 " << num(top + plot_h / 2) << ")\">"
    << xml_escaped(y_label) << "</text>\n";
  for (const auto& m : marks) dashed_mark(s, left, py(m.value), left + plot_w, py(m.value), m.label, m.value);

  double legend_y = top + 4;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const auto& p = series[i];
    const std::string colour = series_colour(i);
    s << "<g class=\"series\"><title>" << xml_escaped(p.name) << "</title><polyline fill=\"none\" stroke=\"" << colour
      << "\" stroke-width=\"2\" points=\"";
    // A value that is not finite is not drawn (a frame a quantity has no value at, such as the
    // flicker of the first frame).
    bool first = true;
    for (std::size_t f = 0; f < p.values.size(); ++f) {
      if (!std::isfinite(p.values[f])) continue;
      s << (first ? "" : " ") << num(px(static_cast<double>(f))) << "," << num(py(p.values[f]));
      first = false;
    }
    s << "\"/>";
    if (p.values.size() <= 40)
      for (std::size_t f = 0; f < p.values.size(); ++f)
        if (std::isfinite(p.values[f])) s << "<circle cx=\"" << num(px(static_cast<double>(f))) << "\" cy=\"" << num(py(p.values[f]))
          << "\" r=\"2.5\" fill=\"" << colour << "\"><title>" << xml_escaped(p.name) << ", frame " << f << ": "
          << value_text(p.values[f]) << "</title></circle>";
    s << "</g>\n<rect x=\"" << num(legend_x) << "\" y=\"" << num(legend_y - 9) << "\" width=\"14\" height=\"4\" fill=\""
      << colour << "\"/><text x=\"" << num(legend_x + 20) << "\" y=\"" << num(legend_y - 4) << "\" class=\"legend\">"
      << xml_escaped(p.name) << "</text>\n";
    legend_y += 18;
  }
  for (const auto& m : marks) {
    s << "<line x1=\"" << num(legend_x) << "\" x2=\"" << num(legend_x + 14) << "\" y1=\"" << num(legend_y - 7)
      << "\" y2=\"" << num(legend_y - 7) << "\" stroke=\"#444\" stroke-dasharray=\"4 2\"/><text x=\""
      << num(legend_x + 20) << "\" y=\"" << num(legend_y - 4) << "\" class=\"legend\">" << xml_escaped(m.label)
      << "</text>\n";
    legend_y += 18;
  }
  s << "</svg>";
  return s.str();
}

std::string bar_chart_svg(const std::string& title, const std::string& unit, const std::vector<PlotBar>& bars,
                          const std::vector<PlotMark>& marks) {
  const double label_w = 190, bar_w = 380, row = 22, top = 34;
  const double width = label_w + bar_w + 230, height = top + row * static_cast<double>(bars.size()) + 24;
  double largest = 0;
  for (const auto& b : bars) largest = std::max(largest, std::isfinite(b.value) ? b.value : 0.0);
  for (const auto& m : marks) largest = std::max(largest, m.value);
  const double x_top = axis_top(largest);
  auto px = [&](double v) { return label_w + bar_w * std::clamp(v / x_top, 0.0, 1.0); };

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" viewBox=\"0 0 " << num(width) << " " << num(height)
    << "\" role=\"img\" aria-label=\"" << xml_escaped(title) << "\">\n<text x=\"4\" y=\"20\" class=\"title\">"
    << xml_escaped(title) << "</text>\n";
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const auto& b = bars[i];
    const double y = top + row * static_cast<double>(i);
    const std::string fill = b.muted ? "#999" : series_colour(b.colour);
    s << "<g class=\"bar\"><title>" << xml_escaped(b.label) << ": " << value_text(b.value) << " " << xml_escaped(unit)
      << (b.note.empty() ? "" : ", ") << xml_escaped(b.note) << "</title><text x=\"" << num(label_w - 8) << "\" y=\""
      << num(y + 15) << "\" class=\"legend\" text-anchor=\"end\">" << xml_escaped(b.label) << "</text><rect x=\""
      << num(label_w) << "\" y=\"" << num(y + 3) << "\" width=\"" << num(std::max(1.0, px(b.value) - label_w))
      << "\" height=\"" << num(row - 6) << "\" fill=\"" << fill << "\"/><text x=\"" << num(px(b.value) + 6) << "\" y=\""
      << num(y + 15) << "\" class=\"tick\">" << value_text(b.value) << " " << xml_escaped(unit)
      << (b.note.empty() ? "" : "  ") << xml_escaped(b.note) << "</text></g>\n";
  }
  const double bottom = top + row * static_cast<double>(bars.size());
  for (const auto& m : marks) {
    dashed_mark(s, px(m.value), top - 4, px(m.value), bottom, m.label, m.value);
    s << "<text x=\"" << num(px(m.value)) << "\" y=\"" << num(bottom + 16)
      << "\" class=\"tick\" text-anchor=\"middle\">" << xml_escaped(m.label) << " " << value_text(m.value)
      << "</text>\n";
  }
  s << "</svg>";
  return s.str();
}

namespace {

/// Whole decades around [lo, hi] (lo, hi > 0): 10^floor(log10 lo) .. 10^ceil(log10 hi), at least one decade.
std::pair<double, double> decade_span(double lo, double hi) {
  const double a = std::floor(std::log10(lo) + 1e-9), b = std::ceil(std::log10(hi) - 1e-9);
  return {a, std::max(b, a + 1)};
}

bool plottable(const PlotPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y) && p.x > 0 && p.y > 0; }

}  // namespace

std::string log_log_plot_svg(const std::string& title, const std::string& x_label, const std::string& y_label,
                             const std::vector<PointSeries>& series, const std::vector<PlotMark>& marks) {
  const double left = 64, top = 34, plot_w = 520, plot_h = 300, legend_x = left + plot_w + 24;
  const double width = legend_x + 260, height = top + plot_h + 46;
  double x_lo = INFINITY, x_hi = 0, y_lo = INFINITY, y_hi = 0;
  for (const auto& p : series)
    for (const PlotPoint& q : p.points)
      if (plottable(q)) x_lo = std::min(x_lo, q.x), x_hi = std::max(x_hi, q.x), y_lo = std::min(y_lo, q.y), y_hi = std::max(y_hi, q.y);
  for (const auto& m : marks)
    if (m.value > 0 && std::isfinite(m.value)) y_lo = std::min(y_lo, m.value), y_hi = std::max(y_hi, m.value);
  if (!(x_hi > 0)) x_lo = 1, x_hi = 10;
  if (!(y_hi > 0)) y_lo = 1, y_hi = 10;
  const auto [x0, x1] = decade_span(x_lo, x_hi);
  const auto [y0, y1] = decade_span(y_lo, y_hi);
  auto px = [&](double x) { return left + plot_w * (std::log10(x) - x0) / (x1 - x0); };
  auto py = [&](double y) { return top + plot_h * (1.0 - (std::log10(y) - y0) / (y1 - y0)); };
  const std::string text_style = " font-family=\"sans-serif\" font-size=\"12\"";

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" viewBox=\"0 0 " << num(width) << " " << num(height)
    << "\" role=\"img\" aria-label=\"" << xml_escaped(title) << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>"
    << "<text x=\"" << num(left) << "\" y=\"20\" class=\"title\" font-family=\"sans-serif\" font-size=\"14\">"
    << xml_escaped(title) << "</text>\n";
  for (double d = y0; d <= y1 + 1e-9; d += 1)
    s << "<line x1=\"" << num(left) << "\" x2=\"" << num(left + plot_w) << "\" y1=\"" << num(py(std::pow(10.0, d)))
      << "\" y2=\"" << num(py(std::pow(10.0, d))) << "\" class=\"grid\" stroke=\"#e6e8ec\"/><text x=\"" << num(left - 6)
      << "\" y=\"" << num(py(std::pow(10.0, d)) + 4) << "\" class=\"tick\" text-anchor=\"end\"" << text_style << ">"
      << value_text(std::pow(10.0, d)) << "</text>\n";
  for (double d = x0; d <= x1 + 1e-9; d += 1)
    s << "<line x1=\"" << num(px(std::pow(10.0, d))) << "\" x2=\"" << num(px(std::pow(10.0, d))) << "\" y1=\"" << num(top)
      << "\" y2=\"" << num(top + plot_h) << "\" class=\"grid\" stroke=\"#e6e8ec\"/><text x=\"" << num(px(std::pow(10.0, d)))
      << "\" y=\"" << num(top + plot_h + 16) << "\" class=\"tick\" text-anchor=\"middle\"" << text_style << ">"
      << value_text(std::pow(10.0, d)) << "</text>\n";
  s << "<text x=\"" << num(left + plot_w / 2) << "\" y=\"" << num(top + plot_h + 36) << "\" class=\"axis\" text-anchor=\"middle\""
    << text_style << ">" << xml_escaped(x_label) << "</text>\n<text x=\"14\" y=\"" << num(top + plot_h / 2)
    << "\" class=\"axis\" text-anchor=\"middle\" transform=\"rotate(-90 14 " << num(top + plot_h / 2) << ")\"" << text_style
    << ">" << xml_escaped(y_label) << "</text>\n";
  for (const auto& m : marks)
    if (m.value > 0 && std::isfinite(m.value)) dashed_mark(s, left, py(m.value), left + plot_w, py(m.value), m.label, m.value);

  double legend_y = top + 4;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const std::string colour = series_colour(i);
    s << "<g class=\"series\"><title>" << xml_escaped(series[i].name) << "</title><polyline fill=\"none\" stroke=\""
      << colour << "\" stroke-width=\"2\" points=\"";
    bool first = true;
    for (const PlotPoint& q : series[i].points) {
      if (!plottable(q)) continue;
      s << (first ? "" : " ") << num(px(q.x)) << "," << num(py(q.y));
      first = false;
    }
    s << "\"/>";
    for (const PlotPoint& q : series[i].points)
      if (plottable(q))
        s << "<circle cx=\"" << num(px(q.x)) << "\" cy=\"" << num(py(q.y)) << "\" r=\"3\" fill=\"" << colour << "\"><title>"
          << xml_escaped(series[i].name) << (q.note.empty() ? "" : ", ") << xml_escaped(q.note) << ": "
          << value_text(q.x) << ", " << value_text(q.y) << "</title></circle>";
    s << "</g>\n<rect x=\"" << num(legend_x) << "\" y=\"" << num(legend_y - 9) << "\" width=\"14\" height=\"4\" fill=\""
      << colour << "\"/><text x=\"" << num(legend_x + 20) << "\" y=\"" << num(legend_y - 4) << "\" class=\"legend\""
      << text_style << ">" << xml_escaped(series[i].name) << "</text>\n";
    legend_y += 18;
  }
  for (const auto& m : marks) {
    s << "<line x1=\"" << num(legend_x) << "\" x2=\"" << num(legend_x + 14) << "\" y1=\"" << num(legend_y - 7)
      << "\" y2=\"" << num(legend_y - 7) << "\" stroke=\"#444\" stroke-dasharray=\"4 2\"/><text x=\""
      << num(legend_x + 20) << "\" y=\"" << num(legend_y - 4) << "\" class=\"legend\"" << text_style << ">"
      << xml_escaped(m.label) << "</text>\n";
    legend_y += 18;
  }
  s << "</svg>";
  return s.str();
}

}  // namespace glintlab
