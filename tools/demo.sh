#!/bin/sh
# make demo: runs scenes/demo.cmd through ./vroc, writing its stereo frames
# into demo/frames (40 pairs of 480x384, 44 MB), then makes demo/demo.png (a
# contact sheet of the left eye) and demo/demo-anaglyph.png (the last frame
# in red-cyan) with tools/contact-sheet, and says where they are.  Then the
# basketball scene's sound track (SPEC 8): scenes/basketball.cmd run with a
# sound log, rendered by tools/vroc-sound into demo/basketball.wav.
# Usage: tools/demo.sh   (from anywhere; needs ./vroc and ./vroc-render.so: make)
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
out=$top/demo
die() { echo "demo: $*" >&2; exit 1; }

[ -x "$top/vroc" ] || die "no $top/vroc: run make first"
rm -rf "$out/frames"
mkdir -p "$out/frames"
# absolute paths: `frames` first so that the display is open from frame 0
printf 'frames = %s\nread %s\n' "$out/frames" "$top/scenes/demo.cmd" | "$top/vroc" ||
    die "vroc failed on scenes/demo.cmd"
pairs=$(ls "$out/frames" | grep -c -- '-right\.ppm$' || true)
[ "$pairs" -gt 0 ] || die "vroc wrote no frames into $out/frames"
"$top/tools/contact-sheet" -n 16 "$out/frames" "$out/demo.png"
"$top/tools/contact-sheet" -a last "$out/frames" "$out/demo-anaglyph.png"
echo "demo: $pairs stereo frames ($(du -sh "$out/frames" | cut -f1)) in $out/frames"
echo "demo: look at $out/demo.png (left eye, every few frames)"
echo "demo:     and $out/demo-anaglyph.png (last frame, red-cyan glasses)"
[ -x "$top/tools/vroc-sound" ] || die "no $top/tools/vroc-sound: run make first"
printf 'sound_log = %s\nread %s\n' "$out/basketball.log" "$top/scenes/basketball.cmd" | "$top/vroc" ||
    die "vroc failed on scenes/basketball.cmd"
"$top/tools/vroc-sound" "$out/basketball.log" "$out/basketball.wav" || die "tools/vroc-sound failed"
echo "demo: listen to $out/basketball.wav ($(($(grep -vc '^#' "$out/basketball.log"))) bounces of scenes/basketball.cmd)"
