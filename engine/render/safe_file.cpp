#include "render/safe_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace lamina::render {
namespace fs = std::filesystem;
namespace {

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// Writes the bytes to a new file; false with errno set when any step fails.
bool write_all(const fs::path& path, const void* data, std::size_t size) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) return false;
  const bool written = std::fwrite(data, 1, size, file) == size;
  const int write_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written) errno = write_errno;
  return written && closed;
}

void write_bytes_atomically(const fs::path& path, const void* data, std::size_t size) {
  const fs::path temporary = temporary_path(path);
  if (!write_all(temporary, data, size)) {
    const std::string reason = std::strerror(errno);
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw OutputError("cannot write " + quoted(path) + ": " + reason);
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw OutputError("cannot write " + quoted(path) + ": " + ec.message());
  }
}

}  // namespace

fs::path temporary_path(const fs::path& path) {
  fs::path temporary = path;
  temporary += ".tmp";
  return temporary;
}

void prepare_output_folder(const fs::path& folder) {
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw OutputError("output folder " + quoted(folder) + " is a file, not a folder");
  }
  fs::create_directories(folder, ec);
  if (ec) throw OutputError("cannot create output folder " + quoted(folder) + ": " + ec.message());
  const fs::path probe = folder / ".lamina-write-test";
  if (!write_all(probe, "", 0)) {
    throw OutputError("cannot write in output folder " + quoted(folder) + ": " +
                      std::strerror(errno));
  }
  fs::remove(probe, ec);
}

void write_file_atomically(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  write_bytes_atomically(path, bytes.data(), bytes.size());
}

void write_file_atomically(const fs::path& path, std::string_view text) {
  write_bytes_atomically(path, text.data(), text.size());
}

}  // namespace lamina::render
