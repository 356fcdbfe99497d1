"""The README's Python example and venv set-up, run as a user would."""
import re
import subprocess
import sys
import types
from pathlib import Path

import hlens
import pytest

from conftest import SOURCE_DIR

README = (SOURCE_DIR / "README.md").read_text()


def block(marker):
    """The ```python block following `<!-- marker -->` in the README."""
    m = re.search(r"<!-- %s -->\s*```python\n(.*?)```" % re.escape(marker), README, re.S)
    assert m, marker
    return m.group(1)


def fake_pyplot(calls):
    """A stand-in for matplotlib.pyplot (not a dependency here) that records the calls."""
    plt = types.ModuleType("matplotlib.pyplot")

    def record(name):
        def f(*args, **kwargs):
            calls.append((name, args))
            return types.SimpleNamespace(set_aspect=record("set_aspect"))
        return f
    for name in ("fill", "plot", "gca", "show", "title", "savefig"):
        setattr(plt, name, record(name))
    return plt


def test_readme_example_runs(monkeypatch, capsys):
    monkeypatch.chdir(SOURCE_DIR)
    calls = []
    mpl = types.ModuleType("matplotlib")
    mpl.pyplot = fake_pyplot(calls)
    monkeypatch.setitem(sys.modules, "matplotlib", mpl)
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", mpl.pyplot)
    scope = {}
    exec(compile(block("python-example"), "README example", "exec"), scope)
    out = capsys.readouterr().out
    assert "True" in out                     # its own check: the worst triangle has the largest maximum
    r, ts = scope["r"], scope["ts"]
    assert r.hausdorff == max(r.a_to_b.distance, r.b_to_a.distance) > 0
    assert ts.finished and ts.max_sq == pytest.approx(r.b_to_a.distance ** 2, rel=1e-12)
    exec(compile(block("python-plot"), "README plot", "exec"), scope)
    fills = [c for c in calls if c[0] == "fill"]
    assert len(fills) >= len(ts.domains())


def test_venv_install_is_offline_and_works(tmp_path):
    build = Path(sys.modules["hlens"].__file__).resolve().parent.parent
    venv = tmp_path / "venv"
    subprocess.run(["bash", str(SOURCE_DIR / "scripts" / "python-venv.sh"), str(venv), str(build)], check=True,
                   capture_output=True)
    p = subprocess.run([str(venv / "bin" / "python"), "-c", "import hlens, numpy; print(hlens.load.__doc__.split()[0])"],
                       capture_output=True, text=True, env={"PATH": "/usr/bin:/bin"})
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith("load(path")


def test_readme_stats_example_runs(monkeypatch, capsys):
    monkeypatch.chdir(SOURCE_DIR)
    scope = {}
    exec(compile(block("python-stats"), "README stats example", "exec"), scope)
    out = capsys.readouterr().out
    ab, t = scope["ab"], scope["t"]
    assert "mean " in out and "% of A's area is farther than 0.1" in out
    assert sum(ab.histogram["area"]) == pytest.approx(ab.area, rel=1e-12)
    assert 0 < ab.fraction_above < 1 and ab.mean <= ab.rms <= ab.distance
    assert ab.target_mean[t] == ab.target_mean.max() <= ab.target_rms[t] <= ab.target_max[t] * (1 + 1e-12)
