/* SPDX-License-Identifier: MIT */
/*
 * fbtest: the program the Linux framebuffer test runs, both on the host
 * (to produce the expected picture) and, statically linked, inside a QEMU
 * guest running Debian's kernel (to draw through stipple_linuxfb onto real
 * fbdev drivers: bochs and cirrus DRM, vfb).
 *
 *   fbtest expect W H mono|grey OUT.pnm   host: the reference render (P4/P5)
 *   fbtest setmode DEV BPP XRES YRES [XVIRT YVIRT XOFF YOFF [argb]]
 *                                        FBIOPUT_VSCREENINFO, then print it
 *   fbtest mode DEV                      print the device's mode
 *   fbtest draw DEV W H [hold]           render through the port (W = H = 0:
 *                                        the whole screen); "hold"
 *                                        keeps the device open (and the VT in
 *                                        graphics mode) until killed
 *   fbtest dump DEV                      read() the memory of the visible
 *                                        rows, print it base64 on stdout
 *   fbtest console DEV                   VT graphics mode: open/close,
 *                                        exit() and SIGTERM all restore it
 *   fbtest errors                        error messages of bad devices
 *
 * Output lines for the host start with "STP-".
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <linux/fb.h>
#include <linux/kd.h>

#include "render_scene.h"
#include "scene.h"
#include "stp_linuxfb.h"
#include "stp_posix.h"

/* A small scene of our own: a floor, a tilted square, a tetrahedron and a
 * sphere, lit from the upper left; enough different shades for the grey
 * levels and the halftone to matter. */
static const char scene_text[] =
    "b 0.1 0.1 0.1\n"
    "v\n"
    "from 0 -6 2.5\n"
    "at 0 0 0.3\n"
    "up 0 0 1\n"
    "angle 40\n"
    "hither 1\n"
    "resolution 320 240\n"
    "l -4 -5 6\n"
    "l 5 -3 3\n"
    "f 0.8 0.8 0.8 1 0 0 0 0\n"
    "p 4\n"
    "-3 -2 0\n"
    "3 -2 0\n"
    "3 3 0\n"
    "-3 3 0\n"
    "f 0.9 0.6 0.3 0.7 0.3 20 0 0\n"
    "p 3\n"
    "-2 0 0\n"
    "-0.5 0.5 0\n"
    "-1.2 0 1.8\n"
    "p 3\n"
    "-0.5 0.5 0\n"
    "-1.8 1.2 0\n"
    "-1.2 0 1.8\n"
    "p 3\n"
    "-1.8 1.2 0\n"
    "-2 0 0\n"
    "-1.2 0 1.8\n"
    "f 0.5 0.7 0.9 0.6 0.4 30 0 0\n"
    "s 1.2 0.5 0.9 0.9\n"
    "f 0.3 0.9 0.3 1 0 0 0 0\n"
    "p 4\n"
    "0.2 -1.4 0.05\n"
    "1.0 -1.6 0.05\n"
    "1.2 -0.9 0.6\n"
    "0.4 -0.7 0.6\n";

static int render(stp_port *port, int width, int height, int mono)
{
    stp_scene scene;
    stp_scene_options sopt;
    stp_tool_options opt;
    char err[256];
    int rc;

    stp_scene_options_default(&sopt);
    if (stp_scene_parse(scene_text, sizeof scene_text - 1, "nff", "fbtest-scene", &sopt, &scene,
                        err, sizeof err) != 0) {
        fprintf(stderr, "fbtest: %s\n", err);
        return -1;
    }
    stp_tool_options_default(&opt);
    opt.width = width;
    opt.height = height;
    opt.levels = mono ? 16 : 256;
    opt.band_rows = 16; /* several bands per frame, as a panel port sees */
    rc = stp_tool_render(&scene, &opt, port, NULL, err, sizeof err);
    stp_scene_free(&scene);
    if (rc != 0)
        fprintf(stderr, "fbtest: render: %s\n", err);
    return rc;
}

static int cmd_expect(int argc, char **argv)
{
    stp_posix_frame frame;
    int w, h, mono, rc;
    char err[256];
    if (argc != 6)
        return 2;
    w = atoi(argv[2]);
    h = atoi(argv[3]);
    mono = strcmp(argv[4], "mono") == 0;
    if (stp_posix_frame_init(&frame, (uint32_t)w, (uint32_t)h,
                             mono ? STP_PIXEL_MONO1 : STP_PIXEL_GREY8) != 0) {
        perror("fbtest: frame");
        return 1;
    }
    rc = render(stp_posix_frame_port(&frame), w, h, mono);
    if (rc == 0 && stp_posix_write(&frame, argv[5], mono ? STP_POSIX_FILE_P4 : STP_POSIX_FILE_P5,
                                   err, sizeof err) != 0) {
        fprintf(stderr, "fbtest: %s\n", err);
        rc = -1;
    }
    stp_posix_frame_free(&frame);
    return rc == 0 ? 0 : 1;
}

static void print_var(const char *dev, int fd)
{
    struct fb_var_screeninfo v;
    struct fb_fix_screeninfo f;
    if (ioctl(fd, FBIOGET_VSCREENINFO, &v) != 0 || ioctl(fd, FBIOGET_FSCREENINFO, &f) != 0) {
        printf("STP-MODE %s error %s\n", dev, strerror(errno));
        return;
    }
    printf("STP-MODE %s id=%.16s xres=%u yres=%u xvirt=%u yvirt=%u xoff=%u yoff=%u bpp=%u "
           "line=%u visual=%u gray=%u nonstd=%u red=%u:%u green=%u:%u blue=%u:%u transp=%u:%u "
           "smem=%u\n",
           dev, f.id, v.xres, v.yres, v.xres_virtual, v.yres_virtual, v.xoffset, v.yoffset,
           v.bits_per_pixel, f.line_length, f.visual, v.grayscale, v.nonstd, v.red.offset,
           v.red.length, v.green.offset, v.green.length, v.blue.offset, v.blue.length,
           v.transp.offset, v.transp.length, f.smem_len);
    fflush(stdout);
}

static int cmd_mode(int argc, char **argv)
{
    int fd;
    if (argc != 3)
        return 2;
    fd = open(argv[2], O_RDONLY);
    if (fd < 0) {
        printf("STP-ERROR %s: %s\n", argv[2], strerror(errno));
        return 1;
    }
    print_var(argv[2], fd);
    close(fd);
    return 0;
}

static int cmd_setmode(int argc, char **argv)
{
    struct fb_var_screeninfo v;
    int fd;
    if (argc != 6 && argc != 10 && argc != 11)
        return 2;
    fd = open(argv[2], O_RDWR);
    if (fd < 0 || ioctl(fd, FBIOGET_VSCREENINFO, &v) != 0) {
        printf("STP-ERROR %s: %s\n", argv[2], strerror(errno));
        return 1;
    }
    v.bits_per_pixel = (uint32_t)atoi(argv[3]);
    v.xres = (uint32_t)atoi(argv[4]);
    v.yres = (uint32_t)atoi(argv[5]);
    v.xres_virtual = v.xres;
    v.yres_virtual = v.yres;
    v.xoffset = v.yoffset = 0;
    if (argc >= 10) {
        v.xres_virtual = (uint32_t)atoi(argv[6]);
        v.yres_virtual = (uint32_t)atoi(argv[7]);
        v.xoffset = (uint32_t)atoi(argv[8]);
        v.yoffset = (uint32_t)atoi(argv[9]);
    }
    /* vfb picks ARGB1555 over RGB565 when asked for an alpha channel */
    memset(&v.red, 0, sizeof v.red);
    memset(&v.green, 0, sizeof v.green);
    memset(&v.blue, 0, sizeof v.blue);
    memset(&v.transp, 0, sizeof v.transp);
    if (argc == 11 && strcmp(argv[10], "argb") == 0)
        v.transp.length = 1;
    v.grayscale = 0;
    v.nonstd = 0;
    v.activate = FB_ACTIVATE_NOW;
    if (ioctl(fd, FBIOPUT_VSCREENINFO, &v) != 0) {
        printf("STP-ERROR %s: FBIOPUT_VSCREENINFO: %s\n", argv[2], strerror(errno));
        close(fd);
        return 1;
    }
    print_var(argv[2], fd);
    close(fd);
    return 0;
}

static const char *format_name(stp_pixel_format f)
{
    return f == STP_PIXEL_MONO1 ? "MONO1" : f == STP_PIXEL_GREY8 ? "GREY8" : "RGB888";
}

static int cmd_draw(int argc, char **argv)
{
    stp_linuxfb_options opt;
    stp_linuxfb_info info;
    stp_linuxfb *fb;
    char err[256];
    struct timespec t0, t1;
    int rc;
    if (argc != 5 && argc != 6)
        return 2;
    stp_linuxfb_options_default(&opt);
    opt.width = (uint32_t)atoi(argv[3]);
    opt.height = (uint32_t)atoi(argv[4]);
    fb = stp_linuxfb_open(argv[2], &opt, err, sizeof err);
    if (!fb) {
        printf("STP-ERROR %s\n", err);
        return 1;
    }
    stp_linuxfb_get_info(fb, &info);
    printf("STP-INFO %s id=%s %ux%u bpp=%u line=%u visual=%u format=%s lsb_first=%d "
           "on_is_one=%d console=%d\n",
           argv[2], info.id, info.xres, info.yres, info.bits_per_pixel, info.line_length,
           info.visual, format_name(info.format), info.lsb_first, info.on_is_one,
           info.console_switched);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    rc = render(stp_linuxfb_port(fb), (int)stp_linuxfb_port(fb)->width,
                (int)stp_linuxfb_port(fb)->height, info.format == STP_PIXEL_MONO1);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if (rc != 0) {
        printf("STP-ERROR %s: render failed\n", argv[2]);
        stp_linuxfb_close(fb);
        return 1;
    }
    printf("STP-DRAWN %s %ld ms\n", argv[2],
           (long)((t1.tv_sec - t0.tv_sec) * 1000 + (t1.tv_nsec - t0.tv_nsec) / 1000000));
    fflush(stdout);
    if (argc == 6 && strcmp(argv[5], "hold") == 0)
        for (;;)
            pause();
    stp_linuxfb_close(fb);
    return 0;
}

static void b64_line(const unsigned char *p, size_t n)
{
    static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    char out[140];
    size_t i, o = 0;
    for (i = 0; i + 2 < n; i += 3) {
        unsigned long v = ((unsigned long)p[i] << 16) | ((unsigned long)p[i + 1] << 8) | p[i + 2];
        out[o++] = tab[(v >> 18) & 63];
        out[o++] = tab[(v >> 12) & 63];
        out[o++] = tab[(v >> 6) & 63];
        out[o++] = tab[v & 63];
    }
    if (i < n) {
        unsigned long v = (unsigned long)p[i] << 16;
        if (i + 1 < n)
            v |= (unsigned long)p[i + 1] << 8;
        out[o++] = tab[(v >> 18) & 63];
        out[o++] = tab[(v >> 12) & 63];
        out[o++] = i + 1 < n ? tab[(v >> 6) & 63] : '=';
        out[o++] = '=';
    }
    out[o] = '\0';
    puts(out);
}

static int cmd_dump(int argc, char **argv)
{
    struct fb_var_screeninfo v;
    struct fb_fix_screeninfo f;
    unsigned char *buf;
    size_t len, got = 0, i;
    int fd;
    if (argc != 3)
        return 2;
    fd = open(argv[2], O_RDONLY);
    if (fd < 0 || ioctl(fd, FBIOGET_VSCREENINFO, &v) != 0 ||
        ioctl(fd, FBIOGET_FSCREENINFO, &f) != 0) {
        printf("STP-ERROR %s: %s\n", argv[2], strerror(errno));
        return 1;
    }
    len = (size_t)(v.yoffset + v.yres) * f.line_length;
    buf = malloc(len);
    if (!buf)
        return 1;
    while (got < len) { /* read(2) on the device, not the mapping */
        ssize_t r = read(fd, buf + got, len - got);
        if (r <= 0) {
            printf("STP-ERROR %s: read: %s\n", argv[2], r < 0 ? strerror(errno) : "short");
            free(buf);
            return 1;
        }
        got += (size_t)r;
    }
    close(fd);
    printf("STP-DUMP %s %lu\n", argv[2], (unsigned long)len);
    for (i = 0; i < len; i += 96)
        b64_line(buf + i, len - i < 96 ? len - i : 96);
    printf("STP-END %s\n", argv[2]);
    fflush(stdout);
    free(buf);
    return 0;
}

static int kd_mode(void)
{
    int fd = open("/dev/tty0", O_RDWR | O_NOCTTY), mode = -1;
    if (fd < 0)
        return -1;
    if (ioctl(fd, KDGETMODE, &mode) != 0)
        mode = -1;
    close(fd);
    return mode;
}

/* Child: open DEV, tell the parent (fd_ready), wait until it has looked at
 * the console (fd_go), then end as `how` says. */
static void console_child(const char *dev, int fd_ready, int fd_go, const char *how)
{
    stp_linuxfb_options opt;
    char err[256], c;
    stp_linuxfb *fb;
    stp_linuxfb_options_default(&opt);
    opt.clear = 0;
    opt.tty = "/dev/tty0";
    fb = stp_linuxfb_open(dev, &opt, err, sizeof err);
    if (!fb) {
        printf("STP-ERROR %s\n", err);
        fflush(stdout);
        _exit(3);
    }
    if (write(fd_ready, "r", 1) != 1 || read(fd_go, &c, 1) != 1)
        _exit(4);
    if (strcmp(how, "exit") == 0)
        exit(0); /* no close: atexit restores */
    for (;;)
        pause();
}

static int run_child(const char *dev, const char *how, int sig)
{
    int ready[2], go[2], status, mode_during, mode_after;
    struct pollfd pfd;
    char c;
    pid_t pid;
    if (pipe(ready) != 0 || pipe(go) != 0)
        return -1;
    pid = fork();
    if (pid == 0) {
        close(ready[0]);
        close(go[1]);
        console_child(dev, ready[1], go[0], how);
    }
    close(ready[1]);
    close(go[0]);
    pfd.fd = ready[0];
    pfd.events = POLLIN;
    if (poll(&pfd, 1, 5000) != 1 || read(ready[0], &c, 1) != 1) {
        printf("STP-CONSOLE %s: child did not open the device\n", how);
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        close(ready[0]);
        close(go[1]);
        return -1;
    }
    close(ready[0]);
    mode_during = kd_mode();
    if (write(go[1], "g", 1) != 1)
        kill(pid, SIGKILL);
    close(go[1]);
    if (sig)
        kill(pid, sig);
    waitpid(pid, &status, 0);
    mode_after = kd_mode();
    printf("STP-CONSOLE %s during=%d after=%d status=%s%d\n", how, mode_during, mode_after,
           WIFSIGNALED(status) ? "signal " : "exit ",
           WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    fflush(stdout);
    return 0;
}

static int cmd_console(int argc, char **argv)
{
    stp_linuxfb_options opt;
    stp_linuxfb *fb;
    char err[256];
    int during;
    if (argc != 3)
        return 2;
    printf("STP-CONSOLE before=%d\n", kd_mode());
    stp_linuxfb_options_default(&opt);
    opt.clear = 0;
    opt.tty = "/dev/tty0";
    fb = stp_linuxfb_open(argv[2], &opt, err, sizeof err);
    if (!fb) {
        printf("STP-ERROR %s\n", err);
        return 1;
    }
    during = kd_mode();
    stp_linuxfb_close(fb);
    printf("STP-CONSOLE close during=%d after=%d\n", during, kd_mode());
    fflush(stdout);
    run_child(argv[2], "exit", 0);
    run_child(argv[2], "sigterm", SIGTERM);
    run_child(argv[2], "sigint", SIGINT);
    return 0;
}

static int cmd_errors(void)
{
    const char *devs[] = {"/dev/null", "/dev/nonexistent-fb"};
    size_t i;
    for (i = 0; i < sizeof devs / sizeof devs[0]; i++) {
        char err[256];
        stp_linuxfb *fb = stp_linuxfb_open(devs[i], NULL, err, sizeof err);
        printf("STP-OPENERR %s %s\n", fb ? "opened" : "refused", fb ? devs[i] : err);
        stp_linuxfb_close(fb);
    }
    fflush(stdout);
    return 0;
}

int main(int argc, char **argv)
{
    int rc = 2;
    setvbuf(stdout, NULL, _IOFBF, 1 << 16);
    if (argc >= 2) {
        if (strcmp(argv[1], "expect") == 0)
            rc = cmd_expect(argc, argv);
        else if (strcmp(argv[1], "setmode") == 0)
            rc = cmd_setmode(argc, argv);
        else if (strcmp(argv[1], "mode") == 0)
            rc = cmd_mode(argc, argv);
        else if (strcmp(argv[1], "draw") == 0)
            rc = cmd_draw(argc, argv);
        else if (strcmp(argv[1], "dump") == 0)
            rc = cmd_dump(argc, argv);
        else if (strcmp(argv[1], "console") == 0)
            rc = cmd_console(argc, argv);
        else if (strcmp(argv[1], "errors") == 0)
            rc = cmd_errors();
    }
    if (rc == 2)
        fprintf(stderr, "usage: fbtest expect|setmode|draw|dump|console|errors ...\n");
    fflush(stdout);
    return rc;
}
