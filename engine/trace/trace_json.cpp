#include "trace/trace_json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scene/shortest_number.h"

namespace lamina {
namespace {

using Json = nlohmann::json;

// The line is written directly, not built as a JSON tree: a 210-box pyramid writes about
// 9 000 numbers a step, and trees made tracing several times slower than simulating. It goes
// through a buffer of the writer's own, appended to `out` when full: appending each key, number
// and bracket to `out` one by one cost 2.4 times the instructions (callgrind, 60 steps of the
// pyramid: 248 M against 104 M, to_chars apart).
class LineWriter {
 public:
  explicit LineWriter(std::string& out) : out_(out) {}
  LineWriter(const LineWriter&) = delete;
  LineWriter& operator=(const LineWriter&) = delete;

  // `"key":`, after a comma unless it opens the object. Keys are literals: their length is a
  // constant, and copying them a few moves.
  template <std::size_t size>
  LineWriter& key(const char (&name)[size]) {
    constexpr std::size_t length = size - 1;
    make_room(length + 4);
    if (last() != '{') *end_++ = ',';
    *end_++ = '"';
    std::memcpy(end_, name, length);
    end_ += length;
    *end_++ = '"';
    *end_++ = ':';
    return *this;
  }
  // A finite number in shortest round-trip form; JSON has no infinities or NaN: null.
  void number(double x) {
    if (std::isfinite(x)) {
      make_room(shortest_float_length);
      end_ = write_shortest_float(end_, x);
    } else {
      raw("null");
    }
  }
  void vec2(const Vec2& v) {
    raw('[');
    number(v[0]);
    raw(',');
    number(v[1]);
    raw(']');
  }
  // Quoted, with '"', '\\' and control characters escaped as JSON asks (RFC 8259, 7); the
  // rest, UTF-8 included, as it is. (nlohmann's dump, one value per string, cost a tenth of the
  // trace's time on a pyramid.)
  void text(const std::string& s) {
    if (s.size() < sizeof buffer_ / 2) {  // most names: copied as they are, unless one needs escapes
      make_room(s.size() + 2);
      char* const start = end_;
      *end_++ = '"';
      for (const char ch : s) {
        if (ch == '"' || ch == '\\' || static_cast<unsigned char>(ch) < 0x20) {
          end_ = start;
          break;
        }
        *end_++ = ch;
      }
      if (end_ != start) {
        *end_++ = '"';
        return;
      }
    }
    raw('"');
    for (const char ch : s) {
      const auto c = static_cast<unsigned char>(ch);
      if (c == '"' || c == '\\') {
        raw('\\');
        raw(ch);
      } else if (c < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
        raw(escaped);
      } else {
        raw(ch);
      }
    }
    raw('"');
  }
  void raw(char c) {
    make_room(1);
    *end_++ = c;
  }
  void raw(std::string_view s) {
    if (s.size() > sizeof buffer_) {
      flush();
      out_ += s;
      return;
    }
    make_room(s.size());
    end_ = std::copy(s.begin(), s.end(), end_);
  }
  // Appends what the buffer holds to `out`; the line is whole there once this is called last.
  void flush() {
    out_.append(buffer_, end_);
    end_ = buffer_;
  }

 private:
  void make_room(std::size_t size) {
    if (static_cast<std::size_t>(buffer_ + sizeof buffer_ - end_) < size) flush();
  }
  char last() const { return end_ > buffer_ ? end_[-1] : out_.back(); }

  std::string& out_;
  char buffer_[4096];      // the text written since the last flush, up to end_
  char* end_ = buffer_;
};

void write_body(LineWriter& w, const BodyState& b) {
  w.raw('{');
  w.key("name").text(b.name);
  w.key("position").vec2(b.position);
  w.key("angle").number(b.angle);
  w.key("velocity").vec2(b.velocity);
  w.key("angular_velocity").number(b.angular_velocity);
  w.raw('}');
}

void write_contact(LineWriter& w, const ContactState& c) {
  w.raw('{');
  w.key("bodies").raw('[');
  w.text(c.bodies[0]);
  w.raw(',');
  w.text(c.bodies[1]);
  w.raw(']');
  w.key("point").vec2(c.point);
  w.key("normal").vec2(c.normal);
  w.key("depth").number(c.depth);
  w.key("normal_impulse").number(c.normal_impulse);
  w.key("tangent_impulse").number(c.tangent_impulse);
  w.key("cached").raw(c.cached ? "true" : "false");
  w.key("origin").text(c.origin);
  w.raw('}');
}

// `"key":[item,item,...]` of the items written by `write`.
template <std::size_t size, typename Item, typename Write>
void write_list(LineWriter& w, const char (&key)[size], const std::vector<Item>& items, Write write) {
  w.key(key).raw('[');
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) w.raw(',');
    write(w, items[i]);
  }
  w.raw(']');
}

Vec2 vec2_of(const Json& j) { return Vec2(j.at(0).get<double>(), j.at(1).get<double>()); }

BodyState body_state(const Json& j) {
  return {j.at("name"), vec2_of(j.at("position")), j.at("angle"), vec2_of(j.at("velocity")),
          j.at("angular_velocity")};
}

ContactState contact_state(const Json& j) {
  const bool cached = j.at("cached");
  // a trace written before "origin" was: a cached point was kept, any other one is taken as new
  const std::string origin = j.contains("origin") ? j.at("origin").get<std::string>() : cached ? "kept" : "new";
  return {j.at("bodies"), vec2_of(j.at("point")), vec2_of(j.at("normal")), j.at("depth"),
          j.at("normal_impulse"), j.at("tangent_impulse"), cached, origin};
}

}  // namespace

std::string trace_json_line(const TraceStep& step) {
  std::string line;
  append_trace_json_line(line, step);
  return line;
}

void append_trace_json_line(std::string& out, const TraceStep& step) {
  LineWriter w(out);
  w.raw('{');
  w.key("step").raw(std::to_string(step.step));
  w.key("time").number(step.time);
  write_list(w, "bodies", step.bodies, write_body);
  write_list(w, "contacts", step.contacts, write_contact);
  w.raw('}');
  w.flush();
}

TraceStep parse_trace_line(const std::string& line) {
  try {
    const Json j = Json::parse(line);
    TraceStep step{j.at("step"), j.at("time"), {}, {}};
    for (const Json& b : j.at("bodies")) step.bodies.push_back(body_state(b));
    for (const Json& c : j.at("contacts")) step.contacts.push_back(contact_state(c));
    return step;
  } catch (const Json::exception& e) {
    throw std::invalid_argument(std::string("not a trace line: ") + e.what());
  }
}

}  // namespace lamina
