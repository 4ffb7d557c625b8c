#!/usr/bin/env bash
# Installs every Debian 12 package Sightline needs to build, test and run.
# Run as root on a fresh Debian 12 (bookworm) machine. Idempotent.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git clang-format clang-tidy
  clang libclang-rt-dev
  qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  qt6-translations-l10n
  libqt6opengl6-dev libgl1-mesa-dev
  libvtk9-dev libpcl-dev libopencv-dev libeigen3-dev
  libopenni2-dev libaravis-dev aravis-tools
  libceres-dev libyaml-cpp-dev libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth mesa-utils libgl1-mesa-dri
  iproute2 util-linux
  # catkin: tf2_ros's CMake config reaches genmsg through actionlib_msgs, and genmsg needs
  # catkin's CMake files (without it configure stops at find_package(tf2_ros)).
  libroscpp-dev librosbag-dev libsensor-msgs-dev libnav-msgs-dev libgeometry-msgs-dev
  libtf2-ros-dev libtf2-msgs-dev libvisualization-msgs-dev libdiagnostic-msgs-dev libstd-srvs-dev
  ros-core catkin
)

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps.sh: run as root (apt-get install needs it)" >&2
  exit 1
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps.sh: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi
echo "install-deps.sh: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
