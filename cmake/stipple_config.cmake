# SPDX-License-Identifier: MIT
# The core's build-time configuration (include/stipple/config.h) as CMake
# settings, carried to every consumer so the library and an application
# compiled against it agree on struct layouts and fixed-point formats:
#
#   STP_CONFIG_DEFINITIONS  a ;-list of switches, e.g.
#                           "STP_WITH_SHADOWS=0;STP_MAX_LIGHTS=2"
#   STP_CONFIG_HEADER       a header of #defines of switches (self-contained),
#                           installed as <stipple/user_config.h>
#
# Both become PUBLIC compile definitions of stipple_core (so INTERFACE usage
# requirements of stipple::core in the build tree, the exported package and
# add_subdirectory builds) and Cflags of stipple.pc.  A mismatch that gets past
# them (an application compiled by hand with other -D flags) fails to link:
# see include/stipple/config_guard.h.
set(STP_CONFIG_DEFINITIONS "" CACHE STRING
    "Build switches of include/stipple/config.h as a ;-list NAME=VALUE (carried to consumers)")
set(STP_CONFIG_HEADER "" CACHE FILEPATH
    "A header of STP_* switches, included first by stipple/config.h (installed as stipple/user_config.h)")

# The switches config.h knows: every "#ifndef STP_X" there.
file(STRINGS "${PROJECT_SOURCE_DIR}/include/stipple/config.h" _stp_switch_lines REGEX "^#ifndef STP_[A-Z0-9_]+$")
set(STP_CONFIG_SWITCHES "")
foreach(_line IN LISTS _stp_switch_lines)
  string(REGEX REPLACE "^#ifndef (STP_[A-Z0-9_]+)$" "\\1" _name "${_line}")
  list(APPEND STP_CONFIG_SWITCHES ${_name})
endforeach()

set(STP_CONFIG_COMPILE_DEFINITIONS "")
foreach(_def IN LISTS STP_CONFIG_DEFINITIONS)
  if(NOT _def MATCHES "^(STP_[A-Z0-9_]+)=([0-9]+)$")
    message(FATAL_ERROR "STP_CONFIG_DEFINITIONS: '${_def}' is not NAME=DECIMAL (e.g. STP_WITH_SHADOWS=0)")
  endif()
  if(NOT CMAKE_MATCH_1 IN_LIST STP_CONFIG_SWITCHES)
    message(FATAL_ERROR "STP_CONFIG_DEFINITIONS: ${CMAKE_MATCH_1} is not a switch of include/stipple/config.h "
                        "(known: ${STP_CONFIG_SWITCHES})")
  endif()
  list(APPEND STP_CONFIG_COMPILE_DEFINITIONS "${_def}")
endforeach()

set(STP_CONFIG_INCLUDE_DIR "")
if(STP_CONFIG_HEADER)
  if(NOT EXISTS "${STP_CONFIG_HEADER}")
    message(FATAL_ERROR "STP_CONFIG_HEADER: ${STP_CONFIG_HEADER} does not exist")
  endif()
  # One name in the build tree and the install tree, so the definition needs
  # no path (and no quotes that a shell would have to keep).
  set(STP_CONFIG_INCLUDE_DIR "${PROJECT_BINARY_DIR}/stipple_user_config")
  configure_file("${STP_CONFIG_HEADER}" "${STP_CONFIG_INCLUDE_DIR}/stipple/user_config.h" COPYONLY)
  list(APPEND STP_CONFIG_COMPILE_DEFINITIONS "STP_USER_CONFIG=1")
endif()

# stp_apply_config(TARGET): the configuration as TARGET's PUBLIC usage
# requirements.
function(stp_apply_config target)
  if(STP_CONFIG_COMPILE_DEFINITIONS)
    target_compile_definitions(${target} PUBLIC ${STP_CONFIG_COMPILE_DEFINITIONS})
  endif()
  if(STP_CONFIG_INCLUDE_DIR)
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${STP_CONFIG_INCLUDE_DIR}>)
  endif()
endfunction()
