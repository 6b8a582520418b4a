// The benchmarks' tables written out: into a folder, and into a Markdown page between its
// markers (report.h).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "benchmarks/report.h"

namespace lamina {
namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error(path.string() + ": cannot be written");
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

void write_tables(const Tables& tables, const std::string& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw std::runtime_error(folder + ": cannot be created (" + error.message() + ")");
  for (const auto& [name, text] : tables) {
    const bool csv = name.size() > 4 && name.substr(name.size() - 4) == ".csv";
    write_file(std::filesystem::path(folder) / (csv ? name : name + ".md"), text);
  }
}

void update_doc(const Tables& tables, const std::string& doc) {
  std::string text = read_file(doc);
  for (const auto& [name, table] : tables) {
    const std::string begin = "<!-- begin generated: " + name + " -->\n";
    const std::string end = "<!-- end generated: " + name + " -->";
    const size_t from = text.find(begin);
    if (from == std::string::npos) continue;
    const size_t to = text.find(end, from);
    if (to == std::string::npos) {
      throw std::runtime_error(doc + ": \"" + begin + "\" has no end marker");
    }
    text.replace(from + begin.size(), to - from - begin.size(), table);
  }
  write_file(doc, text);
}

}  // namespace lamina
