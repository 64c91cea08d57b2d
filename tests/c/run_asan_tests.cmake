# Configures, builds and runs the c_* tests in a sanitizer build tree.
# Called by the ctest test asan_c_tests:
#   cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DGENERATOR=... -DC_COMPILER=...
#         -DCXX_COMPILER=... -DCTEST_COMMAND=... -DTARGETS=c_a,c_b
#         -P run_asan_tests.cmake
cmake_minimum_required(VERSION 3.16)

include(${CMAKE_CURRENT_LIST_DIR}/../cmake/second_tree_steps.cmake)
opx_require_variables(run_asan_tests.cmake SOURCE_DIR BINARY_DIR GENERATOR C_COMPILER CXX_COMPILER CTEST_COMMAND TARGETS)


file(MAKE_DIRECTORY ${BINARY_DIR})
run_step(asan_c_tests "configure ${BINARY_DIR}"
  ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Debug
    "-DCMAKE_C_FLAGS_DEBUG=-g -O1"
    "-DCMAKE_CXX_FLAGS_DEBUG=-g -O1"
    -DCMAKE_C_COMPILER=${C_COMPILER}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DOPX_SANITIZE=ON
    -DOPX_BUILD_BENCH=OFF
    -DOPX_BUILD_EXAMPLES=OFF)

string(REPLACE "," ";" targets "${TARGETS}")
run_step(asan_c_tests "build ${TARGETS}" ${CMAKE_COMMAND} --build ${BINARY_DIR} -j2 --target ${targets})

# detect_leaks: LeakSanitizer is on by default on Linux; say so explicitly.
# UBSan reports must fail the test, not only print.
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0:strict_string_checks=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
run_step(asan_c_tests "ctest -R ^c_"
  ${CTEST_COMMAND} -R "^c_" -j2 --output-on-failure --timeout 600)
