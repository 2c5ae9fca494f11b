"""docs/api/openapi.yaml describes exactly the routes `serve` registers, and
the live answers carry what the document says they carry (required keys and
basic types, recursively). Also: the bearer token guards writes only (401
without, 403 wrong), surrounding whitespace in the token file is ignored."""
import json
import os
import subprocess
import sys
import tempfile

import yaml

from harness import Serve, check

exe, doc_path = sys.argv[1], sys.argv[2]
doc = yaml.safe_load(open(doc_path))
routes = json.loads(subprocess.run([exe, "serve", "--print-routes", "--json"], capture_output=True, text=True,
                                   check=True).stdout)
served = {(r["method"].lower(), r["path"]) for r in routes}
documented = {(m, p) for p, item in doc["paths"].items() for m in item if m in ("get", "put", "post", "delete", "patch")}
check(served == documented, "routes served but not documented: %s; documented but not served: %s" %
      (sorted(served - documented), sorted(documented - served)))


def deref(node):
    while isinstance(node, dict) and "$ref" in node:
        target = doc
        for part in node["$ref"].lstrip("#/").split("/"):
            target = target[part]
        node = target
    return node


TYPES = {"object": dict, "array": list, "string": str, "integer": int, "number": (int, float), "boolean": bool}


def conforms(value, schema, where):
    schema = deref(schema)
    if value is None and schema.get("nullable"):
        return
    t = schema.get("type")
    if t:
        ok = isinstance(value, TYPES[t]) and not (t in ("integer", "number") and isinstance(value, bool))
        check(ok, "%s: %r is not a %s" % (where, value, t))
    if "enum" in schema:
        check(value in schema["enum"], "%s: %r not in %s" % (where, value, schema["enum"]))
    for key in schema.get("required", []):
        check(isinstance(value, dict) and key in value, "%s: required key '%s' missing in %r" % (where, key, value))
    for key, sub in schema.get("properties", {}).items():
        if isinstance(value, dict) and key in value:
            conforms(value[key], sub, where + "." + key)
    if t == "array":
        for i, item in enumerate(value):
            conforms(item, schema.get("items", {}), "%s[%d]" % (where, i))


def response_schema(path, method, status):
    resp = deref(doc["paths"][path][method]["responses"][str(status)])
    return resp["content"]["application/json"]["schema"]


tmp = tempfile.mkdtemp()
token_file = os.path.join(tmp, "token")
with open(token_file, "w") as f:
    f.write("  s3cret-token \n\n")  # whitespace around it is ignored
s = Serve(exe, "--ports", "2", "--token-file", token_file)
auth = ["Authorization: Bearer s3cret-token"]
try:
    fill = {"{p}": "1", "{index}": "64", "{subindex}": "1", "{name}": "app.js"}

    def concrete(p):
        for k, v in fill.items():
            p = p.replace(k, v)
        return p

    for method, path in sorted(documented):
        url = concrete(path)
        if path.endswith("/events"):
            out = subprocess.run(["curl", "-s", "-N", "-m", "1", s.http + url], capture_output=True, text=True).stdout
            check("event: hello" in out and "event: sample" in out, "event stream: %r" % out[:200])
            continue
        if method == "get":
            code, payload = s.curl("GET", url)  # reads stay open
            check(code == 200, "GET %s -> %d" % (url, code))
            content = doc["paths"][path]["get"]["responses"]["200"]["content"]
            if "application/json" in content:
                conforms(payload, response_schema(path, "get", 200), "GET " + path)
            continue
        body = {"/v1/ports/{p}/processdata/out": {"motor_on": True},
                "/v1/ports/{p}/parameters/{index}/{subindex}": {"value": 1500},
                "/v1/ports/{p}/faults": {"supply_V": 23.5}}[path]
        code, _ = s.curl(method.upper(), url, body)
        check(code == 401, "%s %s without token -> %d, want 401" % (method, url, code))
        code, _ = s.curl(method.upper(), url, body, headers=["Authorization: Bearer wrong"])
        check(code == 403, "%s %s with a wrong token -> %d, want 403" % (method, url, code))
        code, payload = s.curl(method.upper(), url, body, headers=auth)
        check(code == 200, "%s %s -> %d %s" % (method, url, code, payload))
        conforms(payload, response_schema(path, method, 200), method.upper() + " " + path)
    # The documented refusal body, with its HTTP status.
    code, payload = s.curl("PUT", "/v1/ports/1/parameters/64/1", {"value": 50000}, headers=auth)
    check(code == 422, "refused write -> %d" % code)
    conforms(payload, deref(doc["paths"]["/v1/ports/{p}/parameters/{index}/{subindex}"]["put"]["responses"]["422"])
             ["content"]["application/json"]["schema"], "422")
    code, payload = s.curl("GET", "/v1/ports/1/parameters/4242/0")
    check(code == 404 and payload["iolink_error"] == "0x8011", "unknown index -> %d %s" % (code, payload))
    # With a token, Modbus TCP is read-only (it carries no token): exception 01.
    check(s.mbpoll_write(1010, [0, 0, 1], expect_ok=False) != 0, "Modbus write accepted despite the token")
    check(s.get("/v1/ports/1/processdata")["out"]["motor_on"], "HTTP write with the token took effect")
finally:
    rc, err = s.stop()
    s.kill()
check(rc == 0, "exit %d: %s" % (rc, err))
print("PASS")
