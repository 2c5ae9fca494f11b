"""Prints `sreh-twin run --json` output (one object, or JSON Lines) without
its measured members wall_s and real_time_factor (issue 25): what is left
is the deterministic result that tests compare byte for byte."""
import json
import sys

text = open(sys.argv[1]).read()
try:
    docs = [json.loads(text)]
except json.JSONDecodeError:
    docs = [json.loads(line) for line in text.splitlines() if line.strip()]
for doc in docs:
    for key in ("wall_s", "real_time_factor"):
        if key not in doc:
            sys.exit(f"{sys.argv[1]}: no {key} in the run's JSON")
        del doc[key]
    print(json.dumps(doc, sort_keys=True))
