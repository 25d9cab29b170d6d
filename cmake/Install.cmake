# Installation and the exported CMake package: `cmake --install build --prefix <dir>` puts the
# program, the headers of theory/ and sim/, their libraries and molchaosConfig.cmake under <dir>, so
# that another project can `find_package(molchaos)` and link molchaos::theory and molchaos::sim.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(MOLCHAOS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/molchaos)

set(molchaos_exported_libraries theory)
if(TARGET molchaos_sim)
  list(APPEND molchaos_exported_libraries sim)
endif()
list(TRANSFORM molchaos_exported_libraries PREPEND molchaos_ OUTPUT_VARIABLE molchaos_exported_targets)

# Include directories: the source tree while building, <prefix>/include once installed.
# Every directory a library already exports (its include/ and, for theory, the header the
# symbolic derivation generates) is kept for the build and installed under <prefix>/include.
foreach(lib ${molchaos_exported_libraries})
  get_target_property(molchaos_build_includes molchaos_${lib} INTERFACE_INCLUDE_DIRECTORIES)
  set(molchaos_interface_includes "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  foreach(dir ${molchaos_build_includes})
    list(APPEND molchaos_interface_includes "$<BUILD_INTERFACE:${dir}>")
    install(DIRECTORY ${dir}/molchaos DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endforeach()
  set_target_properties(molchaos_${lib} PROPERTIES
    EXPORT_NAME ${lib}
    INTERFACE_INCLUDE_DIRECTORIES "${molchaos_interface_includes}")
endforeach()

# The static libraries name their private helpers (warning flags, the generated version header)
# as link-only dependencies, so those travel in the export set too; their settings apply only
# inside this build.
get_target_property(molchaos_warning_flags molchaos_warnings INTERFACE_COMPILE_OPTIONS)
set_target_properties(molchaos_warnings PROPERTIES
  INTERFACE_COMPILE_OPTIONS "$<BUILD_INTERFACE:${molchaos_warning_flags}>"
  EXPORT_NAME detail_warnings)
set_target_properties(molchaos_version PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "$<BUILD_INTERFACE:${MOLCHAOS_VERSION_DIR}>"
  EXPORT_NAME detail_version)

install(TARGETS ${molchaos_exported_targets} molchaos_warnings molchaos_version
        EXPORT molchaosTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS molchaos RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT molchaosTargets NAMESPACE molchaos:: DESTINATION ${MOLCHAOS_CMAKE_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CITATION.cff
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/molchaosConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/molchaosConfig.cmake
                              INSTALL_DESTINATION ${MOLCHAOS_CMAKE_DIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/molchaosConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/molchaosConfig.cmake
              ${CMAKE_BINARY_DIR}/molchaosConfigVersion.cmake
        DESTINATION ${MOLCHAOS_CMAKE_DIR})
