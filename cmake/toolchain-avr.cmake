# SPDX-License-Identifier: MIT
# Cross toolchain: Debian's avr-gcc (gcc-avr, avr-libc, binutils-avr) for an
# 8-bit AVR, where int is 16 bits.
#
#   cmake -S firmware -B build-avr -DCMAKE_TOOLCHAIN_FILE=cmake/toolchain-avr.cmake \
#         -DSTP_FW_BOARD=atmega2560 -DSTP_FW_COMPILE_TOOL=$PWD/build/tools/stipple
#
# STP_AVR_MCU picks the part (default atmega2560: 256 KB flash, 8 KB SRAM).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR avr)

set(STP_AVR_MCU "atmega2560" CACHE STRING "AVR part for -mmcu")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES STP_AVR_MCU)

set(CMAKE_C_COMPILER avr-gcc)
set(CMAKE_CXX_COMPILER avr-g++)
set(CMAKE_AR avr-ar)
set(CMAKE_RANLIB avr-ranlib)
set(CMAKE_OBJCOPY avr-objcopy CACHE FILEPATH "objcopy for the target")
set(CMAKE_SIZE avr-size CACHE FILEPATH "size for the target")
set(CMAKE_NM avr-nm CACHE FILEPATH "nm for the target")

set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Sections per function and object, dropped at link time when unused.
# avr-libc stays linked (memcpy, memset and the start-up code).
set(CMAKE_C_FLAGS_INIT "-mmcu=${STP_AVR_MCU} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "-mmcu=${STP_AVR_MCU} -ffunction-sections -fdata-sections")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-mmcu=${STP_AVR_MCU} -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
