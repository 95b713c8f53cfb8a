/* SPDX-License-Identifier: MIT */
/* The streaming Loop tests' shared comparison (test_loop_stream.c, test_loop_tiles.c): the
 * corpus shapes, the sink that compares the j-th streamed triangle with subd_loop's face j
 * (bit-identical positions, normals and ids that map one-to-one onto subd_loop's
 * vertices), and lc_compare_one, which streams a mesh and checks all of it (loop_cmp.h). */
#include "loop_cmp.h"
#include "corpus.h"

/* A tetrahedron (valence 3) and a cube of triangles (valence 4 and 5) as OBJ text. */
static const char tet_obj[] = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
static const char cube_obj[] =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\n"
    "f 4 1 5\nf 4 5 8\n";
/* Two triangles and an isolated vertex between them. */
static const char iso_obj[] = "v 0 0 0\nv 1 0 0\nv 9 9 9\nv 1 1 0\nv 0 1 0.5\nf 1 2 4\nf 1 4 5\n";

int lc_load_text(subd_arena *a, const char *txt, subd_mesh *m)
{
    subd_diag d;
    uint32_t n = 0;
    while (txt[n]) n++;
    return CHECK_EQ(subd_obj_read(a, txt, n, m, &d), SUBD_OK);
}

int lc_load_file(subd_arena *a, const char *name, subd_mesh *m)
{
    const corpus_file *f = corpus_find(name);
    subd_diag d;
    if (!CHECK(f != 0)) return 0;
    return CHECK_EQ(subd_obj_read(a, f->data, f->len, m, &d), SUBD_OK);
}

/* Creases on every `every`-th interior edge (both halves) and two corner tags. */
void lc_tag_features(subd_mesh *m, uint32_t every)
{
    uint32_t h, k = 0;
    for (h = 0; h < m->num_corners; h++)
        if (m->twin[h] != SUBD_NONE && h < m->twin[h] && k++ % every == 0u) subd_edge_tag_set(m, h, SUBD_ETAG_CREASE);
    m->vert_tag[0] = (uint8_t)(m->vert_tag[0] | SUBD_VTAG_CORNER);
    m->vert_tag[m->num_verts - 1u] = (uint8_t)(m->vert_tag[m->num_verts - 1u] | SUBD_VTAG_CORNER);
}

int lc_make_shape(int id, subd_arena *a, subd_mesh *m)
{
    int ok;
    switch (id) {
    case S_TET: return lc_load_text(a, tet_obj, m);
    case S_CUBE_CREASE:
        if (!(ok = lc_load_text(a, cube_obj, m))) return 0;
        lc_tag_features(m, 2);
        return 1;
    case S_ICO: return lc_load_file(a, "test/data/icosahedron.obj", m);
    case S_HEXFAN: return lc_load_file(a, "test/data/hexfan.obj", m);
    case S_FAN64: return lc_load_file(a, "test/data/fan64.obj", m);
    case S_GRID_CREASE:
        if (!(ok = lc_load_file(a, "test/data/grid_tri_8x8.obj", m))) return 0;
        lc_tag_features(m, 5);
        return 1;
    case S_ISO: return lc_load_text(a, iso_obj, m);
    case S_TORUS: return lc_load_file(a, "test/data/torus_tri.obj", m);
    default:
        if (!(ok = lc_load_file(a, "test/data/torus_tri.obj", m))) return 0;
        lc_tag_features(m, 3);
        return 1;
    }
}


int lc_cmp_tri(void *ctx, const subd_loop_tri *t)
{
    cmp_sink *s = (cmp_sink *)ctx;
    uint32_t c, k;
    if (s->j >= s->ref->num_faces) {
        s->bad_pos++;
        return 0;
    }
    for (c = 0; c < 3u; c++) {
        uint32_t v = s->ref->corner_vert[3u * s->j + c];
        for (k = 0; k < 3u; k++) {
            uint32_t b = subd_real_bits(t->pos[c][k]);
            const subd_real *want = s->lpos ? s->lpos : s->ref->pos;
            if (!h_same(t->pos[c][k], want[3u * v + k])) s->bad_pos++;
            if (s->lnrm && !h_same(t->normal[c][k], s->lnrm[3u * v + k])) s->bad_pos++;
            if (!s->lnrm && !h_same(t->normal[c][k], 0)) s->bad_pos++;
            s->hash = h_fnv(s->hash, &b, 4);
        }
        if (s->v2id[v] == UINT64_MAX) s->v2id[v] = t->id[c];
        else if (s->v2id[v] != t->id[c]) s->bad_id++;
    }
    s->j++;
    return (s->stop_after && s->j == s->stop_after) ? 7 : 0;
}

/* In-place ascending sort of n ids (shell sort; the test's own, no qsort). */
static void sort_ids(uint64_t *x, uint32_t n)
{
    uint32_t gap, i, j;
    for (gap = n / 2u; gap > 0u; gap /= 2u)
        for (i = gap; i < n; i++) {
            uint64_t v = x[i];
            for (j = i; j >= gap && x[j - gap] > v; j -= gap) x[j] = x[j - gap];
            x[j] = v;
        }
}

uint32_t lc_streams, lc_skipped;

#if H_HOST
uint8_t lc_big_arena[LC_BIG_ARENA_BYTES] __attribute__((aligned(8)));
#endif

void lc_sink_init(cmp_sink *s, subd_loop_sink *sink, const subd_mesh *ref, uint64_t *v2id, uint32_t stop_after,
                  uint32_t hash)
{
    uint32_t v;
    for (v = 0; v < ref->num_verts; v++) v2id[v] = UINT64_MAX;
    s->ref = ref;
    s->lpos = s->lnrm = 0;
    s->v2id = v2id;
    s->j = s->bad_pos = s->bad_id = 0;
    s->stop_after = stop_after;
    s->hash = hash;
    sink->tri = lc_cmp_tri;
    sink->ctx = s;
}

/* Streams `in` at `levels` with rule b and compares with subd_loop. Returns 0 when the
 * arena cannot hold subd_loop's output (the case is skipped and counted). */
int lc_compare_one(subd_arena *a, const subd_mesh *in, uint32_t levels, subd_loop_boundary b, uint32_t flags,
                       uint32_t *hash)
{
    subd_loop_opts o, so;
    subd_mesh ref;
    subd_diag d;
    uint32_t plan, splan, mark = subd_arena_mark(a), v, nid = 0, used;
    cmp_sink s;
    subd_loop_sink sink;
    uint64_t *ids;
    subd_real *lp = 0, *ln = 0; /* limit mode: subd_loop_limit of the reference */
    int st;
    subd_diag_clear(&d);
    o.levels = levels;
    o.boundary = b;
    o.flags = flags & SUBD_LOOP_STREAM_LIMIT ? SUBD_LOOP_ADJACENCY : 0u; /* the reference */
    so = o;
    so.flags = flags;
    if (!CHECK_OK(subd_loop_plan(in, &o, &plan, 0), &d) || !CHECK_OK(subd_loop_stream_plan(in, &so, &splan, 0), &d)) return 0;
    if ((uint64_t)plan + splan + 16u * 1024u > subd_arena_free_bytes(a)) {
        lc_skipped++;
        return 0;
    }
    if (!CHECK_OK(subd_loop(a, in, &o, &ref, &d), &d)) return 0;
    if (flags & SUBD_LOOP_STREAM_LIMIT) {
        uint32_t lplan;
        if (!CHECK_OK(subd_loop_limit_plan(&ref, &(subd_loop_limit_opts){b, SUBD_LOOP_LIMIT_NORMALS}, &lplan, 0), &d)) return 0;
        if ((uint64_t)lplan + ref.num_verts * 8u + splan + 64u > subd_arena_free_bytes(a)) {
            subd_arena_rewind(a, mark);
            lc_skipped++;
            return 0;
        }
        if (!CHECK_OK(subd_loop_limit(a, &ref, &(subd_loop_limit_opts){b, SUBD_LOOP_LIMIT_NORMALS}, &lp, &ln, &d), &d)) return 0;
    }
    if ((uint64_t)ref.num_verts * 8u + splan + 64u > subd_arena_free_bytes(a)) {
        subd_arena_rewind(a, mark);
        lc_skipped++;
        return 0;
    }
    ids = (uint64_t *)subd_arena_alloc(a, ref.num_verts * 8u);
    lc_sink_init(&s, &sink, &ref, ids, 0, *hash);
    s.lpos = lp;
    s.lnrm = ln;
    used = subd_arena_mark(a);
    subd_arena_reset_peak(a);
    st = subd_loop_stream(a, in, &so, &sink, &d);
    CHECK_OK(st, &d);
    CHECK_EQ(subd_arena_mark(a), used);          /* nothing left in the arena */
    CHECK(a->peak - used <= splan);                /* the plan holds */
    CHECK_EQ(s.j, ref.num_faces);                  /* every triangle, once */
    CHECK_EQ(s.bad_pos, 0);                        /* same corners, same bits */
    CHECK_EQ(s.bad_id, 0);                         /* one id per vertex */
    /* control vertices keep their ids; no two vertices share one */
    for (v = 0; v < ref.num_verts; v++) {
        if (ids[v] == UINT64_MAX) continue; /* isolated */
        if (v < in->num_verts && !CHECK_EQ(ids[v], v)) break;
        ids[nid++] = ids[v];
    }
    CHECK_EQ(nid, ref.num_verts - ref.num_isolated);
    sort_ids(ids, nid);
    for (v = 1; v < nid; v++)
        if (!CHECK(ids[v - 1u] < ids[v])) break;
    *hash = s.hash;
    lc_streams++;
    subd_arena_rewind(a, mark);
    return 1;
}

/* A sink that counts the triangles (ctx: a uint32_t). */
int lc_count_tri(void *ctx, const subd_loop_tri *t)
{
    (void)t;
    (*(uint32_t *)ctx)++;
    return 0;
}
