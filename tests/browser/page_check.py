#!/usr/bin/env python3
"""Opens a clumpkit page in headless Chromium (Chrome DevTools protocol over a websocket) and
checks it as a person would see it: it loads from file:// with no console error, requests nothing
outside its folder, draws its first view, sorts its table by a column, draws the particle in its
3-D view, shows a report value, shows the unit of every column of numbers and every report row of
numbers (or, with --before-units, the note of a folder written before units). Exit 0 when every
asked check holds, 1 otherwise, 77 (skipped) without chromium or python3-websocket. With
CLUMPKIT_PAGE_FIGURES set to a folder, a screenshot of the page goes there as KIND.png
(KIND-compare.png for several folders, KIND-before-units.png with --before-units).

  page_check.py INDEX.html [--sort COL --csv FILE] [--rows N] [--view] [--spheres SPECIMEN.csv]
                [--report KEY=VALUE|KEY=from:REPORT.json] [--max-first-view S] [--screenshot OUT.png]
                [--expect-outside-request] [--before-units]
"""
import argparse
import base64
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import urllib.parse
import urllib.request
import zlib

SKIP = 77

# Columns of folders written before units, whose names carried an SI unit (io/base/units.cpp).
OLD_NAMES = {
    "axial_stress_pa": "axial_stress", "radial_stress_pa": "radial_stress", "p_pa": "p",
    "q_pa": "q", "work_pa": "work", "depth_m": "depth", "tip_force_n": "tip_force",
    "sleeve_force_n": "sleeve_force", "qc_pa": "qc", "fs_pa": "fs", "sieve_m": "sieve",
    "diameter_m": "diameter", "peak_force_n": "peak_force", "peak_travel_m": "peak_travel",
    "strength_pa": "strength", "max_force_n": "max_force", "travel_m": "travel", "force_n": "force",
    "stress_pa": "stress",
}


def column_name(cell):
    """A CSV header cell's column as the page names it: "strength[Pa]" and "strength_pa" are
    "strength" (io/base/units.h's column_name)."""
    if "[" in cell and cell.endswith("]"):
        return cell[:cell.index("[")]
    return OLD_NAMES.get(cell, cell)


# What the page shows of units: each column of the table holding a number, and each report row of
# a number, must end in its unit ("volume [m3]", "porosity [1]"; base.js's unitLabel).
UNITS_JS = r"""(() => {
  const D = window.CLUMPKIT_PAGE, unit = / \[[^\]]+\]$/, bad = [];
  let shown = 0;
  const th = [...document.querySelectorAll('#table thead th')];
  if (D.table) D.table.columns.forEach((name, c) => {
    if (!D.table.rows.some((r) => typeof r[c] === 'number')) return;
    const t = th[c] ? th[c].textContent : '(no header)';
    if (unit.test(t)) ++shown; else bad.push('table column ' + name + ' shows ' + JSON.stringify(t));
  });
  const keys = new Set();
  for (const f of D.folders) for (const [k, v] of Object.entries(f.report)) if (typeof v === 'number') keys.add(k);
  for (const k of keys) {
    const tr = [...document.querySelectorAll('#report tbody tr')].find((r) => r.dataset.key === k);
    const t = tr ? tr.children[0].textContent : '(no row)';
    if (unit.test(t)) ++shown; else bad.push('report row ' + k + ' shows ' + JSON.stringify(t));
  }
  return { recorded: D.units_recorded, note: !!document.getElementById('units-note'), shown, bad };
})()"""


def screenshot(b, path):
    shot = b.call("Page.captureScreenshot", format="png", captureBeyondViewport=False)
    with open(path, "wb") as f:
        f.write(base64.b64decode(shot["data"]))


def find_browser():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One headless Chromium and a websocket to its page."""

    def __init__(self, browser, websocket):
        self.profile = tempfile.mkdtemp(prefix="clumpkit-page-")
        self.proc = subprocess.Popen(
            [browser, "--headless=new", "--no-sandbox", "--remote-debugging-port=0",
             "--user-data-dir=" + self.profile, "--no-first-run", "--no-default-browser-check",
             "--disable-extensions", "--disable-background-networking",
             "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage",
             "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--mute-audio",
             "--hide-scrollbars", "--window-size=1400,1100", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        port_file = os.path.join(self.profile, "DevToolsActivePort")
        for _ in range(300):
            if os.path.exists(port_file) and open(port_file).read().count("\n") >= 1:
                break
            time.sleep(0.1)
        port = open(port_file).read().split("\n")[0].strip()
        targets = json.load(urllib.request.urlopen("http://127.0.0.1:%s/json/list" % port))
        page = next(t for t in targets if t["type"] == "page")
        self.ws = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=60)
        self.next_id = 0
        self.events = []

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.ws.recv())
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise RuntimeError("%s: %s" % (method, message["error"]))
                return message.get("result", {})
            self.events.append(message)

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True,
                      awaitPromise=True)
        if "exceptionDetails" in r:
            raise RuntimeError("evaluate %s: %s" % (expression, r["exceptionDetails"]))
        return r["result"].get("value")

    def close(self):
        try:
            self.ws.close()
        finally:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
            shutil.rmtree(self.profile, ignore_errors=True)


def png_pixels(data):
    """RGBA or RGB rows of a non-interlaced 8-bit PNG (what Chromium's screenshots are)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width, height, channels = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", chunk[:10])
            assert depth == 8 and colour in (2, 6), "PNG of depth %d colour %d" % (depth, colour)
            channels = 4 if colour == 6 else 3
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("index")
    ap.add_argument("--sort", help="column to sort by (a header click)")
    ap.add_argument("--csv", help="the table's CSV file: the first row after sorting is its minimum")
    ap.add_argument("--view", action="store_true", help="the 3-D view draws where the particle is")
    ap.add_argument("--report", action="append", default=[], help="KEY=VALUE shown in the report")
    ap.add_argument("--max-first-view", type=float, default=0, help="seconds to first view")
    ap.add_argument("--screenshot", help="write a screenshot of the page here")
    ap.add_argument("--rows", type=int, help="the table shows this many rows (every particle)")
    ap.add_argument("--spheres", help="the 3-D view draws every sphere of this specimen.csv")
    ap.add_argument("--before-units", action="store_true",
                    help="the folder was written before units: the page says so instead of "
                         "showing units")
    ap.add_argument("--expect-outside-request", action="store_true",
                    help="pass only if the page requests something outside its folder (the "
                         "check's own test)")
    args = ap.parse_args()

    browser_path = find_browser()
    try:
        import websocket  # Debian's python3-websocket
    except ImportError:
        websocket = None
    if not browser_path or websocket is None:
        print("page_check: skipped (needs chromium and python3-websocket; scripts/deps installs them)")
        return SKIP

    index = os.path.abspath(args.index)
    folder = os.path.dirname(index)
    url = "file://" + urllib.parse.quote(index)
    failures = []
    b = Browser(browser_path, websocket)
    try:
        for domain in ("Page", "Runtime", "Network", "Log"):
            b.call(domain + ".enable")
        b.call("Page.navigate", url=url)
        ready = None
        for _ in range(600):
            ready = b.evaluate("window.clumpkitPage && window.clumpkitPage.ready && "
                               "window.clumpkitPage.viewDrawn ? window.clumpkitPage.firstViewMs : null")
            if ready is not None:
                break
            time.sleep(0.1)
        if ready is None:
            failures.append("the page did not draw its first view within 60 s")
        else:
            print("page_check: first view after %.0f ms" % ready)
            if args.max_first_view and ready > 1000 * args.max_first_view:
                failures.append("first view after %.0f ms > %.1f s" % (ready, args.max_first_view))
        time.sleep(0.5)  # let lazy images and the part's script arrive
        b.evaluate("1")  # collect the events so far

        if args.sort:
            args.sort = column_name(args.sort)  # the page's columns are bare names
            b.evaluate("document.querySelector('th[data-col=\"%s\"]').click()" % args.sort)
            shown = b.evaluate(
                "(() => { const th = [...document.querySelectorAll('#table th')];"
                " const c = th.findIndex(t => t.dataset.col === '%s');"
                " return document.querySelector('#table tbody tr').children[c].textContent; })()"
                % args.sort)
            if args.csv:
                rows = [l.rstrip("\r\n").split(",") for l in open(args.csv) if not l.startswith("#")]
                col = [column_name(c) for c in rows[0]].index(args.sort)
                lowest = min(float(r[col]) for r in rows[1:] if r[col])
                if abs(float(shown) - lowest) > 1e-4 * max(abs(lowest), 1e-300):
                    failures.append("sorted by %s, first row shows %s, the CSV's least is %r"
                                    % (args.sort, shown, lowest))
                else:
                    print("page_check: sorted by %s, first row %s (least %r)" % (args.sort, shown, lowest))

        if args.rows is not None:
            shown = b.evaluate("document.querySelectorAll('#table tbody tr').length")
            if shown != args.rows:
                failures.append("the table shows %s rows, expected %d" % (shown, args.rows))
            else:
                print("page_check: table of %d rows" % shown)

        if args.spheres is not None:
            lines = open(args.spheres).read().splitlines()
            start = lines.index("# spheres") + 2  # after the section's header row
            args.spheres = sum(1 for l in lines[start:] if l and not l.startswith("#"))
            legend = b.evaluate("document.querySelector('.view .legend').textContent")
            if not legend.startswith("%d spheres drawn" % args.spheres):
                failures.append("the view says %r, expected %d spheres drawn" % (legend, args.spheres))
            else:
                print("page_check: %s" % legend)

        if args.view:
            time.sleep(1.0)
            rect = b.evaluate("(() => { const r = document.querySelector('#view3d')"
                              ".getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; })()")
            shot = b.call("Page.captureScreenshot", format="png",
                          clip={"x": rect[0], "y": rect[1], "width": rect[2], "height": rect[3],
                                "scale": 1})
            w, h, ch, rows = png_pixels(base64.b64decode(shot["data"]))
            # The middle third of the view, where the fitted particle or specimen stands.
            inked = total = 0
            for y in range(h // 3, 2 * h // 3):
                for x in range(w // 3, 2 * w // 3):
                    px = rows[y][x * ch:x * ch + 3]
                    total += 1
                    inked += 1 if min(px) < 235 else 0
            share = inked / max(total, 1)
            print("page_check: 3-D view %dx%d, %.1f %% of its middle drawn on" % (w, h, 100 * share))
            if share < 0.05:
                failures.append("the 3-D view's middle is background (%.2f %% drawn)" % (100 * share))

        for item in args.report:
            key, value = item.split("=", 1)
            if value.startswith("from:"):  # the value of KEY in that report.json
                value = str(json.load(open(value[5:]))[key])
            shown = b.evaluate("(() => { const r = document.querySelector('#report tr[data-key=\"%s\"]');"
                               " return r ? r.children[1].textContent : null; })()" % key)
            if shown is None or abs(float(shown) - float(value)) > 1e-4 * abs(float(value)):
                failures.append("report %s shows %r, the report holds %s" % (key, shown, value))
            else:
                print("page_check: report %s = %s" % (key, shown))

        units = b.evaluate(UNITS_JS)
        if args.before_units:
            if units["recorded"] is not False or not units["note"]:
                failures.append("a folder written before units: the page does not say its units "
                                "are not recorded")
            else:
                print("page_check: the page says its units are not recorded")
        else:
            if units["recorded"] is False or units["note"]:
                failures.append("the page says its folder records no units")
            failures += ["no unit: %s" % x for x in units["bad"]]
            if not units["bad"]:
                print("page_check: %d table columns and report rows show their unit"
                      % units["shown"])

        if args.screenshot:
            screenshot(b, args.screenshot)
        figures = os.environ.get("CLUMPKIT_PAGE_FIGURES")
        if figures and not args.expect_outside_request:  # a leaky copy is no figure
            name = b.evaluate("window.CLUMPKIT_PAGE.kind + "
                              "(window.CLUMPKIT_PAGE.folders.length > 1 ? '-compare' : '')")
            if args.before_units:
                name += "-before-units"
            os.makedirs(figures, exist_ok=True)
            screenshot(b, os.path.join(figures, name + ".png"))
            print("page_check: figure %s" % os.path.join(figures, name + ".png"))

        b.evaluate("1")
        errors, requests = [], []
        for e in b.events:
            m, p = e.get("method"), e.get("params", {})
            if m == "Runtime.exceptionThrown":
                errors.append(p["exceptionDetails"].get("exception", {}).get("description")
                              or p["exceptionDetails"].get("text"))
            elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
                errors.append(" ".join(str(a.get("value", a.get("description"))) for a in p["args"]))
            elif m == "Log.entryAdded" and p["entry"]["level"] == "error":
                errors.append(p["entry"]["text"] + " " + p["entry"].get("url", ""))
            elif m == "Network.requestWillBeSent":
                requests.append(p["request"]["url"])
            elif m == "Network.loadingFailed":
                errors.append("failed to load: " + p.get("errorText", ""))
        base = "file://" + urllib.parse.quote(folder) + "/"
        outside = [u for u in requests if not (u.startswith(base) or u.startswith("data:"))]
        print("page_check: %d requests, %d outside the folder, %d console errors"
              % (len(requests), len(outside), len(errors)))
        if args.expect_outside_request:
            if not outside:
                failures.append("no request outside the folder was seen")
            errors = [e for e in errors if "failed to load" not in e and "127.0.0.1:9" not in e]
        else:
            failures += ["request outside the page's folder: %s" % u for u in outside]
        failures += ["console error: %s" % e for e in errors]
    finally:
        b.close()
    for f in failures:
        print("page_check: FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
