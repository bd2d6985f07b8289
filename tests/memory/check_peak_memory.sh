#!/usr/bin/env bash
# Runs a render with --stats and checks the peak memory it reports against a bound linear in the
# scene's triangles:
#   check_peak_memory.sh TRIANGLES BYTES_PER_TRIANGLE BASE_MIB -- COMMAND...
# Fails if the command fails, if its output has no "peak memory X MiB" line, or if
# X > BASE_MIB + TRIANGLES * BYTES_PER_TRIANGLE / 2^20.
set -u
if [ $# -lt 5 ] || [ "$4" != "--" ]; then
  echo "usage: check_peak_memory.sh TRIANGLES BYTES_PER_TRIANGLE BASE_MIB -- COMMAND..." >&2
  exit 2
fi
triangles=$1 bytes_per_triangle=$2 base_mib=$3
shift 4
output=$("$@" 2>&1)
code=$?
printf '%s\n' "$output"
if [ "$code" != 0 ]; then echo "FAIL: exit code $code"; exit 1; fi
peak=$(sed -nE 's/^peak memory +([0-9]+(\.[0-9]+)?) MiB.*/\1/p' <<<"$output")
if [ -z "$peak" ]; then echo "FAIL: no \"peak memory X MiB\" line in the output"; exit 1; fi
awk -v peak="$peak" -v n="$triangles" -v b="$bytes_per_triangle" -v base="$base_mib" 'BEGIN {
  bound = base + n * b / 1048576
  printf "peak memory %.1f MiB for %d triangles; bound %.1f MiB = %s MiB + %s bytes per triangle\n",
         peak, n, bound, base, b
  if (peak > bound) { print "FAIL: peak memory above the bound"; exit 1 }
}'
