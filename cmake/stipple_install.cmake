# SPDX-License-Identifier: MIT
# cmake --install: the libraries with an export set (imported as stipple::core
# and stipple::posix by find_package(stipple); stipple::posix_png, which needs
# libpng, and stipple::posix_gif, which needs giflib, in export sets of their
# own loaded only for the components "png" and "gif" or when the library is
# found),
# the public headers, the CMake package files and stipple.pc /
# stipple-posix.pc / stipple-posix-png.pc for pkg-config.  Every library of
# the installed API that is built is installed; the other archives in the
# build tree (the command's own parts: scene readers, Linux device ports) are
# pieces of the stipple command, not a library interface.  Paths are
# GNUInstallDirs'; other install rules (the stipple command below, man pages,
# completions) use the same variables, so there is one layout.
include(CMakePackageConfigHelpers)

set(STP_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/stipple" CACHE STRING
    "Where stippleConfig.cmake is installed, relative to the prefix")

set(_stp_install_targets stipple_core)
if(TARGET stipple_posix)
  list(APPEND _stp_install_targets stipple_posix)
endif()
install(TARGETS ${_stp_install_targets} EXPORT stippleTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        PUBLIC_HEADER DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stipple/posix
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/stipple" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
if(STP_CONFIG_INCLUDE_DIR)
  install(FILES "${STP_CONFIG_INCLUDE_DIR}/stipple/user_config.h"
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stipple)
endif()
if(TARGET stipple)
  install(TARGETS stipple RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(EXPORT stippleTargets NAMESPACE stipple:: FILE stippleTargets.cmake
        DESTINATION ${STP_INSTALL_CMAKEDIR})
if(TARGET stipple_posix_png)
  install(TARGETS stipple_posix_png EXPORT stipplePngTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          PUBLIC_HEADER DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stipple/posix
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT stipplePngTargets NAMESPACE stipple:: FILE stipplePngTargets.cmake
          DESTINATION ${STP_INSTALL_CMAKEDIR})
endif()
if(TARGET stipple_posix_gif)
  install(TARGETS stipple_posix_gif EXPORT stippleGifTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          PUBLIC_HEADER DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stipple/posix
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT stippleGifTargets NAMESPACE stipple:: FILE stippleGifTargets.cmake
          DESTINATION ${STP_INSTALL_CMAKEDIR})
endif()
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/stippleConfig.cmake.in"
                              "${PROJECT_BINARY_DIR}/stippleConfig.cmake"
                              INSTALL_DESTINATION ${STP_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API (semantic versioning), so only
# the same major.minor satisfies a request.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/stippleConfigVersion.cmake"
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/stippleConfig.cmake" "${PROJECT_BINARY_DIR}/stippleConfigVersion.cmake"
        DESTINATION ${STP_INSTALL_CMAKEDIR})

# pkg-config: paths relative to the .pc file (${pcfiledir}), so the tree can
# be installed under any prefix (cmake --install --prefix, DESTDIR).
set(STP_PC_DIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
file(RELATIVE_PATH STP_PC_TO_PREFIX "/prefix/${STP_PC_DIR}" "/prefix")
string(REGEX REPLACE "/$" "" STP_PC_TO_PREFIX "${STP_PC_TO_PREFIX}")
set(STP_PC_CFLAGS "")
foreach(_def IN LISTS STP_CONFIG_COMPILE_DEFINITIONS)
  string(APPEND STP_PC_CFLAGS " -D${_def}")
endforeach()
configure_file("${PROJECT_SOURCE_DIR}/cmake/stipple.pc.in" "${PROJECT_BINARY_DIR}/stipple.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/stipple.pc" DESTINATION ${STP_PC_DIR})
if(TARGET stipple_posix)
  configure_file("${PROJECT_SOURCE_DIR}/cmake/stipple-posix.pc.in" "${PROJECT_BINARY_DIR}/stipple-posix.pc" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/stipple-posix.pc" DESTINATION ${STP_PC_DIR})
endif()
if(TARGET stipple_posix_png)
  configure_file("${PROJECT_SOURCE_DIR}/cmake/stipple-posix-png.pc.in" "${PROJECT_BINARY_DIR}/stipple-posix-png.pc" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/stipple-posix-png.pc" DESTINATION ${STP_PC_DIR})
endif()
