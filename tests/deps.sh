#!/bin/sh
# Make sure the build and test dependencies are present: ncursesw, Check
# and libseccomp (found through pkg-config; libseccomp builds the plugin
# sandbox's filter), tmux and unzip (end-to-end tests; unzip reads the
# Gradescope bundle as Gradescope would). Installs them with
# apt-get when running as root or with password-less sudo; otherwise prints
# the exact command to run and fails.
pkgs="libncurses-dev check libseccomp-dev pkg-config tmux unzip"
have() { command -v "$1" >/dev/null 2>&1; }
if have pkg-config && pkg-config --exists ncursesw check libseccomp && have tmux && have unzip; then
    exit 0
fi
if [ "$(id -u)" = 0 ]; then
    sudo=""
elif have sudo && sudo -n true 2>/dev/null; then
    sudo="sudo"
else
    echo "stepwise: missing build dependencies; install them as root (su -c, or sudo) with:" >&2
    echo "    apt-get install -y $pkgs" >&2
    exit 1
fi
echo "stepwise: installing $pkgs" >&2
$sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $pkgs >/dev/null || {
    echo "stepwise: apt-get install failed; run as root: apt-get install -y $pkgs" >&2
    exit 1
}
