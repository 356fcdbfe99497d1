"""hlens.trace() and hlens.TargetSolver against `hlens-cli trace --json`."""
import numpy as np
import pytest

import hlens
from conftest import DEMO_A, DEMO_B, cli_json


def test_trace_equals_cli_line_by_line(demo):
    VA, FA, VB, FB = demo
    cli = cli_json("trace", DEMO_B, DEMO_A, "--target", 22, "--json")
    events = hlens.trace(VB, FB, VA, FA, 22)
    assert len(events) == len(cli) and events[-1]["event"] == "final"
    for got, want in zip(events, cli):
        assert got == want  # floats from 17 digits are the same doubles


def test_target_solver_steps_to_the_same_events(demo):
    VA, FA, VB, FB = demo
    ts = hlens.TargetSolver(VB, FB, VA, FA, 22)
    first = ts.step_event()
    assert first["event"] == "target_begun" and first["step"] == 0
    steps = 0
    while ts.step():
        steps += 1
    assert ts.finished and abs(steps - ts.insertions) <= 1
    assert ts.events == hlens.trace(VB, FB, VA, FA, 22)
    assert ts.max_sq == ts.events[-1]["max_sq"] and ts.search_radius == ts.events[-1]["max"]


def test_domains_tile_the_target_and_arcs_lie_on_their_conics(demo):
    VA, FA, VB, FB = demo
    ts = hlens.TargetSolver(VB, FB, VA, FA, 22)
    for _ in range(20):
        ts.step()
    doms = ts.domains(per_arc=8)
    assert len(doms) > 1
    (ax, ay), (bx, by), (cx, cy) = ts.corners
    target_area = abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2
    assert sum(d["area"] for d in doms) == pytest.approx(target_area, rel=1e-9)
    for d in doms:
        assert set(d["poly"]) == {"a", "b", "c", "d", "e", "f", "type"}
        assert d["label"]["source"] >= 0 and d["covered"]
        for loop, arcs in zip(d["loops"], d["arcs"]):
            assert loop.shape[1] == 2 and np.allclose(loop[0], loop[-1])
            for arc in arcs:
                q, p = arc["equation"], arc["points"]
                x, y = p[:, 0], p[:, 1]
                val = q["a"] * x * x + 2 * q["b"] * x * y + q["c"] * y * y + 2 * q["d"] * x + 2 * q["e"] * y + q["f"]
                scale = max(abs(q[k]) for k in "abcdef")
                assert np.all(np.abs(val) <= 1e-7 * scale), arc["kind"]
            # consecutive arcs meet
            for a1, a2 in zip(arcs, arcs[1:] + arcs[:1]):
                assert np.allclose(a1["points"][-1], a2["points"][0], atol=1e-9)


def test_target_out_of_range(demo):
    VA, FA, VB, FB = demo
    with pytest.raises(ValueError, match=r"target 32 is out of range: A has 32 triangles \(0..31\)"):
        hlens.trace(VB, FB, VA, FA, 32)
