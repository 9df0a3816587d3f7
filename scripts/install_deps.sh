#!/usr/bin/env bash
# Installs what AuRoRA-ROS needs to build, test and run its demo, only where
# missing (idempotent). Debian 12: ROS 1 from Debian's own packages.
# Ubuntu 20.04: ROS Noetic from /opt/ros/noetic (ros-noetic-* packages; the
# ROS apt repository must be configured, see docs/platforms.md).
set -euo pipefail

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

. /etc/os-release
case "${ID}:${VERSION_ID}" in
  debian:12)
    PKGS=(ros-base-dev catkin python3-catkin-pkg python3-rostest python3-rosbag rosbash
          python3-roslaunch python3-rosnode python3-rostopic rosout ros-message-generation
          libroscpp-dev libtf2-ros-dev libtf2-dev libnav-msgs-dev libgeometry-msgs-dev
          libvisualization-msgs-dev libsensor-msgs-dev libstd-msgs-dev libros-rosgraph-msgs-dev
          python3-dynamic-reconfigure libdynamic-reconfigure-config-init-mutex-dev
          rviz librosbag-dev librosbag-storage-dev python3-geometry-msgs python3-std-msgs python3-nav-msgs
          python3-rosgraph-msgs python3-tf2-msgs python3-visualization-msgs python3-sensor-msgs
          python3-rosparam python3-rosnode libangles-dev catkin-lint libroslib-dev python3-roslib python3-rospkg
          python3-pandas python3-tqdm jupyter-notebook jupyter-nbconvert python3-ipywidgets python3-ipykernel
          python3-nbclient)
    ;;
  ubuntu:20.04)
    PKGS=(ros-noetic-ros-base ros-noetic-rostest ros-noetic-rosbag ros-noetic-tf2-ros
          ros-noetic-nav-msgs ros-noetic-visualization-msgs ros-noetic-sensor-msgs
          ros-noetic-dynamic-reconfigure ros-noetic-rviz ros-noetic-rosbash ros-noetic-angles
          python3-catkin-pkg python3-catkin-lint)
    # Python and notebooks (nbconvert 5 executes without nbclient here).
    PKGS+=(python3-pandas python3-tqdm jupyter-notebook jupyter-nbconvert python3-ipywidgets python3-ipykernel)
    ;;
  *)
    echo "install_deps: ${PRETTY_NAME:-this OS} is not supported (Debian 12 or Ubuntu 20.04)" >&2
    exit 1
    ;;
esac
PKGS+=(build-essential cmake libeigen3-dev libyaml-cpp-dev libgtest-dev googletest libxsimd-dev
       libboost-program-options-dev nlohmann-json3-dev libfmt-dev libhdf5-dev python3-h5py libcsv-dev
       libopenmpi-dev openmpi-bin librandom123-dev
       python3-matplotlib python3-numpy python3-yaml ffmpeg xvfb xauth imagemagick
       pybind11-dev python3-dev)

missing=()
for p in "${PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "install_deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
# Refresh the package lists once per day at most (apt-get update is slow).
stamp=/var/lib/apt/periodic/update-success-stamp
if [ ! -e /var/lib/apt/lists/lock ] || [ -z "$(find /var/lib/apt/lists -maxdepth 1 -name '*Packages*' -mmin -1440 2>/dev/null | head -1)" ]; then
  $SUDO apt-get update
fi
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
