#!/usr/bin/env bash
# Thread scaling and the cost of the default AOVs, from render --stats' own "rendering" time (the
# render alone: no start-up, no scene loading, no writing). Runs are interleaved, figures are
# medians, the machine is named:
#   bench/thread_scaling.sh [RUNS] [SCENE] [RESOLUTION]
# Environment: LIGHTPATH (default build/lightpath), more binaries to compare in LIGHTPATH_VS;
# RENDER_FIGURE=cpu times the render by its workers' CPU time instead (a loaded machine).
# `lightpath bench skip` prints the same comparison for every integrator in one process.
set -eu
runs=${1:-7}
scene=${2:-scenes/lecture-room.toml}
resolution=${3:-960x540}
binaries=("${LIGHTPATH:-build/lightpath}" ${LIGHTPATH_VS:-})
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

renderSeconds() {  # BINARY INTEGRATOR THREADS AOV_OPTIONS...
  local binary=$1 integrator=$2 threads=$3
  shift 3
  # RENDER_FIGURE (environment): "time" for the wall time, "cpu" for the idle-machine estimate
  # (serial CPU time + the busiest worker's, which load from other processes does not stretch).
  if [ "${RENDER_FIGURE:-time}" = cpu ]; then
    "$binary" render "$scene" -o "$out/x.exr" --resolution "$resolution" --integrator "$integrator" \
      --threads "$threads" --quiet --stats "$@" | sed -n 's/^cpu time .*: \([0-9.]*\) s on an idle machine$/\1/p'
  else
    "$binary" render "$scene" -o "$out/x.exr" --resolution "$resolution" --integrator "$integrator" \
      --threads "$threads" --quiet --stats "$@" | sed -n 's/^time *\([0-9.]*\) s on.*/\1/p'
  fi
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "machine: $(uname -n), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
     "load average $(cut -d' ' -f1-3 /proc/loadavg) at the start"
echo "scene $scene at $resolution, $runs interleaved runs, median rendering seconds"
configs=("raycast 1" "raycast 2" "whitted 1" "whitted 2" "path 1" "path 2" "whitted 2 --aovs none")
for ((r = 0; r < runs; ++r)); do
  for b in "${!binaries[@]}"; do
    for c in "${!configs[@]}"; do
      read -r -a args <<<"${configs[$c]}"
      renderSeconds "${binaries[$b]}" "${args[@]}" >>"$out/$b.$c"
    done
  done
done
for b in "${!binaries[@]}"; do
  m=()
  for c in "${!configs[@]}"; do m+=("$(median <"$out/$b.$c")"); done
  echo "${binaries[$b]}:"
  awk -v r1="${m[0]}" -v r2="${m[1]}" -v w1="${m[2]}" -v w2="${m[3]}" -v p1="${m[4]}" -v p2="${m[5]}" -v wn="${m[6]}" 'BEGIN {
    printf "  raycast  1 thread %.3f s, 2 threads %.3f s: %.2fx\n", r1, r2, r1 / r2
    printf "  whitted  1 thread %.3f s, 2 threads %.3f s: %.2fx\n", w1, w2, w1 / w2
    printf "  path     1 thread %.3f s, 2 threads %.3f s: %.2fx\n", p1, p2, p1 / p2
    printf "  whitted, 2 threads: classes AOVs %.3f s, --aovs none %.3f s: AOVs cost %+.1f%%\n", w2, wn, (w2 / wn - 1) * 100
  }'
done
