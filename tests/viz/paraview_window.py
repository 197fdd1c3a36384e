#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""ParaView's window shows a solve's .pvsm as `hmcr render` draws the view: the Cornell box
solved, its state opened by ParaView's GUI on an Xvfb screen (its framebuffer read from the file
Xvfb keeps of it), and the render view found on that screen (by its background, made magenta)
must be the view's 512 x 512 pixels, within 10 of 255 per pixel on average of `hmcr render`'s
image (the mouse pointer and the two rasterisers' edges differ). Slow: ParaView starts in about
20 s. Skipped (exit code 77) without paraview or Xvfb; HMCR_DEBUG_SCREEN=FILE.png keeps the
last screen seen.
Usage: paraview_window.py REPO_ROOT HMCR_BINARY."""
import os
import pathlib
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time

root = pathlib.Path(sys.argv[1]).resolve()
hmcr = sys.argv[2]
sys.path.insert(0, str(root / "scripts"))
import system_python  # noqa: E402

system_python.need("numpy", "matplotlib")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.image  # noqa: E402
import numpy as np  # noqa: E402

SKIP = 77
if not shutil.which("paraview") or not shutil.which("Xvfb"):
    print("no paraview or Xvfb: skipped (apt-get install --no-install-recommends paraview xvfb)")
    sys.exit(SKIP)


def screen(path):
    """The RGB pixels of an XWD file of 24-bit depth in 32-bit pixels, as Xvfb writes it."""
    data = path.read_bytes()
    h = struct.unpack(">25I", data[:100])
    header, width, height, order, bpp, line, colours = h[0], h[4], h[5], h[7], h[11], h[12], h[19]
    start = header + 12 * colours
    rows = np.frombuffer(data[start:start + line * height], np.uint8).reshape(height, line)
    px = rows[:, :width * bpp // 8].reshape(height, width, bpp // 8)
    return (px[:, :, [2, 1, 0]] if order == 0 else px[:, :, [1, 2, 3]]).astype(int)


MAGENTA = np.array([255, 0, 255])


def render_view(pixels):
    """The render view: the box of its background, which the test makes magenta (the Cornell
    box's camera view has background along all four edges), or None before it is drawn."""
    background = (pixels == MAGENTA).all(axis=2)
    if background.sum() < 1000:
        return None
    rows, cols = np.where(background.any(axis=1))[0], np.where(background.any(axis=0))[0]
    view = pixels[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1].copy()
    view[(view == MAGENTA).all(axis=2)] = 0  # black, as in hmcr's image
    return view


with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    for args in (["solve", "cornell", "--rays", "300000", "-q", "-o", tmp / "c.vtp"],
                 ["render", tmp / "c.vtp", "--scene", "cornell", "-q", "-o", tmp / "r.png"]):
        subprocess.run([hmcr, *map(str, args)], check=True)
    state = (tmp / "c.pvsm").read_text()
    black = re.search(r'<Property name="Background".*?</Property>', state).group(0)
    (tmp / "c.pvsm").write_text(state.replace(black, black.replace(
        'index="0" value="0"', 'index="0" value="1"').replace(
        'index="2" value="0"', 'index="2" value="1"')))
    expected = (matplotlib.image.imread(tmp / "r.png")[:, :, :3] * 255).round().astype(int)
    fb = tmp / "fb"
    fb.mkdir()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", "1", "-screen", "0", "1280x900x24", "-fbdir",
                             str(fb), "-nolisten", "tcp"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True)
    paraview = None
    try:
        display = ":" + xvfb.stdout.readline().strip()
        env = {**os.environ, "DISPLAY": display, "XDG_RUNTIME_DIR": str(tmp)}
        paraview = subprocess.Popen(["paraview", "--dr", f"--state={tmp / 'c.pvsm'}"], env=env,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        view, deadline = None, time.time() + 180
        while time.time() < deadline:
            time.sleep(3)
            view = render_view(last := screen(fb / "Xvfb_screen0"))
            if view is not None and view.shape == expected.shape:
                time.sleep(3)  # drawn in full
                view = render_view(last := screen(fb / "Xvfb_screen0"))
                break
    finally:
        for process in (paraview, xvfb):
            if process:
                process.terminate()
                process.wait(30)
    if os.environ.get("HMCR_DEBUG_SCREEN"):
        matplotlib.image.imsave(os.environ["HMCR_DEBUG_SCREEN"], last.astype(np.uint8))
    if view is None or view.shape != expected.shape:
        shape = None if view is None else f"{view.shape[1]} x {view.shape[0]}"
        sys.exit(f"ParaView's render view is {shape}, not the view's 512 x 512")
    difference = np.abs(view - expected).mean()
    print(f"ParaView's view: 512 x 512, {difference:.2f} of 255 from hmcr render on average")
    sys.exit(0 if difference < 10 else 1)
