#include "trace/trace_json.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "scene/shortest_number.h"

namespace lamina {
namespace {

using Json = nlohmann::json;

// The line is written directly, not built as a JSON tree: a 210-box pyramid writes about
// 9 000 numbers a step, and trees made tracing several times slower than simulating. It goes
// into room of a few kilobytes its sink gives it (in a string, or in the trace's file's block),
// asking for more when full: appending each key, number and bracket to a string one by one
// cost 2.4 times the instructions (callgrind, 60 steps of the pyramid: 248 M against 104 M,
// to_chars apart).
// Each record (a body, a contact, the line's head) first makes room for the most it can write,
// and its pieces are then written without a check each: the keys with their punctuation as
// literals of constant length ("," "\"point\":"), the numbers, the names (a third of the
// writer's instructions went to those checks).
class LineWriter {
 public:
  // Names are copied whole up to this many characters; a longer one (or one to escape) is
  // escaped character by character, each making its own room.
  static constexpr std::size_t long_name = 256;
  // The most a record writes: its keys and brackets (under 160 characters), up to 8 numbers
  // (with the room write_shortest_float asks) and 3 names.
  static constexpr std::size_t record_room = 160 + 8 * shortest_float_length + 3 * (long_name + 2);

  explicit LineWriter(TextSink& sink) : sink_(sink) { take_room(); }
  LineWriter(const LineWriter&) = delete;
  LineWriter& operator=(const LineWriter&) = delete;

  // Room for a record: what follows, up to the next call, is written without checks.
  void make_room(std::size_t size) {
    if (static_cast<std::size_t>(limit_ - end_) < size) {
      hand_on();
      take_room();
    }
  }
  // Text of a length known at compile time: a key with its punctuation, a bracket.
  template <std::size_t size>
  void literal(const char (&text)[size]) {
    std::memcpy(end_, text, size - 1);
    end_ += size - 1;
  }
  // A key (with its punctuation, as a literal) and its value.
  template <std::size_t size, typename Value>
  void field(const char (&key)[size], const Value& value) {
    literal(key);
    write(value);
  }
  void write(long n) { end_ = std::to_chars(end_, end_ + 24, n).ptr; }
  // A finite number in shortest round-trip form; JSON has no infinities or NaN: null.
  void write(double x) {
    if (std::isfinite(x)) {
      end_ = write_shortest_float(end_, x);
    } else {
      literal("null");
    }
  }
  void write(const Vec2& v) {
    *end_++ = '[';
    write(v[0]);
    *end_++ = ',';
    write(v[1]);
    *end_++ = ']';
  }
  // Quoted, with '"', '\\' and control characters escaped as JSON asks (RFC 8259, 7); the
  // rest, UTF-8 included, as it is. (nlohmann's dump, one value per string, cost a tenth of the
  // trace's time on a pyramid.)
  void write(const std::string& s) {
    const std::size_t n = s.size();
    if (n <= long_name && copied_plain(s)) {  // most names: copied whole
      end_[0] = '"';
      end_[n + 1] = '"';
      end_ += n + 2;
      return;
    }
    put('"');
    for (const char ch : s) {
      const auto c = static_cast<unsigned char>(ch);
      if (c == '"' || c == '\\') {
        put('\\');
        put(ch);
      } else if (c < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
        for (const char* e = escaped; *e != 0; ++e) put(*e);
      } else {
        put(ch);
      }
    }
    put('"');
    make_room(record_room);  // the rest of the record, as its first make_room promised
  }
  // Hands on what is written; the line is whole once this is called last.
  void hand_on() { sink_.wrote(static_cast<std::size_t>(end_ - begin_)); }

 private:
  // Copies s after the opening quote's place and says whether it has nothing to escape: no '"',
  // '\\' or control character (a table look-up per character, in the one pass that copies it:
  // a name is checked on every line it is written in). When it has, the copy is written over.
  bool copied_plain(const std::string& s) {
    static constexpr auto escaped = [] {
      std::array<unsigned char, 256> table{};
      for (int c = 0; c < 0x20; ++c) table[static_cast<std::size_t>(c)] = 1;
      table['"'] = table['\\'] = 1;
      return table;
    }();
    unsigned char any = 0;
    char* out = end_ + 1;
    for (const char ch : s) {
      any |= escaped[static_cast<unsigned char>(ch)];
      *out++ = ch;
    }
    return any == 0;
  }

  void put(char c) {  // with a check: for text that may be of any length
    make_room(1);
    *end_++ = c;
  }

  void take_room() {
    begin_ = end_ = sink_.room(TextSink::room_limit);
    limit_ = begin_ + TextSink::room_limit;
  }

  TextSink& sink_;
  char* begin_ = nullptr;  // the room the sink gave: text from begin_ to end_, room to limit_
  char* end_ = nullptr;
  char* limit_ = nullptr;
};
static_assert(LineWriter::record_room < TextSink::room_limit, "a record fits the room");

// A string as a sink: grown by the room asked for, cut back to what was written.
class StringSink : public TextSink {
 public:
  explicit StringSink(std::string& out) : out_(out), used_(out.size()) {}
  char* room(std::size_t size) override {
    out_.resize(used_ + size);
    return out_.data() + used_;
  }
  void wrote(std::size_t size) override {
    used_ += size;
    out_.resize(used_);
  }

 private:
  std::string& out_;
  std::size_t used_;  // the string's text; room after it
};

void write_body(LineWriter& w, const BodyState& b) {
  w.field(R"({"name":)", b.name);
  w.field(R"(,"position":)", b.position);
  w.field(R"(,"angle":)", b.angle);
  w.field(R"(,"velocity":)", b.velocity);
  w.field(R"(,"angular_velocity":)", b.angular_velocity);
  w.literal("}");
}

void write_contact(LineWriter& w, const ContactState& c) {
  w.field(R"({"bodies":[)", c.bodies[0]);
  w.field(",", c.bodies[1]);
  w.field(R"(],"point":)", c.point);
  w.field(R"(,"normal":)", c.normal);
  w.field(R"(,"depth":)", c.depth);
  w.field(R"(,"normal_impulse":)", c.normal_impulse);
  w.field(R"(,"tangent_impulse":)", c.tangent_impulse);
  if (c.cached) {
    w.literal(R"(,"cached":true)");
  } else {
    w.literal(R"(,"cached":false)");
  }
  w.field(R"(,"origin":)", c.origin);
  w.literal("}");
}

// The items written by `write`, comma-separated, each a record.
template <typename Item, typename Write>
void write_list(LineWriter& w, const std::vector<Item>& items, Write write) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    w.make_room(LineWriter::record_room);
    if (i > 0) w.literal(",");
    write(w, items[i]);
  }
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
  StringSink sink(line);
  write_trace_json_line(sink, step);
  return line;
}

void write_trace_json_line(TextSink& sink, const TraceStep& step) {
  LineWriter w(sink);
  w.make_room(LineWriter::record_room);
  w.field(R"({"step":)", step.step);
  w.field(R"(,"time":)", step.time);
  w.literal(R"(,"bodies":[)");
  write_list(w, step.bodies, write_body);
  w.make_room(LineWriter::record_room);
  w.literal(R"(],"contacts":[)");
  write_list(w, step.contacts, write_contact);
  w.make_room(LineWriter::record_room);
  w.literal("]}");
  w.hand_on();
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
