# Sourced by the benchmark scripts after BUILD is set: Debian's python3 and
# ROS tools first in PATH, Noetic's setup where it exists, the workspace's
# devel space (built in $BUILD), then the repository root as the working folder.
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
cd "$(dirname "${BASH_SOURCE[0]}")/.."
