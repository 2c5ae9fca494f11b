#!/usr/bin/python3
"""The studio answers uncompressed however the browser asks (issue 37,
docs/performance-sizing.md): Chromium accepts brotli, and cpp-httplib's
brotli at quality 11 took 60-130 ms per single-move answer and 0.5 s per
report on the loopback. Checks the answer (JSON with its figures), the
page, its script and the printable report.

usage: uncompressed_check.py SREH_TWIN"""
import json
import re
import subprocess
import sys
import urllib.parse
import urllib.request

AS_CHROMIUM = {"Accept-Encoding": "gzip, deflate, br"}


def fetch(url, data=None):
    headers = dict(AS_CHROMIUM)
    if data is not None:
        headers["Content-Type"] = "application/json"
    with urllib.request.urlopen(urllib.request.Request(url, data=data, headers=headers), timeout=30) as r:
        if r.headers.get("Content-Encoding"):
            sys.exit("%s came %s-compressed" % (url, r.headers.get("Content-Encoding")))
        return r.headers.get("Content-Type", ""), r.read()


def main():
    proc = subprocess.Popen([sys.argv[1], "studio", "--http", "127.0.0.1:0"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        m = re.search(r"(http://127\.0\.0\.1:\d+/)", proc.stdout.readline())
        if not m:
            sys.exit("studio printed no URL")
        url = m.group(1)
        state = {"parts": [{"shape": "disk", "mass_kg": 0.2, "radius_m": 0.04, "thickness_m": 0.01}], "angle_deg": 90}
        kind, body = fetch(url + "api/answer", json.dumps(state).encode())
        if not kind.startswith("application/json"):
            sys.exit("the answer's content type is %r" % kind)
        a = json.loads(body)
        if "size" not in a or a["size"].get("feasible") is not True:
            sys.exit("no feasible answer for a 0.2 kg disk: %s" % a.get("error"))
        kind, page = fetch(url)
        if not kind.startswith("text/html") or b"<html" not in page.lower():
            sys.exit("the page is %r, %d bytes" % (kind, len(page)))
        kind, script = fetch(url + "assets/studio.js")
        if "javascript" not in kind or len(script) < 1000:
            sys.exit("the script is %r, %d bytes" % (kind, len(script)))
        kind, report = fetch(url + "report?s=" + urllib.parse.quote(json.dumps(state)))
        if not kind.startswith("text/html") or b"</html>" not in report.lower():
            sys.exit("the report is %r, %d bytes" % (kind, len(report)))
        print("answer %d, page %d, script %d, report %d bytes, none compressed" %
              (len(body), len(page), len(script), len(report)))
    finally:
        proc.send_signal(2)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


if __name__ == "__main__":
    main()
