tests/analysis/core/tests_analysis_core_autogen/timestamp: \
  /work/main/tests/analysis/core/CMakeLists.txt \
  /work/main/tests/analysis/core/corpus_test.cpp \
  /work/main/tests/analysis/core/pose_test.cpp \
  /work/main/tests/analysis/core/take_test.cpp \
  /usr/bin/cmake
