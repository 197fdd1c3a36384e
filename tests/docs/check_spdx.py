#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Every tracked source names its license (docs/decisions.md#license): the C++ sources, the
Python, CMake and shell files, the Makefile and any tracked file that starts with #! open with
`SPDX-License-Identifier: Apache-2.0` in a comment of their language, on the first line or on
the second after a #! line; the description comment follows it. LICENSE holds the Apache
License 2.0.
Usage: check_spdx.py REPO_ROOT [--add]. Prints one line per source without the line and exits
with 1 if there is any; 77 (skipped) outside a git work tree, where nothing says what is tracked.
With --add (`make spdx`), writes the line into every source that lacks it instead."""
import pathlib
import subprocess
import sys

LICENSE_ID = "Apache-2.0"
TAG = "SPDX-License-Identifier:"
SUFFIXES = {".cpp": "//", ".h": "//", ".py": "#", ".sh": "#", ".cmake": "#"}
NAMES = {"CMakeLists.txt": "#", "Makefile": "#"}

args = [a for a in sys.argv[1:] if a != "--add"]
add = "--add" in sys.argv[1:]
root = pathlib.Path(args[0] if args else ".").resolve()


def tracked_files():
    """The files git tracks under root, or None outside a work tree."""
    run = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True)
    if run.returncode != 0:
        return None
    return [root / name for name in run.stdout.decode().split("\0") if name]


def comment_of(path, text):
    """The line-comment marker of a source, or None for a file that is not one."""
    if path.name in NAMES:
        return NAMES[path.name]
    if path.suffix in SUFFIXES:
        return SUFFIXES[path.suffix]
    return "#" if text.startswith("#!") else None


def top(lines):
    """Where the SPDX line goes: after a #! line, else first."""
    return 1 if lines and lines[0].startswith("#!") else 0


files = tracked_files()
if files is None:
    print(f"check_spdx.py: {root} is not a git work tree: skipped")
    sys.exit(77)

problems = []
license_text = root / "LICENSE"
if not license_text.is_file() or "Apache License" not in license_text.read_text()[:200] \
        or "Version 2.0, January 2004" not in license_text.read_text()[:200]:
    problems.append("LICENSE: not the Apache License 2.0")

for path in sorted(files):
    if not path.is_file() or path.is_symlink():
        continue
    text = path.read_text(errors="replace")
    marker = comment_of(path, text)
    if marker is None:
        continue
    want = f"{marker} {TAG} {LICENSE_ID}"
    lines = text.splitlines(keepends=True)
    at = top(lines)
    if at < len(lines) and lines[at].rstrip("\n") == want:
        continue
    rel = path.relative_to(root)
    # A license line of another kind or place at the top: reported, never doubled.
    elsewhere = [n for n, line in enumerate(lines[:at + 2], 1) if TAG in line]
    if add and not elsewhere:
        lines.insert(at, want + "\n")
        path.write_text("".join(lines))
        print(f"{rel}: {want}")
    elif elsewhere:
        problems.append(f"{rel}:{elsewhere[0]}: the SPDX line is not `{want}` on line {at + 1}")
    else:
        problems.append(f"{rel}:{at + 1}: no `{want}`")

for p in problems:
    print(p)
sys.exit(1 if problems else 0)
