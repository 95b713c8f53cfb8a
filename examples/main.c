/* SPDX-License-Identifier: MIT */
/* A tinysubd consumer as a CMake project builds it (examples/CMakeLists.txt): read an
 * octahedron from an OBJ string, subdivide it three times with subd_loop, stream the same
 * surface with subd_loop_stream, print both triangle counts and a hash of the positions.
 * Exit status 0 when the counts agree and every streamed corner has subd_loop's bits. */
#include <stdio.h>
#include <string.h>
#include "subd.h"

#define LEVELS 3u

static const char octahedron[] =
    "# octahedron\n"
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

/* Static buffers, no heap: the mesh and subd_loop's output; the stream's exact plan. */
static uint64_t arena_buf[64 * 1024 / 8];
static uint64_t stream_buf[(SUBD_LOOP_STREAM_BYTES(LEVELS, 4) + 7u) / 8u];

struct stream_ctx {
    const subd_mesh *ref; /* subd_loop's output, to compare against */
    uint32_t tris, differ;
};

static int on_tri(void *ctx, const subd_loop_tri *t)
{
    struct stream_ctx *c = (struct stream_ctx *)ctx;
    unsigned k;
    for (k = 0; k < 3u; k++) {
        uint32_t v = c->ref->corner_vert[3u * c->tris + k];
        if (memcmp(t->pos[k], &c->ref->pos[3u * v], sizeof t->pos[k]) != 0) c->differ++;
    }
    c->tris++;
    return 0;
}

/* FNV-1a over the bit patterns of the positions (host and device print the same value). */
static uint32_t hash_positions(const subd_mesh *m)
{
    uint32_t h = 2166136261u, i;
    for (i = 0; i < 3u * m->num_verts; i++) {
        uint32_t bits;
        unsigned b;
        memcpy(&bits, &m->pos[i], sizeof bits);
        for (b = 0; b < 32u; b += 8u) h = (h ^ ((bits >> b) & 0xffu)) * 16777619u;
    }
    return h;
}

int main(void)
{
    subd_arena a, s;
    subd_mesh coarse, fine;
    subd_diag d;
    subd_loop_opts o = {LEVELS, SUBD_LOOP_BOUNDARY_PAPER, 0};
    struct stream_ctx c;
    subd_loop_sink sink;

    if (subd_version() != SUBD_VERSION_NUMBER) {
        printf("header version %s does not match the linked library (%u)\n", SUBD_VERSION,
               (unsigned)subd_version());
        return 1;
    }
    subd_arena_init(&a, arena_buf, sizeof arena_buf);
    if (subd_obj_read(&a, octahedron, (uint32_t)(sizeof octahedron - 1u), &coarse, &d) != SUBD_OK ||
        subd_loop(&a, &coarse, &o, &fine, &d) != SUBD_OK) {
        printf("subd_obj_read / subd_loop failed\n");
        return 1;
    }
    c.ref = &fine;
    c.tris = 0;
    c.differ = 0;
    sink.tri = on_tri;
    sink.ctx = &c;
    subd_arena_init(&s, stream_buf, sizeof stream_buf);
    if (subd_loop_stream(&s, &coarse, &o, &sink, &d) != SUBD_OK) {
        printf("subd_loop_stream failed\n");
        return 1;
    }
    printf("tinysubd %s %s: %u control triangles, level %u: subd_loop %u triangles, "
           "subd_loop_stream %u triangles, %s, positions hash %08lx\n",
           SUBD_VERSION, SUBD_FIXED ? "q16.16" : "float32", (unsigned)coarse.num_faces, LEVELS,
           (unsigned)fine.num_faces, (unsigned)c.tris,
           c.differ == 0 ? "same bits" : "POSITIONS DIFFER", (unsigned long)hash_positions(&fine));
    return c.tris == fine.num_faces && c.differ == 0 ? 0 : 1;
}
