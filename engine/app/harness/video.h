// Frames as a video for slides (docs/slides.md): MP4 (H.264), WebM (VP9) or GIF (a palette made
// from the frames themselves), encoded by Debian's `ffmpeg` program, to which the frames are
// piped as raw RGB. The program rather than FFmpeg's libraries: the same encoders, and the GIF's
// two-pass palette (palettegen, paletteuse) is one filter argument instead of a filter graph
// built by hand; what Lamina owns is the pipe and the checks.
//
// The file is complete or absent (engine/output): ffmpeg writes "<FILE>.tmp", renamed when it has
// finished and exited 0. A missing program or encoder, an extension that names no format, or a
// size the encoder refuses is one line (VideoError) before any frame is drawn.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "output/output_file.h"
#include "render/image.h"
#include "render/style.h"

namespace lamina::tutorial {

// A video that cannot be made: the message is one line naming the file and why (an output
// error: exit code 2).
class VideoError : public OutputError {
 public:
  using OutputError::OutputError;
};

// Checks that a video of this path, size and rate can be made here; throws VideoError if not.
void check_video(const std::filesystem::path& path, const render::FrameSize& size, int fps);

class VideoEncoder {
 public:
  // Starts ffmpeg writing `path`'s temporary file. Throws VideoError.
  VideoEncoder(const std::filesystem::path& path, const render::FrameSize& size, int fps);
  // Without finish(): stops ffmpeg and leaves nothing at the path.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  void add(const render::Image& frame);
  // Ends the stream, waits for ffmpeg and puts the file in place. Throws VideoError (nothing at
  // the path) when ffmpeg failed. Returns the frames written.
  int finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lamina::tutorial
