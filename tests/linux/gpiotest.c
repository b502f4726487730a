/* SPDX-License-Identifier: MIT */
/*
 * gpiotest: the panel control lines (stipple_gpio, libgpiod v2) against the
 * kernel's GPIO simulator (gpio-sim) inside the test guest.
 *
 *   gpiotest SYSFS_CHIP_DIR CHIP_NAME
 *
 * SYSFS_CHIP_DIR is /sys/devices/platform/gpio-sim.N/gpiochipM: outputs are
 * read back from its sim_gpioK/value files, inputs driven through
 * sim_gpioK/pull.  The bank is labelled "stp-panel" and has lines RST DC
 * BUSY EN BL VCOM at offsets 0..5.  Prints "STP-GPIO <check> ok|FAIL ...".
 */
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "stp_gpio.h"

static const char *g_dir;
static int g_failures;

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1000.0 + (double)ts.tv_nsec / 1e6;
}

static void sleep_ms(unsigned ms)
{
    struct timespec ts;
    ts.tv_sec = (time_t)(ms / 1000u);
    ts.tv_nsec = (long)(ms % 1000u) * 1000000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}

static void report(const char *check, int ok, const char *fmt, ...)
{
    va_list ap;
    printf("STP-GPIO %s %s ", check, ok ? "ok" : "FAIL");
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout);
    if (!ok)
        g_failures++;
}

/* Physical level of line k as the simulator sees it (0/1, -1 on error). */
static int sim_value(int k)
{
    char path[300], buf[8];
    int fd, n;
    snprintf(path, sizeof path, "%s/sim_gpio%d/value", g_dir, k);
    fd = open(path, O_RDONLY);
    if (fd < 0)
        return -1;
    n = (int)read(fd, buf, sizeof buf - 1);
    close(fd);
    return n > 0 ? buf[0] - '0' : -1;
}

static int sim_pull(int k, const char *pull)
{
    char path[300];
    int fd, ok;
    snprintf(path, sizeof path, "%s/sim_gpio%d/pull", g_dir, k);
    fd = open(path, O_WRONLY);
    if (fd < 0)
        return -1;
    ok = write(fd, pull, strlen(pull)) == (ssize_t)strlen(pull);
    close(fd);
    return ok ? 0 : -1;
}

/* A thread sampling one line's value file, recording level changes. */
typedef struct monitor {
    int line, fd, stop, count, last;
    double t[64];
    int v[64];
    pthread_t th;
} monitor;

static void *monitor_main(void *arg)
{
    monitor *m = arg;
    char buf[8];
    while (!__atomic_load_n(&m->stop, __ATOMIC_ACQUIRE)) {
        int v;
        if (pread(m->fd, buf, sizeof buf - 1, 0) <= 0)
            break;
        v = buf[0] - '0';
        if (v != m->last && m->count < 64) {
            m->t[m->count] = now_ms();
            m->v[m->count] = v;
            m->count++;
            m->last = v;
        }
        {
            struct timespec ts = {0, 50000L};
            nanosleep(&ts, NULL);
        }
    }
    return NULL;
}

static void monitor_start(monitor *m, int line)
{
    char path[300];
    memset(m, 0, sizeof *m);
    m->line = line;
    snprintf(path, sizeof path, "%s/sim_gpio%d/value", g_dir, line);
    m->fd = open(path, O_RDONLY);
    m->last = sim_value(line);
    pthread_create(&m->th, NULL, monitor_main, m);
}

static void monitor_stop(monitor *m)
{
    __atomic_store_n(&m->stop, 1, __ATOMIC_RELEASE);
    pthread_join(m->th, NULL);
    close(m->fd);
}

typedef struct delayed_pull {
    int line;
    unsigned ms;
    const char *pull;
    double at;
    pthread_t th;
} delayed_pull;

static void *delayed_main(void *arg)
{
    delayed_pull *d = arg;
    sleep_ms(d->ms);
    d->at = now_ms();
    sim_pull(d->line, d->pull);
    return NULL;
}

int main(int argc, char **argv)
{
    stp_gpio_panel_config cfg;
    stp_gpio_panel *p;
    char err[256], spec_dc[64], spec_busy[64];
    monitor m;
    double t0, t1;
    int i, ok;

    if (argc != 3) {
        fprintf(stderr, "usage: gpiotest SYSFS_CHIP_DIR CHIP_NAME\n");
        return 2;
    }
    g_dir = argv[1];
    /* every way of naming a line: name alone, chip:name, path:offset,
     * label:name, label:offset */
    snprintf(spec_dc, sizeof spec_dc, "%s:DC", argv[2]);
    snprintf(spec_busy, sizeof spec_busy, "/dev/%s:2", argv[2]);
    memset(&cfg, 0, sizeof cfg);
    cfg.reset = "RST";
    cfg.dc = spec_dc;
    cfg.busy = spec_busy;
    cfg.enable = "stp-panel:EN";
    cfg.backlight = "stp-panel:4";
    cfg.vcom = "VCOM";
    p = stp_gpio_panel_open(&cfg, err, sizeof err);
    report("open", p != NULL, "%s", p ? "all six lines" : err);
    if (!p)
        return 1;

    ok = sim_value(0) == 1 && sim_value(1) == 0 && sim_value(3) == 0 && sim_value(4) == 0 &&
         sim_value(5) == 0;
    report("initial", ok, "RST=%d DC=%d EN=%d BL=%d VCOM=%d (want 1 0 0 0 0)", sim_value(0),
           sim_value(1), sim_value(3), sim_value(4), sim_value(5));

    /* reset: low for 20 ms, then 5 ms settling before the call returns */
    monitor_start(&m, 0);
    t0 = now_ms();
    ok = stp_gpio_panel_reset(p, 20000, 5000, err, sizeof err) == 0;
    t1 = now_ms();
    sleep_ms(5);
    monitor_stop(&m);
    ok = ok && m.count == 2 && m.v[0] == 0 && m.v[1] == 1;
    if (ok) {
        /* The sampler sees each edge a little late (never early), so the
         * bounds use the call's own start and end where it can lag: the
         * release comes >= 20 ms after the call began, the call takes
         * >= 25 ms (pulse + settling), the low level lasts <= 20 + 150. */
        double width = m.t[1] - m.t[0];
        ok = m.t[0] >= t0 && m.t[1] - t0 >= 20.0 && t1 - t0 >= 25.0 && width <= 20.0 + 150.0;
        report("reset", ok,
               "low seen for %.1f ms (<= 170), released %.1f ms after the call (>= 20), "
               "call %.1f ms (>= 25)", width, m.t[1] - t0, t1 - t0);
    } else {
        report("reset", 0, "%d transitions seen (want 1->0->1) %s", m.count, err);
    }

    ok = stp_gpio_panel_dc(p, 1, err, sizeof err) == 0 && sim_value(1) == 1 &&
         stp_gpio_panel_dc(p, 0, err, sizeof err) == 0 && sim_value(1) == 0;
    report("dc", ok, "data -> 1, command -> 0");
    ok = stp_gpio_panel_enable(p, 1, err, sizeof err) == 0 && sim_value(3) == 1 &&
         stp_gpio_panel_backlight(p, 1, err, sizeof err) == 0 && sim_value(4) == 1 &&
         stp_gpio_panel_backlight(p, 0, err, sizeof err) == 0 && sim_value(4) == 0 &&
         stp_gpio_panel_enable(p, 0, err, sizeof err) == 0 && sim_value(3) == 0;
    report("enable-backlight", ok, "on -> 1, off -> 0");

    /* BUSY (active high): not busy at first (the simulator pulls down) */
    t0 = now_ms();
    ok = stp_gpio_panel_wait_ready(p, 1000, err, sizeof err) == 0;
    t1 = now_ms();
    report("busy-idle", ok && t1 - t0 < 50.0, "ready at once (%.1f ms)", t1 - t0);
    {
        delayed_pull d;
        sim_pull(2, "pull-up");
        d.line = 2;
        d.ms = 60;
        d.pull = "pull-down";
        t0 = now_ms();
        pthread_create(&d.th, NULL, delayed_main, &d);
        ok = stp_gpio_panel_wait_ready(p, 2000, err, sizeof err) == 0;
        t1 = now_ms();
        pthread_join(d.th, NULL);
        report("busy-release", ok && t1 >= d.at && t1 - d.at <= 150.0,
               "ready %.1f ms after BUSY fell (<= 150), %.1f ms in all %s", t1 - d.at, t1 - t0,
               ok ? "" : err);
    }
    sim_pull(2, "pull-up");
    t0 = now_ms();
    ok = stp_gpio_panel_wait_ready(p, 150, err, sizeof err) == -1;
    t1 = now_ms();
    report("busy-timeout",
           ok && strcmp(err, "panel still busy after 150 ms") == 0 && t1 - t0 >= 149.5 &&
               t1 - t0 <= 300.0,
           "\"%s\" after %.1f ms (150..300)", err, t1 - t0);
    sim_pull(2, "pull-down");

    /* VCOM: single toggles, then a 20 Hz square wave (25 ms per level) */
    ok = 1;
    for (i = 1; i <= 4; i++) {
        int lvl = stp_gpio_panel_vcom_toggle(p, err, sizeof err);
        ok = ok && lvl == (i & 1) && sim_value(5) == (i & 1);
    }
    report("vcom-toggle", ok, "1 0 1 0");
    monitor_start(&m, 5);
    ok = stp_gpio_panel_vcom_start(p, 20, err, sizeof err) == 0;
    sleep_ms(400);
    stp_gpio_panel_vcom_stop(p);
    sleep_ms(30);
    monitor_stop(&m);
    {
        /* the thread schedules on absolute times, so a late edge (a loaded
         * host, an emulated CPU) is followed by an early one, and the
         * sampler itself lags now and then: check the mean period tightly
         * and each gap loosely */
        double min_gap = 1e9, max_gap = 0, mean = 0;
        int alternating = 1;
        for (i = 1; i < m.count; i++) {
            double g = m.t[i] - m.t[i - 1];
            if (g < min_gap)
                min_gap = g;
            if (g > max_gap)
                max_gap = g;
            alternating = alternating && m.v[i] != m.v[i - 1];
        }
        if (m.count > 1)
            mean = (m.t[m.count - 1] - m.t[0]) / (m.count - 1);
        ok = ok && alternating && m.count >= 12 && m.count <= 17 && mean >= 23.0 &&
             mean <= 27.0 && max_gap <= 120.0;
        report("vcom-20hz", ok,
               "%d edges in 400 ms (12..17), mean gap %.2f ms (23..27), gaps %.1f..%.1f ms",
               m.count, mean, m.count > 1 ? min_gap : 0.0, m.count > 1 ? max_gap : 0.0);
    }
    stp_gpio_panel_close(p);

    /* BUSY# active low ("!"): pulled down = busy */
    memset(&cfg, 0, sizeof cfg);
    cfg.busy = "!stp-panel:BUSY";
    p = stp_gpio_panel_open(&cfg, err, sizeof err);
    ok = p != NULL;
    if (p) {
        sim_pull(2, "pull-down");
        ok = stp_gpio_panel_wait_ready(p, 50, err, sizeof err) == -1;
        sim_pull(2, "pull-up");
        ok = ok && stp_gpio_panel_wait_ready(p, 50, err, sizeof err) == 0;
        stp_gpio_panel_close(p);
    }
    report("busy-active-low", ok, "low = busy, high = ready %s", ok ? "" : err);

    memset(&cfg, 0, sizeof cfg);
    cfg.reset = "NOPE";
    p = stp_gpio_panel_open(&cfg, err, sizeof err);
    report("missing-line", !p && strcmp(err, "reset line 'NOPE' not found on any GPIO chip") == 0,
           "\"%s\"", p ? "opened" : err);
    stp_gpio_panel_close(p);
    memset(&cfg, 0, sizeof cfg);
    cfg.dc = "stp-panel:99";
    p = stp_gpio_panel_open(&cfg, err, sizeof err);
    report("bad-offset", !p && strstr(err, "dc line 'stp-panel:99'") != NULL, "\"%s\"",
           p ? "opened" : err);
    stp_gpio_panel_close(p);

    printf("STP-GPIO-DONE %d failures\n", g_failures);
    fflush(stdout);
    return g_failures ? 1 : 0;
}
