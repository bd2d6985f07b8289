#!/usr/bin/env bash
# lightpath against POV-Ray 3.7 on the lecture room at 1920x1080, end to end (start-up, scene
# loading, rendering, writing the image), interleaved runs, medians, the machine named:
#   bench/vs_povray.sh [RUNS]
# Anti-aliased: POV-Ray +A0.0 +AM1 +R2 (every pixel supersampled 2x2) against --spp 4; one sample
# a pixel: POV-Ray -A against --spp 1; each on 1 and 2 threads. lightpath writes what a user gets
# by default: the beauty and one PNG per `classes` AOV (7 PNGs); POV-Ray writes one PNG.
# The POV-Ray scene is bench/povray/lecture-room.pov (how the materials map: its header); the
# bunny is converted to a mesh2 once per run of this script. Environment: LIGHTPATH (default
# build/lightpath). Needs Debian's povray (apt-get install povray); says so when it is missing.
# Besides wall time, each process's CPU time (user + system, GNU time): on a loaded machine the
# wall times measure the load, the CPU times the programs.
set -eu
runs=${1:-3}
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
lightpath=${LIGHTPATH:-$root/build/lightpath}
if ! command -v povray >/dev/null; then
  echo "vs_povray.sh: POV-Ray is not installed (Debian: apt-get install povray)" >&2
  exit 2
fi
[ -x "$lightpath" ] || { echo "vs_povray.sh: no lightpath binary at $lightpath (build it first)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/povray/obj_to_mesh2.py" "$root/scenes/meshes/stanford-bunny.obj" "$work/lecture-room-bunny.inc" \
  Bunny 7 25 -0.45 -0.23 1.3

now() { date +%s.%N; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# CPU seconds (user + system) of the whole process, from GNU time: load from other processes
# stretches wall time, not this, so on a shared machine it is the steadier of the two figures.
cpuOf() { awk '{ print $1 + $2 }' "$work/time.txt"; }

runLightpath() {  # SPP THREADS KEY
  local start end
  start=$(now)
  /usr/bin/time -o "$work/time.txt" -f "%U %S" \
    "$lightpath" render "$root/scenes/lecture-room.toml" --resolution 1920x1080 --spp "$1" --threads "$2" \
    -o "$work/lp.png" --quiet --stats >"$work/lp.log"
  end=$(now)
  awk -v a="$start" -v b="$end" "BEGIN { print b - a }" >>"$work/$3.wall"
  cpuOf >>"$work/$3.cpu"
  sed -n 's/^wall time *rendering \([0-9.]*\) s, writing \([0-9.]*\) s.*/\1/p' "$work/lp.log" >>"$work/$3.render"
  sed -n 's/^wall time *rendering \([0-9.]*\) s, writing \([0-9.]*\) s.*/\2/p' "$work/lp.log" >>"$work/$3.write"
}
runPovray() {  # ANTIALIAS_OPTIONS THREADS KEY
  local start end
  start=$(now)
  # shellcheck disable=SC2086  # $1 is a list of options
  /usr/bin/time -o "$work/time.txt" -f "%U %S" \
    povray +I"$here/povray/lecture-room.pov" +L"$work" +O"$work/pov.png" +FN +W1920 +H1080 $1 +WT"$2" -D \
    2>"$work/pov.log"
  end=$(now)
  awk -v a="$start" -v b="$end" "BEGIN { print b - a }" >>"$work/$3.wall"
  cpuOf >>"$work/$3.cpu"
  sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/pov.log" >>"$work/$3.render"
}

configs=("4 1" "4 2" "1 1" "1 2")
for ((r = 0; r < runs; ++r)); do
  for config in "${configs[@]}"; do
    read -r spp threads <<<"$config"
    aa=$([ "$spp" = 4 ] && echo "+A0.0 +AM1 +R2" || echo "-A")
    runLightpath "$spp" "$threads" "lp-$spp-$threads"
    runPovray "$aa" "$threads" "pov-$spp-$threads"
  done
done

echo "machine: $(uname -n), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
     "load average $(cut -d' ' -f1-3 /proc/loadavg) at the end"
echo "lecture room, 1920x1080, $runs interleaved runs, median seconds; $(povray --version 2>&1 | grep -m1 POV-Ray)"
echo
echo "| sampling | threads | lightpath wall (render + write) | POV-Ray wall (trace) | wall ratio | lightpath CPU | POV-Ray CPU | CPU ratio |"
echo "|---|---|---|---|---|---|---|---|"
for config in "${configs[@]}"; do
  read -r spp threads <<<"$config"
  lw=$(median <"$work/lp-$spp-$threads.wall") lr=$(median <"$work/lp-$spp-$threads.render")
  lx=$(median <"$work/lp-$spp-$threads.write") lc=$(median <"$work/lp-$spp-$threads.cpu")
  pw=$(median <"$work/pov-$spp-$threads.wall") pr=$(median <"$work/pov-$spp-$threads.render")
  pc=$(median <"$work/pov-$spp-$threads.cpu")
  label=$([ "$spp" = 4 ] && echo "anti-aliased (--spp 4 / +A0.0 +AM1 +R2)" || echo "1 spp (--spp 1 / -A)")
  awk -v l="$label" -v t="$threads" -v lw="$lw" -v lr="$lr" -v lx="$lx" -v pw="$pw" -v pr="$pr" -v lc="$lc" -v pc="$pc" \
    'BEGIN { printf "| %s | %s | %.2f s (%.2f + %.2f) | %.2f s (%.2f) | %.2f | %.2f s | %.2f s | %.2f |\n", l, t, lw, lr, lx, pw, pr, lw / pw, lc, pc, lc / pc }'
done
