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
# Where the build made the Python module, case 1 also imports the installed one and solves
# cornell with it: the same bytes as the installed program's.
# Usage: install_test.sh SOURCE_DIR BUILD_DIR
set -eu
src=$(cd "$1" && pwd)
build=$2
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
    python_said=", and from Python with the same bytes"
fi

# 1. The source tree gone.
mkdir "$tmp/empty" "$tmp/run"
if unshare -m --propagation private true 2>/dev/null; then
    unshare -m --propagation private sh -c '
        set -eu
        mount --bind "$1" "$2"
        test -z "$(ls -A "$2")"
        cd "$3"
        "$4" scenes | grep -qx cornell
        "$4" solve cornell --rays 20000 -q -o cornell.vtp
        test -s cornell.vtp
        if [ -d "$5" ]; then
            PYTHONPATH=$5 /usr/bin/python3 -c "import hmcr; s = hmcr.solve(hmcr.load_scene(\"cornell\"), rays=20000); s.write_vtp(\"py.vtp\")"
            cmp py.vtp cornell.vtp
        fi' sh "$tmp/empty" "$src" "$tmp/run" "$hmcr" "$python"
    echo "solved cornell with the source tree hidden${python_said}"
else
    echo "unshare unavailable: the source tree was not hidden (cases 2 and 3 still prove it)"
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
