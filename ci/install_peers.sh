#!/usr/bin/env bash
# Install the system libraries the peer tools of the tests need (the `peers` extra:
# openseespy, obspy). On Linux openseespy's compiled library links to the system BLAS and
# LAPACK (libblas.so.3, liblapack.so.3), which a bare Debian/Ubuntu lacks: without them
# `import openseespy.opensees` fails ("Failed to import openseespy on Linux"). Debian's
# libblas3 and liblapack3 (reference BLAS/LAPACK, ~3 MB). Run as root (CI containers) or with
# sudo. Idempotent: does nothing if both libraries are already there.
set -euo pipefail
if ldconfig -p | grep 'libblas\.so\.3 ' >/dev/null && ldconfig -p | grep 'liblapack\.so\.3 ' >/dev/null; then
  echo "install_peers: libblas.so.3 and liblapack.so.3 already installed"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends libblas3 liblapack3
