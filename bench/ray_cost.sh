#!/bin/sh
# Instructions per ray (callgrind, 1 thread) of our BVH, on its AVX2 and baseline paths, and of
# Embree, on the same rays: build/ray_cost's castRays() only. The stable figure on a loaded
# machine. Usage: bench/ray_cost.sh [SCENE...] (default: bunny dragon); needs valgrind.
set -eu
build=${BUILD:-build}
scenes=${*:-bunny dragon}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '%-8s %-8s %10s %10s %10s %12s\n' scene rays avx2 baseline embree avx2/embree
for scene in $scenes; do
  for kind in primary shadow random; do
    row="$scene $kind"
    for config in "bvh" "bvh baseline" "embree"; do
      log="$out/$scene-$kind-$(echo "$config" | tr ' ' -)"
      # shellcheck disable=SC2086
      valgrind --tool=callgrind --callgrind-out-file="$log.cg" --toggle-collect='*castRays*' \
        "$build/ray_cost" "$scene" "$kind" $config >"$log.txt" 2>"$log.err"
      rays=$(sed -n 's/.*: \([0-9]*\) rays.*/\1/p' "$log.txt")
      total=$(callgrind_annotate "$log.cg" | sed -n 's/^ *\([0-9,]*\) .*PROGRAM TOTALS.*/\1/p' | tr -d ,)
      row="$row $((total / rays))"
    done
    echo "$row" | awk '{printf "%-8s %-8s %10d %10d %10d %12.2f\n", $1, $2, $3, $4, $5, $3 / $5}'
  done
done
