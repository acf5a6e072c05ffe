# CMake generated Testfile for 
# Source directory: /work/main/tests/analysis/core
# Build directory: /work/main/build/tests/analysis/core
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
include("/work/main/build/tests/analysis/core/tests_analysis_core_include-b12d07c.cmake")
