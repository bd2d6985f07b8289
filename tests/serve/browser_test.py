"""The page of `lightpath serve` in a real browser: headless Chromium (Debian's `chromium`) driven
over the DevTools protocol with Debian's python3-websocket. Loads the page, types an LPE and sees
its tile change, types a broken one and sees the caret message, clicks a mirror pixel and sees a
path through a mirror reflection (RS) drawn over the image, switches to the path tracer, and
keeps screenshots as artefacts. Any console error fails the test. Chromium's profile lives in a
temporary folder that is removed however the test ends, once every Chromium process has exited.

    browser_test.py --lightpath build/lightpath --scene scenes/lecture-room.toml --out OUT
        [--screenshot docs/images/serve.png]
"""
import argparse
import base64
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.request

import websocket  # python3-websocket

sys.path.insert(0, os.path.dirname(__file__))
from serve_process import ServeProcess, read_line  # noqa: E402

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--remote-debugging-port=0", "--window-size=1500,1250", "--hide-scrollbars"]
WAIT_LIMIT = 90.0


def wait_for_group_exit(group, limit=30.0):
    """Waits until no live process (zombies aside) is in process group `group`."""
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        alive = False
        for pid in filter(str.isdigit, os.listdir("/proc")):
            try:
                with open(f"/proc/{pid}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if fields[0] != "Z" and int(fields[2]) == group:
                alive = True
                break
        if not alive:
            return
        time.sleep(0.05)
    raise AssertionError(f"chromium's processes (group {group}) still run {limit} s after it was killed")


class Chromium:
    def __init__(self, profile):
        binary = shutil.which("chromium") or shutil.which("chromium-browser")
        if not binary:
            raise SystemExit("chromium not found: install Debian's chromium (scripts/setup)")
        self.process = subprocess.Popen([binary, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "about:blank"],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                        start_new_session=True)
        self.browser_endpoint = None
        deadline = time.monotonic() + 60
        browser = None
        while time.monotonic() < deadline and browser is None:
            line = read_line(self.process.stderr, deadline - time.monotonic())
            if line is None or (line == "" and self.process.poll() is not None):
                break
            match = re.search(r"DevTools listening on (ws://127\.0\.0\.1:(\d+)/\S+)", line)
            if match:
                browser = match
        if browser is None:
            self.stop()
            raise SystemExit("chromium did not start its DevTools endpoint")
        self.browser_endpoint = browser.group(1)
        port = int(browser.group(2))
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=30) as response:
            targets = json.load(response)
        page = next(t for t in targets if t["type"] == "page")
        self.socket = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=WAIT_LIMIT, suppress_origin=True)
        self.next_id = 0
        self.errors = []

    def stop(self):
        """Closes the browser (so that it stops writing to its profile), then ends whatever of its
        process group is left, and waits until none of it runs."""
        if self.process.poll() is None and self.browser_endpoint:
            try:
                endpoint = websocket.create_connection(self.browser_endpoint, timeout=10, suppress_origin=True)
                endpoint.send(json.dumps({"id": 1, "method": "Browser.close"}))
                self.process.wait(timeout=30)
            except (OSError, websocket.WebSocketException, subprocess.TimeoutExpired):
                pass
        try:
            os.killpg(self.process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self.process.wait()
        wait_for_group_exit(self.process.pid)

    def _note(self, message):
        method, params = message.get("method"), message.get("params", {})
        if method == "Runtime.consoleAPICalled" and params["type"] in ("error", "assert"):
            self.errors.append("console." + params["type"] + ": " +
                               " ".join(str(a.get("value", a.get("description"))) for a in params["args"]))
        elif method == "Runtime.exceptionThrown":
            self.errors.append("uncaught: " + json.dumps(params["exceptionDetails"])[:500])
        elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
            entry = params["entry"]
            # A broken LPE is answered 400 by PUT /api/settings, as docs/serve.md specifies; the page
            # shows it in the tile. Chromium logs every 4xx answer of fetch(); that one is expected.
            if entry.get("source") == "network" and entry.get("url", "").endswith("/api/settings"):
                return
            self.errors.append("log: " + json.dumps(entry)[:500])

    def call(self, method, **params):
        self.next_id += 1
        self.socket.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.socket.recv())
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message["result"]
            self._note(message)

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise AssertionError(f"{expression[:200]}: {result['exceptionDetails'].get('exception', {}).get('description')}")
        return result["result"].get("value")

    def wait_for(self, condition, what):
        """Resolves in the page as soon as `condition` (a JS expression) is truthy; fails after WAIT_LIMIT."""
        script = f"""new Promise((resolve, reject) => {{
            const started = performance.now();
            (function check() {{
                let value;
                try {{ value = ({condition}); }} catch (e) {{ value = undefined; }}
                if (value) resolve(value);
                else if (performance.now() - started > {WAIT_LIMIT * 1000}) reject(new Error("timed out waiting: " + {json.dumps(what)}));
                else setTimeout(check, 25);
            }})();
        }})"""
        value = self.evaluate(script)
        print(f"  ok: {what}")
        return value

    def type_into(self, element, text):
        """Selects the text of the input `element` (a JS expression) and types `text` over it."""
        self.evaluate(f"(() => {{ const e = {element}; e.focus(); e.select(); return true; }})()")
        self.call("Input.insertText", text=text)

    def click(self, x, y):
        for kind in ("mousePressed", "mouseReleased"):
            self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left", clickCount=1)

    def screenshot(self, path, scale=1.0):
        """The whole page, its CSS pixels scaled by `scale`."""
        size = self.call("Page.getLayoutMetrics")["cssContentSize"]
        clip = {"x": 0, "y": 0, "width": size["width"], "height": size["height"], "scale": scale}
        data = self.call("Page.captureScreenshot", format="png", captureBeyondViewport=True, clip=clip)["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))
        print(f"  wrote {path}")


def tile(name):
    return f"[...document.querySelectorAll('.tile')].find(t => t.dataset.layer === {json.dumps(name)})"


# The pixel hash of a tile's image as drawn: changes when the image's content changes.
def tile_hash(name):
    return f"""(() => {{
        const img = {tile(name)}.querySelector('img');
        if (!img.complete || img.naturalWidth === 0) return null;
        const c = document.createElement('canvas');
        c.width = img.naturalWidth; c.height = img.naturalHeight;
        const g = c.getContext('2d');
        g.drawImage(img, 0, 0);
        const d = g.getImageData(0, 0, c.width, c.height).data;
        let h = 0;
        for (let i = 0; i < d.length; i += 7) h = (h * 31 + d[i]) | 0;
        return h;
    }})()"""


def find_mirror_pixel(server, width, height):
    """A pixel whose explanation has a mirror reflection off the mirror ball, found through the API
    (the page is then clicked there like a student would)."""
    for step in (16, 8, 4):
        for y in range(step // 2, height, step):
            for x in range(step // 2, width, step):
                status, e = server.json("GET", f"/api/explain?x={x}&y={y}")
                if status == 200 and any("RS'mirror-ball'" in c["tuple"] for c in e["contributions"]):
                    return x, y
    raise AssertionError("no pixel of the mirror ball found")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lightpath", required=True)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--screenshot", help="also write the screenshot with a pixel's paths here (the README's)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    with tempfile.TemporaryDirectory(prefix="lightpath-chromium-") as profile:
        run(args, profile)


def run(args, profile):
    server = ServeProcess(args.lightpath, args.scene)
    browser = None
    try:
        browser = Chromium(profile)
        for domain in ("Runtime", "Log", "Page"):
            browser.call(f"{domain}.enable")
        browser.call("Page.navigate", url=server.url)

        print("load the page")
        browser.wait_for("document.querySelectorAll('.tile.aov').length === 5", "five AOV tiles of the classes set")
        browser.wait_for("document.getElementById('beauty').naturalWidth === 640", "the beauty image")
        browser.wait_for(f"{tile_hash('raycast')} !== null", "the raycast tile's image")
        browser.wait_for("document.getElementById('sum-check').className === 'ok'", "the sum check")

        print("type an LPE and see its tile change")
        before = browser.evaluate(tile_hash("raycast"))
        browser.type_into(f"{tile('raycast')}.querySelector('.expression')", "E.*<L'key'>")
        browser.wait_for(f"(() => {{ const h = {tile_hash('raycast')}; return h !== null && h !== {before}; }})()",
                         "the raycast tile shows the key light's contribution")

        print("type a broken LPE and see the caret message")
        browser.type_into(f"{tile('raytrace')}.querySelector('.expression')", "E(D|G L")
        message = browser.wait_for(f"(() => {{ const p = {tile('raytrace')}.querySelector('pre.error'); "
                                   "return !p.hidden && p.textContent.includes('^') && p.textContent; })()",
                                   "the syntax error under the raytrace tile")
        lines = message.split("\n")
        quoted = next(i for i, line in enumerate(lines) if line.strip() == "E(D|G L")
        caret = lines[quoted + 1].index("^") - lines[quoted].index("E(D|G L")
        assert "column 8" in message and caret == 7, f"the caret is under column {caret + 1}: {message!r}"
        browser.type_into(f"{tile('raytrace')}.querySelector('.expression')", "ES+(D|G)L")
        browser.wait_for(f"{tile('raytrace')}.querySelector('pre.error').hidden", "the error is gone once fixed")

        print("click a mirror pixel and see a path through a mirror reflection")
        x, y = find_mirror_pixel(server, 640, 480)
        box = browser.evaluate("(() => { const r = document.getElementById('beauty').getBoundingClientRect(); "
                               "return [r.left, r.top, r.width, r.height]; })()")
        browser.click(box[0] + (x + 0.5) * box[2] / 640, box[1] + (y + 0.5) * box[3] / 480)
        browser.wait_for(f"document.getElementById('pixel-label').textContent === '{x},{y}'", f"pixel {x},{y} explained")
        browser.wait_for("[...document.querySelectorAll('#explain-table tbody td[title]')]"
                         ".some(td => td.title.includes(\"RS'mirror-ball'\"))", "a path with RS off the mirror ball in the table")
        browser.wait_for("document.querySelectorAll('#overlay g.path circle[data-event=\"RS\"]').length > 0",
                         "its RS vertex drawn over the image")
        browser.wait_for("document.querySelectorAll('#top-view g.path line').length > 0", "the paths in the top view")
        browser.wait_for("document.querySelectorAll('#automaton g.node.visited').length > 1",
                         "the automaton's visited states highlighted")
        browser.evaluate("document.querySelector('#explain-table tbody tr').click(), true")
        browser.wait_for("document.getElementById('copied').textContent.startsWith('copied: E ')", "a path's LPE copied")
        browser.screenshot(os.path.join(args.out, "serve-explain.png"))

        print("switch to the path tracer")
        browser.evaluate("(() => { const s = document.getElementById('integrator'); s.value = 'path'; "
                         "s.dispatchEvent(new Event('change')); return true; })()")
        browser.wait_for("/^path, 640×480: pass [1-9]/.test(document.getElementById('status').textContent)",
                         "a pass of the path tracer")
        browser.screenshot(os.path.join(args.out, "serve-path.png"))

        if args.screenshot:
            print("the README's screenshot: the classes set, a mirror pixel's paths, one selected")
            browser.evaluate("document.querySelector('button[data-preset=classes]').click(), true")
            browser.wait_for("/\\(done\\)/.test(document.getElementById('status').textContent) && "
                             "document.getElementById('sum-check').className === 'ok'", "the classes set rendered")
            # The page's own click handler (a click there now lands on the drawn path and selects it).
            browser.evaluate(f"explain({x}, {y}).then(() => true)")
            browser.wait_for("document.querySelectorAll('#explain-table tbody tr').length > 0 && "
                             "document.getElementById('explain-table').dataset.generation === String(state.generation)",
                             "the pixel explained again")
            browser.evaluate("[...document.querySelectorAll('#explain-table tbody tr')].find(r => "
                             "r.querySelector('td[title]').title.includes(\"RS'mirror-ball'\")).click(), true")
            browser.wait_for("document.querySelector('#automaton g.node.on-path')", "the selected path's states")
            browser.screenshot(args.screenshot, scale=0.7)  # small enough for the repository

        browser.call("Runtime.evaluate", expression="1")  # collect events still queued
        if browser.errors:
            raise AssertionError("console errors:\n  " + "\n  ".join(browser.errors))
        print("browser: ok")
    finally:
        if browser:
            browser.stop()
        server.stop()


if __name__ == "__main__":
    main()
