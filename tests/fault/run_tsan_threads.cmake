# Configures a ThreadSanitizer build tree, builds the library and
# fault_threads there, and runs it.  Called by the ctest test tsan_threads:
#   cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DGENERATOR=... -DC_COMPILER=...
#         -DCXX_COMPILER=... -P run_tsan_threads.cmake
#
# gcc's TSan runtime is a shared library (libtsan), linked by the library
# and by the test alike, so the library keeps -Wl,--no-undefined and the
# flags go on the command line: no option of the project is needed.
cmake_minimum_required(VERSION 3.16)

include(${CMAKE_CURRENT_LIST_DIR}/../cmake/second_tree_steps.cmake)
opx_require_variables(run_tsan_threads.cmake SOURCE_DIR BINARY_DIR GENERATOR C_COMPILER CXX_COMPILER)


set(tsan_flags "-fsanitize=thread -fno-omit-frame-pointer")
file(MAKE_DIRECTORY ${BINARY_DIR})
# OPX_FAULT_TSAN_TREE keeps that tree from adding this test again.
run_step(tsan_threads "configure ${BINARY_DIR}"
  ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=RelWithDebInfo
    -DCMAKE_C_COMPILER=${C_COMPILER}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    "-DCMAKE_C_FLAGS=${tsan_flags}"
    "-DCMAKE_CXX_FLAGS=${tsan_flags}"
    -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread
    -DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=thread
    -DOPX_FAULT_TSAN_TREE=ON
    -DOPX_BUILD_BENCH=OFF
    -DOPX_BUILD_EXAMPLES=OFF)

run_step(tsan_threads "build fault_threads" ${CMAKE_COMMAND} --build ${BINARY_DIR} -j2 --target fault_threads)

# A race report makes the run fail (TSan's exit code 66), after all of them
# are printed.
set(ENV{TSAN_OPTIONS} "second_deadlock_stack=1")
run_step(tsan_threads "fault_threads"
  ${BINARY_DIR}/tests/fault/fault_threads --poses 24)
