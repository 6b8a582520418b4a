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

void RenderTarget::begin(Colour background) const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffers_[0]);
  gl_.Viewport(0, 0, size_.width, size_.height);
  gl_.ClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);
}

Image RenderTarget::read() const {
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[0]);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[1]);
  gl_.BlitFramebuffer(0, 0, size_.width, size_.height, 0, 0, size_.width, size_.height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[1]);
  Image image{size_.width, size_.height, {}};
  image.rgb.resize(3 * static_cast<std::size_t>(size_.width) * size_.height);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  // The projection puts pixel row 0 (the top) at GL's row 0, so rows come out top first.
  gl_.ReadPixels(0, 0, size_.width, size_.height, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
  return image;
}

}  // namespace lamina::render
