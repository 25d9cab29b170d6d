# Generates molchaos/version.hpp with the project version and the git commit of the source tree,
# refreshed at every build so a result file never carries a stale commit.
set(MOLCHAOS_VERSION_DIR ${CMAKE_BINARY_DIR}/generated)
add_custom_target(molchaos_version_header
  COMMAND ${CMAKE_COMMAND} -DSRC=${CMAKE_SOURCE_DIR} -DOUT=${MOLCHAOS_VERSION_DIR}/molchaos/version.hpp
          -DVERSION=${PROJECT_VERSION} -P ${CMAKE_SOURCE_DIR}/cmake/WriteVersion.cmake
  BYPRODUCTS ${MOLCHAOS_VERSION_DIR}/molchaos/version.hpp
  COMMENT "Recording the source version")
add_library(molchaos_version INTERFACE)
add_dependencies(molchaos_version molchaos_version_header)
target_include_directories(molchaos_version INTERFACE ${MOLCHAOS_VERSION_DIR})
