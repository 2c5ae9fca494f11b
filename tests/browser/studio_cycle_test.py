"""`sreh-twin studio` sizing a cycle and with the uncertainty switch (issue
37), in headless Chromium, typed and clicked as a user would:

- a gripper disk and a payload block 50 mm off the axis, a horizontal axis,
  "a cycle of segments" (pick and place: move 90, dwell, grip, move 0,
  dwell, release): while it sizes the progress bar shows the simulations
  run so far; the answer (the whole object) is `sreh-twin size --cycle
  PROJECT.yaml --json` of the exported project, which is a cycle file; the
  page's sets are the command's;
- the project reopened in a second studio gives the same answer, in cycle
  mode with the payload marked; its scenario runs in the twin
  (`sreh-twin run`, passes);
- the layout at 1400 and 800 px;
- a single move with the uncertainty switch on: the answer is `size
  --uncertainty --json`'s, the page shows the bands (p5 .. p95) and the
  verdict over the samples.
Skipped (77) without chromium.

usage: studio_cycle_test.py SREH_TWIN"""
import json
import os
import subprocess
import sys
import time
import urllib.parse

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from cdp import browser_or_skip  # noqa: E402
from studio_test import (ANSWERED, StudioSession, check, check_layout, cli_json, click, export, text,  # noqa: E402
                         type_into, wait_answer)


def set_checkbox(cdp, element_id, on):
    ok = cdp.evaluate("""(() => { const e = document.getElementById(%s); if (!e) return false;
      e.checked = %s; e.dispatchEvent(new Event('change', {bubbles: true})); return true; })()"""
                      % (json.dumps(element_id), "true" if on else "false"))
    check(ok, "no checkbox #%s on the page" % element_id)


def strip_file(j):
    j = json.loads(json.dumps(j))
    j.get("request", {}).pop("cycle_file", None)
    return j


def build_cycle(cdp):
    click(cdp, "add-part")
    click(cdp, "add-part")
    for key, v in (("mass_kg", 0.2), ("radius_m", 0.06), ("thickness_m", 0.01), ("at_m-2", 0.005)):
        type_into(cdp, "part-0-" + key, v)
    type_into(cdp, "part-1-shape", "box")
    for key, v in (("mass_kg", 0.15), ("x_m", 0.02), ("y_m", 0.02), ("z_m", 0.02), ("at_m-0", 0.05), ("at_m-2", 0.02)):
        type_into(cdp, "part-1-" + key, v)
    set_checkbox(cdp, "part-1-payload", True)
    type_into(cdp, "mounting", "90")
    type_into(cdp, "mode", "cycle")
    check(cdp.evaluate("document.getElementById('segments').children.length") == 6, "the new cycle is not pick and place")
    check(cdp.evaluate("document.getElementById('angle_deg').closest('label').hidden"), "the single move's angle shows in cycle mode")
    # While it sizes: the progress bar with the simulations run so far.
    seen = 0
    end = time.monotonic() + 120
    while not cdp.evaluate("(%s) && window.studio.answer.size && window.studio.answer.size.request.cycle_file !== undefined"
                           % ANSWERED):
        if not cdp.evaluate("document.getElementById('progress-line').hidden"):
            txt = text(cdp, "progress-text") or ""
            if txt.split(" ")[0].isdigit():
                seen = max(seen, int(txt.split(" ")[0]))
        cdp.pump(min(end, time.monotonic() + 0.1))
        check(time.monotonic() < end, "no cycle answer within 120 s")
    check(seen > 0, "no progress shown while the cycle was sized")
    check(cdp.evaluate("document.getElementById('progress-line').hidden"), "the progress bar stays after the answer")
    return cdp.evaluate("window.studio.answer"), seen


def main():
    exe = sys.argv[1]
    browser_or_skip()
    with StudioSession(exe) as session:
        cdp, studio, tmp = session.cdp, session.studio, session.tmp
        a, seen = build_cycle(cdp)
        check("error" not in a, "the cycle was refused: %s" % a.get("error"))
        check(a["command"].startswith("sreh-twin size --cycle PROJECT.yaml"), "command %r" % a["command"])
        project = os.path.join(tmp, "cycle.yaml")
        export(studio, cdp, "export-project", project)
        cli = cli_json(exe, a["command"], project, tmp)
        check(strip_file(a["size"]) == strip_file(cli),
              "studio and size --cycle --json differ:\n%s\n%s" % (json.dumps(a["size"]), json.dumps(cli)))
        check(len(cli["sets"]) == 2, "a set per load expected, got %d" % len(cli["sets"]))
        for k, s in enumerate(cli["sets"]):
            check(float(text(cdp, "rec-speed-%d" % k)) == s["speed_dps"] and int(text(cdp, "rec-set-%d" % k)) == s["parameter_set"],
                  "page set %d differs from size --cycle's %s" % (k, s))
        verdict = text(cdp, "answer-verdict")
        check(verdict == ("FEASIBLE" if cli["feasible"] else "NOT FEASIBLE"), "page verdict %r, size says %s" % (verdict, cli["feasible"]))
        check(cdp.evaluate("!!document.querySelector('#verdict-box #verdict')"), "no verdict block for the cycle")
        for width in (1400, 800):
            check_layout(cdp, "studio-cycle", None, width)
        cdp.set_width(1400)

        # Reopened: the same answer, in cycle mode, the payload marked; the scenario passes in the twin.
        reopened = session.reopen(project)
        again = wait_answer(cdp, "!!window.studio.answer.size", timeout=120)
        check(again["size"] == a["size"], "the reopened cycle answers differently")
        check(cdp.evaluate("document.getElementById('mode').value") == "cycle" and
              cdp.evaluate("document.getElementById('part-1-payload').checked"), "the reopened project lost its cycle or payload")
        q = "?s=" + urllib.parse.quote(json.dumps(cdp.evaluate("window.studio.state")))
        scenario = os.path.join(tmp, "cycle_scenario.yaml")
        with open(scenario, "w") as f:
            f.write(reopened.get("/api/export/scenario" + q))
        r = subprocess.run([exe, "run", scenario], capture_output=True, text=True, timeout=120)
        check(r.returncode == 0, "the cycle's scenario failed (%d): %s %s" % (r.returncode, r.stdout[-400:], r.stderr[-400:]))

        # A single move with the uncertainty band.
        type_into(cdp, "mode", "single")
        type_into(cdp, "angle_deg", 90)
        set_checkbox(cdp, "uncertainty", True)
        u = wait_answer(cdp, "!!window.studio.answer.size && window.studio.answer.size.uncertainty !== undefined && "
                             "window.studio.answer.size.request.angle_deg === 90", timeout=180)
        check("--uncertainty" in u["command"], "the command lacks --uncertainty: %r" % u["command"])
        export(reopened, cdp, "export-project", project)
        cli_u = cli_json(exe, u["command"], project, tmp)
        strip = lambda j: {k: v for k, v in j.items() if k != "request"}  # noqa: E731 (the load's name: the file's)
        check(strip(u["size"]) == strip(cli_u), "studio and size --uncertainty --json differ")
        check(cdp.evaluate("document.querySelectorAll('#uncertainty-box table tr').length") >= 4, "no band table shown")
        check(cli_u["uncertainty"]["samples"] == 32, "not 32 samples")
        shown = text(cdp, "uncertainty-box")
        check("32" in shown and "samples" in shown, "the band does not say its samples: %r" % shown[:200])
        check(not [p for p in cdp.problems() if "favicon" not in json.dumps(p)], "console problems: %s" % cdp.problems())
        print("studio cycle: %s, %d sets, progress up to %d simulations shown; uncertainty: %s"
              % ("feasible" if cli["feasible"] else "infeasible", len(cli["sets"]), seen, cli_u["verdict"]))


if __name__ == "__main__":
    main()
