// Traces as JSON Lines: one object per step, keys in the order below, every number in the
// shortest form that reads back to the same double.
//
//   {"step":1,"time":0.016666666666666666,
//    "bodies":[{"name":"box","position":[0.0,1.99],"angle":0.3,"velocity":[0.0,-0.16],
//               "angular_velocity":0.0}],
//    "contacts":[{"bodies":["ground","box"],"point":[0.1,0.0],"normal":[0.0,1.0],"depth":0.001,
//                 "normal_impulse":0.08,"tangent_impulse":0.0,"cached":true,"origin":"kept"}]}
#pragma once

#include <cstddef>
#include <string>

#include "trace/trace.h"

namespace lamina {

// The step as one line of JSON, without the line break.
std::string trace_json_line(const TraceStep& step);
// Where a line's text goes, written in place: the writer asks for room, writes into it and
// says how much it wrote, a few kilobytes at a time, in order. A trace's file gives room in
// the block it hands to the kernel (output/output_file.h): its text is written where it goes,
// never copied (a third of a megabyte a step on pyramid:20).
class TextSink {
 public:
  virtual ~TextSink() = default;
  // At least `size` bytes (at most room_limit) to write into, after what was written before.
  virtual char* room(std::size_t size) = 0;
  // The first `size` bytes of the last room given hold text now.
  virtual void wrote(std::size_t size) = 0;
  static constexpr std::size_t room_limit = 4096;
};
// The same line written into `sink`.
void write_trace_json_line(TextSink& sink, const TraceStep& step);

// A line of a JSON Lines trace read back. Throws std::invalid_argument for anything else.
TraceStep parse_trace_line(const std::string& line);

}  // namespace lamina
