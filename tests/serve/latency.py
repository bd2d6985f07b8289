"""How long the page waits: from starting `lightpath serve` to its first image, and from an edit
(PUT /api/settings) to the first pass of the new render, medians over alternating edits. Prints
figures; not a test (the machine's load decides them).

    latency.py --lightpath build/lightpath --scene scenes/lecture-room.toml [--edits 10]
"""
import argparse
import json
import os
import platform
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from serve_process import ServeProcess  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--lightpath", required=True)
parser.add_argument("--scene", required=True)
parser.add_argument("--edits", type=int, default=10)
args = parser.parse_args()


def first_pass(server, generation):
    while True:
        status, p = server.json("GET", f"/api/progress?wait=10&generation={generation}&pass=0")
        if p["generation"] == generation and p["passes"] >= 1:
            return p


started = time.monotonic()
server = ServeProcess(args.lightpath, args.scene)
try:
    printed = time.monotonic() - started
    first_pass(server, 1)
    first_image = time.monotonic() - started
    edits = {"lpe": [], "integrator": []}
    sets = [[{"name": "key", "expression": "E.*<L'key'>"}], [{"name": "direct", "expression": "E(D|G)L"}]]
    for i in range(args.edits):
        for kind in edits:
            body = {"lpes": sets[i % 2]} if kind == "lpe" else {"integrator": ["raycast", "whitted"][i % 2]}
            t = time.monotonic()
            status, answer = server.json("PUT", "/api/settings", json.dumps(body))
            assert status == 200, answer
            p = first_pass(server, answer["generation"])
            edits[kind].append(time.monotonic() - t)
    s = p["settings"]
    print(f"machine: {platform.node()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    print(f"scene {args.scene} at {s['width']}x{s['height']}")
    print(f"start to URL printed: {printed:.3f} s; start to first image: {first_image:.3f} s")
    for kind, times in edits.items():
        print(f"edit ({kind}) to first pass: median {statistics.median(times):.3f} s, "
              f"min {min(times):.3f} s, max {max(times):.3f} s over {len(times)}")
finally:
    server.stop()
