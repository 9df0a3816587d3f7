# The project's build rules, written once: every package that finds
# aurora_common (find_package(catkin REQUIRED COMPONENTS aurora_common ...))
# compiles by them, with any build tool (catkin_make, catkin build, a
# release). Bit-exact agreement between the ROS loop, the offline runners,
# the sweep and the Python module needs the same rounding everywhere: no FMA
# contraction (test_fp_contract checks it in each package's tests).
add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-ffp-contract=off>)

set(CMAKE_CXX_STANDARD 14)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release)
endif()
