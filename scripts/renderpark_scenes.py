#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""RenderPark's ten top-level MGF scenes solved and rendered by hmcr (docs/renderpark-scenes.md).

What it does, in order:

1. Finds the scenes: rpkCpp's `etc/` (RenderPark's scenes, in its C++ port) from `--rpk-source`
   (a source folder or clone, or a git directory such as a bare mirror, whose `etc/` is exported
   with `git archive`), or else from a shallow clone of its public repository in a temporary
   folder. Nothing of rpkCpp is written into hmcr's tree.
2. Writes, for each scene, a scene file `WORK/scenes/NAME.json` naming the MGF file, with the views
   below: positions inside the rooms, looking at lit parts (the default view of a bare mesh looks
   at the bounding box from outside, where every wall shows its dark outer face).
3. Runs `hmcr solve` with its defaults (the kl oracle, 2,684,000 rays; WORK/NAME.vtp, .json
   and .pvsm) and `hmcr render` of each view (WORK/NAME-VIEW.png), and prints a markdown table
   from each run summary: patches, of which two-sided, the repairs the load reported, load and
   solve seconds, leaves, peak memory.

Standard library only.  Usage:
    scripts/renderpark_scenes.py --hmcr build/hmcr --work /tmp/rpk-scenes [--rpk-source DIR]
                                 [--threads 2] [--samples 3] [--scenes hospital,graz]
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

RPK_REPOSITORY = "https://github.com/OscarChavarro/rpkCpp"


def view(name, position, look_at, up=(0, 0, 1), fov=60):
    return {"name": name, "position": list(position), "look_at": list(look_at),
            "up": list(up), "fov": fov, "width": 384, "height": 288}


# name, MGF file under etc/, what it is, views (metres; z is up except where up says y).
SCENES = [
    ("classroom", "salon/classroom.mgf", "a classroom: rows of desks and chairs, ceiling lights",
     [view("back", (6.6, 10.9, 1.8), (3.0, 3.0, 0.7)),
      view("front", (0.6, 0.4, 1.7), (4.5, 7.5, 0.9))]),
    ("hospital", "hospital/hosp.mgf", "a hospital floor: corridor, waiting room and offices",
     [view("waiting", (5.2, 2.4, 1.6), (3.4, 8.0, 0.6)),
      view("corridor", (1.5, 0.5, 1.6), (1.5, 12.0, 1.0))]),
    ("graz", "office1/graz.mgf", "an office in Graz: desks, shelves, chairs, a window wall",
     [view("desk", (5.0, 0.2, 1.6), (1.5, 3.5, 0.8)),
      view("shelves", (0.5, 4.2, 1.7), (4.0, 1.0, 0.9))]),
    ("office2", "office2/office2.mgf", "an office: a desk and a cabinet under a ceiling light",
     [view("corner", (3.8, 5.5, 1.6), (1.5, 1.0, 0.8))]),
    ("office3", "office3/office.mgf", "an office with a lamp on a desk (y up)",
     [view("corner", (2.0, 3.0, 2.0), (-1.2, 2.0, -1.2), up=(0, 1, 0))]),
    ("corridor", "corridor.mgf", "an L-shaped corridor with glossy doors, a sphere and a torus",
     [view("along", (0.0, 0.5, 3.0), (3.0, 16.0, 2.5))]),
    ("cube", "cube.mgf", "a room with a glossy floor and coloured blocks under one light",
     [view("corner", (8.5, 1.5, 5.0), (3.5, 6.0, 1.5), fov=65)]),
    ("floor_gloss", "floor_gloss.mgf", "a floor, a green stand and a glossy red sphere under a "
     "light (not a room)", [view("oblique", (3.0, -1.0, 1.6), (6.0, 2.0, 0.4), fov=50)]),
    ("soda", "soda.mgf", "a bar: a counter, stools, tables, glasses and globe lamps (y up)",
     [view("table", (2.8, 1.6, 6.0), (-1.0, 0.8, -2.0), up=(0, 1, 0))]),
    ("examp1", "examp1.mgf", "a fluorescent luminaire, seen from below (not a room)",
     [view("below", (0.0, 0.0, -0.9), (0.0, 0.0, 0.0), up=(0, 1, 0), fov=55)]),
]


def find_etc(source, scratch):
    """rpkCpp's etc/ folder: in a source folder, exported from a git directory, or cloned."""
    if source and os.path.isdir(os.path.join(source, "etc")):
        return os.path.join(source, "etc"), f"the folder {source}"
    if source:  # a git directory: a clone's .git, a bare repository or a mirror
        archive = subprocess.run(["git", "--git-dir", source, "archive", "HEAD", "etc"],
                                 check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", scratch], input=archive, check=True)
        commit = subprocess.run(["git", "--git-dir", source, "rev-parse", "--short", "HEAD"],
                                check=True, capture_output=True, text=True).stdout.strip()
        return os.path.join(scratch, "etc"), f"git archive {commit} of {source}"
    clone = os.path.join(scratch, "rpkCpp")
    subprocess.run(["git", "clone", "--depth", "1", "--quiet", RPK_REPOSITORY, clone], check=True)
    return os.path.join(clone, "etc"), RPK_REPOSITORY


def run(command, log):
    """Runs an hmcr command; its stderr goes to the log, and a failure stops the script."""
    with open(log, "a") as f:
        f.write("$ " + " ".join(command) + "\n")
        f.flush()
        done = subprocess.run(command, stdout=f, stderr=subprocess.STDOUT)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed with exit code {done.returncode}; see {log}")


def repairs_cell(repairs):
    short = {"triangulated": "triangulated", "quads_split": "quads split",
             "corners_removed": "corners removed", "degenerate_dropped": "degenerate dropped",
             "duplicates_dropped": "duplicates dropped", "reflectance_one": "reflectance 1",
             "sides_joined": "**sides joined**", "coincident_dropped": "**coincident dropped**",
             "specular_reduced": "rs reduced"}
    order = list(short) + sorted(set(repairs) - set(short) - {"count"})
    parts = [f"{repairs[k]['count']:,} {short.get(k, k)}" for k in order if k in repairs]
    return ", ".join(parts) or "none"


def solve_and_render(hmcr, etc, work, scene, threads, samples):
    name, mgf, description, views = scene
    os.makedirs(os.path.join(work, "scenes"), exist_ok=True)
    scene_file = os.path.join(work, "scenes", name + ".json")  # WORK/NAME.json: the summary
    with open(scene_file, "w") as f:
        json.dump({"mesh": os.path.abspath(os.path.join(etc, mgf)),
                   "description": f"RenderPark's {mgf}: {description}", "views": views},
                  f, indent=1)
    vtp, log = os.path.join(work, name + ".vtp"), os.path.join(work, name + ".log")
    if os.path.exists(log):
        os.remove(log)
    run([hmcr, "solve", scene_file, "-o", vtp, "--threads", str(threads), "--progress", "none"],
        log)
    for v in views:
        run([hmcr, "render", vtp, "--scene", scene_file, "--view", v["name"],
             "--samples", str(samples), "-o", os.path.join(work, f"{name}-{v['name']}.png")], log)
    with open(vtp[:-len(".vtp")] + ".json") as f:
        return json.load(f)


def table_row(name, mgf, summary):
    s, c, t = summary["scene"], summary["counts"], summary["timings_s"]
    return (f"| {name} | `{mgf}` | {s['patches']:,} | {s.get('two_sided_patches', 0):,} | "
            f"{repairs_cell(s['repairs'])} | {t['load']:.2f} | {t['solve']:.2f} | "
            f"{c['leaves']:,} | {summary['memory']['peak_bytes'] / 2**20:,.0f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--hmcr", required=True, help="the hmcr binary")
    parser.add_argument("--work", required=True, help="folder for scene files, solutions, PNGs")
    parser.add_argument("--rpk-source", help="rpkCpp: a source folder, clone or git directory")
    parser.add_argument("--threads", type=int, default=2, help="threads of each solve")
    parser.add_argument("--samples", type=int, default=3, help="n x n samples per pixel")
    parser.add_argument("--scenes", help="comma-separated names (default: all ten)")
    args = parser.parse_args()
    wanted = args.scenes.split(",") if args.scenes else [s[0] for s in SCENES]
    unknown = set(wanted) - {s[0] for s in SCENES}
    if unknown:
        sys.exit(f"unknown scenes: {', '.join(sorted(unknown))}")
    hmcr = os.path.abspath(args.hmcr)
    os.makedirs(args.work, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        etc, origin = find_etc(args.rpk_source, scratch)
        print(f"scenes from {origin}; hmcr solve defaults, --threads {args.threads}\n")
        print("| scene | file | patches | two-sided | repairs | load s | solve s | leaves "
              "| peak MiB |")
        print("|---|---|--:|--:|---|--:|--:|--:|--:|")
        for scene in SCENES:
            if scene[0] in wanted:
                summary = solve_and_render(hmcr, etc, args.work, scene, args.threads,
                                           args.samples)
                print(table_row(scene[0], scene[1], summary), flush=True)


if __name__ == "__main__":
    main()
