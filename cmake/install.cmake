# Install rules: the libraries (Linux: libdemcontact.so.<version> with the SONAME and
# development symlinks), headers and Fortran sources/modules, the CMake package
# (find_package(demcontact CONFIG)) and the relocatable pkg-config file.

install(FILES "${DC_SHARED}" DESTINATION "${CMAKE_INSTALL_LIBDIR}" RENAME "${DC_SHARED_REAL}")
if(NOT DC_SHARED_REAL STREQUAL DC_SHARED_NAME)
  install(CODE "
    set(_d \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}\")
    execute_process(COMMAND \"${CMAKE_COMMAND}\" -E create_symlink ${DC_SHARED_REAL} \"\${_d}/${DC_SONAME}\")
    execute_process(COMMAND \"${CMAKE_COMMAND}\" -E create_symlink ${DC_SONAME} \"\${_d}/${DC_SHARED_NAME}\")
  ")
endif()
install(FILES "${DC_STATIC}" DESTINATION "${CMAKE_INSTALL_LIBDIR}")
# The command-line tool (src/bin/demcontact), built by the same cargo call.
install(PROGRAMS "${DC_LIB_DIR}/demcontact${CMAKE_EXECUTABLE_SUFFIX}" DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(DIRECTORY include/ DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp" PATTERN "*.f90")
if(TARGET demcontact_fortran)
  install(TARGETS demcontact_fortran ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
  install(DIRECTORY "${CMAKE_BINARY_DIR}/fortran_modules/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
endif()

set(DC_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/demcontact")
configure_package_config_file(cmake/demcontactConfig.cmake.in
  "${CMAKE_BINARY_DIR}/demcontactConfig.cmake"
  INSTALL_DESTINATION "${DC_CMAKE_DIR}"
  PATH_VARS CMAKE_INSTALL_LIBDIR CMAKE_INSTALL_INCLUDEDIR)
write_basic_package_version_file("${CMAKE_BINARY_DIR}/demcontactConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_BINARY_DIR}/demcontactConfig.cmake" "${CMAKE_BINARY_DIR}/demcontactConfigVersion.cmake"
        DESTINATION "${DC_CMAKE_DIR}")
file(RELATIVE_PATH DC_PC_TO_PREFIX "/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/")
string(REGEX REPLACE "/$" "" DC_PC_TO_PREFIX "${DC_PC_TO_PREFIX}")
configure_file(cmake/demcontact.pc.in "${CMAKE_BINARY_DIR}/demcontact.pc" @ONLY)
install(FILES "${CMAKE_BINARY_DIR}/demcontact.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
