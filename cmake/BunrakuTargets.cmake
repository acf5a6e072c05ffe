# Shared settings for project targets: warnings (errors with BUNRAKU_WERROR), sanitizers, and
# the repository root as the include root (`#include "analysis/core/take.h"`).

function(bunraku_configure_target target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local> -Wnon-virtual-dtor)
  if(BUNRAKU_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(BUNRAKU_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(BUNRAKU_FUZZ) # coverage for libFuzzer, and the sanitizers that turn bugs into findings
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# bunraku_analysis_module(NAME SOURCES a.cpp ... [DEPENDS bunraku_analysis_core ...])
# One static library per analysis module folder; it sees only the standard library, Eigen,
# nlohmann-json and the modules it names. Qt is never on its include path.
function(bunraku_analysis_module name)
  cmake_parse_arguments(M "" "" "SOURCES;DEPENDS" ${ARGN})
  set(target bunraku_analysis_${name})
  add_library(${target} STATIC ${M_SOURCES})
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${target} PUBLIC Eigen3::Eigen nlohmann_json::nlohmann_json ${M_DEPENDS})
  target_compile_features(${target} PUBLIC cxx_std_20)
  # The Python module (bindings/python) links these static libraries into a shared object.
  # Without semantic interposition GCC inlines as it does for the executables.
  if(BUNRAKU_PYTHON)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-fno-semantic-interposition>)
  endif()
  bunraku_configure_target(${target})
  set_property(GLOBAL APPEND PROPERTY BUNRAKU_ANALYSIS_MODULES ${target})
endfunction()

# bunraku_add_test(NAME SOURCES ... LIBS ... [QT])
# A Catch2 v2 executable whose cases ctest lists one by one. QT tests use a main that creates
# a QApplication (run them under xvfb-run).
function(bunraku_add_test name)
  cmake_parse_arguments(T "QT" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  if(T_QT)
    target_link_libraries(${name} PRIVATE bunraku_catch_qt_main)
  else()
    target_link_libraries(${name} PRIVATE bunraku_catch_main)
  endif()
  target_link_libraries(${name} PRIVATE ${T_LIBS})
  target_compile_definitions(${name} PRIVATE
    BUNRAKU_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    BUNRAKU_SHARED_DIR="${BUNRAKU_SHARED_DIR}"
    BUNRAKU_BINARY_DIR="${CMAKE_BINARY_DIR}")
  bunraku_configure_target(${name})
  # A case whose peer is missing prints "bunraku-test: skipped:" (tests/support/peer.h): ctest
  # reports it as skipped, not passed (under CI=true it fails instead).
  catch_discover_tests(${name} TEST_PREFIX "${name}: " PROPERTIES TIMEOUT 600 SKIP_REGULAR_EXPRESSION "bunraku-test: skipped:")
endfunction()
