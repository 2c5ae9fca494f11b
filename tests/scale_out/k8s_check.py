#!/usr/bin/python3
"""Issue 31: examples/kubernetes/sweep-job.yaml, checked without a cluster
(CI has none, so the manifest is never run on a real one):

1. yamllint (Debian's yamllint) passes;
2. every object round-trips through the Kubernetes API's own models
   (Debian's python3-kubernetes, generated from the API's OpenAPI spec): an
   unknown or misspelt field, or a value of the wrong type, does not survive
   and fails here; the Job is Indexed and N agrees everywhere;
3. both containers' commands run on this machine as the Job controller would
   run them (JOB_COMPLETION_INDEX = 0 .. N-1, then the merge), with /out a
   temporary folder and a smaller grid: the merged CSV is the unsharded one.

Exit 77 (CTest: skipped) only when yamllint or python3-kubernetes is missing.
    k8s_check.py SREH_TWIN MANIFEST
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

try:
    import yaml
    from kubernetes.client import ApiClient
except ImportError as e:
    print(f"skipped: {e.name} is missing (./setup.sh installs python3-yaml and python3-kubernetes)")
    sys.exit(77)

API_VERSIONS = {"Job": "batch/v1", "PersistentVolumeClaim": "v1"}
SMALL_GRID = "--loads-gcm2 0,4000,12000 --angles-deg 30,90,180"


class Response:  # what ApiClient.deserialize reads
    def __init__(self, obj):
        self.data = json.dumps(obj)


def check_schema(path, docs):
    api = ApiClient()
    for doc in docs:
        kind = doc.get("kind")
        where = f"{path}: {kind} {doc.get('metadata', {}).get('name')}"
        if API_VERSIONS.get(kind) != doc.get("apiVersion"):
            sys.exit(f"{where}: apiVersion {doc.get('apiVersion')}, expected {API_VERSIONS.get(kind)}")
        try:
            back = api.sanitize_for_serialization(api.deserialize(Response(doc), "V1" + kind))
        except (ValueError, TypeError) as e:
            sys.exit(f"{where}: not a valid {kind}: {e}")
        if back != doc:
            sys.exit(f"{where}: not a valid {kind} (fields lost or changed by the API model):\n"
                     f"{json.dumps(doc, indent=1, sort_keys=True)}\nvs\n{json.dumps(back, indent=1, sort_keys=True)}")


def script(job):
    (container,) = job["spec"]["template"]["spec"]["containers"]
    command = container["command"]
    if command[:2] != ["sh", "-c"] or len(command) != 3:
        sys.exit(f"{job['metadata']['name']}: expected command [sh, -c, SCRIPT]")
    return command[2]


def main():
    sreh_twin, manifest = os.path.abspath(sys.argv[1]), sys.argv[2]
    if shutil.which("yamllint") is None:
        print("skipped: yamllint is missing (./setup.sh installs it)")
        sys.exit(77)
    subprocess.run(["yamllint", "--strict", "-d", "{extends: default, rules: {line-length: {max: 130}}}", manifest],
                   check=True)
    with open(manifest, encoding="utf-8") as f:
        docs = [d for d in yaml.safe_load_all(f) if d is not None]
    check_schema(manifest, docs)

    jobs = {d["metadata"]["name"]: d for d in docs if d["kind"] == "Job"}
    sweep, merge = jobs["sreh-sweep"], jobs["sreh-sweep-merge"]
    spec = sweep["spec"]
    n = int(re.search(r"--shard auto/(\d+)", script(sweep)).group(1))
    if spec.get("completionMode") != "Indexed" or spec.get("completions") != n:
        sys.exit(f"sreh-sweep: expected completionMode Indexed and completions {n} (--shard auto/{n})")
    if f"-ge {n} ]" not in script(merge):
        sys.exit(f"sreh-sweep-merge: does not wait for {n} parts")

    with tempfile.TemporaryDirectory() as out:
        env = dict(os.environ, PATH=os.path.dirname(sreh_twin) + os.pathsep + os.environ["PATH"])

        def local(text):  # the pod's command on this machine: /out a folder here, a small grid, one thread
            text = text.replace("/out/", out + "/").replace("--threads 2", "--threads 1")
            return re.sub(r"--loads-gcm2 \S+\s+--angles-deg \S+", SMALL_GRID, text)

        for index in range(n):
            subprocess.run(["sh", "-c", local(script(sweep))], check=True, env=dict(env, JOB_COMPLETION_INDEX=str(index)),
                           stdout=subprocess.DEVNULL)
        subprocess.run(["sh", "-c", local(script(merge))], check=True, env=env, stdout=subprocess.DEVNULL)
        whole = os.path.join(out, "whole.csv")
        subprocess.run([sreh_twin, "sweep", *SMALL_GRID.split(), "--threads", "1", "--csv", whole], check=True,
                       stdout=subprocess.DEVNULL)
        with open(whole, "rb") as a, open(os.path.join(out, "sweep.csv"), "rb") as b:
            if a.read() != b.read():
                sys.exit("the merged CSV differs from the unsharded sweep")
    print(f"{manifest}: yamllint clean, {len(docs)} objects valid for the Kubernetes API models, "
          f"{n} indexed pods + merge give the unsharded CSV")


if __name__ == "__main__":
    main()
