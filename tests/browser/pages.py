"""The report pages of sreh-twin made as a user makes them (issue 29), for the
browser test (pages_test.py) and the screenshots (docs/img/make_screenshots.sh)."""
import os
import subprocess

from cdp import fail


def make_pages(exe, src, out, cycle="tests/sizing/data/load_change_cycle.yaml"):
    """The five report pages (run, size, cycle, sweep, calibration), written by the CLI as a user would; returns {name: index.html}.
    `cycle`: the cycle file, relative to `src` (the default sizes in a fraction of a second)."""
    jobs = {
        "run": ["run", "scenarios/demo.yaml", "--quiet"],  # relative to src: the page shows the command
        "size": ["size", "--angle-deg", "90", "--load-gcm2", "2000"],
        "cycle": ["size", "--cycle", cycle],
        "sweep": ["sweep", "--loads-gcm2", "0,4000,8000", "--angles-deg", "30,90", "--speeds-dps", "1500",
                  "--csv", os.path.join(out, "sweep.csv")],
    }
    procs = {}
    for name, args in jobs.items():  # two at a time: the machine may be small
        with open(os.path.join(out, name + ".err"), "w") as err:
            procs[name] = subprocess.Popen([exe, *args, "--report", os.path.join(out, name)], cwd=src,
                                           stdout=subprocess.DEVNULL, stderr=err)
        if len(procs) % 2 == 0:
            for p in procs.values():
                p.wait(timeout=300)
    # The calibration report (issue 26): a master log of a short scenario, fitted briefly.
    log = os.path.join(out, "master-log.csv")
    subprocess.run([exe, "run", "scenarios/t03_t05_t07_absolute_move.yaml", "--quiet", "--master-log", log], cwd=src,
                   stdout=subprocess.DEVNULL, check=True, timeout=120)
    with open(os.path.join(out, "calibration.err"), "w") as err:
        procs["calibration"] = subprocess.Popen(
            [exe, "calibrate", log, "--load-gcm2", "0", "--fit", "coulomb_friction,viscous_friction",
             "--max-iterations", "2", "--out", os.path.join(out, "fit.yaml"), "--report", os.path.join(out, "calibration")],
            cwd=src, stdout=subprocess.DEVNULL, stderr=err)
    pages = {}
    for name, p in procs.items():
        p.wait(timeout=300)
        with open(os.path.join(out, name + ".err")) as f:
            err = f.read()
        index = os.path.join(out, name, "index.html")
        if p.returncode not in (0, 1) or not os.path.exists(index):
            fail("%s: exit %d, no page: %s" % (name, p.returncode, err))
        pages[name] = "file://" + index
    return pages


