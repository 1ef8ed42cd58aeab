// SVG grouped bar charts for the benchmark reports.
#include "swept/bench/svg_plot.h"

#include "swept/bench/output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace swept::bench {
namespace {

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string tick_label(double v) {
  char buf[64];
  if (v != 0.0 && (std::abs(v) >= 1e5 || std::abs(v) < 1e-3))
    std::snprintf(buf, sizeof buf, "%.0e", v);
  else
    std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A "nice" step (1, 2 or 5 times a power of ten) giving about `target` intervals over `span`.
double nice_step(double span, int target) {
  const double raw = span / target;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

constexpr const char* kPalette[] = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2",
                                    "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};

}  // namespace

std::string render_svg(const BarChart& chart) {
  const std::size_t ng = chart.groups.size(), ns = chart.series.size();
  for (const BarSeries& s : chart.series) {
    if (s.values.size() != ng) throw std::runtime_error("plot '" + chart.title + "': series '" + s.name + "' has " +
                                                        std::to_string(s.values.size()) + " values for " +
                                                        std::to_string(ng) + " groups");
    if ((!s.low.empty() && s.low.size() != ng) || (!s.high.empty() && s.high.size() != ng))
      throw std::runtime_error("plot '" + chart.title + "': series '" + s.name + "' has mismatched whiskers");
  }
  // Value range over bars, whiskers and the reference line.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto see = [&](double v) {
    if (!std::isfinite(v) || (chart.log_scale && v <= 0.0)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  for (const BarSeries& s : chart.series) {
    for (double v : s.values) see(v);
    for (double v : s.low) see(v);
    for (double v : s.high) see(v);
  }
  if (chart.reference_line) see(*chart.reference_line);
  if (!std::isfinite(lo)) {
    if (chart.log_scale) throw std::runtime_error("plot '" + chart.title + "': no positive value on a log scale");
    lo = 0.0;
    hi = 1.0;
  }
  double axis_lo, axis_hi;
  std::vector<double> ticks;
  if (chart.log_scale) {
    axis_lo = std::floor(std::log10(lo));
    axis_hi = std::ceil(std::log10(hi));
    if (axis_hi <= axis_lo) axis_hi = axis_lo + 1;
    for (double e = axis_lo; e <= axis_hi + 1e-9; e += 1) ticks.push_back(std::pow(10.0, e));
  } else {
    axis_lo = std::min(0.0, lo);
    axis_hi = hi > axis_lo ? hi * 1.08 : axis_lo + 1.0;
    const double step = nice_step(axis_hi - axis_lo, 6);
    axis_hi = std::ceil(axis_hi / step) * step;
    for (double t = std::ceil(axis_lo / step) * step; t <= axis_hi + step * 1e-9; t += step) ticks.push_back(t);
  }

  const double bar_w = 14.0, group_gap = 22.0;
  const double group_w = std::max(1.0, static_cast<double>(ns)) * bar_w + group_gap;
  const double left = 78, right = 24, top = 52, bottom = 120;
  const double legend_h = 18.0 * static_cast<double>((ns + 3) / 4);
  // Wide enough for the bars, the title (~7.5 px a character at 14 px) and four legend columns.
  const double plot_w = std::max({420.0, group_w * static_cast<double>(ng),
                                  7.5 * static_cast<double>(chart.title.size()) - left + 20.0,
                                  170.0 * static_cast<double>(std::min<std::size_t>(ns, 4))});
  const double plot_h = 300.0;
  const double width = left + plot_w + right, height = top + legend_h + plot_h + bottom;
  const double y0 = top + legend_h;  // top of the plot area
  auto ypos = [&](double v) {
    double f;
    if (chart.log_scale)
      f = (std::log10(std::max(v, std::pow(10.0, axis_lo))) - axis_lo) / (axis_hi - axis_lo);
    else
      f = (v - axis_lo) / (axis_hi - axis_lo);
    f = std::clamp(f, 0.0, 1.0);
    return y0 + plot_h * (1.0 - f);
  };
  const double base = chart.log_scale ? y0 + plot_h : ypos(0.0);

  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
    << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << "<text x=\"" << num(width / 2) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">"
    << escape(chart.title) << "</text>\n";
  // Legend.
  for (std::size_t s = 0; s < ns; ++s) {
    const double lx = left + static_cast<double>(s % 4) * 170.0, ly = 34 + static_cast<double>(s / 4) * 18.0;
    o << "<rect x=\"" << num(lx) << "\" y=\"" << num(ly) << "\" width=\"12\" height=\"12\" fill=\""
      << kPalette[s % std::size(kPalette)] << "\"/><text x=\"" << num(lx + 16) << "\" y=\"" << num(ly + 10) << "\">"
      << escape(chart.series[s].name) << "</text>\n";
  }
  // Grid and ticks.
  for (double t : ticks) {
    const double y = ypos(t);
    o << "<line x1=\"" << num(left) << "\" x2=\"" << num(left + plot_w) << "\" y1=\"" << num(y) << "\" y2=\"" << num(y)
      << "\" stroke=\"#ddd\"/><text x=\"" << num(left - 6) << "\" y=\"" << num(y + 4) << "\" text-anchor=\"end\">"
      << tick_label(t) << "</text>\n";
  }
  o << "<line x1=\"" << num(left) << "\" x2=\"" << num(left) << "\" y1=\"" << num(y0) << "\" y2=\"" << num(y0 + plot_h)
    << "\" stroke=\"black\"/>\n";
  o << "<line x1=\"" << num(left) << "\" x2=\"" << num(left + plot_w) << "\" y1=\"" << num(base) << "\" y2=\""
    << num(base) << "\" stroke=\"black\"/>\n";
  o << "<text transform=\"translate(16," << num(y0 + plot_h / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
    << escape(chart.y_label) << (chart.log_scale ? " (log scale)" : "") << "</text>\n";
  // Bars, whiskers, group labels.
  const double used = static_cast<double>(ns) * bar_w;
  const double slot = plot_w / std::max<double>(1.0, static_cast<double>(ng));
  for (std::size_t g = 0; g < ng; ++g) {
    const double gx = left + slot * static_cast<double>(g) + (slot - used) / 2;
    for (std::size_t s = 0; s < ns; ++s) {
      const BarSeries& ser = chart.series[s];
      const double v = ser.values[g];
      if (!std::isfinite(v) || (chart.log_scale && v <= 0.0)) continue;
      const double x = gx + static_cast<double>(s) * bar_w;
      const double y = ypos(v);
      o << "<rect x=\"" << num(x + 1) << "\" y=\"" << num(std::min(y, base)) << "\" width=\"" << num(bar_w - 2)
        << "\" height=\"" << num(std::abs(base - y)) << "\" fill=\"" << kPalette[s % std::size(kPalette)]
        << "\"><title>" << escape(ser.name + " / " + chart.groups[g] + ": " + tick_label(v)) << "</title></rect>\n";
      if (!ser.low.empty() && !ser.high.empty() && std::isfinite(ser.low[g]) && std::isfinite(ser.high[g])) {
        const double xc = x + bar_w / 2, ya = ypos(ser.low[g]), yb = ypos(ser.high[g]);
        o << "<path d=\"M" << num(xc) << " " << num(ya) << "V" << num(yb) << "M" << num(xc - 3) << " " << num(ya) << "H"
          << num(xc + 3) << "M" << num(xc - 3) << " " << num(yb) << "H" << num(xc + 3)
          << "\" stroke=\"black\" fill=\"none\"/>\n";
      }
    }
    const double lx = left + slot * (static_cast<double>(g) + 0.5), ly = y0 + plot_h + 14;
    o << "<text transform=\"translate(" << num(lx) << "," << num(ly) << ") rotate(-30)\" text-anchor=\"end\">"
      << escape(chart.groups[g]) << "</text>\n";
  }
  if (chart.reference_line) {
    const double y = ypos(*chart.reference_line);
    o << "<line x1=\"" << num(left) << "\" x2=\"" << num(left + plot_w) << "\" y1=\"" << num(y) << "\" y2=\"" << num(y)
      << "\" stroke=\"#c00\" stroke-dasharray=\"5,3\"/>\n";
    if (!chart.reference_label.empty())
      o << "<text x=\"" << num(left + plot_w - 4) << "\" y=\"" << num(y - 4) << "\" text-anchor=\"end\" fill=\"#c00\">"
        << escape(chart.reference_label) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

void write_svg(const BarChart& chart, const std::string& file) {
  write_output(file, render_svg(chart));
}

}  // namespace swept::bench
