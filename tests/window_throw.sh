#!/bin/sh
# tests/window_throw.sh — click, drag, release throws the ball (SPEC 8's
# select mode driven by the window's mouse, SPEC 9).
# Run alone: VROC_BUILD=build/rel sh tests/window_throw.sh
#
# The ball (radius 0.5, centre c0 = (0,0,1), no gravity, alone) is seen from
# the default eye (0,-8,3) looking at (0,0,1), 640x512, fov 45.  With time
# running in real time (space) and the mouse as the hand (g), a press at
# its centre (320,256) grabs it at the picked point p0 on its front, and
# 10 moves of 8 pixels every 20 ms to the right drag it along +x on the
# plane through p0 facing the view, at the pace xdotool keeps (the hand's
# samples carry what it was).
# SPEC 8: the ball follows the hand rigidly and leaves with the velocity of
# the hand's interpolated motion at the release instant, "a hand moving at a
# constant velocity throws at exactly that velocity from exactly where it
# let go".  The window's hand runs on 50 ms at the drag's velocity past the
# release (man vroc: the live window), so that velocity is the `# throw`
# line of $VROC_HAND_LOG, (vx,vy,vz) with the orientation constant (no
# spin, no v x r term).  So, at the dump's time T after the release at t_up
# where the hand point was x_up:
#     ball velocity  = (vx, vy, vz)                  (to 1e-9)
#     ball centre    = c0 + (p_up - p0) + (vx,vy,vz) (T - t_up)
# and the throw is the hand's own samples' velocity over the last 50 ms
# before the release (man vroc: from the release back to the newest sample
# at least 50 ms older, or the first): (p_last - p_k) / (t_up - t_k), the
# release at the last move's pixel, to 1e-9 of its size, with vx > 0 (the
# drag's sign).  The samples carry the pace xdotool kept: a drag that
# stalls on a loaded machine throws at its last 50 ms's speed, whatever
# the mean (once it came out at 1.69 m/s against a mean of 4.85).
# Ends with `N passed, M failed`.
set -u
top=$(pwd)
. "$top/tests/x11/session.sh"
start_x

open_session
say "sphere ball" "radius = 0.5" "ures = 24" "vres = 24" "translate = (0,0,1)" window dump
if wait_for "$tmp/out" '^ball,' && id=$(window_id); then
    sleep 0.3
    xdotool key --window "$id" g
    sleep 0.1
    xdotool key --window "$id" space
    sleep 0.3
    drag_right "$id"
    sleep 0.5
    xdotool key --window "$id" space
    sleep 0.2
    say dump
    wait_count "$tmp/out" '^ball,' 2
    if awk -v out="$tmp/throw.awk" '
        FNR == NR { if ($0 ~ /^ball,/) ball = $0; next }
        /^[0-9.e+-]+ hand / { if ($NF != 0 && !up) { n++; ts[n] = $1; xs[n] = $3; ys[n] = $4; zs[n] = $5 }
                              else if ($NF == 0 && !up) { up = 1; tu = $1; xu = $3; yu = $4; zu = $5 } }
        /^# throw / { vx = $3; vy = $4; vz = $5 }
        END {
            split(ball, b, ",")          # name,t,x,y,z,qw,qx,qy,qz,vx,vy,vz,...
            T = b[2]
            x0 = xs[1]; y0 = ys[1]; z0 = zs[1]
            if (!up || n < 2) bad = bad " no drag and release in the hand log"
            # the samples velocity over the last 50 ms: from the release (at
            # the last move point) back to the newest sample 50 ms older
            for (k = n; k > 1 && tu - ts[k] < 0.05; k--) ;
            dt = tu - ts[k]
            wx = dt > 0 ? (xs[n] - xs[k]) / dt : 0; wy = dt > 0 ? (ys[n] - ys[k]) / dt : 0
            wz = dt > 0 ? (zs[n] - zs[k]) / dt : 0
            size = sqrt(wx * wx + wy * wy + wz * wz)
            if (!(vx > 0) || (vx - wx) ^ 2 + (vy - wy) ^ 2 + (vz - wz) ^ 2 > (1e-9 * size) ^ 2)
                bad = bad " throw (" vx "," vy "," vz "), the samples over the last 50 ms (" wx "," wy "," wz ")"
            if ((b[10] - vx) ^ 2 + (b[11] - vy) ^ 2 + (b[12] - vz) ^ 2 > 1e-18)
                bad = bad " ball velocity (" b[10] "," b[11] "," b[12] "), the throw (" vx "," vy "," vz ")"
            cx = xu - x0 + vx * (T - tu); cy = yu - y0 + vy * (T - tu); cz = 1 + zu - z0 + vz * (T - tu)
            if ((b[3] - cx) ^ 2 + (b[4] - cy) ^ 2 + (b[5] - cz) ^ 2 > 1e-12)
                bad = bad " ball at (" b[3] "," b[4] "," b[5] ") at " T ", want (" cx "," cy "," cz ")"
            print bad > out
            exit bad != ""
        }' "$tmp/out" "$tmp/hand.log"; then pass
    else fail "throw:$(cat "$tmp/throw.awk")"; sed 's/^/    /' "$tmp/hand.log" | tail -n 6; fi
else fail "throw: no window: $(cat "$tmp/err")"; fi
close_session
grep -q . "$tmp/err" && { fail "the session wrote errors:"; sed 's/^/    /' "$tmp/err" | head -n 5; }
finish
