// A progress bar on standard error for long runs, drawn only when standard error is a
// terminal and the run has taken a moment: scripts and tests reading stderr never see it.
#pragma once

#include <chrono>
#include <string>

namespace lamina::cli {

class ProgressBar {
 public:
  // A bar for `total` steps, labelled (e.g. with the scene's name).
  ProgressBar(std::string label, long total);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // One more step done; redraws when the percentage changes.
  void advance();
  // Erases the bar; later advances draw nothing.
  void finish();

 private:
  void draw(int percent) const;

  bool on_terminal_;                                  // stderr is a terminal and the bar is live
  std::string label_;
  long total_;                                        // steps in the run
  long done_ = 0;                                     // steps done
  int drawn_percent_ = -1;                            // the percentage on screen, −1 for none
  std::chrono::steady_clock::time_point start_;       // when the run began
};

}  // namespace lamina::cli
