#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# oneTBB built with ThreadSanitizer, for `make test-tsan` (docs/testing.md#threadsanitizer).
# Debian's libtbb is not instrumented: TSan cannot see the synchronisation inside TBB's task
# hand-off and reports races between a task's writes and its parent's reads that cannot happen.
# This fetches the Debian source of the very version libtbb-dev installed (its headers are the
# ones the build then compiles against), builds it with clang and -fsanitize=thread and installs
# it to DIR/tbb-tsan; hmcr's TSan build finds it there (TBB_DIR) and runs with it (rpath).
# apt reads a sources list of its own under DIR: the system's apt configuration is not touched.
# Usage: scripts/tsan_tbb.sh DIR [JOBS]. Does nothing when DIR/tbb-tsan already holds that
# version.
set -eu
dir=$(mkdir -p "$1" && cd "$1" && pwd)
jobs=${2:-$(nproc)}
prefix="$dir/tbb-tsan"
package=$(dpkg-query -W -f='${source:Package}' libtbb-dev)
version=$(dpkg-query -W -f='${source:Version}' libtbb-dev)
if [ "$(cat "$prefix/debian-version" 2>/dev/null)" = "$version" ]; then exit 0; fi
rm -rf "$prefix" "$dir/tbb-build" "$dir/tbb-source"
. /etc/os-release
apt="$dir/tbb-apt"
mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$dir/tbb-source"
cat >"$apt/sources.list" <<EOF
deb-src http://deb.debian.org/debian $VERSION_CODENAME main
deb-src http://deb.debian.org/debian $VERSION_CODENAME-updates main
deb-src http://deb.debian.org/debian-security $VERSION_CODENAME-security main
EOF
set -- -o Dir::Etc::SourceList="$apt/sources.list" -o Dir::Etc::SourceParts=/dev/null \
  -o Dir::State::Lists="$apt/lists" -o Dir::Cache="$apt/cache"
apt-get "$@" -qq update
(cd "$dir/tbb-source" && apt-get "$@" -qq source "$package=$version") >"$dir/tbb-source.log" 2>&1 ||
  { cat "$dir/tbb-source.log" >&2; exit 1; }
source_dir=$(find "$dir/tbb-source" -maxdepth 1 -mindepth 1 -type d -name "$package-*" | head -n 1)
[ -n "$source_dir" ] || { echo "tsan_tbb.sh: no source of $package $version" >&2; exit 1; }

# TBB's own tests, its examples and its allocator are not what hmcr runs; warnings are not
# errors (clang 14 warns where GCC, Debian's compiler for it, does not).
cmake -S "$source_dir" -B "$dir/tbb-build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DTBB_SANITIZE=thread -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF \
  -DTBBMALLOC_BUILD=OFF -DCMAKE_INSTALL_PREFIX="$prefix" >"$dir/tbb-build.log" 2>&1 &&
  cmake --build "$dir/tbb-build" -j "$jobs" >>"$dir/tbb-build.log" 2>&1 &&
  cmake --install "$dir/tbb-build" >>"$dir/tbb-build.log" 2>&1 ||
  { tail -n 40 "$dir/tbb-build.log" >&2; echo "tsan_tbb.sh: building $package failed" >&2; exit 1; }
echo "$version" >"$prefix/debian-version"
echo "tsan_tbb.sh: $package $version with ThreadSanitizer in $prefix"
