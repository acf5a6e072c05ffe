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
  if(BUNRAKU_TSAN) # scripts/tsan.sh: the workbench's threads (docs/RELIABILITY.md)
    target_compile_options(${target} PRIVATE -fsanitize=thread -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=thread)
  endif()
  if(BUNRAKU_FUZZ) # the sanitizers that turn bugs into findings, and libFuzzer's coverage
    # The coverage only where the fuzz targets read (the analysis layer and the targets
    # themselves): the tests and the Qt layers the sanitizer build also holds have no use for
    # it, and it slows their compilation and their runs (docs/PERFORMANCE.md, "Build").
    set(sanitizers address,undefined)
    if(target MATCHES "^(bunraku_analysis_|fuzz_)")
      set(sanitizers fuzzer-no-link,address,undefined)
    endif()
    target_compile_options(${target} PRIVATE -fsanitize=${sanitizers} -fno-omit-frame-pointer -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# bunraku_precompile(TARGET KIND): precompiled third-party headers (BUNRAKU_PCH), the one
# measure that keeps a clean build of this tree on two cores short (docs/PERFORMANCE.md, "Build").
# Project headers are never precompiled: a TU sees exactly the project headers it includes. The
# analysis modules are not precompiled: their time goes to instantiating Eigen, not to parsing,
# and gcc 12 at -O3 warns (-Warray-bounds, a known false positive in std::string) in some of them
# when the standard headers come first.
#   tests      the standard library, Eigen and Catch2 (every non-Qt test reuses one)
#   qt-tests   those and QtWidgets (every Qt test reuses one; not QtTest, which not all link)
#   qt-gui     the standard library, Eigen and QtGui (render)
#   qt         the standard library, Eigen and QtWidgets (widgets, app, cli: one each)
set(BUNRAKU_PCH_STD <algorithm> <array> <cmath> <filesystem> <functional> <map> <memory> <optional> <string> <vector>)
function(bunraku_precompile target kind)
  if(NOT BUNRAKU_PCH)
    return()
  endif()
  if(kind STREQUAL "tests")
    target_precompile_headers(${target} PRIVATE ${BUNRAKU_PCH_STD} <Eigen/Core> <Eigen/Geometry> <catch2/catch.hpp>)
  elseif(kind STREQUAL "qt-tests")
    target_precompile_headers(${target} PRIVATE ${BUNRAKU_PCH_STD} <Eigen/Core> <Eigen/Geometry> <catch2/catch.hpp> <QtWidgets>)
  elseif(kind STREQUAL "qt-gui")
    target_precompile_headers(${target} PRIVATE ${BUNRAKU_PCH_STD} <Eigen/Core> <Eigen/Geometry> <QtGui>)
  elseif(kind STREQUAL "qt")
    target_precompile_headers(${target} PRIVATE ${BUNRAKU_PCH_STD} <Eigen/Core> <Eigen/Geometry> <QtWidgets>)
  else()
    message(FATAL_ERROR "bunraku_precompile: unknown kind ${kind}")
  endif()
endfunction()

# Targets whose precompiled headers others reuse (REUSE_FROM: one header compile for many
# targets built with the same flags).
# A header compiled with other macros than a target's (a Qt module more or less) is not used
# (gcc falls back to reading the headers, with a warning), never an error.
function(bunraku_reuse_precompiled target from)
  if(BUNRAKU_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
    target_compile_options(${target} PRIVATE -Wno-error=invalid-pch)
  endif()
endfunction()

# Test code at -O1 in optimised builds: the code under test is the libraries', compiled as the
# programs are; the tests' own TUs (Catch2's expansions, fixtures) compile about twice as fast,
# and gcc 12's -O2/-O3 false positives in std::string (-Warray-bounds) stay out of them.
function(bunraku_test_optimisation target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release,RelWithDebInfo>:-O1>)
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

# bunraku_add_test(NAME SOURCES ... LIBS ... [QT] [TIMEOUT seconds] [COST n])
# A Catch2 v2 executable whose cases ctest lists one by one. QT tests use a main that creates
# a QApplication (run them under xvfb-run). COST: ctest --parallel starts costlier cases first,
# before it has timings of its own (a fresh clone): the slowest suite does not run alone last.
function(bunraku_add_test name)
  cmake_parse_arguments(T "QT" "TIMEOUT;COST" "SOURCES;LIBS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  if(NOT T_COST)
    set(T_COST 0)
  endif()
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
  bunraku_test_optimisation(${name})
  if(T_QT)
    bunraku_reuse_precompiled(${name} bunraku_pch_qt-tests)
  elseif(BUNRAKU_PCH)
    # -fPIC as Qt's targets add it, so that a test linking a Qt layer (tests_cli) and one that
    # does not compile with the same flags as the header they share.
    target_compile_options(${name} PRIVATE -fPIC)
    bunraku_reuse_precompiled(${name} bunraku_pch_tests)
  endif()
  # A case whose peer is missing prints "bunraku-test: skipped:" (tests/support/peer.h): ctest
  # reports it as skipped, not passed (under CI=true it fails instead).
  catch_discover_tests(${name} TEST_PREFIX "${name}: " PROPERTIES TIMEOUT ${T_TIMEOUT} COST ${T_COST}
                       SKIP_REGULAR_EXPRESSION "bunraku-test: skipped:")
endfunction()
