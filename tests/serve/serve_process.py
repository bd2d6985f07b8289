"""Starts `lightpath serve` on a free loopback port for the script tests and waits for the line
that names its URL (an event, never a fixed sleep). Standard library only."""
import json
import os
import re
import select
import subprocess
import time
import urllib.error
import urllib.request


class ServeProcess:
    def __init__(self, lightpath, scene, startup_limit=60.0, env=None):
        self.process = subprocess.Popen([lightpath, "serve", scene, "--port", "0"], stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True, start_new_session=True, env=env)
        line = read_line(self.process.stdout, startup_limit)
        match = re.search(r"at (http://127\.0\.0\.1:(\d+)/) \(Ctrl-C stops\)", line or "")
        if not match:
            self.stop()
            raise RuntimeError(f"lightpath serve did not print its URL: {line!r}; stderr: {self.process.stderr.read()}")
        self.url = match.group(1)
        self.port = int(match.group(2))

    def request(self, method, path, body=None, timeout=60.0):
        """(status, headers, bytes) of one request; 4xx/5xx answers are returned, not raised."""
        data = body.encode() if isinstance(body, str) else body
        request = urllib.request.Request(self.url.rstrip("/") + path, data=data, method=method,
                                         headers={"Content-Type": "application/json"} if data is not None else {})
        try:
            with urllib.request.urlopen(request, timeout=timeout) as response:
                return response.status, dict(response.headers), response.read()
        except urllib.error.HTTPError as error:
            return error.code, dict(error.headers), error.read()

    def json(self, method, path, body=None):
        status, _, data = self.request(method, path, body)
        return status, json.loads(data)

    def wait_until_done(self, generation, limit=120.0):
        deadline = time.monotonic() + limit
        passes = -1
        while time.monotonic() < deadline:
            status, progress = self.json("GET", f"/api/progress?wait=5&generation={generation}&pass={passes}")
            assert status == 200, progress
            if progress["generation"] == generation:
                if progress["done"]:
                    return progress
                passes = progress["passes"]
        raise AssertionError(f"generation {generation} not done within {limit} s")

    def resident_kib(self):
        with open(f"/proc/{self.process.pid}/status") as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        raise RuntimeError("no VmRSS")

    def stop(self):
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()


def read_line(stream, limit):
    """One line of a pipe, or None when none arrives within `limit` seconds."""
    ready, _, _ = select.select([stream], [], [], limit)
    return stream.readline() if ready else None
