"""hlens.distance(stats=True) and hlens.batch(stats=True) against `hlens-cli distance --stats`:
the same fields and numbers to the last bit, per-triangle mean and RMS equal to the CLI's error map
(--export-errors), and the CLI's messages for bad options.

The statistics run the full construction of every triangle: the meshes here are small.
"""
import json

import numpy as np
import pytest

import hlens
from conftest import DEMO_A, DEMO_B, SCHEDULED, run_cli, without, write_obj
from test_distance import assert_same_report

DIRECTIONS = ("a_to_b", "b_to_a")


def untimed(report):
    """The report without its times (and the paths, thread count and scheduled work counters, which
    legitimately differ)."""
    r = without(report, "seconds", "threads", "path", *SCHEDULED)
    for d in DIRECTIONS:
        if d in r and "stats_seconds" in r[d]:
            r[d]["stats_seconds"] = without(r[d]["stats_seconds"], "first_pass", "percentiles")
    return r


def distance_cli(*args):
    """`hlens-cli distance ... --json`: exit code 0, or 4 when not within a tolerance."""
    code, out, err = run_cli("distance", *args, "--json")
    assert code in (0, 4) and len(out) == 1, err
    return json.loads(out[0])


def same_as_distance_cli(py, cli):
    """Python reports `exceeds` (as batch does) where `distance --tolerance` gives its verdict."""
    py, cli = untimed(py), untimed(cli)
    if "within_tolerance" in cli:
        assert py.pop("exceeds") == (not cli.pop("within_tolerance"))
    assert_same_report(py, cli)


def read_error_ply(path):
    """Per face of an --export-errors PLY: (max, mean, rms), parsed from the CLI's 17 digits."""
    lines = open(path).read().splitlines()
    nv = next(int(l.split()[2]) for l in lines if l.startswith("element vertex"))
    start = lines.index("end_header") + 1 + nv
    faces = np.array([[float(x) for x in l.split()[5:8]] for l in lines[start:]])
    return faces[:, 0], faces[:, 1], faces[:, 2]


def triangle_areas(V, F):
    V, F = np.asarray(V, dtype=np.float64), np.asarray(F)
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)


def bumpy_grid(n, size, x0, amp, seed):
    """An n x n grid of quads with random heights: a small pair with non-trivial statistics."""
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.linspace(x0, x0 + size, n + 1), np.linspace(0, size, n + 1))
    V = np.column_stack([x.ravel(), y.ravel(), amp * rng.uniform(size=x.size)])
    q = np.array([[j * (n + 1) + i for i in range(n)] for j in range(n)]).ravel()
    F = np.vstack([np.column_stack([q, q + 1, q + n + 2]), np.column_stack([q, q + n + 2, q + n + 1])])
    return V, F


@pytest.fixture(scope="module")
def grids(tmp_path_factory):
    d = tmp_path_factory.mktemp("grids")
    V, F = bumpy_grid(5, 1.0, 0.0, 0.25, 1)
    W, G = bumpy_grid(4, 1.1, -0.05, 0.3, 2)
    return V, F, write_obj(d / "ga.obj", V, F), W, G, write_obj(d / "gb.obj", W, G)


@pytest.mark.parametrize("options,cli_flags", [
    ({"stats": True}, ["--stats"]),
    ({"stats": True, "histogram": 4, "tolerance": 0.1}, ["--stats", "--histogram", 4, "--tolerance", 0.1]),
    ({"stats": True, "histogram": 1, "tolerance": 0.5, "one_sided": True, "mode": "paper", "threads": 1},
     ["--stats", "--histogram", 1, "--tolerance", 0.5, "--one-sided", "--mode", "paper", "--threads", 1]),
])
def test_demo_stats_equal_cli(demo, options, cli_flags):
    V, F, W, G = demo
    r = hlens.distance(V, F, W, G, **options)
    cli = distance_cli(DEMO_A, DEMO_B, *cli_flags)
    same_as_distance_cli(r.to_dict(), cli)
    assert r.a_to_b.mean == cli["a_to_b"]["mean"] and r.a_to_b.percentiles == cli["a_to_b"]["percentiles"]
    assert r.a_to_b.histogram == cli["a_to_b"].get("histogram")
    assert r.a_to_b.area_above == cli["a_to_b"].get("area_above")


def test_per_triangle_mean_and_rms_equal_the_cli_error_map(grids, tmp_path):
    V, F, a, W, G, b = grids
    r = hlens.distance(np.asfortranarray(V), F.astype(np.uint32), W, G, stats=True, histogram=3, tolerance=0.05)
    cli = distance_cli(a, b, "--stats", "--histogram", 3, "--tolerance", 0.05, "--export-errors", tmp_path / "err.ply")
    same_as_distance_cli(r.to_dict(), cli)
    for name, one, mesh in (("ab", r.a_to_b, (V, F)), ("ba", r.b_to_a, (W, G))):
        _, mean, rms = read_error_ply(tmp_path / f"err-{name}.ply")
        assert one.target_mean.dtype == np.float64 and one.target_mean.shape == (len(mesh[1]),)
        assert one.target_mean.tobytes() == mean.tobytes()
        assert one.target_rms.tobytes() == rms.tobytes()
        # the area-weighted per-triangle values add up to the direction's (areas computed here)
        w = triangle_areas(*mesh)
        assert (w * one.target_mean).sum() / w.sum() == pytest.approx(one.mean, rel=1e-10)
        assert np.sqrt((w * one.target_rms ** 2).sum() / w.sum()) == pytest.approx(one.rms, rel=1e-10)
        assert np.all(one.target_mean <= one.target_rms * (1 + 1e-12))


def test_without_stats_there_are_none(demo):
    V, F, W, G = demo
    r = hlens.distance(V, F, W, G)
    assert r.a_to_b.target_mean is None and r.b_to_a.target_rms is None and r.a_to_b.mean is None
    assert "mean" not in r.to_dict()["a_to_b"]


def test_progress_with_stats(demo):
    V, F, W, G = demo
    seen = []
    hlens.distance(V, F, W, G, stats=True, threads=1, progress=seen.append)
    assert seen and seen == sorted(seen) and seen[-1] == 1.0 and all(0 <= f <= 1 for f in seen)


@pytest.mark.parametrize("options,cli_flags", [
    ({"stats": True, "histogram": -3}, ["--stats", "--histogram", -3]),
    ({"stats": True, "histogram": 100001}, ["--stats", "--histogram", 100001]),
    ({"histogram": 4}, ["--histogram", 4]),
    ({"stats": True, "tolerance": -0.1}, ["--stats", "--tolerance", -0.1]),
    ({"stats": True, "tolerance": float("nan")}, ["--stats", "--tolerance", "nan"]),
    ({"stats": True, "tolerance": "abc"}, ["--stats", "--tolerance", "abc"]),
])
def test_bad_options_raise_the_cli_message(demo, options, cli_flags):
    """The CLI's message without its dashes (`--histogram` is the argument `histogram`)."""
    V, F, W, G = demo
    code, out, err = run_cli("distance", DEMO_A, DEMO_B, *cli_flags)
    assert code == 2 and out == [] and err.startswith("hlens-cli: --")
    with pytest.raises(ValueError) as e:
        hlens.distance(V, F, W, G, **options)
    assert str(e.value) == err.strip().removeprefix("hlens-cli: ").replace("--", "")
    with pytest.raises(ValueError) as e:
        hlens.batch(DEMO_A, [DEMO_B], **options)
    assert str(e.value) == err.strip().removeprefix("hlens-cli: ").replace("--", "")


def test_python_batch_stats_equal_cli(grids, tmp_path):
    """Each Result of hlens.batch(stats=True) equals its line of `hlens-cli batch --stats`, and that
    pair's `hlens-cli distance --stats`."""
    V, F, a, W, G, b = grids
    files = [b, DEMO_B, str(tmp_path / "missing.obj")]
    flags = ["--stats", "--histogram", 2, "--tolerance", 0.2]
    code, out, err = run_cli("batch", a, *files, "--json", "--jobs", 2, *flags)  # one thread per pair, as below
    assert code == 2, err                                          # the missing file
    lines = {it["index"]: it for it in map(json.loads, out[:-1])}
    got = list(hlens.batch(a, files, stats=True, histogram=2, tolerance=0.2, jobs=2))
    assert sorted(r.index for r in got) == [0, 1, 2]
    for r in got:
        if not r.ok:
            assert r.to_dict() == lines[r.index]
            continue
        assert_same_report(untimed(r.to_dict()), untimed(lines[r.index]))
        same_as_distance_cli(without(r.to_dict(), "index"), distance_cli(a, files[r.index], *flags))
        for d in (r.a_to_b, r.b_to_a):
            assert d.target_mean.shape == d.target_max.shape and len(d.histogram["area"]) == 2
