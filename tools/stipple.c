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

#include "compile_scene.h"
#include "options.h"
#include "progress.h"
#include "rt_compare.h"
#if STP_HAVE_DEVICE
#include "stp_device.h"
#endif
#include "render_scene.h"
#include "scene.h"
#include "stp_posix.h"

static const char *program = "stipple";

static void usage_main(FILE *to)
{
    fprintf(to,
            "usage: stipple COMMAND [options]\n"
            "\n"
            "commands:\n"
            "  render SCENE -o OUT   render an NFF, OBJ or OFF scene to PBM, PGM, PPM or text\n"
            "  dither IMAGE -o OUT   halftone a PGM/PPM image to PBM\n"
            "  compile SCENE -o OUT.c  write a scene as C source and a minimal configuration\n"
            "                        header for firmware (see 'stipple compile --help')\n"
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
            "Renders SCENE (.nff, .obj, .off) with the fixed-point core.  OUT's extension picks\n"
            "the output: .pbm (halftoned 1-bit), .pgm (grey), .ppm (colour file of the grey\n"
            "picture, or of the colour one with --color), .txt (line-printer text, one\n"
            "character per pixel); '-' writes to stdout in the --format given (default txt).\n"
            "\n"
            "  -o, --output FILE        where to write\n"
            "      --device SPEC        draw on a Linux device instead, at its size and format:\n"
            "                           fb:/dev/fbN, usb:VID:PID or usb (receipt printer),\n"
            "                           spi:/dev/spidevB.C,controller=ssd1306|sharp-ls013b7dh03|\n"
            "                           ssd1680|ssd1680-128x296,dc=LINE,reset=LINE,busy=LINE,...\n"
            "                           (see ports/linux-fb/stp_device.h)\n"
            "      --format KIND        pbm, plain-pbm, pgm, ppm or txt (default: from OUT)\n"
            "  -b, --band ROWS          render in bands of ROWS rows (default: whole frame)\n"
            "      --stats              print display-file and memory figures on stderr\n"
            "      --palette grey|pseudo  .ppm through a 256-entry colour table: the frame is\n"
            "                           an indexed frame buffer of styles; pseudo maps dark to\n"
            "                           blue and light to red; --gamma applies per primary\n"
            "  -h, --help               this help\n");
    stp_tool_options_help(to);
}

static void usage_dither(FILE *to)
{
    fprintf(to,
            "usage: stipple dither IMAGE -o OUT.pbm [options]\n"
            "\n"
            "Halftones a PGM or PPM image (PPM through luminance) with an ordered-dither cell\n"
            "or error diffusion (-d fs, atkinson, ...).\n"
            "With bayer2/4/8 the pixels equal ImageMagick's -ordered-dither o2x2/o4x4/o8x8.\n"
            "\n"
            "  -o, --output FILE     where to write (.pbm; '-' for stdout)\n"
            "      --plain           write plain PBM (P1) instead of raw (P4)\n"
            "  -d, --dither CELL     as for render (default bayer4)\n"
            "      --spacing KIND    linear (default), exponential, cubic\n"
            "  -g, --gamma G         apply V = (I/k)^(1/G) to the grey first (default 1)\n"
            "      --linear          turn sRGB grey into linear light first (a panel's\n"
            "                        density of lit pixels is linear light)\n"
            "      --gamma-k K       (default 1)\n"
            "  -h, --help            this help\n");
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

static int parse_kind(const char *s, stp_posix_file_kind *kind)
{
    if (!strcmp(s, "pbm"))
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
    OPT_LINEAR
};

/* Turn an indexed frame buffer (STYLE8: style index 1..levels per pixel)
 * into RGB through a 256-entry colour table, grey or pseudocolour, with the
 * gamma table applied to each primary (SPEC.md section 6). */
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
static int render_to_device(const char *scene_path, const char *spec, stp_tool_options *opt,
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
    if (stp_scene_load(scene_path, sopt, &scene, err, sizeof err) != 0)
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
    rc = stp_tool_render(&scene, opt,
                         stp_progress_wrap(&progress, port, opt->raytrace ? "ray tracing" : "rendering"),
                         &stats, err, sizeof err);
    stp_progress_finish(&progress);
    stp_scene_free(&scene);
    if (rc != 0) {
        const char *why = stp_device_error(dev);
        fprintf(stderr, "%s: %s: %s%s%s\n", program, scene_path, err, *why ? ": " : "", why);
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
    (void)spec;
    (void)opt;
    (void)sopt;
    (void)size_given;
    (void)show_stats;
    return fail("render: this build has no Linux device ports (--device)");
#endif
}

static int cmd_render(int argc, char **argv)
{
    static const struct option own[] = {
        {"output", required_argument, 0, 'o'}, {"format", required_argument, 0, OPT_FORMAT},
        {"band", required_argument, 0, 'b'},   {"stats", no_argument, 0, OPT_STATS},
        {"palette", required_argument, 0, OPT_PALETTE},
        {"device", required_argument, 0, OPT_DEVICE},
        {"help", no_argument, 0, 'h'},         {0, 0, 0, 0}};
    struct option longs[64];
    stp_tool_options opt;
    stp_scene_options sopt;
    stp_scene scene;
    stp_posix_frame frame;
    stp_style_table lp;
    stp_tool_stats stats;
    stp_posix_file_kind kind = STP_POSIX_FILE_UNKNOWN;
    const char *out_path = 0, *scene_path, *device_spec = 0;
    char err[512];
    int c, show_stats = 0, palette = 0, size_given = 0;

    stp_tool_options_default(&opt);
    stp_scene_options_default(&sopt);
    if (stp_tool_long_options(longs, sizeof longs / sizeof longs[0], own) != 0)
        return fail("internal: option table too small");
    optind = 1;
    while ((c = getopt_long(argc, argv, STP_TOOL_SHORT_OPTIONS "o:b:h", longs, 0)) != -1) {
        int applied = stp_tool_apply_option(c, optarg, &opt, &sopt, err, sizeof err);
        if (c == 's')
            size_given = 1;
        if (applied < 0)
            return fail("%s", err);
        if (applied)
            continue;
        switch (c) {
        case 'o': out_path = optarg; break;
        case OPT_FORMAT:
            if (parse_kind(optarg, &kind))
                return fail("bad --format '%s' (pbm, plain-pbm, pgm, ppm, txt)", optarg);
            break;
        case 'b':
            if (stp_tool_parse_int(optarg, 1, 32767, &opt.band_rows))
                return fail("bad --band '%s' (1..32767)", optarg);
            break;
        case OPT_STATS: show_stats = 1; break;
        case OPT_DEVICE: device_spec = optarg; break;
        case OPT_PALETTE:
            if (!strcmp(optarg, "grey") || !strcmp(optarg, "gray"))
                palette = 1;
            else if (!strcmp(optarg, "pseudo"))
                palette = 2;
            else
                return fail("bad --palette '%s' (grey, pseudo)", optarg);
            break;
        case 'h': usage_render(stdout); return 0;
        default: usage_render(stderr); return 2;
        }
    }
    if (optind != argc - 1) {
        usage_render(stderr);
        return 2;
    }
    scene_path = argv[optind];
    if (device_spec) {
        if (out_path || palette || kind != STP_POSIX_FILE_UNKNOWN)
            return fail("render: --device draws on the device: no -o, --format or --palette");
        return render_to_device(scene_path, device_spec, &opt, &sopt, size_given, show_stats);
    }
    if (!out_path)
        return fail("render: no output given (-o FILE, -o - for stdout, or --device SPEC)");
    if (kind == STP_POSIX_FILE_UNKNOWN) {
        kind = stp_posix_kind_from_path(out_path);
        if (kind == STP_POSIX_FILE_UNKNOWN) {
            if (strcmp(out_path, "-") != 0)
                return fail("%s: unknown output extension (use .pbm .pgm .ppm .txt or --format)",
                            out_path);
            kind = STP_POSIX_FILE_ASCII;
        }
    }
    if (stp_scene_load(scene_path, &sopt, &scene, err, sizeof err) != 0)
        return fail("%s", err);
    if (kind == STP_POSIX_FILE_ASCII) {
        /* the line printer has 16 characters: INTENSITY levels map onto them */
        stp_posix_lineprinter_table(&lp);
        if (opt.levels != lp.levels)
            opt.levels = lp.levels;
        opt.styles = &lp;
    }
    if (format_for_kind(kind) == STP_PIXEL_MONO1)
        stp_tool_still_defaults(&opt); /* a still 1-bit picture: diffusion */
    if (palette && (kind != STP_POSIX_FILE_P6 || opt.colour))
        return fail("--palette needs a .ppm output (and no --color)");
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
        int rc = stp_tool_render(&scene, &opt, port, &stats, err, sizeof err);
        stp_progress_finish(&progress);
        if (rc != 0) {
            stp_posix_frame_free(&frame);
            stp_scene_free(&scene);
            return fail("%s: %s", scene_path, err);
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
    if (stp_posix_write(&frame, out_path, kind, err, sizeof err) != 0) {
        stp_posix_frame_free(&frame);
        return fail("%s", err);
    }
    stp_posix_frame_free(&frame);
    return 0;
}

static int cmd_dither(int argc, char **argv)
{
    static const struct option longs[] = {
        {"output", required_argument, 0, 'o'}, {"plain", no_argument, 0, OPT_PLAIN},
        {"dither", required_argument, 0, 'd'}, {"spacing", required_argument, 0, STP_TOOL_OPT_SPACING},
        {"gamma", required_argument, 0, 'g'}, {"gamma-k", required_argument, 0, STP_TOOL_OPT_GAMMA_K},
        {"linear", no_argument, 0, OPT_LINEAR}, {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    stp_tool_options opt;
    stp_posix_image img;
    stp_posix_frame frame;
    stp_cell cell;
    stp_diffusion diffusion;
    uint8_t table[256];
    const char *out_path = 0;
    char err[512];
    int c, plain = 0, use_gamma = 0, linear = 0;
    uint32_t y, x;

    stp_tool_options_default(&opt);
    optind = 1;
    while ((c = getopt_long(argc, argv, "o:d:g:h", longs, 0)) != -1) {
        switch (c) {
        case 'o': out_path = optarg; break;
        case OPT_PLAIN: plain = 1; break;
        case OPT_LINEAR: linear = 1; break;
        case 'd':
        case STP_TOOL_OPT_SPACING:
        case 'g':
        case STP_TOOL_OPT_GAMMA_K: {
            stp_scene_options unused;
            if (stp_tool_apply_option(c, optarg, &opt, &unused, err, sizeof err) < 0)
                return fail("%s", err);
            use_gamma |= c == 'g' || c == STP_TOOL_OPT_GAMMA_K;
            break;
        }
        case 'h': usage_dither(stdout); return 0;
        default: usage_dither(stderr); return 2;
        }
    }
    if (optind != argc - 1) {
        usage_dither(stderr);
        return 2;
    }
    if (!out_path)
        return fail("dither: no output given (-o FILE.pbm)");
    if (strcmp(out_path, "-") != 0 && stp_posix_kind_from_path(out_path) != STP_POSIX_FILE_P4)
        return fail("%s: dither writes PBM; give a .pbm name", out_path);
    if (stp_tool_cell(&opt, &cell) != 0)
        return fail("bad halftone cell");
    if (use_gamma && linear)
        return fail("dither: --linear and --gamma both map the grey: give one");
    if (use_gamma && stp_gamma_table(table, 256, stp_tool_fix(opt.gamma), stp_tool_fix(opt.gamma_k)))
        return fail("bad gamma");
    if (linear) {
        /* sRGB to linear light (IEC 61966-2-1): a panel's share of lit
         * pixels is linear light */
        int v;
        for (v = 0; v < 256; v++) {
            double e = v / 255.0, l = e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
            table[v] = (uint8_t)lround(255.0 * l);
        }
        use_gamma = 1;
    }
    if (stp_posix_read_grey(argv[optind], &img, err, sizeof err) != 0)
        return fail("%s", err);
    if (stp_posix_frame_init(&frame, img.width, img.height, STP_PIXEL_MONO1) != 0) {
        stp_posix_image_free(&img);
        return fail("out of memory");
    }
    if (stp_tool_diffusion(&opt, img.width, &diffusion) < 0) {
        stp_posix_image_free(&img);
        stp_posix_frame_free(&frame);
        return fail("out of memory");
    }
    for (y = 0; y < img.height; y++) {
        uint8_t *grey = img.samples + (size_t)y * img.width;
        if (use_gamma)
            for (x = 0; x < img.width; x++)
                grey[x] = table[grey[x]];
        if (diffusion.errors) {
            stp_diffuse_row(&diffusion, grey, img.width, y); /* packs in place */
            memcpy(frame.pixels + (size_t)y * frame.stride, grey, frame.stride);
        } else {
            stp_halftone_row(frame.pixels + (size_t)y * frame.stride, grey, img.width, y, &cell);
        }
    }
    free(diffusion.errors);
    stp_posix_image_free(&img);
    if (stp_posix_write(&frame, out_path, plain ? STP_POSIX_FILE_P1 : STP_POSIX_FILE_P4, err,
                        sizeof err) != 0) {
        stp_posix_frame_free(&frame);
        return fail("%s", err);
    }
    stp_posix_frame_free(&frame);
    return 0;
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
    optind = 1;
    while ((c = getopt_long(argc, argv, "s:h", longs, 0)) != -1) {
        switch (c) {
        case OPT_BENCH_SCENES: dir = optarg; break;
        case OPT_BENCH_BUDGET:
            if (stp_tool_parse_double(optarg, &budget) || !(budget > 0) || budget > 3600)
                return fail("bad --budget '%s' (seconds, > 0)", optarg);
            break;
        case 's':
        case STP_TOOL_OPT_DEPTH:
        case STP_TOOL_OPT_MIN_WEIGHT:
            if (stp_tool_apply_option(c, optarg, &opt, &sopt, err, sizeof err) < 0)
                return fail("%s", err);
            break;
        case 'h': usage_bench(stdout); return 0;
        default: usage_bench(stderr); return 2;
        }
    }
    if (optind < argc)
        return stp_rt_bench(stdout, dir, (const char *const *)(argv + optind), argc - optind, &opt,
                            budget) == 0
                   ? 0
                   : 1;
    return stp_rt_bench(stdout, dir, default_names, 2, &opt, budget) == 0 ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage_main(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--version") || !strcmp(argv[1], "version")) {
        printf("stipple %s\n", stp_version());
        return 0;
    }
    if (!strcmp(argv[1], "render"))
        return cmd_render(argc - 1, argv + 1);
    if (!strcmp(argv[1], "dither"))
        return cmd_dither(argc - 1, argv + 1);
    if (!strcmp(argv[1], "bench"))
        return cmd_bench(argc - 1, argv + 1);
    if (!strcmp(argv[1], "compile"))
        return stp_tool_compile_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        if (argc > 2 && !strcmp(argv[2], "render"))
            usage_render(stdout);
        else if (argc > 2 && !strcmp(argv[2], "dither"))
            usage_dither(stdout);
        else if (argc > 2 && !strcmp(argv[2], "bench"))
            usage_bench(stdout);
        else
            usage_main(stdout);
        return 0;
    }
    fprintf(stderr, "%s: unknown command '%s'\n", program, argv[1]);
    usage_main(stderr);
    return 2;
}
