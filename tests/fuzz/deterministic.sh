#!/usr/bin/env bash
# The fuzz gate's promise (scripts/fuzz --runs): a fixed seed and a fixed number of inputs from the
# same corpus give the same run on any machine. Runs FUZZER twice, each on a fresh copy of CORPUS,
# and fails unless both end with the same coverage, features, corpus size and new units added:
# those follow from the inputs alone, never from time.
#   deterministic.sh FUZZER CORPUS RUNS [LIBFUZZER FLAG ...]
set -euo pipefail
fuzzer=$1 corpus=$2 runs=$3
shift 3
work=$(mktemp -d "${TMPDIR:-/tmp}/lightpath-fuzz-twice.XXXXXX")
trap 'rm -rf "$work"' EXIT

summary() {
    # The last status line's counters (cov, ft, corp) and libFuzzer's final statistics.
    grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+' "$1" | tail -n 1
    grep -E '^stat::(number_of_executed_units|new_units_added):' "$1"
}
for run in 1 2; do
    cp -r "$corpus" "$work/corpus-$run"
    "$fuzzer" "$work/corpus-$run" -runs="$runs" -seed=1 -timeout=600 -print_final_stats=1 "$@" \
        >"$work/log-$run" 2>&1 || { echo "run $run failed:"; tail -n 30 "$work/log-$run"; exit 1; }
    summary "$work/log-$run" >"$work/summary-$run"
done
echo "run 1:"; sed 's/^/  /' "$work/summary-1"
if ! diff -u "$work/summary-1" "$work/summary-2"; then
    echo "the two runs differ: the fuzz gate would not give the same verdict twice"
    exit 1
fi
echo "both runs agree"
