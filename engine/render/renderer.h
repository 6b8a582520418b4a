// Draws Frames off screen and returns their pixels. Runs on the thread where the GL context is
// current (the GL thread); the images it returns are plain data for the encoder threads.
#pragma once

#include <memory>

#include "render/camera.h"
#include "render/draw_list.h"
#include "render/frame.h"
#include "render/gl_context.h"
#include "render/image.h"
#include "render/style.h"
#include "render/vector_output.h"

namespace lamina::render {

class Renderer {
 public:
  // `context` must be current on this thread and outlive the renderer.
  // Throws GlContextError when the context cannot draw Lamina's frames.
  Renderer(const GlContext& context, const FrameSize& size);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The frame as the camera sees it, with the given overlays, anti-aliased by 4× MSAA:
  // rasterise(paint(...)).
  Image render(const Frame& frame, const Camera& camera, const Overlays& overlays);
  // The frame as drawing commands, in pixels: what every output format is made from.
  DrawList paint(const Frame& frame, const Camera& camera, const Overlays& overlays);
  // The commands drawn by OpenGL.
  Image rasterise(const DrawList& list);
  // What lies behind the drawing: the paper colour unless set; transparent gives images with
  // an alpha plane (Image::alpha).
  void set_background(const Background& background);
  // Characters drawn or measured so far that no font has (font_set.h): each is a .notdef box.
  long missing_glyphs() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lamina::render
