#include "output/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cstring>
#include <fstream>
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
  descriptor_ = ::open(file_.temporary().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (descriptor_ < 0) throw cannot_write(file_.path(), std::strerror(errno));
}

OutputFile::~OutputFile() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

void OutputFile::write(std::string_view text) {
  if (size_ == 0 && held_ == 0) {  // the first piece, maybe the whole file: as it is
    hand_over(text);
    return;
  }
  while (!text.empty()) {
    const std::size_t to_gather = to_bound() - held_;  // for the block to be whole
    if (held_ == 0 && text.size() >= to_gather) {  // whole blocks straight from the text
      const std::size_t whole = to_gather + (text.size() - to_gather) / write_block * write_block;
      hand_over(text.substr(0, whole));
      text.remove_prefix(whole);
      continue;
    }
    const std::size_t taken = std::min(to_gather, text.size());
    std::memcpy(room(taken), text.data(), taken);
    text.remove_prefix(taken);
    wrote(taken);
  }
}

char* OutputFile::room(std::size_t size) {
  assert(size <= room_limit);
  (void)size;  // the block has room_limit bytes past its end: held_ is below to_bound()
  return block() + held_;
}

void OutputFile::wrote(std::size_t size) {
  held_ += size;
  const std::size_t whole = to_bound();
  if (held_ < whole) return;
  hand_over({block_.get(), whole});  // the block up to the bound
  held_ -= whole;
  std::memmove(block_.get(), block_.get() + whole, held_);  // what was written past it
}

char* OutputFile::block() {
  if (!block_) block_ = std::make_unique<char[]>(write_block + room_limit);
  return block_.get();
}

void OutputFile::hand_over(std::string_view text) {
  reserve_for(text.size());
  const char* next = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t written = ::write(descriptor_, next, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail(written < 0 ? std::strerror(errno) : "nothing written");
    next += written;
    left -= static_cast<std::size_t>(written);
  }
  size_ += text.size();
}

// Space for `size` more bytes, reserved ahead once the file is written in more than one piece
// (a file written whole, such as a frame, reserves nothing). The reservation is only a help: a
// file system that refuses it (one without fallocate, a full disk) is not asked again, and
// the write itself says whether the bytes fit.
void OutputFile::reserve_for(std::size_t size) {
#if defined(__linux__)
  if (size_ == 0 || size_ + size <= reserved_ || !can_reserve_) return;
  const std::uint64_t end = size_ + size + reserve_block;
  const auto from = static_cast<off_t>(size_);
  const auto length = static_cast<off_t>(end - size_);
  can_reserve_ = ::fallocate(descriptor_, FALLOC_FL_KEEP_SIZE, from, length) == 0;
  if (can_reserve_) reserved_ = end;
#else
  (void)size;
#endif
}

void OutputFile::commit() {
  if (held_ > 0) {
    hand_over({block_.get(), held_});
    held_ = 0;
  }
  // The space reserved past the end is given back: the file holds what was written.
  if (reserved_ > size_ && ::ftruncate(descriptor_, static_cast<off_t>(size_)) != 0) {
    fail(std::strerror(errno));
  }
  const int closed = ::close(descriptor_);
  descriptor_ = -1;
  if (closed != 0) fail(std::strerror(errno));
  file_.commit();
}

void OutputFile::fail(const std::string& why) {
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = -1;
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
