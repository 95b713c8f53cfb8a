/* SPDX-License-Identifier: MIT */
/* subd tool: the `info` report. Counts, face sizes, boundary loops, connected components,
 * Euler characteristic and genus, valence histograms and the bounding box of the input mesh,
 * one "key: value" line each (the tool tests read them by key).
 */
#include <stdlib.h>
#include <string.h>
#include "subd_tool.h"

static uint32_t uf_find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]]; /* path halving; iterative, no recursion */
        x = parent[x];
    }
    return x;
}

/* Connected components of the faces (through shared edges, via twin). Returns the count, or
 * UINT32_MAX when out of memory. Vertex-only contact cannot join components: the builder
 * rejects such non-manifold vertices. */
static uint32_t face_components(const subd_mesh *m)
{
    uint32_t *parent, f, c, n = 0;
    if (m->num_faces == 0) return 0;
    parent = (uint32_t *)malloc((size_t)m->num_faces * sizeof *parent);
    if (!parent) return UINT32_MAX;
    for (f = 0; f < m->num_faces; f++) parent[f] = f;
    for (c = 0; c < m->num_corners; c++) {
        uint32_t t = m->twin[c];
        if (t != SUBD_NONE) {
            uint32_t a = uf_find(parent, m->corner_face[c]), b = uf_find(parent, m->corner_face[t]);
            if (a != b) {
                if (a < b) parent[b] = a;
                else parent[a] = b;
            }
        }
    }
    for (f = 0; f < m->num_faces; f++)
        if (uf_find(parent, f) == f) n++;
    free(parent);
    return n;
}

/* Prints "k:count" pairs of a histogram, or "none". */
static void print_hist(FILE *f, const uint32_t *h, uint32_t n)
{
    uint32_t k;
    int any = 0;
    for (k = 0; k < n; k++)
        if (h[k]) {
            fprintf(f, "%s%lu:%lu", any ? " " : "", (unsigned long)k, (unsigned long)h[k]);
            any = 1;
        }
    if (!any) fprintf(f, "none");
    fputc('\n', f);
}

/* "label: x y z\n" in the library's exact decimal form. */
static void print_point(FILE *f, const char *label, const subd_real *p)
{
    uint32_t k;
    fprintf(f, "%s:", label);
    for (k = 0; k < 3u; k++) {
        char buf[32];
        uint32_t n = subd_real_format(p[k], buf);
        fputc(' ', f);
        fwrite(buf, 1, n, f);
    }
    fputc('\n', f);
}

int tool_info_report(FILE *f, const tool_run *r)
{
    const subd_mesh *m = &r->in.mesh;
    uint32_t fsize[SUBD_MAX_FACE_SIZE + 1], *val_int = NULL, *val_bnd = NULL;
    uint32_t v, fc, k, max_val = 0, comps, used_verts;
    int32_t chi, chi_surf;
    int64_t twice_genus;
    subd_real lo[3], hi[3];

    memset(fsize, 0, sizeof fsize);
    for (fc = 0; fc < m->num_faces; fc++) {
        uint32_t s = subd_face_size(m, fc);
        if (s <= SUBD_MAX_FACE_SIZE) fsize[s]++;
    }
    for (v = 0; v < m->num_verts; v++) {
        uint32_t val = subd_vertex_valence(m, v);
        if (val > max_val) max_val = val;
    }
    val_int = (uint32_t *)calloc((size_t)max_val + 1u, sizeof *val_int);
    val_bnd = (uint32_t *)calloc((size_t)max_val + 1u, sizeof *val_bnd);
    comps = face_components(m);
    if (!val_int || !val_bnd || comps == UINT32_MAX) {
        free(val_int);
        free(val_bnd);
        return tool_out_of_memory();
    }
    for (v = 0; v < m->num_verts; v++) {
        if (m->vert_tag[v] & SUBD_VTAG_ISOLATED) continue;
        if (m->vert_tag[v] & SUBD_VTAG_BOUNDARY) val_bnd[subd_vertex_valence(m, v)]++;
        else val_int[subd_vertex_valence(m, v)]++;
    }
    for (k = 0; k < 3u; k++) lo[k] = hi[k] = m->pos[k];
    for (v = 1; v < m->num_verts; v++)
        for (k = 0; k < 3u; k++) {
            subd_real x = m->pos[3u * v + k];
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }

    /* Euler characteristic and genus. chi = V - E + F counts isolated vertices (each adds 1
     * to chi and is a component of its own). For the surface part (faces only, which the
     * builder guarantees is an oriented 2-manifold with boundary) with c components and b
     * boundary loops: chi_s = chi - isolated = sum_i (2 - 2 g_i - b_i), so
     *   genus = sum_i g_i = (2c - chi_s - b) / 2. */
    chi = subd_mesh_euler(m);
    chi_surf = chi - (int32_t)m->num_isolated;
    used_verts = m->num_verts - m->num_isolated;
    twice_genus = 2 * (int64_t)comps - chi_surf - (int64_t)m->num_boundary_loops;

    fprintf(f, "file: %s (%s, %lu bytes)\n", r->o.input, host_format_name(r->in.format),
            (unsigned long)r->in.file_bytes);
    fprintf(f, "arithmetic: %s\n", ARITHMETIC);
    fprintf(f, "validation: ok\n");
    fprintf(f, "vertices: %lu (%lu on faces, %lu isolated)\n", (unsigned long)m->num_verts,
            (unsigned long)used_verts, (unsigned long)m->num_isolated);
    fprintf(f, "faces: %lu\n", (unsigned long)m->num_faces);
    fprintf(f, "corners: %lu\n", (unsigned long)m->num_corners);
    fprintf(f, "edges: %lu\n", (unsigned long)m->num_edges);
    fprintf(f, "face sizes: ");
    print_hist(f, fsize, SUBD_MAX_FACE_SIZE + 1u);
    fprintf(f, "boundary edges: %lu\n", (unsigned long)m->num_boundary_edges);
    fprintf(f, "boundary loops: %lu\n", (unsigned long)m->num_boundary_loops);
    fprintf(f, "isolated vertices: %lu\n", (unsigned long)m->num_isolated);
    fprintf(f, "polylines: %lu (%lu vertices)\n", (unsigned long)m->num_lines,
            (unsigned long)m->num_line_verts);
    fprintf(f, "components: %lu (%lu with faces, %lu isolated vertices)\n",
            (unsigned long)comps + m->num_isolated, (unsigned long)comps, (unsigned long)m->num_isolated);
    fprintf(f, "euler characteristic: %ld (V - E + F; surface only: %ld)\n", (long)chi, (long)chi_surf);
    if (twice_genus >= 0 && twice_genus % 2 == 0)
        fprintf(f, "genus: %ld\n", (long)(twice_genus / 2));
    else
        fprintf(f, "genus: n/a\n");
    fprintf(f, "valence interior: ");
    print_hist(f, val_int, max_val + 1u);
    fprintf(f, "valence boundary: ");
    print_hist(f, val_bnd, max_val + 1u);
    print_point(f, "bbox min", lo);
    print_point(f, "bbox max", hi);
    fprintf(f, "arena bytes: %lu\n", (unsigned long)r->in.planned);
    free(val_int);
    free(val_bnd);
    return EXIT_OK;
}
