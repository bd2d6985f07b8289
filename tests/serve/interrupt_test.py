"""Ctrl-C stops `lightpath serve` cleanly within a second, even with a long render in flight and
a long poll waiting: exit code 0, the line "stopped" printed."""
import argparse
import signal
import sys
import threading
import time

sys.path.insert(0, __import__("os").path.dirname(__file__))
from serve_process import ServeProcess, read_line  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--lightpath", required=True)
parser.add_argument("--scene", required=True)
args = parser.parse_args()

server = ServeProcess(args.lightpath, args.scene)
try:
    status, _, page = server.request("GET", "/")
    assert status == 200 and b"<script" in page, status
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
    server.process.send_signal(signal.SIGINT)
    code = server.process.wait(timeout=30)
    elapsed = time.monotonic() - started
    rest = server.process.stdout.read()
    print(f"stopped in {elapsed:.3f} s with exit code {code}; output: {rest.strip()!r}")
    assert code == 0, f"exit code {code}"
    assert "lightpath serve: stopped" in rest, rest
    assert elapsed < 1.0, f"Ctrl-C took {elapsed:.3f} s, more than a second"
finally:
    server.stop()
print("interrupt: ok")
