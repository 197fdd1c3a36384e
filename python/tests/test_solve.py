# SPDX-License-Identifier: Apache-2.0
"""The Python module against the engine's exact values and the command line's own output."""
import json
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import hmcr

RHO, E = 0.5, 1.0


def inward_box():
    """The unit cube's six faces as quads facing inward: a closed furnace."""
    v = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
    # Corners counter-clockwise seen from inside the cube.
    faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    return v, faces


def furnace():
    v, faces = inward_box()
    return hmcr.scene_from_arrays(v, faces, reflectance=[RHO] * 3, emission=[E] * 3, sides=1,
                                  name="furnace")


def test_a_closed_furnace_keeps_every_iterations_power():
    # Every ray lands in a closed box and deposits rho times its power, and an iteration's rays
    # carry its unshot power exactly, so after K iterations the area-weighted mean of B is
    # E (1 + rho + ... + rho^K) whatever the seed: exact but for the dithered rounding of each
    # ray's power to a quantum, 2^-61 of the iteration's power (below 1e-12 relative here).
    sol = hmcr.solve(furnace(), rays=50_000, max_depth=0, refine_share=1, seed=3)
    k = sol.stats["iterations"]
    mean = (sol.area[:, None] * sol.radiosity).sum(axis=0) / sol.area.sum()
    expected = E * sum(RHO**i for i in range(k + 1))
    np.testing.assert_allclose(mean, [expected] * 3, rtol=1e-9)
    assert sol.patch_id.tolist() == list(range(6))
    assert (sol.side == 0).all() and (sol.level == 0).all()
    assert sol.cluster_id is None


def test_each_furnace_patch_is_unbiased():
    # Per patch, B is random, with mean the K-bounce value: over 16 seeds each patch's mean lies
    # within 5 standard errors of it (t with 15 degrees of freedom: a false alarm for one of the
    # 6 patches, grey in every channel, in about 1 run in 1,000).
    values, ks = [], set()
    for seed in range(1, 17):
        sol = hmcr.solve(furnace(), rays=20_000, max_depth=0, refine_share=1, seed=seed)
        values.append(sol.radiosity)
        ks.add(sol.stats["iterations"])
    assert len(ks) == 1, "the stop rule ends every seed's solve at the same iteration"
    expected = E * sum(RHO**i for i in range(ks.pop() + 1))
    values = np.array(values)
    se = values.std(axis=0, ddof=1) / np.sqrt(len(values))
    assert (np.abs(values.mean(axis=0) - expected) < 5 * se + 1e-12).all()


def parallel_squares_form_factor():
    """From a unit square to the parallel unit square 1 m above it."""
    x = y = 1.0
    return 2 / (np.pi * x * y) * (
        np.log(np.sqrt((1 + x * x) * (1 + y * y) / (1 + x * x + y * y)))
        + x * np.sqrt(1 + y * y) * np.arctan(x / np.sqrt(1 + y * y))
        + y * np.sqrt(1 + x * x) * np.arctan(y / np.sqrt(1 + x * x))
        - x * np.arctan(x) - y * np.arctan(y))


def test_the_plates_receive_the_form_factor():
    # The first iteration's n rays from the emitter (E = 1) each land on the receiver (rho = 0.5)
    # with probability F; the black emitter sends nothing back, so the receiver's B is
    # rho E hits / n: mean rho E F, standard error rho E sqrt(F (1 - F) / n). Within 4 of them:
    # a false alarm in 1 run in 16,000.
    sol = hmcr.solve(hmcr.load_scene("plates"), rays=200_000, max_depth=0, refine_share=1,
                     seed=5)
    f, n = parallel_squares_form_factor(), sol.stats["iteration_rays"][0]
    receiver = sol.radiosity[np.argmin(sol.radiosity[:, 0])]
    se = RHO * E * np.sqrt(f * (1 - f) / n)
    assert (np.abs(receiver - RHO * E * f) < 4 * se).all(), (receiver, RHO * E * f, se)


def test_write_vtp_gives_the_command_lines_bytes(tmp_path):
    args = ["--rays", "30000", "--seed", "7", "--oracle", "power"]
    cli = tmp_path / "cli.vtp"
    subprocess.run([os.environ["HMCR_BINARY"], "solve", "cornell", *args, "-q", "-o", str(cli)],
                   check=True, cwd=tmp_path)
    sol = hmcr.solve(hmcr.load_scene("cornell"), rays=30_000, seed=7, oracle="power")
    py = tmp_path / "py.vtp"
    sol.write_vtp(str(py))
    assert py.read_bytes() == cli.read_bytes()


def test_the_same_bits_on_one_and_two_threads():
    scene = hmcr.load_scene("cornell")
    one = hmcr.solve(scene, rays=30_000, threads=1)
    two = hmcr.solve(scene, rays=30_000, threads=2)
    assert np.array_equal(one.radiosity, two.radiosity)
    assert np.array_equal(one.point_radiosity, two.point_radiosity)


def test_a_solve_leaves_pythons_floating_point_mode_alone():
    hmcr.solve(furnace(), rays=20_000)
    assert np.float64(5e-324) / 2 == 0 and np.float64(5e-324) > 0  # subnormals are not flushed
    assert np.finfo(np.float64).smallest_subnormal > 0


def test_a_scene_solves_again_unchanged():
    scene = hmcr.load_scene("cornell")
    first = hmcr.solve(scene, rays=20_000)
    again = hmcr.solve(scene, rays=20_000)
    assert scene.patch_count == 24
    assert np.array_equal(first.radiosity, again.radiosity)


def test_arrays_are_the_leaves_polygons():
    sol = hmcr.solve(hmcr.load_scene("cornell"), rays=20_000)
    cells = len(sol.offsets) - 1
    assert cells == sol.stats["faces"] == len(sol.radiosity) == len(sol.patch_id)
    assert sol.offsets[0] == 0 and sol.offsets[-1] == len(sol.connectivity)
    assert sol.connectivity.min() >= 0 and sol.connectivity.max() < len(sol.points)
    assert sol.points.shape == sol.point_radiosity.shape == (len(sol.points), 3)
    assert sol.options["rays"] == 20_000 and sol.options["oracle"] == "kl"


def test_a_higher_order_solutions_cells_are_its_leaves_sub_cells():
    sol = hmcr.solve(hmcr.load_scene("cornell"), rays=20_000, basis="quadratic")
    cells = len(sol.offsets) - 1
    assert sol.basis == "quadratic" and cells == 9 * sol.stats["faces"]
    assert len(sol.leaf_index) == cells and sol.leaf_index[-1] + 1 == sol.stats["faces"]
    assert sol.coefficients.shape == (cells, 6, 3)
    assert np.array_equal(sol.coefficients[:, 0, :], sol.radiosity)
    assert sol.leaf_coordinates.shape == (len(sol.points), 2)
    constant = hmcr.solve(hmcr.load_scene("cornell"), rays=20_000)
    assert constant.basis == "constant" and constant.leaf_index is None


@pytest.mark.parametrize("keywords, flags", [
    ({"rays": 0}, ["--rays", "0"]),
    ({"oracle": "foo"}, ["--oracle", "foo"]),
    ({"min_area": 2}, ["--min-area", "2"]),
])
def test_a_bad_setting_is_the_command_lines_error(tmp_path, keywords, flags):
    run = subprocess.run([os.environ["HMCR_BINARY"], "solve", "cornell", *flags, "-q", "-o",
                          str(tmp_path / "x.vtp")], capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 2
    with pytest.raises(hmcr.InputError) as error:
        hmcr.solve(hmcr.load_scene("cornell"), **keywords)
    assert run.stderr.strip() == "hmcr: error: " + str(error.value)


def test_unknown_settings_and_bad_arrays_are_refused():
    with pytest.raises(hmcr.InputError, match="unknown setting 'ray'"):
        hmcr.solve(furnace(), ray=10)
    v, faces = inward_box()
    with pytest.raises(hmcr.InputError, match=r"^<arrays>: face 2: corner 9 is not a vertex"):
        hmcr.scene_from_arrays(v, [faces[0], [0, 1, 9]], [0.5] * 3, [1.0] * 3)
    with pytest.raises(hmcr.InputError, match="reflectance must be 3 values"):
        hmcr.scene_from_arrays(v, faces, [0.5] * 2, [1.0] * 3)


def test_settings_come_from_the_one_table():
    names = [s["name"] for s in hmcr.settings()]
    assert "rays" in names and "oracle" in names and "clustering" in names
    rays = next(s for s in hmcr.settings() if s["name"] == "rays")
    assert rays["default"] == 2_684_000 and rays["scope"] == "scene_file"


def test_progress_is_told_and_an_exception_there_stops_the_solve():
    seen = []
    hmcr.solve(furnace(), rays=20_000, progress=lambda stage, f: seen.append(f))
    assert seen and max(seen) <= 1

    def interrupt(stage, fraction):
        if fraction > 0:
            raise KeyboardInterrupt

    scene = furnace()
    with pytest.raises(KeyboardInterrupt):
        hmcr.solve(scene, rays=2_000_000, progress=interrupt)
    # The scene is whole after the interrupted solve.
    assert hmcr.solve(scene, rays=20_000, max_depth=0).stats["leaves"] == 6


def read_pfm(path):
    """A colour PFM as hmcr writes it: little-endian floats, the bottom row first."""
    data = path.read_bytes()
    header, rest = data.split(b"\n", 3)[:3], data.split(b"\n", 3)[3]
    width, height = map(int, header[1].split())
    assert header[0] == b"PF" and float(header[2]) < 0
    return np.frombuffer(rest, dtype="<f4").reshape(height, width, 3)[::-1]


def test_error_and_render_are_the_command_lines(tmp_path):
    binary = os.environ["HMCR_BINARY"]

    def cli(*args):
        subprocess.run([binary, *args, "-q"], check=True, cwd=tmp_path)

    cli("reference", "plates", "--kind", "mesh", "--rays", "200000", "-o", "ref")
    cli("solve", "plates", "--rays", "50000", "-o", "sol.vtp")
    cli("error", "sol.vtp", "--reference", "ref", "-o", "error.json")
    cli("render", "sol.vtp", "--scene", "plates", "-o", "sol.png", "--pfm", "sol.pfm")
    scene = hmcr.load_scene("plates")
    sol = hmcr.solve(scene, rays=50_000)
    measured = hmcr.error(sol, str(tmp_path / "ref"), scene)
    expected = json.loads((tmp_path / "error.json").read_text())
    for key in ["object_error", "finer_share", "views", "samples_per_axis"]:
        assert measured[key] == expected[key], key
    assert measured["object_error"]["relative_l2"] > 0
    image = sol.render(scene)
    assert np.array_equal(image.astype(np.float32), read_pfm(tmp_path / "sol.pfm"))
    with pytest.raises(hmcr.InputError, match="not of 'cornell'"):
        sol.render(hmcr.load_scene("cornell"))


def test_views_from_arrays_are_checked_as_a_scene_files():
    v, faces = inward_box()
    view = {"name": "corner", "position": [0.9, 0.9, 0.9], "look_at": [0.1, 0.1, 0.1],
            "width": 32, "height": 24}
    scene = hmcr.scene_from_arrays(v, faces, [RHO] * 3, [E] * 3, sides=1, views=[view])
    assert scene.views == ["corner"]
    image = hmcr.solve(scene, rays=20_000).render(scene, "corner")
    assert image.shape == (24, 32, 3) and (image > 0).all()
    with pytest.raises(hmcr.InputError, match=r"^<arrays>: views\[0\] \('up'\): up is parallel"):
        hmcr.scene_from_arrays(v, faces, [RHO] * 3, [E] * 3, views=[
            {"name": "up", "position": [0.5, 0.5, 0.1], "look_at": [0.5, 0.5, 0.9],
             "up": [0, 0, 1]}])


def test_ctrl_c_stops_a_solve():
    # SIGINT while hmcr works: Python's handler only notes it, and the solve raises
    # KeyboardInterrupt at its next ray batch. 10^9 rays would take minutes.
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        hmcr.solve(furnace(), rays=1_000_000_000, threads=1)
    timer.join()
    assert time.monotonic() - started < 30


def test_the_gil_is_released_while_hmcr_works():
    # Another Python thread wakes every millisecond while a solve shoots. Held by the solve, the
    # GIL would keep it asleep until the solve returned (hmcr runs no Python in between); released,
    # it wakes about once a millisecond of the solve's.
    wakes, done = [0], threading.Event()

    def wake():
        while not done.is_set():
            time.sleep(0.001)
            wakes[0] += 1

    waker = threading.Thread(target=wake)
    waker.start()
    time.sleep(0.05)
    before, started = wakes[0], time.monotonic()
    hmcr.solve(furnace(), rays=3_000_000, threads=1)
    during, seconds = wakes[0] - before, time.monotonic() - started
    done.set()
    waker.join()
    assert seconds > 0.1, "a solve long enough to tell"
    assert during > 20, (during, seconds)


def test_a_meshing_study_is_the_command_lines(tmp_path):
    binary = os.environ["HMCR_BINARY"]
    subprocess.run([binary, "reference", "plates", "--kind", "mesh", "--rays", "200000", "-o",
                    "ref", "-q"], check=True, cwd=tmp_path)
    subprocess.run([binary, "study", "plates", "--reference", "ref", "--budgets", "8,32",
                    "--oracles", "power,kl", "--seeds", "2", "--rays", "20000", "-o", "cli", "-q"],
                   check=True, cwd=tmp_path)
    rows = hmcr.meshing_study(hmcr.load_scene("plates"), tmp_path / "ref", [8, 32],
                              tmp_path / "py", oracles=["power", "kl"], seeds=2, rays=20_000)
    assert len(rows) == 8
    assert all(not isinstance(v, (dict, list)) for row in rows for v in row.values())
    cli = json.loads((tmp_path / "cli" / "table.json").read_text())["cells"]
    untimed = lambda cell: {k: v for k, v in cell.items() if k not in ("seconds", "probe_history")}
    assert [untimed(c) for c in cli] == \
        [untimed(c) for c in json.loads((tmp_path / "py" / "table.json").read_text())["cells"]]
    row = next(r for r in rows if r["oracle"] == "kl" and r["budget"] == 32 and r["seed"] == 1)
    cell = next(c for c in cli if c["oracle"] == "kl" and c["budget"] == 32 and c["seed"] == 1)
    assert row["leaves"] == cell["leaves"]
    assert row["object_error"] == cell["object_error"]["relative_l2"]
    assert row["rmse_a_side"] == cell["views"]["side"]["rmse_a"]
    with pytest.raises(hmcr.InputError, match="oracle is set per cell"):
        hmcr.meshing_study(hmcr.load_scene("plates"), tmp_path / "ref", [8], tmp_path / "x",
                           oracle="kl")


def test_a_mesh_reference_is_the_command_lines(tmp_path):
    subprocess.run([os.environ["HMCR_BINARY"], "reference", "plates", "--kind", "mesh", "--rays",
                    "200000", "-o", "cli", "-q"], check=True, cwd=tmp_path)
    said = hmcr.mesh_reference(hmcr.load_scene("plates"), str(tmp_path / "py"), rays=200_000)
    assert said["leaves"] == 2 * 4**7  # two unit squares halved until an element is <= 1e-4 m^2
    cli, py = tmp_path / "cli", tmp_path / "py"
    assert (py / "reference.vtp").read_bytes() == (cli / "reference.vtp").read_bytes()
    images = sorted(p.relative_to(cli) for p in (cli / "views").rglob("*") if p.is_file())
    assert images and images == sorted(p.relative_to(py) for p in (py / "views").rglob("*")
                                       if p.is_file())
    for image in images:
        assert (py / image).read_bytes() == (cli / image).read_bytes(), image
    with pytest.raises(hmcr.InputError, match="oracle is not a reference's setting"):
        hmcr.mesh_reference(hmcr.load_scene("plates"), str(tmp_path / "x"), oracle="kl")


def test_information_and_trace_are_the_command_lines(tmp_path):
    binary = os.environ["HMCR_BINARY"]

    def cli(*args):
        return subprocess.run([binary, *args], check=True, cwd=tmp_path, capture_output=True,
                              text=True).stdout

    scene = hmcr.load_scene("cornell")
    shared = ("h_p", "h_s", "i_s", "h_j", "i_cs", "discretisation_error", "lines", "samples")
    patches = json.loads(cli("info", "cornell", "--json", "--lines", "100000"))
    measured = hmcr.information(scene, lines=100_000)
    for key in shared:
        assert measured[key] == patches[key], key
    cli("solve", "cornell", "--rays", "30000", "-q", "-o", "sol.vtp")
    leaves = json.loads(cli("info", "sol.vtp", "--json", "--lines", "100000"))
    assert hmcr.solve(scene, rays=30_000).information(lines=100_000)["i_s"] == leaves["i_s"]
    cli("trace", "cornell", "--spp", "4", "--width", "64", "-q", "-o", "t.png", "--pfm", "t.pfm")
    traced = hmcr.trace(scene, spp=4, width=64)
    assert np.array_equal(traced["image"].astype(np.float32), read_pfm(tmp_path / "t.pfm"))
    assert traced["samples"].shape == traced["image"].shape[:2] and (traced["samples"] == 4).all()
    with pytest.raises(hmcr.InputError, match=r"unknown sampler 'nope' \(valid: "):
        hmcr.trace(scene, sampler="nope")


def test_a_points_reference_and_a_sampling_study_are_the_command_lines(tmp_path):
    binary = os.environ["HMCR_BINARY"]

    def cli(*args):
        subprocess.run([binary, *args, "-q"], check=True, cwd=tmp_path)

    cli("reference", "plates", "--kind", "points", "--points", "2000", "--paths", "16", "--spp",
        "4", "-o", "cli-ref")
    scene = hmcr.load_scene("plates")
    said = hmcr.points_reference(scene, str(tmp_path / "py-ref"), points=2000, paths=16, spp=4)
    assert said["points"] > 0 and said["noise"] > 0
    assert (tmp_path / "py-ref" / "points.vtp").read_bytes() == \
        (tmp_path / "cli-ref" / "points.vtp").read_bytes()
    cli("study", "plates", "--reference", "cli-ref", "--samplers", "uniform,srhe", "--spp", "10",
        "--seeds", "1", "-o", "cli-study")
    rows = hmcr.sampling_study(scene, tmp_path / "cli-ref", tmp_path / "py-study",
                               samplers=["uniform", "srhe"], spps=[10], seeds=1)
    assert len(rows) == 2
    assert all(not isinstance(v, (dict, list)) for row in rows for v in row.values())
    untimed = lambda views: {name: {k: v for k, v in view.items() if k != "seconds"}
                             for name, view in views.items()}
    for row, cell in zip(rows, json.loads((tmp_path / "cli-study" / "table.json").read_text())
                         ["cells"]):
        assert row["sampler"] == cell["sampler"] and row["spp"] == cell["spp"]
        assert row["rmse_a_side"] == cell["views"]["side"]["errors"]["rmse_a"]
    py_cells = json.loads((tmp_path / "py-study" / "table.json").read_text())["cells"]
    cli_cells = json.loads((tmp_path / "cli-study" / "table.json").read_text())["cells"]
    assert [untimed(c["views"]) for c in py_cells] == [untimed(c["views"]) for c in cli_cells]
