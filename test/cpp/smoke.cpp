// SPDX-License-Identifier: MIT
// The public headers from C++ (g++ -std=c++11 -Wall -Wextra -Werror, as `make test` builds
// it): read a mesh, subdivide it, stream it, check the counts and that both agree. Exit 0 ok.
#include "subd.h"
#include <cstdio>
#include <cstring>

namespace {
alignas(8) uint8_t arena_buf[64 * 1024];
alignas(8) uint8_t stream_buf[SUBD_LOOP_STREAM_BYTES(3, 6)];

const char tetra[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

struct count_ctx {
    const subd_mesh *ref;
    uint32_t n, bad;
};

int on_tri(void *ctx, const subd_loop_tri *t)
{
    count_ctx *c = static_cast<count_ctx *>(ctx);
    for (int k = 0; k < 3; k++) {
        uint32_t v = c->ref->corner_vert[3u * c->n + static_cast<uint32_t>(k)];
        if (std::memcmp(t->pos[k], &c->ref->pos[3u * v], sizeof t->pos[k]) != 0) c->bad++;
    }
    c->n++;
    return 0;
}
} // namespace

int main()
{
    subd_arena a, s;
    subd_mesh m, fine;
    subd_diag d;
    subd_loop_opts o = {3, SUBD_LOOP_BOUNDARY_PAPER, 0};
    subd_arena_init(&a, arena_buf, sizeof arena_buf);
    if (subd_version() != SUBD_VERSION_NUMBER) return std::puts("version mismatch"), 1;
    if (subd_obj_read(&a, tetra, sizeof tetra - 1, &m, &d) != SUBD_OK) return std::puts("read failed"), 1;
    if (subd_loop(&a, &m, &o, &fine, &d) != SUBD_OK) return std::puts("loop failed"), 1;
    count_ctx c = {&fine, 0, 0};
    subd_loop_sink sink = {on_tri, &c};
    subd_arena_init(&s, stream_buf, sizeof stream_buf);
    if (subd_loop_stream(&s, &m, &o, &sink, &d) != SUBD_OK) return std::puts("stream failed"), 1;
    if (c.n != 4u * 64u || c.bad != 0u || fine.num_faces != 256u) return std::puts("counts differ"), 1;
    std::printf("c++ smoke: %u triangles streamed = subd_loop's, version %s\n", c.n, SUBD_VERSION);
    return 0;
}
