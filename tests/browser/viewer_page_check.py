#!/usr/bin/env python3
"""The viewer page in a real browser: `dyop view` writes a page and its per-step counts (--json),
headless Chromium opens the page at a step (#step=N), and this checks what it shows.

- the page decoded its recording and drew (#status reads "ready") without a script error
  (#errors, where the page writes every error, stays empty), and shows the numbers of a contact
  (#details, as a click on it does);
- the body, contact, agreeing and marked counts it shows for both runners are the ones the C++
  side recorded for that step (the page counts them from the data it decoded);
- the page opens framed where the bodies touch, readable: a typical fixture at least
  READABLE_FIXTURE_PX across, and runner A's contact points in view when it has any;
- a screenshot of the slide comparison has content: both runners' colours and many pixels that
  are not background, and so has one of tiles as it opens (1,494 bodies over 60 m).

Usage: viewer_page_check.py DYOP [WORKDIR]. Exits non-zero with the reasons on standard error.
Needs `chromium` on PATH (scripts/browser_test.sh installs it).
"""
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

# Scenes and steps: the slide (the plug-in's internal-edge marks), mixed (circles, boxes and an
# edge ground: every manifold type), paper (no Box2D world), rain-tall (1,500 bodies, fast
# impacts: thousands of contacts to decode), tiles (1,494 bodies spread over a tall, wide scene:
# the opening frame), grounds-flat (two worlds that differ in their grounds: a chain, drawn as its
# edges, beside the builders' triangles), terrain-craters (a ground whose triangles come and go
# with craters dug while it is recorded).
CASES = [("slide", 40), ("mixed", 30), ("paper", 20), ("rain-tall", 60), ("tiles", 60),
         ("grounds-flat", 60), ("terrain-craters", 40)]
CHROMIUM = ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
            "--virtual-time-budget=10000", "--window-size=1200,1000"]
# Of the screenshot's pixels, at least this share must differ from the page's backgrounds: the
# bodies, grounds, contacts and plots cover far more; a blank or failed page covers none.
MIN_CONTENT_SHARE = 0.03
# The page shows the largest penetration in mm to 1 decimal from separations quantised to 0.1 mm
# (report/viewer_page.hpp's separation_quantum): half a quantum plus the display's rounding.
PENETRATION_MM = 0.05 + 0.05 + 1e-9
# The page's READABLE_FIXTURE_PX, less the display's rounding to 0.1 px.
READABLE_FIXTURE_PX = 32 - 0.05
RUNNER_COLOURS = {"A (blue)": (59, 120, 201), "B (orange)": (224, 123, 31)}
BACKGROUNDS = [(255, 255, 255), (250, 250, 250)]

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, file=sys.stderr)


def element(dom, element_id):
    m = re.search(r'id="%s"[^>]*>([^<]*)<' % re.escape(element_id), dom)
    return m.group(1) if m else None


def errors_text(dom):
    m = re.search(r'<div id="errors">(.*?)</div><span', dom, re.S)
    return None if m is None else m.group(1)


def run_chromium(args):
    result = subprocess.run(CHROMIUM + args, capture_output=True, text=True, timeout=180)
    if result.returncode != 0:
        fail("chromium exited with %d: %s" % (result.returncode, result.stderr[-2000:]))
    return result.stdout


def png_pixels(path):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError("unsupported PNG (depth %d, colour %d)" % (depth, colour))
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def check_counts(dyop, workdir, scene, steps):
    page = os.path.join(workdir, scene + ".html")
    summary_path = os.path.join(workdir, scene + ".json")
    subprocess.run([dyop, "view", scene, "--steps", str(steps), "--out", page, "--json",
                    summary_path], check=True, stdout=subprocess.DEVNULL)
    summary = json.load(open(summary_path))
    shown = steps - 3  # a step other than the first and the last
    dom = run_chromium(["--dump-dom", "file://%s#step=%d&select=deepest" % (page, shown)])
    if element(dom, "status") != "ready":
        fail("%s: the page is not ready (status %r)" % (scene, element(dom, "status")))
    errors = errors_text(dom)
    if errors is None or errors.strip():
        fail("%s: script errors on the page: %r" % (scene, errors))
    if element(dom, "step") != str(shown):
        fail("%s: the page shows step %r, not %d" % (scene, element(dom, "step"), shown))
    frame = summary["frames"][shown - 1]
    # The numbers of runner A's deepest contact, as a click shows them: both runners' rows.
    details = re.search(r'<div id="details"[^>]*>(.*?)</div>', dom, re.S)
    if frame["touching"][0] > 0 and (details is None or "Contact of fixture" not in details.group(1)
                                     or not all(r in details.group(1) for r in summary["runners"])):
        fail("%s: no contact numbers for the deepest contact: %r"
             % (scene, details and details.group(1)[:300]))
    for k, side in enumerate("ab"):
        expected = {"bodies": summary["bodies"], "contacts": frame["touching"][k],
                    "agree": frame["agreeing"][k], "marked": frame["marked"][k]}
        for name, value in expected.items():
            got = element(dom, "%s-%s" % (name, side))
            if got != str(value):
                fail("%s, step %d, runner %s: %s shows %r, recorded %d"
                     % (scene, shown, summary["runners"][k], name, got, value))
        # Decoded from the page's data: separations travel to 0.1 mm (viewer_page.hpp).
        got = element(dom, "penetration-" + side)
        if got is None or abs(float(got) - 1000 * frame["max_penetration"][k]) > PENETRATION_MM:
            fail("%s, step %d, runner %s: largest penetration shows %r mm, recorded %.4f mm"
                 % (scene, shown, summary["runners"][k], got, 1000 * frame["max_penetration"][k]))
    fixture_px, in_view = element(dom, "fixture-px"), element(dom, "points-in-view")
    if fixture_px is None or float(fixture_px) < READABLE_FIXTURE_PX:
        fail("%s: opens with a typical fixture %r px across" % (scene, fixture_px))
    if frame["touching"][0] > 0 and (in_view is None or int(in_view) == 0):
        fail("%s: opens with none of runner A's contact points in view (%r)" % (scene, in_view))
    print("%s, step %d: %s" % (scene, shown, ", ".join(
        "%s %s bodies, %s contacts, %s agree, %s marked" % (
            summary["runners"][k], element(dom, "bodies-" + s), element(dom, "contacts-" + s),
            element(dom, "agree-" + s), element(dom, "marked-" + s))
        for k, s in enumerate("ab"))))
    return page


def check_screenshot(page, workdir, name, address):
    shot = os.path.join(workdir, name + ".png")
    run_chromium(["--screenshot=" + shot, "file://%s#%s" % (page, address)])
    if not os.path.exists(shot):
        fail("no screenshot written")
        return
    width, height, rows = png_pixels(shot)
    content = sum(1 for row in rows for p in row if p not in BACKGROUNDS)
    share = content / float(width * height)
    near = lambda p, c: all(abs(p[i] - c[i]) <= 12 for i in range(3))
    for runner, colour in RUNNER_COLOURS.items():
        if not any(near(p, colour) for row in rows for p in row):
            fail("%s screenshot: no pixel of runner %s's colour %s" % (name, runner, colour))
    if share < MIN_CONTENT_SHARE:
        fail("%s screenshot: only %.1f %% of the pixels are not background" % (name, 100 * share))
    print("screenshot %s: %dx%d, %.1f %% not background" % (shot, width, height, 100 * share))


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    dyop = os.path.abspath(sys.argv[1])
    if shutil.which("chromium") is None:
        print("FAIL: chromium is not installed (scripts/browser_test.sh installs it)", file=sys.stderr)
        return 1
    workdir = os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="dyop_view_")
    os.makedirs(workdir, exist_ok=True)
    pages = {scene: check_counts(dyop, workdir, scene, steps) for scene, steps in CASES}
    check_screenshot(pages["slide"], workdir, "slide", "step=12&x=1.2&y=-7.6&scale=220")
    check_screenshot(pages["tiles"], workdir, "tiles", "step=40")
    if failures:
        print("viewer page check: %d failure(s)" % len(failures), file=sys.stderr)
        return 1
    print("viewer page check: passed (%s)" % workdir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
