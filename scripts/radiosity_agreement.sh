#!/usr/bin/env bash
# Radiosity against the path tracer on the diffuse Cornell box (README "Radiosity"): the ED*L AOV
# of both at 64x64, the path tracer at 4096 spp (Sobol), radiosity at patch budgets 4x apart in
# both displays and 16 spp (camera rays only: pixels average their footprint like the reference's). Prints the solve's wall time on 2 threads (from --stats), the process's CPU time
# (both threads), and the mean absolute difference relative to the reference's mean, over 8x8-pixel
# blocks (box averages, so the path tracer's noise averages out) and over single pixels.
# Usage: scripts/radiosity_agreement.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
lightpath=${1:-build}/lightpath
out=${2:-out/radiosity-agreement}
scene=scenes/cornell-original.toml
common=(--resolution 64x64 --lpe 'diffuse=ED*L' --no-beauty --quiet --threads 2)
mkdir -p "$out"

mean() { oiiotool "$@" --printstats 2>&1 | awk '/Stats Avg/ {print ($3 + $4 + $5) / 3}'; }

if [ ! -f "$out/path.exr" ]; then
  "$lightpath" render "$scene" --integrator path --spp 4096 --sampler sobol "${common[@]}" -o "$out/path.exr" >/dev/null
fi
oiiotool "$out/path.exr" --resize:filter=box 8x8 -o "$out/path-blocks.exr"
reference=$(mean "$out/path.exr")

printf '%8s %8s %10s %8s %8s %8s\n' patches display solve_s cpu_s blocks pixels
for patches in 256 1024 4096 16384; do
  for display in smooth flat; do
    image="$out/radiosity-$patches-$display.exr"
    TIMEFORMAT=%U
    { cpu=$( { time "$lightpath" render "$scene" --integrator radiosity --patches "$patches" --radiosity-display "$display" \
        --spp 16 --sampler sobol "${common[@]}" --stats -o "$image" >"$out/stats.txt"; } 2>&1 ); }
    solve=$(sed -n 's/.*solved in \([0-9.]*\) s.*/\1/p' "$out/stats.txt")
    blocks=$(mean "$image" --resize:filter=box 8x8 "$out/path-blocks.exr" --absdiff)
    pixels=$(mean "$image" "$out/path.exr" --absdiff)
    printf '%8s %8s %10s %8s %8.4f %8.4f\n' "$patches" "$display" "$solve" "$cpu" \
      "$(echo "$blocks $reference" | awk '{print $1 / $2}')" "$(echo "$pixels $reference" | awk '{print $1 / $2}')"
  done
done
