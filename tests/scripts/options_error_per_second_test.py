#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/options_error_per_second.py on the plates: its rows are the seeds' solutions as
`hmcr error` measures them (the mean of the error files it keeps, the same leaves for a
variant's seeds at one epsilon), its efficiency is 1 / (error^2 x CPU s) relative to the first
row's, and an unknown variant or a failing hmcr stops it with a message instead of a traceback.

Usage: options_error_per_second_test.py HMCR SOURCE_DIR. Exit code 1 on failure."""
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile

HMCR, SOURCE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
SCRIPT = os.path.join(SOURCE, "scripts", "options_error_per_second.py")
problems = []

with tempfile.TemporaryDirectory() as tmp:
    ref, work = os.path.join(tmp, "ref"), os.path.join(tmp, "work")
    subprocess.run([HMCR, "reference", "plates", "--points", "2000", "--paths", "16", "-q", "-o",
                    ref], check=True)
    base = [sys.executable, SCRIPT, "--hmcr", HMCR, "--scene", "plates", "--reference", ref]
    out = subprocess.run(base + ["--budgets", "64", "--budget-tolerance", "0.1", "--seeds", "2",
                                 "--variants", "random,sobol+both", "--work", work],
                         capture_output=True, text=True)
    if out.returncode != 0:
        problems.append(f"the script failed: {out.stderr}")
    rows = [line.split() for line in out.stdout.splitlines()[2:]]
    if [r[1] for r in rows] != ["random", "sobol+both"]:
        problems.append(f"rows {rows}")
    else:
        first = None
        for r in rows:
            errors = [json.load(open(f))["object_error"]["relative_l2"]
                      for f in sorted(glob.glob(os.path.join(work, f"64-{r[1]}-s*-error.json")))]
            leaves = {json.load(open(f))["counts"]["leaves"]
                      for f in glob.glob(os.path.join(work, f"64-{r[1]}-s*.json"))
                      if not f.endswith("-error.json")}
            mean, seconds, efficiency = float(r[3]), float(r[6]), float(r[7])
            if len(errors) != 2 or abs(statistics.fmean(errors) - mean) > 5e-5:
                problems.append(f"{r[1]}: printed error {mean}, the files hold {errors}")
            if len(leaves) != 1 or float(r[2]) != leaves.pop():
                problems.append(f"{r[1]}: the seeds' leaves differ or are not the printed ones")
            # A variant's sequence word reaches hmcr (random is not the default).
            sequences = {json.load(open(f))["options"]["sequence"]
                         for f in glob.glob(os.path.join(work, f"64-{r[1]}-s*.json"))
                         if not f.endswith("-error.json")}
            if sequences != {r[1].split("+")[0]}:
                problems.append(f"{r[1]}: solved with sequence {sequences}")
            # From the printed figures, rounded to 1e-4 and 0.01: their relative rounding,
            # the first row's and this one's, and the efficiency's own 0.005.
            value = 1 / (mean * mean * seconds)
            rounding = 2 * 0.5e-4 / mean + 0.005 / seconds
            first = first or (value, rounding)
            bound = efficiency * (rounding + first[1]) + 0.005
            if abs(value / first[0] - efficiency) > bound:
                problems.append(f"{r[1]}: efficiency {efficiency}, its error and seconds give "
                                f"{value / first[0]:.2f}")
    bad = subprocess.run(base + ["--variants", "random,sobal"], capture_output=True, text=True)
    if bad.returncode == 0 or "unknown variant word 'sobal'" not in bad.stderr:
        problems.append(f"an unknown variant: exit {bad.returncode}, {bad.stderr!r}")
    failing = subprocess.run(base + ["--budgets", "64", "--budget-tolerance", "0.001"],
                             capture_output=True, text=True)
    if failing.returncode != 2 or "Traceback" in failing.stderr:
        problems.append(f"a budget hmcr cannot reach: exit {failing.returncode}, "
                        f"{failing.stderr[-300:]!r}")

for p in problems:
    print(p)
sys.exit(1 if problems else 0)
