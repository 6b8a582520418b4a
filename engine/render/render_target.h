// Where frames are drawn: a multisampled framebuffer, resolved by a blit into a plain one that
// is read back as RGB.
#pragma once

#include "render/gl_api.h"
#include "render/image.h"
#include "render/style.h"

namespace lamina::render {

class RenderTarget {
 public:
  // 4 samples per pixel, or the context's maximum when lower. Throws GlContextError when the
  // framebuffer cannot be made (for example a size above the context's limit).
  RenderTarget(const GlApi& gl, const FrameSize& size);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Binds the multisampled framebuffer and clears it to `background`.
  // Clears to the background; `transparent` clears to nothing (opacity 0) instead.
  void begin(Colour background, bool transparent = false) const;
  // Resolves the samples (glBlitFramebuffer) and reads the pixels, top row first; with
  // `with_alpha`, their opacity too, the colours taken back from the blend's premultiplied
  // form (colour × opacity, over a cleared transparent black) to straight colour.
  Image read(bool with_alpha = false) const;

 private:
  GLuint framebuffer(GLsizei samples, GLuint renderbuffer) const;

  const GlApi& gl_;
  FrameSize size_;
  GLuint renderbuffers_[2] = {0, 0};  // multisampled, resolved
  GLuint framebuffers_[2] = {0, 0};
};

}  // namespace lamina::render
