"""`run DIR --junit` read back by a real JUnit consumer, Debian's
python3-junitparser (issue 39): the cases, the failure, and logs with real
line breaks; the failure of a move into a post names its code's name
(manual 7.2: position tracking error, 114.5).

usage: junit_read.py FILE.xml"""
import sys

from junitparser import Failure, JUnitXml


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


xml = JUnitXml.fromfile(sys.argv[1])
cases = {case.name: case for suite in xml for case in suite}
if sorted(cases) != ["a_passes", "b_fails", "c_blocked"]:
    fail("testcases %s" % sorted(cases))
for name, case in cases.items():
    out = case.system_out or ""
    if "\\n" in out or out.count("\n") < 2:
        fail("%s: <system-out> is not one line per check: %r" % (name, out[:200]))
    failures = [r for r in case.result if isinstance(r, Failure)]
    if (name == "a_passes") != (not failures):
        fail("%s: failures %s" % (name, failures))
blocked = [r for r in cases["c_blocked"].result if isinstance(r, Failure)][0]
if "error_code 8 (position tracking error, 114.5)" not in blocked.message:
    fail("the failure does not name the error: %r" % blocked.message)
if "\\n" in (blocked.text or "") or not (blocked.text or "").endswith("\n"):
    fail("failure text not in lines: %r" % blocked.text)
print("junitparser read %d testcases; failure: %s" % (len(cases), blocked.message))
