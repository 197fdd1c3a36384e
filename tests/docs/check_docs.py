#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The docs stay true to the tree: every relative link of README.md and docs/*.md names a file
that exists and, with #anchor, one of its headings; every docs/... citation in the sources
resolves (docs/design.md §N to a heading numbered N, docs/X.md#anchor to a heading); every
source path cited in a source's comment is a file of the tree (a cited line within it); every
registered oracle and pixel criterion has its entry in docs/oracles.md or docs/criteria.md,
holding line 2 of its source file's opening comment (its paper, or why it has none; the comment
after the license line); and the viewing advice keeps the build: `make view-deps` installs
ParaView without its recommended packages (python3-paraview, which would remove libvtk9-dev),
and the docs send readers there; no source includes a folder its layer does not link, and
docs/developing.md's table of layers names the links of CMakeLists.txt's hmcr_layer lines.
Usage: check_docs.py REPO_ROOT. Prints one line per problem; exit code 1 if there is any."""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
problems = []


def slug(heading):
    """GitHub's anchor of a heading: lower case, spaces to '-', punctuation dropped."""
    text = re.sub(r"`|\*", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def headings(path):
    """Every heading of a Markdown file (outside code blocks): its text."""
    out, fenced = [], False
    for line in path.read_text().splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and (m := re.match(r"#{1,6} (.*)", line)):
            out.append(m.group(1).strip())
    return out


def anchors(path):
    seen, out = {}, set()
    for h in headings(path):
        s = slug(h)
        n = seen.get(s, 0)
        out.add(s if n == 0 else f"{s}-{n}")
        seen[s] = n + 1
    return out


def check_link(source, where, target):
    path, _, anchor = target.partition("#")
    file = (source.parent / path).resolve() if path else source
    if not file.exists():
        problems.append(f"{where}: link to {target}: no such file")
    elif anchor and file.suffix == ".md" and anchor not in anchors(file):
        problems.append(f"{where}: link to {target}: no such heading in {file.name}")


# 1. Relative links between the docs.
for md in [root / "README.md", *sorted((root / "docs").glob("*.md"))]:
    fenced = False
    for n, line in enumerate(md.read_text().splitlines(), 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        for target in re.findall(r"\]\(([^)\s]+)\)", line):
            if re.match(r"[a-z]+:", target):  # http:, mailto:
                continue
            check_link(md, f"{md.relative_to(root)}:{n}", target)

# 2. Citations of the docs in the sources: docs/design.md §N, docs/X.md#anchor.
design = root / "docs" / "design.md"
numbers = {m.group(1) for h in headings(design) if (m := re.match(r"(\d+(?:\.\d+)*)\.? ", h))}
sources = [p for p in root.rglob("*") if p.suffix in (".cpp", ".h", ".py", ".sh", ".txt")
           or p.name in ("CMakeLists.txt", "Makefile")]
for src in sorted(sources):
    rel = src.relative_to(root)
    if rel.parts[0].startswith(("build", ".git")) or rel == pathlib.Path(__file__).relative_to(root):
        continue
    for n, line in enumerate(src.read_text(errors="replace").splitlines(), 1):
        for doc, rest in re.findall(r"docs/([\w-]+\.md)((?:#[\w-]+)?(?: §[\d.]+(?:, §[\d.]+)*)?)",
                                    line):
            where = f"{rel}:{n}"
            if rest.startswith("#"):
                check_link(root / "docs" / "x.md", where, doc + rest)
            else:
                check_link(root / "docs" / "x.md", where, doc)
            for number in re.findall(r"§([\d.]+[\d])", rest):
                if doc != "design.md" or number not in numbers:
                    problems.append(f"{where}: docs/{doc} §{number}: no such section")

# 3. Every registered plug-in has its entry, holding its paper paragraph.
def plugin_entries(registry, folder, doc):
    text = (root / registry).read_text()
    sections = {}
    current = None
    for line in (root / doc).read_text().splitlines():
        if m := re.match(r"## `([^`]+)`\s*$", line):
            current = m.group(1)
            sections[current] = []
        elif line.startswith("## "):
            current = None
        elif current:
            sections[current].append(line)
    for file_name in re.findall(r"^\s*X\((\w+)\)", text, re.M):
        src = root / folder / f"{file_name}.cpp"
        code = src.read_text()
        name = re.search(r'Named(?:Oracle|Criterion)\(\s*"([^"]+)"', code).group(1)
        lines = code.splitlines()
        if lines and "SPDX-" in lines[0]:  # the opening comment follows the license line
            lines = lines[1:]
        second = lines[1]
        paper = second[2:].strip() if second.startswith("//") else ""
        entry = sections.get(name)
        if entry is None:
            problems.append(f"{doc}: no entry '## `{name}`' for the registered {src.relative_to(root)}")
        elif paper and paper not in " ".join(" ".join(entry).split()):
            problems.append(f"{doc}: the entry of `{name}` does not hold line 2 of "
                            f"{src.relative_to(root)}: {paper!r}")


plugin_entries("radiosity/oracle_registry.cpp", "oracles", "docs/oracles.md")
plugin_entries("trace/criteria/registry.cpp", "trace/criteria", "docs/criteria.md")

# 4. ParaView without what would remove libvtk9-dev: `make view-deps`, and no doc that installs
# it another way.
def recipe(makefile, target):
    lines, out = makefile.read_text().splitlines(), None
    for line in lines:
        if out is None and line.startswith(target + ":"):
            out = []
        elif out is not None:
            if not line.startswith("\t"):
                break
            out.append(line)
    return "\n".join(out) if out is not None else None


makefile = root / "Makefile"
view = recipe(makefile, "view-deps")
view_packages = re.search(r"^VIEW_DEPS\s*:?=\s*(.*)$", makefile.read_text(), re.M)
if view is None:
    problems.append("Makefile: no view-deps target (ParaView and Xvfb for viewing results)")
elif "--no-install-recommends" not in view or "apt-get install" not in view:
    problems.append("Makefile: view-deps does not install with apt-get --no-install-recommends")
elif not view_packages or "paraview" not in view_packages.group(1).split():
    problems.append("Makefile: VIEW_DEPS does not name paraview")
for md in [root / "README.md", *sorted((root / "docs").glob("*.md"))]:
    text = md.read_text()
    for n, line in enumerate(text.splitlines(), 1):
        if re.search(r"\bapt(-get)? install\b", line) and "paraview" in line \
                and "--no-install-recommends" not in line:
            problems.append(f"{md.relative_to(root)}:{n}: installs paraview with its recommended "
                            "packages (python3-paraview removes libvtk9-dev): say make view-deps")
for doc in ("README.md", "docs/usage.md"):
    if "make view-deps" not in (root / doc).read_text():
        problems.append(f"{doc}: the viewing advice does not say make view-deps")

# An install path that names a version names this one (CMakeLists.txt's project version), and a
# find_package of hmcr asks for its minor version.
version = re.search(r"project\(hmcr VERSION ([\d.]+)", (root / "CMakeLists.txt").read_text())
for md in [root / "README.md", *sorted((root / "docs").glob("*.md"))]:
    for n, line in enumerate(md.read_text().splitlines(), 1):
        for named in re.findall(r"/hmcr/(\d+\.\d+\.\d+)", line):
            if version and named != version.group(1):
                problems.append(f"{md.relative_to(root)}:{n}: names version {named}; hmcr is "
                                f"{version.group(1)} (CMakeLists.txt)")
        # find_package(hmcr X.Y) asks for the same minor version (hmcrConfigVersion.cmake's
        # SameMinorVersion): this one's.
        for named in re.findall(r"find_package\(hmcr (\d+\.\d+)", line):
            if version and not version.group(1).startswith(named + "."):
                problems.append(f"{md.relative_to(root)}:{n}: asks for hmcr {named}; hmcr is "
                                f"{version.group(1)} (CMakeLists.txt)")

# Source paths cited in the sources' comments name what is there: a path that starts at a folder
# of the tree and names a source or doc (`radiosity/solver.h`, `rays/patch.h:12`, `:12-20`) is a
# file of the tree, with at least as many lines as a line cited; a bare `name.h` or `name.cpp`
# is beside the citing file or, in a test, in the folder it tests (tests/rays/ tests rays/).
# A path with a word in capitals is a pattern (`oracles/NAME.cpp`), not a citation.
def cpp_comments(text):
    """(line number, text) of each comment of a C++ source, string literals skipped."""
    out, i, n, line = [], 0, len(text), 1
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            out.append((line, text[i + 2:end]))
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end
            for k, part in enumerate(text[i + 2:end].split("\n")):
                out.append((line + k, part))
            line += text.count("\n", i, end)
            i = end + 2
        elif c == "R" and (m := re.match(r'R"([^(\s]*)\(', text[i:i + 20])):
            end = text.find(")" + m.group(1) + '"', i)
            end = n if end < 0 else end
            line += text.count("\n", i, end)
            i = end + len(m.group(1)) + 2
        elif c == '"' or (c == "'" and not text[i - 1].isalnum()):  # 1'000: a digit separator
            k = i + 1
            while k < n and text[k] != c and text[k] != "\n":
                k += 2 if text[k] == "\\" else 1
            i = k + 1
        else:
            if c == "\n":
                line += 1
            i += 1
    return out


def script_comments(path, text):
    """(line number, text) of each comment of a script: Python's comments and docstrings
    (tokenize, ast), a shell's, Make's or CMake's `#` lines and trailing `  # ...`."""
    if path.suffix == ".py":
        import ast
        import io
        import tokenize
        out = [(tok.start[0], tok.string) for tok in
               tokenize.generate_tokens(io.StringIO(text).readline) if tok.type == tokenize.COMMENT]
        for node in ast.walk(ast.parse(text)):
            body = getattr(node, "body", None)
            if isinstance(body, list) and body and isinstance(body[0], ast.Expr) \
                    and isinstance(body[0].value, ast.Constant) \
                    and isinstance(body[0].value.value, str):
                first, doc = body[0].value.lineno, body[0].value.value
                out += [(first + k, part) for k, part in enumerate(doc.split("\n"))]
        return out
    return [(k, m.group(1)) for k, line in enumerate(text.splitlines(), 1)
            if (m := re.search(r"(?:^|\s)#(.*)", line))]


tops = sorted(p.name for p in root.iterdir()
              if p.is_dir() and not p.name.startswith((".", "build")))
cited = re.compile(r"(?<![\w./-])((?:%s)/[\w./-]*\.(?:h|cpp|py|sh|md|txt|supp))"
                   r"(?::(\d+)(?:-(\d+))?)?(?![\w/])" % "|".join(map(re.escape, tops)))
bare = re.compile(r"(?<![\w./-])([a-z_][a-z0-9_]*\.(?:h|cpp))(?![\w/])")
line_counts = {}
for src in sorted(sources):
    rel = src.relative_to(root)
    if rel.parts[0].startswith(("build", ".git")):
        continue
    text = src.read_text(errors="replace")
    comments = cpp_comments(text) if src.suffix in (".cpp", ".h") else script_comments(src, text)
    near = [src.parent]
    if rel.parts[0] == "tests" and len(rel.parts) > 2:
        near.append(root.joinpath(*rel.parts[1:-1]))
    for n, comment in comments:
        for m in cited.finditer(comment):
            path = m.group(1)
            if re.search(r"[A-Z]{2,}|(^|/)[A-Z](\.|/)", path):
                continue
            target = root / path
            if not target.is_file():
                problems.append(f"{rel}:{n}: cites {path}: no such file")
            elif m.group(2):
                if path not in line_counts:
                    line_counts[path] = len(target.read_text(errors="replace").splitlines())
                count = line_counts[path]
                if int(m.group(3) or m.group(2)) > count:
                    problems.append(f"{rel}:{n}: cites {m.group(0)}: {path} has {count} lines")
        if src.suffix in (".cpp", ".h"):
            for m in bare.finditer(comment):
                if not any((folder / m.group(1)).is_file() for folder in near):
                    problems.append(f"{rel}:{n}: cites {m.group(1)}: not beside it "
                                    "(name its folder)")

# The layers (CMakeLists.txt's hmcr_layer lines): no source includes a folder its library does not
# link, directly or through the folders it links (which the build refuses too, but only for the
# configurations built); and docs/developing.md's table of layers names each folder's links.
cmake = (root / "CMakeLists.txt").read_text()
links = {}
for m in re.finditer(r"^hmcr_layer\((\w+)([^)]*)\)", cmake, re.M):
    links[m.group(1)] = re.findall(r"\bhmcr_(\w+)", m.group(2))
reach = {}
for folder in links:  # the lines run bottom to top: a folder's links are already resolved
    reach[folder] = {folder}.union(*(reach.get(f, {f}) for f in links[folder]))
for folder in links:
    for src in sorted((root / folder).rglob("*")):
        if src.suffix not in (".cpp", ".h"):
            continue
        for n, line in enumerate(src.read_text(errors="replace").splitlines(), 1):
            m = re.match(r'\s*#\s*include\s+"(\w+)/', line)
            if m and m.group(1) in links and m.group(1) not in reach[folder]:
                problems.append(f"{src.relative_to(root)}:{n}: includes {m.group(1)}/, a layer "
                                f"{folder}/ does not link (CMakeLists.txt's hmcr_layer lines)")
rows = {}
for line in (root / "docs/developing.md").read_text().splitlines():
    if m := re.match(r"\| `(\w+)/` \| ([^|]*) \|", line):
        rows[m.group(1)] = set(re.findall(r"\w+", m.group(2))) & set(links)
for folder, linked in links.items():
    if folder not in rows:
        problems.append(f"docs/developing.md: the table of layers has no row for `{folder}/`")
    elif rows[folder] != set(linked):
        problems.append(f"docs/developing.md: the layers' table says `{folder}/` links "
                        f"{sorted(rows[folder]) or 'no folder'}; CMakeLists.txt links "
                        f"{sorted(linked) or 'no folder'}")

for p in problems:
    print(p)
sys.exit(1 if problems else 0)
