#include "app/harness/video.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "output/output_file.h"

extern char** environ;

namespace lamina::tutorial {
namespace {

struct Container {
  const char* extension;
  const char* format;   // ffmpeg's -f
  const char* encoder;  // what `ffmpeg -encoders` must list
  bool even_sides;      // 4:2:0 colour: width and height even
};

constexpr Container containers[] = {{".mp4", "mp4", "libx264", true},
                                    {".webm", "webm", "libvpx-vp9", true},
                                    {".gif", "gif", "gif", false}};

const Container* container_of(const std::filesystem::path& path) {
  for (const Container& c : containers) {
    if (path.extension() == c.extension) return &c;
  }
  return nullptr;
}

// The ffmpeg program on the PATH, or empty.
std::string ffmpeg_program() {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(folder) / "ffmpeg";
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

// Whether ffmpeg lists the encoder (`ffmpeg -encoders`: " V..... libx264  ...").
bool has_encoder(const std::string& program, const std::string& encoder) {
  const std::string command = "'" + program + "' -hide_banner -encoders 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return false;
  std::string listing;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) listing.append(buffer, n);
  pclose(pipe);
  return listing.find(" " + encoder + " ") != std::string::npos;
}

std::string size_text(const render::FrameSize& size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

}  // namespace

void check_video(const std::filesystem::path& path, const render::FrameSize& size, int fps) {
  const Container* c = container_of(path);
  const std::string where = "--video '" + path.string() + "': ";
  if (c == nullptr) throw VideoError(where + "the file must end in .mp4, .webm or .gif");
  if (fps < 1 || fps > 240) throw VideoError(where + "--fps must be 1..240, got " + std::to_string(fps));
  if (c->even_sides && (size.width % 2 != 0 || size.height % 2 != 0)) {
    throw VideoError(where + "the " + c->encoder + " encoder needs even sides (4:2:0 colour), " +
                     size_text(size) + " has an odd one: choose another --size");
  }
  const std::string program = ffmpeg_program();
  if (program.empty()) throw VideoError(where + "no ffmpeg program on the PATH (Debian package ffmpeg)");
  if (!has_encoder(program, c->encoder)) {
    throw VideoError(where + "ffmpeg has no " + c->encoder + " encoder (Debian's ffmpeg has it)");
  }
}

struct VideoEncoder::Impl {
  TemporaryFile file;
  std::filesystem::path log;  // ffmpeg's messages, for the line a failure reports
  pid_t child = -1;
  int pipe_in = -1;           // ffmpeg's standard input
  int frames = 0;
  void (*old_sigpipe)(int) = SIG_DFL;

  Impl(const std::filesystem::path& path, const render::FrameSize& size, int fps) : file(path) {
    check_video(path, size, fps);
    const Container& c = *container_of(path);
    log = file.temporary();
    log += ".log";
    std::vector<std::string> args = {ffmpeg_program(), "-hide_banner", "-loglevel", "error", "-y",
                                     "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size_text(size),
                                     "-r", std::to_string(fps), "-i", "pipe:0"};
    const std::string format = c.format;
    if (format == "mp4") {
      args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18",
                               "-movflags", "+faststart"});
    } else if (format == "webm") {
      args.insert(args.end(), {"-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p", "-crf", "30", "-b:v", "0"});
    } else {
      // one palette for the whole clip, made from its own frames, no dithering: clean colours
      args.insert(args.end(), {"-vf", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=none"});
    }
    args.insert(args.end(), {"-f", format, file.temporary().string()});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    int fds[2];
    if (pipe(fds) != 0) throw VideoError("--video '" + path.string() + "': cannot make a pipe to ffmpeg");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    // its own process group: a Ctrl-C meant for lamina does not cut the video short; lamina
    // stops it itself (the destructor)
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    const int spawned = posix_spawn(&child, argv[0], &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    close(fds[0]);
    if (spawned != 0) {
      close(fds[1]);
      child = -1;
      throw VideoError("--video '" + path.string() + "': cannot start ffmpeg");
    }
    pipe_in = fds[1];
    // a write to an ffmpeg that has died is an error to report, not a signal that kills lamina
    old_sigpipe = std::signal(SIGPIPE, SIG_IGN);
  }

  ~Impl() {
    if (pipe_in >= 0) close(pipe_in);
    if (child > 0) {
      kill(child, SIGTERM);
      int status = 0;
      waitpid(child, &status, 0);
    }
    std::error_code ignored;
    std::filesystem::remove(log, ignored);
    std::signal(SIGPIPE, old_sigpipe);
  }

  // The last line ffmpeg wrote, for a message.
  std::string last_message() const {
    std::ifstream in(log);
    std::string line, last;
    while (std::getline(in, line)) {
      if (!line.empty()) last = line;
    }
    return last.empty() ? "ffmpeg failed" : "ffmpeg: " + last;
  }
};

VideoEncoder::VideoEncoder(const std::filesystem::path& path, const render::FrameSize& size, int fps)
    : impl_(std::make_unique<Impl>(path, size, fps)) {}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add(const render::Image& frame) {
  const std::uint8_t* data = frame.rgb.data();
  std::size_t left = frame.rgb.size();
  while (left > 0) {
    const ssize_t written = write(impl_->pipe_in, data, left);
    if (written <= 0) {
      throw VideoError("--video '" + impl_->file.path().string() + "': " + impl_->last_message());
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  ++impl_->frames;
}

int VideoEncoder::finish() {
  close(impl_->pipe_in);
  impl_->pipe_in = -1;
  int status = 0;
  waitpid(impl_->child, &status, 0);
  impl_->child = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw VideoError("--video '" + impl_->file.path().string() + "': " + impl_->last_message());
  }
  impl_->file.commit();
  return impl_->frames;
}

}  // namespace lamina::tutorial
