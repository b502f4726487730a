# SPDX-License-Identifier: MIT
# Cross toolchain: Debian's arm-none-eabi-gcc for a Cortex-M without FPU.
#
#   cmake -S firmware -B build-fw \
#         -DCMAKE_TOOLCHAIN_FILE=cmake/toolchain-arm-none-eabi.cmake -DSTP_CPU=cortex-m3
#
# STP_CPU picks the core: cortex-m0plus (default), cortex-m3 or cortex-m4.
# -mfloat-abi=soft on every CPU, the M4 included: the core is integer only,
# so no FPU instruction and no soft-float routine may appear; the firmware
# build checks the linked image for __aeabi_f*/__aeabi_d* symbols.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(STP_CPU "cortex-m0plus" CACHE STRING "Cortex-M core: cortex-m0plus, cortex-m3 or cortex-m4")
set_property(CACHE STP_CPU PROPERTY STRINGS cortex-m0plus cortex-m3 cortex-m4)
if(NOT STP_CPU MATCHES "^cortex-m(0plus|3|4)$")
  message(FATAL_ERROR "STP_CPU='${STP_CPU}': use cortex-m0plus, cortex-m3 or cortex-m4")
endif()
# try_compile projects re-read this file in a fresh cache: hand STP_CPU on.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES STP_CPU)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar)
set(CMAKE_RANLIB arm-none-eabi-ranlib)
set(CMAKE_OBJCOPY arm-none-eabi-objcopy CACHE FILEPATH "objcopy for the target")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "size for the target")
set(CMAKE_NM arm-none-eabi-nm CACHE FILEPATH "nm for the target")

# There is no OS to run a test executable on: check the compiler by building
# a static library only.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# -ffunction-sections/-fdata-sections with --gc-sections at link time: what
# a scene does not call (lines, painter, gamma tables...) is dropped.
set(CMAKE_C_FLAGS_INIT "-mcpu=${STP_CPU} -mthumb -mfloat-abi=soft -ffreestanding -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=${STP_CPU} -mthumb")
# No C library and no start files: the port brings its own vector table,
# reset handler, memcpy and memset.  libgcc stays (-lgcc is added by the
# firmware project) for the 64-bit integer division helpers the core's
# 64-bit arithmetic calls (__aeabi_ldivmod and, on M0+, __aeabi_idiv).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-mcpu=${STP_CPU} -mthumb -mfloat-abi=soft -nostdlib -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
