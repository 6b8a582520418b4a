#include "output/unfinished_files.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>

namespace lamina {
namespace {

// A row's state. Its owner moves it free -> filling -> registered -> free;
// remove_unfinished_files() moves it registered -> removing -> registered. Each move is a
// compare-and-swap, so the remover never reads a path while it is written, and the owner never
// reuses a row whose path the remover is reading.
enum State : int { free_row, filling, registered, removing };

struct Row {
  std::atomic<int> state{free_row};
  char path[PATH_MAX];  // the temporary file, NUL-terminated, while registered or removing
};

// Lock-free atomics are async-signal-safe; a lock-based one would not be.
static_assert(std::atomic<int>::is_always_lock_free);

Row table[max_unfinished_files];

}  // namespace

UnfinishedFile::UnfinishedFile(const std::filesystem::path& temporary) {
  const std::string& text = temporary.native();
  if (text.size() >= PATH_MAX) return;
  for (std::size_t row = 0; row < max_unfinished_files; ++row) {
    int expected = free_row;
    if (!table[row].state.compare_exchange_strong(expected, filling)) continue;
    std::memcpy(table[row].path, text.c_str(), text.size() + 1);
    table[row].state.store(registered);
    row_ = static_cast<int>(row);
    return;
  }
}

void UnfinishedFile::finished() {
  if (row_ < 0) return;
  std::atomic<int>& state = table[row_].state;
  int expected = registered;
  // Fails only while remove_unfinished_files() on another thread unlinks this row's file: one
  // system call, after which the row is registered again.
  while (!state.compare_exchange_weak(expected, free_row)) expected = registered;
  row_ = -1;
}

void remove_unfinished_files() {
  const int saved_errno = errno;
  for (Row& row : table) {
    int expected = registered;
    if (!row.state.compare_exchange_strong(expected, removing)) continue;
    unlink(row.path);
    row.state.store(registered);
  }
  errno = saved_errno;
}

}  // namespace lamina
