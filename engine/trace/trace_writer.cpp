#include "trace/trace_writer.h"

#include "trace/trace_csv.h"
#include "trace/trace_json.h"

namespace lamina {
namespace {

// A trace's file as the sink of its JSON lines: the text written in the file's block.
static_assert(TextSink::room_limit <= OutputFile::room_limit, "the file gives the room asked");
class FileSink : public TextSink {
 public:
  explicit FileSink(OutputFile& file) : file_(file) {}
  char* room(std::size_t size) override { return file_.room(size); }
  void wrote(std::size_t size) override { file_.wrote(size); }

 private:
  OutputFile& file_;
};

}  // namespace

TraceWriter::TraceWriter(const std::filesystem::path& path) : csv_(path.extension() == ".csv") {
  files_.push_back(std::make_unique<OutputFile>(path));
  if (!csv_) return;
  files_.push_back(std::make_unique<OutputFile>(contacts_csv_path(path)));
  files_[0]->write(trace_csv_body_header());
  files_[1]->write(trace_csv_contact_header());
}

void TraceWriter::write(const TraceStep& step) {
  if (!csv_) {
    FileSink sink(*files_[0]);
    write_trace_json_line(sink, step);
    files_[0]->write("\n");
    return;
  }
  text_.clear();  // keeps its capacity: a pyramid's step is about 330 kB of text
  append_trace_csv_body_rows(text_, step);
  files_[0]->write(text_);
  text_.clear();
  append_trace_csv_contact_rows(text_, step);
  files_[1]->write(text_);
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
