# SPDX-License-Identifier: Apache-2.0
"""hmcr from Python: scenes from files or arrays, solves, and solutions as numpy arrays.

    import hmcr
    scene = hmcr.load_scene("cornell")
    solution = hmcr.solve(scene, rays=200_000, seed=1)
    solution.radiosity          # one RGB row per leaf, W/m^2
    solution.write_vtp("cornell.vtp")

Every solver setting is a keyword of solve(); hmcr.settings() lists them. A bad value raises
hmcr.InputError with the command line's one-line message. docs/python.md is the tutorial.
"""
import os
from pathlib import Path

# The bundled scenes: the source tree's when this package is a build folder's, else the
# install's P/share/hmcr (this file is P/lib/python3/dist-packages/hmcr/__init__.py).
if "HMCR_DATA_DIR" not in os.environ:
    try:
        from ._build_tree import SOURCE_DIR as _data
    except ImportError:
        _data = str(Path(__file__).resolve().parents[4] / "share" / "hmcr")
    os.environ["HMCR_DATA_DIR"] = _data

from ._core import (  # noqa: E402
    InputError,
    Scene,
    Solution,
    __version__,
    error,
    load_scene,
    scene_from_arrays,
    settings,
    solve,
)

__all__ = ["InputError", "Scene", "Solution", "__version__", "error", "load_scene",
           "scene_from_arrays", "settings", "solve"]
