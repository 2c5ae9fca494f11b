"""`sreh-twin studio` in headless Chromium (issue 37), driven as a user would:
typing into the page's fields and clicking its buttons.

- builds a two-part load with an offset part, sets a 90 deg move that must
  position within 0.3 s, reads the verdict and the recommended set from the
  page and compares them (and the whole answer) with `sreh-twin size --json`
  given the exported project file (identical);
- pins the option, changes the supply to 20 V, pins again: both columns show
  their supply, verdict and set, the supply cell is marked as a difference,
  and the 20 V column agrees with `size --json --voltage-V 20`;
- makes the load too heavy: the page says "over by X g cm^2" with X the
  inertia above the module's 15000 g cm^2, and the extra inertia is the
  extra mass times r^2/2 (a disk); no verdict, no writes;
- exports the project, reopens it in a second studio: the same answer; the
  address reproduces the view (the same state and answer);
- exports the CSV (the figures of `size --json`) and the scenario, and runs
  the scenario with `sreh-twin run` (it passes);
- the load's picture (load show --picture) is shown on request;
- uploads an STL as a third part: an open box is refused with the file named
  on the page; a closed box (binary STL in mm) is stored next to the project,
  its inertia on the page is `sreh-twin load show --json`'s of the exported
  project (and m (a^2 + b^2) / 12 + m d^2), `size --json` of that project is
  the page's answer, and the project reopens with the mesh;
- the page at 1400 x 900 and 800 x 900 and the printable report have
  nothing wider than the page (layout_check.js); screenshots are written.
With --latency N: only a measurement, no checks: N edits of a part's mass,
the time from request to the answer shown, p95 printed, with a required
positioning time and without (docs/performance-sizing.md).
Skipped (77) without chromium.

usage: studio_test.py SREH_TWIN [--latency N] [--screenshots DIR]"""
import base64
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import urllib.parse
import urllib.request

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from cdp import Cdp, browser_or_skip, fail  # noqa: E402

CHECK_JS = open(os.path.join(here, "layout_check.js")).read()
ANSWERED = "!!window.studio && window.studio.pending === 0 && !!window.studio.answer"


def check(cond, msg):
    if not cond:
        fail(msg)


class Studio:
    """A `sreh-twin studio` process on a free loopback port."""

    def __init__(self, exe, *args):
        self.proc = subprocess.Popen([exe, "studio", "--http", "127.0.0.1:0", *args], stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True)
        line = self.proc.stdout.readline()
        m = re.search(r"(http://127\.0\.0\.1:\d+/)", line)
        if not m:
            self.proc.kill()
            fail("studio printed no URL: %r %s" % (line, self.proc.stderr.read()))
        self.url = m.group(1)

    def get(self, path):
        with urllib.request.urlopen(urllib.parse.urljoin(self.url, path), timeout=30) as r:
            return r.read().decode()

    def stop(self):
        self.proc.send_signal(2)
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


class StudioSession:
    """The studio in a headless Chromium tab at 1400 px, its first answer
    shown; reopen(project) opens a project in a second studio in the same tab.
    On leaving: the tab, both studios and the scratch folder go."""

    def __init__(self, exe):
        self.exe = exe
        self.tmp = tempfile.mkdtemp()
        self.studio = None
        self.reopened = None
        self.cdp = None

    def __enter__(self):
        try:
            self.studio = Studio(self.exe)
            self.cdp = Cdp(os.path.join(self.tmp, "profile"))
            self.cdp.open_tab()
            self.cdp.set_width(1400)
            self.cdp.navigate(self.studio.url, ANSWERED)
        except BaseException:  # a failed check exits (SystemExit): clean up all the same
            self.__exit__()
            raise
        return self

    def reopen(self, project):
        if self.reopened:
            self.reopened.stop()
        self.reopened = Studio(self.exe, project)
        self.cdp.navigate(self.reopened.url, ANSWERED)
        return self.reopened

    def __exit__(self, *exc):
        if self.cdp:
            self.cdp.close()
        for s in (self.studio, self.reopened):
            if s:
                s.stop()
        shutil.rmtree(self.tmp, ignore_errors=True)


def wait_answer(cdp, extra="true", timeout=30):
    end = time.monotonic() + timeout
    time.sleep(0.05)
    while not cdp.evaluate("(%s) && (%s)" % (ANSWERED, extra)):
        cdp.pump(end)
    return cdp.evaluate("window.studio.answer")


def type_into(cdp, element_id, value):
    """Sets a field as typing does: the value, then an input (and for a select, change) event."""
    ok = cdp.evaluate("""(() => { const e = document.getElementById(%s); if (!e) return false;
      e.value = %s; e.dispatchEvent(new Event('input', {bubbles: true}));
      if (e.tagName === 'SELECT') e.dispatchEvent(new Event('change', {bubbles: true})); return true; })()"""
                      % (json.dumps(element_id), json.dumps(str(value))))
    check(ok, "no field #%s on the page" % element_id)


def click(cdp, element_id):
    """A real click on the element, scrolled into view first."""
    check(cdp.evaluate("(() => { const e = document.getElementById(%s); if (!e) return false;"
                       " e.scrollIntoView({block: 'center'}); return true; })()" % json.dumps(element_id)),
          "no #%s on the page" % element_id)
    cdp.click(element_id)


def js_number(v):
    """A number as the page's script writes it (3000, 81.3)."""
    return "%d" % v if float(v).is_integer() else repr(float(v))


def text(cdp, element_id):
    return cdp.evaluate("(document.getElementById(%s) || {}).textContent" % json.dumps(element_id))


def same_answer(studio_json, cli_json_):
    """Equal but for the load's name: the CLI names the file the project was
    saved as, which the page cannot know before the export."""
    def strip(j):
        j = json.loads(json.dumps(j))
        j.get("request", {}).pop("load_name", None)
        return j
    return strip(studio_json) == strip(cli_json_)


def cli_json(exe, command, project, tmp):
    """Runs the command line the studio shows, with the exported project and a report folder."""
    args = command.replace("PROJECT.yaml", project).replace("REPORT", os.path.join(tmp, "report%d" % time.monotonic_ns()))
    argv = args.split()
    check(argv[0] == "sreh-twin" and argv[1] == "size", "unexpected command line %r" % command)
    r = subprocess.run([exe] + argv[1:], capture_output=True, text=True, timeout=120)
    check(r.returncode in (0, 1), "size failed (%d): %s" % (r.returncode, r.stderr))
    return json.loads(r.stdout)


def build_load(cdp):
    click(cdp, "add-part")
    click(cdp, "add-part")
    # A plate on the axis and a block 50 mm off it.
    for key, v in (("mass_kg", 0.2), ("radius_m", 0.04), ("thickness_m", 0.01), ("at_m-2", 0.005)):
        type_into(cdp, "part-0-" + key, v)
    type_into(cdp, "part-1-shape", "box")
    for key, v in (("mass_kg", 0.1), ("x_m", 0.02), ("y_m", 0.02), ("z_m", 0.02), ("at_m-0", 0.05), ("at_m-2", 0.02)):
        type_into(cdp, "part-1-" + key, v)
    type_into(cdp, "angle_deg", 90)
    type_into(cdp, "target", "positioning")
    type_into(cdp, "target_ms", 300)
    return wait_answer(cdp, "window.studio.answer.load.parts.length === 2 && !!window.studio.answer.size && "
                            "window.studio.answer.size.request.max_positioning_ms === 300")


def export(studio, cdp, link_id, path):
    href = cdp.evaluate("document.getElementById(%s).getAttribute('href')" % json.dumps(link_id))
    body = studio.get(href)
    with open(path, "w") as f:
        f.write(body)
    return body


def check_layout(cdp, label, shots, width):
    cdp.set_width(width)
    time.sleep(0.3)
    problems = cdp.evaluate(CHECK_JS)
    check(not problems, "%s at %d px: %s" % (label, width, problems))
    if shots:
        cdp.screenshot(os.path.join(shots, "%s-%d.png" % (label, width)), max_height=2400)


def check_print(cdp):
    """Printed on A4 (210 mm less 2 x 12 mm margins: 703 CSS px wide, 1032 px a page): the provenance
    and the verdict end on page 1, and Chromium makes an A4 PDF."""
    cdp.set_width(703)
    cdp.send("Emulation.setEmulatedMedia", {"media": "print"})
    bottom = cdp.evaluate("""(() => { const b = (id) => { const e = document.getElementById(id);
      return e ? e.getBoundingClientRect().bottom + window.scrollY : 1e9; };
      return Math.max(b('provenance'), b('verdict')); })()""")
    check(bottom <= 1032, "printed, the provenance and verdict end at %s px, past page 1 (1032 px)" % bottom)
    pdf = base64.b64decode(cdp.send("Page.printToPDF", {"preferCSSPageSize": True}, timeout=60)["data"])
    check(pdf[:5] == b"%PDF-" and re.search(rb"/MediaBox ?\[0 0 59[45]\.?[0-9]* 84[12]", pdf) is not None, "no A4 PDF")
    cdp.send("Emulation.setEmulatedMedia", {"media": ""})


def box_stl(path, size_mm, binary, drop_last=False):
    """A box centred on its origin, outward normals, as binary or ASCII STL; drop_last leaves a hole."""
    h = [v / 2.0 for v in size_mm]
    tris = []
    for axis in range(3):
        for sign in (-1, 1):
            u, v = [a for a in range(3) if a != axis]
            quad = []
            for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0] * 3
                p[axis], p[u], p[v] = sign * h[axis], du * h[u], dv * h[v]
                quad.append(p)
            a, b, c = quad[0], quad[1], quad[2]
            n = [(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                 (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                 (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])]
            if n[axis] * sign < 0:
                quad.reverse()
            tris += [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
    if drop_last:
        tris.pop()
    with open(path, "wb") as f:
        if binary:
            f.write(b"box written by studio_test.py".ljust(80, b" ") + struct.pack("<I", len(tris)))
            for t in tris:
                f.write(struct.pack("<12fH", 0, 0, 0, *[c for p in t for c in p], 0))
        else:
            f.write(b"solid box\n" + b"".join(b"facet normal 0 0 0\nouter loop\n" + b"".join(
                b"vertex %g %g %g\n" % tuple(p) for p in t) + b"endloop\nendfacet\n" for t in tris) + b"endsolid box\n")


def upload(cdp, element_id, path, n_uploads):
    """Picks `path` in the file field as a user does; waits until the page has sent it (its n-th upload)."""
    root = cdp.send("DOM.getDocument", {"depth": 0})["root"]["nodeId"]
    node = cdp.send("DOM.querySelector", {"nodeId": root, "selector": "#" + element_id})["nodeId"]
    check(node != 0, "no file field #%s" % element_id)
    cdp.send("DOM.setFileInputFiles", {"files": [path], "nodeId": node})
    end = time.monotonic() + 30
    while not cdp.evaluate("window.studio.uploads.length >= %d" % n_uploads):
        cdp.pump(end)
    return cdp.evaluate("window.studio.uploads[%d]" % (n_uploads - 1))


def check_mesh_upload(session, exe):
    """A third part from an STL: refused when open (the file named on the page), else stored next to the
    project and its figures those of `load show --json` of the exported project."""
    cdp, tmp, studio = session.cdp, session.tmp, session.reopened
    cdp.set_width(1400)
    cdp.navigate(studio.url, ANSWERED)
    click(cdp, "add-part")
    type_into(cdp, "part-2-shape", "mesh")
    a = wait_answer(cdp, "!!window.studio.answer.error")
    check(a["error"] == "part 3 (mesh): no STL file yet: upload one", "a mesh part without its file: %r" % a["error"])
    bad, good = os.path.join(tmp, "open_box.stl"), os.path.join(tmp, "block.stl")
    box_stl(bad, (30, 20, 10), binary=False, drop_last=True)
    box_stl(good, (30, 20, 10), binary=True)
    u = upload(cdp, "part-2-stl", bad, 1)
    shown = text(cdp, "error")
    check("error" in u and shown.startswith("open_box.stl: the mesh is not closed"), "an open mesh: page says %r" % shown)
    check(not os.path.exists(os.path.join(tmp, "meshes", "open_box.stl")), "the open mesh was stored")
    u = upload(cdp, "part-2-stl", good, 2)
    stored = os.path.join(tmp, "meshes", "block.stl")
    check(u.get("file") == stored and u.get("triangles") == 12, "the upload answered %s, not %s" % (u, stored))
    with open(good, "rb") as f, open(stored, "rb") as g:
        check(f.read() == g.read(), "the stored STL is not the uploaded file")
    for key, v in (("mass_kg", 0.1), ("scale", 0.001), ("at_m-0", 0.03), ("at_m-2", 0.01)):
        type_into(cdp, "part-2-" + key, v)
    a = wait_answer(cdp, "!!window.studio.answer.size && window.studio.answer.load.parts.length === 3 && "
                         "window.studio.state.parts[2].at_m[2] === 0.01")
    check(text(cdp, "part-2-file") == "block.stl", "the part shows %r as its file" % text(cdp, "part-2-file"))
    check_layout(cdp, "studio-mesh", None, 800)  # the file field fits a narrow window too
    cdp.set_width(1400)
    project = os.path.join(tmp, "project_mesh.yaml")
    body = export(studio, cdp, "export-project", project)
    check(json.dumps(stored) in body, "the project does not name the stored STL:\n%s" % body)
    r = subprocess.run([exe, "load", "show", "--json", project], capture_output=True, text=True, timeout=60)
    check(r.returncode == 0, "load show of the exported project failed: %s" % r.stderr)
    shown = json.loads(r.stdout)
    page_total = float(text(cdp, "load-inertia").split()[0])
    check(page_total == round(shown["inertia_gcm2"], 1), "page inertia %s, load show %s" % (page_total, shown["inertia_gcm2"]))
    page_mesh = float(cdp.evaluate("document.querySelectorAll('#load-parts tr')[3].cells[3].textContent"))
    check(page_mesh == round(shown["parts"][2]["inertia_gcm2"], 1), "page mesh part %s, load show %s" % (page_mesh, shown["parts"][2]))
    box = 0.1 * (0.03 ** 2 + 0.02 ** 2) / 12 + 0.1 * 0.03 ** 2  # m (a^2 + b^2) / 12 + m d^2, kg m^2
    check(abs(shown["parts"][2]["inertia_gcm2"] - box * 1e7) < 0.5, "the box's inertia %s is not %s" % (shown["parts"][2], box * 1e7))
    cli = cli_json(exe, a["command"], project, tmp)
    check(same_answer(a["size"], cli), "studio and size --json of the mesh project differ")
    session.reopen(project)
    again = wait_answer(cdp, "!!window.studio.answer.size")
    check(again["size"] == a["size"] and again["load"] == a["load"], "the reopened mesh project answers differently")
    check(text(cdp, "part-2-file") == "block.stl", "the reopened project lost its mesh")
    return page_mesh


def process_cpu_s(pid):
    """User + system CPU seconds of a process so far (all its threads)."""
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def latency(session, n, label):
    cdp = session.cdp
    cdp.evaluate("window.studio.timings.length = 0")
    cpu0 = process_cpu_s(session.studio.proc.pid)
    for k in range(n):
        type_into(cdp, "part-1-mass_kg", 0.1 + 0.002 * (k + 1))
        wait_answer(cdp, "window.studio.timings.length === %d" % (k + 1), timeout=120)
    print("%s, %d edits: the studio's process used %.2f s of CPU" % (label, n, process_cpu_s(session.studio.proc.pid) - cpu0))
    got = cdp.evaluate("window.studio.timings")
    p95 = lambda v: sorted(v)[min(len(v) - 1, int(round(0.95 * (len(v) - 1))))]  # noqa: E731
    p50 = lambda v: sorted(v)[len(v) // 2]  # noqa: E731
    for key, what in (("client_ms", "request -> answer shown"), ("server_ms", "server wall"), ("cpu_ms", "server CPU"),
                      ("shown_ms", "answer parsed -> shown")):
        v = [x[key] for x in got]
        print("%s, %d edits, %s: p50 %.0f ms, p95 %.0f ms, max %.0f ms" % (label, n, what, p50(v), p95(v), max(v)))


def main():
    exe = sys.argv[1]
    n_latency = int(sys.argv[sys.argv.index("--latency") + 1]) if "--latency" in sys.argv else 0
    shots = sys.argv[sys.argv.index("--screenshots") + 1] if "--screenshots" in sys.argv else None
    browser_or_skip()
    if n_latency:
        with StudioSession(exe) as session:
            build_load(session.cdp)
            latency(session, n_latency, "positioning within 300 ms (gentlest set)")
            type_into(session.cdp, "target", "none")
            wait_answer(session.cdp, "window.studio.answer.size && window.studio.answer.size.request.max_positioning_ms === null")
            latency(session, n_latency, "no required time (fastest set)")
        return
    with StudioSession(exe) as session:
        cdp, studio, tmp = session.cdp, session.studio, session.tmp
        a = build_load(cdp)
        check("error" not in a, "the two-part load was refused: %s" % a.get("error"))
        project = os.path.join(tmp, "project.yaml")
        export(studio, cdp, "export-project", project)
        cli = cli_json(exe, a["command"], project, tmp)
        check(same_answer(a["size"], cli), "studio and size --json differ:\n%s\n%s" % (json.dumps(a["size"]), json.dumps(cli)))
        # What the page shows is that answer.
        verdict = text(cdp, "answer-verdict")
        check(verdict == ("FEASIBLE" if cli["feasible"] else "NOT FEASIBLE"), "page verdict %r, size says %s" % (verdict, cli["feasible"]))
        check(("NOT" in (text(cdp, "verdict-answer") or "NOT")) == ("NOT" in verdict), "the verdict block disagrees with the summary")
        shown = [float(text(cdp, i)) for i in ("rec-speed", "rec-accel", "rec-jerk")]
        rec = cli["recommended"]
        check(shown == [rec["speed_dps"], rec["accel_pct"], rec["jerk_pct"]], "page set %s, size set %s" % (shown, rec))
        check(int(text(cdp, "rec-set")) == rec["parameter_set"], "page parameter set differs")
        check(abs(float(text(cdp, "rec-positioning")) - cli["positioning_s"]) < 1e-4, "page positioning time differs")
        check(cli["feasible"] == (cdp.evaluate("!!document.getElementById('writes-text')")),
              "ISDU writes shown for an infeasible set, or missing for a feasible one")
        if cli["feasible"]:
            check(str(rec["isdu_writes"][0]["value"]) in text(cdp, "writes-text"), "the writes are not the set's")
        click(cdp, "show-picture")  # the load on the module, as load show --picture draws it
        end = time.monotonic() + 60
        while not cdp.evaluate("(() => { const i = document.getElementById('load-picture'); return i.complete && i.naturalWidth > 0; })()"):
            cdp.pump(end)
        check(cdp.evaluate("document.getElementById('load-picture').naturalWidth") == 1280, "the load picture is not 1280 px wide")
        for width in (1400, 800):
            check_layout(cdp, "studio", shots, width)
        cdp.set_width(1400)

        # Compare: this option and the same at 20 V.
        click(cdp, "pin")
        wait_answer(cdp, "window.studio.pins.length === 1 && !!window.studio.pins[0].answer && !!document.getElementById('cmp-voltage-0')")
        type_into(cdp, "voltage_V", 20)
        a20 = wait_answer(cdp, "window.studio.answer.size && window.studio.answer.size.request.voltage_V === 20")
        click(cdp, "pin")
        wait_answer(cdp, "window.studio.pins.length === 2 && !!document.getElementById('cmp-voltage-1')")
        cli20 = cli_json(exe, a20["command"], project, tmp)  # the project's load; the command carries the 20 V
        check(same_answer(a20["size"], cli20), "studio at 20 V and size --json --voltage-V 20 differ")
        check(text(cdp, "cmp-voltage-0") == "24" and text(cdp, "cmp-voltage-1") == "20",
              "compare columns: %s / %s" % (text(cdp, "cmp-voltage-0"), text(cdp, "cmp-voltage-1")))
        check(cdp.evaluate("document.getElementById('cmp-voltage-1').classList.contains('diff')"), "the 20 V cell is not marked")
        for col, j in ((0, cli), (1, cli20)):
            check(text(cdp, "cmp-verdict-%d" % col) == ("feasible" if j["feasible"] else "NOT feasible"), "column %d verdict" % col)
            r = j["recommended"]
            check(text(cdp, "cmp-set-%d" % col) == " / ".join(js_number(r[k]) for k in ("speed_dps", "accel_pct", "jerk_pct")),
                  "column %d set %r vs %s" % (col, text(cdp, "cmp-set-%d" % col), r))
        check(len(cdp.evaluate("window.studio.pins")) == 2, "two pins")

        # Export at 20 V, reopen in a second studio: the same answer.
        export(studio, cdp, "export-project", project)
        reopened = session.reopen(project)
        again = wait_answer(cdp, "!!window.studio.answer.size")
        check(again["size"] == a20["size"], "the reopened project answers differently")
        # CSV: the figures of size --json; the scenario passes in the twin.
        q = "?s=" + urllib.parse.quote(json.dumps(cdp_state(reopened)))
        csv = reopened.get("/api/export/csv" + q)
        check(csv.startswith("figure,value\n"), "CSV header: %r" % csv[:40])
        rows = dict(line.split(",", 1) for line in csv.strip().split("\n")[1:] if "," in line)
        check(rows.get("recommended.speed_dps") == json.dumps(a20["size"]["recommended"]["speed_dps"]), "CSV speed row")
        check(rows.get("feasible") == json.dumps(a20["size"]["feasible"]), "CSV feasible row")
        scenario = os.path.join(tmp, "scenario.yaml")
        with open(scenario, "w") as f:
            f.write(reopened.get("/api/export/scenario" + q))
        r = subprocess.run([exe, "run", scenario], capture_output=True, text=True, timeout=120)
        check(r.returncode == 0, "the exported scenario failed (%d): %s %s" % (r.returncode, r.stdout[-400:], r.stderr[-400:]))

        # A link with the state reproduces the view.
        cdp.navigate(reopened.url + "#state=" + urllib.parse.quote(json.dumps({"state": cdp_state(reopened), "pins": []})), ANSWERED)
        check(wait_answer(cdp, "!!window.studio.answer.size")["size"] == a20["size"], "the link does not reproduce the answer")

        # Over the limit: a 5 kg plate.
        type_into(cdp, "part-0-mass_kg", 5)
        over = wait_answer(cdp, "!!document.getElementById('load-over')")
        m = re.search(r"over by ([0-9.]+) g cm\^2", text(cdp, "load-over"))
        check(m is not None, "no 'over by X g cm^2': %r" % text(cdp, "load-over"))
        inertia = over["load"]["inertia_gcm2"]
        check(abs(float(m.group(1)) - (inertia - 15000)) < 0.06, "over by %s, inertia %s" % (m.group(1), inertia))
        extra = inertia - again["load"]["inertia_gcm2"]  # 4.8 kg more on a 40 mm disk: 4.8 * 0.04^2 / 2 kg m^2
        check(abs(extra - 4.8 * 0.04 ** 2 / 2 * 1e7) < 1.0, "the extra inertia %s is not m r^2 / 2" % extra)
        check("size" not in over and "load" in over and text(cdp, "verdict-box") == "", "a verdict for a load over the limit")
        check("part 1" in text(cdp, "load-over").lower(), "the heaviest part is not named: %r" % text(cdp, "load-over"))

        # The printable page: provenance and verdict at the top, nothing too wide.
        cdp.navigate(reopened.url + "report" + q, "document.readyState === 'complete'")
        order = cdp.evaluate("""(() => { const p = document.getElementById('provenance'), v = document.getElementById('verdict');
          return !!p && !!v && (p.compareDocumentPosition(v) & Node.DOCUMENT_POSITION_FOLLOWING) > 0; })()""")
        check(order, "the report lacks provenance before the verdict")
        for width in (1400, 800):
            check_layout(cdp, "studio-report", shots, width)
        check_print(cdp)
        mesh_gcm2 = check_mesh_upload(session, exe)
        # The browser logs the refused upload's 400 (the open mesh): expected, like the missing favicon.
        expected = ("favicon", "/api/mesh?name=open_box.stl")
        check(not [p for p in cdp.problems() if not any(e in json.dumps(p) for e in expected)], "console problems: %s" % cdp.problems())
        print("studio: two-part load, %s; 20 V %s; over the limit by %s g cm^2; project, CSV and scenario exported; "
              "an STL box of %s g cm^2 uploaded" % ("feasible" if cli["feasible"] else "infeasible",
                                                    "feasible" if cli20["feasible"] else "infeasible", m.group(1), mesh_gcm2))


_state_cache = {}


def cdp_state(studio):
    """The state the reopened studio started from (its page's project)."""
    if studio.url not in _state_cache:
        page = studio.get("/")
        m = re.search(r"window\.STUDIO = (\{.*?\});</script>", page, re.S)
        check(m is not None, "the page carries no project")
        _state_cache[studio.url] = json.loads(m.group(1).replace("<\\/", "</"))["project"]
    return _state_cache[studio.url]


if __name__ == "__main__":
    main()
