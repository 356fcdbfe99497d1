"""Input variants (dtypes, memory order, lists) and bad input (ValueError with the CLI's message)."""
import numpy as np
import pytest

import hlens
from conftest import run_cli, write_obj

# A unit right triangle and the same triangle one unit above: every distance is exactly 1.
V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float64)
W = V + [0, 0, 1]
F = np.array([[0, 1, 2]])


def reference(VA, FA, VB, FB):
    return hlens.distance(VA, FA, VB, FB, threads=1).to_dict()


@pytest.mark.parametrize("dtype", [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64])
def test_any_integer_dtype_for_triangles(demo, dtype):
    VA, FA, VB, FB = demo
    if np.iinfo(dtype).max < len(VA):  # too small for the demo's indices: the unit triangles
        assert hlens.distance(V, F.astype(dtype), W, F.astype(dtype), threads=1).hausdorff == 1.0
        return
    want = reference(VA, FA, VB, FB)
    got = hlens.distance(VA, FA.astype(dtype), VB, FB.astype(dtype), threads=1).to_dict()
    assert got["a_to_b"]["distance"] == want["a_to_b"]["distance"] and got["hausdorff"] == want["hausdorff"]


@pytest.mark.parametrize("dtype", [np.float16, np.float32, np.longdouble, np.int32, np.int64, np.uint16])
def test_any_real_dtype_for_vertices(dtype):
    # the values are exact in every dtype, so the result is the float64 one, and here exactly 1
    r = hlens.distance(V.astype(dtype), F, W.astype(dtype), F, threads=1)
    assert r.hausdorff == 1.0 and r.a_to_b.distance == 1.0


def test_float32_input_equals_its_float64_values(demo):
    VA, FA, VB, FB = demo
    VA32, VB32 = VA.astype(np.float32), VB.astype(np.float32)
    a = hlens.distance(VA32, FA, VB32, FB, threads=1).to_dict()
    b = hlens.distance(VA32.astype(np.float64), FA, VB32.astype(np.float64), FB, threads=1).to_dict()
    a.pop("seconds"), b.pop("seconds")
    for d in (a, b):
        for k in ("a_to_b", "b_to_a"):
            d[k].pop("seconds")
    assert a == b


def test_fortran_order_lists_and_slices(demo):
    VA, FA, VB, FB = demo
    want = reference(VA, FA, VB, FB)["hausdorff"]
    assert hlens.distance(np.asfortranarray(VA), np.asfortranarray(FA), VB, FB, threads=1).hausdorff == want
    assert hlens.distance(VA.tolist(), FA.tolist(), VB.tolist(), FB.tolist(), threads=1).hausdorff == want
    wide = np.zeros((len(VA), 6))
    wide[:, ::2] = VA  # a strided view
    assert hlens.distance(wide[:, ::2], FA, VB, FB, threads=1).hausdorff == want


@pytest.mark.parametrize("VA,FA,message", [
    (V[:, :2], F, "A: vertices must have shape (n, 3), got shape (3, 2)"),
    (V, F.ravel(), "A: triangles must have shape (n, 3), got shape (3,)"),
    (V, np.zeros((0, 3), dtype=int), "A: no triangles"),
    (V, [], "A: no triangles"),
    (V, [[0, 1, 3]], "A: triangle 0: vertex index 3 out of range (3 vertices)"),
    (V, [[0, 1, 2], [0, -1, 2]], "A: triangle 1: vertex index -1 out of range (3 vertices)"),
    (V, np.array([[0, 1, 2**40]], dtype=np.int64), "A: triangle 0: vertex index 1099511627776 out of range (3 vertices)"),
    (V, F.astype(float), "A: triangles must be integer vertex indices, got dtype float64"),
    ([[0, 0, 0], [1, 0, float("nan")], [0, 1, 0]], F, "A: vertex 1 has a NaN or infinite coordinate"),
    ([[0, 0, 0], [1, 0, float("inf")], [0, 1, 0]], F, "A: vertex 1 has a NaN or infinite coordinate"),
    (V.astype(complex), F, "A: vertices must be real numbers, got dtype complex128"),
    ([["a", "b", "c"]] * 3, F, "A: vertices must be real numbers, got dtype <U1"),
])
def test_bad_input_raises_value_error(VA, FA, message):
    with pytest.raises(ValueError) as e:
        hlens.distance(VA, FA, W, F)
    assert str(e.value) == message


def test_bad_b_is_named_b():
    with pytest.raises(ValueError, match=r"^B: triangle 0: vertex index 5 out of range \(3 vertices\)$"):
        hlens.distance(V, F, W, [[0, 1, 5]])


def test_nan_on_an_unused_vertex_is_fine():
    # only vertices used by a triangle belong to the surface (as in files)
    r = hlens.distance(np.vstack([V, [np.nan] * 3]), F, W, F, threads=1)
    assert r.hausdorff == 1.0


def test_bad_options():
    with pytest.raises(ValueError, match="unknown mode 'exact'"):
        hlens.distance(V, F, W, F, mode="exact")
    with pytest.raises(ValueError, match="threads must be between"):
        hlens.distance(V, F, W, F, threads=-1)
    with pytest.raises(ValueError, match="tolerance needs a number, got 'nan'"):
        hlens.distance(V, F, W, F, tolerance=float("nan"))


@pytest.mark.parametrize("name,content", [
    ("missing.obj", None),
    ("empty.obj", ""),
    ("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n"),
    ("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
    ("bad.xyz", "1 2 3\n"),
])
def test_load_errors_have_the_cli_message(tmp_path, name, content):
    p = tmp_path / name
    if content is not None:
        p.write_text(content)
    good = write_obj(tmp_path / "good.obj", V, F)
    code, out, err = run_cli("distance", p, good)
    assert code == 2 and err.startswith("hlens-cli: ")
    with pytest.raises(ValueError) as e:
        hlens.load(p)
    assert str(e.value) == err[len("hlens-cli: "):].rstrip("\n")
