#!/bin/sh
# The benchmark's own dependency: GSL's development files (libgsl-dev), for
# the peer comparison in `make bench`. Installs them with apt-get when
# running as root or with password-less sudo; otherwise says how, and the
# benchmark runs without the comparison. Never needed to build or test
# stepwise itself.
pkg=libgsl-dev
have() { command -v "$1" >/dev/null 2>&1; }
if have pkg-config && pkg-config --exists gsl; then
    exit 0
fi
if [ "$(id -u)" = 0 ]; then
    sudo=""
elif have sudo && sudo -n true 2>/dev/null; then
    sudo="sudo"
else
    echo "stepwise bench: GSL not found; for the peer comparison run: sudo apt-get install -y $pkg" >&2
    exit 0
fi
echo "stepwise bench: installing $pkg (for the peer comparison only)" >&2
$sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $pkg >/dev/null || {
    echo "stepwise bench: apt-get install $pkg failed; the benchmark runs without the peer comparison" >&2
}
exit 0
