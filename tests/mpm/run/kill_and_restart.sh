#!/bin/sh
# Real signals from outside, three times (tests/mpm/CMakeLists.txt, docs/mpm.md#checkpoint-and-
# restart): runs SCENE (a path relative to SOURCE, run from SOURCE, so that scene.json holds
# material paths relative to the working directory, as every shipped scene run from the
# repository root does) uninterrupted into OUT/a; runs it again into OUT/b and stops it three
# times, each time once history.csv has grown: SIGTERM (exit 143), SIGINT (exit 130), SIGTERM,
# each followed by `mpm run --restart OUT/b`, the second from another working directory. Each stop
# must leave a checkpoint, status.json "interrupted" and no .tmp; the last restart runs to the end
# and history.csv (every ledger row to 17 digits) must match OUT/a byte for byte.
# Usage: kill_and_restart.sh MPM SOURCE SCENE OUT
set -u
mpm=$1 source=$2 scene=$3 out=$4
rm -rf "$out" && mkdir -p "$out" || exit 1
cd "$source" || exit 1
"$mpm" run "$scene" --out "$out/a" --threads 2 || { echo "uninterrupted run failed"; exit 1; }
rows() { cat "$out/b/history.csv" 2>/dev/null | wc -l; }

# stop_once SIGNAL CODE: waits for history.csv to grow by 4 rows past its length now, sends SIGNAL
# to the background run $pid, and checks what the stop left.
stop_once() {
  target=$(($(rows) + 4)) i=0
  while [ "$(rows)" -lt $target ]; do
    i=$((i + 1))
    [ $i -gt 6000 ] && { echo "history.csv did not grow in 60 s"; kill $pid; exit 1; }
    kill -0 $pid 2>/dev/null || { echo "the run ended before the $1 (make the scene longer)"; exit 1; }
    sleep 0.01
  done
  kill -"$1" $pid
  wait $pid
  rc=$?
  [ $rc -eq "$2" ] || { echo "expected exit $2 after SIG$1, got $rc"; exit 1; }
  grep -q '"status": "interrupted"' "$out/b/status.json" || { echo "status.json:"; cat "$out/b/status.json"; exit 1; }
  [ -f "$out/b/checkpoint.bin" ] || { echo "no checkpoint after SIG$1"; exit 1; }
  ls "$out/b"/*.tmp "$out/b"/particles/*.tmp 2>/dev/null && { echo "a .tmp file was left"; exit 1; }
  stops="$stops SIG$1 at $(grep -o '"step": [0-9]*' "$out/b/status.json" | head -1 | cut -d' ' -f2);"
}

stops=""
"$mpm" run "$scene" --out "$out/b" --threads 2 &
pid=$!
stop_once TERM 143
"$mpm" run --restart "$out/b" &
pid=$!
stop_once INT 130
# The second restart from elsewhere: material paths stay relative to the first run's directory.
(cd / && exec "$mpm" run --restart "$out/b") &
pid=$!
stop_once TERM 143
"$mpm" run --restart "$out/b" || { echo "the third restart failed"; exit 1; }
grep -q '"status": "completed"' "$out/b/status.json" || { echo "not completed"; exit 1; }
cmp "$out/a/history.csv" "$out/b/history.csv" || { echo "history.csv differs"; exit 1; }
echo "stopped by$stops restarted three times; history.csv identical ($(wc -l < "$out/a/history.csv") lines)"
rm -rf "$out"
