// A frame's drawing commands (draw_list.h) as vector graphics for slides: SVG, written here as
// text so that captions and labels stay <text> elements (Cairo 1.16's SVG surface would turn
// them into glyph outlines, which no one can select or search), and PDF through Cairo (Debian's
// libcairo2-dev), whose text stays text (the DejaVu faces embedded, searchable). Both take the
// commands apart the same way (one decomposition, vector_output.cpp): an arrow into its shaft
// and head (arrow_shape), a dashed line into its dashes, as the PNG path draws them; circles stay
// circles. One pixel of the frame is one SVG user unit and one PDF point.
#pragma once

#include <memory>
#include <string>

#include "render/draw_list.h"
#include "render/frame.h"
#include "render/style.h"

namespace lamina::render {

// What lies behind the drawing: the paper colour, another colour, or nothing (transparent: a
// PNG with an alpha channel, an SVG or PDF with no background).
struct Background {
  bool transparent = false;
  Colour colour = palette::background;
};

// The SVG document of one frame, `size` pixels.
std::string svg_document(const DrawList& list, const FrameSize& size, const Background& background);

// A PDF of one page per frame, each `size` points.
class PdfDocument {
 public:
  explicit PdfDocument(const FrameSize& size);
  ~PdfDocument();
  PdfDocument(const PdfDocument&) = delete;
  PdfDocument& operator=(const PdfDocument&) = delete;

  void add_page(const DrawList& list, const Background& background);
  int pages() const { return pages_; }
  // Ends the document and returns its bytes; no page may be added after.
  std::string finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int pages_ = 0;
};

}  // namespace lamina::render
