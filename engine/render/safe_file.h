// Output files that are either complete or absent: write to a temporary name in the same
// folder, then rename (atomic on one file system).
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace lamina::render {

// An output folder or file that cannot be made or written; the message is one line naming it.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Creates `folder` (and its parents) if needed and checks that a file can be written in it.
// Throws OutputError when it is a file, cannot be created or is not writable; leaves no file.
void prepare_output_folder(const std::filesystem::path& folder);

// Writes `bytes` to `path.tmp`, then renames it to `path`. On failure the temporary file is
// removed and OutputError is thrown: `path` is never left half written.
void write_file_atomically(const std::filesystem::path& path,
                           const std::vector<std::uint8_t>& bytes);
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

// The temporary name write_file_atomically() uses for `path`.
std::filesystem::path temporary_path(const std::filesystem::path& path);

}  // namespace lamina::render
