#include "render/vector_output.h"

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "render/font_set.h"
#include "render/tessellate.h"

namespace lamina::render {
namespace {

// What a vector output draws: the commands taken apart into these (emit, below).
class VectorSink {
 public:
  virtual ~VectorSink() = default;
  virtual void polygon(const std::vector<Vec2>& points, Colour fill) = 0;
  virtual void outline(const std::vector<Vec2>& points, double width, Colour colour) = 0;  // mitred
  virtual void segment(const Vec2& a, const Vec2& b, double width, Colour colour) = 0;     // butt ends
  virtual void polyline(const std::vector<Vec2>& points, double width, Colour colour) = 0;  // round joins
  virtual void circle(const Vec2& centre, double radius, Colour fill) = 0;
  virtual void text(const std::string& line, const TextStyle& style, const Vec2& origin) = 0;
};

// Every command, in order, as the sink's shapes (the PNG path's geometry: arrow_shape, dashes).
void emit(const DrawList& list, VectorSink& sink) {
  using Kind = DrawCommand::Kind;
  for (const DrawCommand& c : list.commands()) {
    switch (c.kind) {
      case Kind::fill_convex: sink.polygon(c.points, c.colour); break;
      case Kind::stroke_convex: sink.outline(c.points, c.width, c.colour); break;
      case Kind::segment: sink.segment(c.points[0], c.points[1], c.width, c.colour); break;
      case Kind::polyline:
        if (c.dash > 0.0) {
          for (const auto& d : dashes(c.points, c.dash)) sink.segment(d[0], d[1], c.width, c.colour);
        } else {
          sink.polyline(c.points, c.width, c.colour);
        }
        break;
      case Kind::disc: sink.circle(c.points[0], c.radius, c.colour); break;
      case Kind::ringed_disc:
        sink.circle(c.points[0], c.radius + 0.5 * c.ring_width, c.ring);
        sink.circle(c.points[0], c.radius - 0.5 * c.ring_width, c.colour);
        break;
      case Kind::arrow: {
        const ArrowShape shape = arrow_shape(c.points[0], c.points[1], c.width);
        if (!shape.drawn) break;
        sink.segment(shape.shaft_from, shape.shaft_to, c.width, c.colour);
        sink.polygon({shape.head[0], shape.head[1], shape.head[2]}, c.colour);
        break;
      }
      case Kind::text:
        // the PNG path's rounding of the baseline's origin (Typesetter::draw)
        sink.text(c.text, c.style, Vec2(std::round(c.points[0].x()), std::round(c.points[0].y())));
        break;
    }
  }
}

// ---- SVG ----

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", x);
  std::string s = text;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string rgb(Colour c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

// fill="#rrggbb" and its opacity when not opaque
std::string paint(const char* what, Colour c) {
  std::string s = std::string(" ") + what + "=\"" + rgb(c) + "\"";
  if (c.a != 255) s += std::string(" ") + what + "-opacity=\"" + number(c.a / 255.0) + "\"";
  return s;
}

std::string points_attribute(const std::vector<Vec2>& points) {
  std::string s = " points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    s += (i ? " " : "") + number(points[i].x()) + "," + number(points[i].y());
  }
  return s + "\"";
}

std::string escaped(const std::string& text) {
  std::string s;
  for (const char ch : text) {
    switch (ch) {
      case '&': s += "&amp;"; break;
      case '<': s += "&lt;"; break;
      case '>': s += "&gt;"; break;
      case '"': s += "&quot;"; break;
      default: s += ch;
    }
  }
  return s;
}

class SvgSink final : public VectorSink {
 public:
  std::string out;

  void polygon(const std::vector<Vec2>& points, Colour fill) override {
    out += "<polygon" + points_attribute(points) + paint("fill", fill) + "/>\n";
  }
  void outline(const std::vector<Vec2>& points, double width, Colour colour) override {
    out += "<polygon" + points_attribute(points) + " fill=\"none\"" + paint("stroke", colour) +
           " stroke-width=\"" + number(width) + "\" stroke-linejoin=\"miter\"/>\n";
  }
  void segment(const Vec2& a, const Vec2& b, double width, Colour colour) override {
    out += "<line x1=\"" + number(a.x()) + "\" y1=\"" + number(a.y()) + "\" x2=\"" + number(b.x()) +
           "\" y2=\"" + number(b.y()) + "\"" + paint("stroke", colour) + " stroke-width=\"" +
           number(width) + "\"/>\n";
  }
  void polyline(const std::vector<Vec2>& points, double width, Colour colour) override {
    out += "<polyline" + points_attribute(points) + " fill=\"none\"" + paint("stroke", colour) +
           " stroke-width=\"" + number(width) + "\" stroke-linejoin=\"round\"/>\n";
  }
  void circle(const Vec2& centre, double radius, Colour fill) override {
    out += "<circle cx=\"" + number(centre.x()) + "\" cy=\"" + number(centre.y()) + "\" r=\"" +
           number(radius) + "\"" + paint("fill", fill) + "/>\n";
  }
  void text(const std::string& line, const TextStyle& style, const Vec2& origin) override {
    out += "<text x=\"" + number(origin.x()) + "\" y=\"" + number(origin.y()) +
           "\" font-family=\"" + font_family(style.face) + "\" font-size=\"" + std::to_string(style.px) +
           "\"" + (is_bold(style.face) ? " font-weight=\"bold\"" : "") + paint("fill", style.colour) +
           " xml:space=\"preserve\">" + escaped(line) + "</text>\n";
  }
};

// ---- PDF (Cairo) ----

void check(cairo_status_t status, const char* what) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("Cairo could not ") + what + ": " + cairo_status_to_string(status));
  }
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

class CairoSink final : public VectorSink {
 public:
  // faces[t][k]: Cairo's face of font k of typeface t's chain (font_set.h)
  CairoSink(cairo_t* cr, FontSet& fonts, const std::array<std::vector<cairo_font_face_t*>, 3>& faces)
      : cr_(cr), fonts_(fonts), faces_(faces) {}

  void polygon(const std::vector<Vec2>& points, Colour fill) override {
    path(points, true);
    source(fill);
    cairo_fill(cr_);
  }
  void outline(const std::vector<Vec2>& points, double width, Colour colour) override {
    path(points, true);
    stroke(width, colour, CAIRO_LINE_JOIN_MITER);
  }
  void segment(const Vec2& a, const Vec2& b, double width, Colour colour) override {
    path({a, b}, false);
    stroke(width, colour, CAIRO_LINE_JOIN_MITER);
  }
  void polyline(const std::vector<Vec2>& points, double width, Colour colour) override {
    path(points, false);
    stroke(width, colour, CAIRO_LINE_JOIN_ROUND);
  }
  void circle(const Vec2& centre, double radius, Colour fill) override {
    cairo_new_path(cr_);
    cairo_arc(cr_, centre.x(), centre.y(), std::max(radius, 0.0), 0.0, 2.0 * M_PI);
    source(fill);
    cairo_fill(cr_);
  }
  void text(const std::string& line, const TextStyle& style, const Vec2& origin) override {
    source(style.colour);
    cairo_move_to(cr_, origin.x(), origin.y());
    // each run in its own font; cairo_show_text leaves the point after the run for the next
    for (const TextRun& run : fonts_.runs(line, style.face)) {
      cairo_set_font_face(cr_, faces_[static_cast<std::size_t>(style.face)][run.font]);
      cairo_set_font_size(cr_, style.px);
      cairo_show_text(cr_, run.text.c_str());
    }
  }

 private:
  void path(const std::vector<Vec2>& points, bool closed) {
    cairo_new_path(cr_);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i == 0) {
        cairo_move_to(cr_, points[i].x(), points[i].y());
      } else {
        cairo_line_to(cr_, points[i].x(), points[i].y());
      }
    }
    if (closed) cairo_close_path(cr_);
  }
  void source(Colour c) { cairo_set_source_rgba(cr_, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0); }
  void stroke(double width, Colour colour, cairo_line_join_t join) {
    source(colour);
    cairo_set_line_width(cr_, width);
    cairo_set_line_join(cr_, join);
    cairo_set_line_cap(cr_, CAIRO_LINE_CAP_BUTT);
    cairo_stroke(cr_);
  }

  cairo_t* cr_;
  FontSet& fonts_;
  const std::array<std::vector<cairo_font_face_t*>, 3>& faces_;
};

}  // namespace

std::string svg_document(const DrawList& list, const FrameSize& size, const Background& background) {
  SvgSink sink;
  const std::string w = std::to_string(size.width), h = std::to_string(size.height);
  sink.out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w +
             "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  if (!background.transparent) {
    sink.out += "<rect width=\"" + w + "\" height=\"" + h + "\"" + paint("fill", background.colour) + "/>\n";
  }
  emit(list, sink);
  return sink.out + "</svg>\n";
}

namespace {

// The fonts of every PDF, opened once for the process and never closed. Cairo keeps a font face
// in caches of its own after its last user lets go, keyed by the FT_Face it was made from; faces
// closed while Cairo held them let a later FT_Face at the same address be taken for the old one
// (seen: a Korean caption drawn in DejaVu, as boxes, in 3 of 12 runs, as the heap's addresses
// fell). Kept for the process, they stay what Cairo thinks they are.
struct PdfFonts {
  FontSet fonts;
  std::array<std::vector<cairo_font_face_t*>, 3> faces;  // Cairo's face of each font of each chain

  PdfFonts() {
    for (std::size_t t = 0; t < faces.size(); ++t) {
      const auto face = static_cast<Typeface>(t);
      for (std::size_t k = 0; k < font_chain(face).size(); ++k) {
        faces[t].push_back(cairo_ft_font_face_create_for_ft_face(fonts.face(face, k), 0));
      }
    }
  }
};

PdfFonts& pdf_fonts() {
  static PdfFonts* const fonts = new PdfFonts();  // never deleted: see PdfFonts
  return *fonts;
}

}  // namespace

struct PdfDocument::Impl {
  std::string bytes;
  PdfFonts& fonts = pdf_fonts();
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = nullptr;

  explicit Impl(const FrameSize& size) {
    surface = cairo_pdf_surface_create_for_stream(append, &bytes, size.width, size.height);
    check(cairo_surface_status(surface), "start a PDF");
    cr = cairo_create(surface);
    check(cairo_status(cr), "draw into a PDF");
  }

  ~Impl() {
    if (cr != nullptr) cairo_destroy(cr);
    if (surface != nullptr) cairo_surface_destroy(surface);
  }
};

PdfDocument::PdfDocument(const FrameSize& size) : impl_(std::make_unique<Impl>(size)) {}

PdfDocument::~PdfDocument() = default;

void PdfDocument::add_page(const DrawList& list, const Background& background) {
  cairo_t* cr = impl_->cr;
  if (!background.transparent) {
    const Colour c = background.colour;
    cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0);
    cairo_paint(cr);
  }
  CairoSink sink(cr, impl_->fonts.fonts, impl_->fonts.faces);
  emit(list, sink);
  cairo_show_page(cr);
  check(cairo_status(cr), "draw a PDF page");
  ++pages_;
}

std::string PdfDocument::finish() {
  cairo_destroy(impl_->cr);
  impl_->cr = nullptr;
  cairo_surface_finish(impl_->surface);
  check(cairo_surface_status(impl_->surface), "finish a PDF");
  return std::move(impl_->bytes);
}

}  // namespace lamina::render
