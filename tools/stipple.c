/* SPDX-License-Identifier: MIT */
/* The stipple command: render a scene, or halftone an image. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "animate_command.h"
#include "camera.h"
#include "compile_scene.h"
#include "options.h"
#include "outlines.h"
#include "palette.h"
#include "palette_output.h"
#include "progress.h"
#include "rt_compare.h"
#if STP_HAVE_DEVICE
#include "stp_device.h"
#endif
#include "render_scene.h"
#include "scene.h"
#include "scenegen.h"
#include "stp_posix.h"
#include "stp_posix_bitmap.h"
#if STP_HAVE_JPEG
#include "stp_posix_jpeg.h"
#endif
#include "image_ops.h"
#include "stp_posix_png.h"

static const char *program = "stipple";

static void usage_main(FILE *to)
{
    fprintf(to,
            "usage: stipple COMMAND [options]\n"
            "\n"
            "commands:\n"
            "  render SCENE -o OUT   render an NFF, OBJ, OFF or PLY scene to PBM, PGM, PPM,\n"
            "                        PNG or text\n"
            "  animate SCENE -o OUT.gif  a scene from a moving camera: an animated GIF or\n"
            "                        numbered PBM/PNG frames (see 'stipple animate --help')\n"
            "  dither IMAGE -o OUT   halftone a PNG, PGM or PPM image to PBM or 1-bit PNG\n"
            "  compile SCENE -o OUT.c  write a scene as C source and a minimal configuration\n"
            "                        header for firmware (see 'stipple compile --help')\n"
            "  scene NAME -o OUT.nff write a procedural scene (teapot, tetra, sphereflake,\n"
            "                        torus, rings, mountain; see 'stipple scene --help')\n"
            "  bench [SCENE...]      ray tracer speed (rays/s, us/frame, with and without its\n"
            "                        hierarchy) and error against the double reference\n"
            "  help [COMMAND]        show help\n"
            "  --version             print the version and exit\n"
            "\n"
            "Run 'stipple COMMAND --help' for a command's options.\n");
}

static void usage_render(FILE *to)
{
    fprintf(to,
            "usage: stipple render SCENE -o OUT [options]\n"
            "       stipple render SCENE --device SPEC [options]\n"
            "\n"
            "Renders SCENE (.nff, .obj, .off, .ply; '-' reads standard input, which needs\n"
            "--scene-format) with the fixed-point core.  OUT's extension picks the output:\n"
            ".pbm (halftoned 1-bit), .pgm (grey), .ppm (colour file of the grey picture, or\n"
            "of the colour one with --color), .png (grey, or colour with --color or\n"
            "--palette; --format png1 for halftoned 1-bit), .txt (line-printer text, one\n"
            "character per pixel), .xbm (1-bit X bitmap, u8g2 drawXBMP), .h (1-bit C array\n"
            "of rows, Adafruit GFX drawBitmap; --format c-pages: SSD1306 pages); '-' writes\n"
            "to stdout in the --format given (default txt).\n"
            "PNG: -o X.png writes 8-bit grey; --format png1 the 1-bit picture a panel shows.\n"
            "Grey and colour pictures have 256 levels unless --levels says otherwise;\n"
            "1-bit pictures, text and --palette 16.  Options the chosen renderer or output\n"
            "does not use are refused.\n"
            "\n"
            "  -o, --output FILE        where to write\n"
            "      --scene-format KIND  nff, obj, off or ply: the scene's format when its\n"
            "                           name does not say (needed for '-')\n"
            "      --device SPEC        draw on a Linux device instead, at its size and format:\n"
            "                           fb:/dev/fbN, usb:VID:PID or usb (receipt printer),\n"
            "                           spi:/dev/spidevB.C,controller=ssd1306|sharp-ls013b7dh03|\n"
            "                           ssd1680|ssd1680-128x296,dc=LINE,reset=LINE,busy=LINE,...\n"
            "                           (see ports/linux-fb/stp_device.h)\n"
            "      --format KIND        pbm, plain-pbm, pgm, ppm, png, png1, txt, xbm, c or\n"
            "                           c-pages (default: from OUT)\n"
            "      --invert             lit and unlit (grey: light and dark) swapped; text:\n"
            "                           the background prints as blanks unless --invert\n"
            "  -b, --band ROWS          render in bands of ROWS rows (default: whole frame)\n"
            "      --stats              print display-file and memory figures on stderr\n"
            "      --palette grey|pseudo  .ppm/.png through a 256-entry colour table: the frame is\n"
            "                           an indexed frame buffer of styles; pseudo maps dark to\n"
            "                           blue and light to red; --gamma applies per primary\n"
            "      --palette bw|bwr|grey4|grey16|rgb8|FILE  the picture in 256 levels (colour\n"
            "                           unless the palette is grey) dithered to the palette\n"
            "                           (-d, default fs); .png, .ppm (.pgm for greys)\n"
            "      --planes PREFIX      with --palette bwr: also PREFIX.bw, PREFIX.red, the\n"
            "                           SSD1680's RAM planes (docs/palettes.md)\n"
            "      --outlines KIND      draw silhouette, crease or both edges as lines over\n"
            "                           the polygons, where visible (docs/outlines.md), or\n"
            "                           none; default for a 1-bit picture file without -d:\n"
            "                           silhouettes when the objects would not stand out\n"
            "      --crease-angle DEG   normals further apart make a crease (default 40)\n"
            "      --outline-level L    the lines' shade 0..1 (default 0, black), or auto:\n"
            "                           white on a dark background\n"
            "      --no-rescale         give the core the scene's coordinates as they are (as\n"
            "                           a firmware would), not scaled into its range: a point\n"
            "                           beyond +-32767 units from the eye is refused\n"
            "  -h, --help               this help\n");
    stp_tool_camera_help(to, 0);
    stp_tool_options_help(to);
}

static void usage_help(FILE *to)
{
    fprintf(to, "usage: stipple help [COMMAND]\n"
                "\n"
                "Prints the commands, or the options of COMMAND (the same as\n"
                "'stipple COMMAND --help').\n");
}

static void usage_dither(FILE *to)
{
    fprintf(to,
            "usage: stipple dither IMAGE -o OUT.pbm [options]\n"
            "       stipple dither IMAGE -o OUT.png --palette PALETTE [--planes PREFIX]\n"
            "\n"
            "Halftones a PNG, JPEG, PGM or PPM image ('-' reads standard input; colour\n"
            "through luminance, alpha ignored) with an ordered-dither cell or error\n"
            "diffusion (-d fs, atkinson, ...), after turning, mirroring and resizing it to\n"
            "the panel (--rotate, --flip, --size: in that order), and --invert.\n"
            "With bayer2/4/8 the pixels equal ImageMagick's -ordered-dither o2x2/o4x4/o8x8.\n"
            "\n"
            "  -o, --output FILE     where to write: .pbm, .png (1-bit PNG), .xbm (X bitmap,\n"
            "                        u8g2 drawXBMP), .h (C array of rows, Adafruit GFX\n"
            "                        drawBitmap); '-' for PBM on stdout\n"
            "      --format KIND     pbm, plain-pbm, png1, xbm, c (rows) or c-pages (SSD1306\n"
            "                        pages: a byte a column of 8 rows) (default: from OUT)\n"
            "  -s, --size WxH        resize to the panel first (area average), as --resize\n"
            "      --resize MODE     fit (default: the whole image, black bars), fill (the\n"
            "                        panel covered, the middle kept) or stretch\n"
            "      --rotate DEG      turn clockwise first: 90, 180 or 270\n"
            "      --flip            mirror left to right (upside down: --rotate 180 --flip)\n"
            "      --invert          the negative: light pixels unlit (paper vs OLED)\n"
            "      --plain           write plain PBM (P1) instead of raw (P4)\n"
            "  -d, --dither CELL     as for render (default bayer4)\n"
            "      --spacing KIND    linear (default), exponential, cubic\n"
            "  -g, --gamma G         apply V = (I/k)^(1/G) to the grey first (default 1)\n"
            "      --linear          turn sRGB grey into linear light first (a panel's\n"
            "                        density of lit pixels is linear light)\n"
            "      --gamma-k K       (default 1)\n"
            "      --palette P       dither to a palette instead of black and white: bw, bwr\n"
            "                        (black/white/red e-paper), grey4, grey16, rgb8 or a file\n"
            "                        of 'R G B' lines; colour kept, nearest colour per pixel,\n"
            "                        error per channel; writes .png, .ppm (.pgm for greys)\n"
            "      --planes PREFIX   with --palette bwr: also PREFIX.bw and PREFIX.red, the\n"
            "                        SSD1680's two RAM planes (docs/palettes.md)\n"
            "  -h, --help            this help\n");
}

/* stp_tool_render, from the camera of --eye, --at and --up when given. */
static int render_with_camera(const stp_scene *scene, const stp_tool_options *opt, stp_port *port,
                              stp_tool_stats *stats, char *err, size_t err_size)
{
    stp_tool_camera_scene moved;
    stp_tool_options still;
    int rc;
    if (!stp_tool_camera_wanted(opt))
        return stp_tool_render(scene, opt, port, stats, err, err_size);
    if (stp_tool_camera_apply(scene, opt, NULL, 0, &moved, &still, err, err_size) != 0)
        return -1;
    rc = stp_tool_render(&moved.scene, &still, port, stats, err, err_size);
    stp_tool_camera_free(&moved);
    return rc;
}

/* Print "stipple: <message>" on stderr; returns the exit status 1. */
static int fail(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", program);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 1;
}

/* png: 1 for "png" (grey, or RGB with --color or --palette: *kind is
 * settled once the options are known), 2 for "png1" (1-bit), else 0. */
static int parse_kind(const char *s, stp_posix_file_kind *kind, int *png, int *bitmap)
{
    *png = 0;
    *bitmap = 0;
    if (!strcmp(s, "xbm") || !strcmp(s, "c") || !strcmp(s, "c-pages")) {
        *bitmap = 1 + (s[0] == 'x' ? STP_POSIX_BITMAP_XBM
                                   : s[1] ? STP_POSIX_BITMAP_PAGES : STP_POSIX_BITMAP_ROWS);
        *kind = STP_POSIX_FILE_P4;
    } else if (!strcmp(s, "png"))
        *png = 1;
    else if (!strcmp(s, "png1")) {
        *png = 2;
        *kind = STP_POSIX_FILE_P4;
    } else if (!strcmp(s, "pbm"))
        *kind = STP_POSIX_FILE_P4;
    else if (!strcmp(s, "plain-pbm"))
        *kind = STP_POSIX_FILE_P1;
    else if (!strcmp(s, "pgm"))
        *kind = STP_POSIX_FILE_P5;
    else if (!strcmp(s, "ppm"))
        *kind = STP_POSIX_FILE_P6;
    else if (!strcmp(s, "txt"))
        *kind = STP_POSIX_FILE_ASCII;
    else
        return -1;
    return 0;
}

static stp_pixel_format format_for_kind(stp_posix_file_kind kind)
{
    switch (kind) {
    case STP_POSIX_FILE_P4:
    case STP_POSIX_FILE_P1: return STP_PIXEL_MONO1;
    case STP_POSIX_FILE_P5: return STP_PIXEL_GREY8;
    case STP_POSIX_FILE_P6: return STP_PIXEL_RGB888;
    default: return STP_PIXEL_STYLE8;
    }
}

enum {
    OPT_FORMAT = STP_TOOL_OPT_COMMAND,
    OPT_STATS,
    OPT_PLAIN,
    OPT_PALETTE,
    OPT_DEVICE,
    OPT_BENCH_SCENES,
    OPT_BENCH_BUDGET,
    OPT_SCENE_FORMAT,
    OPT_LINEAR,
    OPT_PLANES,
    OPT_OUTLINES,
    OPT_CREASE_ANGLE,
    OPT_OUTLINE_LEVEL,
    OPT_NO_RESCALE,
    OPT_INVERT,
    OPT_RESIZE,
    OPT_ROTATE,
    OPT_FLIP
};

/* The line printer's characters the other way round: light styles print
 * dense characters, for a dark background printed as blanks. */
static const uint8_t lineprinter_light[16] = {' ', '.', ':', '-', '+', '=', 'o', 'a',
                                              'k', '#', '$', '%', 'B', '&', 'M', '@'};

/* 1 when the picture's background (--background, else the scene's, else the
 * core's black) is dark: luminance below one half. */
static int dark_background(const stp_scene *scene, const stp_tool_options *opt)
{
    const double *b = opt->background_given ? opt->background_rgb
                                            : scene->has_background ? scene->background : 0;
    return !b || 0.30 * b[0] + 0.59 * b[1] + 0.11 * b[2] < 0.5;
}

/* --invert: lit and unlit swapped (MONO1), or each byte v made 255 - v. */
static void invert_frame(stp_posix_frame *f)
{
    size_t i, n = f->stride * f->height;
    for (i = 0; i < n; i++)
        f->pixels[i] = (uint8_t)(255 - f->pixels[i]);
}

/* A note when the scene's file asks for another size (NFF "resolution")
 * than the one drawn because --size was not given; for a person at a
 * terminal (scripts and logs that read stderr see only errors). */
static void note_resolution(const char *path, const stp_scene *scene, const stp_tool_options *opt)
{
    if (isatty(STDERR_FILENO) && scene->resolution[0] > 0 && scene->resolution[1] > 0 &&
        (scene->resolution[0] != opt->width || scene->resolution[1] != opt->height))
        fprintf(stderr, "stipple: note: %s asks for %dx%d (its resolution line); drawing %dx%d, the "
                        "default: give --size to choose\n",
                path, scene->resolution[0], scene->resolution[1], opt->width, opt->height);
}

/* Turn an indexed frame buffer (STYLE8: style index 1..levels per pixel)
 * into RGB through a 256-entry colour table, grey or pseudocolour, with the
 * gamma table applied to each primary (docs/model.md section 6). */
static int index_to_colour(stp_posix_frame *frame, int levels, int pseudo, const stp_tool_options *opt)
{
    stp_colour_table table;
    stp_posix_frame rgb;
    uint8_t gamma[256];
    uint32_t x, y;
    if (pseudo)
        stp_colour_table_pseudocolour(&table);
    else
        stp_colour_table_grey(&table);
    if ((opt->gamma != 1.0 || opt->gamma_k != 1.0) &&
        stp_gamma_table(gamma, 256, stp_tool_fix(opt->gamma), stp_tool_fix(opt->gamma_k)) == 0)
        stp_colour_table_apply_gamma(&table, gamma, gamma, gamma);
    if (stp_posix_frame_init(&rgb, frame->width, frame->height, STP_PIXEL_RGB888) != 0)
        return -1;
    for (y = 0; y < frame->height; y++)
        for (x = 0; x < frame->width; x++) {
            int index = frame->pixels[y * frame->stride + x];
            uint32_t entry = table.entry[index < 1 ? 0 : ((index - 1) * 255 + (levels - 1) / 2) / (levels - 1)];
            uint8_t *p = &rgb.pixels[y * rgb.stride + 3 * x];
            p[0] = (uint8_t)(entry >> 16);
            p[1] = (uint8_t)(entry >> 8);
            p[2] = (uint8_t)entry;
        }
    stp_posix_frame_free(frame);
    *frame = rgb;
    /* the port points back at its frame: re-aim it after the move */
    frame->port.user = frame;
    return 0;
}

/* stipple render --device SPEC: the scene onto a Linux device (fbdev, USB
 * receipt printer, SPI panel; ports/linux-fb/stp_device.h).  The picture
 * takes the device's size and pixel format unless --size asks for less. */
static int render_to_device(const char *scene_path, const char *scene_format, const char *spec,
                            stp_tool_options *opt,
                            const stp_scene_options *sopt, int size_given, int show_stats)
{
#if STP_HAVE_DEVICE
    stp_scene scene;
    stp_device_options dopt;
    stp_device *dev;
    stp_port *port;
    stp_tool_stats stats;
    stp_progress progress;
    char err[512];
    int rc;
    if (stp_scene_load_as(scene_path, scene_format, sopt, &scene, err, sizeof err) != 0)
        return fail("%s", err);
    stp_device_options_default(&dopt);
    if (size_given) {
        dopt.width = (uint32_t)opt->width;
        dopt.height = (uint32_t)opt->height;
    }
    if (opt->colour)
        dopt.format = STP_PIXEL_RGB888;
    dev = stp_device_open(spec, &dopt, err, sizeof err);
    if (!dev) {
        stp_scene_free(&scene);
        return fail("%s", err);
    }
    port = stp_device_port(dev);
    opt->width = (int)port->width;
    opt->height = (int)port->height;
    rc = render_with_camera(&scene, opt,
                         stp_progress_wrap(&progress, port, opt->raytrace ? "ray tracing" : "rendering"),
                         &stats, err, sizeof err);
    stp_progress_finish(&progress);
    stp_scene_free(&scene);
    if (rc != 0) {
        const char *why = stp_device_error(dev);
        char message[1024];
        stp_tool_scene_message(message, sizeof message, scene_path, err);
        fprintf(stderr, "%s: %s%s%s\n", program, message, *why ? ": " : "", why);
        stp_device_close(dev);
        return 1;
    }
    if (stp_device_finish(dev, err, sizeof err) != 0) {
        stp_device_close(dev);
        return fail("%s", err);
    }
    if (show_stats)
        fprintf(stderr, "%s: drawn on %s\n", scene_path, stp_device_describe(dev));
    stp_device_close(dev);
    return 0;
#else
    (void)scene_path;
    (void)scene_format;
    (void)spec;
    (void)opt;
    (void)sopt;
    (void)size_given;
    (void)show_stats;
    return fail("render: this build has no Linux device ports (--device)");
#endif
}

/* Options that depend on the output: the halftone cell is for 1-bit
 * pictures only, text has its 16 characters as levels, an indexed frame
 * holds style indices 1..255 in a byte.  Picks the default levels: 256 for
 * grey and colour pictures (16 would posterise them), 16 otherwise. */
static int check_output_options(const stp_tool_given *given, stp_posix_file_kind kind,
                                int palette, stp_tool_options *opt, char *err, size_t err_size)
{
    int mono = kind == STP_POSIX_FILE_P4 || kind == STP_POSIX_FILE_P1;
    if (!mono && (given->code['d'] || given->code[STP_TOOL_OPT_SPACING])) {
        snprintf(err, err_size, "--%s halftones 1-bit pictures (.pbm) only",
                 given->code['d'] ? "dither" : "spacing");
        return -1;
    }
    if (kind == STP_POSIX_FILE_ASCII) {
        if (given->code['l'] && opt->levels != 16) {
            snprintf(err, err_size, "--levels: text has 16 levels, one per character");
            return -1;
        }
        opt->levels = 16;
    }
    if (palette && opt->levels > 255) {
        snprintf(err, err_size, "--palette: at most 255 levels (a style index is a byte)");
        return -1;
    }
    if (!given->code['l'] && !palette && (kind == STP_POSIX_FILE_P5 || kind == STP_POSIX_FILE_P6))
        opt->levels = 256;
    return 0;
}

static int palette_picture(const stp_palette *pal, const stp_tool_options *opt, int linear,
                           const uint8_t *pixels, int channels, uint32_t width, uint32_t height,
                           const char *out_path, const char *planes);

/* stipple render --palette bw|bwr|grey4|grey16|rgb8|FILE: the scene in 256
 * levels (in colour unless the palette is grey), dithered to the palette
 * (-d; default Floyd-Steinberg, rows left to right, as 1-bit stills). */
static int render_palette(const char *scene_path, const char *scene_format, const char *spec,
                          const char *planes, const char *out_path, stp_tool_options *opt,
                          const stp_scene_options *sopt, const stp_tool_given *given, int format_given)
{
    stp_palette pal;
    stp_scene scene;
    stp_posix_frame frame;
    char err[512];
    int rc;
    if (stp_palette_load(spec, &pal, err, sizeof err) != 0)
        return stp_tool_usage_error("render", "bad --palette: %s (or grey, pseudo)", err);
    if (planes && !pal.bwr)
        return stp_tool_usage_error("render", "--planes writes the planes of --palette bwr");
    if (format_given || !stp_palette_output_accepts(&pal, out_path))
        return stp_tool_usage_error("render", "%s: a palette picture is written as .png, .ppm%s "
                                              "(no --format)", out_path, pal.grey ? " or .pgm" : "");
    if (!pal.grey)
        opt->colour = 1;
    if (!given->code['l'])
        opt->levels = 256;
    if (!opt->dither_given) {
        opt->dither = STP_TOOL_DITHER_DIFFUSE;
        opt->diffuse_kernel = STP_DIFFUSE_FLOYD_STEINBERG;
        opt->diffuse_raster = 1;
    }
    if (stp_scene_load_as(scene_path, scene_format, sopt, &scene, err, sizeof err) != 0)
        return fail("%s", err);
    if (stp_posix_frame_init(&frame, (uint32_t)opt->width, (uint32_t)opt->height,
                             opt->colour ? STP_PIXEL_RGB888 : STP_PIXEL_GREY8) != 0) {
        stp_scene_free(&scene);
        return fail("out of memory for the frame");
    }
    rc = render_with_camera(&scene, opt, stp_posix_frame_port(&frame), 0, err, sizeof err);
    stp_scene_free(&scene);
    if (rc != 0) {
        stp_posix_frame_free(&frame);
        return fail("%s: %s", scene_path, err);
    }
    rc = palette_picture(&pal, opt, 0, frame.pixels, opt->colour ? 3 : 1, frame.width, frame.height,
                         out_path, planes);
    stp_posix_frame_free(&frame);
    return rc;
}

static int cmd_render(int argc, char **argv)
{
    static const struct option own[] = {
        {"output", required_argument, 0, 'o'}, {"format", required_argument, 0, OPT_FORMAT},
        {"band", required_argument, 0, 'b'},   {"stats", no_argument, 0, OPT_STATS},
        {"palette", required_argument, 0, OPT_PALETTE},
        {"device", required_argument, 0, OPT_DEVICE},
        {"scene-format", required_argument, 0, OPT_SCENE_FORMAT},
        {"planes", required_argument, 0, OPT_PLANES},
        {"outlines", required_argument, 0, OPT_OUTLINES},
        {"crease-angle", required_argument, 0, OPT_CREASE_ANGLE},
        {"outline-level", required_argument, 0, OPT_OUTLINE_LEVEL},
        {"no-rescale", no_argument, 0, OPT_NO_RESCALE},
        {"eye", required_argument, 0, STP_TOOL_OPT_EYE}, {"at", required_argument, 0, STP_TOOL_OPT_AT},
        {"up", required_argument, 0, STP_TOOL_OPT_UP},
        {"invert", no_argument, 0, OPT_INVERT},
        {"help", no_argument, 0, 'h'},         {0, 0, 0, 0}};
    struct option longs[64];
    stp_tool_options opt;
    stp_scene_options sopt;
    stp_scene scene;
    stp_posix_frame frame;
    stp_style_table lp;
    stp_tool_stats stats;
    stp_posix_file_kind kind = STP_POSIX_FILE_UNKNOWN;
    stp_tool_given given;
    const char *out_path = 0, *scene_path, *device_spec = 0, *scene_format = 0;
    const char *new_palette = 0, *planes = 0;
    char err[512];
    int c, show_stats = 0, palette = 0, png = 0, format_given = 0, crease_given = 0, level_given = 0;
    int bitmap = 0, invert = 0;

    stp_tool_options_default(&opt);
    stp_scene_options_default(&sopt);
    if (stp_tool_long_options(longs, sizeof longs / sizeof longs[0], own) != 0)
        return fail("internal: option table too small");
    memset(&given, 0, sizeof given);
    opterr = 0;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":" STP_TOOL_SHORT_OPTIONS "o:b:h", longs, 0)) != -1) {
        int applied = stp_tool_apply_option(c, optarg, &opt, &sopt, err, sizeof err);
        if (applied == 0)
            applied = stp_tool_apply_camera_option(c, optarg, 1, &opt, err, sizeof err);
        if (c > 0 && c < STP_TOOL_OPT_COMMAND)
            given.code[c] = 1;
        if (applied < 0)
            return stp_tool_usage_error("render", "%s", err);
        if (applied)
            continue;
        switch (c) {
        case 'o': out_path = optarg; break;
        case OPT_FORMAT:
            if (parse_kind(optarg, &kind, &png, &bitmap))
                return stp_tool_usage_error("render", "bad --format '%s' (pbm, plain-pbm, pgm, "
                                                      "ppm, txt, png, png1, xbm, c, c-pages)", optarg);
            format_given = 1;
            break;
        case 'b':
            if (stp_tool_parse_int(optarg, 1, 32767, &opt.band_rows))
                return stp_tool_usage_error("render", "bad --band '%s' (1..32767)", optarg);
            break;
        case OPT_STATS: show_stats = 1; break;
        case OPT_DEVICE: device_spec = optarg; break;
        case OPT_SCENE_FORMAT:
            if (!(scene_format = stp_tool_parse_scene_format(optarg)))
                return stp_tool_usage_error("render", "bad --scene-format '%s' (nff, obj, off, ply)",
                                            optarg);
            break;
        case OPT_PALETTE:
            if (!strcmp(optarg, "grey") || !strcmp(optarg, "gray"))
                palette = 1;
            else if (!strcmp(optarg, "pseudo"))
                palette = 2;
            else
                new_palette = optarg; /* bw, bwr, ... or a file: loaded below */
            break;
        case OPT_PLANES: planes = optarg; break;
        case OPT_OUTLINES:
            opt.outlines_given = 1;
            if (!strcmp(optarg, "silhouette"))
                opt.outlines = STP_OUTLINE_SILHOUETTE;
            else if (!strcmp(optarg, "crease"))
                opt.outlines = STP_OUTLINE_CREASE;
            else if (!strcmp(optarg, "both"))
                opt.outlines = STP_OUTLINE_SILHOUETTE | STP_OUTLINE_CREASE;
            else if (!strcmp(optarg, "none"))
                opt.outlines = 0;
            else
                return stp_tool_usage_error("render", "bad --outlines '%s' (silhouette, crease, "
                                                      "both, none)", optarg);
            break;
        case OPT_CREASE_ANGLE:
            if (stp_tool_parse_double(optarg, &opt.crease_angle) || !(opt.crease_angle >= 0) ||
                opt.crease_angle > 180)
                return stp_tool_usage_error("render", "bad --crease-angle '%s' (degrees, 0..180)",
                                            optarg);
            crease_given = 1;
            break;
        case OPT_OUTLINE_LEVEL:
            if (!strcmp(optarg, "auto"))
                opt.outline_level = -1;
            else if (stp_tool_parse_double(optarg, &opt.outline_level) || !(opt.outline_level >= 0) ||
                     opt.outline_level > 1)
                return stp_tool_usage_error("render", "bad --outline-level '%s' (0..1 or auto)",
                                            optarg);
            level_given = 1;
            break;
        case OPT_NO_RESCALE: opt.keep_units = 1; break;
        case OPT_INVERT: invert = 1; break;
        case 'h': usage_render(stdout); return 0;
        default: return stp_tool_getopt_error("render", c, argv);
        }
    }
    if (optind >= argc)
        return stp_tool_usage_error("render", "no scene given");
    if (optind < argc - 1)
        return stp_tool_usage_error("render", "one scene only ('%s' is extra)", argv[optind + 1]);
    scene_path = argv[optind];
    if (!strcmp(scene_path, "-") && !scene_format)
        return stp_tool_usage_error("render", "a scene from standard input ('-') needs "
                                              "--scene-format nff|obj|off|ply");
    if (stp_tool_check_renderer(&given, opt.raytrace, err, sizeof err) != 0)
        return stp_tool_usage_error("render", "%s", err);
    if (opt.outlines && opt.raytrace)
        return stp_tool_usage_error("render", "--outlines: the polygon renderer draws lines, not "
                                              "--raytrace");
    if (!opt.outlines && (crease_given || level_given))
        return stp_tool_usage_error("render", "--%s is for --outlines",
                                    crease_given ? "crease-angle" : "outline-level");
    if (opt.keep_units && opt.raytrace)
        return stp_tool_usage_error("render", "--no-rescale is for the polygon renderer (the "
                                              "ray tracer takes the scene scaled into its range)");
    if (device_spec) {
        if (out_path || palette || new_palette || format_given)
            return stp_tool_usage_error("render", "--device draws on the device: no -o, --format "
                                                  "or --palette");
        return render_to_device(scene_path, scene_format, device_spec, &opt, &sopt,
                                given.code['s'], show_stats);
    }
    if (!out_path)
        return stp_tool_usage_error("render", "no output given (-o FILE, -o - for stdout, or "
                                              "--device SPEC)");
    if (planes && !new_palette)
        return stp_tool_usage_error("render", "--planes needs --palette bwr");
    if (new_palette)
        return render_palette(scene_path, scene_format, new_palette, planes, out_path, &opt, &sopt,
                              &given, format_given);
    if (!format_given && stp_posix_png_path(out_path))
        png = 1;
    if (!format_given && stp_posix_bitmap_layout_from_path(out_path) >= 0) {
        bitmap = 1 + stp_posix_bitmap_layout_from_path(out_path);
        kind = STP_POSIX_FILE_P4;
    }
    if (png == 1)
        kind = opt.colour || palette ? STP_POSIX_FILE_P6 : STP_POSIX_FILE_P5;
    if (kind == STP_POSIX_FILE_UNKNOWN) {
        kind = stp_posix_kind_from_path(out_path);
        if (kind == STP_POSIX_FILE_UNKNOWN) {
            if (strcmp(out_path, "-") != 0)
                return stp_tool_usage_error("render", "%s: unknown output extension (use .pbm "
                                                      ".pgm .ppm .png .txt .xbm .h or --format)", out_path);
            kind = STP_POSIX_FILE_ASCII;
        }
    }
    if (palette && (kind != STP_POSIX_FILE_P6 || opt.colour))
        return stp_tool_usage_error("render", "--palette needs a .ppm or .png output (and no "
                                              "--color)");
    if (check_output_options(&given, kind, palette, &opt, err, sizeof err) != 0)
        return stp_tool_usage_error("render", "%s", err);
    if (stp_scene_load_as(scene_path, scene_format, &sopt, &scene, err, sizeof err) != 0)
        return fail("%s", err);
    if (!given.code['s'])
        note_resolution(scene_path, &scene, &opt);
    if (kind == STP_POSIX_FILE_ASCII) {
        /* the line printer has 16 characters: INTENSITY levels map onto
         * them, the background printed as blanks (--invert: the other way) */
        stp_posix_lineprinter_table(&lp);
        if (dark_background(&scene, &opt) != invert)
            lp.codes = lineprinter_light;
        opt.styles = &lp;
    }
    if (!opt.band_rows && stp_progress_wanted())
        opt.band_rows = (opt.height + 31) / 32; /* bands, so the bar moves */
    if (format_for_kind(kind) == STP_PIXEL_MONO1)
        stp_tool_still_defaults(&opt); /* a still 1-bit picture: diffusion */
    /* with a palette the frame is an indexed frame buffer: style indices */
    if (stp_posix_frame_init(&frame, (uint32_t)opt.width, (uint32_t)opt.height,
                             palette ? STP_PIXEL_STYLE8 : format_for_kind(kind)) != 0) {
        stp_scene_free(&scene);
        return fail("out of memory for the frame");
    }
    {
        /* a bar on a terminal when the frame takes more than a second */
        stp_progress progress;
        stp_port *port = stp_progress_wrap(&progress, stp_posix_frame_port(&frame),
                                           opt.raytrace ? "ray tracing" : "rendering");
        int rc = render_with_camera(&scene, &opt, port, &stats, err, sizeof err);
        stp_progress_finish(&progress);
        if (rc != 0) {
            char message[1024];
            stp_posix_frame_free(&frame);
            stp_scene_free(&scene);
            stp_tool_scene_message(message, sizeof message, scene_path, err);
            return fail("%s", message);
        }
    }
    stp_scene_free(&scene);
    if (show_stats && opt.raytrace)
        fprintf(stderr,
                "%s: %lu objects, %lu hierarchy nodes built in %.6f s, traced in %.3f s: "
                "%lu rays, %lu shadow rays, %lu box tests, %lu object tests, "
                "%zu bytes of scene and frame memory\n",
                scene_path, stats.rt_objects, stats.rt_nodes, stats.rt_build_seconds,
                stats.rt_trace_seconds, stats.rt_rays, stats.rt_shadow_rays, stats.rt_box_tests,
                stats.rt_object_tests, stats.frame_bytes);
    else if (show_stats)
        fprintf(stderr,
                "%s: %lu polygons (%lu degenerate skipped), %lu display-file entries, "
                "%zu bytes of frame memory\n",
                scene_path, stats.polygons_in, stats.polygons_skipped, stats.display_entries,
                stats.frame_bytes);
    if (palette && index_to_colour(&frame, opt.levels, palette == 2, &opt) != 0) {
        stp_posix_frame_free(&frame);
        return fail("out of memory for the frame");
    }
    if (invert && kind != STP_POSIX_FILE_ASCII)
        invert_frame(&frame);
    if ((bitmap ? stp_posix_write_bitmap(&frame, out_path, (stp_posix_bitmap_layout)(bitmap - 1), err, sizeof err)
         : png  ? stp_posix_write_png(&frame, out_path, err, sizeof err)
                : stp_posix_write(&frame, out_path, kind, err, sizeof err)) != 0) {
        stp_posix_frame_free(&frame);
        return fail("%s", err);
    }
    stp_posix_frame_free(&frame);
    return 0;
}

/* Dither pixels (channels 1 or 3 bytes each) to the palette and write the
 * picture, and with planes a bwr picture's two planes.  Returns the exit
 * status. */
static int palette_picture(const stp_palette *pal, const stp_tool_options *opt, int linear,
                           const uint8_t *pixels, int channels, uint32_t width, uint32_t height,
                           const char *out_path, const char *planes)
{
    stp_palette_method m;
    stp_cell cell;
    uint8_t *index = malloc((size_t)width * height);
    char err[512];
    int rc = 1;
    memset(&m, 0, sizeof m);
    m.diffuse = opt->dither == STP_TOOL_DITHER_DIFFUSE;
    m.kernel = opt->diffuse_kernel;
    m.serpentine = !opt->diffuse_raster;
    m.linear = linear;
    if (stp_tool_cell(opt, &cell) != 0) {
        free(index);
        return fail("bad halftone cell");
    }
    m.cell = &cell;
    if (!index || stp_palette_dither(pal, &m, pixels, channels, width, height, index) != 0)
        rc = fail("out of memory");
    else if (stp_palette_write(pal, index, width, height, out_path, err, sizeof err) != 0 ||
             (planes && stp_palette_write_planes(index, width, height, planes, err, sizeof err) != 0))
        rc = fail("%s", err);
    else
        rc = 0;
    free(index);
    return rc;
}

/* Reads a PNG, JPEG or PNM image, told apart by their first bytes: as grey
 * (channels 1) when grey is set, else keeping its colour (channels 1 or 3). */
static int read_image(const char *path, int grey, stp_posix_image *img, char *err, size_t err_size)
{
    int first = EOF;
    if (!strcmp(path, "-")) {
        first = getc(stdin);
        if (first != EOF)
            (void)ungetc(first, stdin);
    } else {
        FILE *fp = fopen(path, "rb");
        if (fp) {
            first = getc(fp);
            fclose(fp);
        }
    }
    if (first == 0xFF) {
#if STP_HAVE_JPEG
        return stp_posix_read_jpeg(path, img, grey, err, err_size);
#else
        snprintf(err, err_size, "%s: a JPEG file, and this build reads no JPEG (it needs libjpeg, "
                                "Debian package libjpeg62-turbo-dev)", path);
        return -1;
#endif
    }
    if (first == 0x89)
        return stp_posix_read_png(path, img, grey, err, err_size);
    return grey ? stp_posix_read_grey(path, img, err, err_size) : stp_posix_read_pnm(path, img, err, err_size);
}

/* What stipple dither does to the image before the halftone. */
typedef struct dither_shape {
    int rotate, flip, invert, size_given;
    uint32_t width, height;
    stp_tool_resize resize;
} dither_shape;

/* Turn, mirror, resize and invert img as shape says.  Returns 0, or the
 * exit status of the failure. */
static int shape_image(stp_posix_image *img, const dither_shape *shape)
{
    if (stp_tool_image_rotate(img, shape->rotate) != 0)
        return fail("out of memory");
    if (shape->flip)
        stp_tool_image_flip(img);
    if (shape->size_given && stp_tool_image_resize(img, shape->width, shape->height, shape->resize) != 0)
        return fail("out of memory");
    if (shape->invert)
        stp_tool_image_invert(img);
    return 0;
}

/* A dither option of its own (not -d, --spacing, -g, --gamma-k): applied
 * to shape, *format, *bitmap.  Returns 0, or the usage error's status. */
static int dither_shape_option(int c, const char *arg, dither_shape *shape, stp_tool_options *opt)
{
    switch (c) {
    case 's': {
        stp_scene_options unused;
        char err[128];
        if (stp_tool_apply_option(c, arg, opt, &unused, err, sizeof err) < 0)
            return stp_tool_usage_error("dither", "%s", err);
        shape->width = (uint32_t)opt->width;
        shape->height = (uint32_t)opt->height;
        shape->size_given = 1;
        return 0;
    }
    case OPT_RESIZE:
        if (!strcmp(arg, "fit"))
            shape->resize = STP_TOOL_RESIZE_FIT;
        else if (!strcmp(arg, "fill"))
            shape->resize = STP_TOOL_RESIZE_FILL;
        else if (!strcmp(arg, "stretch"))
            shape->resize = STP_TOOL_RESIZE_STRETCH;
        else
            return stp_tool_usage_error("dither", "bad --resize '%s' (fit, fill, stretch)", arg);
        return 0;
    case OPT_ROTATE:
        if (stp_tool_parse_int(arg, 0, 270, &shape->rotate) || shape->rotate % 90)
            return stp_tool_usage_error("dither", "bad --rotate '%s' (0, 90, 180, 270: degrees clockwise)",
                                        arg);
        return 0;
    case OPT_FLIP: shape->flip = 1; return 0;
    case OPT_INVERT: shape->invert = 1; return 0;
    default: return -1;
    }
}

/* The grey table of --gamma/--gamma-k or --linear into table; returns 1
 * when there is one, 0 when none, -1 for a bad gamma. */
static int dither_grey_table(const stp_tool_options *opt, int use_gamma, int linear, uint8_t table[256])
{
    int v;
    if (use_gamma)
        return stp_gamma_table(table, 256, stp_tool_fix(opt->gamma), stp_tool_fix(opt->gamma_k)) ? -1 : 1;
    if (!linear)
        return 0;
    /* sRGB to linear light (IEC 61966-2-1): a panel's share of lit
     * pixels is linear light */
    for (v = 0; v < 256; v++) {
        double e = v / 255.0, l = e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
        table[v] = (uint8_t)lround(255.0 * l);
    }
    return 1;
}

/* Halftone the grey image img into the MONO1 frame (its size). */
static int halftone_image(stp_posix_image *img, const stp_tool_options *opt, const uint8_t *table,
                          stp_posix_frame *frame)
{
    stp_cell cell;
    stp_diffusion diffusion;
    uint32_t x, y;
    if (stp_tool_cell(opt, &cell) != 0)
        return fail("bad halftone cell");
    if (stp_posix_frame_init(frame, img->width, img->height, STP_PIXEL_MONO1) != 0)
        return fail("out of memory");
    if (stp_tool_diffusion(opt, img->width, &diffusion) < 0) {
        stp_posix_frame_free(frame);
        return fail("out of memory");
    }
    for (y = 0; y < img->height; y++) {
        uint8_t *grey = img->samples + (size_t)y * img->width;
        if (table)
            for (x = 0; x < img->width; x++)
                grey[x] = table[grey[x]];
        if (diffusion.errors) {
            stp_diffuse_row(&diffusion, grey, img->width, y); /* packs in place */
            memcpy(frame->pixels + (size_t)y * frame->stride, grey, frame->stride);
        } else {
            stp_halftone_row(frame->pixels + (size_t)y * frame->stride, grey, img->width, y, &cell);
        }
    }
    free(diffusion.errors);
    return 0;
}

/* The 1-bit output of dither: --format, else from the name.  *png 1 for
 * PNG, *bitmap layout + 1 for XBM/C, *plain for plain PBM.  Returns 0, or
 * the usage error's status. */
static int dither_output_kind(const char *out_path, const char *format, int *png, int *bitmap, int *plain)
{
    stp_posix_file_kind kind = STP_POSIX_FILE_P4;
    if (format) {
        if (parse_kind(format, &kind, png, bitmap) != 0 ||
            (kind != STP_POSIX_FILE_P4 && kind != STP_POSIX_FILE_P1) || *png == 1)
            return stp_tool_usage_error("dither", "bad --format '%s' (pbm, plain-pbm, png1, xbm, c, "
                                                  "c-pages)", format);
        *png = *png == 2;
        if (kind == STP_POSIX_FILE_P1)
            *plain = 1;
        return 0;
    }
    *png = stp_posix_png_path(out_path);
    if (stp_posix_bitmap_layout_from_path(out_path) >= 0)
        *bitmap = 1 + stp_posix_bitmap_layout_from_path(out_path);
    else if (strcmp(out_path, "-") != 0 && !*png && stp_posix_kind_from_path(out_path) != STP_POSIX_FILE_P4)
        return stp_tool_usage_error("dither", "%s: dither writes PBM, 1-bit PNG, XBM or a C array; give "
                                              "a .pbm, .png, .xbm or .h name (or --format)", out_path);
    return 0;
}

static int write_mono(const stp_posix_frame *frame, const char *out_path, int png, int bitmap, int plain)
{
    char err[512];
    int rc = bitmap ? stp_posix_write_bitmap(frame, out_path, (stp_posix_bitmap_layout)(bitmap - 1), err,
                                             sizeof err)
             : png  ? stp_posix_write_png(frame, out_path, err, sizeof err)
                    : stp_posix_write(frame, out_path, plain ? STP_POSIX_FILE_P1 : STP_POSIX_FILE_P4, err,
                                      sizeof err);
    return rc != 0 ? fail("%s", err) : 0;
}

/* stipple dither --palette: colour kept, dithered to the palette. */
static int dither_palette(const char *in_path, const char *out_path, const char *spec, const char *planes,
                          const stp_tool_options *opt, int linear, const dither_shape *shape)
{
    stp_palette pal;
    stp_posix_image colour;
    char err[512];
    int rc;
    if (stp_palette_load(spec, &pal, err, sizeof err) != 0)
        return stp_tool_usage_error("dither", "--palette: %s", err);
    if (planes && !pal.bwr)
        return stp_tool_usage_error("dither", "--planes writes the planes of --palette bwr");
    if (!stp_palette_output_accepts(&pal, out_path))
        return stp_tool_usage_error("dither", "%s: a palette picture is written as .png, .ppm%s", out_path,
                                    pal.grey ? " or .pgm" : "");
    if (read_image(in_path, 0, &colour, err, sizeof err) != 0)
        return fail("%s", err);
    if ((rc = shape_image(&colour, shape)) == 0)
        rc = palette_picture(&pal, opt, linear, colour.samples, colour.channels, colour.width, colour.height,
                             out_path, planes);
    stp_posix_image_free(&colour);
    return rc;
}

static int cmd_dither(int argc, char **argv)
{
    static const struct option longs[] = {
        {"output", required_argument, 0, 'o'}, {"plain", no_argument, 0, OPT_PLAIN},
        {"dither", required_argument, 0, 'd'}, {"spacing", required_argument, 0, STP_TOOL_OPT_SPACING},
        {"gamma", required_argument, 0, 'g'}, {"gamma-k", required_argument, 0, STP_TOOL_OPT_GAMMA_K},
        {"linear", no_argument, 0, OPT_LINEAR}, {"palette", required_argument, 0, OPT_PALETTE},
        {"planes", required_argument, 0, OPT_PLANES}, {"size", required_argument, 0, 's'},
        {"resize", required_argument, 0, OPT_RESIZE}, {"rotate", required_argument, 0, OPT_ROTATE},
        {"flip", no_argument, 0, OPT_FLIP}, {"invert", no_argument, 0, OPT_INVERT},
        {"format", required_argument, 0, OPT_FORMAT}, {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    stp_tool_options opt;
    dither_shape shape;
    const char *palette_spec = 0, *planes = 0, *out_path = 0, *format = 0;
    stp_posix_image img;
    stp_posix_frame frame;
    uint8_t table[256];
    char err[512];
    int c, plain = 0, use_gamma = 0, png = 0, bitmap = 0, linear = 0, has_table, rc;

    stp_tool_options_default(&opt);
    memset(&shape, 0, sizeof shape);
    opterr = 0;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":o:d:g:s:h", longs, 0)) != -1) {
        switch (c) {
        case 'o': out_path = optarg; break;
        case OPT_PLAIN: plain = 1; break;
        case OPT_LINEAR: linear = 1; break;
        case OPT_PALETTE: palette_spec = optarg; break;
        case OPT_PLANES: planes = optarg; break;
        case OPT_FORMAT: format = optarg; break;
        case 'd':
        case STP_TOOL_OPT_SPACING:
        case 'g':
        case STP_TOOL_OPT_GAMMA_K: {
            stp_scene_options unused;
            if (stp_tool_apply_option(c, optarg, &opt, &unused, err, sizeof err) < 0)
                return stp_tool_usage_error("dither", "%s", err);
            use_gamma |= c == 'g' || c == STP_TOOL_OPT_GAMMA_K;
            break;
        }
        case 'h': usage_dither(stdout); return 0;
        default:
            rc = dither_shape_option(c, optarg, &shape, &opt);
            if (rc < 0)
                return stp_tool_getopt_error("dither", c, argv);
            if (rc > 0)
                return rc;
        }
    }
    if (optind >= argc)
        return stp_tool_usage_error("dither", "no image given");
    if (optind < argc - 1)
        return stp_tool_usage_error("dither", "one image only ('%s' is extra)", argv[optind + 1]);
    if (!out_path)
        return stp_tool_usage_error("dither", "no output given (-o FILE.pbm)");
    if (planes && !palette_spec)
        return stp_tool_usage_error("dither", "--planes needs --palette bwr");
    if (palette_spec) {
        if (plain || use_gamma || format)
            return stp_tool_usage_error("dither", "--palette takes no --%s",
                                        plain ? "plain" : use_gamma ? "gamma" : "format");
        return dither_palette(argv[optind], out_path, palette_spec, planes, &opt, linear, &shape);
    }
    if ((rc = dither_output_kind(out_path, format, &png, &bitmap, &plain)) != 0)
        return rc;
    if ((png || bitmap) && plain)
        return stp_tool_usage_error("dither", "--plain is for PBM");
    if (use_gamma && linear)
        return fail("dither: --linear and --gamma both map the grey: give one");
    if ((has_table = dither_grey_table(&opt, use_gamma, linear, table)) < 0)
        return fail("bad gamma");
    if (read_image(argv[optind], 1, &img, err, sizeof err) != 0)
        return fail("%s", err);
    if ((rc = shape_image(&img, &shape)) == 0 && (rc = halftone_image(&img, &opt, has_table ? table : 0, &frame)) == 0) {
        rc = write_mono(&frame, out_path, png, bitmap, plain);
        stp_posix_frame_free(&frame);
    }
    stp_posix_image_free(&img);
    return rc;
}

static void usage_bench(FILE *to)
{
    fprintf(to,
            "usage: stipple bench [options] [SCENE...]\n"
            "\n"
            "Ray-traces each SCENE (a name in the scenes folder, default balls-s2 and\n"
            "teapot-s2) with and without the bounding-volume hierarchy and prints its\n"
            "build time, us per frame, rays, rays per second and the largest and mean\n"
            "shade error against the double-precision reference ray tracer.\n"
            "(The polygon renderer's error-against-run-time table is the build target\n"
            "'bench': cmake --build build --target bench.)\n"
            "\n"
            "      --scenes DIR         folder of the .nff files (default: $STP_SCENES_DIR,\n"
            "                           else the one this build was configured with)\n"
            "  -s, --size WxH           frame size (default 256x256)\n"
            "      --depth N            deepest reflection/refraction (default 4)\n"
            "      --min-weight W       lightest ray cast (default 1/64)\n"
            "      --budget SECONDS     time per measurement (default 1)\n"
            "  -h, --help               this help\n");
}

static int cmd_bench(int argc, char **argv)
{
    static const char *const default_names[] = {"balls-s2", "teapot-s2"};
    static const struct option longs[] = {
        {"scenes", required_argument, 0, OPT_BENCH_SCENES},
        {"size", required_argument, 0, 's'},
        {"depth", required_argument, 0, STP_TOOL_OPT_DEPTH},
        {"min-weight", required_argument, 0, STP_TOOL_OPT_MIN_WEIGHT},
        {"budget", required_argument, 0, OPT_BENCH_BUDGET},
        {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    stp_tool_options opt;
    stp_scene_options sopt;
    const char *dir = getenv("STP_SCENES_DIR");
    double budget = 1.0;
    char err[512];
    int c;
    stp_tool_options_default(&opt);
    stp_scene_options_default(&sopt);
    opt.width = opt.height = 256;
    opt.raytrace = 1;
    if (!dir || !*dir)
        dir = STP_DEFAULT_SCENES_DIR;
    opterr = 0;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":s:h", longs, 0)) != -1) {
        switch (c) {
        case OPT_BENCH_SCENES: dir = optarg; break;
        case OPT_BENCH_BUDGET:
            if (stp_tool_parse_double(optarg, &budget) || !(budget > 0) || budget > 3600)
                return stp_tool_usage_error("bench", "bad --budget '%s' (seconds, 0..3600)",
                                            optarg);
            break;
        case 's':
        case STP_TOOL_OPT_DEPTH:
        case STP_TOOL_OPT_MIN_WEIGHT:
            if (stp_tool_apply_option(c, optarg, &opt, &sopt, err, sizeof err) < 0)
                return stp_tool_usage_error("bench", "%s", err);
            break;
        case 'h': usage_bench(stdout); return 0;
        default: return stp_tool_getopt_error("bench", c, argv);
        }
    }
    if (optind < argc)
        return stp_rt_bench(stdout, dir, (const char *const *)(argv + optind), argc - optind, &opt,
                            budget) == 0
                   ? 0
                   : 1;
    return stp_rt_bench(stdout, dir, default_names, 2, &opt, budget) == 0 ? 0 : 1;
}

static int dispatch(int argc, char **argv);

/* Every command, then standard output flushed: a help text, version or
 * scene that could not be written (a closed or full stdout) is an error. */
int main(int argc, char **argv)
{
    int rc = dispatch(argc, argv);
    /* a command that failed has said why */
    if (rc == 0 && (fflush(stdout) != 0 || ferror(stdout))) {
        fprintf(stderr, "stipple: writing to standard output: %s\n", strerror(errno));
        return 1;
    }
    return rc;
}

/* stipple help [COMMAND] */
static int cmd_help(int argc, char **argv)
{
    if (argc < 3) {
        usage_main(stdout);
        return 0;
    }
    if (argc > 3)
        return stp_tool_usage_error("help", "one command at a time");
    if (!strcmp(argv[2], "render"))
        usage_render(stdout);
    else if (!strcmp(argv[2], "dither"))
        usage_dither(stdout);
    else if (!strcmp(argv[2], "animate"))
        stp_tool_animate_usage(stdout);
    else if (!strcmp(argv[2], "bench"))
        usage_bench(stdout);
    else if (!strcmp(argv[2], "compile"))
        stp_tool_compile_usage(stdout);
    else if (!strcmp(argv[2], "scene")) {
        char *scene_help[] = {argv[2], "--help", NULL};
        return stp_scenegen_main(2, scene_help);
    } else if (!strcmp(argv[2], "help") || !strcmp(argv[2], "--help") || !strcmp(argv[2], "-h"))
        usage_help(stdout);
    else
        return stp_tool_usage_error(0, "no command '%s' (render, animate, dither, scene, compile, bench, help)",
                                    argv[2]);
    return 0;
}

static int dispatch(int argc, char **argv)
{
    if (argc < 2)
        return stp_tool_usage_error(0, "no command given (render, animate, dither, scene, compile, bench, help)");
    if (!strcmp(argv[1], "--version") || !strcmp(argv[1], "version")) {
        printf("stipple %s\n", stp_version());
        return 0;
    }
    if (!strcmp(argv[1], "render"))
        return cmd_render(argc - 1, argv + 1);
    if (!strcmp(argv[1], "dither"))
        return cmd_dither(argc - 1, argv + 1);
    if (!strcmp(argv[1], "animate"))
        return stp_tool_animate_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "bench"))
        return cmd_bench(argc - 1, argv + 1);
    if (!strcmp(argv[1], "scene"))
        return stp_scenegen_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "compile"))
        return stp_tool_compile_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))
        return cmd_help(argc, argv);
    return stp_tool_usage_error(0, "unknown command '%s'", argv[1]);
}
