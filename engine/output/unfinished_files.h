// The temporary files being written right now, so that a process about to die by a signal can
// remove them first (the `lamina` command on a second Ctrl-C) and leave no "<path>.tmp" behind.
// A temporary is registered before it is created and unregistered once it is renamed into place
// or removed, so every one that exists is registered.
//
// The table is fixed: max_unfinished_files paths of fewer than PATH_MAX (4096) bytes, in static
// storage, each with an atomic state, so remove_unfinished_files() needs no lock and no
// allocation and may run in a signal handler. Lamina has at most 6 temporaries open at once (a
// CSV trace and its contacts file, one frame per encoder thread, at most 4), far below the size.
// A file that finds the table full, or whose path is longer, is still written, committed and
// removed as usual; it is only not registered, and a signal that kills the process may leave its
// temporary behind.
#pragma once

#include <cstddef>
#include <filesystem>

namespace lamina {

inline constexpr std::size_t max_unfinished_files = 32;

// The registration of one temporary file, from before it is created until it is gone.
class UnfinishedFile {
 public:
  // Registers `temporary`, which the caller is about to create (see above when it is not).
  explicit UnfinishedFile(const std::filesystem::path& temporary);
  ~UnfinishedFile() { finished(); }
  UnfinishedFile(const UnfinishedFile&) = delete;
  UnfinishedFile& operator=(const UnfinishedFile&) = delete;

  // The file has been renamed into place or removed: unregisters it (once; later calls do
  // nothing).
  void finished();

 private:
  int row_ = -1;  // its row in the table, -1 when not registered
};

// Removes every registered temporary file with unlink(), the only call it makes besides lock-free
// atomics: async-signal-safe. Leaves the files registered (their writers find them gone) and
// errno as it was. A file another thread creates after the call is not removed, so a process
// should die right after it (the `lamina` command re-raises the signal).
void remove_unfinished_files();

}  // namespace lamina
