"""hlens.distance() and hlens.load() against hlens-cli: the same numbers to the last bit."""
import math
import struct
import threading

import numpy as np
import pytest

import hlens
from conftest import DEMO_A, DEMO_B, SCHEDULED, SHARED, cli_json, without, write_obj


def bits(x):
    return struct.pack("<d", x)


def assert_same_report(py, cli):
    """Equal dicts, floats compared bit for bit (json reads the CLI's 17 digits back exactly)."""
    if isinstance(cli, dict):
        assert py.keys() == cli.keys()
        for k in cli:
            assert_same_report(py[k], cli[k])
    elif isinstance(cli, list):
        assert len(py) == len(cli)
        for a, b in zip(py, cli):
            assert_same_report(a, b)
    elif isinstance(cli, float) or isinstance(py, float):
        assert bits(float(py)) == bits(float(cli)), (py, cli)
    else:
        assert py == cli


@pytest.mark.parametrize("options,cli_flags", [
    ({}, []),
    ({"mode": "paper", "one_sided": True, "threads": 1}, ["--mode", "paper", "--one-sided", "--threads", "1"]),
    ({"units": "mm"}, ["--units", "mm"]),
])
def test_demo_pair_equals_cli(demo, options, cli_flags):
    V, F, W, G = demo
    r = hlens.distance(V, F, W, G, **options)
    [cli] = cli_json("distance", DEMO_A, DEMO_B, "--json", *cli_flags)
    vary = ("seconds", "threads", "path") + (() if options.get("threads") == 1 else SCHEDULED)
    assert_same_report(without(r.to_dict(), *vary), without(cli, *vary))


def test_shared_mesh_against_perturbed_copy_equals_cli(tmp_path):
    V, F = hlens.load(SHARED / "spot.obj")
    rng = np.random.default_rng(7)
    W = V + rng.uniform(-1e-3, 1e-3, V.shape)
    b = write_obj(tmp_path / "spot_moved.obj", W, F)
    r = hlens.distance(V, F, W, F)
    [cli] = cli_json("distance", SHARED / "spot.obj", b, "--json")
    vary = ("seconds", "threads", "path") + SCHEDULED
    assert_same_report(without(r.to_dict(), *vary), without(cli, *vary))
    # the attributes are the dict's values
    assert r.hausdorff == cli["hausdorff"] and r.b_to_a.upper == cli["b_to_a"]["upper"]
    assert r.a_to_b.from_point == cli["a_to_b"]["from_point"]


def test_attributes_and_arrays(demo):
    V, F, W, G = demo
    r = hlens.distance(V, F, W, G, tolerance=0.1)
    assert r.ok and r.exceeds is True and r.tolerance == 0.1 and r.units is None
    assert r.hausdorff == max(r.a_to_b.distance, r.b_to_a.distance)
    assert r.a_to_b.lower <= r.a_to_b.distance <= r.a_to_b.upper
    # the diagonal of both meshes' box together, computed here from the arrays
    both = np.vstack([V, W])
    ext = both.max(axis=0) - both.min(axis=0)
    assert r.diagonal == pytest.approx(math.sqrt(float(ext @ ext)), rel=1e-15)
    assert r.relative == r.hausdorff / r.diagonal
    tm = r.a_to_b.target_max
    assert tm.dtype == np.float64 and tm.shape == (len(F),)
    assert r.b_to_a.target_max.shape == (len(G),) and r.b_to_a.target_exact.dtype == np.bool_
    # the witness triangle's exact maximum is the distance; no triangle exceeds it
    assert r.a_to_b.target_exact[r.a_to_b.target]
    assert tm[r.a_to_b.target] == r.a_to_b.distance and tm.max() == r.a_to_b.distance
    assert hlens.distance(V, F, W, G, tolerance=0.2).exceeds is False
    one = hlens.distance(V, F, W, G, one_sided=True)
    assert one.b_to_a is None and one.hausdorff is None and "b_to_a" not in one.to_dict()


def test_load_equals_cli_vertex_count(tmp_path):
    # a duplicated vertex is merged by weld=True, kept by weld=False (as --no-weld)
    p = tmp_path / "dup.obj"
    p.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 4 5 3\n")
    V, F = hlens.load(p)
    assert V.shape == (4, 3) and F.tolist() == [[0, 1, 2], [1, 3, 2]]
    V2, F2 = hlens.load(str(p), weld=False)
    assert V2.shape == (5, 3) and F2.tolist() == [[0, 1, 2], [3, 4, 2]]


def test_progress_is_reported_from_the_calling_thread(demo):
    V, F, W, G = demo
    seen, threads = [], set()

    def progress(f):
        seen.append(f)
        threads.add(threading.get_ident())

    hlens.distance(V, F, W, G, mode="paper", threads=1, progress=progress)
    assert seen and seen[-1] == 1.0
    assert all(0 <= f <= 1 for f in seen) and seen == sorted(seen)
    assert threads == {threading.get_ident()}


def test_progress_exception_stops_the_computation(demo):
    V, F, W, G = demo

    def progress(f):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        hlens.distance(V, F, W, G, mode="paper", threads=1, progress=progress)


def test_gil_is_released(demo):
    """Another Python thread runs while distance() computes (it could not if the GIL were held)."""
    V, F, W, G = demo
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1

    t = threading.Thread(target=count)
    t.start()
    try:
        before = ticks
        r = hlens.distance(V, F, W, G, mode="paper", threads=1)
        during = ticks - before
    finally:
        done.set()
        t.join()
    assert r.seconds > 0.05 and during > 10000
