#!/bin/sh
# interrupt.sh <lamina> <folder> <INT|TERM> <trace|frames|view>
# Starts a long `lamina run` writing into <folder>, sends it the signal once it has written
# something (view: while it fits the frames' view, before its first step), and checks that it
# stops as docs/lamina-command.md promises:
#   - exit code 128 + the signal (130 for Ctrl-C's SIGINT, 143 for SIGTERM);
#   - nothing on standard output, one line on standard error: "lamina: SCENE: interrupted after
#     step N; trace -> FILE holds steps 1..N[, M frames -> DIR]" (SIGTERM: "terminated");
#   - the trace holds steps 1..N, every line whole; the M frames (steps 0, 3, 6, ... up to N) are
#     complete PNGs, ending with their IEND chunk; nothing else and no temporary file is left;
#   - view: "... before step 1, while fitting the frames' view; nothing written", and nothing is.
lamina=$1 folder=$2 signal=$3 mode=$4
trace=$folder/trace.jsonl
frames=$folder/frames
every=3

fail() {
  echo "FAIL ($mode, SIG$signal): $*"
  [ -f "$folder/stderr" ] && echo "stderr: $(cat "$folder/stderr")"
  exit 1
}

# True when the process has exited (gone, or a zombie the shell has not reaped yet).
finished() { [ ! -e "/proc/$1" ] || [ "$(cut -d' ' -f3 "/proc/$1/stat")" = Z ]; }

case $signal in
  INT) code_expected=130 what=interrupted ;;
  TERM) code_expected=143 what=terminated ;;
  *) fail "signal must be INT or TERM" ;;
esac
case $mode in
  trace)  # 55 boxes at 10000 sweeps a step: ~50 ms and ~80 kB a step
    scene=pyramid:10
    set -- run $scene --iterations 10000 --steps 100000 --trace "$trace"
    written=$trace.tmp ;;
  frames)  # the view is fitted in ~0.3 s, then ~1000 frames/s
    scene=box-on-ground
    set -- run $scene --steps 100000 --frames "$frames" --every $every --size 160x90 --trace "$trace"
    written=$frames/${scene}_0001.png ;;
  view)  # fitting the view simulates 100000 steps of 820 boxes first: minutes
    scene=pyramid:40
    set -- run $scene --steps 100000 --frames "$frames" --trace "$trace"
    written=$trace.tmp ;;
  *) fail "mode must be trace, frames or view" ;;
esac

rm -rf "$folder" && mkdir -p "$folder" || fail "cannot make $folder"
# A shell starts a background command with SIGINT ignored, and lamina keeps an ignored SIGINT
# ignored (as under nohup); a user's Ctrl-C reaches it with the default, as here.
env --default-signal=INT,TERM "$lamina" "$@" >"$folder/stdout" 2>"$folder/stderr" &
pid=$!

tries=0
until [ -e "$written" ] && { [ "$mode" = view ] || [ -s "$written" ]; }; do
  finished $pid && fail "lamina ended before it was signalled"
  tries=$((tries + 1))
  [ $tries -le 600 ] || { kill -KILL $pid; fail "$written not written after 60 s"; }
  sleep 0.1
done
kill -$signal $pid
tries=0
until finished $pid; do
  tries=$((tries + 1))
  [ $tries -le 600 ] || { kill -KILL $pid; fail "still running 60 s after SIG$signal"; }
  sleep 0.1
done
wait $pid
code=$?

[ $code -eq $code_expected ] || fail "exit code $code, expected $code_expected"
[ -s "$folder/stdout" ] && fail "wrote to standard output: $(cat "$folder/stdout")"
[ "$(wc -l <"$folder/stderr")" -eq 1 ] || fail "standard error is not one line"
rm "$folder/stdout"
stderr=$(cat "$folder/stderr")
rm "$folder/stderr"

if [ "$mode" = view ]; then
  expected="lamina: $scene: $what before step 1, while fitting the frames' view; nothing written"
  [ "$stderr" = "$expected" ] || fail "stderr: $stderr
expected: $expected"
  left=$(ls -A "$folder")
  [ -z "$left" ] || fail "left behind: $left"
  rm -rf "$folder"
  echo "SIG$signal while fitting the view: exit code $code, nothing written"
  exit 0
fi

steps=$(echo "$stderr" | sed -n "s/^lamina: $scene: $what after step \([0-9][0-9]*\);.*/\1/p")
[ -n "$steps" ] && [ "$steps" -ge 1 ] || fail "stderr does not name a step after the first: $stderr"
expected="lamina: $scene: $what after step $steps; trace -> $trace holds steps 1..$steps"
if [ "$mode" = frames ]; then
  count=$((steps / every + 1))
  expected="$expected, $count frames -> $frames"
fi
[ "$stderr" = "$expected" ] || fail "stderr: $stderr
expected: $expected"

# The trace: N lines, line k whole and of step k ('{"step":k,' ... '}'), and a newline at its end.
[ "$(wc -l <"$trace")" -eq "$steps" ] || fail "the trace has $(wc -l <"$trace") lines, not $steps"
awk -v q='"' 'index($0, "{" q "step" q ":" NR ",") != 1 || !/}$/ { print "line " NR; exit 1 }' \
  "$trace" >/dev/null || fail "a trace line is not the whole line of its step"
[ "$(tail -c 1 "$trace" | od -An -tx1 | tr -d ' ')" = 0a ] || fail "the trace's last line is cut short"

# Nothing else in the folder; the frames, complete.
for file in "$folder"/* "$folder"/.[!.]*; do
  [ -e "$file" ] || continue
  [ "$file" = "$trace" ] || [ "$file" = "$frames" ] || fail "left behind: $file"
done
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
echo "SIG$signal after step $steps: exit code $code, the trace and ${count:-no} frames complete"
