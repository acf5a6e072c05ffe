# A test whose peer is missing must fail under CI=true and be reported as skipped otherwise, never
# pass (tests/support/peer.h): a WARN followed by `return` or `continue` is a test that passes
# without its check. This check fails on any WARN( whose line or the two lines after it hold a
# `return` or a `continue`, anywhere in tests/ except the requirePeer helper itself.
# Run: cmake -DROOT=<source dir> -P check_peer_warnings.cmake
file(GLOB_RECURSE sources "${ROOT}/tests/*.cpp" "${ROOT}/tests/*.h")
list(FILTER sources EXCLUDE REGEX "/tests/support/peer\\.(cpp|h)$")
set(bad "")
foreach(source IN LISTS sources)
  file(READ "${source}" text)
  # ';' separates CMake list items: a placeholder keeps each match whole.
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REGEX MATCHALL "WARN\\([^\n]*(\n[^\n]*)?(\n[^\n]*)?" windows "${text}")
  foreach(window IN LISTS windows)
    if(window MATCHES "(^|[^A-Za-z0-9_])(return|continue)([^A-Za-z0-9_]|$)")
      string(REGEX MATCH "^WARN[^\n]*" first "${window}")
      string(REPLACE "<semicolon>" "," first "${first}")
      list(APPEND bad "${source}: ${first}")
    endif()
  endforeach()
endforeach()
if(bad)
  string(REPLACE ";" "\n  " listed "${bad}")
  message(FATAL_ERROR "a WARN followed by return/continue passes a test without its peer; use requirePeer (tests/support/peer.h):\n  ${listed}")
endif()
