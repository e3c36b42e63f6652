#!/usr/bin/python3
"""Opens zrender's HTML bench report in headless Chromium and checks it as a reader would.

    tools/bench-report-check.py ZRENDER BUILD_DIR

Renders a bench of bunny and spot (two threads, compared with a baseline run) with --json and
--html, and makes the page again with bench-report, which must give the same bytes. Then, in
Debian's chromium, driven over the DevTools protocol with the network switched off, at a
phone's width (390 px) and a desktop's (1280 px), and in the dark colour scheme: no console
error and no request leaves the page; each scene's chart has one group per algorithm; every
image decodes and has alt text; the table's numbers are the results file's; a click on a
column's header sorts the rows by it, a second click reverses them. Full-page screenshots go to
BUILD_DIR/bench-report-*.png (CI keeps them). Exits 77 (skipped) without the reference models.
"""
import base64
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request

import websocket

zrender, build = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if not os.path.exists(os.path.join(root, "models", "bunny", "bunny.obj")):
    print("bench-report-check: models/bunny is not linked (tools/setup.sh)")
    sys.exit(77)


def fail(message):
    print("bench-report-check: " + message, file=sys.stderr)
    sys.exit(1)


work = tempfile.mkdtemp(prefix="zrender-report.")
browser = None
try:
    bench = [zrender, "bench", "bunny", "spot", "--width", "320", "--height", "320", "--repeat", "3"]
    for args in (["--json", "base.json"],
                 ["--threads", "2", "--baseline", "base.json", "--json", "r.json", "--html", "r.html"]):
        r = subprocess.run(bench + args, cwd=work, capture_output=True, text=True)
        if r.returncode != 0:
            fail(f"zrender bench exited {r.returncode}: {r.stderr}")
    r = subprocess.run([zrender, "bench-report", "r.json", "--baseline", "base.json", "--html",
                        "again.html"], cwd=work, capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"zrender bench-report exited {r.returncode}: {r.stderr}")
    page = open(os.path.join(work, "r.html"), "rb").read()
    if open(os.path.join(work, "again.html"), "rb").read() != page:
        fail("bench-report's page is not the bench's page")
    results = json.load(open(os.path.join(work, "r.json")))

    with socket.socket() as s:  # a free port for the DevTools protocol
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    browser = subprocess.Popen(
        ["chromium", "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--no-default-browser-check", "--disable-extensions", "--disable-background-networking",
         f"--remote-debugging-port={port}", f"--user-data-dir={work}/profile", "about:blank"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    targets = None
    for _ in range(200):
        try:
            targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json", timeout=1))
            break
        except OSError:
            time.sleep(0.1)
    pages = [t for t in targets or [] if t.get("type") == "page"]
    if not pages:
        fail("chromium did not start (DevTools protocol not reachable)")
    ws = websocket.create_connection(pages[0]["webSocketDebuggerUrl"], timeout=30)
    events, errors, requests = [], [], []
    next_id = [0]

    def note(event):
        method, params = event.get("method"), event.get("params", {})
        if method == "Runtime.exceptionThrown":
            errors.append(params["exceptionDetails"].get("text", "exception"))
        elif method == "Runtime.consoleAPICalled" and params.get("type") == "error":
            errors.append(str(params.get("args")))
        elif method == "Log.entryAdded" and params["entry"].get("level") == "error":
            errors.append(params["entry"].get("text"))
        elif method == "Network.requestWillBeSent":
            url = params["request"]["url"]
            if not url.startswith(("file:", "data:", "about:")):
                requests.append(url)
        events.append(method)

    def call(method, **params):
        next_id[0] += 1
        ws.send(json.dumps({"id": next_id[0], "method": method, "params": params}))
        while True:
            message = json.loads(ws.recv())
            if message.get("id") == next_id[0]:
                if "error" in message:
                    fail(f"{method}: {message['error']}")
                return message.get("result", {})
            note(message)

    def wait_for(method):
        while method not in events:
            note(json.loads(ws.recv()))
        events.remove(method)

    def js(expression):
        result = call("Runtime.evaluate", expression=expression, returnByValue=True)
        if "exceptionDetails" in result:
            fail(f"script failed: {expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    for domain in ("Runtime", "Log", "Page", "Network"):
        call(domain + ".enable")
    call("Network.emulateNetworkConditions", offline=True, latency=0, downloadThroughput=-1,
         uploadThroughput=-1)
    url = "file://" + os.path.join(work, "r.html")
    algorithms = ["zbuffer", "scanline", "interval", "hierarchical", "octree"]

    for width, scheme in ((390, "light"), (1280, "light"), (1280, "dark")):
        call("Emulation.setEmulatedMedia",
             features=[{"name": "prefers-color-scheme", "value": scheme}])
        call("Emulation.setDeviceMetricsOverride", width=width, height=900, deviceScaleFactor=1,
             mobile=width < 600)
        call("Page.navigate", url=url)
        wait_for("Page.loadEventFired")
        charts = js("Array.from(document.querySelectorAll('svg.chart')).map(s => "
                    "Array.from(s.querySelectorAll('g.series')).map(g => g.dataset.algorithm))")
        if charts != [algorithms, algorithms]:
            fail(f"{width} px: the charts' algorithm groups are {charts}")
        images = js("Array.from(document.images).map(i => [i.src.slice(0, 11), i.naturalWidth, "
                    "i.alt.length])")
        if len(images) != 2 or any(src != "data:image/" or w == 0 or alt == 0
                                   for src, w, alt in images):
            fail(f"{width} px: images {images}")
        fetched = js("performance.getEntriesByType('resource').map(e => e.name)"
                     ".filter(n => !n.startsWith('data:'))")
        if fetched:
            fail(f"the page fetched {fetched}")
        overflow = js("document.documentElement.scrollWidth - window.innerWidth")
        if overflow > 0:
            wide = js("Array.from(document.querySelectorAll('body *')).filter(e => "
                      "e.getBoundingClientRect().right > window.innerWidth + 1).slice(0, 5)"
                      ".map(e => e.tagName + '.' + e.className.baseVal + e.className)")
            fail(f"{width} px: the page is {overflow} px wider than the window: {wide}")
        if scheme == "dark" and js("getComputedStyle(document.body).backgroundColor") != \
                "rgb(18, 18, 18)":
            fail("the dark colour scheme is not applied")
        if width == 1280 and scheme == "light":  # the window's first screen, for the README
            shot = call("Page.captureScreenshot", format="png")
            open(os.path.join(build, "bench-report-1280-top.png"), "wb").write(
                base64.b64decode(shot["data"]))
        height = call("Page.getLayoutMetrics")["cssContentSize"]["height"]
        call("Emulation.setDeviceMetricsOverride", width=width, height=int(height),
             deviceScaleFactor=1, mobile=width < 600)
        shot = call("Page.captureScreenshot", format="png", captureBeyondViewport=True)
        name = f"bench-report-{width}{'-dark' if scheme == 'dark' else ''}.png"
        open(os.path.join(build, name), "wb").write(base64.b64decode(shot["data"]))

    # The table's numbers are the results file's (data-value holds each to 0.1 microsecond).
    heads = js("Array.from(document.querySelectorAll('table.cells th')).map(h => h.textContent)")
    rows = js("Array.from(document.querySelectorAll('table.cells tbody tr')).map(r => "
              "Array.from(r.cells).map(c => c.dataset.value !== undefined ? c.dataset.value "
              ": c.textContent))")
    column = {h: i for i, h in enumerate(heads)}
    cells = {(c["scene"], c["algorithm"]): c for c in results["cells"]}
    if len(rows) != len(cells):
        fail(f"the table has {len(rows)} rows for {len(cells)} cells")
    for row in rows:
        cell = cells[(row[column["scene"]], row[column["algorithm"]])]
        one = cell["one_thread_frame_ms"]["median"] / cell["frame_ms"]["median"]
        for head, value in (("frame ms", cell["frame_ms"]["median"]),
                            ("frame MAD ms", cell["frame_ms"]["mad"]),
                            ("fastest ms", cell["frame_ms"]["min"]),
                            ("visibility ms", cell["visibility_ms"]["median"]),
                            ("shading ms", cell["shade_ms"]["median"]),
                            ("speed-up over one thread", one)):
            if abs(float(row[column[head]]) - value) > 5e-5:
                fail(f"{row[column['scene']]}/{row[column['algorithm']]}: {head} "
                     f"{row[column[head]]}, the results file {value}")

    # A click on "frame ms" sorts by it; a second click reverses.
    frame = column["frame ms"]
    read = ("Array.from(document.querySelectorAll('table.cells tbody tr'))"
            f".map(r => Number(r.cells[{frame}].dataset.value))")
    before = js(read)
    js(f"document.querySelectorAll('table.cells th button')[{frame}].click()")
    up = js(read)
    js(f"document.querySelectorAll('table.cells th button')[{frame}].click()")
    down = js(read)
    if up != sorted(before) or down != sorted(before, reverse=True) or up == before == down:
        fail(f"sorting by frame ms: {before} -> {up} -> {down}")
    if errors:
        fail(f"console errors: {errors}")
    if requests:
        fail(f"network requests: {requests}")
    print(f"bench-report-check: the page passed at 390 and 1280 px, light and dark; "
          f"screenshots in {build}/bench-report-*.png")
finally:
    if browser:
        browser.kill()
        browser.wait()
    shutil.rmtree(work, ignore_errors=True)
