/* SPDX-License-Identifier: MIT */
/* The reader checks (fuzz_obj.c, fuzz_off.c, fuzz_stl.c, fuzz_ply.c). The input is the file;
 * for the text formats OBJ and OFF, bytes after the first NUL byte, if any, are a tag file
 * (include/subd_tags.h) applied to the mesh (subd_tags_check, subd_tags_apply, and
 * subd_tags_alpha with several dens); STL and PLY may be binary, so all of their input is the
 * file and the tag checks run with an empty tag file. A mesh read is written and read back:
 * OBJ and OFF by their own writers, PLY through OBJ (there is no PLY writer), STL by
 * subd_stl_write, which must give the same mesh (float32 always; Q16.16 when every coordinate
 * is below 256 in magnitude, where float32 holds it exactly). */
#include "fuzz_reader.h"

#include <stdlib.h>
#include <string.h>

typedef int (*plan_fn)(const char *, uint32_t, uint32_t *, subd_diag *);
typedef int (*read_fn)(subd_arena *, const char *, uint32_t, subd_mesh *, subd_diag *);
typedef int (*write_fn)(const subd_mesh *, char *, uint32_t, uint32_t *);

/* subd_tags_alpha on the same text, after subd_tags_check gave st0 (line0) and rep0, with
 * the report's common den (every value exact), 1, a fine one (3600000) and invalid ones:
 * den <= 0 is SUBD_ERR_PARAM; else an invalid file gives check's failure (or SUBD_ERR_RANGE
 * on an earlier line: values are converted while checking), a valid one SUBD_OK or
 * SUBD_ERR_RANGE; diag.line names a failing line; NULL arrays give the same status; on
 * failure nothing is stored; on success only named entries change (at most one per alpha /
 * falpha line), within +-SUBD_ALPHA_MAX_NUM, and the counts are check's. The mesh is never
 * changed (no tag bits). */
static void alpha_run(const subd_mesh *m, const char *tags, uint32_t tlen, int st0, uint32_t line0,
                      const subd_tags_report *rep0)
{
    static const int32_t dens[4] = {1, 3600000, 0, -7};
    uint32_t nv = m->num_verts, nf = m->num_faces;
    int32_t *vn = (int32_t *)malloc(((size_t)nv + 1u) * 4u), *fn = (int32_t *)malloc(((size_t)nf + 1u) * 4u);
    int32_t *vn0 = (int32_t *)malloc(((size_t)nv + 1u) * 4u), *fn0 = (int32_t *)malloc(((size_t)nf + 1u) * 4u);
    FZ_CHECK(vn && fn && vn0 && fn0, "malloc", nv, nf);
    fz_snap sm;
    fz_snap_take(&sm, m, sizeof *m);
    for (uint32_t k = 0; k < 5u; k++) {
        int32_t den = k == 0u ? (rep0->alpha_den > 0 ? rep0->alpha_den : 1) : dens[k - 1u];
        for (uint32_t i = 0; i < nv; i++)
            vn[i] = vn0[i] = (int32_t)(0x5A5A5A5Au ^ i * 2654435761u);
        for (uint32_t i = 0; i < nf; i++)
            fn[i] = fn0[i] = (int32_t)(0x3C3C3C3Cu ^ i * 2246822519u);
        subd_tags_report rep;
        subd_diag d;
        int st = subd_tags_alpha(tags, tlen, m, den, vn, fn, &rep, &d);
        fz_status_known(st, 0, "subd_tags_alpha");
        fz_snap_check(&sm, "subd_tags_alpha mesh");
        if (den <= 0)
            FZ_CHECK(st == SUBD_ERR_PARAM, "subd_tags_alpha den <= 0", st, den);
        else if (st0 != SUBD_OK)
            FZ_CHECK(st == st0 ? d.line == line0 : st == SUBD_ERR_RANGE && d.line <= line0,
                     "subd_tags_alpha = subd_tags_check on an invalid file", st, st0);
        else
            FZ_CHECK(st == SUBD_OK || st == SUBD_ERR_RANGE, "subd_tags_alpha on a valid file", st, d.line);
        if (st == SUBD_ERR_RANGE || st == SUBD_ERR_PARSE || st == SUBD_ERR_INDEX)
            FZ_CHECK(d.line > 0, "subd_tags_alpha: diag.line names the line", st, d.line);
        subd_diag d2;
        int st2 = subd_tags_alpha(tags, tlen, m, den, NULL, NULL, NULL, &d2);
        FZ_CHECK(st2 == st, "subd_tags_alpha without arrays", st2, st);
        if (st != SUBD_OK) {
            FZ_CHECK(memcmp(vn, vn0, (size_t)nv * 4u) == 0 && memcmp(fn, fn0, (size_t)nf * 4u) == 0,
                     "subd_tags_alpha: nothing stored on failure", st, d.line);
            continue;
        }
        FZ_CHECK(rep.creases == rep0->creases && rep.vertex_tags == rep0->vertex_tags &&
                     rep.vertex_alphas == rep0->vertex_alphas && rep.face_alphas == rep0->face_alphas &&
                     rep.alpha_den == rep0->alpha_den,
                 "subd_tags_alpha report = subd_tags_check report", rep.vertex_alphas, rep0->vertex_alphas);
        uint32_t cv = 0, cf = 0;
        for (uint32_t i = 0; i < nv; i++)
            if (vn[i] != vn0[i]) {
                cv++;
                FZ_CHECK(vn[i] <= SUBD_ALPHA_MAX_NUM && vn[i] >= -SUBD_ALPHA_MAX_NUM, "vertex alpha range", i, vn[i]);
            }
        for (uint32_t i = 0; i < nf; i++)
            if (fn[i] != fn0[i]) {
                cf++;
                FZ_CHECK(fn[i] <= SUBD_ALPHA_MAX_NUM && fn[i] >= -SUBD_ALPHA_MAX_NUM, "face alpha range", i, fn[i]);
            }
        FZ_CHECK(cv <= rep.vertex_alphas && cf <= rep.face_alphas, "subd_tags_alpha stores only named entries", cv,
                 cf);
    }
    fz_snap_free(&sm);
    free(vn);
    free(fn);
    free(vn0);
    free(fn0);
}

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
    alpha_run(&m, tags, tlen, st, d.line, &rep);
    fz_snap_free(&sv);
    fz_snap_free(&se);
    fz_snap_free(&sm);
    free(vt);
    free(et);
}

/* Q16.16 coordinates a float32 holds exactly (|x| < 256); always true in float32. */
static int fits_f32(const subd_mesh *m)
{
    for (uint32_t i = 0; i < 3u * m->num_verts; i++) {
        int64_t v = (int64_t)subd_real_bits(m->pos[i]);
        if (SUBD_FIXED && ((int32_t)v >= (1 << 24) || (int32_t)v <= -(1 << 24)))
            return 0;
    }
    return 1;
}

static void round_trip(const subd_mesh *m, plan_fn pl, read_fn rd, write_fn wr)
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
    if (wr == subd_stl_write && !fits_f32(m)) {
        free(txt);
        return; /* Q16.16 beyond 256: float32 rounds, corners may weld differently */
    }
    st = pl(txt, len, &plan, &d);
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

typedef struct fz_format {
    plan_fn plan;
    read_fn rd;
    const char *plan_name, *call;
    plan_fn rt_plan; /* the round trip: written by rt_wr, read back by rt_rd */
    read_fn rt_rd;
    write_fn rt_wr;
    int binary;      /* no tag file after a NUL */
} fz_format;

static const fz_format fz_formats[4] = {
    {subd_obj_plan, subd_obj_read, "subd_obj_plan", "subd_obj_read", subd_obj_plan, subd_obj_read, subd_obj_write, 0},
    {subd_off_plan, subd_off_read, "subd_off_plan", "subd_off_read", subd_off_plan, subd_off_read, subd_off_write, 0},
    {subd_stl_plan, subd_stl_read, "subd_stl_plan", "subd_stl_read", subd_stl_plan, subd_stl_read, subd_stl_write, 1},
    {subd_ply_plan, subd_ply_read, "subd_ply_plan", "subd_ply_read", subd_obj_plan, subd_obj_read, subd_obj_write, 1},
};

void fz_reader_run(const uint8_t *data, size_t size, int fmt)
{
    const fz_format *fm = &fz_formats[fmt];
    plan_fn plan = fm->plan;
    read_fn rd = fm->rd;
    const char *call = fm->call;
    if (size > 1u << 20)
        return;
    const uint8_t *nul = fm->binary ? NULL : (const uint8_t *)memchr(data, 0, size);
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
    fz_status_known(st, 0, fm->plan_name);
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
                round_trip(&m, fm->rt_plan, fm->rt_rd, fm->rt_wr);
                tags_run(&m, tags, tlen);
            }
        }
        fz_arena_close(&fa);
    }
    fz_snap_check(&in, "input unchanged");
    fz_snap_free(&in);
    free(buf);
}
