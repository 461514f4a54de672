#!/usr/bin/env bash
# Installs the Debian packages cdvp needs. Idempotent: when everything is
# already installed it does nothing (and needs no network).
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libsystemc-dev                 # SystemC 2.3.4 + TLM-2.0 (pkg-config: systemc)
  libboost-program-options-dev   # command line
  nlohmann-json3-dev             # JSON reports
  libssl-dev                     # SHA-256 digests of a sweep's inputs and rows (OpenSSL libcrypto)
  libtomlplusplus-dev            # TOML config files (cdvp run --config)
  libgtest-dev libgmock-dev      # tests
  libbenchmark-dev               # benchmarks
  libbullet-dev                  # software broad-phase baselines (Bullet 3.24, float)
  libfcl-dev libode-dev          # the library baselines: FCL 0.7's managers, ODE 0.16's spaces (double)
  gtkwave                        # vcd2fst (--vcd-format fst), and the viewer the waveform tests open
  xvfb xauth                     # an X server for GTKWave in the tests (xvfb-run)
  clang-14 libclang-rt-14-dev    # fuzz build: libFuzzer and the clang sanitizer runtimes live in libclang-rt-14-dev
  libcgal-dev                    # independent oracle for the pair tests (box_self_intersection_d)
  gnuplot-nox                    # plots of measured results
  graphviz                       # the layer graph, docs/layers.png (scripts/figures.py)
  parallel                       # GNU parallel for sweeps and the synthesis table
  help2man                       # the man page, generated from --help at build time
  yosys                          # synthesis behind the resource model (scripts/synthesize.sh)
  iverilog                       # simulates the RTL against the C++ model (tests/rtl)
  verilator                      # compiles the board RTL for --fidelity rtl (models/rtl_engine) and lints it
  pybind11-dev python3-dev       # the Python module (sw/python), for Debian's /usr/bin/python3
  python3-pandas python3-pytest  # its tables and its tests
  python3-matplotlib             # the example that draws the paper's speedup figure from cdvp.sweep
  mkdocs                         # the docs site, built with --strict by the test docs.site
  python3-jsonschema             # validates real reports and sweep rows against docs/schema (tests/schema)
  python3-distributed            # cdvp.sweep(executor=) on a Dask LocalCluster in the module's tests
  slurmctld slurmd slurm-client munge  # a one-node Slurm on the loopback for the sweep's job-array test (tests/slurm)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
