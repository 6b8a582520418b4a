// Signals during `lamina run`. Ctrl-C (SIGINT) and SIGTERM do not kill the run half way through
// a write: the handler only notes the signal, the run checks it between steps and stops with its
// outputs complete (RunStopped, exit code 128 + the signal). A second one of the same kills it at
// once, by that signal, after removing the temporary files being written
// (output/unfinished_files.h): it leaves no "<path>.tmp", only the files already complete.
#pragma once

#include <string>

#include "app/cli/exit_codes.h"

namespace lamina::cli {

// From now on SIGINT and SIGTERM are noted, not fatal, the first time each arrives; the second
// time, the unfinished files are removed and the signal is raised again with its default action.
// One that the caller of lamina ignores (nohup, a background job) stays ignored.
void note_stop_signals();

// The signal that asked the run to stop, 0 while none has.
int stop_signal();

// The error that stops a run for `signal`: "<where>: interrupted <when>" (SIGINT), or
// "terminated" (SIGTERM), with exit code 128 + signal.
RunStopped stopped_by(int signal, const std::string& where, const std::string& when);

// A write past the file size limit (`ulimit -f`) fails with EFBIG, "File too large", and is
// reported like any failed write, instead of SIGXFSZ killing lamina with a core dump.
void ignore_file_size_signal();

}  // namespace lamina::cli
