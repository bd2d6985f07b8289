#!/usr/bin/env bash
# Runs a command inside a new memory cgroup limited to LIMIT bytes, as a container or a shared CI
# runner would, then removes the group. Exits 77 (ctest's SKIP_RETURN_CODE) where no cgroup can be
# made here (not root, or no writable memory controller), so the test is reported skipped, not passed.
#   in_memory_cgroup.sh LIMIT -- COMMAND [ARG ...]
set -uo pipefail
limit=$1
[[ $2 == -- ]] || { echo "usage: in_memory_cgroup.sh LIMIT -- COMMAND [ARG ...]" >&2; exit 2; }
shift 2

v1=$(sed -n 's/^[0-9]*:memory://p' /proc/self/cgroup)
v2=$(sed -n 's/^0:://p' /proc/self/cgroup)
group=""
if [[ -n $v1 && -w /sys/fs/cgroup/memory$v1 ]]; then
    group=/sys/fs/cgroup/memory$v1/lightpath-test-$$
    mkdir "$group" 2>/dev/null && echo "$limit" >"$group/memory.limit_in_bytes" 2>/dev/null || group=""
elif [[ -n $v2 && -w /sys/fs/cgroup$v2 ]] && grep -qw memory "/sys/fs/cgroup$v2/cgroup.controllers" 2>/dev/null; then
    group=/sys/fs/cgroup$v2/lightpath-test-$$
    mkdir "$group" 2>/dev/null && echo "$limit" >"$group/memory.max" 2>/dev/null || group=""
fi
if [[ -z $group ]]; then
    echo "in_memory_cgroup: cannot make a memory cgroup here; skipped"
    exit 77
fi
# This shell joins the group, so the command starts inside it; afterwards the shell returns to its
# own group and the then empty group is removed.
echo $$ >"$group/cgroup.procs"
"$@"
status=$?
echo $$ >"$(dirname "$group")/cgroup.procs"
rmdir "$group" 2>/dev/null
exit $status
