// Vector frames (render/vector_output.h, docs/slides.md): the SVG and PDF of a frame are the
// drawing the PNG is, with the text kept as text. Checked with Debian's own readers, not with
// Lamina's code: xmllint parses the SVG (well-formed), rsvg-convert (librsvg2-bin) and pdftoppm
// (poppler-utils) rasterise them, pdfinfo counts pages and pdftotext finds the caption.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "render/backend.h"
#include "render/png_codec.h"
#include "render/renderer.h"
#include "render/vector_output.h"
#include "render_test_frame.h"

namespace {

using namespace lamina::render;
using testing::ScratchFolder;
using testing::test_size;

// The test frame at a slide's size: 960 × 540, big enough for text to be compared.
constexpr FrameSize slide_size{960, 540};

// The bounds of the comparison with the PNG, measured on this frame: the SVG (rsvg-convert)
// differs in 0.54 % of the 4 × 4 blocks by more than 24, by 75 at most; the PDF (pdftoppm) in
// 0.79 %, by 75 at most — glyphs a fraction of a pixel apart. Drawing one kind of command less
// was seen to fail them: without the discs (the contact markers) a block differs by 170,
// without the arrows by 254 (and the PDF's share is 1.18 %), without the text 2.8 % of blocks
// differ by up to 200.
constexpr double share_bound = 0.01;    // of the blocks
constexpr double largest_bound = 110.0;  // of 255, in one block's mean

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Runs a shell command; its standard output.
std::string run(const std::string& command) {
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    std::size_t n = 0;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    REQUIRE(pclose(pipe) == 0);
  }
  return out;
}

Image png_file(const std::filesystem::path& path) {
  const std::string bytes = read(path);
  return decode_png(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
}

// How two renderings of one frame differ, seen in blocks of 4 × 4 pixels (each block's mean
// colour), so that where an edge's anti-aliasing shade falls and a glyph's sub-pixel place
// (hinted FreeType bitmaps in the PNG, outlines in librsvg and poppler) average out, while a
// shape that is missing or misplaced changes its blocks: the share of blocks whose largest
// channel difference exceeds 24 (of 255), and the largest.
struct Difference {
  double share_over_24 = 0.0;
  double largest = 0.0;
};

Difference difference(const Image& a, const Image& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  constexpr int block = 4;
  long over = 0, blocks = 0;
  double largest = 0.0;
  for (int y0 = 0; y0 + block <= a.height; y0 += block) {
    for (int x0 = 0; x0 + block <= a.width; x0 += block) {
      double worst = 0.0;
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int y = y0; y < y0 + block; ++y) {
          for (int x = x0; x < x0 + block; ++x) sum += int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c]);
        }
        worst = std::max(worst, std::abs(sum) / (block * block));
      }
      over += worst > 24.0;
      largest = std::max(largest, worst);
      ++blocks;
    }
  }
  return {double(over) / blocks, largest};
}

struct Drawn {
  Image png;
  DrawList list;
};

// The frame drawn as a PNG and as commands; `missing` gets the glyphs no font had.
Drawn draw_test_frame(const Frame& frame = testing::full_frame(), long* missing = nullptr) {
  const auto context = open_context(default_backend());
  Renderer renderer(*context, slide_size);
  Overlays all = Overlays::parse("all");
  const Style style = Style::for_size(slide_size);
  const Camera camera = Camera::fit({lamina::Vec2(-3.5, -0.5), lamina::Vec2(3.5, 3.2)},
                                    style.drawing_area(slide_size, true));
  Drawn drawn{renderer.render(frame, camera, all), renderer.paint(frame, camera, all)};
  if (missing != nullptr) *missing = renderer.missing_glyphs();
  return drawn;
}

}  // namespace

TEST_SUITE("vector frames") {
  TEST_CASE("the SVG is well-formed, keeps its text as text and looks like the PNG") {
    ScratchFolder folder("svg");
    const Drawn drawn = draw_test_frame();
    const std::string svg = svg_document(drawn.list, slide_size, Background{});
    const auto path = folder.path() / "frame.svg";
    write(path, svg);
    run("xmllint --noout " + path.string());  // fails the test unless well-formed
    // the caption, the status line, a panel line and the legend as <text> elements
    for (const char* text : {">Fig 4-3  test frame</text>", ">t = 0.500 s · step 30</text>",
                             ">λ = 40.000 N</text>", ">box</text>"}) {
      CAPTURE(std::string(text));
      CHECK(svg.find(text) != std::string::npos);
    }
    run("rsvg-convert " + path.string() + " -o " + (folder.path() / "svg.png").string());
    const Difference d = difference(drawn.png, png_file(folder.path() / "svg.png"));
    MESSAGE("SVG by rsvg-convert against the PNG: " << 100 * d.share_over_24
                                                    << " % of 4 × 4 blocks differ by more than 24, at most " << d.largest);
    CHECK(d.share_over_24 <= share_bound);
    CHECK(d.largest <= largest_bound);
  }

  TEST_CASE("a transparent SVG has no background and a colour one has it") {
    const Drawn drawn = draw_test_frame();
    CHECK(svg_document(drawn.list, slide_size, Background{true, {}}).find("<rect") == std::string::npos);
    CHECK(svg_document(drawn.list, slide_size, Background{false, {1, 2, 3, 255}}).find("<rect width=\"960\" height=\"540\" fill=\"#010203\"/>") !=
          std::string::npos);
  }

  TEST_CASE("the PDF has a page per frame, searchable text, and looks like the PNG") {
    ScratchFolder folder("pdf");
    const Drawn drawn = draw_test_frame();
    PdfDocument pdf(slide_size);
    for (int page = 0; page < 3; ++page) pdf.add_page(drawn.list, Background{});
    CHECK(pdf.pages() == 3);
    const auto path = folder.path() / "frames.pdf";
    write(path, pdf.finish());
    CHECK(run("pdfinfo " + path.string()).find("Pages:           3") != std::string::npos);
    CHECK(run("pdftotext " + path.string() + " -").find("Fig 4-3 test frame") != std::string::npos);
    // one point per pixel: at 72 dpi a page is the frame's size
    run("pdftoppm -png -r 72 -f 2 -l 2 " + path.string() + " " + (folder.path() / "page").string());
    const Difference d = difference(drawn.png, png_file(folder.path() / "page-2.png"));
    MESSAGE("PDF page by pdftoppm against the PNG: " << 100 * d.share_over_24
                                                     << " % of 4 × 4 blocks differ by more than 24, at most " << d.largest);
    CHECK(d.share_over_24 <= share_bound);  // the same bounds and reasons as the SVG's
    CHECK(d.largest <= largest_bound);
  }

  TEST_CASE("a Korean caption: every glyph drawn, kept as text in the SVG and the PDF, alike in all three") {
    // Hangul from Nanum Gothic beside DejaVu's Latin, Greek and symbols (render/font_set.h)
    Frame frame = testing::full_frame();
    frame.caption = "그림 4-3  시험 프레임";
    frame.status = "t = 0.500 s · 단계 30 · 구속조건 λ";
    long missing = -1;
    const Drawn drawn = draw_test_frame(frame, &missing);
    CHECK(missing == 0);
    ScratchFolder folder("korean");
    const std::string svg = svg_document(drawn.list, slide_size, Background{});
    CHECK(svg.find(">그림 4-3  시험 프레임</text>") != std::string::npos);
    CHECK(svg.find("font-family=\"DejaVu Sans, NanumGothic\"") != std::string::npos);
    write(folder.path() / "frame.svg", svg);
    run("rsvg-convert " + (folder.path() / "frame.svg").string() + " -o " + (folder.path() / "svg.png").string());
    PdfDocument pdf(slide_size);
    pdf.add_page(drawn.list, Background{});
    write(folder.path() / "frame.pdf", pdf.finish());
    const std::string text = run("pdftotext " + (folder.path() / "frame.pdf").string() + " -");
    CHECK(text.find("그림 4-3 시험 프레임") != std::string::npos);
    CHECK(text.find("단계 30 · 구속조건 λ") != std::string::npos);
    run("pdftoppm -png -r 72 " + (folder.path() / "frame.pdf").string() + " " + (folder.path() / "page").string());
    // the same bounds and reasons as the English frame's: a caption drawn in a wrong font or
    // as boxes in one output differs in its blocks
    for (const char* file : {"svg.png", "page-1.png"}) {
      CAPTURE(std::string(file));
      const Difference d = difference(drawn.png, png_file(folder.path() / file));
      MESSAGE(std::string(file) << " against the PNG: " << 100 * d.share_over_24 << " % of blocks over 24, at most " << d.largest);
      CHECK(d.share_over_24 <= share_bound);
      CHECK(d.largest <= largest_bound);
    }
  }
  TEST_CASE("a caption too long for its room is drawn smaller, whole, not cut short") {
    // Captions of 70 to 100 characters beside the status line on a 960 × 540 slide: each fits
    // at some size of 8 px or more, so each must be drawn whole. The size scaled by room over
    // width is not always small enough (a face's width is not proportional to its size: its
    // glyphs are hinted and rounded), and a caption cut short there lost its last word to "…"
    // (Chapter 2's spring caption, 1280 × 720). Checked in the SVG, whose text is the text.
    const auto context = open_context(default_backend());
    Renderer renderer(*context, slide_size);
    const Style style = Style::for_size(slide_size);
    const Camera camera = Camera::fit({lamina::Vec2(-3.5, -0.5), lamina::Vec2(3.5, 3.2)},
                                      style.drawing_area(slide_size, false));
    const std::string words =
        "Ch 2 · A spring: explicit Euler multiplies E by 1 + ω²Δt² a step, eq. 2-5 keeps it, "
        "and the semi-implicit step keeps it bounded";
    int whole = 0;
    for (std::size_t length = 70; length <= 100; ++length) {
      Frame frame;
      frame.caption = words.substr(0, length);
      while ((frame.caption.back() & 0xC0) == 0x80 || (frame.caption.back() & 0x80) != 0) {
        frame.caption.pop_back();  // whole UTF-8 characters only
      }
      frame.status = "t = 3.000 s · step 180 · Δt = 1/60 s";
      const std::string svg =
          svg_document(renderer.paint(frame, camera, Overlays()), slide_size, Background{});
      CAPTURE(frame.caption);
      CHECK(svg.find(">" + frame.caption + "</text>") != std::string::npos);
      CHECK(svg.find("…") == std::string::npos);
      ++whole;
    }
    CHECK(whole == 31);
  }
}
