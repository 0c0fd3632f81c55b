#!/bin/sh
# Builds the KDL side of the ik benchmark: the kdl_ik program from bench/kdl/kdl_ik.cpp against Debian's liborocos-kdl-dev.
# Usage: build.sh [output-directory]   (default: this directory). Exit 3 when KDL's headers or library are missing.
set -e
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here}
if [ ! -f /usr/include/kdl/chainiksolverpos_lma.hpp ]; then
    echo "Orocos KDL headers not found (/usr/include/kdl); install liborocos-kdl-dev" >&2
    exit 3
fi
mkdir -p "$out"
if [ "$out/kdl_ik" -nt "$here/kdl_ik.cpp" ]; then
    exit 0
fi
g++ -O2 -std=c++17 -I/usr/include/eigen3 "$here/kdl_ik.cpp" -o "$out/kdl_ik" -lorocos-kdl
