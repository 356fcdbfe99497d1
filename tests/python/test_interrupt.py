"""Ctrl-C (SIGINT) stops a long computation with KeyboardInterrupt instead of hanging."""
import os
import signal
import subprocess
import sys
import time

from conftest import SHARED

SCRIPT = r"""
import sys, numpy as np, hlens
V, F = hlens.load(sys.argv[1])
W = V + np.random.default_rng(1).uniform(-1e-3, 1e-3, V.shape)
print("started", flush=True)
try:
    hlens.distance(V, F, W, F, mode="paper")   # about two minutes here
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(7)
print("finished", flush=True)
"""


def test_sigint_raises_keyboard_interrupt():
    p = subprocess.Popen([sys.executable, "-c", SCRIPT, str(SHARED / "nefertiti.obj")],
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
