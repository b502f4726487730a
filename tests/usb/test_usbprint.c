/* SPDX-License-Identifier: MIT */
/*
 * The USB receipt printer port through the real libusb-1.0, talking usbfs to
 * an emulated printer (printer_sim.c) under umockdev.  Run under
 * umockdev-wrapper.  Asserts the exact bytes of print jobs, the paper-out
 * refusal, the usblp detach/claim/release/reattach sequence and the stall,
 * timeout and unplug errors.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "printer_sim.h"
#include "render_scene.h"
#include "scene.h"
#include "stp_posix.h"
#include "stp_usbprint.h"

static const char scene_text[] =
    "v\nfrom 0 -5 2\nat 0 0 0.3\nup 0 0 1\nangle 40\nhither 1\nresolution 64 64\n"
    "l -4 -5 6\n"
    "f 0.9 0.9 0.9 1 0 0 0 0\n"
    "p 4\n-3 -2 0\n3 -2 0\n3 3 0\n-3 3 0\n"
    "f 0.6 0.6 0.6 0.7 0.3 20 0 0\n"
    "s 0.3 0.5 0.9 0.9\n";

typedef struct {
    printer_sim *sim;
} fixture;

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof *f);
    f->sim = printer_sim_new();
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    printer_sim_free(f->sim);
    free(f);
    return 0;
}

static void assert_logged(printer_sim *sim, const char *line)
{
    if (!printer_sim_logged(sim, line)) {
        char *t = printer_sim_log_text(sim);
        print_error("missing \"%s\" in the device log: %s\n", line, t);
        g_free(t);
        fail();
    }
}

static void opts(stp_usbprint_options *o, uint32_t w, uint32_t h)
{
    stp_usbprint_options_default(o);
    o->vendor_id = SIM_VID;
    o->product_id = SIM_PID;
    o->width = w;
    o->height = h;
}

/* The expected job for a MONO1 picture sent in bands of band_rows rows:
 * written from the ESC/POS command descriptions, not from the port. */
static GByteArray *expected_job(const uint8_t *mono, size_t stride, uint32_t w, uint32_t h,
                                uint32_t band_rows, unsigned feed, int cut)
{
    GByteArray *b = g_byte_array_new();
    uint32_t rb = (w + 7) / 8, y0, y, x;
    static const guint8 init[] = {0x1B, 0x40};
    g_byte_array_append(b, init, 2);
    for (y0 = 0; y0 < h; y0 += band_rows) {
        uint32_t band = h - y0 < band_rows ? h - y0 : band_rows, done = 0;
        while (done < band) {
            uint32_t n = band - done > 255 ? 255 : band - done;
            guint8 hdr[8] = {0x1D, 0x76, 0x30, 0x00, (guint8)(rb & 255), (guint8)(rb >> 8),
                             (guint8)(n & 255), (guint8)(n >> 8)};
            g_byte_array_append(b, hdr, 8);
            for (y = y0 + done; y < y0 + done + n; y++)
                for (x = 0; x < rb * 8; x += 8) {
                    guint8 v = 0;
                    uint32_t k;
                    for (k = 0; k < 8; k++) {
                        uint32_t px = x + k;
                        int on = px < w && (mono[y * stride + px / 8] & (0x80 >> (px % 8)));
                        if (px < w && !on) /* a dark pixel is a printed dot */
                            v = (guint8)(v | (0x80 >> k));
                    }
                    g_byte_array_append(b, &v, 1);
                }
            done += n;
        }
    }
    {
        guint8 tail[6] = {0x1B, 0x64, (guint8)feed, 0x1D, 0x56, 0x01};
        g_byte_array_append(b, tail, cut ? 6 : 3);
    }
    return b;
}

static void assert_job(printer_sim *sim, GByteArray *want)
{
    guint i;
    if (sim->job->len != want->len)
        print_error("job is %u bytes, expected %u\n", sim->job->len, want->len);
    assert_int_equal(sim->job->len, want->len);
    for (i = 0; i < want->len; i++)
        if (sim->job->data[i] != want->data[i]) {
            print_error("job byte %u is %02x, expected %02x\n", i, sim->job->data[i],
                        want->data[i]);
            fail();
        }
}

/* A scene rendered through the port: the job must hold exactly the picture
 * the same scene gives in memory, in GS v 0 bands, in <= chunk transfers. */
static void test_print_scene(void **state)
{
    fixture *f = *state;
    stp_usbprint_options o;
    stp_usbprint *p;
    stp_scene scene;
    stp_scene_options so;
    stp_tool_options to;
    stp_posix_frame frame;
    char err[256];
    GByteArray *want;
    const uint32_t w = 100, h = 300; /* 13 bytes a row, 4 pad bits; 300 rows */

    opts(&o, w, h);
    o.chunk_size = 512;
    o.cut = 1;
    p = stp_usbprint_open(&o, err, sizeof err);
    if (!p)
        print_error("%s\n", err);
    assert_non_null(p);
    assert_logged(f->sim, "GETDRIVER 0");
    assert_logged(f->sim, "DISCONNECT 0");
    assert_logged(f->sim, "CLAIM 0");
    assert_int_equal(f->sim->usblp_bound, 0);
    assert_int_equal(stp_usbprint_begin(p, err, sizeof err), 0);
    assert_logged(f->sim, "CONTROL a1 01 0000 0000 1");

    stp_scene_options_default(&so);
    assert_int_equal(stp_scene_parse(scene_text, sizeof scene_text - 1, "nff", "t", &so, &scene,
                                     err, sizeof err), 0);
    stp_tool_options_default(&to);
    to.width = (int)w;
    to.height = (int)h;
    to.band_rows = 0; /* one band of 300 rows: split 255 + 45 */
    assert_int_equal(stp_tool_render(&scene, &to, stp_usbprint_port(p), NULL, err, sizeof err), 0);
    assert_int_equal(stp_usbprint_end(p, err, sizeof err), 0);
    stp_usbprint_close(p);
    assert_logged(f->sim, "RELEASE 0");
    assert_logged(f->sim, "CONNECT 0");
    assert_int_equal(f->sim->usblp_bound, 1);

    assert_int_equal(stp_posix_frame_init(&frame, w, h, STP_PIXEL_MONO1), 0);
    assert_int_equal(stp_tool_render(&scene, &to, stp_posix_frame_port(&frame), NULL, err,
                                     sizeof err), 0);
    want = expected_job(frame.pixels, frame.stride, w, h, h, 4, 1);
    {
        /* the picture has both light pixels and printed dots */
        uint32_t yy, xx, on = 0;
        for (yy = 0; yy < h; yy++)
            for (xx = 0; xx < w; xx++)
                on += (frame.pixels[yy * frame.stride + xx / 8] >> (7 - xx % 8)) & 1u;
        if (!(on > w * h / 20 && on < w * h - w * h / 20))
            print_error("%u of %u pixels light\n", on, w * h);
        assert_true(on > w * h / 20 && on < w * h - w * h / 20);
    }
    if (getenv("STP_USB_SHOW_LOG")) {
        char *t = printer_sim_log_text(f->sim);
        print_message("device log: %s\n", t);
        g_free(t);
    }
    assert_job(f->sim, want);
    assert_true(f->sim->max_bulk <= 512);
    assert_int_equal(f->sim->unknown, 0);
    g_byte_array_unref(want);
    stp_posix_frame_free(&frame);
    stp_scene_free(&scene);
}

/* A hand-made pattern in bands of 7 rows, odd width, found by class. */
static void test_pattern_by_class(void **state)
{
    fixture *f = *state;
    stp_usbprint_options o;
    stp_usbprint *p;
    stp_port *port;
    char err[256];
    uint8_t img[20 * 3];
    uint32_t x, y;
    GByteArray *want;

    memset(img, 0, sizeof img);
    for (y = 0; y < 20; y++)
        for (x = 0; x < 19; x++)
            if ((x + 2 * y) % 3 == 0)
                img[y * 3 + x / 8] |= (uint8_t)(0x80 >> (x % 8));
    opts(&o, 19, 20);
    o.vendor_id = o.product_id = 0; /* by class 7: skips the mouse */
    o.feed_lines = 2;
    p = stp_usbprint_open(&o, err, sizeof err);
    if (!p)
        print_error("%s\n", err);
    assert_non_null(p);
    assert_int_equal(stp_usbprint_begin(p, err, sizeof err), 0);
    port = stp_usbprint_port(p);
    assert_int_equal(port->format, STP_PIXEL_MONO1);
    for (y = 0; y < 20; y += 7)
        assert_int_equal(port->flush(port, y, 20 - y < 7 ? 20 - y : 7, img + y * 3, 3), 0);
    assert_int_equal(stp_usbprint_end(p, err, sizeof err), 0);
    stp_usbprint_close(p);
    want = expected_job(img, 3, 19, 20, 7, 2, 0);
    assert_job(f->sim, want);
    g_byte_array_unref(want);
}

static void test_paper_out(void **state)
{
    fixture *f = *state;
    stp_usbprint_options o;
    stp_usbprint *p;
    char err[256];
    uint8_t st = 0;

    f->sim->status = 0x30; /* paper empty, selected, error */
    opts(&o, 64, 8);
    p = stp_usbprint_open(&o, err, sizeof err);
    assert_non_null(p);
    assert_int_equal(stp_usbprint_status(p, &st, err, sizeof err), 0);
    assert_int_equal(st, 0x30);
    assert_int_equal(stp_usbprint_begin(p, err, sizeof err), -1);
    assert_non_null(strstr(err, "paper out"));
    assert_non_null(strstr(err, "0x30"));
    assert_int_equal(f->sim->job->len, 0); /* not even ESC @ */

    f->sim->status = 0x10; /* paper present but "not error" clear */
    assert_int_equal(stp_usbprint_begin(p, err, sizeof err), -1);
    assert_non_null(strstr(err, "reports an error"));
    assert_int_equal(f->sim->job->len, 0);
    stp_usbprint_close(p);
    assert_int_equal(f->sim->usblp_bound, 1);
}

static void test_not_found(void **state)
{
    stp_usbprint_options o;
    char err[256];
    (void)state;
    opts(&o, 64, 8);
    o.product_id = 0x9999;
    assert_null(stp_usbprint_open(&o, err, sizeof err));
    assert_string_equal(err, "usb printer 0416:9999 not found");
}

/* Runs a job that fails at about `at` bytes; returns the render status. */
static int failing_job(fixture *f, sim_fault fault, char *err, size_t errlen, stp_usbprint **pp)
{
    stp_usbprint_options o;
    stp_usbprint *p;
    uint8_t img[48 * 40];
    uint32_t y;
    int rc = 0;
    memset(img, 0x5A, sizeof img);
    f->sim->fault = fault;
    f->sim->fault_at = 100;
    opts(&o, 384, 40);
    o.chunk_size = 64;
    o.timeout_ms = 300;
    p = stp_usbprint_open(&o, err, errlen);
    assert_non_null(p);
    assert_int_equal(stp_usbprint_begin(p, err, errlen), 0);
    for (y = 0; y < 40 && rc == 0; y += 10)
        rc = stp_usbprint_port(p)->flush(stp_usbprint_port(p), y, 10, img + y * 48, 48);
    *pp = p;
    return rc;
}

static void check_released(fixture *f, stp_usbprint *p)
{
    char err[256];
    assert_int_equal(stp_usbprint_end(p, err, sizeof err), -1);
    assert_non_null(strstr(err, "printer released: "));
    stp_usbprint_close(p);
    (void)f;
}

static void test_stall(void **state)
{
    fixture *f = *state;
    char err[256];
    stp_usbprint *p;
    assert_int_equal(failing_job(f, SIM_FAULT_STALL, err, sizeof err, &p), -1);
    assert_string_equal(stp_usbprint_error(p),
                        "printer stalled bulk OUT endpoint 0x01 after 128 of 488 bytes "
                        "(halt cleared, job aborted)");
    assert_logged(f->sim, "CLEAR_HALT 01");
    assert_logged(f->sim, "RELEASE 0");
    assert_int_equal(f->sim->usblp_bound, 1); /* given back to usblp at once */
    assert_int_equal(f->sim->job->len, 2 + 64 + 64); /* ESC @ and two whole chunks */
    check_released(f, p);
}

static void test_timeout(void **state)
{
    fixture *f = *state;
    char err[256];
    stp_usbprint *p;
    assert_int_equal(failing_job(f, SIM_FAULT_HANG, err, sizeof err, &p), -1);
    assert_string_equal(stp_usbprint_error(p),
                        "printer accepted no data for 300 ms (timed out after 128 of 488 bytes, "
                        "job aborted)");
    assert_logged(f->sim, "DISCARD");
    assert_logged(f->sim, "RELEASE 0");
    assert_int_equal(f->sim->usblp_bound, 1);
    check_released(f, p);
}

static void test_unplug(void **state)
{
    fixture *f = *state;
    char err[256];
    stp_usbprint *p;
    assert_int_equal(failing_job(f, SIM_FAULT_UNPLUG, err, sizeof err, &p), -1);
    assert_string_equal(stp_usbprint_error(p),
                        "printer unplugged during the job (128 of 488 bytes sent)");
    assert_logged(f->sim, "UNPLUGGED");
    check_released(f, p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_print_scene, setup, teardown),
        cmocka_unit_test_setup_teardown(test_pattern_by_class, setup, teardown),
        cmocka_unit_test_setup_teardown(test_paper_out, setup, teardown),
        cmocka_unit_test_setup_teardown(test_not_found, setup, teardown),
        cmocka_unit_test_setup_teardown(test_stall, setup, teardown),
        cmocka_unit_test_setup_teardown(test_timeout, setup, teardown),
        cmocka_unit_test_setup_teardown(test_unplug, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
