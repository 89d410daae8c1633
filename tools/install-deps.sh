#!/bin/sh
# Install the Debian packages VROC needs, only when a check says one is missing,
# so that a machine that has everything pays nothing (make deps runs this).
# Idempotent, non-interactive; needs root (or sudo) only when it installs.
# Usage: install-deps.sh [fuzz] [lint] [bench] — the build's packages, and
# those of `make fuzz` (AFL++), `make lint` (cppcheck, clang-tidy) and
# `make bench` (ODE 0.16.2, the peer engine bench_ode runs beside vroc) when
# named: only those targets need them.
set -eu

missing=""
need() { # need PACKAGE TEST-COMMAND...
    pkg=$1; shift
    if ! "$@" >/dev/null 2>&1; then missing="$missing $pkg"; fi
}
have_file() { test -e "$1"; }

need libccd-dev         have_file /usr/include/ccd/ccd.h
need libsuitesparse-dev have_file /usr/include/suitesparse/klu.h
need libosmesa6-dev     have_file /usr/include/GL/osmesa.h
need liblcm-dev         have_file /usr/include/lcm/lcm.h
need liblcm-bin         command -v lcm-gen
need libglib2.0-dev     pkg-config --exists glib-2.0
need libreadline-dev    have_file /usr/include/readline/readline.h
need pkg-config         command -v pkg-config
need netpbm             command -v pnmtopng
need libpng-dev         have_file /usr/include/png.h
need libglfw3-dev       have_file /usr/include/GLFW/glfw3.h
need xvfb               command -v Xvfb
need xdotool            command -v xdotool
need iproute2           command -v ip
need util-linux         command -v unshare
need groff-base         command -v groff
need man-db             command -v man
need libsndfile1-dev    have_file /usr/include/sndfile.h
need valgrind           command -v valgrind     # make valgrind, run by make check
for group in "$@"; do
    case $group in
    fuzz) need afl++     command -v afl-clang-fast ;;
    lint) need cppcheck  command -v cppcheck
          need clang-tidy command -v clang-tidy ;;
    bench) need libode-dev have_file /usr/include/ode/ode.h ;;
    *) echo "install-deps: unknown group '$group' (fuzz, lint, bench)" >&2; exit 2 ;;
    esac
done

[ -z "$missing" ] && exit 0

echo "install-deps: installing:$missing" >&2
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
