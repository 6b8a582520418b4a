#include "output/output_file.h"

#include <cerrno>
#include <cstring>
#include <system_error>

namespace lamina {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

OutputError cannot_write(const fs::path& path, const std::string& why) {
  return OutputError("cannot write " + quoted(path) + ": " + why);
}

// The path's folder exists (made if missing) and the path is not a folder or a device.
void check_destination(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status)) throw cannot_write(path, "it is a folder");
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw cannot_write(path, "it is not a regular file");
  }
  const fs::path folder = path.parent_path();
  if (!folder.empty() && !fs::is_directory(folder, error)) {
    fs::create_directories(folder, error);
    if (error) {
      throw cannot_write(path, "cannot create folder " + quoted(folder) + ": " + error.message());
    }
  }
}

// Makes and removes an empty file in `folder`, so that a folder nothing can be written in is
// refused before the run, not at its first file.
void check_writable(const fs::path& folder) {
  const fs::path probe = folder / ".lamina-write-test";
  if (!std::ofstream(probe, std::ios::binary)) {
    const std::string why = std::strerror(errno);
    throw OutputError("cannot write in output folder " + quoted(folder) + ": " + why);
  }
  std::error_code ignored;
  fs::remove(probe, ignored);
}

}  // namespace

TemporaryFile::TemporaryFile(fs::path path)
    : path_(std::move(path)), temporary_(temporary_path(path_)), unfinished_(temporary_) {
  check_destination(path_);
}

TemporaryFile::~TemporaryFile() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void TemporaryFile::commit() {
  std::error_code error;
  fs::rename(temporary_, path_, error);
  if (error) fail(error.message());
  unfinished_.finished();
  committed_ = true;
}

void TemporaryFile::fail(const std::string& why) {
  std::error_code ignored;
  fs::remove(temporary_, ignored);
  throw cannot_write(path_, why);
}

OutputFile::OutputFile(fs::path path) : file_(std::move(path)) {
  out_.open(file_.temporary(), std::ios::binary | std::ios::trunc);
  if (!out_) throw cannot_write(file_.path(), std::strerror(errno));
}

void OutputFile::write(std::string_view text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out_) fail(std::strerror(errno));
}

void OutputFile::commit() {
  out_.close();
  if (!out_) fail(std::strerror(errno));
  file_.commit();
}

void OutputFile::fail(const std::string& why) {
  out_.close();
  file_.fail(why);
}

void write_file_atomically(const fs::path& path, std::string_view text) {
  OutputFile file(path);
  file.write(text);
  file.commit();
}

void write_file_atomically(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  write_file_atomically(path, text);
}

void make_file_atomically(const fs::path& path,
                          const std::function<std::string(const fs::path&)>& make) {
  TemporaryFile file(path);
  const std::string why = make(file.temporary());
  if (!why.empty()) file.fail(why);
  file.commit();
}

void prepare_output_folder(const fs::path& folder) {
  std::error_code error;
  if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
    throw OutputError("output folder " + quoted(folder) + " is a file, not a folder");
  }
  fs::create_directories(folder, error);
  if (error) {
    throw OutputError("cannot create output folder " + quoted(folder) + ": " + error.message());
  }
  check_writable(folder);
}

fs::path temporary_path(const fs::path& path) {
  fs::path temporary = path;
  temporary += ".tmp";
  return temporary;
}

}  // namespace lamina
