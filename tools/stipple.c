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
            "  help [COMMAND]        show help\n"
            "\n"
            "Run 'stipple COMMAND --help' for a command's options.\n");
}

static void usage_render(FILE *to)
{
    fprintf(to,
            "usage: stipple render SCENE -o OUT [options]\n"
            "\n"
            "Renders SCENE (.nff, .obj, .off) with the fixed-point core.  OUT's extension picks\n"
            "the output: .pbm (halftoned 1-bit), .pgm (grey), .ppm (colour file of the grey\n"
            "picture), .txt (line-printer text, one character per pixel); '-' writes to stdout\n"
            "in the --format given (default txt).\n"
            "\n"
            "  -o, --output FILE        where to write (required)\n"
            "  -s, --size WxH           device size in pixels (default 128x64)\n"
            "      --format KIND        pbm, plain-pbm, pgm, ppm or txt (default: from OUT)\n"
            "  -l, --levels N           INTENSITY levels, 2..256 (default 16)\n"
            "  -d, --dither CELL        bayer2, bayer4 (default), bayer8, seed2x2, pattern2x2,\n"
            "                           or user:W:H:t,t,... (thresholds 0..255, row-major)\n"
            "      --spacing KIND       threshold spacing of Bayer cells: linear (default),\n"
            "                           exponential, cubic\n"
            "  -g, --gamma G            gamma of the device table V = (I/k)^(1/G) (default 1)\n"
            "      --gamma-k K          k of the gamma table (default 1)\n"
            "      --hidden METHOD      zbuffer (default), painter or none\n"
            "      --backface           remove back faces (for closed meshes)\n"
            "      --no-shading         fill each polygon with its material's reflectivity\n"
            "      --color              colour shading (10.45) with the scene's colours; with a\n"
            "                           .ppm output the picture is in colour (default: grey)\n"
            "      --transparent        NFF's T makes surfaces transparent: v = v_r + t v_t,\n"
            "                           t from T/2 (grazing) to T (facing); best with\n"
            "                           --hidden painter (back to front)\n"
            "      --smooth             Gouraud shading from vertex normals (NFF pp, OBJ vn;\n"
            "                           averaged face normals where the file has none)\n"
            "  -b, --band ROWS          render in bands of ROWS rows (default: whole frame)\n"
            "      --light X,Y,Z        a light (repeatable, up to %d); replaces the scene's\n"
            "      --bright B           overall brightness BRIGHT (default 1)\n"
            "      --ambient B          background (indirect) light share (default 0.2)\n"
            "      --attenuation C      C of the distance term 1/(C+U) (default 1)\n"
            "      --raw-power          use power 1-B for every light (the seed's SET-LIGHT)\n"
            "                           instead of cancelling attenuation at the scene centre\n"
            "      --parallel           parallel instead of perspective projection\n"
            "      --fov DEGREES        field of view over the shorter side (default: the\n"
            "                           scene's, else 45)\n"
            "      --slices N           sphere/cone slices for tessellation (default 16)\n"
            "      --stacks N           sphere stacks (default 8)\n"
            "      --stats              print display-file and memory figures on stderr\n"
            "  -h, --help               this help\n",
            STP_MAX_LIGHTS);
}

static void usage_dither(FILE *to)
{
    fprintf(to,
            "usage: stipple dither IMAGE -o OUT.pbm [options]\n"
            "\n"
            "Halftones a PGM or PPM image (PPM through luminance) with an ordered-dither cell.\n"
            "With bayer2/4/8 the pixels equal ImageMagick's -ordered-dither o2x2/o4x4/o8x8.\n"
            "\n"
            "  -o, --output FILE     where to write (.pbm; '-' for stdout)\n"
            "      --plain           write plain PBM (P1) instead of raw (P4)\n"
            "  -d, --dither CELL     as for render (default bayer4)\n"
            "      --spacing KIND    linear (default), exponential, cubic\n"
            "  -g, --gamma G         apply V = (I/k)^(1/G) to the grey first (default 1)\n"
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

static int parse_int(const char *s, int lo, int hi, int *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi)
        return -1;
    *out = (int)v;
    return 0;
}

static int parse_double(const char *s, double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (errno || end == s || *end || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

static int parse_dither(const char *s, stp_tool_options *opt)
{
    if (!strcmp(s, "bayer2"))
        opt->dither = STP_TOOL_DITHER_BAYER2;
    else if (!strcmp(s, "bayer4"))
        opt->dither = STP_TOOL_DITHER_BAYER4;
    else if (!strcmp(s, "bayer8"))
        opt->dither = STP_TOOL_DITHER_BAYER8;
    else if (!strcmp(s, "seed2x2"))
        opt->dither = STP_TOOL_DITHER_SEED2X2;
    else if (!strcmp(s, "pattern2x2"))
        opt->dither = STP_TOOL_DITHER_PATTERN2X2;
    else if (!strncmp(s, "user:", 5)) {
        int w, h, i, n;
        char *copy = strdup(s + 5), *tok, *save = 0;
        if (!copy)
            return -1;
        tok = strtok_r(copy, ":", &save);
        if (!tok || parse_int(tok, 1, STP_CELL_MAX, &w)) {
            free(copy);
            return -1;
        }
        tok = strtok_r(0, ":", &save);
        if (!tok || parse_int(tok, 1, STP_CELL_MAX, &h)) {
            free(copy);
            return -1;
        }
        n = 0;
        for (tok = strtok_r(0, ",", &save); tok; tok = strtok_r(0, ",", &save)) {
            if (n >= w * h || parse_int(tok, 0, 255, &i)) {
                free(copy);
                return -1;
            }
            opt->user_cell[n++] = (unsigned char)i;
        }
        free(copy);
        if (n != w * h)
            return -1;
        opt->user_cell_w = w;
        opt->user_cell_h = h;
        opt->dither = STP_TOOL_DITHER_USER;
    } else
        return -1;
    return 0;
}

static int parse_spacing(const char *s, stp_spacing *out)
{
    if (!strcmp(s, "linear"))
        *out = STP_SPACING_LINEAR;
    else if (!strcmp(s, "exponential"))
        *out = STP_SPACING_EXPONENTIAL;
    else if (!strcmp(s, "cubic"))
        *out = STP_SPACING_CUBIC;
    else
        return -1;
    return 0;
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
    OPT_FORMAT = 256, OPT_SPACING, OPT_GAMMA_K, OPT_HIDDEN, OPT_BACKFACE, OPT_NO_SHADING,
    OPT_LIGHT, OPT_BRIGHT, OPT_AMBIENT, OPT_ATTEN, OPT_RAW_POWER, OPT_PARALLEL, OPT_FOV,
    OPT_SLICES, OPT_STACKS, OPT_STATS, OPT_PLAIN, OPT_SMOOTH, OPT_COLOUR, OPT_TRANSPARENT
};

static int cmd_render(int argc, char **argv)
{
    static const struct option longs[] = {
        {"output", required_argument, 0, 'o'}, {"size", required_argument, 0, 's'},
        {"format", required_argument, 0, OPT_FORMAT}, {"levels", required_argument, 0, 'l'},
        {"dither", required_argument, 0, 'd'}, {"spacing", required_argument, 0, OPT_SPACING},
        {"gamma", required_argument, 0, 'g'}, {"gamma-k", required_argument, 0, OPT_GAMMA_K},
        {"hidden", required_argument, 0, OPT_HIDDEN}, {"backface", no_argument, 0, OPT_BACKFACE},
        {"no-shading", no_argument, 0, OPT_NO_SHADING}, {"smooth", no_argument, 0, OPT_SMOOTH},
        {"color", no_argument, 0, OPT_COLOUR}, {"transparent", no_argument, 0, OPT_TRANSPARENT}, {"colour", no_argument, 0, OPT_COLOUR}, {"band", required_argument, 0, 'b'},
        {"light", required_argument, 0, OPT_LIGHT}, {"bright", required_argument, 0, OPT_BRIGHT},
        {"ambient", required_argument, 0, OPT_AMBIENT},
        {"attenuation", required_argument, 0, OPT_ATTEN},
        {"raw-power", no_argument, 0, OPT_RAW_POWER}, {"parallel", no_argument, 0, OPT_PARALLEL},
        {"fov", required_argument, 0, OPT_FOV}, {"slices", required_argument, 0, OPT_SLICES},
        {"stacks", required_argument, 0, OPT_STACKS}, {"stats", no_argument, 0, OPT_STATS},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    stp_tool_options opt;
    stp_scene_options sopt;
    stp_scene scene;
    stp_posix_frame frame;
    stp_style_table lp;
    stp_tool_stats stats;
    stp_posix_file_kind kind = STP_POSIX_FILE_UNKNOWN;
    const char *out_path = 0, *scene_path;
    char err[512];
    int c, show_stats = 0;

    stp_tool_options_default(&opt);
    stp_scene_options_default(&sopt);
    optind = 1;
    while ((c = getopt_long(argc, argv, "o:s:l:d:g:b:h", longs, 0)) != -1) {
        switch (c) {
        case 'o': out_path = optarg; break;
        case 's': {
            int w, h;
            char extra;
            if (sscanf(optarg, "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 32767 ||
                h > 32767)
                return fail("bad --size '%s' (want WxH, 1..32767 each)", optarg);
            opt.width = w;
            opt.height = h;
            break;
        }
        case OPT_FORMAT:
            if (parse_kind(optarg, &kind))
                return fail("bad --format '%s' (pbm, plain-pbm, pgm, ppm, txt)", optarg);
            break;
        case 'l':
            if (parse_int(optarg, 2, 256, &opt.levels))
                return fail("bad --levels '%s' (2..256)", optarg);
            break;
        case 'd':
            if (parse_dither(optarg, &opt))
                return fail("bad --dither '%s'", optarg);
            break;
        case OPT_SPACING:
            if (parse_spacing(optarg, &opt.spacing))
                return fail("bad --spacing '%s'", optarg);
            break;
        case 'g':
            if (parse_double(optarg, &opt.gamma) || opt.gamma <= 0)
                return fail("bad --gamma '%s' (> 0)", optarg);
            break;
        case OPT_GAMMA_K:
            if (parse_double(optarg, &opt.gamma_k) || opt.gamma_k <= 0)
                return fail("bad --gamma-k '%s' (> 0)", optarg);
            break;
        case OPT_HIDDEN:
            if (!strcmp(optarg, "zbuffer"))
                opt.hidden = STP_HIDDEN_ZBUFFER;
            else if (!strcmp(optarg, "painter"))
                opt.hidden = STP_HIDDEN_PAINTER;
            else if (!strcmp(optarg, "none"))
                opt.hidden = STP_HIDDEN_NONE;
            else
                return fail("bad --hidden '%s' (zbuffer, painter, none)", optarg);
            break;
        case OPT_BACKFACE: opt.backface_removal = 1; break;
        case OPT_NO_SHADING: opt.shading = 0; break;
        case OPT_SMOOTH: opt.smooth = 1; break;
        case OPT_COLOUR: opt.colour = 1; break;
        case OPT_TRANSPARENT: opt.transparency = 1; break;
        case 'b':
            if (parse_int(optarg, 1, 32767, &opt.band_rows))
                return fail("bad --band '%s' (1..32767)", optarg);
            break;
        case OPT_LIGHT: {
            stp_scene_vec3 p;
            char extra;
            if (opt.light_count >= STP_MAX_LIGHTS)
                return fail("too many --light options");
            if (sscanf(optarg, "%lf,%lf,%lf%c", &p.x, &p.y, &p.z, &extra) != 3 || !isfinite(p.x) ||
                !isfinite(p.y) || !isfinite(p.z))
                return fail("bad --light '%s' (want X,Y,Z)", optarg);
            opt.lights[opt.light_count++] = p;
            break;
        }
        case OPT_BRIGHT:
            if (parse_double(optarg, &opt.brightness) || opt.brightness < 0)
                return fail("bad --bright '%s' (>= 0)", optarg);
            break;
        case OPT_AMBIENT:
            if (parse_double(optarg, &opt.background) || opt.background < 0 || opt.background > 1)
                return fail("bad --ambient '%s' (0..1)", optarg);
            break;
        case OPT_ATTEN:
            if (parse_double(optarg, &opt.attenuation_c) || opt.attenuation_c <= 0)
                return fail("bad --attenuation '%s' (> 0)", optarg);
            break;
        case OPT_RAW_POWER: opt.auto_power = 0; break;
        case OPT_PARALLEL: opt.perspective = 0; break;
        case OPT_FOV:
            if (parse_double(optarg, &opt.fov) || opt.fov <= 0 || opt.fov >= 180)
                return fail("bad --fov '%s' (0..180)", optarg);
            break;
        case OPT_SLICES:
            if (parse_int(optarg, 3, 1024, &sopt.sphere_slices))
                return fail("bad --slices '%s' (3..1024)", optarg);
            sopt.cone_slices = sopt.sphere_slices;
            break;
        case OPT_STACKS:
            if (parse_int(optarg, 2, 1024, &sopt.sphere_stacks))
                return fail("bad --stacks '%s' (2..1024)", optarg);
            break;
        case OPT_STATS: show_stats = 1; break;
        case 'h': usage_render(stdout); return 0;
        default: usage_render(stderr); return 2;
        }
    }
    if (optind != argc - 1) {
        usage_render(stderr);
        return 2;
    }
    scene_path = argv[optind];
    if (!out_path)
        return fail("render: no output given (-o FILE, or -o - for stdout)");
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
    if (stp_posix_frame_init(&frame, (uint32_t)opt.width, (uint32_t)opt.height,
                             format_for_kind(kind)) != 0) {
        stp_scene_free(&scene);
        return fail("out of memory for the frame");
    }
    if (stp_tool_render(&scene, &opt, stp_posix_frame_port(&frame), &stats, err, sizeof err) != 0) {
        stp_posix_frame_free(&frame);
        stp_scene_free(&scene);
        return fail("%s: %s", scene_path, err);
    }
    stp_scene_free(&scene);
    if (show_stats)
        fprintf(stderr,
                "%s: %lu polygons (%lu degenerate skipped), %lu display-file entries, "
                "%zu bytes of frame memory\n",
                scene_path, stats.polygons_in, stats.polygons_skipped, stats.display_entries,
                stats.frame_bytes);
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
        {"dither", required_argument, 0, 'd'}, {"spacing", required_argument, 0, OPT_SPACING},
        {"gamma", required_argument, 0, 'g'}, {"gamma-k", required_argument, 0, OPT_GAMMA_K},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    stp_tool_options opt;
    stp_posix_image img;
    stp_posix_frame frame;
    stp_cell cell;
    uint8_t table[256];
    const char *out_path = 0;
    char err[512];
    int c, plain = 0, use_gamma = 0;
    uint32_t y, x;

    stp_tool_options_default(&opt);
    optind = 1;
    while ((c = getopt_long(argc, argv, "o:d:g:h", longs, 0)) != -1) {
        switch (c) {
        case 'o': out_path = optarg; break;
        case OPT_PLAIN: plain = 1; break;
        case 'd':
            if (parse_dither(optarg, &opt))
                return fail("bad --dither '%s'", optarg);
            break;
        case OPT_SPACING:
            if (parse_spacing(optarg, &opt.spacing))
                return fail("bad --spacing '%s'", optarg);
            break;
        case 'g':
            if (parse_double(optarg, &opt.gamma) || opt.gamma <= 0)
                return fail("bad --gamma '%s' (> 0)", optarg);
            use_gamma = 1;
            break;
        case OPT_GAMMA_K:
            if (parse_double(optarg, &opt.gamma_k) || opt.gamma_k <= 0)
                return fail("bad --gamma-k '%s' (> 0)", optarg);
            use_gamma = 1;
            break;
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
    if (use_gamma && stp_gamma_table(table, 256, stp_tool_fix(opt.gamma), stp_tool_fix(opt.gamma_k)))
        return fail("bad gamma");
    if (stp_posix_read_grey(argv[optind], &img, err, sizeof err) != 0)
        return fail("%s", err);
    if (stp_posix_frame_init(&frame, img.width, img.height, STP_PIXEL_MONO1) != 0) {
        stp_posix_image_free(&img);
        return fail("out of memory");
    }
    for (y = 0; y < img.height; y++) {
        uint8_t *grey = img.samples + (size_t)y * img.width;
        if (use_gamma)
            for (x = 0; x < img.width; x++)
                grey[x] = table[grey[x]];
        stp_halftone_row(frame.pixels + (size_t)y * frame.stride, grey, img.width, y, &cell);
    }
    stp_posix_image_free(&img);
    if (stp_posix_write(&frame, out_path, plain ? STP_POSIX_FILE_P1 : STP_POSIX_FILE_P4, err,
                        sizeof err) != 0) {
        stp_posix_frame_free(&frame);
        return fail("%s", err);
    }
    stp_posix_frame_free(&frame);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage_main(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "render"))
        return cmd_render(argc - 1, argv + 1);
    if (!strcmp(argv[1], "dither"))
        return cmd_dither(argc - 1, argv + 1);
    if (!strcmp(argv[1], "compile"))
        return stp_tool_compile_main(argc - 1, argv + 1);
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        if (argc > 2 && !strcmp(argv[2], "render"))
            usage_render(stdout);
        else if (argc > 2 && !strcmp(argv[2], "dither"))
            usage_dither(stdout);
        else
            usage_main(stdout);
        return 0;
    }
    fprintf(stderr, "%s: unknown command '%s'\n", program, argv[1]);
    usage_main(stderr);
    return 2;
}
