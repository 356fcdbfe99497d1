"""`hlens-cli batch` and hlens.batch(): a folder with a corrupt file, results as each pair ends."""
import json
import shutil

import numpy as np
import pytest

import hlens
from conftest import DEMO_A, DEMO_B, SCHEDULED, SHARED, cli_json, run_cli, without, write_obj


@pytest.fixture
def folder(tmp_path):
    """demo_b, a corrupt file, demo_a itself (distance 0) and a missing file."""
    shutil.copy(DEMO_B, tmp_path / "0_demo_b.obj")
    (tmp_path / "1_corrupt.ply").write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 99\n")
    shutil.copy(DEMO_A, tmp_path / "2_same.obj")
    files = [str(tmp_path / n) for n in ("0_demo_b.obj", "1_corrupt.ply", "2_same.obj", "3_missing.stl")]
    return files


def parse(out):
    lines = [json.loads(l) for l in out]
    return lines[:-1], lines[-1]["summary"]


@pytest.mark.parametrize("jobs", [1, 2])
def test_cli_batch_reports_the_failures_and_finishes_the_rest(folder, jobs):
    code, out, err = run_cli("batch", DEMO_A, *folder, "--json", "--jobs", jobs)
    assert code == 2, err
    items, summary = parse(out)
    by_index = {it["index"]: it for it in items}
    assert sorted(by_index) == [0, 1, 2, 3]
    assert "truncated" in by_index[1]["error"] or "PLY" in by_index[1]["error"]
    assert by_index[1]["path"] == folder[1] and by_index[1]["error"].startswith(folder[1] + ": ")
    assert by_index[3]["error"] == folder[3] + ": file not found"
    # each pair equals `distance` on the same files
    [single] = cli_json("distance", DEMO_A, folder[0], "--json")
    assert without(by_index[0], "seconds", "threads", "index", *SCHEDULED) == without(single, "seconds", "threads", *SCHEDULED)
    assert by_index[2]["hausdorff"] < 1e-12
    assert summary["files"] == 4 and summary["compared"] == 2 and summary["failed"] == 2
    assert summary["largest"] == single["hausdorff"] and summary["largest_path"] == folder[0]


def test_cli_batch_tolerance_exit_codes(folder):
    good = [folder[0], folder[2]]
    h = cli_json("distance", DEMO_A, folder[0], "--json")[0]["hausdorff"]
    code, out, _ = run_cli("batch", DEMO_A, *good, "--json", "--tolerance", h)
    assert code == 0 and parse(out)[1]["exceeding"] == 0          # equal is not beyond
    code, out, _ = run_cli("batch", DEMO_A, *good, "--json", "--tolerance", h * 0.999)
    items, summary = parse(out)
    assert code == 4 and summary["exceeding"] == 1
    assert {it["index"]: it["exceeds"] for it in items} == {0: True, 1: False}
    code, _, _ = run_cli("batch", DEMO_A, *folder, "--tolerance", h * 0.999)
    assert code == 2                                               # a failed file wins over 4


def test_cli_batch_usage_errors(tmp_path):
    assert run_cli("batch", DEMO_A)[0] == 2
    assert run_cli("batch", tmp_path / "nope.obj", DEMO_B)[2] == f"hlens-cli: {tmp_path / 'nope.obj'}: file not found\n"
    assert run_cli("batch", DEMO_A, DEMO_B, "--tolerance", "-1")[0] == 2
    assert run_cli("batch", DEMO_A, DEMO_B, "--jobs", "0")[0] == 2


def test_python_batch_equals_cli(folder):
    code, out, _ = run_cli("batch", DEMO_A, *folder, "--json", "--tolerance", "0.1", "--units", "mm")
    cli = {it["index"]: it for it in parse(out)[0]}
    got = list(hlens.batch(DEMO_A, folder, tolerance=0.1, jobs=2, units="mm"))
    assert sorted(r.index for r in got) == [0, 1, 2, 3]
    for r in got:
        assert r.path == folder[r.index]
        assert r.ok == ("error" not in cli[r.index])
        assert without(r.to_dict(), "seconds", "threads", *SCHEDULED) == without(cli[r.index], "seconds", "threads", *SCHEDULED)
    assert [r.exceeds for r in sorted(got, key=lambda r: r.index) if r.ok] == [True, False]


def test_python_batch_bad_reference(tmp_path):
    with pytest.raises(ValueError, match="file not found"):
        hlens.batch(tmp_path / "nope.obj", [DEMO_B])
