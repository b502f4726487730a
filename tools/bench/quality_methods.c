/* SPDX-License-Identifier: MIT */
/* The quality bench's methods: see quality_methods.h. */
#include "quality_methods.h"
#include "outlines.h"

#include "diffuse_ref.h"

static void bayer4_on_ideal(const double *ideal, int w, int h, unsigned char *bits)
{
    stp_cell cell;
    (void)stp_cell_bayer(&cell, 4);
    ref_ordered(ideal, w, h, cell.thresholds, 4, 4, bits);
}

static void fs_on_ideal(const double *ideal, int w, int h, unsigned char *bits)
{
    ref_diffuse(ideal, w, h, REF_FLOYD_STEINBERG, 0, bits);
}

static void levels256(stp_tool_options *opt)
{
    opt->levels = 256;
}

static void diffuse(stp_tool_options *opt, stp_diffusion_kernel kernel, int raster, int levels)
{
    opt->dither = STP_TOOL_DITHER_DIFFUSE;
    opt->diffuse_kernel = kernel;
    opt->diffuse_raster = raster;
    opt->levels = levels;
}

static void fs16(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_FLOYD_STEINBERG, 0, 16);
}
static void fs(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_FLOYD_STEINBERG, 0, 256);
}
static void fs_raster(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_FLOYD_STEINBERG, 1, 256);
}
/* stipple render's defaults for a PBM (stp_tool_still_defaults) */
static void still(stp_tool_options *opt)
{
    stp_tool_still_defaults(opt);
}
/* the still default without its automatic silhouettes (readable.h) */
static void still_no_lines(stp_tool_options *opt)
{
    stp_tool_still_defaults(opt);
    opt->outlines_auto = 0;
}
/* the still default with outlines (outlines.h) */
static void still_silhouette(stp_tool_options *opt)
{
    stp_tool_still_defaults(opt);
    opt->outlines = STP_OUTLINE_SILHOUETTE;
}
static void still_outlines(stp_tool_options *opt)
{
    stp_tool_still_defaults(opt);
    opt->outlines = STP_OUTLINE_SILHOUETTE | STP_OUTLINE_CREASE;
}
static void still_contrast(stp_tool_options *opt)
{
    stp_tool_still_defaults(opt);
    opt->grey_contrast = 1;
}
static void blue_noise_exposed(stp_tool_options *opt)
{
    opt->dither = STP_TOOL_DITHER_BLUE_NOISE;
    opt->levels = 256;
    opt->exposure_auto = 1;
}
static void atkinson(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_ATKINSON, 0, 256);
}
static void sierra_lite(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_SIERRA_LITE, 0, 256);
}
static void jjn(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_JARVIS_JUDICE_NINKE, 0, 256);
}
static void stucki(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_STUCKI, 0, 256);
}
static void burkes(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_BURKES, 0, 256);
}

static void blue_noise(stp_tool_options *opt)
{
    opt->dither = STP_TOOL_DITHER_BLUE_NOISE;
    opt->levels = 256;
}
/* edge anti-aliasing (--edge-aa) beside the same method without it */
static void edge_aa16(stp_tool_options *opt)
{
    opt->edge_aa = 1;
}

static void still_edge_aa(stp_tool_options *opt)
{
    stp_tool_still_defaults(opt);
    opt->edge_aa = 1;
}

static void blue_noise_exposed_edge_aa(stp_tool_options *opt)
{
    blue_noise_exposed(opt);
    opt->edge_aa = 1;
}

static void bayer16(stp_tool_options *opt)
{
    opt->dither = STP_TOOL_DITHER_BAYER16;
    opt->levels = 256;
}
static void clustered45(stp_tool_options *opt)
{
    opt->dither = STP_TOOL_DITHER_CLUSTERED;
    opt->clustered_n = 6;
    opt->clustered_angle = 45;
    opt->levels = 256;
}

static void smooth16(stp_tool_options *opt)
{
    opt->smooth = 1;
}
static void smooth_fs(stp_tool_options *opt)
{
    diffuse(opt, STP_DIFFUSE_FLOYD_STEINBERG, 1, 256);
    opt->smooth = 1;
}

static const qm_method methods[] = {
    {"bayer4, 16 levels", 0, 0}, /* the library's default (and moving pictures') */
    {"bayer4, 256 levels", levels256, 0},
    {"bayer16", bayer16, 0},
    {"blue-noise", blue_noise, 0},
    {"clustered45:6", clustered45, 0},
    {"fs, 16 levels", fs16, 0},
    {"fs", fs, 0},
    {"fs:raster", fs_raster, 0},
    {QM_STILL_DEFAULT, still, 0},
    {QM_STILL_NO_LINES, still_no_lines, 0},
    {"still, --grey contrast", still_contrast, 0},
    {"still, --outlines silhouette", still_silhouette, 0},
    {"still, --outlines both", still_outlines, 0},
    {"blue-noise, exposure", blue_noise_exposed, 0},
    {"bayer4, 16, --smooth", smooth16, 0},
    {"fs:raster, --smooth", smooth_fs, 0},
    {"atkinson", atkinson, 0},
    {"sierra-lite", sierra_lite, 0},
    {"jjn", jjn, 0},
    {"stucki", stucki, 0},
    {"burkes", burkes, 0},
    {"bayer4, 16, --edge-aa", edge_aa16, 0},
    {"still, --edge-aa", still_edge_aa, 0},
    {"blue-noise, exposure, --edge-aa", blue_noise_exposed_edge_aa, 0},
    {"ideal + bayer4", 0, bayer4_on_ideal},
    {"ideal + floyd-steinberg", 0, fs_on_ideal},
    {QM_IDEAL_FS, still, fs_on_ideal},
};

size_t qm_method_count(void)
{
    return sizeof methods / sizeof methods[0];
}

const qm_method *qm_method_at(size_t i)
{
    return &methods[i];
}
