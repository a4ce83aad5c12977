#!/usr/bin/env bash
# Runs every fuzz target of BUILD_DIR (configured with -DQM2_BUILD_FUZZERS=ON) for SECONDS
# each, from its checked-in seed corpus; new inputs go to BUILD_DIR/fuzz/corpus/<target>, so
# the seeds stay as they are, and a longer run goes on from where the last one stopped.
# Fails at the first target that crashes, leaks, breaks a promise, runs an input for 10 s or
# takes 2 GB, printing the end of its log and leaving the input in BUILD_DIR/fuzz/artifacts:
#   test/fuzz/run.sh BUILD_DIR [SECONDS]        (default 60)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$1"
seconds="${2:-60}"
mkdir -p "$build/fuzz/artifacts"
for target in read_poly read_node read_xy read_wkt mesh_domain; do
  corpus="$build/fuzz/corpus/$target"
  log="$build/fuzz/$target.log"
  mkdir -p "$corpus"
  status=0
  "$build/test/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$build/fuzz/artifacts/$target-" -print_final_stats=1 "$corpus" "$here/corpus/$target" \
    > "$log" 2>&1 || status=$?
  if [ "$status" != 0 ]; then
    tail -n 60 "$log" >&2
    echo "fuzz_$target failed (exit $status); its input is in $build/fuzz/artifacts" >&2
    exit 1
  fi
  echo "fuzz_$target: $(grep -o 'number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$') inputs in $seconds s," \
       "corpus $(ls "$corpus" | wc -l) + $(ls "$here/corpus/$target" | wc -l) seeds"
done
