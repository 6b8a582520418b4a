// Output files that are complete or absent: a file is written under a temporary name beside it,
// "<path>.tmp", and renamed into place when whole (atomic on one file system), so a reader never
// sees half a file, and a run that fails or dies before then leaves nothing at the path.
// Traces stream through an OutputFile; frames and plot data are written whole by
// write_file_atomically(), through the same OutputFile.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lamina {

// An output folder or file that cannot be made or written; the message is one line naming it
// and why.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputFile {
 public:
  // Creates the missing parent folders and opens the temporary file. Throws OutputError when
  // the path is a folder or a device, or cannot be written.
  explicit OutputFile(std::filesystem::path path);
  // Removes the temporary file unless commit() succeeded.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Throws OutputError when the text cannot be written (a full disk, a file size limit).
  void write(std::string_view text);
  // Closes the temporary file and renames it to the path. Throws OutputError on failure,
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

// Writes `text` or `bytes` to `path` through an OutputFile. On failure the temporary file is
// removed and OutputError is thrown: `path` is never left half written.
void write_file_atomically(const std::filesystem::path& path, std::string_view text);
void write_file_atomically(const std::filesystem::path& path,
                           const std::vector<std::uint8_t>& bytes);

// Creates `folder` (and its parents) if needed and checks that a file can be written in it.
// Throws OutputError when it is a file, cannot be created or is not writable; leaves no file.
void prepare_output_folder(const std::filesystem::path& folder);

// The temporary name an OutputFile for `path` is written under: "<path>.tmp".
std::filesystem::path temporary_path(const std::filesystem::path& path);

}  // namespace lamina
