# SPDX-License-Identifier: MIT
# The core built once per configuration.  A test, bench or tool that needs
# the core under other switches than stipple_core links the static library
# of that configuration instead of compiling src/*.c into itself:
#
#   stp_core_configuration(NAME DEFINITION...)
#       defines stipple_core_NAME (once: a second call with the same NAME
#       and definitions is a no-op, with others an error), its definitions
#       PUBLIC so whatever links it is compiled with the same switches.
#
# The configurations the project ships, on the host (their arithmetic and
# switches; the real chips run them in tests/firmware, tests/avr and
# tools/bench/mps2_torus.sh):
#   host            stipple_core: the defaults, the host's 64-bit arithmetic
#   m0plus_full     the defaults on the 32-bit target arithmetic
#                   (STP_WIDE_ARITH=0: no 32 x 32 -> 64 multiply, no count
#                   of leading zeros, no hardware divide, as on a Cortex-M0+)
#   m0plus_minimal  the least core a flat scene on a panel of rows needs, on
#                   the same arithmetic
#   avr             a compiled scene's switches (`stipple compile`), on the
#                   same arithmetic
#   arduino         the Arduino library's switches (ports/arduino/src/
#                   stipple_config.h: diffuse only, one light, the face
#                   shader's compact route) on the AVR's arithmetic (no
#                   32-bit multiply either: STP_HAVE_MUL32=0)
set(STP_CONFIG_m0plus_full STP_WIDE_ARITH=0)
set(STP_CONFIG_m0plus_minimal STP_WIDE_ARITH=0 STP_WITH_GOURAUD=0 STP_WITH_COLOUR=0 STP_WITH_TRANSPARENCY=0
    STP_WITH_SHADOWS=0 STP_WITH_RAYTRACE=0 STP_WITH_EDGE_AA=0 STP_VERTEX_CACHE=0 STP_WITH_PAGES=0)
set(STP_CONFIG_avr STP_WIDE_ARITH=0 STP_WITH_SPECULAR=0 STP_MAX_LIGHTS=1 STP_MAX_SEGMENTS=1
    STP_WITH_LINES=0 STP_WITH_GOURAUD=0 STP_WITH_COLOUR=0 STP_WITH_TRANSPARENCY=0 STP_WITH_SHADOWS=0
    STP_VERTEX_CACHE=0 STP_WITH_EDGE_AA=0 STP_WITH_RAYTRACE=0 STP_WITH_PAINTER=0)
set(STP_CONFIG_arduino STP_WIDE_ARITH=0 STP_HAVE_MUL32=0 STP_WITH_SPECULAR=0 STP_MAX_LIGHTS=1 STP_SHADE_COMPACT=1
    STP_DIRECT_COMPACT=1)
set(STP_SHIPPED_CONFIGURATIONS m0plus_full m0plus_minimal avr arduino)

function(stp_core_configuration name)
  set(_defs ${ARGN})
  if(TARGET stipple_core_${name})
    get_target_property(_had stipple_core_${name} STP_CONFIGURATION)
    if(NOT "${_had}" STREQUAL "${_defs}")
      message(FATAL_ERROR "stipple_core_${name}: defined with '${_had}', now asked with '${_defs}'")
    endif()
    return()
  endif()
  get_target_property(_sources stipple_core SOURCES)
  get_target_property(_dir stipple_core SOURCE_DIR)
  set(_paths "")
  foreach(_src IN LISTS _sources)
    if(IS_ABSOLUTE "${_src}")
      list(APPEND _paths "${_src}")
    else()
      list(APPEND _paths "${_dir}/${_src}")
    endif()
  endforeach()
  add_library(stipple_core_${name} STATIC ${_paths})
  set_target_properties(stipple_core_${name} PROPERTIES STP_CONFIGURATION "${_defs}")
  target_include_directories(stipple_core_${name} PUBLIC ${PROJECT_SOURCE_DIR}/include PRIVATE ${_dir})
  if(_defs)
    target_compile_definitions(stipple_core_${name} PUBLIC ${_defs})
  endif()
  stp_apply_config(stipple_core_${name})
  target_compile_options(stipple_core_${name} PRIVATE -Wconversion -Wno-sign-conversion
                         -Wstrict-prototypes -Wmissing-prototypes -Wcast-align -Wvla)
endfunction()
