tests/bunraku_catch_main_autogen/timestamp: \
  /usr/lib/cmake/Catch2/Catch.cmake \
  /usr/lib/cmake/Catch2/Catch2Config.cmake \
  /usr/lib/cmake/Catch2/Catch2ConfigVersion.cmake \
  /usr/lib/cmake/Catch2/Catch2Targets-none.cmake \
  /usr/lib/cmake/Catch2/Catch2Targets.cmake \
  /work/main/tests/CMakeLists.txt \
  /work/main/tests/support/catch_main.cpp \
  /usr/bin/cmake
