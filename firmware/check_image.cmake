# SPDX-License-Identifier: MIT
# Fails when a firmware image links a floating-point routine (the core must
# be integer only: no soft float) or a C library allocator/stdio function.
# cmake -DNM=arm-none-eabi-nm -DIMAGE=fw.elf -P check_image.cmake
execute_process(COMMAND "${NM}" "${IMAGE}" OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} ${IMAGE} failed")
endif()
string(REGEX MATCHALL "[^\n]* (__aeabi_[fd][a-z0-9]*|__(add|sub|mul|div|neg|fix|float|extend|trunc)[sd]f[a-z0-9]*|malloc|free|printf|puts|_sbrk)\n" bad "${symbols}")
if(bad)
  message(FATAL_ERROR "${IMAGE} links what firmware must not use:\n${bad}")
endif()
