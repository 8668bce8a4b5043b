#!/bin/sh
# The benchmark's own dependencies: GSL's development files (libgsl-dev), for
# the peer comparison in `make bench`, and SUNDIALS's (libsundials-dev), for
# the stiff comparison against CVODE. Installs them with apt-get when
# running as root or with password-less sudo; otherwise says how, and the
# benchmark runs without the comparison. Never needed to build or test
# stepwise itself.
pkg=""
have() { command -v "$1" >/dev/null 2>&1; }
have pkg-config && pkg-config --exists gsl || pkg="libgsl-dev"
[ -f /usr/include/cvode/cvode.h ] || pkg="$pkg libsundials-dev"
if [ -z "$pkg" ]; then
    exit 0
fi
if [ "$(id -u)" = 0 ]; then
    sudo=""
elif have sudo && sudo -n true 2>/dev/null; then
    sudo="sudo"
else
    echo "stepwise bench: $pkg not found; for the peer comparisons run: sudo apt-get install -y $pkg" >&2
    exit 0
fi
echo "stepwise bench: installing $pkg (for the peer comparisons only)" >&2
$sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $pkg >/dev/null || {
    echo "stepwise bench: apt-get install $pkg failed; the benchmark runs without the peer comparisons" >&2
}
exit 0
