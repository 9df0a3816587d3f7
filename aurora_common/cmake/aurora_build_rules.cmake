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

# Test executables (gtests, the rostests' checkers) compile at -O1: at -O3
# they were 40% of the build's compile time, and -O1 takes a third off that.
# What they run at speed (the sweep engines, the nodes, flight) is in the
# libraries and programs, built at -O3. The rounding is the same at every
# level (no contraction, no fast-math), so their bit-exact comparisons with
# -O3 code hold.
function(aurora_test_target target)
  target_compile_options(${target} PRIVATE -O1)
endfunction()

# A test build of many files (the big gtests, the registry test's builds of
# the nodes) compiles them in batches of eight, each batch one translation
# unit (CMake's unity build): the headers and templates they share (the
# laws, the runners, the sweep's engines) compiled once per batch, not once
# per file: half the compile time. The files of such a target keep their
# helpers' names apart (a shared one in the target's support header) and
# each still compiles alone; a file with flags of its own stays out
# (SKIP_UNITY_BUILD_INCLUSION). An optional second argument sets another
# batch size: a target built last, alone, in halves keeps both cores busy.
function(aurora_unity_tests target)
  set(batch 8)
  if(ARGC GREATER 1)
    set(batch ${ARGV1})
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
endfunction()
