#!/usr/bin/env bash
# Installs what tetsmooth needs from Debian/Ubuntu packages, skipping what is
# already there. The CUDA toolkit is optional and not installed here.
# calculix-ccx is the CalculiX solver that tests/python/test_calculix.py runs
# on the decks tetsmooth smooths.
set -euo pipefail
packages=(cmake g++ make libtet1.5-dev libbenchmark-dev libbenchmark-tools libgtest-dev nlohmann-json3-dev
          zlib1g-dev liblzma-dev libnetcdf-dev libexodusii-dev libomp-dev clang libclang-rt-dev python3 python3-pandas python3-matplotlib
          python3-meshio python3-gmsh python3-scipy python3-netcdf4 python3-pip git calculix-ccx)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  echo "install_deps: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# ANSYS .cdb files are checked against an independent reader, Ansys's
# mapdl-archive (PyPI; Debian has none), kept in the checkout's .deps/python
# for Debian's Python, which has its numpy.
pydeps="$(cd "$(dirname "$0")/.." && pwd)/.deps/python"
if ! PYTHONPATH="$pydeps" /usr/bin/python3 -c "import mapdl_archive" 2>/dev/null; then
  echo "install_deps: installing mapdl-archive 0.4.2 into $pydeps" >&2
  /usr/bin/python3 -m pip install -q --disable-pip-version-check --root-user-action=ignore --no-deps --target "$pydeps" mapdl-archive==0.4.2
fi
# LS-DYNA keyword decks likewise, against lsdyna-mesh-reader (PyPI, by the
# author of mapdl-archive).
if ! PYTHONPATH="$pydeps" /usr/bin/python3 -c "import lsdyna_mesh_reader" 2>/dev/null; then
  echo "install_deps: installing lsdyna-mesh-reader 0.2.1 into $pydeps" >&2
  /usr/bin/python3 -m pip install -q --disable-pip-version-check --root-user-action=ignore --no-deps --target "$pydeps" lsdyna-mesh-reader==0.2.1
fi
