#include "trace/trace_csv.h"

#include <initializer_list>

#include "scene/shortest_number.h"

namespace lamina {
namespace {

// Appends a name as one CSV field: quoted, with quotes doubled, when it holds a comma, a quote
// or a line break.
void append_field(std::string& out, const std::string& name) {
  if (name.find_first_of(",\"\r\n") == std::string::npos) {
    out += name;
    return;
  }
  out += '"';
  for (char c : name) out += c == '"' ? "\"\"" : std::string(1, c);
  out += '"';
}

// Appends "step,time,names...,values...[,cached,origin]\n": `cached` is ",true," or ",false,",
// or empty with `origin` for a body's row.
void append_row(std::string& out, const TraceStep& step, std::initializer_list<const std::string*> names,
                std::initializer_list<double> values, const char* cached = "",
                const std::string& origin = "") {
  out += std::to_string(step.step);
  out += ',';
  append_shortest(out, step.time);
  for (const std::string* name : names) {
    out += ',';
    append_field(out, *name);
  }
  for (double value : values) {
    out += ',';
    append_shortest(out, value);
  }
  out += cached;
  out += origin;
  out += '\n';
}

}  // namespace

std::string trace_csv_body_header() { return "step,time,body,x,y,angle,vx,vy,angular_velocity\n"; }

std::string trace_csv_contact_header() {
  return "step,time,body1,body2,x,y,nx,ny,depth,normal_impulse,tangent_impulse,cached,origin\n";
}

std::string trace_csv_body_rows(const TraceStep& step) {
  std::string rows;
  append_trace_csv_body_rows(rows, step);
  return rows;
}

std::string trace_csv_contact_rows(const TraceStep& step) {
  std::string rows;
  append_trace_csv_contact_rows(rows, step);
  return rows;
}

void append_trace_csv_body_rows(std::string& out, const TraceStep& step) {
  for (const BodyState& b : step.bodies) {
    append_row(out, step, {&b.name},
               {b.position[0], b.position[1], b.angle, b.velocity[0], b.velocity[1], b.angular_velocity});
  }
}

void append_trace_csv_contact_rows(std::string& out, const TraceStep& step) {
  for (const ContactState& c : step.contacts) {
    append_row(out, step, {&c.bodies[0], &c.bodies[1]},
               {c.point[0], c.point[1], c.normal[0], c.normal[1], c.depth, c.normal_impulse,
                c.tangent_impulse},
               c.cached ? ",true," : ",false,", c.origin);
  }
}

}  // namespace lamina
