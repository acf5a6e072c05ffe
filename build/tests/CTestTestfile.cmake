# CMake generated Testfile for 
# Source directory: /work/main/tests
# Build directory: /work/main/build/tests
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[layering: analysis includes no Qt header]=] "/usr/bin/cmake" "-DROOT=/work/main" "-P" "/work/main/tests/support/check_layering.cmake")
set_tests_properties([=[layering: analysis includes no Qt header]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/tests/CMakeLists.txt;26;add_test;/work/main/tests/CMakeLists.txt;0;")
subdirs("analysis")
