#!/usr/bin/env bash
# Installs every build and test dependency of Gearsim from Debian's packages.
# Idempotent: packages already present are left as they are. Needs root (or sudo).
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libbullet-dev libbullet-extras-dev      # rigid-body dynamics (double precision: bullet-float64)
  libassimp-dev                           # CAD mesh import (STL/OBJ/PLY/...)
  libeigen3-dev                           # linear algebra
  libosmesa6-dev                          # off-screen OpenGL
  libyaml-cpp-dev                         # scenario and gear-spec files
  libcli11-dev                            # command line
  nlohmann-json3-dev                      # JSON outputs
  libfftw3-dev                            # spectra
  libhdf5-dev                             # per-step binary logs (HDF5)
  libpng-dev                              # PNG frames
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev  # MP4 (H.264) video
  ffmpeg                                  # ffprobe, to check written videos in tests
  gnuplot-nox                             # report plots (SVG)
  libopenmpi-dev openmpi-bin              # gearsim sweep across machines (mpirun; MPI C API)
  calculix-ccx                            # finite-element solver (ccx) for flexible-teeth stiffness
  gmsh libgmsh-dev                        # meshing of gear sections for ccx
  libgtest-dev libgmock-dev               # unit tests
  clang-format-14                         # the tree's layout (.clang-format; ctest style.clang_format)
  python3-dev python3-pybind11 pybind11-dev python3-numpy  # the gearsim Python module (python/)
  python3-pytest python3-matplotlib python3-h5py python3-yaml  # its tests and examples/python
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
