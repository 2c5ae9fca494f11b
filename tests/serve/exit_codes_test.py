"""Issue 27: `serve --help` and docs/serve.md state the same exit codes, and
serve keeps them: 0 after SIGINT and after SIGTERM (a clean stop), 2 for bad
input (one line on stderr)."""
import re
import signal
import subprocess
import sys

from harness import Serve, check

exe, serve_md = sys.argv[1], sys.argv[2]


def norm(text):
    return re.sub(r"\s+", " ", text).strip()


help_text = subprocess.run([exe, "serve", "--help"], capture_output=True, text=True, timeout=20).stdout
m = re.search(r"Exit codes:.*", norm(help_text))
check(m is not None, "serve --help states no exit codes")
codes = m.group(0)
doc = norm(open(serve_md).read().replace("`", ""))
check(codes in doc, "docs/serve.md does not state serve --help's exit codes:\n  %s" % codes)

for sig in (signal.SIGINT, signal.SIGTERM):
    s = Serve(exe, "--ports", "1")
    s.proc.send_signal(sig)
    _, err = s.proc.communicate(timeout=15)
    check(s.proc.returncode == 0, "exit %d after signal %d: %s" % (s.proc.returncode, sig, err))
p = subprocess.run([exe, "serve", "--ports", "99"], capture_output=True, text=True, timeout=20)
check(p.returncode == 2 and p.stderr.count("\n") == 1, "bad --ports: %d %r" % (p.returncode, p.stderr))
print("PASS")
