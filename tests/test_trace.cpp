// Traces: a trace read back gives the run's state exactly, runs write the same bytes, the
// contact impulses are λ Δt, and a trace is complete or absent.
#include <doctest/doctest.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <unistd.h>

#include "output/output_file.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"
#include "scene/shortest_number.h"
#include "trace/trace_csv.h"
#include "trace/trace_json.h"
#include "trace/trace_writer.h"

using namespace lamina;
namespace fs = std::filesystem;

namespace {

// A test case's own empty folder under the system's temporary folder, removed afterwards.
struct TraceFolder {
  const fs::path folder = fs::temp_directory_path() / ("lamina-test-trace-" + std::to_string(getpid()));
  TraceFolder() {
    fs::remove_all(folder);
    fs::create_directories(folder);
  }
  ~TraceFolder() { fs::remove_all(folder); }
};

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string last_line(const fs::path& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  return last;
}

// Runs a built-in scene `steps` steps, writing its trace to `path`; returns the world.
World run_with_trace(const Scene& scene, int steps, const fs::path& path) {
  World world = build_world(scene, world_settings(scene));
  TraceWriter trace(path);
  for (long step = 1; step <= steps; ++step) {
    world.step();
    trace.write(trace_step(scene, world, step));
  }
  trace.finish();
  return world;
}

}  // namespace

TEST_SUITE("Trace") {
  TEST_CASE_FIXTURE(TraceFolder, "the last line of a trace reads back to the world's final state exactly") {
    for (const char* name : {"box-on-ground-tilted", "pendulum", "see-saw"}) {
      CAPTURE(name);
      const Scene scene = builtin_scene(name);
      const fs::path path = folder / (std::string(name) + ".jsonl");
      const World world = run_with_trace(scene, 90, path);
      const TraceStep last = parse_trace_line(last_line(path));
      CHECK(last.step == 90);
      CHECK(last.time == world.time());
      std::size_t k = 0;
      for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        if (scene.bodies[i].is_static) continue;
        REQUIRE(k < last.bodies.size());
        const BodyState& b = last.bodies[k++];
        const RigidBody& body = world.bodies()[i];
        CAPTURE(b.name);
        // Exact: the shortest round-trip form reads back to the same double (no tolerance).
        CHECK(b.name == scene.bodies[i].name);
        CHECK(b.position == Vec2{body.x.x(), body.x.y()});
        CHECK(b.angle == planar_angle(body.q));
        CHECK(b.velocity == Vec2{body.v.x(), body.v.y()});
        CHECK(b.angular_velocity == body.angular_velocity.z());
      }
      CHECK(k == last.bodies.size());
    }
  }

  TEST_CASE_FIXTURE(TraceFolder, "two runs of a scene write the same bytes") {
    const Scene scene = pyramid_scene(6);
    run_with_trace(scene, 60, folder / "first.jsonl");
    run_with_trace(scene, 60, folder / "second.jsonl");
    const std::string first = contents(folder / "first.jsonl");
    CHECK(first.size() > 0);
    CHECK(first == contents(folder / "second.jsonl"));
  }

  TEST_CASE("a resting box's contact impulses add up to m g Δt, normal from ground to box") {
    const Scene scene = builtin_scene("box-on-ground-resting");
    World world = build_world(scene, world_settings(scene));
    for (int step = 0; step < 120; ++step) world.step();
    const TraceStep record = trace_step(scene, world, 120);
    REQUIRE(record.contacts.size() == 2);
    double impulse = 0.0;
    for (const ContactState& c : record.contacts) {
      CHECK(c.bodies == std::array<std::string, 2>{"ground", "box"});
      CHECK(c.normal == Vec2{0.0, 1.0});
      impulse += c.normal_impulse;
    }
    // m = 1 kg (density 1 kg/m², 1 m²): at rest the contacts carry its weight. The tolerance
    // is the PGS residual after 10 sweeps, warm started from a resting cache.
    const double m_g_dt = 1.0 * 9.8 * scene.step.dt;
    CHECK(impulse == doctest::Approx(m_g_dt).epsilon(1e-6));
  }

  TEST_CASE("a trace line has the documented keys, in order, numbers in shortest form") {
    TraceStep step{1, 1.0 / 60.0, {{"box", {0.0, 0.1 + 0.2}, 0.3, {0.0, -0.16}, 0.0}}, {}};
    step.contacts.push_back({{"ground", "box"}, {0.1, 0.0}, {0.0, 1.0}, 0.001, 0.08, 0.0, true, "kept"});
    CHECK(trace_json_line(step) ==
          R"({"step":1,"time":0.016666666666666666,"bodies":[{"name":"box",)"
          R"("position":[0.0,0.30000000000000004],"angle":0.3,"velocity":[0.0,-0.16],)"
          R"("angular_velocity":0.0}],"contacts":[{"bodies":["ground","box"],"point":[0.1,0.0],)"
          R"("normal":[0.0,1.0],"depth":0.001,"normal_impulse":0.08,"tangent_impulse":0.0,)"
          R"("cached":true,"origin":"kept"}]})");
  }

  TEST_CASE_FIXTURE(TraceFolder, "a CSV trace has one row per dynamic body per step and its contacts beside it") {
    const Scene scene = builtin_scene("vertical-stack");
    run_with_trace(scene, 10, folder / "stack.csv");
    const std::string bodies = contents(folder / "stack.csv");
    CHECK(bodies.rfind(trace_csv_body_header(), 0) == 0);
    CHECK(std::count(bodies.begin(), bodies.end(), '\n') == 1 + 10 * 5);  // five boxes
    CHECK(last_line(folder / "stack.csv").rfind("10,0.16666666666666666,box4,", 0) == 0);
    const std::string contacts = contents(folder / "stack.contacts.csv");
    CHECK(contacts.rfind(trace_csv_contact_header(), 0) == 0);
    CHECK(contacts.find("\n10,0.16666666666666666,ground,box0,") != std::string::npos);
  }

  TEST_CASE("every number reads back to the same double, and whole numbers read as floating point") {
    for (double x : {2.0, -0.0, 0.1 + 0.2, 1.0 / 3.0, 1e-300, 5e-324, 1e21, -1.5e-7, 0.0001}) {
      std::string text;
      append_shortest(text, x);
      CAPTURE(text);
      const double back = std::strtod(text.c_str(), nullptr);
      CHECK(back == x);  // exact: no tolerance
      CHECK(std::signbit(back) == std::signbit(x));
      CHECK(text.find_first_of(".e") != std::string::npos);
    }
  }

  TEST_CASE("numbers are written as std::to_chars writes them, byte for byte") {
    // Lamina's shortest-decimal writer (Dragonbox, Schubfach where the fractions decide)
    // against libstdc++'s std::to_chars (Ryu), an independent implementation of the same
    // definition: the shortest decimal that reads back, the nearer of two, fixed notation
    // unless scientific is shorter. No tolerance: the bytes. (Each of Dragonbox's three
    // hand-overs to Schubfach, taken out, makes some of these differ.)
    long compared = 0;
    long differing = 0;
    const auto compare = [&](double x) {
      char expected[32];
      const std::string wanted(expected, std::to_chars(expected, expected + sizeof expected, x).ptr);
      const std::string written = shortest_number(x);
      ++compared;
      if (written != wanted && ++differing <= 5) CHECK_MESSAGE(written == wanted, "x = " << wanted);
    };
    std::uint64_t state = 20261203;  // splitmix64: the same doubles on every run
    const auto next = [&state] {
      std::uint64_t z = (state += 0x9e3779b97f4a7c15u);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
      return z ^ (z >> 31);
    };
    const auto of_bits = [](std::uint64_t bits) {
      double x;
      std::memcpy(&x, &bits, sizeof x);
      return x;
    };
    for (int i = 0; i < 1000000; ++i) {  // any bit pattern: every exponent, subnormals too
      const double x = of_bits(next());
      if (std::isfinite(x)) compare(x);
    }
    for (int i = 0; i < 300000; ++i) {  // short decimals, where trailing zeros and ties live
      const int length = 1 + static_cast<int>(next() % 17);
      std::uint64_t digits = next() % 100000000000000000u;
      for (int d = length; d < 17; ++d) digits /= 10;
      const std::string text = std::to_string(digits) + "e" + std::to_string(static_cast<int>(next() % 640) - 330);
      compare(std::strtod(text.c_str(), nullptr));
    }
    for (int e = -1074; e <= 1023; ++e) {  // powers of two (the uneven intervals) and neighbours
      const double p = std::ldexp(1.0, e);
      for (double x : {p, std::nextafter(p, 0.0), std::nextafter(p, 1e308), -p}) compare(x);
    }
    for (int n = 0; n <= 100000; ++n) compare(n * 0.25);  // whole numbers, quarters, and zero
    for (int j = -60; j <= 60; ++j) {
      // 10^23 2^j lies halfway between two doubles: the one with an odd significand must not
      // take its short decimal (the end of its interval is open; rounding goes to the even one)
      const double halfway = std::ldexp(1e23, j);
      for (double x : {halfway, std::nextafter(halfway, 0.0), std::nextafter(halfway, 1e308)}) compare(x);
    }
    for (double x : {-0.0, 1e21, 1e22, 1e23, 1e-5, 1e-4, 1e16, 1e17, 123456789012345680.0,
                     std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                     std::numeric_limits<double>::denorm_min(), 1.0 / 3.0, 0.1 + 0.2}) {
      compare(x);
    }
    CHECK(differing == 0);
    CHECK(compared > 1400000);  // all of the above but the non-finite bit patterns
  }

  TEST_CASE("a JSON trace escapes what JSON asks of a name, and reads it back whole") {
    // a name with a quote, a backslash, a tab and non-ASCII text: escaped exactly as RFC 8259
    // asks (the quote and backslash by a backslash, the control character as \u0009), read back
    // by nlohmann-json (parse_trace_line), an independent parser
    const std::string name = "a\"b\\c\td 상자";
    const TraceStep step{3, 0.5, {{name, {1.0, 2.0}, 0.0, {0.0, 0.0}, 0.0}}, {}};
    const std::string line = trace_json_line(step);
    CHECK(line.find(R"("name":"a\"b\\c\u0009d 상자")") != std::string::npos);
    CHECK(parse_trace_line(line).bodies.at(0).name == name);
  }

  TEST_CASE("every character JSON escapes is escaped wherever it stands in a name") {
    // The writer copies a name whole and checks it in the same pass, escaping it only when it
    // must: each character RFC 8259 asks to escape (the controls below 0x20, '"', '\\'), and
    // the plain ones either side of them (0x20, '!', '#', '[', ']', 0x7f), at every place of
    // names of 1 to 24 bytes among plain letters and Hangul (UTF-8's bytes of 0x80 and above,
    // never escaped). Read back by nlohmann-json, an independent parser, exactly; a name with
    // nothing to escape is copied as it is.
    std::string specials;
    for (int c = 0; c < 0x20; ++c) specials += static_cast<char>(c);
    specials += "\"\\ !#[]\x7f";
    const std::string fillers[] = {"abcdefghijklmnopqrstuvwx", "상자상자상자상자"};  // 24 bytes
    int names = 0;
    for (const std::string& filler : fillers) {
      for (std::size_t length = 1; length <= 24; ++length) {
        for (std::size_t at = 0; at < length; ++at) {
          for (const char special : specials) {
            std::string name = filler.substr(0, length);
            name[at] = special;  // in Hangul, a byte of a character replaced: still one string
            const TraceStep step{1, 0.5, {{name, {1.0, 2.0}, 0.0, {0.0, 0.0}, 0.0}}, {}};
            const std::string line = trace_json_line(step);
            const bool plain = static_cast<unsigned char>(special) >= 0x20 && special != '"' &&
                               special != '\\';
            CAPTURE(name);
            if (filler == fillers[0]) CHECK(parse_trace_line(line).bodies.at(0).name == name);
            CHECK((line.find("\"name\":\"" + name + "\"") != std::string::npos) == plain);
            ++names;
          }
        }
      }
    }
    CHECK(names == 2 * 300 * 40);  // places in names of 1 to 24 bytes, times 40 characters
  }

  TEST_CASE("a JSON line of long names and many records reads back whole") {
    // The writer makes room once per record and writes its pieces unchecked: names longer than
    // it copies whole (256), names to escape, and lines of many buffers' worth (4096 bytes) must
    // still come out whole. Read back by nlohmann-json, field by field, exactly.
    TraceStep step{7, 0.125, {}, {}};
    for (int i = 0; i < 300; ++i) {
      const std::string name = (i % 3 == 0 ? std::string(1000 + i, 'x')
                                : i % 3 == 1 ? "tab\there \"quoted\" " + std::to_string(i)
                                             : "box" + std::to_string(i));
      step.bodies.push_back({name, {i * 0.1, -i / 3.0}, 1e-5 * i, {1e21, -0.0}, 2.5});
      step.contacts.push_back({{name, std::string(i, '\\')}, {0.5, 1.0 / 7.0}, {0.0, 1.0}, -1e-9,
                               1e300, 3.0, i % 2 == 0, "refound"});
    }
    const std::string line = trace_json_line(step);
    const TraceStep back = parse_trace_line(line);
    REQUIRE(back.bodies.size() == step.bodies.size());
    REQUIRE(back.contacts.size() == step.contacts.size());
    for (std::size_t i = 0; i < step.bodies.size(); ++i) {
      CAPTURE(i);
      CHECK(back.bodies[i].name == step.bodies[i].name);
      CHECK(back.bodies[i].position == step.bodies[i].position);
      CHECK(back.bodies[i].angle == step.bodies[i].angle);
      CHECK(back.bodies[i].velocity == step.bodies[i].velocity);
      CHECK(back.contacts[i].bodies == step.contacts[i].bodies);
      CHECK(back.contacts[i].point == step.contacts[i].point);
      CHECK(back.contacts[i].normal_impulse == step.contacts[i].normal_impulse);
      CHECK(back.contacts[i].cached == step.contacts[i].cached);
      CHECK(back.contacts[i].origin == "refound");
    }
  }

  TEST_CASE("a CSV field holding a comma or a quote is quoted") {
    const TraceStep step{3, 0.5, {{"a,\"b\"", {1.0, 2.0}, 0.0, {0.0, 0.0}, 0.0}}, {}};
    CHECK(trace_csv_body_rows(step) == "3,0.5,\"a,\"\"b\"\"\",1.0,2.0,0.0,0.0,0.0,0.0\n");
  }

  TEST_CASE_FIXTURE(TraceFolder, "a trace not finished leaves no file, not even its temporary") {
    {
      TraceWriter trace(folder / "run.csv");
      trace.write(TraceStep{1, 0.1, {}, {}});
    }
    CHECK(fs::is_empty(folder));
  }

  TEST_CASE_FIXTURE(TraceFolder, "a trace path that cannot be written is refused with one line naming it") {
    std::ofstream(folder / "file") << "x";
    for (const fs::path& path : {folder / "file" / "run.jsonl", folder}) {
      CAPTURE(path);
      std::string message;
      try {
        TraceWriter trace(path);
      } catch (const OutputError& e) {
        message = e.what();
      }
      CHECK(message.find(path.string()) != std::string::npos);
      CHECK(message.find('\n') == std::string::npos);
    }
    CHECK(std::distance(fs::directory_iterator(folder), {}) == 1);  // only "file"
  }
}
