#!/usr/bin/env bash
# Runs a command and checks what a user would see:
#   expect.sh EXIT_CODE OUTPUT_PATTERN [--absent FILE | --kept FILE | --has PATTERN | --lacks PATTERN]... -- COMMAND...
# EXIT_CODE must match exactly, OUTPUT_PATTERN and every --has PATTERN (grep -E) must occur in
# stdout+stderr (one command run, several lines checked), no --lacks PATTERN may (a refusal made before rendering prints no render statistics), every
# --absent FILE must not exist afterwards (no half-written output), and every --kept FILE, made
# beforehand as "an older image", must be left byte for byte as it was.
set -u
expected_code=$1 pattern=$2
shift 2
absent=() kept=() has=() lacks=()
while [ "$1" != "--" ]; do
  [ "$1" = "--absent" ] && absent+=("$2") && shift 2 && continue
  [ "$1" = "--kept" ] && kept+=("$2") && shift 2 && continue
  [ "$1" = "--has" ] && has+=("$2") && shift 2 && continue
  [ "$1" = "--lacks" ] && lacks+=("$2") && shift 2 && continue
  echo "expect.sh: unknown argument $1" >&2; exit 2
done
shift
older="an older image, written $(date +%s.%N)"
for f in "${absent[@]}"; do rm -f "$f"; done
for f in "${kept[@]}"; do mkdir -p "$(dirname "$f")" && printf '%s' "$older" >"$f"; done
output=$("$@" 2>&1)
code=$?
status=0
printf '%s\n' "$output"
if [ "$code" != "$expected_code" ]; then echo "FAIL: exit code $code, expected $expected_code"; status=1; fi
if ! grep -Eq -- "$pattern" <<<"$output"; then echo "FAIL: output lacks /$pattern/"; status=1; fi
for p in "${has[@]}"; do
  if ! grep -Eq -- "$p" <<<"$output"; then echo "FAIL: output lacks /$p/"; status=1; fi
done
for p in "${lacks[@]}"; do
  if grep -Eq -- "$p" <<<"$output"; then echo "FAIL: output has /$p/"; status=1; fi
done
for f in "${absent[@]}"; do
  if [ -e "$f" ]; then echo "FAIL: $f was written"; status=1; fi
done
for f in "${kept[@]}"; do
  if [ "$(cat "$f" 2>/dev/null)" != "$older" ]; then echo "FAIL: the older $f was destroyed"; status=1; fi
done
# Nor any temporary file beside an output.
for f in "${absent[@]}" "${kept[@]}"; do
  if compgen -G "$(dirname "$f")/.$(basename "$f").tmp-*" >/dev/null; then echo "FAIL: temporary file left for $f"; status=1; fi
done
exit $status
