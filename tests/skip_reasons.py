#!/usr/bin/python3
"""Prints each skipped test of a ctest run with its reason (issue 39): ctest
lists skipped tests without why unless -V. Reads the JUnit file ctest wrote
(ctest --output-junit FILE) and takes the reason from the test's own output:
after GoogleTest's "Skipped" line (GTEST_SKIP() << "why"), else the last
line a script printed before exiting 77 (SKIP_RETURN_CODE).
Usage: skip_reasons.py CTEST_JUNIT.xml"""
import sys
import xml.etree.ElementTree as ET

NOISE = ("[==========]", "[----------]", "[ RUN      ]", "[  SKIPPED ]", "[       OK ]", "[  PASSED  ]",
         "Running main()", "Note: Google Test filter")


def reason(output):
    lines = [line.strip() for line in (output or "").splitlines()]
    lines = [line for line in lines if line and not line.startswith(NOISE)]
    for i, line in enumerate(lines):
        if line.endswith(": Skipped") or line == "Skipped":
            rest = lines[i + 1:]
            if rest:
                return " ".join(rest[:2])
    return lines[-1] if lines else "no reason printed"


def main():
    root = ET.parse(sys.argv[1]).getroot()
    skipped = []
    for case in root.iter("testcase"):
        if case.find("skipped") is None:
            continue
        out = case.findtext("system-out") or ""
        skipped.append((case.get("name"), reason(out)))
    if not skipped:
        return
    print(f"{len(skipped)} test{'s' if len(skipped) != 1 else ''} skipped:")
    width = max(len(name) for name, _ in skipped)
    for name, why in skipped:
        print(f"  {name:<{width}}  {why}")


if __name__ == "__main__":
    main()
