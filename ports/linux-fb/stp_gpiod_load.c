/* SPDX-License-Identifier: MIT */
/*
 * libgpiod v2 loaded when the first control line is opened, not linked:
 * the functions stp_gpio.c calls, defined here with libgpiod's own
 * prototypes (<gpiod.h>), each forwarding to the one dlsym finds in
 * libgpiod.so.3.  So a stipple command built where libgpiod 2 was found
 * still starts on a machine without it (plain Debian 12 has only
 * libgpiod 1), and only a device spec that names GPIO lines needs it.
 *
 * Built into stipple_gpio with STP_GPIO_LOAD=1 (ports/linux-fb/CMakeLists.txt);
 * programs that link libgpiod themselves (the static gpio-sim test) leave
 * this file out.  When the library cannot be loaded, every forwarder fails
 * the way libgpiod reports errors (NULL or -1, errno = ELIBACC), and
 * stp_gpiod_load has already said why.
 */
#include "stp_gpiod_load.h"
#include "stp_error.h"

#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include <gpiod.h>

#define STP_GPIOD_SONAME "libgpiod.so.3"

static pthread_once_t load_once = PTHREAD_ONCE_INIT;
static void *library;                 /* dlopen's handle; NULL: not loaded */
static char load_error[256];          /* dlerror's text when it failed */

static void load_library(void)
{
    library = dlopen(STP_GPIOD_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char *why = dlerror();
        snprintf(load_error, sizeof load_error, "%s", why ? why : "not found");
    }
}

int stp_gpiod_load(char *err, size_t errlen)
{
    pthread_once(&load_once, load_library);
    if (library)
        return 0;
    stp_error_set(err, errlen,
                  "GPIO control lines need libgpiod 2 (" STP_GPIOD_SONAME
                  "; Debian 12: libgpiod3 from bookworm-backports): %s",
                  load_error);
    return -1;
}

/* The address of NAME in the loaded library, or NULL (errno = ELIBACC). */
static void *symbol(const char *name)
{
    void *address = NULL;
    if (stp_gpiod_load(NULL, 0) == 0)
        address = dlsym(library, name);
    if (!address)
        errno = ELIBACC;
    return address;
}

/* A forwarder for a function returning a value (FAIL when not loaded) and
 * one returning nothing.  The object pointer becomes a function pointer by
 * memcpy, as POSIX's dlsym specifies (ISO C has no such conversion). */
#define STP_FORWARD(ret, name, params, args, fail)                                                 \
    ret name params                                                                                \
    {                                                                                              \
        ret(*fn) params;                                                                           \
        void *address = symbol(#name);                                                             \
        if (!address)                                                                              \
            return fail;                                                                           \
        memcpy(&fn, &address, sizeof fn);                                                          \
        return fn args;                                                                            \
    }
#define STP_FORWARD_VOID(name, params, args)                                                       \
    void name params                                                                               \
    {                                                                                              \
        void(*fn) params;                                                                          \
        void *address = symbol(#name);                                                             \
        if (!address)                                                                              \
            return;                                                                                \
        memcpy(&fn, &address, sizeof fn);                                                          \
        fn args;                                                                                   \
    }

STP_FORWARD(struct gpiod_chip *, gpiod_chip_open, (const char *path), (path), NULL)
STP_FORWARD_VOID(gpiod_chip_close, (struct gpiod_chip *chip), (chip))
STP_FORWARD(struct gpiod_chip_info *, gpiod_chip_get_info, (struct gpiod_chip *chip), (chip), NULL)
STP_FORWARD_VOID(gpiod_chip_info_free, (struct gpiod_chip_info *info), (info))
STP_FORWARD(const char *, gpiod_chip_info_get_label, (struct gpiod_chip_info *info), (info), NULL)
STP_FORWARD(int, gpiod_chip_get_line_offset_from_name, (struct gpiod_chip *chip, const char *name),
            (chip, name), -1)
STP_FORWARD(struct gpiod_line_request *, gpiod_chip_request_lines,
            (struct gpiod_chip *chip, struct gpiod_request_config *req_cfg,
             struct gpiod_line_config *line_cfg),
            (chip, req_cfg, line_cfg), NULL)
STP_FORWARD(struct gpiod_line_settings *, gpiod_line_settings_new, (void), (), NULL)
STP_FORWARD_VOID(gpiod_line_settings_free, (struct gpiod_line_settings *settings), (settings))
STP_FORWARD_VOID(gpiod_line_settings_set_active_low,
                 (struct gpiod_line_settings *settings, bool active_low), (settings, active_low))
STP_FORWARD(int, gpiod_line_settings_set_direction,
            (struct gpiod_line_settings *settings, enum gpiod_line_direction direction),
            (settings, direction), -1)
STP_FORWARD(int, gpiod_line_settings_set_edge_detection,
            (struct gpiod_line_settings *settings, enum gpiod_line_edge edge), (settings, edge), -1)
STP_FORWARD(int, gpiod_line_settings_set_output_value,
            (struct gpiod_line_settings *settings, enum gpiod_line_value value), (settings, value),
            -1)
STP_FORWARD(struct gpiod_line_config *, gpiod_line_config_new, (void), (), NULL)
STP_FORWARD_VOID(gpiod_line_config_free, (struct gpiod_line_config *config), (config))
STP_FORWARD(int, gpiod_line_config_add_line_settings,
            (struct gpiod_line_config *config, const unsigned int *offsets, size_t num_offsets,
             struct gpiod_line_settings *settings),
            (config, offsets, num_offsets, settings), -1)
STP_FORWARD(struct gpiod_request_config *, gpiod_request_config_new, (void), (), NULL)
STP_FORWARD_VOID(gpiod_request_config_free, (struct gpiod_request_config *config), (config))
STP_FORWARD_VOID(gpiod_request_config_set_consumer,
                 (struct gpiod_request_config *config, const char *consumer), (config, consumer))
STP_FORWARD_VOID(gpiod_line_request_release, (struct gpiod_line_request *request), (request))
STP_FORWARD(enum gpiod_line_value, gpiod_line_request_get_value,
            (struct gpiod_line_request *request, unsigned int offset), (request, offset),
            GPIOD_LINE_VALUE_ERROR)
STP_FORWARD(int, gpiod_line_request_set_value,
            (struct gpiod_line_request *request, unsigned int offset, enum gpiod_line_value value),
            (request, offset, value), -1)
STP_FORWARD(int, gpiod_line_request_wait_edge_events,
            (struct gpiod_line_request *request, int64_t timeout_ns), (request, timeout_ns), -1)
STP_FORWARD(int, gpiod_line_request_read_edge_events,
            (struct gpiod_line_request *request, struct gpiod_edge_event_buffer *buffer,
             size_t max_events),
            (request, buffer, max_events), -1)
STP_FORWARD(struct gpiod_edge_event_buffer *, gpiod_edge_event_buffer_new, (size_t capacity),
            (capacity), NULL)
STP_FORWARD_VOID(gpiod_edge_event_buffer_free, (struct gpiod_edge_event_buffer *buffer), (buffer))
