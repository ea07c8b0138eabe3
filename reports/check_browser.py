#!/usr/bin/env python3
"""Render the report in headless Chromium and check it as a reader would see it.

    python3 reports/check_browser.py [REPORT_DIR] [--screenshots DIR] [--tiles]

For index.html (and every other page it links: audit.html, engines.html) at a
phone width (400 px, mobile emulation, so the viewport meta tag counts) and a
desktop width (1400 px) it checks that

- every figure (<object> SVG) and image that is shown loads and is an SVG or
  a decoded image, and every relative link and #anchor resolves;
- no console error, uncaught exception or failed load occurs;
- nothing overflows horizontally (document width <= viewport width);
- the smallest text drawn in a visible figure is at least 7.5 px on screen and
  the page's own text at least 11 px;
- no text in a visible figure overlaps another text, a curve or reference
  line (elements of class `c` and `r`, sampled along their length), a marker
  (class `m`), or crosses the frame of a plot (class `frame`): every text is
  wholly inside a plot or wholly outside it. Boxes are the browser's own
  (getBBox through getCTM); a tolerance of 0.25 pt at print size;

and writes full-page screenshots (PNG) of index.html at both widths into the
screenshots directory (default REPORT_DIR/screenshots); with --tiles also
screen-sized pieces of them (index-WIDTH-NN.png) for reading.

It talks to Chromium over the DevTools protocol on a pipe
(--remote-debugging-pipe): Python's standard library only, no driver to install.
Chromium is `$CHROMIUM`, else `chromium` or `chromium-browser` on PATH, else the
one Playwright downloads (`pip install playwright && playwright install --with-deps
chromium`, found under ~/.cache/ms-playwright); if none is found the check FAILS
(exit 2) — it never passes without a browser.
Exit 0: all checks pass; 1: a check failed (each failure printed); 2: no browser.
"""

import base64
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.parse
from pathlib import Path

WIDTHS = [400, 1400]
HEIGHT = 900
MIN_FIG_TEXT_PX = 7.5
MIN_PAGE_TEXT_PX = 11.0
TILES = "--tiles" in sys.argv

FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--no-default-browser-check",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--hide-scrollbars",
    "--mute-audio",
    "--force-color-profile=srgb",
    "--font-render-hinting=none",
    "--allow-file-access-from-files",
    "--remote-debugging-pipe",
]


def find_chromium():
    env = os.environ.get("CHROMIUM")
    if env:
        return env if shutil.which(env) or Path(env).is_file() else None
    for name in ("chromium", "chromium-browser", "google-chrome"):
        p = shutil.which(name)
        if p:
            return p
    # the Chromium that `playwright install chromium` downloads
    cache = Path(os.environ.get("PLAYWRIGHT_BROWSERS_PATH", Path.home() / ".cache" / "ms-playwright"))
    for p in sorted(cache.glob("chromium-*/chrome-linux*/chrome"), reverse=True):
        if p.is_file():
            return str(p)
    return None


class Browser:
    """Chromium driven over the DevTools protocol on fds 3 (in) and 4 (out)."""

    def __init__(self, exe, profile):
        to_child_r, self.to_child_w = os.pipe()
        self.from_child_r, from_child_w = os.pipe()

        def fds():
            # via fresh copies: a pipe end may already be fd 3 or 4 (and close-on-exec)
            a, b = os.dup(to_child_r), os.dup(from_child_w)
            os.dup2(a, 3)
            os.dup2(b, 4)

        self.proc = subprocess.Popen(
            [exe, *FLAGS, f"--user-data-dir={profile}", "about:blank"],
            preexec_fn=fds,
            close_fds=False,  # keep the dup2'ed fds 3 and 4 (others are close-on-exec)
            stdout=subprocess.DEVNULL,
            stderr=open(os.environ.get("CHROMIUM_LOG", os.devnull), "w"),
        )
        os.close(to_child_r)
        os.close(from_child_w)
        self.buf = b""
        self.next_id = 0
        self.events = []

    def _read_message(self, deadline):
        while b"\0" not in self.buf:
            if time.time() > deadline:
                raise TimeoutError("no answer from Chromium")
            chunk = os.read(self.from_child_r, 1 << 16)
            if not chunk:
                raise RuntimeError("Chromium closed the pipe (did it start?)")
            self.buf += chunk
        msg, self.buf = self.buf.split(b"\0", 1)
        return json.loads(msg)

    def send(self, method, params=None, session=None, timeout=60):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.to_child_w, json.dumps(msg).encode() + b"\0")
        deadline = time.time() + timeout
        while True:
            m = self._read_message(deadline)
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']}")
                return m.get("result", {})
            self.events.append(m)

    def wait_event(self, method, timeout=60):
        deadline = time.time() + timeout
        for i, e in enumerate(self.events):
            if e.get("method") == method:
                del self.events[i]
                return e
        while True:
            m = self._read_message(deadline)
            if m.get("method") == method:
                return m
            self.events.append(m)

    def close(self):
        try:
            self.send("Browser.close", timeout=10)
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()


READY = r"""
(() => [...document.querySelectorAll('object')]
  .filter(o => o.offsetParent !== null)
  .every(o => o.contentDocument && o.contentDocument.documentElement
              // not the about:blank placeholder an <object> holds before its SVG
              && o.contentDocument.documentElement.tagName.toLowerCase() === 'svg'
              && o.contentDocument.readyState === 'complete'))()
"""

PROBE = r"""
(() => {
  // the box of an element in the figure's viewport (px), through its CTM
  const boxOf = el => {
    const b = el.getBBox(), m = el.getCTM();
    const pts = [[b.x, b.y], [b.x + b.width, b.y], [b.x, b.y + b.height], [b.x + b.width, b.y + b.height]]
      .map(([x, y]) => [m.a * x + m.c * y + m.e, m.b * x + m.d * y + m.f]);
    const xs = pts.map(p => p[0]), ys = pts.map(p => p[1]);
    return {x0: Math.min(...xs), x1: Math.max(...xs), y0: Math.min(...ys), y1: Math.max(...ys)};
  };
  const meets = (a, b, tol) => a.x0 + tol < b.x1 && b.x0 + tol < a.x1 && a.y0 + tol < b.y1 && b.y0 + tol < a.y1;
  const within = (a, b, tol) => a.x0 >= b.x0 - tol && a.x1 <= b.x1 + tol && a.y0 >= b.y0 - tol && a.y1 <= b.y1 + tol;
  const overlaps = (d, scale) => {
    const tol = 0.25 * scale;
    const texts = [...d.querySelectorAll('text')].filter(t => t.textContent.trim())
      .map(t => ({s: t.textContent.trim(), b: boxOf(t)}));
    const lines = [...d.querySelectorAll('.c, .r')].map(el => {
      const m = el.getCTM(), n = el.getTotalLength(), pts = [];
      const step = Math.max(0.2, n / 4000);
      for (let l = 0; l <= n; l += step) {
        const p = el.getPointAtLength(l);
        pts.push([m.a * p.x + m.c * p.y + m.e, m.b * p.x + m.d * p.y + m.f]);
      }
      return {what: el.classList.contains('r') ? 'reference line' : 'curve',
              title: (el.querySelector('title') || {}).textContent || '', pts};
    });
    const marks = [...d.querySelectorAll('.m')].map(el => ({title: (el.querySelector('title') || {}).textContent || '', b: boxOf(el)}));
    const frames = [...d.querySelectorAll('.frame')].map(boxOf);
    const bad = [];
    texts.forEach((t, i) => {
      for (let j = i + 1; j < texts.length; j++)
        if (meets(t.b, texts[j].b, tol)) bad.push(`text "${t.s}" overlaps text "${texts[j].s}"`);
      const inner = {x0: t.b.x0 + tol, x1: t.b.x1 - tol, y0: t.b.y0 + tol, y1: t.b.y1 - tol};
      for (const l of lines)
        if (l.pts.some(([x, y]) => x > inner.x0 && x < inner.x1 && y > inner.y0 && y < inner.y1)) {
          bad.push(`text "${t.s}" overlaps the ${l.what} "${l.title.slice(0, 50)}"`);
        }
      for (const m of marks)
        if (meets(t.b, m.b, tol)) bad.push(`text "${t.s}" overlaps the marker "${m.title.slice(0, 50)}"`);
      for (const f of frames)
        if (meets(t.b, f, tol) && !within(t.b, f, tol)) bad.push(`text "${t.s}" crosses a plot's frame`);
    });
    return bad;
  };
  const out = {failures: [], links: [], minFigText: 1e9, minPageText: 1e9};
  const vw = Math.min(window.innerWidth, __WIDTH__);
  const docW = Math.max(document.documentElement.scrollWidth, document.body.scrollWidth);
  if (docW > vw + 1) {
    const wide = [...document.body.querySelectorAll('*')]
      .filter(e => e.getBoundingClientRect().right > vw + 1)
      .slice(0, 5).map(e => e.tagName + (e.id ? '#' + e.id : '') + (e.className ? '.' + e.className : ''));
    out.failures.push(`horizontal overflow: document ${docW} px wide in a ${vw} px viewport (${wide.join(', ')})`);
  }
  const visible = e => e.offsetParent !== null && e.getClientRects().length > 0;
  // content sticking out of the viewport outside any scrolling container
  const scrolls = e => {
    for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) {
      const o = getComputedStyle(a).overflowX;
      if (o === 'auto' || o === 'scroll' || o === 'hidden') return true;
    }
    return false;
  };
  const out_of_view = [];
  for (const e of document.body.querySelectorAll('*')) {
    if (!visible(e) || scrolls(e)) continue;
    for (const r of e.getClientRects()) {
      if (r.right > vw + 1 && r.width > 0) { out_of_view.push(e.tagName + ': ' + (e.textContent || '').trim().slice(0, 40)); break; }
    }
    if (out_of_view.length >= 5) break;
  }
  if (out_of_view.length) out.failures.push(`content beyond the right edge: ${out_of_view.join(' | ')}`);
  let figs = 0;
  for (const o of document.querySelectorAll('object')) {
    if (!visible(o)) continue;
    figs++;
    const d = o.contentDocument;
    const svg = d && d.documentElement;
    if (!svg || svg.tagName.toLowerCase() !== 'svg') {
      out.failures.push(`figure did not load: ${o.getAttribute('data')}`);
      continue;
    }
    const r = o.getBoundingClientRect();
    if (r.height < 50) out.failures.push(`figure ${o.getAttribute('data')} is ${r.height} px high`);
    const vb = svg.viewBox && svg.viewBox.baseVal;
    const scale = vb && vb.width ? r.width / vb.width : 1;
    for (const t of d.querySelectorAll('text')) {
      const fs = parseFloat(t.getAttribute('font-size') || svg.getAttribute('font-size') || '16');
      const px = fs * scale;
      if (px < out.minFigText) { out.minFigText = px; out.minFigWhere = o.getAttribute('data'); }
    }
    // overlaps: texts against texts, curves, markers and frames
    const bad = overlaps(d, scale);
    for (const b of bad.slice(0, 8)) out.failures.push(`overlap in ${o.getAttribute('data')}: ${b}`);
    if (bad.length > 8) out.failures.push(`overlap in ${o.getAttribute('data')}: ${bad.length - 8} more`);
    out.overlapChecked = (out.overlapChecked || 0) + 1;
  }
  out.figures = figs;
  for (const img of document.querySelectorAll('img')) {
    if (!visible(img)) continue;
    if (!(img.complete && img.naturalWidth > 0)) out.failures.push(`image did not load: ${img.getAttribute('src')}`);
  }
  for (const a of document.querySelectorAll('a[href]')) {
    const h = a.getAttribute('href');
    if (h.startsWith('#')) {
      if (!document.getElementById(decodeURIComponent(h.slice(1)))) out.failures.push(`dangling anchor ${h}`);
    } else out.links.push(a.href);
  }
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  let n;
  while ((n = walker.nextNode())) {
    if (!n.textContent.trim()) continue;
    const e = n.parentElement;
    if (!visible(e)) continue;
    const px = parseFloat(getComputedStyle(e).fontSize);
    if (px < out.minPageText) { out.minPageText = px; out.minPageWhere = e.tagName + ': ' + n.textContent.trim().slice(0, 40); }
  }
  return out;
})()
"""


def check_page(b, url, width, shot=None):
    """Loads url at width; returns (failures, links, info)."""
    failures = []
    t = b.send("Target.createTarget", {"url": "about:blank"})
    s = b.send("Target.attachToTarget", {"targetId": t["targetId"], "flatten": True})["sessionId"]
    for dom in ("Page", "Runtime", "Log", "Network"):
        b.send(f"{dom}.enable", session=s)
    b.send(
        "Emulation.setDeviceMetricsOverride",
        {"width": width, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": width < 700},
        session=s,
    )
    b.events.clear()
    b.send("Page.navigate", {"url": url}, session=s)
    b.wait_event("Page.loadEventFired", timeout=120)
    # the figures are <object>s, each a document of its own: wait until every
    # shown one has loaded (a busy machine can be slower than the page's load event)
    deadline = time.time() + 60
    while time.time() < deadline:
        r = b.send("Runtime.evaluate", {"expression": READY, "returnByValue": True}, session=s)
        if r.get("result", {}).get("value"):
            break
        time.sleep(0.2)
    time.sleep(0.3)
    r = b.send(
        "Runtime.evaluate",
        {"expression": PROBE.replace("__WIDTH__", str(width)), "returnByValue": True},
        session=s,
    )
    if "exceptionDetails" in r:
        failures.append(f"probe failed: {r['exceptionDetails']}")
        probe = {"failures": [], "links": []}
    else:
        probe = r["result"]["value"]
    failures += probe["failures"]
    if probe.get("minFigText", 1e9) < MIN_FIG_TEXT_PX:
        failures.append(
            f"figure text {probe['minFigText']:.1f} px < {MIN_FIG_TEXT_PX} px ({probe.get('minFigWhere')})"
        )
    if probe.get("minPageText", 1e9) < MIN_PAGE_TEXT_PX:
        failures.append(
            f"page text {probe['minPageText']:.1f} px < {MIN_PAGE_TEXT_PX} px ({probe.get('minPageWhere')})"
        )
    for e in b.events:
        if e.get("sessionId") != s:
            continue
        m, p = e.get("method"), e.get("params", {})
        if m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            failures.append(f"console error: {p.get('args')}")
        elif m == "Runtime.exceptionThrown":
            failures.append(f"uncaught exception: {p.get('exceptionDetails', {}).get('text')}")
        elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            failures.append(f"console error: {p['entry'].get('text')} {p['entry'].get('url', '')}")
        elif m == "Network.loadingFailed" and not p.get("canceled"):
            failures.append(f"load failed: {p.get('errorText')} (request {p.get('requestId')})")
    if shot:
        m = b.send("Page.getLayoutMetrics", session=s)
        h = int(m["cssContentSize"]["height"])
        b.send(
            "Emulation.setDeviceMetricsOverride",
            {"width": width, "height": h, "deviceScaleFactor": 1, "mobile": width < 700},
            session=s,
        )
        time.sleep(0.3)
        img = b.send("Page.captureScreenshot", {"format": "png"}, session=s, timeout=120)
        Path(shot).write_bytes(base64.b64decode(img["data"]))
        if TILES:
            # pieces of the page at screen size, for reading (not kept)
            step = 1200 if width < 700 else 1000
            for k, y in enumerate(range(0, h, step)):
                clip = {"x": 0, "y": y, "width": width, "height": min(step, h - y), "scale": 1}
                img = b.send("Page.captureScreenshot", {"format": "png", "clip": clip}, session=s)
                Path(f"{shot[:-4] if isinstance(shot, str) else str(shot)[:-4]}-{k:02d}.png").write_bytes(
                    base64.b64decode(img["data"])
                )
    b.send("Target.closeTarget", {"targetId": t["targetId"]})
    info = {
        "figures": probe.get("figures", 0),
        "minFigText": probe.get("minFigText"),
        "overlapChecked": probe.get("overlapChecked", 0),
    }
    return failures, probe.get("links", []), info


def main():
    args = [a for a in sys.argv[1:] if a != "--tiles"]
    shots = None
    if "--screenshots" in args:
        i = args.index("--screenshots")
        shots = Path(args[i + 1])
        del args[i : i + 2]
    root = Path(args[0] if args else Path(__file__).resolve().parent).resolve()
    shots = (shots or root / "screenshots").resolve()
    index = root / "index.html"
    if not index.is_file():
        print(f"check_browser: FAIL: {index} does not exist (run `cylroll report` first)")
        return 1
    exe = find_chromium()
    if not exe:
        print(
            "check_browser: FAIL: no Chromium found ($CHROMIUM, chromium, chromium-browser). "
            "Install it (Debian: apt-get install chromium); the report is NOT checked.",
            file=sys.stderr,
        )
        return 2
    shots.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    failures = []
    with tempfile.TemporaryDirectory() as profile:
        b = Browser(exe, profile)
        try:
            pages = [index]
            seen = set()
            while pages:
                page = pages.pop(0)
                if page in seen:
                    continue
                seen.add(page)
                for w in WIDTHS:
                    shot = shots / f"index-{w}.png" if page == index else None
                    f, links, info = check_page(b, page.as_uri(), w, shot)
                    rel = page.relative_to(root)
                    smallest = (
                        f", smallest figure text {info['minFigText']:.1f} px" if info["figures"] else ""
                    )
                    print(
                        f"check_browser: {rel} at {w} px: {info['figures']} figures shown{smallest}, "
                        f"{info['overlapChecked']} checked for overlaps, {len(f)} problems"
                    )
                    failures += [f"{rel} at {w} px: {x}" for x in f]
                    for link in links:
                        u = urllib.parse.urlparse(link)
                        if u.scheme != "file":
                            failures.append(f"{rel}: non-local link {link}")
                            continue
                        target = Path(urllib.parse.unquote(u.path))
                        if not target.exists():
                            failures.append(f"{rel}: link to missing {target}")
                        elif target.suffix == ".html" and root in target.parents:
                            pages.append(target)
        finally:
            b.close()
    for f in sorted(set(failures)):
        print(f"check_browser: FAIL: {f}")
    print(
        f"check_browser: {'FAILED' if failures else 'ok'}: {len(seen)} pages at {WIDTHS} px in "
        f"{time.time() - t0:.1f} s; screenshots in {shots}"
    )
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
