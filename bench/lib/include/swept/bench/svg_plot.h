#pragma once
/// A small SVG chart writer for the CLI's reports (`swept bench paper`): grouped bar charts with
/// optional min–max whiskers, a linear or logarithmic value axis and a reference line. Output is
/// a self-contained SVG document that any browser or Markdown viewer opens.
#include <optional>
#include <string>
#include <vector>

namespace swept::bench {

/// One series of a grouped bar chart: one value per group (NaN: no bar for that group).
struct BarSeries {
  std::string name;
  std::vector<double> values;
  std::vector<double> low;   ///< optional whisker bottoms (same length as values, or empty)
  std::vector<double> high;  ///< optional whisker tops (same length as values, or empty)
};

/// A grouped bar chart: groups along the x axis, one bar per series in each group.
struct BarChart {
  std::string title;
  std::string y_label;
  std::vector<std::string> groups;
  std::vector<BarSeries> series;
  bool log_scale = false;                 ///< logarithmic value axis (values must be > 0)
  std::optional<double> reference_line;   ///< e.g. 1.0 for speed-ups
  std::string reference_label;
};

/// Renders the chart as an SVG document. Throws std::runtime_error when a series' length does
/// not match the groups, or when a log-scale chart has no positive value.
std::string render_svg(const BarChart& chart);

/// Writes `render_svg(chart)` to `file`. Throws std::runtime_error naming the file on failure.
void write_svg(const BarChart& chart, const std::string& file);

}  // namespace swept::bench
