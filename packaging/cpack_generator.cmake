# CPACK_PROJECT_CONFIG_FILE: settings per CPack generator. The tarball's programs are stripped
# when installed into it; the Debian generator strips them itself after copying their symbols
# into the -dbgsym package (CPACK_DEBIAN_DEBUGINFO_PACKAGE), which needs them unstripped.
if(CPACK_GENERATOR STREQUAL "TGZ")
  set(CPACK_STRIP_FILES ON)
endif()
