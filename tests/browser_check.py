"""Render study reports in headless Chromium and check what a reader would see.

    python3 tests/browser_check.py SCREENSHOT_DIR OUT [OUT ...]

For each OUT/index.html, at a 1280 px wide window: no console errors or
uncaught exceptions, no network request (the report is self-contained), nothing
wider than the window (the page never scrolls sideways), every figure drawn
(each <figure> holds an SVG with a non-empty box and marks in it), and
every movie playing, its time slider seeking it; a contents list and the
findings box on the first screen, no contrast theory flagged, no text drawn
smaller than MIN_TEXT px (figures' text at their drawn scale). A screenshot of the top of each report goes
to SCREENSHOT_DIR/<name of OUT>.png for a person to look at.

Talks the DevTools protocol over a pipe (`--remote-debugging-pipe`: JSON
messages separated by NUL on file descriptors 3 and 4), so it needs nothing
beyond Python's standard library and Debian's `chromium`. Exit 1 with every
problem listed when a check fails.
"""

import base64
import fcntl
import json
import os
import shutil
import subprocess
import sys
import tempfile

WIDTH, HEIGHT = 1280, 900
# The smallest text a projector shows legibly at WIDTH, in CSS px.
MIN_TEXT = 12
LOCAL = ("file:", "data:", "about:")

# Runs in the page once it has loaded; returns what the checks need.
PROBE = """(async () => {
  const width = window.innerWidth;
  const wide = [...document.querySelectorAll('body *')]
    .filter(e => e.getBoundingClientRect().right > width + 0.5)
    .filter(e => !e.closest('.scroll'))
    .slice(0, 5)
    .map(e => e.tagName.toLowerCase() + (e.id ? '#' + e.id : '') +
              ': right edge ' + Math.round(e.getBoundingClientRect().right) + ' px');
  const figures = [...document.querySelectorAll('figure')].map((f, i) => {
    const svg = f.querySelector('svg');
    const caption = (f.querySelector('figcaption') || {}).textContent || 'figure ' + (i + 1);
    if (!svg) return {caption, problem: 'no SVG'};
    const box = svg.getBoundingClientRect();
    if (box.width < 10 || box.height < 10) return {caption, problem: 'drawn ' + box.width + 'x' + box.height + ' px'};
    const marks = svg.querySelectorAll('path, polyline, circle, rect, line').length;
    if (marks < 3) return {caption, problem: 'only ' + marks + ' marks'};
    return {caption, problem: null};
  });
  // Movies: the animation clock runs, and the slider under each seeks it.
  const movies = [...document.querySelectorAll('svg.movie')];
  const before = movies.map(m => m.getCurrentTime());
  await new Promise(done => setTimeout(done, 500));
  const films = movies.map((m, i) => {
    if (!(m.getCurrentTime() > before[i])) return 'movie ' + (i + 1) + ' does not play';
    const slider = m.parentElement.querySelector('.player input[type=range]');
    if (!slider) return 'movie ' + (i + 1) + ' has no time slider';
    slider.value = slider.max / 2;
    slider.dispatchEvent(new Event('input'));
    if (!m.animationsPaused() || Math.abs(m.getCurrentTime() - slider.max / 2) > 1e-3)
      return 'movie ' + (i + 1) + ': the slider does not seek';
    return null;
  });
  // The first screen: the findings box and the contents list start on it.
  const top = selector => {
    const e = document.querySelector(selector);
    return e ? e.getBoundingClientRect().top + window.scrollY : null;
  };
  // A contrast theory is shown, never flagged.
  const flagged = [...document.querySelectorAll('tr')]
    .filter(r => r.textContent.includes('(contrast)') && r.textContent.includes('⚠')).length;
  // Text as drawn, in CSS px: its computed size, and inside a figure
  // times the figure's scale (drawn width over its own).
  const small = [];
  for (const e of document.querySelectorAll('body *')) {
    if (![...e.childNodes].some(n => n.nodeType === 3 && n.textContent.trim())) continue;
    let size = parseFloat(getComputedStyle(e).fontSize);
    const svg = e.closest('svg');
    if (svg) {
      const own = svg.viewBox.baseVal && svg.viewBox.baseVal.width || svg.width.baseVal.value;
      size *= svg.getBoundingClientRect().width / own;
    }
    if (size < MIN_TEXT) small.push(e.textContent.trim().slice(0, 40) + ' (' + size.toFixed(1) + ' px)');
  }
  return {
    contentsTop: top('#contents'),
    findingsTop: top('section.findings'),
    flagged,
    small,
    scrollWidth: document.documentElement.scrollWidth,
    width,
    wide,
    figures,
    movies: movies.length,
    films: films.filter(f => f),
  };
})()""".replace("MIN_TEXT", str(MIN_TEXT))


class Browser:
    """One headless Chromium driven over its DevTools pipe."""

    def __init__(self):
        exe = shutil.which("chromium") or shutil.which("chromium-browser")
        if exe is None:
            sys.exit("browser_check: chromium not found (apt-get install chromium)")
        self.profile = tempfile.mkdtemp(prefix="bonkers-chromium-")
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()
        # Chromium expects the pipe on fds 3 (reads) and 4 (writes); move both
        # out of the way first so that neither lands on the other.
        def child_fds():
            high = [fcntl.fcntl(fd, fcntl.F_DUPFD, 10) for fd in (to_chrome_r, from_chrome_w)]
            os.dup2(high[0], 3)
            os.dup2(high[1], 4)

        self.proc = subprocess.Popen(
            [exe, "--headless=new", "--no-sandbox", "--disable-gpu",
             "--remote-debugging-pipe", "--no-first-run", "--no-default-browser-check",
             f"--user-data-dir={self.profile}", f"--window-size={WIDTH},{HEIGHT}",
             "about:blank"],
            preexec_fn=child_fds, pass_fds=(3, 4),
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def send(self, method, params=None, route=None):
        """Send one command (to a page, if `route` is given: see `attach`) and
        wait for its answer; events seen meanwhile are kept."""
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if route:
            key, value = route
            message[key] = value
        os.write(self.to_chrome, json.dumps(message).encode() + b"\0")
        while True:
            reply = self.receive()
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def receive(self):
        while b"\0" not in self.buffer:
            chunk = os.read(self.from_chrome, 1 << 16)
            if not chunk:
                raise RuntimeError("chromium closed its DevTools pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def attach(self, target):
        """Attach to a page target in flat mode: commands to the page and its
        events carry the id Target.attachToTarget answers with, under the key
        of that answer's one field. Returns that (key, id) pair."""
        reply = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})
        [(key, value)] = reply.items()
        return key, value

    def wait_for(self, method, route):
        key, value = route
        for i, event in enumerate(self.events):
            if event.get("method") == method and event.get(key) == value:
                return self.events.pop(i)
        while True:
            event = self.receive()
            if event.get("method") == method and event.get(key) == value:
                return event
            self.events.append(event)

    def close(self):
        try:
            self.send("Browser.close")
        except (RuntimeError, OSError):
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def check(browser, page, screenshot):
    """The problems a reader would meet on `page`; writes its screenshot."""
    target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
    route = browser.attach(target)
    for domain in ("Page", "Runtime", "Log", "Network"):
        browser.send(f"{domain}.enable", route=route)
    browser.send("Emulation.setDeviceMetricsOverride",
                 {"width": WIDTH, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": False},
                 route=route)
    browser.events.clear()
    browser.send("Page.navigate", {"url": "file://" + os.path.abspath(page)}, route=route)
    browser.wait_for("Page.loadEventFired", route)
    probe = browser.send("Runtime.evaluate",
                         {"expression": PROBE, "returnByValue": True, "awaitPromise": True},
                         route=route)["result"]["value"]
    shot = browser.send("Page.captureScreenshot", {"format": "png"}, route=route)
    with open(screenshot, "wb") as f:
        f.write(base64.b64decode(shot["data"]))

    problems = []
    for event in browser.events:
        method, params = event.get("method"), event.get("params", {})
        if method == "Runtime.exceptionThrown":
            problems.append("uncaught exception: " + params["exceptionDetails"].get("text", ""))
        elif method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in params["args"])
            problems.append("console error: " + text)
        elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
            problems.append("browser error: " + params["entry"]["text"])
        elif method == "Network.requestWillBeSent":
            url = params["request"]["url"]
            if not url.startswith(LOCAL):
                problems.append("network request: " + url)
    if probe["scrollWidth"] > probe["width"]:
        problems.append(f"page is {probe['scrollWidth']} px wide in a {probe['width']} px window: "
                        + "; ".join(probe["wide"]))
    for part in ("contents", "findings"):
        at = probe[part + "Top"]
        if at is None or at > HEIGHT:
            problems.append(f"no {part} on the first screen ({at} px from the top)")
    if probe["flagged"]:
        problems.append(f"{probe['flagged']} contrast row(s) flagged ⚠")
    if probe["small"]:
        problems.append(f"{len(probe['small'])} text(s) under {MIN_TEXT} px, e.g. "
                        + "; ".join(probe["small"][:6]))
    if not probe["figures"]:
        problems.append("no figures")
    problems += probe["films"]
    for figure in probe["figures"]:
        if figure["problem"]:
            problems.append(f"figure '{figure['caption'][:60]}': {figure['problem']}")
    browser.send("Target.closeTarget", {"targetId": target})
    return problems, len(probe["figures"]), probe["movies"]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    shots, outs = sys.argv[1], sys.argv[2:]
    os.makedirs(shots, exist_ok=True)
    browser = Browser()
    failed = False
    try:
        for out in outs:
            page = os.path.join(out, "index.html")
            screenshot = os.path.join(shots, os.path.basename(os.path.normpath(out)) + ".png")
            problems, figures, movies = check(browser, page, screenshot)
            if problems:
                failed = True
                print(f"{page}: {len(problems)} problem(s)")
                for p in problems:
                    print("  " + p)
            else:
                print(f"{page}: ok at {WIDTH} px, {figures} figures drawn, {movies} movie(s) "
                      f"playing and seeking, no errors, no network; screenshot {screenshot}")
    finally:
        browser.close()
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
