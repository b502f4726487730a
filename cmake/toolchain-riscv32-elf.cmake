# SPDX-License-Identifier: MIT
# Cross toolchain: Debian's riscv64-unknown-elf-gcc building 32-bit code,
# rv32imac / ilp32 (integer, multiply/divide, atomics, compressed; no FPU),
# freestanding, no C library (-nostdlib; libgcc for 64-bit division only).
#
#   cmake -S firmware -B build-rv32 -DCMAKE_TOOLCHAIN_FILE=cmake/toolchain-riscv32-elf.cmake
#
# The Debian package ships an rv32imac/ilp32 multilib of libgcc, which is
# what -march/-mabi below select.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)

set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_ASM_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_AR riscv64-unknown-elf-ar)
set(CMAKE_RANLIB riscv64-unknown-elf-ranlib)
set(CMAKE_OBJCOPY riscv64-unknown-elf-objcopy CACHE FILEPATH "objcopy for the target")
set(CMAKE_SIZE riscv64-unknown-elf-size CACHE FILEPATH "size for the target")
set(CMAKE_NM riscv64-unknown-elf-nm CACHE FILEPATH "nm for the target")

set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_C_FLAGS_INIT "-march=rv32imac -mabi=ilp32 -mcmodel=medlow -ffreestanding -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "-march=rv32imac -mabi=ilp32")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-march=rv32imac -mabi=ilp32 -nostdlib -nostartfiles -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
