#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Install.* (CMakeLists.txt): `cmake --install` into a temporary prefix, then the installed hmcr
# must find its bundled scenes and plotting script in PREFIX/share/hmcr, never in the source
# tree it was built from:
#   1. the source tree hidden (an empty folder mounted over it, in a mount namespace of this
#      test's own, where unshare may do that), the installed hmcr lists and solves `cornell`;
#   2. `cornell` removed from the prefix, the installed hmcr refuses it (exit 2) although the
#      source tree, visible here, holds it;
#   3. $HMCR_DATA_DIR names another data folder, and the installed hmcr takes its scenes there.
# Case 1 also builds an outside CMake project (tests/install/consumer) against the prefix alone,
# find_package(hmcr) and hmcr::hmcr, whose solve of cornell must give the installed program's
# bytes; and where the build made the Python module, imports the installed one and solves
# cornell with it, to the same bytes.
# Usage: install_test.sh SOURCE_DIR BUILD_DIR [library|no-library] (no-library: a sanitizer
# build's, whose libraries an outside project cannot link without the sanitizer's runtime).
set -eu
src=$(cd "$1" && pwd)
build=$2
library=${3:-library}
library_said=""
[ "$library" = library ] && library_said=", an outside project of the library"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" > "$tmp/install.log"
hmcr=$prefix/bin/hmcr
test -x "$hmcr"
test -f "$prefix/share/hmcr/scenes/cornell/cornell.json"
test -f "$prefix/share/hmcr/scenes/office/generate.py"
test -f "$prefix/share/hmcr/scripts/plot_study.py"
unset HMCR_SCENES HMCR_DATA_DIR
# The Python module, where the build made it.
python=$prefix/lib/python3/dist-packages
python_said=""
if [ -d "$python/hmcr" ]; then
    test -f "$python/hmcr/__init__.py"
    test ! -e "$python/hmcr/_build_tree.py"
    python_said=" and the Python module"
fi

# 1. The source tree gone: what the installed program, an outside project of the installed
# library and the installed Python module do with the prefix alone (installed_uses.sh). The
# outside project's own files are copied out first.
mkdir "$tmp/empty" "$tmp/run"
cp -r "$src/tests/install/consumer" "$tmp/consumer"
uses="$src/tests/install/installed_uses.sh"
cp "$uses" "$tmp/installed_uses.sh"
if unshare -m --propagation private true 2>/dev/null; then
    unshare -m --propagation private sh -c '
        set -eu
        mount --bind "$1" "$2"
        test -z "$(ls -A "$2")"
        shift 2
        sh "$@"' sh "$tmp/empty" "$src" "$tmp/installed_uses.sh" "$prefix" "$tmp/run" "$tmp/consumer" \
        "$library"
    echo "with the source tree hidden: the program${library_said}${python_said} solved cornell to the same bytes"
else
    sh "$tmp/installed_uses.sh" "$prefix" "$tmp/run" "$tmp/consumer" "$library"
    echo "unshare unavailable: the source tree was not hidden (cases 2 and 3 still prove it); the program${library_said}${python_said} solved cornell to the same bytes"
fi

# 2. The prefix without cornell: refused, whatever the source tree holds.
mv "$prefix/share/hmcr/scenes/cornell" "$tmp/cornell"
cd "$tmp/run"
status=0
"$hmcr" solve cornell --rays 20000 -q -o refused.vtp 2> "$tmp/err" || status=$?
test "$status" -eq 2
grep -q "cornell: no such file or bundled scene" "$tmp/err"
test ! -e refused.vtp

# 3. Another data folder by name.
mkdir -p "$tmp/data/scenes"
mv "$tmp/cornell" "$tmp/data/scenes/cornell"
HMCR_DATA_DIR=$tmp/data "$hmcr" scenes > "$tmp/scenes"
test "$(cat "$tmp/scenes")" = cornell
echo "installed hmcr: scenes from the prefix and from \$HMCR_DATA_DIR only"
