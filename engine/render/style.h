// Sizes of the lecture style, in pixels, scaled with the frame height (the reference is 720).
#pragma once

#include "render/camera.h"

namespace lamina::render {

// Frame size in pixels.
struct FrameSize {
  int width = 1280;
  int height = 720;
};

struct Style {
  double unit = 1.0;     // pixels per reference pixel: height / 720
  double outline = 2.0;  // body outlines, joints
  double line = 2.0;     // paths, rotation marks, normals
  double arrow = 2.5;    // arrow shafts
  double marker = 6.0;   // radius of contact markers and pins
  double margin = 16.0;  // frame border and gaps between blocks
  int caption_px = 24;   // caption and panel titles (bold)
  int text_px = 19;      // status, labels, legend
  int mono_px = 17;      // panel lines (monospaced)
  int tick_px = 15;      // axis tick labels

  static Style for_size(const FrameSize& size);

  // Height of the bar holding the caption and the status line.
  double top_bar() const;
  // The part of the frame a camera fits the scene into: below the top bar, inside the margins,
  // and clear of the tick labels when axes are shown.
  Rect drawing_area(const FrameSize& size, bool axes) const;
};

}  // namespace lamina::render
