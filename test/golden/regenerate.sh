#!/usr/bin/env bash
# Regenerates the golden lists from the meshes the current build makes:
#   test/golden/regenerate.sh [BUILD_DIR]        (default: build)
# Runs the golden tests (their failures are the point), then writes golden.txt and, where
# ../shared/data gave cases, golden_shared.txt from what each test found. Say why the meshes
# changed in the commit message.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-build}"
rm -rf "$build/test/golden/actual"
ctest --test-dir "$build" -L '^golden' -j2 > /dev/null || true
for label in golden golden_shared; do
  actual="$build/test/golden/actual/$label"
  [ -d "$actual" ] || continue
  tmp="$(mktemp)"
  cat "$actual"/*.txt | LC_ALL=C sort > "$tmp"
  mv "$tmp" "$here/$label.txt"
  echo "$here/$label.txt: $(wc -l < "$here/$label.txt") meshes"
done
