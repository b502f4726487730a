/* SPDX-License-Identifier: MIT */
/*
 * Shared by the libFuzzer targets in this folder: a reader that turns the
 * fuzz input into numbers (past the end it yields zeros, so every input is
 * usable), and a check that aborts with a message, which libFuzzer reports
 * as a crash and saves as a reproducer.
 */
#ifndef STP_FUZZ_COMMON_H
#define STP_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A broken invariant: report where and what, then abort (a finding). */
#define FZ_CHECK(cond, ...)                                                          \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
            fprintf(stderr, __VA_ARGS__);                                            \
            fputc('\n', stderr);                                                     \
            abort();                                                                 \
        }                                                                            \
    } while (0)

typedef struct fz_reader {
    const uint8_t *p;
    size_t left;
} fz_reader;

static inline void fz_init(fz_reader *in, const uint8_t *data, size_t size)
{
    in->p = data;
    in->left = size;
}

static inline int fz_done(const fz_reader *in)
{
    return in->left == 0;
}

static inline uint8_t fz_u8(fz_reader *in)
{
    if (in->left == 0)
        return 0;
    in->left--;
    return *in->p++;
}

static inline uint16_t fz_u16(fz_reader *in)
{
    uint16_t hi = fz_u8(in);
    return (uint16_t)((hi << 8) | fz_u8(in));
}

static inline uint32_t fz_u32(fz_reader *in)
{
    uint32_t hi = fz_u16(in);
    return (hi << 16) | fz_u16(in);
}

/* A value in lo..hi (hi - lo < 65536), from one byte when the range fits. */
static inline int fz_range(fz_reader *in, int lo, int hi)
{
    unsigned span = (unsigned)(hi - lo) + 1u;
    unsigned v = span <= 256u ? fz_u8(in) : fz_u16(in);
    return lo + (int)(v % span);
}

#endif
