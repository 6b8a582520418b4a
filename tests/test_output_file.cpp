// Output files: an output folder that cannot be made or written is refused with one line, a
// file is complete or absent, and a write that fails leaves neither a partial file nor its
// temporary behind, also when the frame writer's threads write the frames or another program
// writes the file. Every temporary that exists is registered, so that a dying process can remove
// it (remove_unfinished_files(), the `lamina` command's second Ctrl-C), and no other.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "output/output_file.h"
#include "output/unfinished_files.h"
#include "render/frame_writer.h"
#include "render_test_frame.h"

namespace {

using namespace lamina;
using namespace lamina::render;
using lamina::Vec2;
namespace fs = std::filesystem;

// The message of the OutputError `action` throws; fails the test when it throws nothing.
template <typename Action>
std::string output_error(Action action) {
  try {
    action();
  } catch (const OutputError& e) {
    return e.what();
  }
  FAIL("no OutputError");
  return {};
}

void touch(const fs::path& path) { std::ofstream(path) << "x"; }

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t file_count(const fs::path& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), {}));
}

std::size_t temporary_count(const fs::path& folder) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() == ".tmp") ++count;
  }
  return count;
}

// The disk space a file holds, in bytes: st_blocks counts 512-byte units, reserved ones too.
std::uint64_t allocated_bytes(const fs::path& path) {
  struct stat status {};
  REQUIRE(::stat(path.c_str(), &status) == 0);
  return static_cast<std::uint64_t>(status.st_blocks) * 512;
}

// Whether the file system of `folder` reserves space past a file's end (fallocate, keeping the
// size), as ext4, XFS and tmpfs do.
bool can_reserve_in(const fs::path& folder) {
  const fs::path probe = folder / "probe";
  const int descriptor = ::open(probe.c_str(), O_WRONLY | O_CREAT, 0644);
  REQUIRE(descriptor >= 0);
  const bool reserved = ::fallocate(descriptor, FALLOC_FL_KEEP_SIZE, 0, 4096) == 0;
  ::close(descriptor);
  fs::remove(probe);
  return reserved;
}

Image small_image() { return Image{2, 2, std::vector<std::uint8_t>(12, 200)}; }

}  // namespace

// A trace's path in a scratch folder, and the temporary it is written under.
struct TraceTarget {
  explicit TraceTarget(const std::string& folder)
      : scratch(folder), path(scratch.path() / "trace.jsonl"), temporary(temporary_path(path)) {}
  testing::ScratchFolder scratch;
  fs::path path;
  fs::path temporary;
};

TEST_SUITE("OutputFile") {
  TEST_CASE("an output folder that is a file is refused with one line naming it") {
    const testing::ScratchFolder scratch("safe-file");
    const fs::path file = scratch.path() / "frames";
    touch(file);
    const std::string message = output_error([&] { prepare_output_folder(file); });
    CHECK(message.find(file.string()) != std::string::npos);
    CHECK(message.find("is a file") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(fs::is_regular_file(file));  // left as it was
  }

  TEST_CASE("a folder below a file cannot be created and nothing is left") {
    const testing::ScratchFolder scratch("safe-below");
    touch(scratch.path() / "file");
    const std::string message =
        output_error([&] { prepare_output_folder(scratch.path() / "file" / "frames"); });
    CHECK(message.find("cannot create output folder") != std::string::npos);
    CHECK(file_count(scratch.path()) == 1);
  }

  TEST_CASE("a folder the system does not let anyone create is refused") {
    // /proc refuses new folders even to root, so this holds whoever runs the tests.
    const std::string message = output_error([] { prepare_output_folder("/proc/lamina-frames"); });
    CHECK(message.find("/proc/lamina-frames") != std::string::npos);
  }

  TEST_CASE("a read-only folder is refused before anything is written") {
    if (geteuid() == 0) {
      MESSAGE("skipped: root writes into read-only folders (the /proc case above still runs)");
      return;
    }
    const testing::ScratchFolder scratch("safe-readonly");
    fs::permissions(scratch.path(), fs::perms::owner_read | fs::perms::owner_exec);
    const std::string message = output_error([&] { prepare_output_folder(scratch.path()); });
    CHECK(message.find("cannot write in output folder") != std::string::npos);
  }

  TEST_CASE("a committed file holds every piece written, in the folders made for it") {
    const testing::ScratchFolder scratch("output-commit");
    const fs::path target = scratch.path() / "new" / "run.jsonl";
    OutputFile file(target);
    file.write("first line\n");
    file.write("second line\n");
    CHECK_FALSE(fs::exists(target));  // nothing at the path before commit()
    file.commit();
    CHECK(contents(target) == "first line\nsecond line\n");
    CHECK(file_count(target.parent_path()) == 1);  // no temporary left
  }

  TEST_CASE("a file written in pieces has space reserved ahead of it, and none once committed") {
    const TraceTarget trace("output-reserve");
    const fs::path& temporary = trace.temporary;
    const std::string piece(100000, 'x');  // a third of a pyramid:20 trace's step
    OutputFile file(trace.path);
    file.write(piece);
    // One piece reserves nothing (a frame, written whole, would not use it): 100 kB in 4 KiB
    // blocks, far below the 32 MiB a reservation takes.
    CHECK(allocated_bytes(temporary) < std::uint64_t{1} << 20);
    for (int k = 1; k < 12; ++k) file.write(piece);  // 1.2 MB: the first block handed over
    if (can_reserve_in(trace.scratch.path())) {
      CHECK(allocated_bytes(temporary) >= OutputFile::write_block + OutputFile::reserve_block);
    } else {
      MESSAGE("not checked: this file system reserves no space (the commit is still checked)");
    }
    file.commit();
    // The reservation given back: the 1.2 MB written and the rest of their last block (4 KiB on
    // ext4; 64 KiB allows any block size in use).
    CHECK(fs::file_size(trace.path) == 12 * piece.size());
    CHECK(allocated_bytes(trace.path) < 12 * piece.size() + 64 * 1024);
    std::string all;
    for (int k = 0; k < 12; ++k) all += piece;
    CHECK(contents(trace.path) == all);
  }

  TEST_CASE("pieces after the first reach the file in whole blocks that end at block bounds") {
    // What the kernel has been handed shows in the temporary's size. The first piece goes as
    // it is (a file written whole is not held back); the others are gathered until the file
    // reaches a multiple of write_block, and a piece that spans blocks goes straight through,
    // up to the last bound it reaches; commit() hands over the rest.
    const TraceTarget trace("output-blocks");
    const fs::path& temporary = trace.temporary;
    const std::uint64_t block = OutputFile::write_block;
    std::string expected;
    const auto piece = [&expected](std::size_t size, char c) {
      const std::string text(size, c);
      expected += text;
      return text;
    };
    OutputFile file(trace.path);
    file.write(piece(100000, 'a'));
    CHECK(fs::file_size(temporary) == 100000);
    file.write(piece(300000, 'b'));
    file.write(piece(300000, 'c'));
    CHECK(fs::file_size(temporary) == 100000);  // held: the file is short of its first bound
    file.write(piece(700000, 'd'));             // reaches it: one block up to 1 MiB
    CHECK(fs::file_size(temporary) == block);
    file.write(piece(2 * block + 5000, 'e'));  // the held rest and two whole blocks
    CHECK(fs::file_size(temporary) == 3 * block);
    file.write(piece(10, 'f'));
    CHECK(fs::file_size(temporary) == 3 * block);
    file.commit();
    CHECK(fs::file_size(trace.path) == expected.size());
    CHECK(contents(trace.path) == expected);
  }

  TEST_CASE("text written in place reaches the file in the same blocks, pieces among it") {
    // A trace's JSON lines are written straight into the file's block (room, wrote); the
    // block is handed over whole at each bound, what was written past the bound kept for the
    // next, and pieces written by write() between join the same text, in order.
    const TraceTarget trace("output-in-place");
    std::string expected;
    OutputFile file(trace.path);
    std::uint64_t written = 0;
    for (int k = 0; k < 900; ++k) {  // 900 × (3001 + 1) bytes: 2.7 MB, two bounds passed
      char* room = file.room(4096);
      const std::string text(3001, static_cast<char>('a' + k % 26));
      std::memcpy(room, text.data(), text.size());
      file.wrote(text.size());
      file.write("\n");
      expected += text + "\n";
      written += text.size() + 1;
      CHECK(fs::file_size(trace.temporary) ==
            written / OutputFile::write_block * OutputFile::write_block);
    }
    file.commit();
    CHECK(contents(trace.path) == expected);
  }

  TEST_CASE("a file written whole is written as it is, in one piece") {
    const testing::ScratchFolder scratch("output-whole");
    const fs::path target = scratch.path() / "frame.png";
    OutputFile file(target);
    file.write(std::string(3 * OutputFile::write_block / 2, 'p'));  // not held back: not bound
    CHECK(fs::file_size(temporary_path(target)) == 3 * OutputFile::write_block / 2);
    file.commit();
    CHECK(fs::file_size(target) == 3 * OutputFile::write_block / 2);
  }

  TEST_CASE("a file destroyed before commit leaves nothing, not even its temporary") {
    const testing::ScratchFolder scratch("output-uncommitted");
    {
      OutputFile file(scratch.path() / "run.jsonl");
      file.write("a line\n");
    }
    CHECK(file_count(scratch.path()) == 0);
  }

  TEST_CASE("a path that is a folder or a device is refused with one line naming it") {
    const testing::ScratchFolder scratch("output-not-a-file");
    const fs::path target = scratch.path() / "frame_0000.png";
    fs::create_directory(target);  // a folder where the frame should go
    const std::string message =
        output_error([&] { write_file_atomically(target, std::vector<std::uint8_t>{1, 2, 3}); });
    CHECK(message == "cannot write '" + target.string() + "': it is a folder");
    CHECK(fs::is_directory(target));
    CHECK_FALSE(fs::exists(temporary_path(target)));
    CHECK(file_count(scratch.path()) == 1);
    CHECK(output_error([] { OutputFile file("/dev/null"); }) ==
          "cannot write '/dev/null': it is not a regular file");
  }

  TEST_CASE(
      "a commit that cannot be renamed into place leaves neither the file nor its "
      "temporary") {
    const testing::ScratchFolder scratch("output-rename");
    const fs::path target = scratch.path() / "trace.jsonl";
    OutputFile file(target);
    file.write("a line\n");
    fs::create_directory(target);  // a folder appears where the file should go: rename fails
    const std::string message = output_error([&] { file.commit(); });
    CHECK(message.rfind("cannot write '" + target.string() + "': ", 0) == 0);
    CHECK(fs::is_directory(target));
    CHECK_FALSE(fs::exists(temporary_path(target)));
    CHECK(file_count(scratch.path()) == 1);
  }

  TEST_CASE("the frame writer reports the first failed frame and leaves no partial file") {
    const testing::ScratchFolder scratch("safe-writer");
    fs::create_directory(scratch.path() / "frame_1.png");
    std::string message;
    {
      FrameWriter writer(2, 1);
      try {
        for (int i = 0; i < 3; ++i) {
          writer.submit(scratch.path() / ("frame_" + std::to_string(i) + ".png"), small_image());
        }
        writer.finish();
      } catch (const OutputError& e) {
        message = e.what();
      }
    }  // the writer's destructor waits for the frames other workers are still writing
    CHECK(message.find("frame_1.png") != std::string::npos);
    for (const auto& entry : fs::directory_iterator(scratch.path())) {
      CAPTURE(entry.path());
      CHECK(entry.path().extension() != ".tmp");
    }
  }
}

// remove_unfinished_files() is what a dying process calls; here it runs in the test itself, and
// what it removes shows what is registered. No test holds a registered file after it ends.
TEST_SUITE("Unfinished files") {
  TEST_CASE("an open file's temporary is removed, and nothing at its path") {
    const testing::ScratchFolder scratch("unfinished-open");
    const fs::path target = scratch.path() / "trace.jsonl";
    std::ofstream(target) << "the last run's trace\n";
    OutputFile file(target);
    file.write("a line\n");
    REQUIRE(fs::exists(temporary_path(target)));
    remove_unfinished_files();
    CHECK_FALSE(fs::exists(temporary_path(target)));
    CHECK(contents(target) == "the last run's trace\n");  // the complete file is not touched
    // Its writer finds the temporary gone: the commit fails with one line, the old file stays.
    const std::string message = output_error([&] { file.commit(); });
    CHECK(message.rfind("cannot write '" + target.string() + "': ", 0) == 0);
    CHECK(contents(target) == "the last run's trace\n");
  }

  TEST_CASE("a committed or destroyed file is no longer registered") {
    const testing::ScratchFolder scratch("unfinished-done");
    OutputFile committed(scratch.path() / "committed.jsonl");
    committed.commit();
    { OutputFile destroyed(scratch.path() / "destroyed.jsonl"); }
    // Files at their temporary names that are no longer theirs: they must stay.
    touch(temporary_path(scratch.path() / "committed.jsonl"));
    touch(temporary_path(scratch.path() / "destroyed.jsonl"));
    remove_unfinished_files();
    CHECK(temporary_count(scratch.path()) == 2);
  }

  TEST_CASE("a file that finds the table full is written all the same, only not registered") {
    const testing::ScratchFolder scratch("unfinished-full");
    std::vector<std::unique_ptr<OutputFile>> files;
    for (std::size_t i = 0; i <= max_unfinished_files; ++i) {
      files.push_back(std::make_unique<OutputFile>(scratch.path() / ("f" + std::to_string(i))));
    }
    remove_unfinished_files();
    // The first max_unfinished_files temporaries are removed; the one past the table is left.
    REQUIRE(temporary_count(scratch.path()) == 1);
    OutputFile& last = *files.back();
    CHECK(fs::exists(temporary_path(last.path())));
    last.write("whole\n");
    last.commit();
    CHECK(contents(last.path()) == "whole\n");
    files.clear();
    // The rows are free again once their files are gone.
    OutputFile next(scratch.path() / "next");
    remove_unfinished_files();
    CHECK_FALSE(fs::exists(temporary_path(next.path())));
  }
}

TEST_SUITE("make_file_atomically") {
  TEST_CASE("the file the maker writes at the temporary path lands at the path, whole") {
    const testing::ScratchFolder scratch("make-file");
    const fs::path target = scratch.path() / "plot.png";
    make_file_atomically(target, [&](const fs::path& temporary) {
      CHECK(temporary == temporary_path(target));
      CHECK_FALSE(fs::exists(target));  // nothing at the path while the maker writes
      std::ofstream(temporary) << "drawn";
      return std::string();
    });
    CHECK(contents(target) == "drawn");
    CHECK(file_count(scratch.path()) == 1);  // no temporary left
  }

  TEST_CASE("the maker's temporary is registered while it writes") {
    const testing::ScratchFolder scratch("make-registered");
    const fs::path target = scratch.path() / "plot.png";
    const std::string message = output_error([&] {
      make_file_atomically(target, [&](const fs::path& temporary) {
        std::ofstream(temporary) << "half drawn";
        remove_unfinished_files();  // as a dying process would
        CHECK_FALSE(fs::exists(temporary));
        return std::string();
      });
    });
    CHECK(message == "cannot write '" + target.string() + "': No such file or directory");
    CHECK(file_count(scratch.path()) == 0);
  }

  TEST_CASE("a maker that fails or throws leaves neither the file nor its temporary") {
    const testing::ScratchFolder scratch("make-fails");
    const fs::path target = scratch.path() / "plot.png";
    const auto half_drawn = [](const fs::path& temporary) { std::ofstream(temporary) << "half"; };
    CHECK(output_error([&] {
            make_file_atomically(target, [&](const fs::path& temporary) {
              half_drawn(temporary);
              return std::string("gnuplot could not draw it");
            });
          }) == "cannot write '" + target.string() + "': gnuplot could not draw it");
    CHECK(file_count(scratch.path()) == 0);
    CHECK_THROWS_AS(make_file_atomically(target,
                                         [&](const fs::path& temporary) -> std::string {
                                           half_drawn(temporary);
                                           throw std::runtime_error("the maker's own error");
                                         }),
                    std::runtime_error);
    CHECK(file_count(scratch.path()) == 0);
  }
}
