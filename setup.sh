#!/usr/bin/env bash
# Installs everything sreh-twin needs from Debian 12 packages, as root on a
# fresh machine (README "Quick start"). Safe to run again.
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then
  echo "setup.sh: run as root (it installs Debian packages with apt-get)" >&2
  exit 2
fi
export DEBIAN_FRONTEND=noninteractive
packages=(
  build-essential cmake pkg-config git ca-certificates   # compiler, build
  libmujoco-dev libqhull-dev                              # physics (mujocoConfig.cmake needs the qhull headers)
  libeigen3-dev libyaml-cpp-dev                           # linear algebra, scenario files
  libceres-dev                                            # calibrate: bounded nonlinear least squares (issue 26)
  libcli11-dev libfmt-dev nlohmann-json3-dev              # command line, formatting, JSON output
  libgtest-dev libgmock-dev libbenchmark-dev              # tests, benchmarks
  libosmesa6-dev libpng-dev ffmpeg                        # off-screen rendering, PNG frames, H.264 video
  libjs-dygraphs                                          # zoomable plots, inlined into reports and the live page
  clang libclang-rt-14-dev                                # libFuzzer harnesses (tests/fuzz)
  lld                                                     # links the big test binaries several times faster than GNU ld (CMake's SREH_LLD; docs/performance-ci.md)
  libxml2-utils                                           # xmllint: checks the IODD-like export against our XSD
  libmodbus-dev libcpp-httplib-dev libmosquitto-dev       # serve: Modbus TCP, HTTP/JSON, MQTT
  libssl-dev                                              # serve: HMAC of signed MQTT commands
  mosquitto mbpoll curl python3-pymodbus                  # serve's tests: broker and real PLC-style clients
  python3-serial-asyncio                                  # pymodbus' client package imports it even for TCP (only Recommended)
  python3-yaml                                            # serve's OpenAPI test reads docs/api/openapi.yaml
  python3-junitparser                                     # run --junit read back by a real JUnit consumer (tests/tools/junit_check.sh)
  pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest  # Python API (headers: python3-dev) and its tests, Debian's /usr/bin/python3
  parallel                                                # sharded sweeps and scenario runs
  slurmctld slurmd slurm-client munge                     # tests/scale_out: a one-node Slurm started by hand (no service is started at install)
  python3-distributed                                     # tests/scale_out: the Dask example on scheduler + worker processes
  yamllint python3-kubernetes                             # tests/scale_out: the Kubernetes manifest linted, checked against the API's models
)
if [ "${SREH_WITH_EXAMPLES:-0}" = 1 ]; then
  packages+=(python3-matplotlib) # only for examples/python
fi
if [ "${SREH_WITH_BROWSER:-0}" = 1 ]; then
  packages+=(chromium) # only for the report-in-a-browser test
fi
# serve --opcua (issue 38): the OPC UA front is Node.js with node-opcua (Debian 12 packages no C/C++
# OPC UA stack). Debian's nodejs (18) and npm, unless a Node.js with npm is already there (e.g. nodesource's
# nodejs, which replaces Debian's package and bundles its own npm).
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The OPC UA front's packages (serve/opcua): exactly the versions in its committed package-lock.json,
# chosen to run on Node 18 (docs/opcua.md "Install"); no install scripts run, nothing is fetched later.
front="$(cd "$(dirname "$0")" && pwd)/serve/opcua"
if [ ! -d "$front/node_modules/node-opcua" ] || [ "$front/package-lock.json" -nt "$front/node_modules/.package-lock.json" ]; then
  (cd "$front" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error)
fi
