// Writing a trace as the run goes: JSON Lines (trace_json.h), or CSV (trace_csv.h) when the
// path ends in ".csv": bodies in FILE.csv, contacts in FILE.contacts.csv. Nothing appears at
// the paths until finish(), which puts the steps written so far in place, whole: at the end of
// a run, or of one stopped early that keeps what it has (a diverged step, Ctrl-C). A writer
// destroyed unfinished, as when a write fails, leaves no trace file (output/output_file.h).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "output/output_file.h"
#include "trace/trace.h"

namespace lamina {

class TraceWriter {
 public:
  // Opens the trace's temporary file(s). Throws OutputError when a path cannot be written.
  explicit TraceWriter(const std::filesystem::path& path);

  // Appends one step. Throws OutputError when the disk refuses it.
  void write(const TraceStep& step);
  // Puts the file(s) in place, holding every step written. Throws OutputError on failure.
  void finish();

  // The file(s) the trace goes to: the path, and for CSV the contacts file after it.
  std::vector<std::filesystem::path> paths() const;

 private:
  bool csv_;                                   // CSV (two files) rather than JSON Lines (one)
  std::vector<std::unique_ptr<OutputFile>> files_;  // JSON Lines; or CSV bodies, CSV contacts
  std::string text_;                           // the text of a CSV step being written
};

// The contacts file of a CSV trace: "run.csv" → "run.contacts.csv".
std::filesystem::path contacts_csv_path(const std::filesystem::path& path);

}  // namespace lamina
