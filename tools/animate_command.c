/* SPDX-License-Identifier: MIT */
/* stipple animate: see animate_command.h and docs/animate.md. */
#define _POSIX_C_SOURCE 200809L
#include "animate_command.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "animate.h"
#include "options.h"
#include "scene.h"
#include "stp_posix.h"
#include "stp_posix_png.h"
#if STP_HAVE_GIF
#include "stp_posix_gif.h"
#endif

void stp_tool_animate_usage(FILE *to)
{
    fprintf(to,
            "usage: stipple animate SCENE -o OUT.gif [options]\n"
            "       stipple animate SCENE -o frame%%03d.pbm|frame%%03d.png [options]\n"
            "\n"
            "Draws SCENE (.nff, .obj, .off, .ply) from a moving camera as 1-bit frames:\n"
            "an animated GIF that loops (lit pixels white on black, as an OLED shows\n"
            "them), or numbered files, 1-bit PBM or 1-bit PNG, numbered from 0 by the\n"
            "printf-style %%d in OUT (%%03d: three digits).  Frames do not flicker by\n"
            "default: the blue-noise screen (its thresholds stay put on the panel while\n"
            "the picture moves) and one exposure for the whole sequence.  Without --eye\n"
            "or --at keys the camera makes one whole turn.\n"
            "\n"
            "  -o, --output OUT         NAME.gif, or a pattern with one %%d and .pbm/.png\n"
            "  -n, --frames N           frames, 1..%d (default 60)\n"
            "      --orbit DEGREES      the camera's turn about the up axis through the\n"
            "                           look-at point over all the frames (frame i at\n"
            "                           DEGREES * i / N; 360 loops; default 360 without\n"
            "                           --eye/--at keys, else 0); the lights turn with it\n"
            "      --elevation DEGREES  the eye's height as an angle above the look-at\n"
            "                           point's horizon, -89..89 (default: the view's)\n"
            "      --hold STEPS         a pixel flips only when its grey moves this many\n"
            "                           steps of 255 past its threshold (default %d; 0: the\n"
            "                           plain screen, each frame as a still would be)\n"
            "      --fps N              GIF frames per second, 1..100 (default 20)\n"
            "      --stats              print the exposure and the mean share of pixels\n"
            "                           that change between frames on stderr\n"
            "      --scene-format KIND  nff, obj, off or ply, when SCENE's name does not say\n",
            STP_TOOL_MAX_FRAMES, STP_TOOL_DEFAULT_HOLD);
    stp_tool_camera_help(to, 1);
    fprintf(to, "  -h, --help               this help\n"
                "\n"
                "The render options below apply to every frame; the defaults differ from a\n"
                "still's: -d blue-noise, -l 256, --exposure auto over all the frames.\n");
    stp_tool_options_help(to);
}

enum {
    OPT_ORBIT = STP_TOOL_OPT_COMMAND,
    OPT_ELEVATION,
    OPT_FPS,
    OPT_STATS,
    OPT_SCENE_FORMAT,
    OPT_HOLD
};

/* Where the frames go: a GIF, or numbered files. */
typedef struct animation_output {
    const char *path;
    int gif;                  /* 1: path is a .gif */
    int png;                  /* numbered: 1 for 1-bit PNG, 0 for PBM */
    size_t prefix_len;        /* numbered: path[0..prefix_len) before the %d */
    int digits;               /* the %0Nd's N (0: as many as needed) */
    const char *suffix;       /* after the %d */
#if STP_HAVE_GIF
    stp_posix_gif frames;
#endif
} animation_output;

/* A numbered pattern: one "%d" or "%0Nd" and no other '%', ending in .pbm
 * or .png.  Returns 0, or -1. */
static int parse_pattern(const char *path, animation_output *o)
{
    const char *p = strchr(path, '%'), *q;
    size_t n;
    if (!p)
        return -1;
    q = p + 1;
    o->digits = 0;
    if (*q == '0')
        q++;
    while (*q >= '0' && *q <= '9' && o->digits < 100)
        o->digits = o->digits * 10 + (*q++ - '0');
    if (*q != 'd' || strchr(q, '%'))
        return -1;
    o->prefix_len = (size_t)(p - path);
    o->suffix = q + 1;
    n = strlen(o->suffix);
    if (n < 4 || (strcmp(o->suffix + n - 4, ".pbm") && strcmp(o->suffix + n - 4, ".png")))
        return -1;
    o->png = !strcmp(o->suffix + n - 4, ".png");
    return 0;
}

static int write_numbered(const animation_output *o, const stp_posix_frame *frame, int index, char *err,
                          size_t err_size)
{
    char name[4096];
    if (snprintf(name, sizeof name, "%.*s%0*d%s", (int)o->prefix_len, o->path, o->digits, index, o->suffix) >=
        (int)sizeof name) {
        snprintf(err, err_size, "%s: name too long", o->path);
        return -1;
    }
    return o->png ? stp_posix_write_png(frame, name, err, err_size)
                  : stp_posix_write(frame, name, STP_POSIX_FILE_P4, err, err_size);
}

static int take_frame(const stp_posix_frame *frame, int index, void *ctx, char *err, size_t err_size)
{
    animation_output *o = ctx;
#if STP_HAVE_GIF
    if (o->gif)
        return stp_posix_gif_add(&o->frames, frame, err, err_size);
#endif
    return write_numbered(o, frame, index, err, err_size);
}

/* The command line's own options (the shared ones are applied first). */
static int own_option(int c, const char *arg, stp_tool_motion *motion, int *orbit_given, int *fps,
                      int *show_stats, const char **out, const char **scene_format, char **argv)
{
    switch (c) {
    case 'o': *out = arg; return 0;
    case 'n':
        if (stp_tool_parse_int(arg, 1, STP_TOOL_MAX_FRAMES, &motion->frames))
            return stp_tool_usage_error("animate", "bad --frames '%s' (1..%d)", arg, STP_TOOL_MAX_FRAMES);
        return 0;
    case OPT_ORBIT:
        if (stp_tool_parse_double(arg, &motion->orbit_degrees) || fabs(motion->orbit_degrees) > 36000)
            return stp_tool_usage_error("animate", "bad --orbit '%s' (degrees, -36000..36000)", arg);
        *orbit_given = 1;
        return 0;
    case OPT_ELEVATION:
        if (stp_tool_parse_double(arg, &motion->elevation_degrees) || fabs(motion->elevation_degrees) > 89)
            return stp_tool_usage_error("animate", "bad --elevation '%s' (degrees, -89..89)", arg);
        motion->elevation_given = 1;
        return 0;
    case OPT_FPS:
        if (stp_tool_parse_int(arg, 1, 100, fps))
            return stp_tool_usage_error("animate", "bad --fps '%s' (1..100)", arg);
        return 0;
    case OPT_STATS: *show_stats = 1; return 0;
    case OPT_SCENE_FORMAT:
        if (!(*scene_format = stp_tool_parse_scene_format(arg)))
            return stp_tool_usage_error("animate", "bad --scene-format '%s' (nff, obj, off, ply)", arg);
        return 0;
    default: return stp_tool_getopt_error("animate", c, argv);
    }
}

/* Check OUT and set up o.  Returns 0, or the usage error's status. */
static int open_output(const char *out, animation_output *o, const stp_tool_options *opt)
{
    memset(o, 0, sizeof *o);
    o->path = out;
    if (!out)
        return stp_tool_usage_error("animate", "no output given (-o NAME.gif or -o frame%%03d.pbm)");
    if (strlen(out) >= 4 && !strcmp(out + strlen(out) - 4, ".gif")) {
#if STP_HAVE_GIF
        o->gif = 1;
        return stp_posix_gif_init(&o->frames, (uint32_t)opt->width, (uint32_t)opt->height) == 0 ? 0 : 1;
#else
        (void)opt;
        fprintf(stderr, "stipple animate: %s: this build has no GIF output (it needs giflib, Debian "
                        "package libgif-dev); numbered frames work: -o frame%%03d.pbm\n",
                out);
        return 1;
#endif
    }
    if (parse_pattern(out, o) != 0)
        return stp_tool_usage_error("animate", "%s: give NAME.gif, or a pattern with one %%d ending in "
                                               ".pbm or .png (frame%%03d.pbm)", out);
    return 0;
}

static int run(const char *scene_path, const char *scene_format, const stp_scene_options *sopt,
               const stp_tool_options *opt, const stp_tool_motion *motion, animation_output *o, int fps,
               int show_stats)
{
    stp_scene scene;
    stp_tool_animation_stats stats;
    char err[1024];
    int rc;
    if (stp_scene_load_as(scene_path, scene_format, sopt, &scene, err, sizeof err) != 0) {
        fprintf(stderr, "stipple: %s\n", err);
        return 1;
    }
    rc = stp_tool_animate(&scene, opt, motion, take_frame, o, &stats, err, sizeof err);
    stp_scene_free(&scene);
#if STP_HAVE_GIF
    if (rc == 0 && o->gif) {
        o->frames.delay_cs = (unsigned)lround(100.0 / fps);
        rc = stp_posix_gif_write(&o->frames, o->path, err, sizeof err);
    }
    if (o->gif)
        stp_posix_gif_free(&o->frames);
#else
    (void)fps;
#endif
    if (rc != 0) {
        fprintf(stderr, "stipple: %s: %s\n", scene_path, err);
        return 1;
    }
    if (show_stats)
        fprintf(stderr, "%s: %d frames of %dx%d, exposure gain %.4f, %.3f %% of pixels change between "
                        "frames on average (at most %.3f %%)\n",
                scene_path, stats.frames, opt->width, opt->height, stats.gain, 100 * stats.mean_changed,
                100 * stats.max_changed);
    return 0;
}

int stp_tool_animate_main(int argc, char **argv)
{
    static const struct option own[] = {
        {"output", required_argument, 0, 'o'},       {"frames", required_argument, 0, 'n'},
        {"orbit", required_argument, 0, OPT_ORBIT},  {"elevation", required_argument, 0, OPT_ELEVATION},
        {"fps", required_argument, 0, OPT_FPS},      {"stats", no_argument, 0, OPT_STATS},
        {"hold", required_argument, 0, OPT_HOLD},
        {"scene-format", required_argument, 0, OPT_SCENE_FORMAT},
        {"eye", required_argument, 0, STP_TOOL_OPT_EYE}, {"at", required_argument, 0, STP_TOOL_OPT_AT},
        {"up", required_argument, 0, STP_TOOL_OPT_UP}, {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    struct option longs[64];
    stp_tool_options opt;
    stp_scene_options sopt;
    stp_tool_motion motion;
    stp_tool_given given;
    animation_output o;
    const char *out = 0, *scene_format = 0;
    char err[512];
    int c, orbit_given = 0, fps = 20, show_stats = 0, rc;

    stp_tool_options_default(&opt);
    stp_scene_options_default(&sopt);
    memset(&motion, 0, sizeof motion);
    memset(&given, 0, sizeof given);
    motion.frames = 60;
    if (stp_tool_long_options(longs, sizeof longs / sizeof longs[0], own) != 0)
        return 1;
    opterr = 0;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":" STP_TOOL_SHORT_OPTIONS "o:n:h", longs, 0)) != -1) {
        int applied = stp_tool_apply_option(c, optarg, &opt, &sopt, err, sizeof err);
        if (applied == 0)
            applied = stp_tool_apply_camera_option(c, optarg, STP_TOOL_CAMERA_KEYS, &opt, err, sizeof err);
        if (c > 0 && c < STP_TOOL_OPT_COMMAND)
            given.code[c] = 1;
        if (applied < 0)
            return stp_tool_usage_error("animate", "%s", err);
        if (applied)
            continue;
        if (c == 'h') {
            stp_tool_animate_usage(stdout);
            return 0;
        }
        if (c == OPT_HOLD) {
            if (stp_tool_parse_int(optarg, 0, 255, &opt.hold))
                return stp_tool_usage_error("animate", "bad --hold '%s' (grey steps, 0..255)", optarg);
            opt.hold_given = 1;
            continue;
        }
        if ((rc = own_option(c, optarg, &motion, &orbit_given, &fps, &show_stats, &out, &scene_format, argv)))
            return rc;
    }
    if (optind >= argc)
        return stp_tool_usage_error("animate", "no scene given");
    if (optind < argc - 1)
        return stp_tool_usage_error("animate", "one scene only ('%s' is extra)", argv[optind + 1]);
    if (stp_tool_check_renderer(&given, opt.raytrace, err, sizeof err) != 0)
        return stp_tool_usage_error("animate", "%s", err);
    if (opt.colour)
        return stp_tool_usage_error("animate", "--colour: frames are 1-bit");
    if (!orbit_given)
        motion.orbit_degrees = opt.eye_count > 1 || opt.at_count > 1 ? 0 : 360;
    stp_tool_animation_defaults(&opt);
    if ((rc = open_output(out, &o, &opt)) != 0)
        return rc;
    return run(argv[optind], scene_format, &sopt, &opt, &motion, &o, fps, show_stats);
}
