#!/usr/bin/env bash
# The fuzz gate gives one verdict on every machine only if the same commit fuzzes the same inputs
# everywhere (tests/fuzz/README.md). This runs one fuzz binary three times as scripts/fuzz --gate
# does (seed list in name order, a fixed count, seed 1, no comparison operands, no address
# randomisation), each time with an environment of another size (which moves the stack, as another
# machine's would), and fails unless the three corpora it makes are the same files (libFuzzer names
# each by the SHA-1 of its contents). Exit 77 (skipped) where the system forbids turning address
# randomisation off, as scripts/fuzz then runs without it.
# Usage: gate_reproducible.sh FUZZ_BINARY CORPUS_DIR DICT RUNS
set -euo pipefail
binary=$1 corpus=$2 dict=$3 runs=$4
if ! setarch "$(uname -m)" -R true 2>/dev/null; then
    echo "gate_reproducible: this system does not let a process turn address randomisation off: skipped"
    exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/lightpath-fuzz-repro.XXXXXX")
trap 'rm -rf "$work"' EXIT
find "$corpus" -maxdepth 1 -type f | LC_ALL=C sort | paste -sd, >"$work/seeds"
for padding in 0 8 24; do
    mkdir "$work/out-$padding"
    env LIGHTPATH_FUZZ_PADDING="$(printf '%*s' "$padding" '')" setarch "$(uname -m)" -R \
        "$binary" "$work/out-$padding" -seed_inputs=@"$work/seeds" -runs="$runs" -seed=1 -max_len=4096 \
        -dict="$dict" -timeout=600 -use_cmp=0 >"$work/log-$padding" 2>&1 || {
        echo "gate_reproducible: $binary failed; its log:" >&2
        tail -20 "$work/log-$padding" >&2
        exit 1
    }
    (cd "$work/out-$padding" && ls | LC_ALL=C sort) >"$work/files-$padding"
    grep -E '^#[0-9]+[[:space:]]+DONE' "$work/log-$padding" | sed "s/^/environment +$padding bytes: /"
done
for padding in 8 24; do
    if ! cmp -s "$work/files-0" "$work/files-$padding"; then
        echo "gate_reproducible: the corpus differs between environments of +0 and +$padding bytes:" >&2
        diff "$work/files-0" "$work/files-$padding" | head -10 >&2
        exit 1
    fi
done
echo "gate_reproducible: $(wc -l <"$work/files-0") inputs, the same in all three runs"
