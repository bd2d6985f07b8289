#!/usr/bin/env bash
# Sends Ctrl-C (SIGINT) to a render once it says it is ready for it, never after a fixed delay:
#   interrupt_when_ready.sh READY_FILE -- COMMAND...
# COMMAND must create READY_FILE once its Ctrl-C handler is installed and rendering has begun
# (lightpath render --ready-file). Exits with COMMAND's exit code. The bounds below only ever fail
# the test: a command that never gets ready, or keeps running after SIGINT, is killed (exit 137)
# or given up on (exit 124), and the caller expects neither.
set -u
ready=$1
[ "$2" = "--" ] || { echo "usage: interrupt_when_ready.sh READY_FILE -- COMMAND..." >&2; exit 2; }
shift 2
readonly kReadyWithin=300   # seconds: a sanitized build on a loaded machine starts slowly
readonly kStopWithin=30     # seconds after SIGINT: the renderer checks for it at every pixel
rm -f "$ready"
"$@" &
pid=$!
waited=0
# Poll for the event (the file), at 20 Hz; the bound is far above any real start-up.
until [ -e "$ready" ]; do
  if ! kill -0 "$pid" 2>/dev/null; then
    wait "$pid"; code=$?
    echo "FAIL: the command exited ($code) before it was ready for Ctrl-C"; exit "$((code == 130 ? 1 : code))"
  fi
  if [ "$waited" -ge $((kReadyWithin * 20)) ]; then
    kill -KILL "$pid"; wait "$pid"
    echo "FAIL: not ready within $kReadyWithin s"; exit 124
  fi
  sleep 0.05; waited=$((waited + 1))
done
kill -INT "$pid"
for ((tick = 0; tick < kStopWithin * 20; ++tick)); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -0 "$pid" 2>/dev/null && { kill -KILL "$pid"; echo "FAIL: still running $kStopWithin s after SIGINT"; }
wait "$pid"
code=$?
rm -f "$ready"
exit "$code"
