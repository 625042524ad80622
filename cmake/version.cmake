# The version string every provenance record carries: `git describe` of the
# last commit that changed the code (write_version.cmake), refreshed at every
# build but rewritten only when it changes, so that unchanged code does not
# relink every tool.
set(MESOWAVE_VERSION_CPP ${CMAKE_BINARY_DIR}/generated/version.cpp)
add_custom_target(mesowave_version_stamp
  COMMAND ${CMAKE_COMMAND}
          -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
          -DOUTPUT=${MESOWAVE_VERSION_CPP}
          -DFALLBACK=${PROJECT_VERSION}
          -P ${CMAKE_SOURCE_DIR}/cmake/write_version.cmake
  BYPRODUCTS ${MESOWAVE_VERSION_CPP}
  COMMENT "Stamping git describe into the version")
