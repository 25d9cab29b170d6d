#!/bin/sh
# Installs the build tree into <build>/packaging/prefix, then configures, builds and runs the
# consumer project against it (find_package(molchaos), molchaos::theory, molchaos::sim).
# Usage: install_and_consume.sh <build dir> <consumer source dir>
set -eu
build=$1
consumer=$2
work=$build/packaging
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work.install.log" 2>&1 ||
  { cat "$work.install.log"; exit 1; }
test -f "$work/prefix/lib/cmake/molchaos/molchaosConfig.cmake"
test -f "$work/prefix/include/molchaos/theory/cooling.hpp"
test -x "$work/prefix/bin/molchaos"
"$work/prefix/bin/molchaos" --version
cmake -S "$consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release
cmake --build "$work/consumer" -j 2
"$work/consumer/consumer"
