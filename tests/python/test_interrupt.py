"""Ctrl-C (SIGINT) stops a long computation with KeyboardInterrupt instead of hanging."""
import os
import signal
import subprocess
import sys
import time

import pytest

from conftest import SHARED

SCRIPT = r"""
import sys, numpy as np, hlens
V, F = hlens.load(sys.argv[1])
W = V + np.random.default_rng(1).uniform(-1e-3, 1e-3, V.shape)
said = []

def in_stats(f):                               # the statistics take the fractions after 0.05
    if f > 0.05 and not said:
        said.append(f)
        print("started", flush=True)

try:
    if sys.argv[2] == "stats":
        hlens.distance(V, F, W, F, stats=True, progress=in_stats)
    else:
        print("started", flush=True)
        hlens.distance(V, F, W, F, mode="paper")   # about two minutes here
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(7)
print("finished", flush=True)
"""


@pytest.mark.parametrize("what", ["paper", "stats"])
def test_sigint_raises_keyboard_interrupt(what):
    p = subprocess.Popen([sys.executable, "-c", SCRIPT, str(SHARED / "nefertiti.obj"), what],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    assert p.stdout.readline().strip() == "started"
    time.sleep(1.0)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    try:
        out, err = p.communicate(timeout=30)
    finally:
        p.kill()
    assert p.returncode == 7, err
    assert out.strip() == "interrupted"
    assert time.monotonic() - sent < 30
