# `cmake --install` (issue 13): the libraries a user links into their own
# program (device_logic: the firmware alone; twin: firmware + MuJoCo plant),
# their headers, the sreh-twin tool, the models, and a CMake package so that
#   find_package(sreh_twin)
#   target_link_libraries(app sreh_twin::device_logic sreh_twin::twin)
# works. The tool finds the models relative to where it is installed
# (twin/models_dir.hpp).
include(CMakePackageConfigHelpers)

set(SREH_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/sreh_twin)
set(sreh_installed_libraries io device_logic twin) # twin uses io (atomic files, interrupt flag)

install(TARGETS ${sreh_installed_libraries} EXPORT sreh_twinTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(folder ${sreh_installed_libraries})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sreh_twin/${folder}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(TARGETS sreh-twin RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sreh_twin/models)

install(EXPORT sreh_twinTargets NAMESPACE sreh_twin:: DESTINATION ${SREH_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/sreh_twinConfig.cmake.in
  ${PROJECT_BINARY_DIR}/sreh_twinConfig.cmake INSTALL_DESTINATION ${SREH_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sreh_twinConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sreh_twinConfig.cmake ${PROJECT_BINARY_DIR}/sreh_twinConfigVersion.cmake
        DESTINATION ${SREH_INSTALL_CMAKEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/tools/completion/sreh-twin.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME sreh-twin)
