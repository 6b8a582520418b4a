#include "render/renderer.h"

#include <cstddef>
#include <string>

#include "render/gl_api.h"
#include "render/gl_program.h"
#include "render/paint.h"
#include "render/render_target.h"
#include "render/vector_output.h"

namespace lamina::render {

struct Renderer::Impl {
  GlApi gl;
  FrameSize size;
  Style style;
  Background background;
  Typesetter text;
  RenderTarget target;
  GLuint program = 0;
  GLuint vertex_array = 0;
  GLuint vertex_buffer = 0;
  GLuint atlas_texture = 0;

  Impl(const GlContext& context, const FrameSize& frame_size)
      : gl(context), size(frame_size), style(Style::for_size(frame_size)), target(gl, frame_size) {
    program = make_frame_program(gl);
    make_vertex_array();
    make_atlas_texture();
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }

  ~Impl() {
    gl.DeleteTextures(1, &atlas_texture);
    gl.DeleteBuffers(1, &vertex_buffer);
    gl.DeleteVertexArrays(1, &vertex_array);
    gl.DeleteProgram(program);
  }

  // The layout of Vertex (mesh.h): position, atlas coordinate, colour as normalised bytes.
  void make_vertex_array() {
    gl.GenVertexArrays(1, &vertex_array);
    gl.BindVertexArray(vertex_array);
    gl.GenBuffers(1, &vertex_buffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
    const auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), at(offsetof(Vertex, x)));
    gl.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), at(offsetof(Vertex, u)));
    gl.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                           at(offsetof(Vertex, colour)));
    for (GLuint i = 0; i < 3; ++i) gl.EnableVertexAttribArray(i);
  }

  void make_atlas_texture() {
    GlyphAtlas& atlas = text.atlas();
    gl.GenTextures(1, &atlas_texture);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, atlas_texture);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, GlyphAtlas::size, GlyphAtlas::size, 0, GL_RED,
                  GL_UNSIGNED_BYTE, atlas.texels().data());
    atlas.mark_uploaded();
  }

  // Sends the atlas rows that gained glyphs while painting this frame.
  void upload_new_glyphs() {
    GlyphAtlas& atlas = text.atlas();
    if (atlas.dirty_first() == atlas.dirty_end()) return;
    const std::size_t offset = static_cast<std::size_t>(atlas.dirty_first()) * GlyphAtlas::size;
    gl.TexSubImage2D(GL_TEXTURE_2D, 0, 0, atlas.dirty_first(), GlyphAtlas::size,
                     atlas.dirty_end() - atlas.dirty_first(), GL_RED, GL_UNSIGNED_BYTE,
                     atlas.texels().data() + offset);
    atlas.mark_uploaded();
  }

  DrawList paint(const Frame& frame, const Camera& camera, const Overlays& overlays) {
    DrawList list;
    Canvas canvas{list, camera, style, text, size, overlays};
    paint_grid(frame, canvas);
    paint_world(frame, canvas);
    paint_overlays(frame, canvas);
    paint_axes(frame, canvas);
    paint_text(frame, canvas);
    paint_legend(frame, canvas);
    return list;
  }

  void draw(const Mesh& mesh) {
    target.begin(background.colour, background.transparent);
    gl.UseProgram(program);
    gl.Uniform2f(gl.GetUniformLocation(program, "frame_size"), static_cast<float>(size.width),
                 static_cast<float>(size.height));
    gl.Uniform1i(gl.GetUniformLocation(program, "atlas"), 0);
    gl.BindVertexArray(vertex_array);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
    const std::vector<Vertex>& vertices = mesh.vertices();
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                  vertices.data(), GL_STREAM_DRAW);
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  }

  void check_errors() const {
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR) {
      throw GlContextError("OpenGL error " + std::to_string(error) + " while drawing a frame");
    }
  }
};

Renderer::Renderer(const GlContext& context, const FrameSize& size)
    : impl_(std::make_unique<Impl>(context, size)) {}

Renderer::~Renderer() = default;

void Renderer::set_background(const Background& background) { impl_->background = background; }

long Renderer::missing_glyphs() const { return impl_->text.missing_glyphs(); }

DrawList Renderer::paint(const Frame& frame, const Camera& camera, const Overlays& overlays) {
  return impl_->paint(frame, camera, overlays);
}

Image Renderer::render(const Frame& frame, const Camera& camera, const Overlays& overlays) {
  return rasterise(impl_->paint(frame, camera, overlays));
}

Image Renderer::rasterise(const DrawList& list) {
  Mesh mesh(impl_->text.atlas().solid_uv());
  tessellate(list, mesh, impl_->text);
  impl_->upload_new_glyphs();
  impl_->draw(mesh);
  Image image = impl_->target.read(impl_->background.transparent);
  impl_->check_errors();
  return image;
}

}  // namespace lamina::render
