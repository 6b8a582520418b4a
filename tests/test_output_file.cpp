// Output files: an output folder that cannot be made or written is refused with one line, a
// file is complete or absent, and a write that fails leaves neither a partial file nor its
// temporary behind, also when the frame writer's threads write the frames.
#include <doctest/doctest.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>

#include "output/output_file.h"
#include "render/frame_writer.h"
#include "render_test_frame.h"

namespace {

using namespace lamina;
using namespace lamina::render;
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

Image small_image() { return Image{2, 2, std::vector<std::uint8_t>(12, 200)}; }

}  // namespace

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
