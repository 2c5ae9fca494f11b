#!/usr/bin/python3
"""The studio's answer goes uncompressed however the browser asks (issue 37,
docs/performance-sizing.md): Chromium accepts brotli, and cpp-httplib's
brotli at quality 11 took 60-130 ms per single-move answer on the loopback.
Also checks the answer is JSON with its figures.

usage: answer_encoding_check.py SREH_TWIN"""
import json
import re
import subprocess
import sys
import urllib.request


def main():
    proc = subprocess.Popen([sys.argv[1], "studio", "--http", "127.0.0.1:0"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        m = re.search(r"(http://127\.0\.0\.1:\d+/)", proc.stdout.readline())
        if not m:
            sys.exit("studio printed no URL")
        state = {"parts": [{"shape": "disk", "mass_kg": 0.2, "radius_m": 0.04, "thickness_m": 0.01}], "angle_deg": 90}
        rq = urllib.request.Request(m.group(1) + "api/answer", data=json.dumps(state).encode(),
                                    headers={"Content-Type": "application/json",
                                             "Accept-Encoding": "gzip, deflate, br"})  # as Chromium asks
        with urllib.request.urlopen(rq, timeout=30) as r:
            encoding = r.headers.get("Content-Encoding")
            kind = r.headers.get("Content-Type", "")
            body = r.read()
        if encoding:
            sys.exit("the answer came %s-compressed" % encoding)
        if not kind.startswith("application/json"):
            sys.exit("the answer's content type is %r" % kind)
        a = json.loads(body)
        if "size" not in a or a["size"].get("feasible") is not True:
            sys.exit("no feasible answer for a 0.2 kg disk: %s" % a.get("error"))
        print("answer: %d bytes uncompressed, %s" % (len(body), kind))
    finally:
        proc.send_signal(2)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


if __name__ == "__main__":
    main()
