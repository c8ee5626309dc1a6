#!/usr/bin/env bash
# Runs the libFuzzer targets of the input loaders (tests/fuzz/fuzz_*.cpp), one process at a time.
#   tests/fuzz/run_fuzz.sh BUILD_DIR SECONDS [TARGET ...]
# BUILD_DIR is the `fuzz` preset's build (build-fuzz/), SECONDS the time per target, TARGETs any of
# material path scene fit_config experiment (default: all). `./run.sh fuzz [SECONDS]` and the
# CTest tests of label `fuzz` call this script.
#
# Each target starts from a copy of its seed corpus (the repository's real inputs,
# tests/data/bad_* and tests/fuzz/regressions/) in a scratch folder that is deleted afterwards, so
# the repository never grows.
# Findings (crash-*, leak-*, timeout-*, oom-* inputs) go to BUILD_DIR/findings/TARGET/, the log to
# BUILD_DIR/findings/TARGET.log. Exit status 1 when any target has a finding.
# Reproduce one: BUILD_DIR/bin/fuzz_TARGET BUILD_DIR/findings/TARGET/crash-...
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
build="$(cd "${1:?usage: run_fuzz.sh BUILD_DIR SECONDS [TARGET ...]}" && pwd)"
seconds="${2:?usage: run_fuzz.sh BUILD_DIR SECONDS [TARGET ...]}"
shift 2
targets=("$@")
((${#targets[@]})) || targets=(material path scene fit_config experiment)

# Seed inputs per target: repository inputs, the matching tests/data/bad_* folders and
# tests/fuzz/regressions/TARGET/ (past findings, minimal; libFuzzer runs every seed first).
seeds() {
  shopt -s nullglob
  printf '%s\n' "$here/regressions/$1"/*
  case "$1" in
    material) printf '%s\n' "$repo"/data/materials/*.json "$repo"/tests/data/bad_material*/* ;;
    path) printf '%s\n' "$repo"/data/paths/*.json "$repo"/tests/data/bad_path*/* ;;
    scene) printf '%s\n' "$repo"/data/scenes/*/*.json "$repo"/tests/data/bad_scene*/* ;;
    fit_config)
      printf '%s\n' "$repo"/data/fits/*.json "$repo"/tests/data/bad_fit*/* \
        "$repo"/tests/data/bad_check*/*
      ;;
    experiment)
      printf '%s\n' "$repo"/data/experiments/*/*.csv "$repo"/tests/data/bad_experiment*/*
      ;;
    *)
      echo "run_fuzz.sh: unknown target '$1'" >&2
      exit 2
      ;;
  esac
}

scratch="$(mktemp -d "${TMPDIR:-/tmp}/impact_fuzz_run.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
export TMPDIR="$scratch"  # the targets' own scratch mirrors go here too
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
mkdir -p "$build/findings"

status=0
summary=()
for t in "${targets[@]}"; do
  bin="$build/bin/fuzz_$t"
  [ -x "$bin" ] || { echo "run_fuzz.sh: $bin is missing (cmake --build --preset fuzz)" >&2; exit 2; }
  corpus="$scratch/$t/corpus"
  findings="$build/findings/$t"
  log="$build/findings/$t.log"
  mkdir -p "$corpus" "$findings"
  touch "$scratch/$t/start"
  while IFS= read -r f; do
    [ -f "$f" ] && cp "$f" "$corpus/$(basename "$(dirname "$f")")_$(basename "$f")"
  done < <(seeds "$t")
  options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
           -artifact_prefix="$findings/")
  [ -f "$here/dict/$t.dict" ] && options+=(-dict="$here/dict/$t.dict")
  echo "run_fuzz.sh: $t for ${seconds} s, $(ls "$corpus" | wc -l) seeds: $bin ${options[*]} CORPUS"
  rc=0
  (cd "$scratch" && "$bin" "${options[@]}" "$corpus") >"$log" 2>&1 || rc=$?
  # The last status line: "#N DONE cov: C ft: F corp: U/Sb ..." (or the line before a finding).
  last="$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)"
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)"
  cov="$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")"
  ft="$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")"
  corp="$(sed -n 's/.* corp: \([0-9]*\/[0-9]*[a-zA-Z]*\).*/\1/p' <<<"$last")"
  artifacts="$(find "$findings" -type f -newer "$scratch/$t/start" | wc -l)"
  if ((rc != 0 || artifacts != 0)); then
    status=1
    result="FINDING (exit $rc; $(find "$findings" -type f -newer "$scratch/$t/start" -printf '%f ')see $log)"
    tail -n 40 "$log" >&2
  else
    result="ok"
  fi
  summary+=("$(printf '%-11s execs %-9s cov %-6s ft %-6s corpus %-12s %s' "$t" "${execs:-?}" \
    "${cov:-?}" "${ft:-?}" "${corp:-?}" "$result")")
done
printf 'run_fuzz.sh: %s\n' "${summary[@]}"
exit "$status"
