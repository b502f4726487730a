/* SPDX-License-Identifier: MIT */
/* Private: alignment checks of caller memory. */
#ifndef STIPPLE_ALIGN_PRIVATE_H
#define STIPPLE_ALIGN_PRIVATE_H

#include <stddef.h>
#include <stdint.h>

/* 1 when p is a multiple of alignment (a power of two) */
static inline int stp_is_aligned(const void *p, size_t alignment)
{
    return ((uintptr_t)p & (uintptr_t)(alignment - 1u)) == 0;
}

#endif
