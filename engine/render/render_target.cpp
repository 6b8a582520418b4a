#include "render/render_target.h"

#include <algorithm>
#include <string>

namespace lamina::render {
namespace {

constexpr GLint wanted_samples = 4;

}  // namespace

RenderTarget::RenderTarget(const GlApi& gl, const FrameSize& size) : gl_(gl), size_(size) {
  GLint max_samples = 0;
  gl_.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  gl_.GenRenderbuffers(2, renderbuffers_);
  framebuffers_[0] = framebuffer(std::min(wanted_samples, max_samples), renderbuffers_[0]);
  framebuffers_[1] = framebuffer(0, renderbuffers_[1]);
}

RenderTarget::~RenderTarget() {
  gl_.DeleteFramebuffers(2, framebuffers_);
  gl_.DeleteRenderbuffers(2, renderbuffers_);
}

GLuint RenderTarget::framebuffer(GLsizei samples, GLuint renderbuffer) const {
  gl_.BindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, size_.width, size_.height);
  GLuint fbo = 0;
  gl_.GenFramebuffers(1, &fbo);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer);
  if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw GlContextError("cannot make a " + std::to_string(size_.width) + "x" +
                         std::to_string(size_.height) + " framebuffer with " +
                         std::to_string(samples) + " samples");
  }
  return fbo;
}

void RenderTarget::begin(Colour background, bool transparent) const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffers_[0]);
  gl_.Viewport(0, 0, size_.width, size_.height);
  if (transparent) {
    gl_.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  } else {
    gl_.ClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  }
  gl_.Clear(GL_COLOR_BUFFER_BIT);
}

Image RenderTarget::read(bool with_alpha) const {
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[0]);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[1]);
  gl_.BlitFramebuffer(0, 0, size_.width, size_.height, 0, 0, size_.width, size_.height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[1]);
  Image image{size_.width, size_.height, {}};
  image.rgb.resize(3 * static_cast<std::size_t>(size_.width) * size_.height);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  // The projection puts pixel row 0 (the top) at GL's row 0, so rows come out top first.
  if (!with_alpha) {
    gl_.ReadPixels(0, 0, size_.width, size_.height, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    return image;
  }
  const std::size_t pixels = static_cast<std::size_t>(size_.width) * size_.height;
  std::vector<std::uint8_t> rgba(4 * pixels);
  gl_.ReadPixels(0, 0, size_.width, size_.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  image.alpha.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    // the blend (SRC_ALPHA, ONE_MINUS_SRC_ALPHA; alpha: ONE, ONE_MINUS_SRC_ALPHA) over (0, 0, 0, 0)
    // leaves colour × opacity; straight colour is that over the opacity
    const int a = rgba[4 * i + 3];
    image.alpha[i] = static_cast<std::uint8_t>(a);
    for (int c = 0; c < 3; ++c) {
      const int premultiplied = rgba[4 * i + c];
      image.rgb[3 * i + c] =
          a == 0 ? 0 : static_cast<std::uint8_t>(std::min(255, (premultiplied * 255 + a / 2) / a));
    }
  }
  return image;
}

}  // namespace lamina::render
