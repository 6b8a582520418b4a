// An output file that is complete or absent: written under a temporary name beside it and
// renamed into place by commit() (atomic on one file system), so a reader never sees half a
// line, and a run that fails or dies before commit() leaves nothing at the path.
#pragma once

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace lamina {

// An output path that cannot be written; the message is one line naming it and why.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputFile {
 public:
  // Creates the missing parent folders and opens the temporary file "<path>.tmp". Throws
  // OutputFileError when the path is a folder or a device, or cannot be written.
  explicit OutputFile(std::filesystem::path path);
  // Removes the temporary file unless commit() succeeded.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Throws OutputFileError when the text cannot be written (a full disk).
  void write(std::string_view text);
  // Closes the temporary file and renames it to the path. Throws OutputFileError on failure,
  // having removed the temporary file.
  void commit();

  const std::filesystem::path& path() const { return path_; }

 private:
  [[noreturn]] void fail(const std::string& why);

  std::filesystem::path path_;       // where the file goes when complete
  std::filesystem::path temporary_;  // where it is written until then
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace lamina
