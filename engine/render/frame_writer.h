// The second half of the frame pipeline: PNG encoding and writing on worker threads, fed plain
// RGB images by the GL thread through a bounded queue. Each file's bytes depend only on its
// image, never on which worker wrote it or when.
#pragma once

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/image.h"

namespace lamina::render {

class FrameWriter {
 public:
  // `workers` threads (at least 1) and at most `capacity` images waiting (at least 1).
  FrameWriter(int workers, std::size_t capacity);
  // Waits for the queued frames, then stops the workers. Errors are reported by finish().
  ~FrameWriter();
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  // Queues `image` to be written to `path` as PNG, waiting while the queue is full.
  // Throws OutputError as soon as a worker has failed, so the caller stops rendering.
  void submit(std::filesystem::path path, Image image);
  // Waits until every queued frame is written; throws OutputError for the first failure.
  void finish();

 private:
  struct Job {
    std::filesystem::path path;
    Image image;
  };

  void work();
  void throw_if_failed() const;  // caller holds mutex_

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::size_t capacity_;
  std::size_t busy_ = 0;  // jobs taken by a worker and not yet done
  bool stopping_ = false;
  std::string error_;  // the first failure, empty while all is well
  std::vector<std::thread> workers_;
};

}  // namespace lamina::render
