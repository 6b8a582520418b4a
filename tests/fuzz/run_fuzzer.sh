#!/bin/sh
# run_fuzzer.sh <fuzzer> <seed writer or -> <work> <seconds> <regressions> <seed folder>...
#
# First runs every file of <regressions> (tests/data/fuzz/regressions for scene_fuzzer,
# physics_regressions for physics_fuzzer) once, whole, so that a crash found before fails at
# once, however long its file. Then fuzzes for <seconds>: writes the seeds (scene_fuzzer's: the
# built-in scenes) into <work>/seeds unless the writer is "-", and runs libFuzzer over
# <work>/corpus (where it keeps new inputs, kept between runs), <work>/seeds, <regressions> and
# the seed folders given (the bad-scene catalogue). Exits non-zero on a crash, a sanitizer report, a leak
# or an input slower than -timeout; the input is saved as <work>/crashes/<kind>-<sha1>.
#
# <seconds> 0 runs no mutation: each seed (the writer's, then the seed folders') is run once, the
# same inputs on every machine (fuzz_physics in CI: libFuzzer's mutations follow coverage, which
# differs by an edge between two runs of one input and one build, so a mutating run cannot be
# repeated; docs/reliability.md).
#
# LAMINA_FUZZ_DICT names a dictionary (-dict) and LAMINA_FUZZ_FLAGS adds libFuzzer flags, each
# fuzzer's own (tests/fuzz/CMakeLists.txt); LAMINA_FUZZ_NO_REGRESSION_SEEDS (set to any word)
# runs the regressions first only, not as seeds of the fuzzing (the physics fuzzer's are scene
# files, whose mutations would all read as one kind of the grammar).
# Bounds of one execution: -max_len=8192 bytes of scene file (longer seeds are cut to that),
# -timeout=10 s, -rss_limit_mb=2048; scene_fuzzer.cpp also steps only scenes of at most 64
# bodies and 1000 iterations.
set -eu
[ $# -ge 5 ] || {
  echo "usage: $0 <scene_fuzzer> <write_seed_corpus> <work> <seconds> <regressions> <seeds>..." >&2
  exit 2
}
fuzzer=$1 seed_writer=$2 work=$3 seconds=$4 regressions=$5
shift 5

mkdir -p "$work/corpus" "$work/crashes" "$work/seeds"
[ "$seed_writer" = "-" ] || "$seed_writer" "$work/seeds"

# A sanitizer report stops the run with its stack (the build has -fno-sanitize-recover=all).
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

status=0
"$fuzzer" -timeout=10 -rss_limit_mb=2048 "$regressions"/* || status=$?
if [ "$status" -ne 0 ]; then
  echo "run_fuzzer.sh: a regression crashed again (exit $status):" \
       "the file named by 'Running:' above." >&2
  exit "$status"
fi

if [ "$seconds" = 0 ]; then
  "$fuzzer" -runs=0 -max_len=8192 -timeout=10 -rss_limit_mb=2048 ${LAMINA_FUZZ_FLAGS:-} \
    -print_final_stats=1 -artifact_prefix="$work/crashes/" "$work/seeds" "$@" || status=$?
  if [ "$status" -ne 0 ]; then
    echo "run_fuzzer.sh: $(basename "$fuzzer") failed on a seed (exit $status); it is in $work/crashes/." >&2
    echo "Reproduce: $fuzzer <input>; then keep it in $regressions/ under a short name." >&2
  fi
  exit "$status"
fi

[ -n "${LAMINA_FUZZ_NO_REGRESSION_SEEDS:-}" ] || set -- "$regressions" "$@"
"$fuzzer" -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
  ${LAMINA_FUZZ_DICT:+-dict="$LAMINA_FUZZ_DICT"} ${LAMINA_FUZZ_FLAGS:-} -print_final_stats=1 -artifact_prefix="$work/crashes/" \
  "$work/corpus" "$work/seeds" "$@" || status=$?
if [ "$status" -ne 0 ]; then
  echo "run_fuzzer.sh: $(basename "$fuzzer") failed (exit $status); the input is in $work/crashes/." >&2
  echo "Reproduce: $fuzzer <input>; shrink: $fuzzer -minimize_crash=1 -runs=100000 <input>;" \
       "then keep it in $regressions/ under a short name." >&2
  exit "$status"
fi
