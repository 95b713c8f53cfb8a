/* SPDX-License-Identifier: MIT */
/* The small-mesh decoder of the scheme fuzz targets (fuzz_mesh.h). Moved from
 * fuzz_schemes.c unchanged, so the committed corpora decode to the same meshes. */
#include "fuzz_mesh.h"

#include <string.h>

/* base integer coordinate plus a perturbation byte (1/64 units); 0x7f = a special value */
subd_real fz_coord(int base, uint8_t b, uint8_t sel)
{
#if SUBD_FIXED
    if (b == 0x7fu) {
        static const subd_real sp[4] = {INT32_MAX, INT32_MIN, 30000 * 65536, -(1 << 30)};
        return sp[sel & 3u];
    }
    return (subd_real)(base * 65536 + (int32_t)(int8_t)b * 1024);
#else
    if (b == 0x7fu) {
        static const float sp[4] = {1e30f, -3e38f, 1e-30f, 0.0f};
        float z = 0.0f;
        if (sel == 0xffu)
            return z / z; /* NaN */
        if (sel == 0xfeu)
            return 1.0f / z; /* inf */
        return sp[sel & 3u];
    }
    return (float)base + (float)(int8_t)b / 64.0f;
#endif
}


static void put_tri(fz_decoded *m, uint32_t a, uint32_t b, uint32_t c)
{
    if (m->nf >= FZ_MAXF)
        return;
    uint32_t k = 0;
    for (uint32_t f = 0; f < m->nf; f++)
        k += m->fsize[f];
    m->fsize[m->nf++] = 3;
    m->idx[k] = a, m->idx[k + 1] = b, m->idx[k + 2] = c;
}
static void put_quad(fz_decoded *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
    put_tri(m, a, b, c);
    uint32_t k = 0;
    for (uint32_t f = 0; f < m->nf; f++)
        k += m->fsize[f];
    m->fsize[m->nf - 1] = 4;
    m->idx[k] = d;
}

void fz_decode_mesh(cur *c, fz_decoded *m)
{
    static const int tet[4][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    static const int oct[6][3] = {{2, 0, 0}, {-2, 0, 0}, {0, 2, 0}, {0, -2, 0}, {0, 0, 2}, {0, 0, -2}};
    int base[FZ_MAXV][3];
    memset(base, 0, sizeof base);
    memset(m, 0, sizeof *m);
    uint8_t t = u8(c) % 8u;
    switch (t) {
    case 1: /* tetrahedron */
        m->nv = 4;
        memcpy(base, tet, sizeof tet);
        put_tri(m, 0, 2, 1), put_tri(m, 0, 1, 3), put_tri(m, 0, 3, 2), put_tri(m, 1, 2, 3);
        break;
    case 2: /* octahedron */
        m->nv = 6;
        memcpy(base, oct, sizeof oct);
        put_tri(m, 0, 2, 4), put_tri(m, 2, 1, 4), put_tri(m, 1, 3, 4), put_tri(m, 3, 0, 4);
        put_tri(m, 2, 0, 5), put_tri(m, 1, 2, 5), put_tri(m, 3, 1, 5), put_tri(m, 0, 3, 5);
        break;
    case 3: { /* 3x3 grid of vertices, 8 triangles, open */
        m->nv = 9;
        for (int v = 0; v < 9; v++)
            base[v][0] = v % 3, base[v][1] = v / 3;
        uint8_t diag = u8(c);
        for (uint32_t j = 0; j < 2; j++)
            for (uint32_t i = 0; i < 2; i++) {
                uint32_t a = j * 3 + i, b = a + 1, d = a + 3, e = a + 4;
                if ((diag >> (j * 2 + i)) & 1u)
                    put_tri(m, a, b, e), put_tri(m, a, e, d);
                else
                    put_tri(m, a, b, d), put_tri(m, b, e, d);
            }
        break;
    }
    case 4: /* cube of quads (closed) */
        m->nv = 8;
        for (int v = 0; v < 8; v++)
            base[v][0] = v & 1, base[v][1] = (v >> 1) & 1, base[v][2] = (v >> 2) & 1;
        put_quad(m, 0, 2, 3, 1), put_quad(m, 4, 5, 7, 6), put_quad(m, 0, 1, 5, 4);
        put_quad(m, 2, 6, 7, 3), put_quad(m, 0, 4, 6, 2), put_quad(m, 1, 3, 7, 5);
        break;
    case 5: { /* fan around vertex 0 of valence k (open or closed with a cap vertex) */
        uint8_t b = u8(c);
        uint32_t k = 2u + b % 12u, closed = (b >> 4) & 1u;
        m->nv = 1 + k + closed;
        static const int ring[12][2] = {{4, 0}, {3, 2}, {2, 3}, {0, 4}, {-2, 3}, {-3, 2},
                                        {-4, 0}, {-3, -2}, {-2, -3}, {0, -4}, {2, -3}, {3, -2}};
        for (uint32_t i = 0; i < k; i++)
            base[1 + i][0] = ring[(i * 12u) / k][0], base[1 + i][1] = ring[(i * 12u) / k][1];
        base[0][2] = 1;
        for (uint32_t i = 0; i < k; i++) {
            uint32_t a = 1 + i, n = 1 + (i + 1) % k;
            if (i + 1 < k || k > 2)
                put_tri(m, 0, a, n);
            if (closed && (i + 1 < k || k > 2))
                put_tri(m, k + 1, n, a);
        }
        if (closed)
            base[k + 1][2] = -1;
        break;
    }
    case 6: /* two triangles sharing an edge, or one */
        m->nv = 4;
        base[1][0] = 1, base[2][1] = 1, base[3][0] = 1, base[3][1] = 1;
        put_tri(m, 0, 1, 2);
        if (u8(c) & 1u)
            put_tri(m, 1, 3, 2);
        break;
    case 7: /* cube, triangulated (closed, valences 4 and 5) */
        m->nv = 8;
        for (int v = 0; v < 8; v++)
            base[v][0] = v & 1, base[v][1] = (v >> 1) & 1, base[v][2] = (v >> 2) & 1;
        {
            static const uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
            uint8_t diag = u8(c);
            for (uint32_t f = 0; f < 6; f++) {
                const uint32_t *a = q[f];
                if ((diag >> f) & 1u)
                    put_tri(m, a[0], a[1], a[2]), put_tri(m, a[0], a[2], a[3]);
                else
                    put_tri(m, a[0], a[1], a[3]), put_tri(m, a[1], a[2], a[3]);
            }
        }
        break;
    default: { /* random face list: often invalid */
        m->nv = 3u + u8(c) % (FZ_MAXV - 2u);
        uint32_t nf = 1u + u8(c) % 12u;
        for (uint32_t v = 0; v < m->nv; v++)
            for (int k = 0; k < 3; k++)
                base[v][k] = s8(c) / 32;
        uint32_t k = 0;
        for (uint32_t f = 0; f < nf; f++) {
            uint8_t sz = u8(c);
            uint32_t n = sz < 24u ? 4u : sz < 28u ? 2u : sz < 30u ? 5u : 3u;
            m->fsize[m->nf++] = n;
            for (uint32_t i = 0; i < n; i++) {
                uint8_t x = u8(c);
                m->idx[k++] = x >= 252u ? m->nv + (x & 3u) : x % m->nv;
            }
        }
        break;
    }
    }
    for (uint32_t v = 0; v < m->nv; v++)
        for (int k = 0; k < 3; k++) {
            uint8_t b = u8(c);
            m->pos[3 * v + (uint32_t)k] = fz_coord(base[v][k], b == 0x7fu ? 0x7fu : (uint8_t)(b & 0x9fu), b == 0x7fu ? u8(c) : 0);
        }
    if (u8(c) & 1u) /* flip one face */
        if (m->nf && m->fsize[0] >= 3) {
            uint32_t tmp = m->idx[0];
            m->idx[0] = m->idx[1];
            m->idx[1] = tmp;
        }
}

