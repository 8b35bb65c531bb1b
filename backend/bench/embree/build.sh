#!/bin/sh
# Builds embree_rays beside this script against Debian's Embree 3 (apt-get install libembree-dev).
set -eu
cd "$(dirname "$0")"
g++ -std=c++17 -O3 -march=native -Wall -Wextra -o embree_rays embree_rays.cpp -lembree3 -pthread
echo "built $(pwd)/embree_rays"
