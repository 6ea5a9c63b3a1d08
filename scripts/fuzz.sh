#!/usr/bin/env bash
# Runs every libFuzzer target of a FIBERBRIDGE_FUZZ=ON build for a bounded time each, seeded with
# the bundled inputs (data/, prm/, tests/*/data, tests/app/scenes). Exits non-zero when any target
# finds a crash, an uncaught exception, a sanitizer report, a leak or a timeout; the input that did
# it is left in BUILD/fuzz/findings/ (turn it into a regression test, see fuzz/CMakeLists.txt).
#   bash scripts/fuzz.sh [BUILD_DIR=build-fuzz] [SECONDS_PER_TARGET=60] [TARGET...]
# (the FIBERBRIDGE_FUZZ build also registers one ctest per target that runs this script on it).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-build-fuzz}" && pwd)"
seconds="${2:-60}"
shift $(($# < 2 ? $# : 2))
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(csv_reader rdelta_reader law_points law_table table1_reader test_record_reader
  scene_reader dic_frame_reader archive_reader)
findings="$build/fuzz/findings"
mkdir -p "$findings"

seed() { # seed TARGET FILE...: copies the files into the target's corpus
  local dir="$build/fuzz/work/$1/corpus"
  shift
  mkdir -p "$dir"
  for f in "$@"; do [[ -f "$f" ]] && cp "$f" "$dir/$(echo "${f#"$root"/}" | tr / _)"; done
}
csvs=("$root"/data/*.csv "$root"/data/*/*.csv "$root"/tests/*/data/*.csv)
scenes=("$root"/prm/*.prm "$root"/tests/app/data/*.prm "$root"/tests/app/scenes/*.prm)
status=0
for target in "${targets[@]}"; do
  rm -rf "$build/fuzz/work/$target"
  case $target in
    scene_reader) seed "$target" "${scenes[@]}" ;;
    test_record_reader) # the shared records, each also with the column map of prm/test_records.prm
      seed "$target" "${csvs[@]}" "$root"/data/dcb_records/*.csv
      map=$(grep -h "set Columns" "$root"/prm/test_records.prm | sed 's/.*Columns *= *//')
      for f in "$root"/data/dcb_records/*.csv; do
        { echo "#columns: $map"; cat "$f"; } >"$build/fuzz/work/$target/corpus/mapped_$(basename "$f")"
      done ;;
    law_points) # the law points of every bundled scene, one value per corpus file
      mkdir -p "$build/fuzz/work/$target/corpus"
      i=0
      while IFS= read -r p; do
        printf '%s' "$p" >"$build/fuzz/work/$target/corpus/points_$((i++))"
      done < <(grep -h "set Points" "${scenes[@]}" | sed 's/.*Points *= *//' | sort -u) ;;
    dic_frame_reader) # the frames of each layout (VIC csv, DICe and nodemap txt) and the csvs
      seed "$target" "$root"/tests/dic/data/* "${csvs[@]}" ;;
    *) seed "$target" "${csvs[@]}" ;;
  esac
  work="$build/fuzz/work/$target"
  exe="$build/fuzz/${target}_fuzz"
  if [[ ! -x "$exe" ]]; then
    echo "fuzz: $target: not built in $build (the scene reader needs the app: FIBERBRIDGE_FUZZ with deal.II)" >&2
    status=1
    continue
  fi
  mkdir -p "$work/new"
  log="$work/fuzz.log"
  # -timeout: one input taking over 10 s is a finding (a reader must not hang); leaks are findings.
  if env ASAN_OPTIONS=detect_leaks=1 \
    LSAN_OPTIONS="suppressions=$root/tests/sanitizer/lsan.supp" \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$findings/${target}-" "$work/new" "$work/corpus" \
    >"$log" 2>&1; then
    echo "fuzz: $target: clean for ${seconds} s ($(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') runs)"
  else
    echo "fuzz: $target: FINDING (log $log, inputs in $findings):" >&2
    grep -m3 -E "ERROR|runtime error|uncaught|SUMMARY" "$log" >&2 || tail -5 "$log" >&2
    status=1
  fi
done
exit $status
