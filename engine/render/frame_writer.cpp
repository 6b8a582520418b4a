#include "render/frame_writer.h"

#include <algorithm>

#include "output/output_file.h"
#include "render/png_codec.h"

namespace lamina::render {

FrameWriter::FrameWriter(int workers, std::size_t capacity)
    : capacity_(std::max<std::size_t>(capacity, 1)) {
  for (int i = 0; i < std::max(workers, 1); ++i) workers_.emplace_back([this] { work(); });
}

FrameWriter::~FrameWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void FrameWriter::throw_if_failed() const {
  if (!error_.empty()) throw OutputError(error_);
}

void FrameWriter::submit(std::filesystem::path path, Image image) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < capacity_ || !error_.empty(); });
  throw_if_failed();
  queue_.push_back({std::move(path), std::move(image)});
  changed_.notify_all();
}

void FrameWriter::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return (queue_.empty() && busy_ == 0) || !error_.empty(); });
  throw_if_failed();
}

void FrameWriter::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return !queue_.empty() || stopping_; });
    if (queue_.empty()) return;
    Job job = std::move(queue_.front());
    queue_.pop_front();
    ++busy_;
    changed_.notify_all();
    lock.unlock();
    std::string failure;
    try {
      write_file_atomically(job.path, encode_png(job.image));
    } catch (const std::exception& e) {
      failure = e.what();
    }
    lock.lock();
    --busy_;
    if (error_.empty()) error_ = failure;
    changed_.notify_all();
  }
}

}  // namespace lamina::render
