/* SPDX-License-Identifier: MIT */
/* Panel control lines through libgpiod v2 (see stp_gpio.h). */
#include "stp_gpio.h"
#include "stp_error.h"

#include <dirent.h>
#include <errno.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gpiod.h>

#ifdef STP_GPIO_LOAD
#include "stp_gpiod_load.h"
#endif

enum { L_RESET, L_DC, L_BUSY, L_ENABLE, L_BACKLIGHT, L_VCOM, L_COUNT };

static const char *const line_role[L_COUNT] = {"reset", "dc", "busy", "enable", "backlight",
                                               "vcom"};

typedef struct line {
    struct gpiod_chip *chip;
    struct gpiod_line_request *req;
    unsigned int offset;
    int edges; /* busy: edge events requested */
} line;

struct stp_gpio_panel {
    line lines[L_COUNT];
    pthread_mutex_t lock;   /* VCOM level and thread state */
    pthread_cond_t cond;
    pthread_t vcom_thread;
    int vcom_running, vcom_stop, vcom_level;
    unsigned vcom_half_ms;
    struct gpiod_edge_event_buffer *events;
};

static int64_t now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

static void sleep_us(unsigned us)
{
    struct timespec ts;
    ts.tv_sec = (time_t)(us / 1000000u);
    ts.tv_nsec = (long)(us % 1000000u) * 1000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}

/* Opens the chip a spec names; NULL chip spec: NULL (search them all). */
static struct gpiod_chip *open_chip(const char *chip_spec, size_t len)
{
    char path[300];
    DIR *d;
    struct dirent *e;
    if (len >= 200)
        return NULL;
    if (chip_spec[0] == '/') {
        snprintf(path, sizeof path, "%.*s", (int)len, chip_spec);
        return gpiod_chip_open(path);
    }
    if (len > 8 && strncmp(chip_spec, "gpiochip", 8) == 0) {
        snprintf(path, sizeof path, "/dev/%.*s", (int)len, chip_spec);
        return gpiod_chip_open(path);
    }
    /* a label: look at every chip */
    d = opendir("/dev");
    if (!d)
        return NULL;
    while ((e = readdir(d)) != NULL) {
        struct gpiod_chip *c;
        struct gpiod_chip_info *info;
        int match = 0;
        if (strncmp(e->d_name, "gpiochip", 8) != 0)
            continue;
        snprintf(path, sizeof path, "/dev/%s", e->d_name);
        c = gpiod_chip_open(path);
        if (!c)
            continue;
        info = gpiod_chip_get_info(c);
        if (info) {
            const char *label = gpiod_chip_info_get_label(info);
            match = strlen(label) == len && strncmp(label, chip_spec, len) == 0;
            gpiod_chip_info_free(info);
        }
        if (match) {
            closedir(d);
            return c;
        }
        gpiod_chip_close(c);
    }
    closedir(d);
    return NULL;
}

/* Offset of a line (name or number) on chip, or -1. */
static int find_offset(struct gpiod_chip *chip, const char *name)
{
    const char *s = name;
    char *end;
    long v;
    if (*s >= '0' && *s <= '9') {
        v = strtol(s, &end, 10);
        if (*end == '\0' && v >= 0 && v < 65536)
            return (int)v;
    }
    return gpiod_chip_get_line_offset_from_name(chip, name);
}

/* Resolves "[!]CHIP:LINE" or "[!]LINE" to an open chip and an offset. */
static int resolve(const char *spec, struct gpiod_chip **chip, unsigned *offset, int *bang,
                   char *err, size_t errlen, const char *role)
{
    const char *s = spec, *colon;
    *bang = 0;
    if (*s == '!') {
        *bang = 1;
        s++;
    }
    colon = strrchr(s, ':');
    if (colon) {
        int off;
        *chip = open_chip(s, (size_t)(colon - s));
        if (!*chip) {
            stp_error_set(err, errlen, "%s line '%s': no GPIO chip '%.*s' (%s)", role, spec,
                    (int)(colon - s), s, strerror(errno ? errno : ENOENT));
            return -1;
        }
        off = find_offset(*chip, colon + 1);
        if (off < 0) {
            stp_error_set(err, errlen, "%s line '%s': no line '%s' on that chip", role, spec,
                    colon + 1);
            gpiod_chip_close(*chip);
            *chip = NULL;
            return -1;
        }
        *offset = (unsigned)off;
        return 0;
    } else {
        DIR *d = opendir("/dev");
        struct dirent *e;
        char path[300];
        while (d && (e = readdir(d)) != NULL) {
            struct gpiod_chip *c;
            int off;
            if (strncmp(e->d_name, "gpiochip", 8) != 0)
                continue;
            snprintf(path, sizeof path, "/dev/%s", e->d_name);
            c = gpiod_chip_open(path);
            if (!c)
                continue;
            off = gpiod_chip_get_line_offset_from_name(c, s);
            if (off >= 0) {
                closedir(d);
                *chip = c;
                *offset = (unsigned)off;
                return 0;
            }
            gpiod_chip_close(c);
        }
        if (d)
            closedir(d);
        stp_error_set(err, errlen, "%s line '%s' not found on any GPIO chip", role, spec);
        return -1;
    }
}

static int request_line(line *l, int role, const char *spec, const char *consumer, char *err,
                        size_t errlen)
{
    struct gpiod_line_settings *ls = NULL;
    struct gpiod_line_config *lc = NULL;
    struct gpiod_request_config *rc = NULL;
    int bang, active_low, rcode = -1, tries;

    if (resolve(spec, &l->chip, &l->offset, &bang, err, errlen, line_role[role]) != 0)
        return -1;
    /* reset is asserted low; the others are asserted high; '!' inverts */
    active_low = (role == L_RESET) ^ bang;
    for (tries = 0; tries < 2 && rcode != 0; tries++) {
        ls = gpiod_line_settings_new();
        lc = gpiod_line_config_new();
        rc = gpiod_request_config_new();
        if (!ls || !lc || !rc) {
            stp_error_set(err, errlen, "%s line: out of memory", line_role[role]);
            break;
        }
        gpiod_line_settings_set_active_low(ls, active_low);
        if (role == L_BUSY) {
            gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_INPUT);
            l->edges = tries == 0; /* second try: no interrupts, poll */
            if (l->edges)
                gpiod_line_settings_set_edge_detection(ls, GPIOD_LINE_EDGE_BOTH);
        } else {
            gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_OUTPUT);
            gpiod_line_settings_set_output_value(ls, GPIOD_LINE_VALUE_INACTIVE);
        }
        gpiod_request_config_set_consumer(rc, consumer ? consumer : "stipple");
        if (gpiod_line_config_add_line_settings(lc, &l->offset, 1, ls) == 0) {
            l->req = gpiod_chip_request_lines(l->chip, rc, lc);
            if (l->req)
                rcode = 0;
        }
        if (rcode != 0 && (role != L_BUSY || tries == 1))
            stp_error_set(err, errlen, "%s line '%s' (offset %u): cannot request it: %s",
                    line_role[role], spec, l->offset, strerror(errno));
        gpiod_line_settings_free(ls);
        gpiod_line_config_free(lc);
        gpiod_request_config_free(rc);
        ls = NULL;
        lc = NULL;
        rc = NULL;
        if (role != L_BUSY)
            break;
    }
    return rcode;
}

stp_gpio_panel *stp_gpio_panel_open(const stp_gpio_panel_config *cfg, char *err, size_t errlen)
{
    stp_gpio_panel *p;
    const char *specs[L_COUNT];
    int i;
    if (!cfg) {
        stp_error_set(err, errlen, "no GPIO configuration");
        return NULL;
    }
#ifdef STP_GPIO_LOAD
    if (stp_gpiod_load(err, errlen) != 0)
        return NULL;
#endif
    specs[L_RESET] = cfg->reset;
    specs[L_DC] = cfg->dc;
    specs[L_BUSY] = cfg->busy;
    specs[L_ENABLE] = cfg->enable;
    specs[L_BACKLIGHT] = cfg->backlight;
    specs[L_VCOM] = cfg->vcom;
    p = calloc(1, sizeof *p);
    if (!p) {
        stp_error_set(err, errlen, "out of memory");
        return NULL;
    }
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->cond, NULL);
    for (i = 0; i < L_COUNT; i++)
        if (specs[i] && specs[i][0] &&
            request_line(&p->lines[i], i, specs[i], cfg->consumer, err, errlen) != 0) {
            stp_gpio_panel_close(p);
            return NULL;
        }
    p->events = gpiod_edge_event_buffer_new(16);
    if (!p->events) {
        stp_error_set(err, errlen, "out of memory");
        stp_gpio_panel_close(p);
        return NULL;
    }
    return p;
}

static int set_line(stp_gpio_panel *p, int role, int active, char *err, size_t errlen)
{
    line *l = &p->lines[role];
    if (!l->req) {
        stp_error_set(err, errlen, "no %s line configured", line_role[role]);
        return -1;
    }
    if (gpiod_line_request_set_value(l->req, l->offset,
                                     active ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE)
        != 0) {
        stp_error_set(err, errlen, "%s line: cannot set it: %s", line_role[role], strerror(errno));
        return -1;
    }
    return 0;
}

int stp_gpio_panel_reset(stp_gpio_panel *p, unsigned assert_us, unsigned settle_us, char *err,
                         size_t errlen)
{
    if (!p || set_line(p, L_RESET, 1, err, errlen) != 0)
        return -1;
    sleep_us(assert_us);
    if (set_line(p, L_RESET, 0, err, errlen) != 0)
        return -1;
    sleep_us(settle_us);
    return 0;
}

int stp_gpio_panel_dc(stp_gpio_panel *p, int data, char *err, size_t errlen)
{
    return p ? set_line(p, L_DC, data != 0, err, errlen) : -1;
}

int stp_gpio_panel_enable(stp_gpio_panel *p, int on, char *err, size_t errlen)
{
    return p ? set_line(p, L_ENABLE, on != 0, err, errlen) : -1;
}

int stp_gpio_panel_backlight(stp_gpio_panel *p, int on, char *err, size_t errlen)
{
    return p ? set_line(p, L_BACKLIGHT, on != 0, err, errlen) : -1;
}

int stp_gpio_panel_wait_ready(stp_gpio_panel *p, unsigned timeout_ms, char *err, size_t errlen)
{
    line *l;
    int64_t deadline;
    if (!p)
        return -1;
    l = &p->lines[L_BUSY];
    if (!l->req) {
        stp_error_set(err, errlen, "no busy line configured");
        return -1;
    }
    deadline = now_ns() + (int64_t)timeout_ms * 1000000;
    for (;;) {
        enum gpiod_line_value v = gpiod_line_request_get_value(l->req, l->offset);
        int64_t left;
        if (v == GPIOD_LINE_VALUE_ERROR) {
            stp_error_set(err, errlen, "busy line: cannot read it: %s", strerror(errno));
            return -1;
        }
        if (v == GPIOD_LINE_VALUE_INACTIVE)
            return 0;
        left = deadline - now_ns();
        if (left <= 0) {
            stp_error_set(err, errlen, "panel still busy after %u ms", timeout_ms);
            return -1;
        }
        if (l->edges) {
            int r = gpiod_line_request_wait_edge_events(l->req, left);
            if (r < 0) {
                stp_error_set(err, errlen, "busy line: waiting for an edge: %s", strerror(errno));
                return -1;
            }
            if (r > 0 && gpiod_line_request_read_edge_events(l->req, p->events, 16) < 0) {
                stp_error_set(err, errlen, "busy line: reading edges: %s", strerror(errno));
                return -1;
            }
        } else {
            sleep_us(left < 1000000 ? (unsigned)(left / 1000) : 1000u);
        }
    }
}

int stp_gpio_panel_vcom_toggle(stp_gpio_panel *p, char *err, size_t errlen)
{
    int level;
    if (!p)
        return -1;
    pthread_mutex_lock(&p->lock);
    level = !p->vcom_level;
    if (set_line(p, L_VCOM, level, err, errlen) == 0)
        p->vcom_level = level;
    else
        level = -1;
    pthread_mutex_unlock(&p->lock);
    return level;
}

static void *vcom_main(void *arg)
{
    stp_gpio_panel *p = arg;
    struct timespec next;
    clock_gettime(CLOCK_MONOTONIC, &next);
    pthread_mutex_lock(&p->lock);
    while (!p->vcom_stop) {
        int r;
        next.tv_nsec += (long)p->vcom_half_ms * 1000000L;
        while (next.tv_nsec >= 1000000000L) {
            next.tv_nsec -= 1000000000L;
            next.tv_sec++;
        }
        /* the condition variable uses CLOCK_MONOTONIC (see start) */
        do
            r = pthread_cond_timedwait(&p->cond, &p->lock, &next);
        while (r == 0 && !p->vcom_stop);
        if (p->vcom_stop)
            break;
        {
            /* woken far too late (a loaded system): restart the schedule
             * from now instead of catching up with a burst of edges */
            struct timespec now;
            int64_t late;
            clock_gettime(CLOCK_MONOTONIC, &now);
            late = ((int64_t)now.tv_sec - next.tv_sec) * 1000000000 + (now.tv_nsec - next.tv_nsec);
            if (late > (int64_t)p->vcom_half_ms * 500000)
                next = now;
        }
        if (set_line(p, L_VCOM, !p->vcom_level, NULL, 0) == 0)
            p->vcom_level = !p->vcom_level;
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

int stp_gpio_panel_vcom_start(stp_gpio_panel *p, unsigned hz, char *err, size_t errlen)
{
    pthread_condattr_t ca;
    if (!p)
        return -1;
    if (!p->lines[L_VCOM].req) {
        stp_error_set(err, errlen, "no vcom line configured");
        return -1;
    }
    if (hz == 0 || hz > 500) {
        stp_error_set(err, errlen, "vcom: %u Hz out of range (1..500)", hz);
        return -1;
    }
    stp_gpio_panel_vcom_stop(p);
    pthread_cond_destroy(&p->cond);
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    pthread_cond_init(&p->cond, &ca);
    pthread_condattr_destroy(&ca);
    p->vcom_half_ms = 500u / hz;
    if (p->vcom_half_ms == 0)
        p->vcom_half_ms = 1;
    p->vcom_stop = 0;
    if (pthread_create(&p->vcom_thread, NULL, vcom_main, p) != 0) {
        stp_error_set(err, errlen, "vcom: cannot start the toggling thread");
        return -1;
    }
    p->vcom_running = 1;
    return 0;
}

void stp_gpio_panel_vcom_stop(stp_gpio_panel *p)
{
    if (!p || !p->vcom_running)
        return;
    pthread_mutex_lock(&p->lock);
    p->vcom_stop = 1;
    pthread_cond_broadcast(&p->cond);
    pthread_mutex_unlock(&p->lock);
    pthread_join(p->vcom_thread, NULL);
    p->vcom_running = 0;
}

void stp_gpio_panel_close(stp_gpio_panel *p)
{
    int i;
    if (!p)
        return;
    stp_gpio_panel_vcom_stop(p);
    for (i = 0; i < L_COUNT; i++) {
        if (p->lines[i].req)
            gpiod_line_request_release(p->lines[i].req);
        if (p->lines[i].chip)
            gpiod_chip_close(p->lines[i].chip);
    }
    if (p->events)
        gpiod_edge_event_buffer_free(p->events);
    pthread_cond_destroy(&p->cond);
    pthread_mutex_destroy(&p->lock);
    free(p);
}
