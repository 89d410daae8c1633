#!/bin/sh
# tests/sound_parallel.sh — collision sounds with workers (SPEC 8, issue
# 27): six balls bouncing on a floor and off each other give the same
# sound log, byte for byte (times, volumes, points, speeds), serially and
# with 1 and 2 workers in this process (memq://) and forked over UDP
# multicast; and with workers on udpm every event of the log goes out on
# VROC_SOUND (counted by lcm-logger, which records the channel).  The
# serial log must hold sounds of both kinds (ball on floor, ball on ball)
# so that the comparison cannot pass on two empty logs.  Runs itself in a
# private network namespace; fails (never skips) when it cannot make one.
# Run by tests/run.sh from the repo root with VROC_BUILD set.
set -u
if [ -z "${VROC_NETNS:-}" ]; then
    exec unshare -n sh -c 'ip link set lo up && ip link set lo multicast on &&
        ip route add 224.0.0.0/4 dev lo && VROC_NETNS=1 exec sh "$0"' "$0" ||
        { echo "FAIL cannot make a private network namespace (unshare -n needs root)"; echo "0 passed, 1 failed"; exit 1; }
fi
vroc=${VROC_BUILD:-build/rel}/vroc
url='udpm://239.255.76.69:7669?ttl=0'
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$(pwd)/tests/lsan.supp:print_suppressions=0}"
export HOME="$tmp"

# Four balls dropped from different heights; two more thrown at each
# other 1 m above the floor (they meet at t = 0.25 s, then fall).
scene() {
    printf 'time_step = 0.01\ncollision_dist = 0.01\ngravity\n'
    printf 'cube floor\nsize = (2, 2, 0.05)\nmass = -1\nelasticity = 0.9\n'
    i=0
    for spec in '-1.2 -1.2 0.6 0.1 0.8' '-0.4 -1.2 0.9 0.08 0.85' '0.4 -1.2 1.3 0.12 0.7' '1.2 -1.2 0.45 0.1 0.9'; do
        set -- $spec
        printf 'sphere drop%d\nradius = %s\ntranslate = (%s, %s, %s)\nelasticity = %s\n' $i "$4" "$1" "$2" "$3" "$5"
        i=$((i + 1))
    done
    printf 'sphere left\nradius = 0.1\ntranslate = (-0.5, 0.8, 1)\nlinear_vel = (1.6, 0, 0)\nelasticity = 0.9\n'
    printf 'sphere right\nradius = 0.1\ntranslate = (0.5, 0.8, 1)\nlinear_vel = (-1.6, 0, 0)\nelasticity = 0.9\n'
}

run() { # run NAME GPS [URL]: 250 frames with a sound log
    { printf 'gps = %s\n' "$2"
      [ -z "${3:-}" ] || printf 'lcm_url = %s\n' "$3"
      printf 'sound_log = %s\n' "$tmp/$1.log"
      scene
      printf 'step 250\n'; } | "$vroc" -q >"$tmp/$1.out" 2>"$tmp/$1.err"
}

run serial 0
lines=$(grep -vc '^#' "$tmp/serial.log")
# a ball-on-ball sound is 1 m above the floor's top: z near 1.0
mid=$(awk -F, '!/^#/ && $6 > 0.5 { n++ } END { print n + 0 }' "$tmp/serial.log")
if [ -s "$tmp/serial.err" ] || [ "$lines" -lt 12 ] || [ "$mid" -lt 1 ]; then
    fail "sound_parallel: the serial run made $lines sounds ($mid of the balls meeting): $(head -n 1 "$tmp/serial.err")"
else pass; fi

for case in "memq1 1 memq://" "memq2 2 memq://" "udpm1 1 $url" "udpm2 2 $url"; do
    set -- $case
    run "$1" "$2" "$3"
    if [ -s "$tmp/$1.err" ]; then fail "sound_parallel: $1: $(head -n 1 "$tmp/$1.err")"
    elif cmp -s "$tmp/serial.log" "$tmp/$1.log"; then pass
    else
        fail "sound_parallel: $1 ($2 workers on $3): its sound log differs from the serial run's"
        diff "$tmp/serial.log" "$tmp/$1.log" | head -n 6 | sed 's/^/    /'
    fi
done

# VROC_SOUND with workers on udpm: lcm-logger hears every event
lcm-logger -f --lcm-url="$url" -c VROC_SOUND "$tmp/sound.lcmlog" >"$tmp/logger.out" 2>&1 &
logger=$!
sleep 0.5
run udpm2b 2 "$url"
sleep 0.5
kill $logger
wait $logger 2>/dev/null
heard=$(grep -ao VROC_SOUND "$tmp/sound.lcmlog" 2>/dev/null | wc -l)
if [ "$heard" = "$lines" ]; then pass
else fail "sound_parallel: lcm-logger heard $heard VROC_SOUND messages, the log has $lines events: $(head -n 1 "$tmp/logger.out")"; fi

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
