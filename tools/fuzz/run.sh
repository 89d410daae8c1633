#!/bin/sh
# tools/fuzz/run.sh FROM TO [VROC] — runs tools/fuzz/edits.py's scripts for
# seeds FROM..TO in every mode (save: saved at a step and read by a fresh
# vroc, SPEC 11) and reports seeds whose dumps differ, and
# crashes, sanitizer reports or hangs (VROC: e.g. build/asan/vroc; default
# build/rel/vroc).  The udp mode needs a private network namespace: run as
# root, it makes one (unshare -n), as tests/scenes_parallel.sh does.
# Optional developer tool (python3); not part of `make check`.
set -u
if [ -z "${VROC_NETNS:-}" ]; then
    exec unshare -n sh -c 'ip link set lo up && ip link set lo multicast on &&
        ip route add 224.0.0.0/4 dev lo && VROC_NETNS=1 exec sh "$0" "$@"' "$0" "$@" ||
        { echo "cannot make a private network namespace (unshare -n needs root)"; exit 1; }
fi
here=$(cd "$(dirname "$0")" && pwd)
vroc=$(cd "$(dirname "${3:-build/rel/vroc}")" && pwd)/$(basename "${3:-build/rel/vroc}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export LSAN_OPTIONS="suppressions=$here/../../tests/lsan.supp:print_suppressions=0"
bad=0
for s in $(seq "$1" "$2"); do
    for mode in serial noheap udp kill switch save; do
        python3 "$here/edits.py" "$s" "$mode" >"$tmp/$mode.cmd"
        kill=""
        [ "$mode" = kill ] && kill="1:$((s % 7 + 2)):$((s % 3))"   # worker 1, a frame 2..8, a round 0..2
        if [ "$mode" = save ]; then   # to #SAVE and `save`; a fresh vroc reads it and the rest
            sed "/^#SAVE\$/,\$d" "$tmp/save.cmd" >"$tmp/head.cmd"
            echo "save $tmp/saved.vroc" >>"$tmp/head.cmd"
            sed "1,/^#SAVE\$/d" "$tmp/save.cmd" >"$tmp/tail.cmd"
            rm -f "$tmp/saved.vroc"
            timeout 300 "$vroc" -q "$tmp/head.cmd" >"$tmp/save.out" 2>"$tmp/save.err"
            rc=$?   # 1: the script's own errors (an edit that overlaps), as in serial
            if [ "$rc" -le 1 ] && [ -s "$tmp/saved.vroc" ]; then
                cat "$tmp/saved.vroc" "$tmp/tail.cmd" | timeout 300 "$vroc" -q >"$tmp/save.out" 2>>"$tmp/save.err"
                rc=$?
            elif [ "$rc" -le 1 ]; then
                echo "seed $s save: no file saved"; bad=$((bad + 1))
            fi
        else
            VROC_FAULT_KILL=$kill timeout 300 "$vroc" -q "$tmp/$mode.cmd" >"$tmp/$mode.out" 2>"$tmp/$mode.err"
            rc=$?
        fi
        if [ "$rc" -gt 1 ] || grep -q 'Sanitizer\|runtime error' "$tmp/$mode.err"; then
            echo "seed $s $mode: exit $rc $(grep -m1 'ERROR\|runtime error' "$tmp/$mode.err")"; bad=$((bad + 1))
        fi
        if [ "$mode" != serial ] && ! cmp -s "$tmp/serial.out" "$tmp/$mode.out"; then
            echo "seed $s: $mode differs from serial"; bad=$((bad + 1))
        fi
    done
done
echo "seeds $1..$2: $bad problems"
[ "$bad" = 0 ]
