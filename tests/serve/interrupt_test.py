"""Ctrl-C stops `lightpath serve` cleanly within a second, even with a long render in flight and
a long poll waiting: exit code 0, the line "stopped" printed. SIGTERM does the same. However the
server ends (Ctrl-C, SIGTERM, SIGKILL), it leaves nothing in the temporary folder: it serves
PNGs and EXRs from memory and never makes a folder there, so none can be orphaned (each run gets
its own empty TMPDIR, which must still be empty while serving and after the end)."""
import argparse
import os
import signal
import sys
import tempfile
import threading
import time

sys.path.insert(0, __import__("os").path.dirname(__file__))
from serve_process import ServeProcess  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--lightpath", required=True)
parser.add_argument("--scene", required=True)
args = parser.parse_args()


def serve_images(server):
    """A PNG of a layer and the EXR, once the first pass is there."""
    status, answer = server.json("PUT", "/api/settings", '{"integrator": "whitted", "spp": 1, "width": 32, "height": 24}')
    assert status == 200, answer
    server.wait_until_done(answer["generation"])
    for path, magic in (("/api/image/beauty.png", b"\x89PNG"), ("/api/render.exr", b"\x76\x2f\x31\x01")):
        status, _, data = server.request("GET", path)
        assert status == 200 and data.startswith(magic), (path, status, data[:80])


def interrupt(sig, tmpdir):
    env = dict(os.environ, TMPDIR=tmpdir)
    server = ServeProcess(args.lightpath, args.scene, env=env)
    try:
        status, _, page = server.request("GET", "/")
        assert status == 200 and b"<script" in page, status
        serve_images(server)
        assert os.listdir(tmpdir) == [], f"while serving, the temporary folder holds {os.listdir(tmpdir)}"
        # A render of hours, and a client waiting in a long poll for its next pass.
        status, answer = server.json("PUT", "/api/settings", '{"integrator": "path", "spp": 4096, "width": 1024, "height": 768}')
        assert status == 200, answer
        generation = answer["generation"]
        poll = threading.Thread(target=lambda: server.request("GET", f"/api/progress?wait=10&generation={generation}&pass=100"),
                                daemon=True)
        poll.start()
        # Interrupt once that render is under way (its first pass published, or a long poll answered).
        server.json("GET", f"/api/progress?wait=10&generation={generation}&pass=-1")

        started = time.monotonic()
        server.process.send_signal(sig)
        code = server.process.wait(timeout=30)
        elapsed = time.monotonic() - started
        rest = server.process.stdout.read()
        name = signal.Signals(sig).name
        print(f"{name}: stopped in {elapsed:.3f} s with exit code {code}; output: {rest.strip()!r}")
        if sig == signal.SIGKILL:
            assert code == -signal.SIGKILL, f"exit code {code}"
        else:
            assert code == 0, f"exit code {code}"
            assert "lightpath serve: stopped" in rest, rest
            assert elapsed < 1.0, f"{name} took {elapsed:.3f} s, more than a second"
    finally:
        server.stop()
    assert os.listdir(tmpdir) == [], f"after {signal.Signals(sig).name}, the temporary folder holds {os.listdir(tmpdir)}"


for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGKILL):
    with tempfile.TemporaryDirectory(prefix="lightpath-interrupt-") as tmpdir:
        interrupt(sig, tmpdir)
print("interrupt: ok")
