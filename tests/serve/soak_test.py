"""1,000 mixed requests against one `lightpath serve`: valid ones, refused ones and raw garbage on
the socket. Afterwards the server must still answer correctly, and its resident memory must not
have grown by more than a bound after the warm-up (a leak of one small render per request would
exceed it several times over). Bounded in count and time; loopback only."""
import argparse
import json
import random
import socket
import struct
import sys
import time

sys.path.insert(0, __import__("os").path.dirname(__file__))
from serve_process import ServeProcess  # noqa: E402

REQUESTS = 1000
WARM_UP = 200
GROWTH_LIMIT_KIB = 48 * 1024
TIME_LIMIT = 240.0

parser = argparse.ArgumentParser()
parser.add_argument("--lightpath", required=True)
parser.add_argument("--scene", required=True)
args = parser.parse_args()
rng = random.Random(18)


def raw(port, data, read_limit=10.0):
    """Sends bytes as they are and returns what comes back before the server closes or times out."""
    with socket.create_connection(("127.0.0.1", port), timeout=read_limit) as s:
        try:
            s.sendall(data)
            s.shutdown(socket.SHUT_WR)
            chunks = []
            while True:
                chunk = s.recv(65536)
                if not chunk:
                    break
                chunks.append(chunk)
            return b"".join(chunks)
        except (ConnectionResetError, BrokenPipeError):
            return b""


def settings():
    integrator = rng.choice(["raycast", "whitted", "path"])
    sets = [[{"name": "direct", "expression": "E(D|G)L"}],
            [{"name": "a", "expression": "E.*<L'lamp'>"}, {"name": "b", "expression": "E.*B"}]]
    if integrator != "raycast":  # ray casting follows no mirror: the one judge refuses this (400)
        sets.append([{"name": "mirror", "expression": "E<RS>+.*"}])
    return json.dumps({"width": rng.randint(16, 48), "height": rng.randint(12, 36), "spp": rng.randint(1, 8),
                       "integrator": integrator, "lpes": rng.choice(sets)})


def garbage():
    kind = rng.randrange(5)
    if kind == 0:
        return bytes(rng.randrange(256) for _ in range(rng.randint(1, 2000)))
    if kind == 1:
        return b"GET /" + b"A" * 20000 + b" HTTP/1.1\r\nHost: x\r\n\r\n"
    if kind == 2:
        return b"PUT /api/settings HTTP/1.1\r\nHost: x\r\nContent-Length: 99999999999999999999\r\n\r\n{"
    if kind == 3:
        return b"GET /api/settings HTTP/1.1\r\n" + b"X-Junk: " + b"z" * 50000 + b"\r\n\r\n"
    return b"POST /api/settings HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\nzz\r\n" + struct.pack("<Q", rng.getrandbits(64))


# (kind, method, path, body, accepted statuses)
def next_request():
    roll = rng.random()
    if roll < 0.10:
        return ("garbage",)
    if roll < 0.30:
        return ("http", "PUT", "/api/settings", settings(), {200})
    if roll < 0.45:
        return ("http", "GET", f"/api/explain?x={rng.randint(0, 15)}&y={rng.randint(0, 11)}", None, {200, 409})
    if roll < 0.55:
        return ("http", "GET", "/api/image/beauty.png?exposure=0.5", None, {200, 503})
    if roll < 0.62:
        return ("http", "GET", rng.choice(["/api/progress", "/api/scene", "/api/settings", "/", "/app.js"]), None, {200})
    if roll < 0.66:
        return ("http", "GET", "/api/automaton.svg", None, {200})
    bad = [
        ("PUT", "/api/settings", '{"spp": ', {400}),
        ("PUT", "/api/settings", '{"width": 0}', {400}),
        ("PUT", "/api/settings", '{"height": 1000000000}', {400}),
        ("PUT", "/api/settings", '{"bogus": true}', {400}),
        ("PUT", "/api/settings", '{"lpes": [{"name": "x", "expression": "E(D|G L"}]}', {400}),
        ("PUT", "/api/settings", '{"integrator": "raycast", "lpes": [{"name": "x", "expression": "E<RS>L"}]}', {400}),
        ("PUT", "/api/settings", " " * 100000, {413}),
        ("GET", "/../../etc/passwd", None, {404}),
        ("GET", "/api/explain?x=99999&y=0", None, {400}),
        ("GET", "/api/image/none.png", None, {404, 503}),
        ("DELETE", "/api/settings", None, {403}),  # not JSON: refused before the method is looked at
        ("DELETE", "/api/settings", "{}", {405}),
    ]
    method, path, body, statuses = rng.choice(bad)
    return ("http", method, path, body, statuses)


server = ServeProcess(args.lightpath, args.scene)
started = time.monotonic()
try:
    status, answer = server.json("PUT", "/api/settings", '{"width": 16, "height": 12, "spp": 1}')
    assert status == 200, answer
    server.wait_until_done(answer["generation"])
    failures, resident = [], {}
    for i in range(REQUESTS):
        assert time.monotonic() - started < TIME_LIMIT, f"soak took over {TIME_LIMIT} s at request {i}"
        request = next_request()
        if request[0] == "garbage":
            reply = raw(server.port, garbage())
            if reply and not reply.startswith(b"HTTP/1.1 4"):
                failures.append((i, "garbage answered with", reply[:60]))
        else:
            _, method, path, body, statuses = request
            status, _, data = server.request(method, path, body)
            if status not in statuses:
                failures.append((i, method, path, (body or "")[:60], status, data[:200]))
        assert server.process.poll() is None, f"the server died at request {i}"
        if i + 1 in (WARM_UP, 400, 600, 800, REQUESTS):
            resident[i + 1] = server.resident_kib()
    print("resident KiB after requests:", resident)
    print(f"{REQUESTS} requests in {time.monotonic() - started:.1f} s, {len(failures)} unexpected answers")
    for failure in failures[:20]:
        print("unexpected:", failure)
    assert not failures
    growth = resident[REQUESTS] - resident[WARM_UP]
    assert growth < GROWTH_LIMIT_KIB, f"resident memory grew by {growth} KiB after the warm-up"

    # Still correct: a fresh render, its layers, an explanation.
    status, answer = server.json("PUT", "/api/settings", '{"width": 32, "height": 24, "spp": 1, "integrator": "whitted", '
                                                         '"lpes": [{"name": "mirror", "expression": "E<RS>+.*"}]}')
    assert status == 200, answer
    done = server.wait_until_done(answer["generation"])
    assert done["layers"] == ["beauty", "mirror", "rest"], done["layers"]
    assert done["sumError"] < 1e-5, done["sumError"]
    status, headers, png = server.request("GET", "/api/image/mirror.png")
    assert status == 200 and png[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">II", png[16:24]) == (32, 24)
    status, explanation = server.json("GET", "/api/explain?x=16&y=12")
    assert status == 200 and explanation["pixel"] == [16, 12], explanation
finally:
    server.stop()
print("soak: ok")
