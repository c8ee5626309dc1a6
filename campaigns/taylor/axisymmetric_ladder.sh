#!/bin/bash
# The House shots in axisymmetry on the ladder 4, 6, 8, 12, 16, 24 cells per radius (docs/taylor.md,
# "Axisymmetric ladder"): Table 1's set, failure off, mirror anvil. One pass per level into the same
# OUT, coarse first, so that results.md and convergence.csv hold every finished level while the
# finer ones run; each pass skips the runs already finished (result.json), so the script can be
# stopped and started again. OUT/meta_n<N>.json: the wall time of the pass that added level N.
#   campaigns/taylor/axisymmetric_ladder.sh [OUT] [THREADS]
cd "$(dirname "$0")/../.." || exit 1
OUT=${1:-docs/figures/taylor_axisymmetric_ladder}
THREADS=${2:-2}
levels=""
for n in 4 6 8 12 16 24; do
  levels="${levels:+$levels,}$n"
  echo "=== $(date -u +%H:%M:%S) levels $levels"
  /usr/bin/python3 campaigns/taylor/taylor.py "$OUT" --runs build/taylor --sets table1 \
    --failure off --geometry axisymmetric --jobs 1 --threads "$THREADS" --cells-per-radius "$levels"
  status=$?
  cp "$OUT/meta.json" "$OUT/meta_n$n.json"
  echo "=== $(date -u +%H:%M:%S) levels $levels done (exit $status)"
done
