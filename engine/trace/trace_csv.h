// Traces as CSV, for spreadsheets: one row per dynamic body per step in one file, one row per
// contact per step in a second. Columns as in trace.h; numbers in shortest round-trip form.
//
//   step,time,body,x,y,angle,vx,vy,angular_velocity
//   step,time,body1,body2,x,y,nx,ny,depth,normal_impulse,tangent_impulse,cached,origin
#pragma once

#include <string>

#include "trace/trace.h"

namespace lamina {

// The header lines, each with its line break.
std::string trace_csv_body_header();
std::string trace_csv_contact_header();

// The step's rows, each with its line break.
std::string trace_csv_body_rows(const TraceStep& step);
std::string trace_csv_contact_rows(const TraceStep& step);
// The same rows appended to `out`, so that a writer reuses one buffer step after step.
void append_trace_csv_body_rows(std::string& out, const TraceStep& step);
void append_trace_csv_contact_rows(std::string& out, const TraceStep& step);

}  // namespace lamina
