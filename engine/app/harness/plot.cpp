#include "app/harness/plot.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "output/output_file.h"

namespace lamina::tutorial {
namespace fs = std::filesystem;
namespace {

std::string csv_text(const Plot& plot) {
  std::ostringstream out;
  out << plot.x_label;
  for (const Series& s : plot.series) out << "," << s.name;
  out << "\n";
  for (const std::vector<double>& row : plot.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      char number[32];
      std::snprintf(number, sizeof number, "%.9g", row[i]);
      out << (i ? "," : "") << number;
    }
    out << "\n";
  }
  return out.str();
}

bool gnuplot_on_path() {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (!folder.empty() && access((fs::path(folder) / "gnuplot").c_str(), X_OK) == 0) return true;
  }
  return false;
}

// A gnuplot string literal: single quotes, with inner ones doubled.
std::string literal(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

std::string hex(render::Colour c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02X%02X%02X", c.r, c.g, c.b);
  return text;
}

std::string gnuplot_script(const Plot& plot, const fs::path& csv, const fs::path& png) {
  std::ostringstream s;
  s << "set terminal pngcairo size 1280,720 noenhanced font 'DejaVu Sans,16'\n"
    << "set output " << literal(png.string()) << "\n"
    << "set datafile separator ','\n"
    << "set key " << plot.legend << " opaque box\n"
    << (plot.log_y ? "set logscale y\nset format y '%.0e'\n" : "")
    << "set grid lc rgb '#E2E2DE'\n"
    << "set title " << literal(plot.title) << "\n"
    << "set xlabel " << literal(plot.x_label) << "\n"
    << "set ylabel " << literal(plot.y_label) << "\n"
    << "plot ";
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const Series& series = plot.series[i];
    s << (i ? ", " : "") << literal(csv.string()) << " using 1:" << i + 2
      << " with lines lw 3 lc rgb '" << hex(series.colour) << "' dt " << (series.dashed ? 2 : 1)
      << " title " << literal(series.name);
  }
  s << "\n";
  return s.str();
}

// Runs gnuplot, which draws the plot into `png`; returns an empty string when it has, else why not.
std::string run_gnuplot(const Plot& plot, const fs::path& csv, const fs::path& png) {
  std::FILE* gnuplot = popen("gnuplot", "w");
  if (gnuplot == nullptr) return "cannot start gnuplot";
  const std::string script = gnuplot_script(plot, csv, png);
  std::fwrite(script.data(), 1, script.size(), gnuplot);
  return pclose(gnuplot) == 0 ? "" : "gnuplot could not draw it";
}

}  // namespace

void write_plot(const fs::path& folder, const Plot& plot) {
  const fs::path csv = folder / (plot.name + ".csv"), png = folder / (plot.name + ".png");
  write_file_atomically(csv, csv_text(plot));
  if (gnuplot_on_path()) {
    make_file_atomically(
        png, [&](const fs::path& temporary) { return run_gnuplot(plot, csv, temporary); });
  } else {
    std::cout << "wrote " << csv.string() << "; for the plot " << png.filename().string()
              << " install gnuplot (sudo apt-get install gnuplot-nox) and run again\n";
  }
}

}  // namespace lamina::tutorial
