// Plots a reader would rather look at than read: the data as CSV, drawn to PNG by gnuplot
// (pngcairo) when it is installed. Without gnuplot the CSV is still written and one line says
// how to get the plot.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/colour.h"

namespace lamina::tutorial {

// One plotted column: its CSV header and how its line looks.
struct Series {
  std::string name;  // CSV header, legend text, e.g. "E explicit (J)"
  render::Colour colour = render::palette::blue;
  bool dashed = false;
};

struct Plot {
  std::string name;  // file stem: <name>.csv, <name>.png
  std::string title;
  std::string x_label;  // the first CSV column's header, e.g. "t (s)"
  std::string y_label;
  std::vector<Series> series;             // the other columns
  std::vector<std::vector<double>> rows;  // x, then one value per series
  std::string legend = "top left";        // gnuplot's key position, e.g. "top right"
  bool log_y = false;                     // a logarithmic y axis (residuals, errors)
};

// Writes folder/<name>.csv, then folder/<name>.png with gnuplot when it is on PATH.
// Throws OutputError (output/output_file.h) when a file cannot be written or gnuplot fails.
void write_plot(const std::filesystem::path& folder, const Plot& plot);

}  // namespace lamina::tutorial
