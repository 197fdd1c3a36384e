#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""docs/usage.md and the program's help agree: every option `hmcr COMMAND --help` offers is in
usage.md's section of that command (its `### hmcr COMMAND` section, the solver settings table
where the section says it takes every solver setting, and the options of every command that
reads a scene); every option the section names in code is one the command takes; where a
section's table gives an option a plain default (a number or one word in code), the help shows
the same; and a table row names the option's short form where the help has one.
Usage: check_help.py REPO_ROOT HMCR_BINARY. Prints one line per problem; exit code 1 if any."""
import pathlib
import re
import subprocess
import sys

root = pathlib.Path(sys.argv[1]).resolve()
hmcr = sys.argv[2]
usage = root / "docs" / "usage.md"
problems = []
LONG = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*)")


def run_help(*args):
    run = subprocess.run([hmcr, *args, "--help"], capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        sys.exit(f"{hmcr} {' '.join(args)} --help: exit code {run.returncode}: {run.stderr}")
    return run.stdout


def commands():
    """The subcommands `hmcr --help` lists."""
    text = run_help().split("Subcommands:", 1)[1]
    return [m.group(1) for m in re.finditer(r"^  ([a-z][a-z-]*)\s", text, re.M)]


def help_options(command):
    """{long option: (short option or None, default or None)} of `hmcr COMMAND --help`."""
    out = {}
    for line in run_help(command).splitlines():
        m = re.match(r"  (-\w,)?(--[\w-]+)(?: (\S+))?", line)
        if not m or m.group(2) == "--help":
            continue
        kind = m.group(3) or ""
        default = kind.split("=", 1)[1] if re.fullmatch(r"[A-Z:]+=\S+", kind) else None
        out[m.group(2)] = (m.group(1)[:-1] if m.group(1) else None, default)
    return out


def sections():
    """usage.md's sections: (heading, [(line number, line)]) outside code blocks."""
    out, fenced = [], False
    for n, line in enumerate(usage.read_text().splitlines(), 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if not fenced and re.match(r"#{2,3} ", line):
            out.append((line.lstrip("#").strip(), []))
        elif out and not fenced:
            out[-1][1].append((n, line))
    return out


def code_options(lines, command="", others=()):
    """The long options named in inline code in the lines: {option: first line number}; not
    those of a span that begins with another command (`render --reference`)."""
    out = {}
    for n, line in lines:
        for span in re.findall(r"`([^`]+)`", line):
            words = span.removeprefix("hmcr ").split()
            if words and words[0] != command and words[0] in others:
                continue
            for option in LONG.findall(span):
                out.setdefault(option, n)
    return out


def table_rows(lines):
    """Rows of the tables whose header's first column is `option` or `setting`:
    (line number, first cell, second cell)."""
    rows, in_table = [], False
    for n, line in lines:
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip().strip("|"))] \
            if line.startswith("|") else None
        if cells is None:
            in_table = False
        elif cells[0] in ("option", "setting"):
            in_table = True
        elif in_table and not set(cells[0]) <= set("-: ") and len(cells) >= 2:
            rows.append((n, cells[0], cells[1]))
    return rows


def plain_default(text):
    """A default usage.md states plainly, as the help would print it: a number, or one word in
    code; None for prose (`the view's`, `8 × spp`, `none`)."""
    text = re.sub(r":.*", "", text).strip()  # "0: all cores"
    if m := re.fullmatch(r"`([\w.-]+)`", text):
        return m.group(1)
    text = text.replace(",", "")
    if m := re.fullmatch(r"10\^(-?\d+)", text):
        return float(f"1e{m.group(1)}")
    try:
        return float(text)
    except ValueError:
        return None


def same_default(doc, shown):
    if isinstance(doc, float):
        try:
            return abs(float(shown) - doc) <= 1e-12 * abs(doc)
        except ValueError:
            return False
    return doc == shown


all_sections = sections()
by_heading = {h: lines for h, lines in all_sections}
solver_rows = table_rows(by_heading["Solver settings"])
options_lines = by_heading["Options"]
options_text = " ".join(l for _, l in options_lines)
scene_rows = table_rows(options_lines)
# "and all but `info` take `-q, --quiet`"
quiet_exceptions = set(re.findall(r"`(\w[\w-]*)`",
                                  re.search(r"and all but (.*?) take `-q", options_text).group(1)))
# The commands that read a scene: their synopsis in "## Commands" names SCENE.
synopsis = re.search(r"## Commands\n\n```\n(.*?)```", usage.read_text(), re.S).group(1)
scene_commands = {m.group(1) for m in re.finditer(r"^hmcr ([a-z-]+) .*SCENE", synopsis, re.M)}

all_commands = commands()
for command in all_commands:
    section = [lines for h, lines in all_sections
               if (m := re.match(r"hmcr (.*)", h)) and command in re.split(r",? and |, ", m.group(1))]
    where = f"docs/usage.md: hmcr {command}"
    if not section:
        problems.append(f"{where}: no section '### hmcr {command}'")
        continue
    lines = section[0]
    rows = table_rows(lines)
    named = code_options(lines, command, all_commands)
    if any("every [solver setting]" in l for _, l in lines):
        rows += solver_rows
        named.update(code_options([(n, c) for n, c, _ in solver_rows]))
    if command in scene_commands:
        rows += scene_rows
        named.update(code_options([(n, c) for n, c, _ in scene_rows]))
        if command not in quiet_exceptions:
            named.setdefault("--quiet", 0)
    helped = help_options(command)
    for option in helped:
        if option not in named:
            problems.append(f"{where}: {option} is in `hmcr {command} --help` but not in its section")
    for option, n in named.items():
        if option not in helped:
            problems.append(f"docs/usage.md:{n}: hmcr {command}: names {option}, which "
                            f"`hmcr {command} --help` does not offer")
    for n, first, default in rows:
        for option in LONG.findall(first):
            if option not in helped:
                continue
            short, shown = helped[option]
            if short and not re.search(rf"(?<![\w-]){short}\b", first):
                problems.append(f"docs/usage.md:{n}: hmcr {command}: {option} is also {short}")
            doc = plain_default(default)
            if doc is not None and (shown is None or not same_default(doc, shown)):
                problems.append(f"docs/usage.md:{n}: hmcr {command}: {option}'s default is "
                                f"{default} here and {shown} in the help")

for p in problems:
    print(p)
sys.exit(1 if problems else 0)
