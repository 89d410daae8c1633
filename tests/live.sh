#!/bin/sh
# tests/live.sh — live trackers (SPEC 8), in a private network namespace
# (UDP multicast on loopback only; it fails loudly when it cannot make one,
# it never skips).  One track file drives three runs that must print the
# same head and hand poses frame after frame: `track FILE`; `trackers =
# URL` fed by tools' vroc-tracker in real time; and the same, fed by
# lcm-logplayer replaying what lcm-logger recorded of a vroc-tracker
# session.  The track ends before the run does: the run goes on (the
# trackers stop sending), the devices holding their last poses.  A ball
# dropped on a table meanwhile: its bounces go out on VROC_SOUND.
# Ends with `N passed, M failed`.
set -u
if [ -z "${VROC_NETNS:-}" ]; then
    unshare -n sh -c 'ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo &&
        VROC_NETNS=1 exec sh "$0" ||
        { echo "FAIL live: cannot make a private network namespace (unshare -n needs root)"; echo "0 passed, 1 failed"; exit 1; }' "$0"
    exit $?
fi
top=$(pwd)
case ${VROC_BUILD:?set VROC_BUILD to the build folder} in
/*) build=$VROC_BUILD ;;
*) build=$top/$VROC_BUILD ;;
esac
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
url='udpm://239.255.76.68:7668?ttl=0'
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$top/tests/lsan.supp:print_suppressions=0}"

# 0.99 s of samples every 30 ms: the head sweeping along x and turning,
# the hand rising with its trigger down from 0.3 s to 0.6 s
awk 'BEGIN {
    for (k = 0; k <= 33; k++) {
        t = k * 0.03; a = 0.02 * k; b = (t >= 0.3 && t < 0.6) ? 1 : 0
        printf "%.2f head %.2f -8 1.7 %.17g 0 0 %.17g\n", t, 0.05 * k, cos(a), sin(a)
        printf "%.2f hand 0.3 -7.5 %.2f 1 0 0 0 %d\n", t, 1 + 0.01 * k, b
    } }' >"$tmp/live.trk"
script() { # script SOURCE-STATEMENT: 30 frames of 50 ms, the poses after each
    echo 'time_step = 0.05'
    echo "$1"
    printf 'collision_dist = 0.01\ngravity\ncube table\nsize = (1, 1, 0.05)\nmass = -1\n'
    printf 'sphere ball\nradius = 0.1\ntranslate = (0, 0, 1)\n'

    i=0
    while [ $i -lt 30 ]; do echo step; echo 'show head'; echo 'show hand'; i=$((i + 1)); done
}
script "track $tmp/live.trk" >"$tmp/a.cmd"
script "trackers = $url" >"$tmp/b.cmd"

"$build/vroc" "$tmp/a.cmd" >"$tmp/a.out" 2>"$tmp/a.err"
if [ $? = 0 ] && [ ! -s "$tmp/a.err" ] && [ "$(grep -c '^head ' "$tmp/a.out")" = 30 ]; then pass
else fail "live: the track file run failed"; sed 's/^/    /' "$tmp/a.err" | head -n 5; fi

live_run() { # live_run NAME FEEDER...: vroc listening while FEEDER sends
    name=$1; shift
    "$build/vroc" "$tmp/b.cmd" >"$tmp/$name.out" 2>"$tmp/$name.err" &
    pid=$!
    sleep 1
    "$@" >"$tmp/$name.feed" 2>&1 || fail "live: $name: the feeder failed: $(head -n 1 "$tmp/$name.feed")"
    wait $pid
    st=$?
    if [ $st = 0 ] && cmp -s "$tmp/a.out" "$tmp/$name.out"; then pass
    else
        fail "live: $name: status $st; its poses differ from the track file's run"
        diff "$tmp/a.out" "$tmp/$name.out" | head -n 6 | sed 's/^/    /'
        sed 's/^/    /' "$tmp/$name.err" | head -n 3
    fi
}
# lcm-logger records the session: the tracker's samples and vroc's sounds
lcm-logger -f --lcm-url="$url" "$tmp/session.lcmlog" >"$tmp/logger.out" 2>&1 &
logger=$!
live_run tracker "$build/vroc-tracker" "$tmp/live.trk" "$url"
sleep 0.5
kill $logger
wait $logger 2>/dev/null
if grep -q VROC_HAND "$tmp/session.lcmlog" && grep -q VROC_SOUND "$tmp/session.lcmlog"; then pass
else fail "live: lcm-logger recorded no VROC_HAND or no VROC_SOUND message: $(head -n 2 "$tmp/logger.out")"; fi
live_run logplayer lcm-logplayer --lcm-url="$url" "$tmp/session.lcmlog"

# a track file that does not parse: vroc-tracker says where, sends nothing
printf '0 head 0 0 0 1 0 0 0\n0.1 hand 0 0 0 2 0 0 0\n' >"$tmp/bad.trk"
"$build/vroc-tracker" "$tmp/bad.trk" "$url" 2>"$tmp/bad.err"
if [ $? = 1 ] && grep -q "bad.trk:2: the quaternion must be a unit one" "$tmp/bad.err"; then pass
else fail "live: vroc-tracker on a bad line: $(cat "$tmp/bad.err")"; fi
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
