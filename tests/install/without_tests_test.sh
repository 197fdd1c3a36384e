#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Install.ConfiguresWithoutTheTestDependencies (CMakeLists.txt): `cmake -DBUILD_TESTING=OFF`
# configures hmcr, in a fresh build folder, with GoogleTest and Python made unfindable
# (CMAKE_DISABLE_FIND_PACKAGE_*, which fails the configure at any find_package of them that is
# REQUIRED), and the build it generates has the program and no test target or test. zlib cannot
# be hidden so: CMake's FindPNG and VTK's package file look for it (docs/testing.md).
# `make check-without-tests` also builds, installs and runs the program so configured.
# Usage: without_tests_test.sh SOURCE_DIR CXX_COMPILER
set -eu
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake -S "$src" -B "$tmp/build" -DBUILD_TESTING=OFF -DCMAKE_CXX_COMPILER="$2" \
    -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_Python3=ON \
    > "$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/build" --target help > "$tmp/targets"
grep -qx '\.\.\. hmcr' "$tmp/targets"
if grep -E '_(tests|fuzz)$' "$tmp/targets"; then
    echo "BUILD_TESTING=OFF still generates these test targets"
    exit 1
fi
ctest --test-dir "$tmp/build" -N > "$tmp/tests"
grep -qx 'Total Tests: 0' "$tmp/tests"
echo "configured without GoogleTest and Python: hmcr and no tests"
