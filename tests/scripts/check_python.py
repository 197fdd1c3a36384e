#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The scripts find a Python that has their modules (scripts/system_python.py): run by a python3
without Debian's numpy and matplotlib (a virtual environment of /usr/bin/python3, as a user's
pyenv or venv comes first on the PATH), each runs again in /usr/bin/python3 and works; run
directly, by its shebang, too; and where no Python has a module, one line names its package.
Usage: check_python.py REPO_ROOT. Prints one line per problem; exit code 1 if any."""
import json
import os
import pathlib
import subprocess
import sys
import tempfile

root = pathlib.Path(sys.argv[1]).resolve()
scripts = root / "scripts"
problems = []


def run(*command, cwd=None):
    env = {k: v for k, v in os.environ.items() if not k.startswith("HMCR_SCRIPT_")}
    try:
        return subprocess.run([str(c) for c in command], capture_output=True, text=True,
                              timeout=300, cwd=cwd, env=env)
    except OSError as e:  # not executable
        return subprocess.CompletedProcess(command, -1, "", str(e))


def expect(what, r, code=0, err=None):
    if r.returncode != code or (err is not None and err not in r.stderr):
        problems.append(f"{what}: exit code {r.returncode} (expected {code}); stderr: "
                        f"{r.stderr.strip()[-400:]}")


with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    made = run("/usr/bin/python3", "-m", "venv", "--without-pip", tmp / "venv")
    python = tmp / "venv" / "bin" / "python3"
    if made.returncode != 0:
        sys.exit(f"cannot make a virtual environment: {made.stderr.strip()}")
    for module in ("numpy", "matplotlib"):
        if run(python, "-c", f"import {module}").returncode == 0:
            sys.exit(f"{python} has {module}: it cannot stand for a Python without it")

    # plot_study.py draws a figure from plot data.
    data = tmp / "plot_data.json"
    point = {"x": 100, "x_se": None, "y": 0.1, "y_se": None, "n": 1}
    data.write_text(json.dumps({"figures": [{"name": "f", "panels": [{
        "type": "lines", "title": "t", "x_label": "x", "y_label": "y",
        "series": [{"name": "s", "points": [point]}]}]}]}))
    for how in ([python, scripts / "plot_study.py"], [scripts / "plot_study.py"]):
        (tmp / "f.png").unlink(missing_ok=True)
        expect(f"{' '.join(map(str, how))} DATA", run(*how, data))
        if not (tmp / "f.png").exists():
            problems.append(f"{' '.join(map(str, how))} DATA: no f.png")

    # The scripts whose modules are numpy and matplotlib reach their own arguments.
    for script in ("compare_references.py", "cycles_compare.py"):
        expect(f"venv python3 {script} --help", run(python, scripts / script, "--help"))
        expect(f"{script} --help", run(scripts / script, "--help"))
    expect("venv python3 make_figures.py", run(python, scripts / "make_figures.py"), 1,
           "scripts/make_figures.py studies/cornell")

    # A module no Python has: one line naming it, exit code 3, no third run.
    lacking = tmp / "lacking.py"
    lacking.write_text(f"import sys\nsys.path.insert(0, {str(scripts)!r})\nimport system_python\n"
                       "system_python.need('numpy', 'hmcr_no_such_module')\n")
    r = run(python, lacking)
    expect("a module no Python has", r, 3,
           f"lacking.py: no module hmcr_no_such_module in {python} or /usr/bin/python3 (Debian: "
           "apt-get install hmcr_no_such_module)\n")
    if r.stderr.count("\n") != 1:
        problems.append(f"a module no Python has: not one line: {r.stderr!r}")

for p in problems:
    print(p)
sys.exit(1 if problems else 0)
