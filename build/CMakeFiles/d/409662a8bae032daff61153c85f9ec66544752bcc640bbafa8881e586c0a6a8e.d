app/bunraku_cli_autogen/timestamp: \
  /work/main/app/CMakeLists.txt \
  /work/main/app/cli/cli.cpp \
  /work/main/app/cli/cli.h \
  /work/main/app/cli/cmd_axis.cpp \
  /work/main/app/cli/cmd_decompose.cpp \
  /work/main/app/cli/cmd_demo.cpp \
  /work/main/app/cli/cmd_io.cpp \
  /work/main/app/cli/cmd_normalise.cpp \
  /work/main/app/cli/cmd_render.cpp \
  /work/main/app/cli/commands.cpp \
  /work/main/app/cli/commands.h \
  /usr/bin/cmake
