# Install rules and the exported package of vlit (docs/library.md "Installing").
include(CMakePackageConfigHelpers)

set(VLIT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/vlit)

install(TARGETS vlit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS vlit_lib EXPORT vlitTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/vlit DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(EXPORT vlitTargets NAMESPACE vlit:: DESTINATION ${VLIT_CMAKE_DIR} FILE vlitTargets.cmake)

configure_package_config_file(cmake/vlitConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/vlitConfig.cmake
                              INSTALL_DESTINATION ${VLIT_CMAKE_DIR})
# 0.x: a minor release may change the API, so only the same MAJOR.MINOR satisfies a request.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/vlitConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/vlitConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/vlitConfigVersion.cmake
        DESTINATION ${VLIT_CMAKE_DIR})

# pkg-config: relocatable (prefix found from the .pc file's own directory).
file(RELATIVE_PATH VLIT_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" VLIT_PC_TO_PREFIX "${VLIT_PC_TO_PREFIX}")
configure_file(cmake/vlit.pc.in ${CMAKE_CURRENT_BINARY_DIR}/vlit.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/vlit.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

include(cmake/packaging.cmake)
