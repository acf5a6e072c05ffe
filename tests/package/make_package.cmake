# ctest fixture "package": builds the package as a user would (cmake --build BUILD_DIR --target
# package), then unpacks the .deb with dpkg -x into STAGE/root - a folder outside the build and
# source trees - and copies the .deb and its -dbgsym .ddeb to STAGE/package.deb and
# STAGE/package-dbgsym.ddeb for tests_package.
#   cmake -DBUILD_DIR=... -DSTAGE=... -DDEB=name.deb -DDDEB=name.ddeb -P make_package.cmake
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target package RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "cmake --build ${BUILD_DIR} --target package failed")
endif()
foreach(file ${DEB} ${DDEB})
  if(NOT EXISTS ${BUILD_DIR}/${file})
    message(FATAL_ERROR "the package target did not make ${BUILD_DIR}/${file}")
  endif()
endforeach()
file(REMOVE_RECURSE ${STAGE})
file(MAKE_DIRECTORY ${STAGE}/root)
file(COPY_FILE ${BUILD_DIR}/${DEB} ${STAGE}/package.deb)
file(COPY_FILE ${BUILD_DIR}/${DDEB} ${STAGE}/package-dbgsym.ddeb)
execute_process(COMMAND dpkg -x ${STAGE}/package.deb ${STAGE}/root RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "dpkg -x ${STAGE}/package.deb failed")
endif()
message(STATUS "unpacked ${DEB} into ${STAGE}/root")
