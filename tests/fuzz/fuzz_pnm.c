/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: the PNM reader of the POSIX port (stp_posix_read_pnm and
 * stp_posix_read_grey).  The reader takes a path, so each input is written
 * to one scratch file made once per process (in /dev/shm when it exists,
 * else $TMPDIR or /tmp; removed at exit) and read back from there.  A
 * regular file also keeps the reader's length check in play, as for real
 * files.
 *
 * Checked beyond the sanitizers (ports/posix/stp_posix.h):
 *  - failure: -1, the image zeroed, a message starting with the path;
 *  - success: 0, sides 1..32767, pnm_type 1..6 matching the magic number,
 *    channels 1 (P1, P2, P4, P5, and always for read_grey) or 3, maxval 1 for
 *    PBM and 1..65535 otherwise, every sample readable (the buffer holds
 *    width * height * channels bytes), PBM samples only 0 or 255;
 *  - read_grey fails exactly when read_pnm does, with the same size, and
 *    gives the same samples for PBM and PGM;
 *  - a tiny message buffer stays NUL-terminated.
 */
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <unistd.h>

#include "fuzz_common.h"
#include "stp_posix.h"

static char scratch_path[4096];
static int scratch_fd = -1;

static void remove_scratch(void)
{
    if (scratch_fd >= 0) {
        (void)close(scratch_fd);
        (void)unlink(scratch_path);
        scratch_fd = -1;
    }
}

static void open_scratch(void)
{
    const char *dir = getenv("TMPDIR");
    int n;

    if (access("/dev/shm", W_OK) == 0)
        dir = "/dev/shm";
    else if (dir == NULL || *dir == '\0')
        dir = "/tmp";
    n = snprintf(scratch_path, sizeof scratch_path, "%s/stp-fuzz-pnm-XXXXXX", dir);
    FZ_CHECK(n > 0 && (size_t)n < sizeof scratch_path, "scratch path too long");
    scratch_fd = mkstemp(scratch_path);
    FZ_CHECK(scratch_fd >= 0, "cannot create %s: %s", scratch_path, strerror(errno));
    atexit(remove_scratch);
}

static void write_scratch(const uint8_t *data, size_t size)
{
    size_t done = 0;

    FZ_CHECK(ftruncate(scratch_fd, 0) == 0, "ftruncate: %s", strerror(errno));
    while (done < size) {
        ssize_t n = pwrite(scratch_fd, data + done, size - done, (off_t)done);
        FZ_CHECK(n > 0, "pwrite: %s", strerror(errno));
        done += (size_t)n;
    }
}

static int is_zeroed(const stp_posix_image *img)
{
    return img->width == 0 && img->height == 0 && img->channels == 0 &&
           img->samples == NULL && img->pnm_type == 0 && img->maxval == 0;
}

static void check_message(const char *err, size_t errlen)
{
    size_t len = strlen(scratch_path);

    FZ_CHECK(strnlen(err, errlen) < errlen, "message not terminated");
    FZ_CHECK(strncmp(err, scratch_path, len) == 0 && err[len] == ':' && err[len + 1] == ' ',
             "message does not start with the path: '%s'", err);
}

/* Touches every sample (so ASan sees a short buffer) and returns their sum. */
static unsigned long check_image(const stp_posix_image *img, int grey, int magic)
{
    size_t i, n;
    unsigned long sum = 0;

    FZ_CHECK(img->width >= 1 && img->width <= 32767 && img->height >= 1 &&
                 img->height <= 32767,
             "size %u x %u", (unsigned)img->width, (unsigned)img->height);
    FZ_CHECK(img->pnm_type == magic, "pnm_type %d for magic P%d", img->pnm_type, magic);
    if (grey || magic == 1 || magic == 2 || magic == 4 || magic == 5)
        FZ_CHECK(img->channels == 1, "channels %d for P%d", img->channels, magic);
    else
        FZ_CHECK(img->channels == 3, "channels %d for P%d", img->channels, magic);
    if (magic == 1 || magic == 4)
        FZ_CHECK(img->maxval == 1, "PBM maxval %u", (unsigned)img->maxval);
    else
        FZ_CHECK(img->maxval >= 1 && img->maxval <= 65535, "maxval %u", (unsigned)img->maxval);
    FZ_CHECK(img->samples != NULL, "no samples");
    n = (size_t)img->width * img->height * (size_t)img->channels;
    for (i = 0; i < n; i++) {
        if (magic == 1 || magic == 4)
            FZ_CHECK(img->samples[i] == 0 || img->samples[i] == 255, "PBM sample %u",
                     img->samples[i]);
        sum += img->samples[i];
    }
    return sum;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    stp_posix_image img, grey;
    char err[512], tiny[3];
    int rc, rc_grey, magic;

    if (scratch_fd < 0)
        open_scratch();
    write_scratch(data, size);
    magic = size >= 2 && data[0] == 'P' && data[1] >= '1' && data[1] <= '6' ? data[1] - '0' : 0;

    memset(&img, 0xA5, sizeof img);
    rc = stp_posix_read_pnm(scratch_path, &img, err, sizeof err);
    FZ_CHECK(rc == 0 || rc == -1, "read_pnm returned %d", rc);
    if (rc == 0) {
        FZ_CHECK(magic != 0, "accepted a file without a P1..P6 magic number");
        (void)check_image(&img, 0, magic);
    } else {
        FZ_CHECK(is_zeroed(&img), "failed read left the image non-zero");
        check_message(err, sizeof err);
    }

    memset(&grey, 0x5A, sizeof grey);
    rc_grey = stp_posix_read_grey(scratch_path, &grey, tiny, sizeof tiny);
    FZ_CHECK(rc_grey == rc, "read_grey returned %d, read_pnm %d", rc_grey, rc);
    if (rc_grey == 0) {
        (void)check_image(&grey, 1, magic);
        FZ_CHECK(grey.width == img.width && grey.height == img.height &&
                     grey.maxval == img.maxval,
                 "read_grey and read_pnm disagree on the header");
        if (img.channels == 1)
            FZ_CHECK(memcmp(grey.samples, img.samples, (size_t)img.width * img.height) == 0,
                     "read_grey changed one-channel samples");
    } else {
        FZ_CHECK(is_zeroed(&grey), "failed read_grey left the image non-zero");
        FZ_CHECK(strnlen(tiny, sizeof tiny) < sizeof tiny, "tiny message not terminated");
    }
    stp_posix_image_free(&img);
    stp_posix_image_free(&grey);
    FZ_CHECK(is_zeroed(&img), "stp_posix_image_free left something");
    return 0;
}
