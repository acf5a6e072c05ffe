# Every Catch test case must run when ctest runs it. catch_discover_tests registers each case by
# its name (escaping '[', ']', ',' and '\' for Catch), but a ';' splits the name for ctest into
# a list: the registered "test" then matches no case and passes without running anything.
# This check fails on any TEST_CASE name holding a ';'.
# Run: cmake -DROOT=<source dir> -P check_test_names.cmake
file(GLOB_RECURSE sources "${ROOT}/tests/*.cpp" "${ROOT}/tests/*.h")
set(bad "")
foreach(source IN LISTS sources)
  file(READ "${source}" text)
  # file(READ) keeps ';' inside the string; the match is on one line of the source.
  string(REGEX MATCHALL "TEST_CASE\\(\"[^\"\n]*;[^\"\n]*\"" found "${text}")
  if(found)
    string(REPLACE ";" "<;>" shown "${found}")
    list(APPEND bad "${source}: ${shown}")
  endif()
endforeach()
if(bad)
  string(REPLACE ";" "\n  " listed "${bad}")
  message(FATAL_ERROR "test names with ';', which ctest runs as names matching no case:\n  ${listed}")
endif()
