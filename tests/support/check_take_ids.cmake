# Take ids ("corpus/N", "imported/N", "live/name") are built and read by the Document alone
# (app/document.cpp) and stored by the project file (app/project_file.cpp): no other file of the
# app spells them (comments aside); it asks Document::isCorpusTakeId, liveTakeId, ...
file(GLOB_RECURSE files ${ROOT}/app/*.h ${ROOT}/app/*.cpp)
set(failed FALSE)
foreach(f IN LISTS files)
  if(f MATCHES "/app/(document|project_file)\\.cpp$")
    continue()
  endif()
  file(STRINGS ${f} lines REGEX "\"(corpus|imported|live)/")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "//.*" "" code "${line}")
    if(code MATCHES "\"(corpus|imported|live)/")
      message(SEND_ERROR "${f}: a take id spelt outside the Document and the project file: ${line}")
      set(failed TRUE)
    endif()
  endforeach()
endforeach()
