/* SPDX-License-Identifier: MIT */
/* Shared render options: see options.h. */
#define _POSIX_C_SOURCE 200809L
#include "options.h"
#include "camera.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static const struct option shared[] = {
    {"size", required_argument, 0, 's'},
    {"levels", required_argument, 0, 'l'},
    {"dither", required_argument, 0, 'd'},
    {"spacing", required_argument, 0, STP_TOOL_OPT_SPACING},
    {"gamma", required_argument, 0, 'g'},
    {"gamma-k", required_argument, 0, STP_TOOL_OPT_GAMMA_K},
    {"hidden", required_argument, 0, STP_TOOL_OPT_HIDDEN},
    {"backface", no_argument, 0, STP_TOOL_OPT_BACKFACE},
    {"no-shading", no_argument, 0, STP_TOOL_OPT_NO_SHADING},
    {"smooth", no_argument, 0, STP_TOOL_OPT_SMOOTH},
    {"color", no_argument, 0, STP_TOOL_OPT_COLOUR},
    {"colour", no_argument, 0, STP_TOOL_OPT_COLOUR},
    {"transparent", no_argument, 0, STP_TOOL_OPT_TRANSPARENT},
    {"light", required_argument, 0, STP_TOOL_OPT_LIGHT},
    {"bright", required_argument, 0, STP_TOOL_OPT_BRIGHT},
    {"ambient", required_argument, 0, STP_TOOL_OPT_AMBIENT},
    {"attenuation", required_argument, 0, STP_TOOL_OPT_ATTEN},
    {"raw-power", no_argument, 0, STP_TOOL_OPT_RAW_POWER},
    {"parallel", no_argument, 0, STP_TOOL_OPT_PARALLEL},
    {"fov", required_argument, 0, STP_TOOL_OPT_FOV},
    {"slices", required_argument, 0, STP_TOOL_OPT_SLICES},
    {"stacks", required_argument, 0, STP_TOOL_OPT_STACKS},
    {"shadows", required_argument, 0, STP_TOOL_OPT_SHADOWS},
    {"raytrace", no_argument, 0, STP_TOOL_OPT_RAYTRACE},
    {"depth", required_argument, 0, STP_TOOL_OPT_DEPTH},
    {"min-weight", required_argument, 0, STP_TOOL_OPT_MIN_WEIGHT},
    {"no-hierarchy", no_argument, 0, STP_TOOL_OPT_NO_HIERARCHY},
    {"exposure", required_argument, 0, STP_TOOL_OPT_EXPOSURE},
    {"grey", required_argument, 0, STP_TOOL_OPT_GREY},
    {"gray", required_argument, 0, STP_TOOL_OPT_GREY},
    {"background", required_argument, 0, STP_TOOL_OPT_BACKGROUND},
    {"edge-aa", no_argument, 0, STP_TOOL_OPT_EDGE_AA},
};

int stp_tool_long_options(struct option *out, size_t cap, const struct option *extra)
{
    size_t n = sizeof shared / sizeof shared[0], k = 0;
    while (extra[k].name)
        k++;
    if (n + k + 1 > cap)
        return -1;
    memcpy(out, shared, sizeof shared);
    memcpy(out + n, extra, sizeof *extra * (k + 1));
    return 0;
}

int stp_tool_parse_int(const char *s, int lo, int hi, int *out)
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

int stp_tool_parse_double(const char *s, double *out)
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

int stp_tool_parse_dither(const char *s, stp_tool_options *opt)
{
    static const struct {
        const char *name;
        stp_tool_dither dither;
    } names[] = {{"bayer2", STP_TOOL_DITHER_BAYER2},   {"bayer4", STP_TOOL_DITHER_BAYER4},
                 {"bayer8", STP_TOOL_DITHER_BAYER8},   {"seed2x2", STP_TOOL_DITHER_SEED2X2},
                 {"pattern2x2", STP_TOOL_DITHER_PATTERN2X2}, {"bayer16", STP_TOOL_DITHER_BAYER16},
                 {"blue-noise", STP_TOOL_DITHER_BLUE_NOISE}};
    /* error diffusion: NAME, NAME:raster for rows all left to right, or
     * NAME:blue for rows left to right with blue-noise-modulated thresholds */
    static const struct {
        const char *name;
        stp_diffusion_kernel kernel;
    } kernels[] = {{"fs", STP_DIFFUSE_FLOYD_STEINBERG},  {"floyd-steinberg", STP_DIFFUSE_FLOYD_STEINBERG},
                   {"atkinson", STP_DIFFUSE_ATKINSON},   {"sierra-lite", STP_DIFFUSE_SIERRA_LITE},
                   {"jjn", STP_DIFFUSE_JARVIS_JUDICE_NINKE}, {"stucki", STP_DIFFUSE_STUCKI},
                   {"burkes", STP_DIFFUSE_BURKES}};
    size_t i;
    int w, h, n = 0, t;
    char *copy, *tok, *save = 0;
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(s, names[i].name)) {
            opt->dither = names[i].dither;
            return 0;
        }
    for (i = 0; i < sizeof kernels / sizeof kernels[0]; i++) {
        size_t len = strlen(kernels[i].name);
        int blue = !strncmp(s, kernels[i].name, len) && !strcmp(s + len, ":blue");
        if (!strncmp(s, kernels[i].name, len) && (!s[len] || !strcmp(s + len, ":raster") || blue)) {
            opt->dither = STP_TOOL_DITHER_DIFFUSE;
            opt->diffuse_kernel = kernels[i].kernel;
            opt->diffuse_raster = s[len] != 0;
            opt->diffuse_noise = blue;
            return 0;
        }
    }
    /* clustered:N (0 degrees) or clustered45:N */
    if (!strncmp(s, "clustered:", 10) || !strncmp(s, "clustered45:", 12)) {
        int angle = s[9] == ':' ? 0 : 45, side;
        stp_cell probe;
        if (stp_tool_parse_int(s + (angle ? 12 : 10), 2, STP_CELL_MAX, &side) ||
            stp_cell_clustered(&probe, side, angle) != 0)
            return -1;
        opt->dither = STP_TOOL_DITHER_CLUSTERED;
        opt->clustered_n = side;
        opt->clustered_angle = angle;
        return 0;
    }
    /* user:W:H:t,t,... (row-major thresholds) */
    if (strncmp(s, "user:", 5) != 0 || !(copy = strdup(s + 5)))
        return -1;
    tok = strtok_r(copy, ":", &save);
    if (!tok || stp_tool_parse_int(tok, 1, STP_CELL_MAX, &w))
        goto bad;
    tok = strtok_r(0, ":", &save);
    if (!tok || stp_tool_parse_int(tok, 1, STP_CELL_MAX, &h))
        goto bad;
    for (tok = strtok_r(0, ",", &save); tok; tok = strtok_r(0, ",", &save)) {
        if (n >= w * h || stp_tool_parse_int(tok, 0, 255, &t))
            goto bad;
        opt->user_cell[n++] = (unsigned char)t;
    }
    if (n != w * h)
        goto bad;
    free(copy);
    opt->user_cell_w = w;
    opt->user_cell_h = h;
    opt->dither = STP_TOOL_DITHER_USER;
    return 0;
bad:
    free(copy);
    return -1;
}

int stp_tool_parse_spacing(const char *s, stp_spacing *out)
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

/* Set *field from arg when it parses and lies in [lo, hi] (bounds inclusive
 * unless open_lo / open_hi). */
static int parse_range(const char *arg, double lo, int open_lo, double hi, int open_hi,
                       double *field)
{
    double v;
    if (stp_tool_parse_double(arg, &v) || v < lo || (open_lo && v == lo) || v > hi ||
        (open_hi && v == hi))
        return -1;
    *field = v;
    return 0;
}

int stp_tool_apply_option(int code, const char *arg, stp_tool_options *opt,
                          stp_scene_options *sopt, char *err, size_t err_size)
{
    const char *what = 0;
    char depth_what[32];
    switch (code) {
    case 's': {
        int w, h;
        char extra;
        if (sscanf(arg, "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 32767 || h > 32767) {
            what = "--size (want WxH, 1..32767 each)";
            break;
        }
        opt->width = w;
        opt->height = h;
        return 1;
    }
    case 'l':
        if (stp_tool_parse_int(arg, 2, 256, &opt->levels))
            what = "--levels (2..256)";
        opt->levels_given = 1;
        break;
    case 'd':
        if (stp_tool_parse_dither(arg, opt))
            what = "--dither (bayer2, bayer4, bayer8, bayer16, blue-noise, clustered:N, "
                   "clustered45:N, seed2x2, pattern2x2, user:W:H:t,..., fs, atkinson, sierra-lite, "
                   "jjn, stucki, burkes; NAME:raster, NAME:blue)";
        opt->dither_given = 1;
        break;
    case STP_TOOL_OPT_SPACING:
        if (stp_tool_parse_spacing(arg, &opt->spacing))
            what = "--spacing (linear, exponential, cubic)";
        break;
    case 'g':
        if (parse_range(arg, 0, 1, 1e6, 0, &opt->gamma))
            what = "--gamma (> 0)";
        break;
    case STP_TOOL_OPT_GAMMA_K:
        if (parse_range(arg, 0, 1, 1e6, 0, &opt->gamma_k))
            what = "--gamma-k (> 0)";
        break;
    case STP_TOOL_OPT_HIDDEN:
        if (!strcmp(arg, "zbuffer"))
            opt->hidden = STP_HIDDEN_ZBUFFER;
        else if (!strcmp(arg, "painter"))
            opt->hidden = STP_HIDDEN_PAINTER;
        else if (!strcmp(arg, "none"))
            opt->hidden = STP_HIDDEN_NONE;
        else
            what = "--hidden (zbuffer, painter, none)";
        break;
    case STP_TOOL_OPT_BACKFACE: opt->backface_removal = 1; break;
    case STP_TOOL_OPT_NO_SHADING: opt->shading = 0; break;
    case STP_TOOL_OPT_SMOOTH: opt->smooth = 1; break;
    case STP_TOOL_OPT_EDGE_AA: opt->edge_aa = 1; break;
    case STP_TOOL_OPT_COLOUR: opt->colour = 1; break;
    case STP_TOOL_OPT_TRANSPARENT: opt->transparency = 1; break;
    case STP_TOOL_OPT_LIGHT: {
        stp_scene_vec3 p;
        char extra;
        if (opt->light_count >= STP_MAX_LIGHTS) {
            what = "--light (too many)";
            break;
        }
        if (sscanf(arg, "%lf,%lf,%lf%c", &p.x, &p.y, &p.z, &extra) != 3 || !isfinite(p.x) ||
            !isfinite(p.y) || !isfinite(p.z)) {
            what = "--light (want X,Y,Z)";
            break;
        }
        opt->lights[opt->light_count++] = p;
        return 1;
    }
    case STP_TOOL_OPT_BRIGHT:
        if (parse_range(arg, 0, 0, 1e6, 0, &opt->brightness))
            what = "--bright (>= 0)";
        break;
    case STP_TOOL_OPT_AMBIENT:
        if (parse_range(arg, 0, 0, 1, 0, &opt->background))
            what = "--ambient (0..1)";
        break;
    case STP_TOOL_OPT_ATTEN:
        if (parse_range(arg, 0, 1, 1e6, 0, &opt->attenuation_c))
            what = "--attenuation (> 0)";
        break;
    case STP_TOOL_OPT_RAW_POWER: opt->auto_power = 0; break;
    case STP_TOOL_OPT_PARALLEL: opt->perspective = 0; break;
    case STP_TOOL_OPT_FOV:
        if (parse_range(arg, 0, 1, 180, 1, &opt->fov))
            what = "--fov (0..180)";
        break;
    case STP_TOOL_OPT_SLICES:
        if (stp_tool_parse_int(arg, 3, 1024, &sopt->sphere_slices))
            what = "--slices (3..1024)";
        else
            sopt->cone_slices = sopt->sphere_slices;
        break;
    case STP_TOOL_OPT_STACKS:
        if (stp_tool_parse_int(arg, 2, 1024, &sopt->sphere_stacks))
            what = "--stacks (2..1024)";
        break;
    case STP_TOOL_OPT_SHADOWS: {
        int n;
        if (stp_tool_parse_int(arg, 1, 4096, &n))
            what = "--shadows (1..4096)";
        else
            opt->shadow_resolution = (unsigned)n;
        break;
    }
    case STP_TOOL_OPT_RAYTRACE:
        /* traced analytically: no tessellation to hold in memory */
        opt->raytrace = 1;
        sopt->analytic_only = 1;
        break;
    case STP_TOOL_OPT_DEPTH:
        if (stp_tool_parse_int(arg, 0, STP_RT_MAX_DEPTH, &opt->rt_depth)) {
            snprintf(depth_what, sizeof depth_what, "--depth (0..%d)", STP_RT_MAX_DEPTH);
            what = depth_what;
        }
        break;
    case STP_TOOL_OPT_MIN_WEIGHT:
        if (parse_range(arg, 0, 0, 1, 0, &opt->rt_min_weight))
            what = "--min-weight (0..1)";
        break;
    case STP_TOOL_OPT_NO_HIERARCHY: opt->rt_hierarchy = 0; break;
    case STP_TOOL_OPT_EXPOSURE:
        opt->exposure_given = 1;
        if (!strcmp(arg, "auto"))
            opt->exposure_auto = 1;
        else if (!strcmp(arg, "off"))
            opt->exposure_auto = 0;
        else
            what = "--exposure (auto, off)";
        break;
    case STP_TOOL_OPT_GREY:
        if (!strcmp(arg, "contrast"))
            opt->grey_contrast = 1;
        else if (!strcmp(arg, "luminance"))
            opt->grey_contrast = 0;
        else
            what = "--grey (luminance, contrast)";
        break;
    case STP_TOOL_OPT_BACKGROUND: {
        double v[3];
        char extra;
        int k = sscanf(arg, "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &extra);
        if (k == 1)
            v[1] = v[2] = v[0];
        if ((k != 1 && k != 3) || (k == 1 && strchr(arg, ',')) || v[0] < 0 || v[0] > 1 ||
            v[1] < 0 || v[1] > 1 || v[2] < 0 || v[2] > 1) {
            what = "--background (V or R,G,B, each 0..1)";
            break;
        }
        opt->background_given = 1;
        memcpy(opt->background_rgb, v, sizeof v);
        break;
    }
    default: return 0;
    }
    if (what) {
        snprintf(err, err_size, "bad %s: '%s'", what, arg ? arg : "");
        return -1;
    }
    return 1;
}

void stp_tool_options_help(FILE *to)
{
    fprintf(to,
            "  -s, --size WxH           device size in pixels (default 128x64)\n"
            "  -l, --levels N           INTENSITY levels, 2..256 (default 16; render: 256\n"
            "                           for grey and colour pictures and 1-bit picture files)\n"
            "  -d, --dither CELL        bayer2, bayer4 (default; fs:blue for a 1-bit\n"
            "                           picture file), bayer8, bayer16, blue-noise (64x64),\n"
            "                           clustered:N (dots, N 2..16), clustered45:N (45\n"
            "                           degrees, N even 4..16), seed2x2, pattern2x2,\n"
            "                           or user:W:H:t,t,... (thresholds 0..255, row-major);\n"
            "                           or error diffusion of 1-bit output: fs, atkinson,\n"
            "                           sierra-lite, jjn, stucki, burkes (serpentine; NAME:raster\n"
            "                           rows left to right, NAME:blue also no worms)\n"
            "      --spacing KIND       threshold spacing of Bayer cells: linear (default),\n"
            "                           exponential, cubic\n"
            "  -g, --gamma G            gamma of the device table V = (I/k)^(1/G) (default 1)\n"
            "      --gamma-k K          k of the gamma table (default 1)\n"
            "      --hidden METHOD      zbuffer (default), painter or none\n"
            "      --backface           remove back faces (for closed meshes)\n"
            "      --no-shading         fill each polygon with its material's reflectivity\n"
            "      --smooth             Gouraud shading from vertex normals (NFF pp, OBJ vn;\n"
            "                           averaged face normals where the file has none)\n"
            "      --color              colour shading (10.45) with the scene's colours; with a\n"
            "                           .ppm output the picture is in colour (default: grey)\n"
            "      --transparent        NFF's T makes surfaces transparent: v = v_r + t v_t,\n"
            "                           t from T/2 (grazing) to T (facing); best with\n"
            "                           --hidden painter (back to front)\n"
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
            "      --shadows N          shadows: a shadow Z buffer of N x N texels per light\n"
            "                           (512 suits 320x240; memory 2 N^2 bytes per light)\n"
            "      --raytrace           ray-trace (docs/model.md 5): spheres and cones stay\n"
            "                           analytic, shadows by shadow rays, reflections weighted\n"
            "                           Ks F, refraction through NFF's T (Snell in spheres)\n"
            "      --depth N            ray tracer: deepest reflection/refraction, 0..%d\n"
            "                           (default 4)\n"
            "      --min-weight W       ray tracer: rays weighing less are not cast, 0..1\n"
            "                           (default 0.015625)\n"
            "      --no-hierarchy       ray tracer: test every object (no bounding volumes)\n"
            "      --exposure auto|off  auto: brightness scaled so the brightest drawn pixel\n"
            "                           reaches the top level (default off; auto for a 1-bit\n"
            "                           picture file)\n"
            "      --grey MODE          grey from colour: luminance (default) or contrast (the\n"
            "                           scene's colours spread along their main axis)\n"
            "      --background V|R,G,B the empty frame's shade or colour (0..1), instead of\n"
            "                           the scene's\n"
            "      --edge-aa            anti-aliased polygon edges: pixels just outside an edge\n"
            "                           take the polygon's shade by the part it covers, before\n"
            "                           the dither (docs/edge-aa.md)\n",
            STP_MAX_LIGHTS, STP_RT_MAX_DEPTH);
}

const char *stp_tool_option_name(int code)
{
    size_t i;
    for (i = 0; i < sizeof shared / sizeof shared[0]; i++)
        if (shared[i].val == code)
            return shared[i].name;
    return "?";
}

/* Options only one of the two renderers reads. */
static const int polygon_only[] = {STP_TOOL_OPT_HIDDEN,      STP_TOOL_OPT_BACKFACE,
                                   STP_TOOL_OPT_NO_SHADING,  STP_TOOL_OPT_SMOOTH,
                                   STP_TOOL_OPT_TRANSPARENT, STP_TOOL_OPT_SHADOWS,
                                   STP_TOOL_OPT_SLICES,      STP_TOOL_OPT_STACKS,
                                   STP_TOOL_OPT_EDGE_AA};
static const int raytrace_only[] = {STP_TOOL_OPT_DEPTH, STP_TOOL_OPT_MIN_WEIGHT,
                                    STP_TOOL_OPT_NO_HIERARCHY};

int stp_tool_check_renderer(const stp_tool_given *given, int raytrace, char *err,
                            size_t err_size)
{
    const int *list = raytrace ? polygon_only : raytrace_only;
    size_t i, n = raytrace ? sizeof polygon_only / sizeof polygon_only[0]
                           : sizeof raytrace_only / sizeof raytrace_only[0];
    char names[160] = "";
    int found = 0;
    for (i = 0; i < n; i++)
        if (given->code[list[i]]) {
            size_t used = strlen(names);
            snprintf(names + used, sizeof names - used, "%s--%s", found ? ", " : "",
                     stp_tool_option_name(list[i]));
            found++;
        }
    if (!found)
        return 0;
    if (raytrace)
        snprintf(err, err_size,
                 "%s %s of the polygon renderer; the ray tracer (--raytrace) does not use %s",
                 names, found > 1 ? "are options" : "is an option", found > 1 ? "them" : "it");
    else
        snprintf(err, err_size, "%s %s of the ray tracer: add --raytrace", names,
                 found > 1 ? "are options" : "is an option");
    return -1;
}

int stp_tool_usage_error(const char *command, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "stipple%s%s: ", command ? " " : "", command ? command : "");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\nTry 'stipple%s%s --help'\n", command ? " " : "", command ? command : "");
    return 2;
}

int stp_tool_getopt_error(const char *command, int c, char *const argv[])
{
    char shown[64];
    const char *word = optind > 0 ? argv[optind - 1] : "";
    /* a long option is the word getopt stopped at (without "=value"); a
     * short one is the letter in optopt */
    if (word && !strncmp(word, "--", 2))
        snprintf(shown, sizeof shown, "%.*s", (int)strcspn(word, "="), word);
    else
        snprintf(shown, sizeof shown, "-%c", optopt > 32 && optopt < 127 ? optopt : '?');
    if (c == ':')
        return stp_tool_usage_error(command, "option '%s' needs a value", shown);
    return stp_tool_usage_error(command, "unknown option '%s'", shown);
}

const char *stp_tool_parse_scene_format(const char *s)
{
    static const char *const formats[] = {"nff", "obj", "off", "ply"};
    size_t i;
    for (i = 0; i < sizeof formats / sizeof formats[0]; i++)
        if (!strcmp(s, formats[i]))
            return formats[i];
    return 0;
}

const struct option stp_tool_camera_options[4] = {{"eye", required_argument, 0, STP_TOOL_OPT_EYE},
                                                  {"at", required_argument, 0, STP_TOOL_OPT_AT},
                                                  {"up", required_argument, 0, STP_TOOL_OPT_UP},
                                                  {0, 0, 0, 0}};

int stp_tool_apply_camera_option(int code, const char *arg, int max_keys, stp_tool_options *opt,
                                 char *err, size_t err_size)
{
    const char *name = code == STP_TOOL_OPT_EYE ? "--eye" : code == STP_TOOL_OPT_AT ? "--at" : "--up";
    stp_scene_vec3 p;
    int *count = code == STP_TOOL_OPT_EYE ? &opt->eye_count : &opt->at_count;
    if (code != STP_TOOL_OPT_EYE && code != STP_TOOL_OPT_AT && code != STP_TOOL_OPT_UP)
        return 0;
    if (stp_tool_parse_point(arg, &p) != 0) {
        snprintf(err, err_size, "bad %s '%s' (want X,Y,Z in the scene's units)", name, arg);
        return -1;
    }
    if (code == STP_TOOL_OPT_UP) {
        if (p.x == 0 && p.y == 0 && p.z == 0) {
            snprintf(err, err_size, "bad --up '%s' (a direction: not 0,0,0)", arg);
            return -1;
        }
        opt->up = p;
        opt->up_given = 1;
        return 1;
    }
    if (*count >= max_keys) {
        if (max_keys == 1)
            snprintf(err, err_size, "%s given twice (several are keys of 'stipple animate')", name);
        else
            snprintf(err, err_size, "more than %d %s keys", max_keys, name);
        return -1;
    }
    (code == STP_TOOL_OPT_EYE ? opt->eye : opt->at)[(*count)++] = p;
    return 1;
}

void stp_tool_camera_help(FILE *to, int animation)
{
    fprintf(to, "      --eye X,Y,Z          the eye's position, in the scene's units (default:\n"
                "                           the scene's view, or one framing a mesh)%s\n"
                "      --at X,Y,Z           the point looked at%s\n"
                "      --up X,Y,Z           the direction that is up in the picture\n",
            animation ? ";\n                           repeated: keys of a path spread evenly over the\n"
                        "                           frames" : "",
            animation ? " (repeated: keys, as --eye)" : "");
}
