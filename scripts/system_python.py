# SPDX-License-Identifier: Apache-2.0
"""The Python the scripts run in: one that has their modules.

numpy, matplotlib and VTK come from Debian's packages (python3-numpy, python3-matplotlib,
python3-vtk9), which serve /usr/bin/python3. Another python3 first on the PATH (pyenv, conda, a
virtual environment) may lack them, so a script run as `python3 scripts/X.py` calls need()
before it imports them: where this interpreter lacks one, the script runs again, once, in
/usr/bin/python3 (with -E, so that PYTHONHOME and PYTHONPATH meant for the other one do not
follow it); where that one lacks it too, it ends with one line naming the package to install.
"""
import importlib.util
import os
import sys

SYSTEM_PYTHON = "/usr/bin/python3"
PACKAGES = {"numpy": "python3-numpy", "matplotlib": "python3-matplotlib", "vtk": "python3-vtk9"}
MISSING_MODULE = 3  # the exit status of a script without its modules
_FIRST = "HMCR_SCRIPT_FIRST_PYTHON"  # in the second run: the interpreter of the first


def missing(modules):
    return [m for m in modules if importlib.util.find_spec(m) is None]


def run_where_importable(*modules):
    """Runs the script again in /usr/bin/python3 when this interpreter lacks one of the modules
    and this is not already the second run; returns otherwise, with the interpreters tried."""
    first = os.environ.pop(_FIRST, None)  # never a third run; the script's children start afresh
    tried = [first, sys.executable] if first else [sys.executable]
    if missing(modules) and not first and os.access(SYSTEM_PYTHON, os.X_OK):
        os.environ[_FIRST] = sys.executable
        sys.stdout.flush()
        sys.stderr.flush()
        os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON, "-E", sys.argv[0], *sys.argv[1:]])
    return tried


def need(*modules):
    """The script's modules, from this interpreter or /usr/bin/python3; else one line and exit
    status MISSING_MODULE."""
    tried = run_where_importable(*modules)
    if lacking := missing(modules):
        packages = " ".join(PACKAGES.get(m, m) for m in lacking)
        sys.stderr.write(f"{os.path.basename(sys.argv[0])}: no module {', '.join(lacking)} in "
                         f"{' or '.join(tried)} (Debian: apt-get install {packages})\n")
        sys.exit(MISSING_MODULE)
