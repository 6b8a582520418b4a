// Output files that are complete or absent: a file is written under a temporary name beside it,
// "<path>.tmp", and renamed into place when whole (atomic on one file system), so a reader never
// sees half a file, and a run that fails or dies before then leaves nothing at the path.
// Traces stream through an OutputFile; frames and plot data are written whole by
// write_file_atomically(), through the same OutputFile; a file another program writes (a plot
// gnuplot draws) goes through make_file_atomically(). All three share one TemporaryFile, which
// registers the temporary as unfinished (unfinished_files.h) while it exists.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "output/unfinished_files.h"

namespace lamina {

// An output folder or file that cannot be made or written; the message is one line naming it
// and why.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The temporary file "<path>.tmp" a file is written under until it is whole: registered as
// unfinished from before it is created, renamed to the path by commit(), removed otherwise.
class TemporaryFile {
 public:
  // Creates the missing parent folders and registers the temporary; creates no file. Throws
  // OutputError when the path is a folder or a device, or its folder cannot be made.
  explicit TemporaryFile(std::filesystem::path path);
  // Removes the temporary file unless commit() succeeded.
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  // Renames the temporary file to the path. Throws OutputError on failure, having removed the
  // temporary file.
  void commit();
  // Removes the temporary file and throws OutputError: "cannot write '<path>': <why>".
  [[noreturn]] void fail(const std::string& why);

  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  std::filesystem::path path_;       // where the file goes when complete
  std::filesystem::path temporary_;  // where it is written until then
  UnfinishedFile unfinished_;        // the temporary's registration, until renamed or removed
  bool committed_ = false;
};

class OutputFile {
 public:
  // Creates the missing parent folders and opens the temporary file. Throws OutputError when
  // the path is a folder or a device, or cannot be written.
  explicit OutputFile(std::filesystem::path path);
  // Closes the temporary file, then removes it unless commit() succeeded (file_'s destructor).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Throws OutputError when the text cannot be written (a full disk, a file size limit); the
  // pieces after the first are gathered into blocks (see below), so such an error may come
  // from a later write() or from commit().
  // A file written in more than one piece (a trace, a step at a time) has its disk space
  // reserved ahead of it, reserve_block bytes at a time (see below).
  void write(std::string_view text);
  // Text written in place, for a writer that formats straight into the file: room for `size`
  // bytes (at most room_limit) after what is written or gathered so far, in the block handed
  // to the kernel (see below); wrote() then takes the first `size` of them, and the writer
  // asks for room again before it writes more. Throws OutputError as write() does.
  char* room(std::size_t size);
  void wrote(std::size_t size);
  static constexpr std::size_t room_limit = std::size_t{16} << 10;
  // Hands over what is gathered, closes the temporary file and renames it to the path. Throws
  // OutputError on failure, having removed the temporary file.
  void commit();

  const std::filesystem::path& path() const { return file_.path(); }

  // The disk space a growing file reserves at a time, past its end (Linux's fallocate, keeping
  // the file's size; given back at commit()). Writing into reserved space spares the kernel the
  // accounting of each new block that ext4 (its delayed allocation) does in every write that
  // grows a file: pyramid:20's trace, 330 kB a step, costs 8 % less CPU time so
  // (docs/performance.md, "Traces"). Where the file system cannot reserve, files grow as before.
  static constexpr std::uint64_t reserve_block = std::uint64_t{32} << 20;
  // The pieces after the first are handed to the kernel in blocks of this size, each at an
  // offset that is a multiple of it (the first block ends at one): written so, pyramid:20's
  // trace costs the kernel a quarter less CPU time than in pieces of a step's 330 kB, the copy
  // into the block included (Linux 6.18 on ext4; docs/performance.md, "Traces"). A file
  // written whole (a frame) is written as it is.
  static constexpr std::size_t write_block = std::size_t{1} << 20;

 private:
  void hand_over(std::string_view text);  // to the kernel, space reserved ahead
  // Bytes from what the kernel has to the next multiple of write_block, where a block ends.
  std::size_t to_bound() const { return write_block - size_ % write_block; }
  char* block();                          // block_, made on first use
  void reserve_for(std::size_t size);
  [[noreturn]] void fail(const std::string& why);

  TemporaryFile file_;            // the path and the temporary written until commit()
  int descriptor_ = -1;           // open on file_.temporary() until commit() or a failure
  std::uint64_t size_ = 0;        // bytes handed to the kernel
  std::uint64_t reserved_ = 0;    // the end of the space reserved, 0 while none is
  bool can_reserve_ = true;       // false once the file system has refused to reserve
  std::unique_ptr<char[]> block_; // write_block bytes and room_limit after them
  std::size_t held_ = 0;          // bytes gathered in block_, to follow the first size_
};

// Writes `text` or `bytes` to `path` through an OutputFile. On failure the temporary file is
// removed and OutputError is thrown: `path` is never left half written.
void write_file_atomically(const std::filesystem::path& path, std::string_view text);
void write_file_atomically(const std::filesystem::path& path,
                           const std::vector<std::uint8_t>& bytes);

// Calls `make` with the temporary path "<path>.tmp" to write the file there, e.g. by telling
// another program to; `make` returns an empty string when it has, else why not. Then renames the
// temporary to `path`. When `make` fails or throws, or the rename fails, the temporary is
// removed and nothing is left at `path`; a failure is thrown as OutputError,
// "cannot write '<path>': <why>".
void make_file_atomically(const std::filesystem::path& path,
                          const std::function<std::string(const std::filesystem::path&)>& make);

// Creates `folder` (and its parents) if needed and checks that a file can be written in it.
// Throws OutputError when it is a file, cannot be created or is not writable; leaves no file.
void prepare_output_folder(const std::filesystem::path& folder);

// The temporary name a file for `path` is written under: "<path>.tmp".
std::filesystem::path temporary_path(const std::filesystem::path& path);

}  // namespace lamina
