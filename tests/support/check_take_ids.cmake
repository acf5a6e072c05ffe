# Take ids are values (app/take_id.h: TakeId::corpus(N), imported(N), live(name)). Their text
# ("corpus/N", "imported/N", "live/name") is written by TakeId::toString (app/take_id.cpp) and read
# by the project file alone (app/project_file.cpp): no other file of the app spells it (comments
# aside); it asks TakeId::kind(), index() and name().
file(GLOB_RECURSE files ${ROOT}/app/*.h ${ROOT}/app/*.cpp)
set(failed FALSE)
foreach(f IN LISTS files)
  if(f MATCHES "/app/(take_id|project_file)\\.cpp$")
    continue()
  endif()
  file(STRINGS ${f} lines REGEX "\"(corpus|imported|live)/")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "//.*" "" code "${line}")
    if(code MATCHES "\"(corpus|imported|live)/")
      message(SEND_ERROR "${f}: a take id spelt outside TakeId and the project file: ${line}")
      set(failed TRUE)
    endif()
  endforeach()
endforeach()
