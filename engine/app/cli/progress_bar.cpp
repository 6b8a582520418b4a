#include "app/cli/progress_bar.h"

#include <cstdio>

#include <unistd.h>

namespace lamina::cli {
namespace {

constexpr std::chrono::milliseconds quiet_start(300);  // runs shorter than this show no bar
constexpr int bar_width = 30;                          // characters between the brackets

}  // namespace

ProgressBar::ProgressBar(std::string label, long total)
    : on_terminal_(isatty(STDERR_FILENO) != 0 && total > 0),
      label_(std::move(label)),
      total_(total),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance() {
  ++done_;
  if (!on_terminal_) return;
  const int percent = static_cast<int>(100 * done_ / total_);
  if (percent == drawn_percent_ || std::chrono::steady_clock::now() - start_ < quiet_start) return;
  drawn_percent_ = percent;
  draw(percent);
}

void ProgressBar::finish() {
  if (on_terminal_ && drawn_percent_ >= 0) std::fputs("\r\033[K", stderr);
  on_terminal_ = false;
}

void ProgressBar::draw(int percent) const {
  const int filled = percent * bar_width / 100;
  std::fprintf(stderr, "\r%s [%s%s] %3d%%  step %ld of %ld", label_.c_str(),
               std::string(filled, '#').c_str(), std::string(bar_width - filled, '.').c_str(),
               percent, done_, total_);
  std::fflush(stderr);
}

}  // namespace lamina::cli
