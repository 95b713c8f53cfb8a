/* SPDX-License-Identifier: MIT */
/* The OBJ/OFF reader checks (fuzz_obj.c, fuzz_off.c). The input is the file; bytes after
 * the first NUL byte, if any, are a tag file (include/subd_tags.h) applied to the mesh. */
#include "fuzz_reader.h"

#include <stdlib.h>
#include <string.h>

typedef int (*plan_fn)(const char *, uint32_t, uint32_t *, subd_diag *);
typedef int (*read_fn)(subd_arena *, const char *, uint32_t, subd_mesh *, subd_diag *);
typedef int (*write_fn)(const subd_mesh *, char *, uint32_t, uint32_t *);

static void tags_run(const subd_mesh *m0, const char *tags, uint32_t tlen)
{
    /* work on a copy of the mesh's tag arrays so the reader's mesh stays as read */
    subd_mesh m = *m0;
    uint8_t *vt = (uint8_t *)malloc((size_t)m.num_verts + 1u);
    uint8_t *et = (uint8_t *)malloc((size_t)m.num_corners + 1u);
    FZ_CHECK(vt != NULL && et != NULL, "malloc", 0, 0);
    memcpy(vt, m0->vert_tag, m.num_verts);
    memcpy(et, m0->edge_tag, m.num_corners);
    m.vert_tag = vt;
    m.edge_tag = et;
    fz_snap sv, se, sm;
    fz_snap_take(&sv, vt, m.num_verts);
    fz_snap_take(&se, et, m.num_corners);
    fz_snap_take(&sm, &m, sizeof m);
    subd_tags_report rep;
    subd_diag d;
    int st = subd_tags_check(tags, tlen, &m, &rep, &d);
    fz_status_known(st, 0, "subd_tags_check");
    fz_snap_check(&sv, "subd_tags_check vert_tag");
    fz_snap_check(&se, "subd_tags_check edge_tag");
    fz_snap_check(&sm, "subd_tags_check mesh");
    int st2 = subd_tags_apply(tags, tlen, &m, &rep, &d);
    FZ_CHECK(st2 == st, "subd_tags_apply = subd_tags_check", st2, st);
    fz_snap_check(&sm, "subd_tags_apply mesh");
    if (st != SUBD_OK) {
        fz_snap_check(&sv, "subd_tags_apply vert_tag (failure)");
        fz_snap_check(&se, "subd_tags_apply edge_tag (failure)");
    } else {
        for (uint32_t v = 0; v < m.num_verts; v++)
            FZ_CHECK((vt[v] & sv.copy[v]) == sv.copy[v] && (vt[v] & ~0x0Cu) == sv.copy[v], "tags only added (v)", v, vt[v]);
        for (uint32_t c = 0; c < m.num_corners; c++) {
            FZ_CHECK((et[c] & se.copy[c]) == se.copy[c] && (et[c] & ~0x02u) == se.copy[c], "tags only added (e)", c, et[c]);
            if (m.twin[c] != SUBD_NONE)
                FZ_CHECK(et[c] == et[m.twin[c]], "edge tag on both half-edges", c, m.twin[c]);
        }
    }
    fz_snap_free(&sv);
    fz_snap_free(&se);
    fz_snap_free(&sm);
    free(vt);
    free(et);
}

static void round_trip(const subd_mesh *m, read_fn rd, write_fn wr)
{
    uint32_t len = 0;
    int st = wr(m, NULL, 0, &len);
    FZ_CHECK(st == SUBD_OK, "writer size", st, 0);
    if (len > FZ_MAX_ARENA)
        return;
    char *txt = (char *)malloc((size_t)len + 1u);
    FZ_CHECK(txt != NULL, "malloc", len, 0);
    uint32_t len2 = 0;
    st = wr(m, txt, len, &len2);
    FZ_CHECK(st == SUBD_OK && len2 == len, "writer", st, len2);
    if (len > 0) {
        st = wr(m, txt, len - 1u, &len2);
        FZ_CHECK(st == SUBD_ERR_NOMEM, "writer cap - 1", st, len2);
    }
    subd_mesh r;
    subd_diag d;
    uint32_t plan = 0;
    st = (wr == subd_off_write ? subd_off_plan : subd_obj_plan)(txt, len, &plan, &d);
    FZ_CHECK(st == SUBD_OK, "plan of written text", st, d.line);
    fz_arena fa;
    fz_arena_open(&fa, plan);
    st = rd(&fa.a, txt, len, &r, &d);
    /* Q16.16 writes exact values; float32 writes round-trip digits: the text reads back */
    FZ_CHECK(st == SUBD_OK, "read back written text", st, d.line);
    FZ_CHECK(r.num_verts == m->num_verts && r.num_faces == m->num_faces && r.num_corners == m->num_corners,
             "round trip counts", r.num_faces, m->num_faces);
    FZ_CHECK(memcmp(r.corner_vert, m->corner_vert, (size_t)m->num_corners * 4u) == 0, "round trip faces", 0, 0);
    FZ_CHECK(memcmp(r.pos, m->pos, (size_t)m->num_verts * 3u * sizeof(subd_real)) == 0, "round trip positions", 0, 0);
    fz_arena_close(&fa);
    free(txt);
}

void fz_reader_run(const uint8_t *data, size_t size, int off)
{
    plan_fn plan = off ? subd_off_plan : subd_obj_plan;
    read_fn rd = off ? subd_off_read : subd_obj_read;
    write_fn wr = off ? subd_off_write : subd_obj_write;
    const char *call = off ? "subd_off_read" : "subd_obj_read";
    if (size > 1u << 20)
        return;
    const uint8_t *nul = (const uint8_t *)memchr(data, 0, size);
    uint32_t len = nul ? (uint32_t)(nul - data) : (uint32_t)size;
    char *buf = (char *)malloc(size ? size : 1u); /* exact size: ASan sees any over-read */
    FZ_CHECK(buf != NULL, "malloc", size, 0);
    if (size)
        memcpy(buf, data, size);
    const char *tags = nul ? buf + len + 1u : buf + len;
    uint32_t tlen = nul ? (uint32_t)(size - len - 1u) : 0u;
    fz_snap in;
    fz_snap_take(&in, buf, size);

    uint32_t bytes = 0;
    subd_diag d;
    int st = plan(buf, len, &bytes, &d);
    fz_status_known(st, 0, off ? "subd_off_plan" : "subd_obj_plan");
    fz_snap_check(&in, "plan: input unchanged");
    uint32_t sizes[3];
    uint32_t n = 0;
    if (st != SUBD_OK) {
        sizes[n++] = 4096u; /* the read must fail as well, cleanly */
    } else if (bytes <= FZ_MAX_ARENA) {
        sizes[n++] = bytes;
        if (bytes > 0)
            sizes[n++] = bytes - 1u;
        if (bytes > 1)
            sizes[n++] = (uint32_t)(((uint64_t)bytes * (size ? data[size / 2u] : 0u)) >> 8);
    }
    for (uint32_t i = 0; i < n; i++) {
        fz_arena fa;
        fz_arena_open(&fa, sizes[i]);
        subd_mesh m;
        memset(&m, 0x5A, sizeof m);
        subd_mesh m0 = m;
        st = rd(&fa.a, buf, len, &m, &d);
        fz_status_known(st, 0, call);
        fz_snap_check(&in, "read: input unchanged");
        fz_arena_after(&fa, st, 0, bytes, call);
        if (st != SUBD_OK) {
            FZ_CHECK(memcmp(&m, &m0, sizeof m) == 0, "read: *out untouched on failure", st, 0);
        } else {
            FZ_CHECK(sizes[i] >= bytes || i > 0, call, sizes[i], bytes);
            fz_validate_mesh(&m, 1, call);
            if (i == 0) {
                round_trip(&m, rd, wr);
                tags_run(&m, tags, tlen);
            }
        }
        fz_arena_close(&fa);
    }
    fz_snap_check(&in, "input unchanged");
    fz_snap_free(&in);
    free(buf);
}
