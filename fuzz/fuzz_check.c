/* SPDX-License-Identifier: MIT */
/* Checks shared by the fuzz targets; see fuzz_check.h. */
#include "fuzz_check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fz_fail(const char *what, const char *detail, long a, long b)
{
    fprintf(stderr, "fuzz check failed: %s (%s; %ld, %ld)\n", what, detail ? detail : "", a, b);
    abort();
}

void fz_status_known(int st, int extra, const char *call)
{
    if (st == SUBD_OK || (extra != 0 && st == extra))
        return;
    FZ_CHECK(st <= SUBD_ERR_NOMEM && st >= SUBD_STATUS_LOWEST, call, st, extra);
}

void fz_arena_open(fz_arena *fa, uint32_t size)
{
    fa->size = size;
    fa->block = (uint8_t *)malloc((size_t)size + FZ_GUARD);
    FZ_CHECK(fa->block != NULL, "malloc", size, 0);
    memset(fa->block, 0xC3, size < 4096u ? (size_t)size : 4096u);
    memset(fa->block + size, 0xA5, FZ_GUARD);
    subd_arena_init(&fa->a, fa->block, size);
    subd_arena_reset_peak(&fa->a);
}

void fz_arena_after(fz_arena *fa, int st, uint32_t mark, uint32_t plan, const char *call)
{
    for (uint32_t i = 0; i < FZ_GUARD; i++)
        FZ_CHECK(fa->block[fa->size + i] == 0xA5, call, i, fa->size);
    FZ_CHECK(fa->a.used <= fa->a.size && fa->a.peak <= fa->a.size, call, fa->a.peak, fa->a.size);
    if (st != SUBD_OK) {
        FZ_CHECK(subd_arena_mark(&fa->a) == mark, call, subd_arena_mark(&fa->a), mark);
    } else {
        FZ_CHECK(fa->a.peak >= mark && fa->a.peak - mark <= plan, call, fa->a.peak - mark, plan);
    }
}

void fz_arena_close(fz_arena *fa)
{
    free(fa->block);
    fa->block = NULL;
}

void fz_snap_take(fz_snap *s, const void *p, size_t n)
{
    s->p = (const uint8_t *)p;
    s->n = n;
    s->copy = (uint8_t *)malloc(n ? n : 1u);
    FZ_CHECK(s->copy != NULL, "malloc", n, 0);
    if (n)
        memcpy(s->copy, p, n);
}

void fz_snap_check(const fz_snap *s, const char *call)
{
    if (s->n)
        FZ_CHECK(memcmp(s->copy, s->p, s->n) == 0, call, s->n, 0);
}

void fz_snap_free(fz_snap *s)
{
    free(s->copy);
    s->copy = NULL;
}

void fz_check_finite(const subd_real *p, uint32_t n, const char *call)
{
    for (uint32_t i = 0; i < n; i++)
        FZ_CHECK(subd_real_is_finite(p[i]), call, i, n);
}

void fz_validate_mesh(const subd_mesh *m, int same_adjacency, const char *call)
{
    uint32_t *fsize = (uint32_t *)malloc(((size_t)m->num_faces + 1u) * 4u);
    uint32_t *lsize = (uint32_t *)malloc(((size_t)m->num_lines + 1u) * 4u);
    FZ_CHECK(fsize != NULL && lsize != NULL, "malloc", m->num_faces, m->num_lines);
    FZ_CHECK(m->num_faces == 0 || m->face_start[0] == 0, call, m->face_start[0], 0);
    for (uint32_t f = 0; f < m->num_faces; f++) {
        FZ_CHECK(m->face_start[f + 1u] > m->face_start[f], call, f, m->face_start[f]);
        fsize[f] = m->face_start[f + 1u] - m->face_start[f];
    }
    FZ_CHECK(m->num_faces == 0 || m->face_start[m->num_faces] == m->num_corners, call,
             m->num_faces ? m->face_start[m->num_faces] : 0, m->num_corners);
    for (uint32_t l = 0; l < m->num_lines; l++)
        lsize[l] = m->line_start[l + 1u] - m->line_start[l];
    subd_face_list fl;
    memset(&fl, 0, sizeof fl);
    fl.num_verts = m->num_verts;
    fl.pos = m->pos;
    fl.num_faces = m->num_faces;
    fl.face_size = fsize;
    fl.index = m->corner_vert;
    fl.num_lines = m->num_lines;
    fl.line_size = m->num_lines ? lsize : NULL;
    fl.line_index = m->num_lines ? m->line_vert : NULL;
    uint32_t plan = 0;
    int st = subd_mesh_plan(&fl, &plan);
    FZ_CHECK(st == SUBD_OK, call, st, 0);
    FZ_CHECK(plan <= 4u * FZ_MAX_ARENA, call, plan, 0);
    fz_arena fa;
    fz_arena_open(&fa, plan);
    subd_mesh b;
    subd_diag d;
    st = subd_mesh_build(&fa.a, &fl, &b, &d);
    FZ_CHECK(st == SUBD_OK, call, st, d.face);
    fz_arena_after(&fa, st, 0, plan, "subd_mesh_build (validator)");
    fz_check_finite(m->pos, 3u * m->num_verts, call);
    if (same_adjacency) {
        FZ_CHECK(m->twin != NULL && m->vert_out != NULL, call, 0, 0);
        FZ_CHECK(memcmp(m->twin, b.twin, (size_t)m->num_corners * 4u) == 0, call, 1, 0);
        FZ_CHECK(memcmp(m->vert_out, b.vert_out, (size_t)m->num_verts * 4u) == 0, call, 2, 0);
        FZ_CHECK(m->num_edges == b.num_edges && m->num_boundary_edges == b.num_boundary_edges &&
                     m->num_boundary_loops == b.num_boundary_loops && m->num_isolated == b.num_isolated,
                 call, m->num_edges, b.num_edges);
        for (uint32_t v = 0; v < m->num_verts; v++)
            FZ_CHECK((m->vert_tag[v] & 3u) == (b.vert_tag[v] & 3u), call, v, m->vert_tag[v]);
        for (uint32_t c = 0; c < m->num_corners; c++)
            FZ_CHECK((m->edge_tag[c] & 1u) == (b.edge_tag[c] & 1u), call, c, m->edge_tag[c]);
    }
    fz_arena_close(&fa);
    free(fsize);
    free(lsize);
}
