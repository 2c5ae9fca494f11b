"""CTest cli.params_export_iodd (issue 13): the IODD-like export is well-formed,
valid against docs/iodd/sreh-iodd.xsd (xmllint), and lists exactly the rows of
the parameter table (`params list --json`), with their access, range and default.

usage: iodd_check.py SREH_TWIN XSD OUT_XML
"""
import json
import subprocess
import sys
import xml.etree.ElementTree as ET

tool, xsd, out = sys.argv[1:4]
subprocess.run([tool, "params", "export", "--iodd", out], check=True)
subprocess.run(["xmllint", "--noout", "--schema", xsd, out], check=True)

rows = json.loads(subprocess.run([tool, "params", "list", "--json"], check=True,
                                 capture_output=True, text=True).stdout)
table = {(r["index"], r["subindex"]): r for r in rows}

ACCESS = {"ro": "r", "wo": "w", "rw": "rw"}
XSI_TYPE = "{http://www.w3.org/2001/XMLSchema-instance}type"
exported = {}
for var in ET.parse(out).getroot().iter("Variable"):
    index = int(var.get("index"))
    dt = var.find("Datatype")
    defaults = {int(i.get("subindex")): i.get("defaultValue") for i in var.findall("RecordItemInfo")}
    if dt.get(XSI_TYPE) == "RecordT":
        for item in dt.findall("RecordItem"):
            sub = int(item.get("subindex"))
            exported[(index, sub)] = (item.get("accessRights"), item.find("SimpleDatatype"), defaults.get(sub))
    else:
        exported[(index, 0)] = (var.get("accessRights"), dt, var.get("defaultValue"))

errors = []
if set(exported) != set(table):
    errors.append(f"rows only in the export: {sorted(set(exported) - set(table))}; "
                  f"only in the table: {sorted(set(table) - set(exported))}")
for key, (access, dt, default) in exported.items():
    row = table.get(key)
    if row is None:
        continue
    if ACCESS[access] != row["access"]:
        errors.append(f"{key}: access {access} vs {row['access']}")
    vr = dt.find("ValueRange")
    if row["min"] is not None:
        if vr is None or int(vr.get("lowerValue")) != row["min"] or int(vr.get("upperValue")) != row["max"]:
            errors.append(f"{key}: range differs from the table")
        if row["access"] != "w" and (default is None or int(default) != row["default"]):
            errors.append(f"{key}: default {default} vs {row['default']}")
if errors:
    print("\n".join(errors))
    sys.exit(1)
print(f"IODD export: {len(exported)} rows, schema-valid, equal to the table")
