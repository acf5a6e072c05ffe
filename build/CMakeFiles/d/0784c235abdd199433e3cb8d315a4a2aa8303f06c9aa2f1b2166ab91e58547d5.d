analysis/core/bunraku_analysis_core_autogen/timestamp: \
  /work/main/analysis/core/CMakeLists.txt \
  /work/main/analysis/core/corpus.cpp \
  /work/main/analysis/core/corpus.h \
  /work/main/analysis/core/pose.cpp \
  /work/main/analysis/core/pose.h \
  /work/main/analysis/core/puppet_layout.cpp \
  /work/main/analysis/core/puppet_layout.h \
  /work/main/analysis/core/take.cpp \
  /work/main/analysis/core/take.h \
  /usr/bin/cmake
