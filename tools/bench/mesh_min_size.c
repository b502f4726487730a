/* SPDX-License-Identifier: MIT */
/* Issue 15 item 3's minimal moving configuration, for its size only
 * (tools/bench/mesh_min_size.sh links it; it is never run): a mesh spun by
 * the model transform, entered by stp_renderer_mesh (no fallback) and
 * rendered flat with one light to a 1-bit 128x64 band. */
#include "stipple/stipple.h"
static stp_renderer_storage storage;
static stp_instr df[4000];
static stp_vec3 verts[500];
static uint16_t tris[3000];
static int16_t normals[3000];
static stp_mesh_vertex scratch[500];
static uint8_t band[16 * 64];
static uint16_t zbuf[128 * 64];
static stp_cell cell;
static int flush(stp_port *p, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{ (void)p; (void)y0; (void)rows; (void)px; (void)stride; return 0; }
int main(void)
{
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, df, 4000, 128, 64);
    stp_view v; stp_lighting l; stp_material m; stp_transform t; stp_port port; stp_frame_memory mem; stp_output out;
    stp_mesh mesh; int a;
    mesh.vertices = verts; mesh.vertex_count = 500; mesh.triangles = tris; mesh.triangle_count = 1000; mesh.normals = normals; mesh.bounds = 0;
    stp_renderer_set_view(r, &v);
    stp_lighting_default(&l);
    stp_renderer_set_lighting(r, &l);
    stp_material_default(&m);
    stp_renderer_set_object_shade(r, &m);
    stp_renderer_set_backface_removal(r, 1);
    port.width = 128; port.height = 64; port.format = STP_PIXEL_MONO1; port.flush = flush; port.user = 0;
    mem.band = band; mem.band_size = sizeof band; mem.band_rows = 64; mem.zbuf = zbuf; mem.zbuf_count = 128 * 64;
    mem.sort = 0; mem.sort_count = 0; mem.setup = 0; mem.setup_count = 0;
    stp_output_default(&out);
    out.cell = &cell;
    for (a = 0;; a += 3) {
        stp_transform_identity(&t);
        stp_transform_rotate(&t, 1, a * STP_FIX_ONE);
        stp_segment_delete(r, 1);
        stp_segment_create(r, 1);
        stp_renderer_set_transform(r, &t);
        stp_renderer_mesh(r, &mesh, scratch, 500);
        stp_segment_close(r);
        stp_renderer_render(r, &port, &out, &mem);
    }
}
void _exit(int c); void _exit(int c) { (void)c; for (;;) {} }
