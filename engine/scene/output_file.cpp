#include "scene/output_file.h"

#include <cerrno>
#include <cstring>
#include <system_error>

namespace lamina {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

OutputFileError cannot_write(const fs::path& path, const std::string& why) {
  return OutputFileError("cannot write " + quoted(path) + ": " + why);
}

// The path's folder exists (made if missing) and the path is not a folder or a device.
void check_destination(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status)) throw cannot_write(path, "it is a folder");
  if (fs::exists(status) && !fs::is_regular_file(status)) throw cannot_write(path, "it is not a regular file");
  const fs::path folder = path.parent_path();
  if (!folder.empty() && !fs::is_directory(folder, error)) {
    fs::create_directories(folder, error);
    if (error) throw cannot_write(path, "cannot create folder " + quoted(folder) + ": " + error.message());
  }
}

}  // namespace

OutputFile::OutputFile(fs::path path) : path_(std::move(path)), temporary_(path_.string() + ".tmp") {
  check_destination(path_);
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw cannot_write(path_, std::strerror(errno));
}

OutputFile::~OutputFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void OutputFile::write(std::string_view text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out_) fail(std::strerror(errno));
}

void OutputFile::commit() {
  out_.close();
  if (!out_) fail(std::strerror(errno));
  std::error_code error;
  fs::rename(temporary_, path_, error);
  if (error) fail(error.message());
  committed_ = true;
}

void OutputFile::fail(const std::string& why) {
  out_.close();
  std::error_code ignored;
  fs::remove(temporary_, ignored);
  throw cannot_write(path_, why);
}

}  // namespace lamina
