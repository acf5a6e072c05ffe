# Additional clean files
cmake_minimum_required(VERSION 3.16)

if("${CONFIG}" STREQUAL "" OR "${CONFIG}" STREQUAL "Release")
  file(REMOVE_RECURSE
  "app/CMakeFiles/bunraku_autogen.dir/AutogenUsed.txt"
  "app/CMakeFiles/bunraku_autogen.dir/ParseCache.txt"
  "app/CMakeFiles/bunraku_cli_autogen.dir/AutogenUsed.txt"
  "app/CMakeFiles/bunraku_cli_autogen.dir/ParseCache.txt"
  "app/bunraku_autogen"
  "app/bunraku_cli_autogen"
  )
endif()
