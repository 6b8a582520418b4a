#include "trace/trace_writer.h"

#include "trace/trace_csv.h"
#include "trace/trace_json.h"

namespace lamina {

TraceWriter::TraceWriter(const std::filesystem::path& path) : csv_(path.extension() == ".csv") {
  files_.push_back(std::make_unique<OutputFile>(path));
  if (!csv_) return;
  files_.push_back(std::make_unique<OutputFile>(contacts_csv_path(path)));
  files_[0]->write(trace_csv_body_header());
  files_[1]->write(trace_csv_contact_header());
}

void TraceWriter::write(const TraceStep& step) {
  if (!csv_) {
    files_[0]->write(trace_json_line(step) + "\n");
    return;
  }
  files_[0]->write(trace_csv_body_rows(step));
  files_[1]->write(trace_csv_contact_rows(step));
}

void TraceWriter::finish() {
  for (const auto& file : files_) file->commit();
}

std::vector<std::filesystem::path> TraceWriter::paths() const {
  std::vector<std::filesystem::path> paths;
  for (const auto& file : files_) paths.push_back(file->path());
  return paths;
}

std::filesystem::path contacts_csv_path(const std::filesystem::path& path) {
  return std::filesystem::path(path).replace_extension(".contacts.csv");
}

}  // namespace lamina
