app/bunraku_autogen/timestamp: \
  /work/main/app/CMakeLists.txt \
  /work/main/app/cli_main.cpp \
  /usr/bin/cmake
