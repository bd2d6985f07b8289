#!/usr/bin/env bash
# Which shared libraries a command loads, as the dynamic loader reports them (LD_DEBUG=files):
#   loaded_libraries.sh --without|--with LIBRARY -- COMMAND...
# --without fails when LIBRARY (a file name prefix, e.g. libOpenImageIO) was loaded, --with when
# it was not. The command's own exit code and output are not judged here (other tests do that).
set -u
mode=$1 library=$2
[ "$3" = "--" ] || { echo "usage: loaded_libraries.sh --without|--with LIBRARY -- COMMAND..." >&2; exit 2; }
shift 3
log=$(mktemp -d)
trap 'rm -rf "$log"' EXIT
LD_DEBUG=files LD_DEBUG_OUTPUT="$log/ld" "$@" >/dev/null 2>&1
if ! compgen -G "$log/ld.*" >/dev/null; then echo "FAIL: the loader reported nothing (LD_DEBUG unsupported?)"; exit 1; fi
loaded=$(grep -ho "file=[^ ]*" "$log"/ld.* | sort -u)
echo "$(wc -l <<<"$loaded") libraries loaded"
if grep -q "file=$library" <<<"$loaded"; then
  [ "$mode" = "--with" ] && { echo "$library loaded, as expected"; exit 0; }
  echo "FAIL: $library was loaded:"; grep "file=$library" <<<"$loaded"; exit 1
fi
[ "$mode" = "--without" ] && { echo "$library not loaded, as expected"; exit 0; }
echo "FAIL: $library was not loaded"; exit 1
