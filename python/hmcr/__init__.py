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

from . import _core  # noqa: E402
from ._core import (  # noqa: E402
    InputError,
    Scene,
    Solution,
    __version__,
    error,
    information,
    load_scene,
    mesh_reference,
    points_reference,
    scene_from_arrays,
    settings,
    solve,
    trace,
)

__all__ = ["InputError", "Scene", "Solution", "__version__", "error", "information",
           "load_scene", "mesh_reference", "meshing_study", "points_reference",
           "sampling_study", "scene_from_arrays", "settings", "solve", "trace"]

# A cell's values that are one number or name each, as table.json names them.
_CELL_VALUES = ("scene", "oracle", "budget", "seed", "status", "message", "epsilon", "leaves",
                "probes", "rays", "mesh_rays", "seconds", "finer_share")


def _flat_cell(cell):
    """One row of plain values: a cell's object errors and its views' metrics by name."""
    row = {key: cell[key] for key in _CELL_VALUES if key in cell}
    for part in ("", "mesh_"):
        error = cell.get(part + "object_error")
        if error:
            row[part + "object_error"] = error["relative_l2"]
            row[part + "object_error_se"] = error["standard_error"]
        for view, metrics in (cell.get(part + "views") or {}).items():
            for metric, value in metrics.items():
                row[f"{part}{metric}_{view}"] = value
    return row


def meshing_study(scene, reference, budgets, output, **keywords):
    """`hmcr study SCENE --reference REFERENCE --budgets ... -o OUTPUT`, its plots aside.

    Every oracle (oracles=[...], all by default) x budget x seed (seeds=3) is solved and measured
    against the reference; OUTPUT gets the cells, tables, images and meshes the command writes,
    and a second call resumes it. Every other keyword is a solver setting, as for solve().
    Returns one dict of plain values per cell (a pandas DataFrame takes the list as it is):
    oracle, budget, seed, leaves, epsilon, object_error and its standard error, each view's
    rmse_a/rmse_p/psnr_a/psnr_p, and the mesh error's (mesh_...).
    """
    cells = _core.meshing_study(scene, str(reference), [int(b) for b in budgets], str(output),
                                **keywords)
    return [_flat_cell(cell) for cell in cells]


# A sampling cell's values that are one number or name each.
_SAMPLING_VALUES = ("scene", "sampler", "spp", "seed", "status", "message", "seconds")


def _flat_sampling_cell(cell):
    """One row of plain values: each view's errors and its achieved samples by name."""
    row = {key: cell[key] for key in _SAMPLING_VALUES if key in cell}
    for view, values in (cell.get("views") or {}).items():
        for key, value in values.items():
            if isinstance(value, dict):
                for metric, v in value.items():
                    row[f"{metric}_{view}"] = v
            else:
                row[f"{key}_{view}"] = value
    return row


def sampling_study(scene, reference, output, **keywords):
    """`hmcr study SCENE --reference REFERENCE --samplers ... -o OUTPUT`, its plots aside.

    Every pixel sampler (samplers=[...], all by default) x mean spp (spps=[60]) x seed (seeds=3)
    traces the scene's views and is measured against the reference. Returns one dict of plain
    values per cell: sampler, spp, seed, and per view its rmse_a/rmse_p/psnr_a/psnr_p and the
    samples it took (spp_VIEW, min_spp_VIEW, max_spp_VIEW, threshold_VIEW, rays_VIEW).
    """
    cells = _core.sampling_study(scene, str(reference), str(output), **keywords)
    return [_flat_sampling_cell(cell) for cell in cells]
