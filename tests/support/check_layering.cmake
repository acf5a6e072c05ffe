# Fails when a file under analysis/ (or bindings/) includes a Qt header, or render/ includes a widgets/ or
# app/ header, or widgets/ includes an app/ header.
function(check_folder folder pattern what)
  file(GLOB_RECURSE files ${ROOT}/${folder}/*.h ${ROOT}/${folder}/*.cpp)
  foreach(f IN LISTS files)
    file(STRINGS ${f} hits REGEX "${pattern}")
    if(hits)
      message(SEND_ERROR "${f}: ${what}: ${hits}")
    endif()
  endforeach()
endfunction()
check_folder(analysis "^[ \t]*#[ \t]*include[ \t]*[<\"](Q[A-Za-z]+|qcustomplot|GL/|glm/)" "analysis/ must not include Qt, OpenGL or GLM")
check_folder(render "^[ \t]*#[ \t]*include[ \t]*\"(widgets|app)/" "render/ must not include widgets/ or app/")
check_folder(widgets "^[ \t]*#[ \t]*include[ \t]*\"app/" "widgets/ must not include app/")
# The Python module links the analysis layer alone: no Qt, OpenGL, render/ or widgets/.
check_folder(bindings "^[ \t]*#[ \t]*include[ \t]*([<\"](Q[A-Za-z]+|qcustomplot|GL/|glm/)|\"(render|widgets)/)" "bindings/ must not include Qt, OpenGL, render/ or widgets/")
