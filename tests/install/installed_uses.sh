#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# installed_uses.sh PREFIX RUN_DIR CONSUMER_DIR [library|no-library], by install_test.sh (with the source tree hidden
# where it can): in RUN_DIR, the installed hmcr lists and solves `cornell`; the outside project in
# CONSUMER_DIR (tests/install/consumer) is configured against PREFIX alone, built, and solves
# cornell to the program's bytes; where PREFIX holds the Python module, it does too.
set -eu
prefix=$1 run=$2 consumer=$3 library=${4:-library}
cd "$run"
"$prefix/bin/hmcr" scenes | grep -qx cornell
"$prefix/bin/hmcr" solve cornell --rays 20000 -q -o cornell.vtp
test -s cornell.vtp
if [ "$library" = library ]; then
    cmake -S "$consumer" -B consumer -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
        > consumer.log 2>&1 || { cat consumer.log; exit 1; }
    cmake --build consumer -j 2 >> consumer.log 2>&1 || { cat consumer.log; exit 1; }
    consumer/solve_scene "$prefix/share/hmcr/scenes/cornell/cornell.json" 20000 library.vtp
    cmp library.vtp cornell.vtp
fi
python=$prefix/lib/python3/dist-packages
if [ -d "$python/hmcr" ]; then
    PYTHONPATH=$python /usr/bin/python3 -c 'import hmcr
s = hmcr.solve(hmcr.load_scene("cornell"), rays=20000)
s.write_vtp("py.vtp")'
    cmp py.vtp cornell.vtp
fi
