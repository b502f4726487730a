/* SPDX-License-Identifier: MIT */
/*
 * stp_panel_run (ports/controllers/panel.c), the one walker over the
 * controllers' init, refresh and sleep sequences: records reach the bus
 * whole and in order, steps reach the step function with their 16-bit
 * argument, and a sequence cut short, a step without a step function, a
 * bus error or a step error stops it with the right status.  The SSD1306's
 * own init sequence walked to the end: its records' bytes, in order, are
 * the sequence's bytes less the counts and steps.  Rows packed into 4-bit
 * grey against their pixels.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "stp_panel.h"

typedef struct log_bus {
    uint8_t bytes[256];
    size_t count, calls, fail_at; /* fail_at: the call (1-based) that fails, 0 none */
    unsigned steps[8][2];
    size_t step_count;
} log_bus;

static int log_command(void *ctx, const uint8_t *bytes, size_t count)
{
    log_bus *b = ctx;
    b->calls++;
    if (b->fail_at == b->calls)
        return -7;
    assert_true(b->count + count <= sizeof b->bytes);
    memcpy(b->bytes + b->count, bytes, count);
    b->count += count;
    return 0;
}

static int log_step(void *ctx, unsigned op, unsigned arg)
{
    log_bus *b = ctx;
    if (op == 9u)
        return -9; /* an op this test does not know */
    assert_true(b->step_count < 8);
    b->steps[b->step_count][0] = op;
    b->steps[b->step_count][1] = arg;
    b->step_count++;
    return 0;
}

static int run(const uint8_t *seq, uint16_t length, log_bus *b, int with_step)
{
    stp_panel_bus bus;
    bus.command = log_command;
    bus.data = 0;
    bus.ctx = b;
    return stp_panel_run(seq, length, &bus, with_step ? log_step : 0, b);
}

static void test_records_and_steps(void **state)
{
    static const uint8_t seq[] = {2, 0xD5, 0x80, 0, 3, 0x34, 0x12, 1, 0xAF, 0, 1, 0xFF, 0x00};
    static const uint8_t want[] = {0xD5, 0x80, 0xAF};
    log_bus b;
    (void)state;
    memset(&b, 0, sizeof b);
    assert_int_equal(run(seq, sizeof seq, &b, 1), 0);
    assert_int_equal(b.calls, 2);
    assert_int_equal(b.count, sizeof want);
    assert_memory_equal(b.bytes, want, sizeof want);
    assert_int_equal(b.step_count, 2);
    assert_int_equal(b.steps[0][0], 3);
    assert_int_equal(b.steps[0][1], 0x1234);
    assert_int_equal(b.steps[1][0], 1);
    assert_int_equal(b.steps[1][1], 0xFF);
    memset(&b, 0, sizeof b);
    assert_int_equal(run(seq, 0, &b, 1), 0); /* an empty sequence */
    assert_int_equal(b.calls, 0);
}

static void test_errors(void **state)
{
    static const uint8_t seq[] = {2, 0xD5, 0x80, 0, 3, 0x34, 0x12, 1, 0xAF};
    static const uint8_t unknown[] = {0, 9, 0, 0, 1, 0xAF};
    log_bus b;
    uint16_t cut;
    (void)state;
    /* cut inside the first record, inside the step, and inside the last
     * record's count (1 byte of 2): each -1, nothing sent past the cut */
    for (cut = 1; cut < sizeof seq; cut++) {
        int want = (cut == 3 || cut == 7) ? 0 : -1;
        memset(&b, 0, sizeof b);
        assert_int_equal(run(seq, cut, &b, 1), want);
    }
    memset(&b, 0, sizeof b);
    assert_int_equal(run(seq, sizeof seq, &b, 0), -1); /* a step, no step function */
    assert_int_equal(b.calls, 1);
    memset(&b, 0, sizeof b);
    b.fail_at = 2;
    assert_int_equal(run(seq, sizeof seq, &b, 1), -7); /* the bus's error */
    assert_int_equal(b.step_count, 1);
    memset(&b, 0, sizeof b);
    assert_int_equal(run(unknown, sizeof unknown, &b, 1), -9); /* the step's error */
    assert_int_equal(b.calls, 0);
}

static void test_ssd1306_init(void **state)
{
    const stp_panel_controller *c = &stp_panel_ssd1306;
    uint8_t want[256];
    size_t n = 0, at = 0;
    log_bus b;
    (void)state;
    while (at < c->init_length) {
        size_t k = c->init[at];
        if (k == 0) {
            at += 4;
            continue;
        }
        memcpy(want + n, c->init + at + 1, k);
        n += k;
        at += 1 + k;
    }
    memset(&b, 0, sizeof b);
    assert_int_equal(run(c->init, c->init_length, &b, 1), 0);
    assert_int_equal(b.count, n);
    assert_memory_equal(b.bytes, want, n);
    assert_int_equal(b.bytes[0], 0xAE); /* display off first */
    assert_int_equal(b.bytes[n - 1], 0xAF); /* display on last */
}

/* stp_panel_pack_mono_row into 4-bit grey (the SSD0323's packing), every
 * width 1..24 (odd ones end on a half byte, its right pixel 0) and several
 * rows, against the pixels one by one; nothing past the packed bytes. */
static void test_grey4_rows(void **state)
{
    static const uint8_t rows[][3] = {
        {0x00, 0x00, 0x00}, {0xFF, 0xFF, 0xFF}, {0xA5, 0x3C, 0x81}, {0x5A, 0xC3, 0x7E}};
    stp_panel_controller c;
    uint8_t out[14];
    uint32_t width, x;
    size_t r;
    (void)state;
    memset(&c, 0, sizeof c);
    c.packing = STP_PANEL_GREY4_LEFT_HIGH;
    for (r = 0; r < sizeof rows / sizeof rows[0]; r++)
        for (width = 1; width <= 24u; width++) {
            memset(out, 0x99, sizeof out);
            stp_panel_pack_mono_row(&c, rows[r], width, out);
            for (x = 0; x < 24u; x++) {
                unsigned on = x < width && (rows[r][x / 8u] >> (7u - x % 8u)) & 1u;
                unsigned got = (out[x / 2u] >> (x % 2u ? 0u : 4u)) & 15u;
                if (x < (width + 1u) / 2u * 2u)
                    assert_int_equal(got, on ? STP_PANEL_GREY4_ON : 0u);
                else
                    assert_int_equal(got, 9u);
            }
            assert_int_equal(out[12], 0x99);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_records_and_steps),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_ssd1306_init),
        cmocka_unit_test(test_grey4_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
