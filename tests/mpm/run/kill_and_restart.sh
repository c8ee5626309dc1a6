#!/bin/sh
# A real SIGTERM from outside (tests/mpm/CMakeLists.txt, docs/mpm.md#checkpoint-and-restart):
# runs SCENE uninterrupted into OUT/a; runs it again into OUT/b, sends SIGTERM once history.csv
# has 4 rows, expects exit 143 (checkpoint written, status.json "interrupted", no .tmp left),
# continues it with `mpm run --restart OUT/b` and expects history.csv (every ledger row to 17
# digits) to match OUT/a byte for byte. Usage: kill_and_restart.sh MPM SCENE OUT
set -u
mpm=$1 scene=$2 out=$3
rm -rf "$out" && mkdir -p "$out" || exit 1
"$mpm" run "$scene" --out "$out/a" --threads 2 || { echo "uninterrupted run failed"; exit 1; }
"$mpm" run "$scene" --out "$out/b" --threads 2 &
pid=$!
i=0
while [ "$(cat "$out/b/history.csv" 2>/dev/null | wc -l)" -lt 5 ]; do
  i=$((i + 1))
  [ $i -gt 6000 ] && { echo "no history rows after 60 s"; kill $pid; exit 1; }
  sleep 0.01
done
kill -TERM $pid
wait $pid
rc=$?
[ $rc -eq 143 ] || { echo "expected exit 143 after SIGTERM, got $rc"; exit 1; }
grep -q '"status": "interrupted"' "$out/b/status.json" || { echo "status.json:"; cat "$out/b/status.json"; exit 1; }
[ -f "$out/b/checkpoint.bin" ] || { echo "no checkpoint"; exit 1; }
stopped=$(grep -o '"step": [0-9]*' "$out/b/status.json" | head -1)
ls "$out/b"/*.tmp "$out/b"/particles/*.tmp 2>/dev/null && { echo "a .tmp file was left"; exit 1; }
"$mpm" run --restart "$out/b" || { echo "restart failed"; exit 1; }
cmp "$out/a/history.csv" "$out/b/history.csv" || { echo "history.csv differs"; exit 1; }
echo "SIGTERM: stopped at $stopped with exit 143; restarted; history.csv identical ($(wc -l < "$out/a/history.csv") lines)"
rm -rf "$out"
