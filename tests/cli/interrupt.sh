#!/bin/sh
# interrupt.sh <lamina> <folder> <INT|TERM> <trace|frames|recording|twice|viewer|viewer-frames>
# Starts a long `lamina run` writing into <folder>, sends it the signal once it has written
# something (recording: while it simulates the run whose frames it records, before it renders
# any; frames: while it renders them; twice: just after a step, then again once lamina has taken
# the first), and checks that it stops as docs/lamina-command.md promises (the long runs give
# --allow-large: they are long on purpose, past the work limits):
#   - exit code 128 + the signal (130 for Ctrl-C's SIGINT, 143 for SIGTERM);
#   - nothing on standard output, one line on standard error: "lamina: SCENE: interrupted after
#     N steps; trace -> FILE holds steps 0..N-1" (SIGTERM: "terminated"), with ", no frames
#     (stopped before rendering)" (recording) or ", while rendering frame M; ... , M frames ->
#     DIR" (frames);
#   - the trace holds steps 0..N-1, every line whole; the M frames are complete PNGs, ending
#     with their IEND chunk; nothing else and no temporary file is left;
#   - viewer (while it simulates a run it records for --viewer) and viewer-frames (while it
#     writes the viewer's frames): ", no viewer page" after the trace, and the viewer's folder
#     holds nothing but, for viewer-frames, an empty frames/ (the frames written are removed);
#   - twice: lamina dies by the second signal in the middle of the step the first one waits for
#     (exit code 128 + the signal, as above), says nothing, and leaves nothing: no trace, since
#     the run never finished it, and no temporary file, which the second signal removes.
lamina=$1 folder=$2 signal=$3 mode=$4
trace=$folder/trace.jsonl
frames=$folder/frames
viewer=$folder/viewer
every=3

fail() {
  echo "FAIL ($mode, SIG$signal): $*"
  [ -f "$folder/stderr" ] && echo "stderr: $(cat "$folder/stderr")"
  exit 1
}

# True when the process has exited (gone, or a zombie the shell has not reaped yet).
finished() { [ ! -e "/proc/$1" ] || [ "$(cut -d' ' -f3 "/proc/$1/stat")" = Z ]; }
running() { ! finished "$1"; }

# wait_while <seconds> <waited for> <command...>: runs the command every 0.01 s while it succeeds;
# after <seconds>, kills lamina and fails: "<waited for> after <seconds> s".
wait_while() {
  seconds=$1 waited_for=$2 tries=0
  shift 2
  while "$@"; do
    tries=$((tries + 1))
    [ $tries -le $((seconds * 100)) ] || { kill -KILL $pid; fail "$waited_for after $seconds s"; }
    sleep 0.01
  done
}

# True until lamina has written something (recording: made the trace's temporary); fails when lamina
# has ended.
not_written() {
  finished $pid && fail "lamina ended before it was signalled"
  ! { [ -e "$written" ] && { [ "$mode" = recording ] || [ -s "$written" ]; }; }
}

# True while the file still has the size $2; fails when lamina has ended.
same_size() {
  finished $pid && fail "lamina ended before it was signalled"
  [ "$(stat -c %s "$1")" = "$2" ]
}

# True while lamina may still be writing the trace: the file grew within the last 0.1 s, or
# lamina sleeps in the kernel (state D: a machine writing back much else can throttle a write
# for a long time). A step's line reaches the file in whole blocks of 1 MiB, not at its end
# (output/output_file.h), so the file's last byte says nothing of where a line ends.
# Fails when lamina has ended.
line_unfinished() {
  finished $pid && fail "lamina ended before it was signalled"
  size=$(stat -c %s "$1")
  sleep 0.1
  [ "$(stat -c %s "$1")" != "$size" ] || [ "$(cut -d' ' -f3 "/proc/$pid/stat")" = D ]
}

# True while the signal is pending for the process, sent but not yet taken by a thread: bit
# number - 1 of ShdPnd, the process's pending set in hexadecimal. Two signals sent while one is
# pending are one signal.
pending() {
  set -- "$(sed -n 's/^ShdPnd:[[:space:]]*//p' "/proc/$1/status" 2>/dev/null)"
  [ -n "$1" ] && [ $((0x${1#????????} >> (number - 1) & 1)) -eq 1 ]
}

# Fails when anything is left in the folder; else removes it.
expect_empty_folder() {
  left=$(ls -A "$folder")
  [ -z "$left" ] || fail "left behind: $left"
  rm -rf "$folder"
}

case $signal in
  INT) code_expected=130 what=interrupted number=2 ;;
  TERM) code_expected=143 what=terminated number=15 ;;
  *) fail "signal must be INT or TERM" ;;
esac
case $mode in
  trace)  # 55 boxes at 10000 sweeps a step: ~50 ms and ~80 kB a step
    scene=pyramid:10
    set -- run $scene --iterations 10000 --steps 100000 --allow-large --trace "$trace"
    written=$trace.tmp ;;
  frames)  # 30000 steps simulated and recorded in ~0.3 s, then ~1000 frames/s
    scene=box-on-ground
    set -- run $scene --steps 30000 --frames "$frames" --every $every --size 160x90 --trace "$trace"
    written=$frames/${scene}_0001.png ;;
  recording)  # 100000 steps of 820 boxes simulated before any frame is drawn: minutes
    scene=pyramid:40
    set -- run $scene --steps 100000 --allow-large --frames "$frames" --trace "$trace"
    written=$trace.tmp ;;
  twice)  # 1275 boxes at 10000 sweeps a step: ~1.5 s and ~1.6 MB a step (a window wide enough
    # for a loaded machine, where the script's polls can come a few hundred ms late)
    scene=pyramid:50
    set -- run $scene --iterations 10000 --steps 100000 --allow-large --trace "$trace"
    written=$trace.tmp ;;
  viewer)  # 55 boxes at 10000 sweeps a step, each step recorded for the viewer
    scene=pyramid:10
    set -- run $scene --iterations 10000 --steps 100000 --allow-large --trace "$trace" --viewer "$viewer"
    written=$trace.tmp ;;
  viewer-frames)  # 3000 steps simulated and recorded in ~1 s, then a frame per step
    scene=box-on-ground
    set -- run $scene --steps 3000 --trace "$trace" --viewer "$viewer" --size 160x90
    written=$viewer/frames/0-${scene}_0001.png ;;
  *) fail "mode must be trace, frames, recording, twice, viewer or viewer-frames" ;;
esac

rm -rf "$folder" && mkdir -p "$folder" || fail "cannot make $folder"
# A shell starts a background command with SIGINT ignored, and lamina keeps an ignored SIGINT
# ignored (as under nohup); a user's Ctrl-C reaches it with the default, as here.
env --default-signal=INT,TERM "$lamina" "$@" >"$folder/stdout" 2>"$folder/stderr" &
pid=$!

wait_while 60 "$written not written" not_written
if [ "$mode" = twice ]; then
  # The first signal just after lamina has written a step, so that the step it waits for has
  # ~1.5 s to run; the second once the first is taken (not merged with it), a few ms later.
  # A signal taken while the step's line is still being written would stop the run between
  # steps, at once, before the second could arrive: so the writing must be over first (each
  # step's 1.6 MB reach at least one bound of 1 MiB, so the file grows at every step).
  wait_while 30 "$written did not grow" same_size "$written" "$(stat -c %s "$written")"
  wait_while 30 "the line of a step in $written not finished" line_unfinished "$written"
  kill -$signal $pid
  wait_while 10 "the first SIG$signal not taken" pending $pid
fi
kill -$signal $pid
wait_while 60 "still running after SIG$signal" running $pid
wait $pid
code=$?

[ $code -eq $code_expected ] || fail "exit code $code, expected $code_expected"
[ -s "$folder/stdout" ] && fail "wrote to standard output: $(cat "$folder/stdout")"
if [ "$mode" = twice ]; then
  # No line: a run stopped by the first signal would say "interrupted after step N" and keep
  # its trace, so an empty standard error shows the second signal killed it.
  [ -s "$folder/stderr" ] && fail "stopped as for one signal, not killed by the second"
  rm "$folder/stdout" "$folder/stderr"
  expect_empty_folder
  echo "SIG$signal twice during a step: exit code $code, no trace and no temporary file left"
  exit 0
fi
[ "$(wc -l <"$folder/stderr")" -eq 1 ] || fail "standard error is not one line"
rm "$folder/stdout"
stderr=$(cat "$folder/stderr")
rm "$folder/stderr"

steps=$(echo "$stderr" | sed -n "s/^lamina: $scene: $what after \([0-9][0-9]*\) steps\{0,1\}[;,].*/\1/p")
[ -n "$steps" ] || fail "stderr does not say how many steps were taken: $stderr"
[ "$mode" = recording ] || [ "$steps" -ge 1 ] || fail "stopped before its first step: $stderr"
noun=steps
[ "$steps" -eq 1 ] && noun=step
held="steps 0..$((steps - 1))"
[ "$steps" -eq 0 ] && held="no steps"
case $mode in
  trace) expected="lamina: $scene: $what after $steps $noun; trace -> $trace holds $held" ;;
  recording)
    expected="lamina: $scene: $what after $steps $noun; trace -> $trace holds $held, no frames (stopped before rendering)" ;;
  viewer) expected="lamina: $scene: $what after $steps $noun; trace -> $trace holds $held, no viewer page" ;;
  viewer-frames)
    expected="lamina: $scene: $what after $steps $noun, while writing the viewer; trace -> $trace holds $held, no viewer page" ;;
  frames)
    count=$(echo "$stderr" | sed -n "s/.* while rendering frame \([0-9][0-9]*\);.*/\1/p")
    [ -n "$count" ] && [ "$count" -ge 1 ] || fail "stderr does not name a frame after the first: $stderr"
    expected="lamina: $scene: $what after $steps $noun, while rendering frame $count; trace -> $trace holds $held, $count frames -> $frames" ;;
esac
[ "$stderr" = "$expected" ] || fail "stderr: $stderr
expected: $expected"

# The trace: N lines, line k + 1 whole and of step k ('{"step":k,' ... '}'), and a newline at
# its end (an empty trace when no step was taken).
[ "$(wc -l <"$trace")" -eq "$steps" ] || fail "the trace has $(wc -l <"$trace") lines, not $steps"
awk -v q='"' 'index($0, "{" q "step" q ":" (NR - 1) ",") != 1 || !/}$/ { print "line " NR; exit 1 }' \
  "$trace" >/dev/null || fail "a trace line is not the whole line of its step"
[ "$steps" -eq 0 ] || [ "$(tail -c 1 "$trace" | od -An -tx1 | tr -d ' ')" = 0a ] ||
  fail "the trace's last line is cut short"

# Nothing else in the folder; the frames, complete.
for file in "$folder"/* "$folder"/.[!.]*; do
  [ -e "$file" ] || continue
  [ "$file" = "$trace" ] || [ "$file" = "$frames" ] || [ "$file" = "$viewer" ] || fail "left behind: $file"
done
if [ -e "$viewer" ]; then
  rmdir "$viewer/frames" 2>/dev/null
  left=$(ls -A "$viewer")
  [ -z "$left" ] || fail "the viewer's folder holds: $left"
fi
if [ "$mode" = frames ]; then
  files=$(ls -A "$frames" | wc -l)
  [ "$files" -eq "$count" ] || fail "$files files in $frames, not $count frames"
  frame=0
  while [ $frame -lt $count ]; do
    png=$frames/${scene}_$(printf %04d $frame).png
    [ "$(tail -c 12 "$png" | od -An -tx1 | tr -d ' \n')" = 0000000049454e44ae426082 ] ||
      fail "$png is missing or cut short"
    frame=$((frame + 1))
  done
fi
rm -rf "$folder"
echo "SIG$signal after $steps steps: exit code $code, the trace and ${count:-no} frames complete"
