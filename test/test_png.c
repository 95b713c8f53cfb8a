/* SPDX-License-Identifier: MIT */
/* Host-only tests of the PNG writer and the software renderer (port/host/png.c, render.c).
 * The PNG output is checked by an independent minimal reader written here (chunk CRCs with
 * a bitwise CRC-32, zlib header and Adler-32, inflate of stored and fixed-Huffman blocks,
 * all five PNG row filters), never by png.c's own helpers. On the device the table is empty. */
#if defined(SUBD_HOST)
#define _POSIX_C_SOURCE 200809L /* mkstemp, close, unlink */
#endif
#include "harness.h"

#if H_HOST
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "../port/host/render.h"

/* ---------------------------------------------------------------- independent PNG reader */

static uint32_t ref_crc(const uint8_t *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    size_t i;
    int k;
    for (i = 0; i < n; i++) {
        c ^= p[i];
        for (k = 0; k < 8; k++) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

static uint32_t ref_adler(const uint8_t *p, size_t n)
{
    uint32_t a = 1, b = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        a = (a + p[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return (b << 16) | a;
}

static uint32_t be32(const uint8_t *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

typedef struct bitrd {
    const uint8_t *p;
    size_t n, pos; /* pos in bits */
    int err;
} bitrd;

static uint32_t rd_bit(bitrd *r)
{
    uint32_t b;
    if (r->pos >= 8u * r->n) { r->err = 1; return 0; }
    b = (uint32_t)(r->p[r->pos >> 3] >> (r->pos & 7u)) & 1u;
    r->pos++;
    return b;
}

static uint32_t rd_bits(bitrd *r, int n) /* LSB first */
{
    uint32_t v = 0;
    int i;
    for (i = 0; i < n; i++) v |= rd_bit(r) << i;
    return v;
}

static uint32_t rd_huff(bitrd *r, int n) /* MSB first */
{
    uint32_t v = 0;
    int i;
    for (i = 0; i < n; i++) v = (v << 1) | rd_bit(r);
    return v;
}

/* Fixed literal/length alphabet (RFC 1951 3.2.6), decoded bit by bit. */
static int fixed_litlen(bitrd *r)
{
    uint32_t c = rd_huff(r, 7);
    if (c <= 0x17u) return 256 + (int)c;
    c = (c << 1) | rd_bit(r);
    if (c >= 0x30u && c <= 0xBFu) return (int)(c - 0x30u);
    if (c >= 0xC0u && c <= 0xC7u) return 280 + (int)(c - 0xC0u);
    c = (c << 1) | rd_bit(r);
    if (c >= 0x190u && c <= 0x1FFu) return 144 + (int)(c - 0x190u);
    return -1;
}

static const uint16_t t_lbase[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
                                     35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t t_lext[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2,
                                   3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t t_dbase[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193,
                                     257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145,
                                     8193, 12289, 16385, 24577};
static const uint8_t t_dext[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6,
                                   7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/* Inflates a raw deflate stream into out[0..cap); *used = bytes written. Counts the block
 * types seen. Returns 0, or -1 on any malformed or unsupported (dynamic) data. */
static int ref_inflate(const uint8_t *in, size_t n, uint8_t *out, size_t cap, size_t *used,
                       size_t *consumed, unsigned nblocks[3])
{
    bitrd r;
    size_t o = 0;
    uint32_t final;
    r.p = in; r.n = n; r.pos = 0; r.err = 0;
    do {
        uint32_t type;
        final = rd_bit(&r);
        type = rd_bits(&r, 2);
        if (r.err || type > 1u) return -1;
        nblocks[type]++;
        if (type == 0) {
            size_t at, len, nlen;
            r.pos = (r.pos + 7u) & ~(size_t)7u;
            at = r.pos >> 3;
            if (at + 4u > n) return -1;
            len = in[at] | ((size_t)in[at + 1] << 8);
            nlen = in[at + 2] | ((size_t)in[at + 3] << 8);
            if ((len ^ 0xFFFFu) != nlen || at + 4u + len > n || o + len > cap) return -1;
            memcpy(out + o, in + at + 4, len);
            o += len;
            r.pos = 8u * (at + 4u + len);
        } else {
            for (;;) {
                int s = fixed_litlen(&r);
                if (r.err || s < 0) return -1;
                if (s < 256) {
                    if (o >= cap) return -1;
                    out[o++] = (uint8_t)s;
                } else if (s == 256) {
                    break;
                } else {
                    uint32_t len, dist, ds, k;
                    if (s > 285) return -1;
                    len = t_lbase[s - 257] + rd_bits(&r, t_lext[s - 257]);
                    ds = rd_huff(&r, 5);
                    if (ds > 29u) return -1;
                    dist = t_dbase[ds] + rd_bits(&r, t_dext[ds]);
                    if (r.err || dist > o || dist > 32768u || o + len > cap) return -1;
                    for (k = 0; k < len; k++, o++) out[o] = out[o - dist];
                }
            }
        }
    } while (!final);
    *used = o;
    *consumed = (r.pos + 7u) >> 3;
    return 0;
}

static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    if (pa <= pb && pa <= pc) return a;
    return pb <= pc ? b : c;
}

typedef struct decoded {
    int w, h;
    uint8_t *rgb;
    unsigned nblocks[3]; /* stored, fixed, dynamic */
    size_t idat_bytes;
} decoded;

/* Independent decoder for 8-bit RGB, non-interlaced PNG. Returns 0 or a negative step. */
static int ref_decode(const uint8_t *png, size_t n, decoded *d)
{
    static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    uint8_t *z = 0, *raw = 0;
    size_t zn = 0, pos = 8, rawn = 0, used = 0, consumed = 0, stride, x, y;
    int seen_ihdr = 0, seen_iend = 0, rc = 0;
    memset(d, 0, sizeof *d);
    if (n < 8 || memcmp(png, sig, 8) != 0) return -1;
    while (pos < n && !seen_iend) {
        uint32_t len;
        const uint8_t *type, *data;
        if (n - pos < 12u) { rc = -2; goto out; }
        len = be32(png + pos);
        if (len > n - pos - 12u) { rc = -2; goto out; }
        type = png + pos + 4;
        data = type + 4;
        if (ref_crc(type, (size_t)len + 4u) != be32(data + len)) { rc = -3; goto out; }
        if (!seen_ihdr && memcmp(type, "IHDR", 4) != 0) { rc = -4; goto out; }
        if (memcmp(type, "IHDR", 4) == 0) {
            if (seen_ihdr || len != 13) { rc = -4; goto out; }
            d->w = (int)be32(data);
            d->h = (int)be32(data + 4);
            if (d->w <= 0 || d->h <= 0 || d->w > 20000 || d->h > 20000) { rc = -4; goto out; }
            if (data[8] != 8 || data[9] != 2 || data[10] || data[11] || data[12]) { rc = -4; goto out; }
            seen_ihdr = 1;
        } else if (memcmp(type, "IDAT", 4) == 0) {
            uint8_t *q = (uint8_t *)realloc(z, zn + len + 1u);
            if (!q) { rc = -5; goto out; }
            z = q;
            memcpy(z + zn, data, len);
            zn += len;
        } else if (memcmp(type, "IEND", 4) == 0) {
            if (len != 0) { rc = -4; goto out; }
            seen_iend = 1;
        } else if (!(type[0] & 0x20u)) {
            rc = -4; /* unknown critical chunk */
            goto out;
        }
        pos += 12u + len;
    }
    if (!seen_iend || pos != n || !z) { rc = -6; goto out; }
    d->idat_bytes = zn;
    /* zlib: CM 8, window <= 32K, no dictionary, check bits, Adler-32 trailer */
    if (zn < 6 || (z[0] & 15u) != 8u || (z[0] >> 4) > 7u || (z[1] & 0x20u) ||
        ((unsigned)z[0] * 256u + z[1]) % 31u != 0u) { rc = -7; goto out; }
    stride = (size_t)d->w * 3u;
    rawn = (stride + 1u) * (size_t)d->h;
    raw = (uint8_t *)malloc(rawn);
    d->rgb = (uint8_t *)malloc(stride * (size_t)d->h);
    if (!raw || !d->rgb) { rc = -5; goto out; }
    if (ref_inflate(z + 2, zn - 2u, raw, rawn, &used, &consumed, d->nblocks) != 0) { rc = -8; goto out; }
    if (used != rawn || 2u + consumed + 4u != zn) { rc = -9; goto out; }
    if (be32(z + zn - 4) != ref_adler(raw, rawn)) { rc = -10; goto out; }
    for (y = 0; y < (size_t)d->h; y++) {
        const uint8_t *src = raw + y * (stride + 1u) + 1;
        uint8_t ft = raw[y * (stride + 1u)];
        uint8_t *row = d->rgb + y * stride;
        const uint8_t *up = y ? row - stride : 0;
        if (ft > 4) { rc = -11; goto out; }
        for (x = 0; x < stride; x++) {
            int a = x >= 3 ? row[x - 3] : 0, b = up ? up[x] : 0, c = (up && x >= 3) ? up[x - 3] : 0;
            int pred = ft == 0 ? 0 : ft == 1 ? a : ft == 2 ? b : ft == 3 ? (a + b) / 2 : paeth(a, b, c);
            row[x] = (uint8_t)(src[x] + pred);
        }
    }
out:
    free(z);
    free(raw);
    if (rc != 0) { free(d->rgb); d->rgb = 0; }
    return rc;
}

/* Encodes, decodes independently, compares. Returns the decoded info (rgb freed). */
static decoded roundtrip(const uint8_t *rgb, int w, int h)
{
    uint8_t *png = 0;
    uint32_t len = 0;
    decoded d;
    memset(&d, 0, sizeof d);
    if (!CHECK_EQ(png_encode_rgb(rgb, w, h, &png, &len), 0)) return d;
    CHECK(png != 0 && len > 8u + 25u + 12u + 12u);
    if (CHECK_EQ(ref_decode(png, len, &d), 0)) {
        CHECK_EQ(d.w, w);
        CHECK_EQ(d.h, h);
        CHECK(memcmp(d.rgb, rgb, (size_t)w * (size_t)h * 3u) == 0);
    }
    free(png);
    free(d.rgb);
    d.rgb = 0;
    return d;
}

/* ---------------------------------------------------------------- checksums */

static void t_crc32_check_value(void)
{
    const uint8_t *s = (const uint8_t *)"123456789";
    uint8_t big[3000];
    uint32_t i;
    CHECK_EQ(png_crc32(s, 9), 0xCBF43926u);
    CHECK_EQ(png_crc32(s, 0), 0u);
    CHECK_EQ(png_crc32((const uint8_t *)"IEND", 4), 0xAE426082u); /* every PNG's last CRC */
    for (i = 0; i < sizeof big; i++) big[i] = (uint8_t)(i * 7u + (i >> 5));
    CHECK_EQ(png_crc32(big, sizeof big), ref_crc(big, sizeof big));
}

static void t_adler32_check_value(void)
{
    uint8_t *big;
    uint32_t i, n = 300000u;
    CHECK_EQ(png_adler32((const uint8_t *)"Wikipedia", 9), 0x11E60398u);
    CHECK_EQ(png_adler32((const uint8_t *)"", 0), 1u);
    /* Long runs of 0xFF exercise the deferred modulo (overflow bound 5552). */
    big = (uint8_t *)malloc(n);
    if (!CHECK(big != 0)) return;
    memset(big, 0xFF, n);
    CHECK_EQ(png_adler32(big, n), ref_adler(big, n));
    for (i = 0; i < n; i++) big[i] = (uint8_t)(i * 2654435761u >> 24);
    CHECK_EQ(png_adler32(big, n), ref_adler(big, n));
    free(big);
}

/* ---------------------------------------------------------------- PNG encoder */

static void t_png_layout(void)
{
    static const uint8_t px[6] = {255, 0, 0, 0, 0, 255}; /* 2 x 1: red, blue */
    uint8_t *png = 0;
    uint32_t len = 0;
    if (!CHECK_EQ(png_encode_rgb(px, 2, 1, &png, &len), 0)) return;
    CHECK(len >= 8u + 25u + 12u + 12u);
    CHECK(png[0] == 0x89 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G');
    CHECK_EQ(be32(png + 8), 13u);
    CHECK(memcmp(png + 12, "IHDR", 4) == 0);
    CHECK_EQ(be32(png + 16), 2u);
    CHECK_EQ(be32(png + 20), 1u);
    CHECK_EQ(png[24], 8);
    CHECK_EQ(png[25], 2);
    CHECK(memcmp(png + 37, "IDAT", 4) == 0);
    CHECK(memcmp(png + len - 8u, "IEND", 4) == 0);
    CHECK_EQ(be32(png + len - 4u), 0xAE426082u);
    free(png);
    roundtrip(px, 2, 1);
}

static void t_png_roundtrip_small(void)
{
    uint8_t img[7 * 5 * 3];
    uint32_t i;
    for (i = 0; i < sizeof img; i++) img[i] = (uint8_t)(i * 37u + 11u);
    roundtrip(img, 7, 5);
    roundtrip(img, 1, 1);
    roundtrip(img, 35, 1);
    roundtrip(img, 1, 35);
}

static void t_png_roundtrip_flat_compresses(void)
{
    int w = 320, h = 240, x, y;
    uint8_t *img = (uint8_t *)malloc((size_t)w * (size_t)h * 3u);
    decoded d;
    if (!CHECK(img != 0)) return;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            uint8_t *p = img + ((size_t)y * (size_t)w + (size_t)x) * 3u;
            int in = (x - 160) * (x - 160) + (y - 120) * (y - 120) < 80 * 80;
            p[0] = in ? 90 : 242;
            p[1] = in ? 120 : 242;
            p[2] = in ? (uint8_t)(150 + y / 4) : 240;
        }
    d = roundtrip(img, w, h);
    CHECK(d.nblocks[1] >= 1u);               /* compressed (fixed Huffman) */
    CHECK(d.idat_bytes * 20u < (size_t)w * (size_t)h * 3u); /* at least 20:1 */
    free(img);
}

static void t_png_roundtrip_noise_stored(void)
{
    /* Incompressible data: falls back to stored blocks, several of them (> 65535 bytes). */
    int w = 300, h = 200;
    size_t n = (size_t)w * (size_t)h * 3u, i;
    uint32_t st = 12345u;
    uint8_t *img = (uint8_t *)malloc(n);
    decoded d;
    if (!CHECK(img != 0)) return;
    for (i = 0; i < n; i++) img[i] = (uint8_t)(h_rand(&st) >> 24);
    d = roundtrip(img, w, h);
    CHECK(d.nblocks[0] >= 3u);
    CHECK(d.idat_bytes <= n + (size_t)h + 64u);
    free(img);
}

static void t_png_roundtrip_patterns(void)
{
    /* Long-distance repeats (rows repeating every 5 rows), short runs, gradients. */
    int w = 211, h = 97, x, y;
    uint8_t *img = (uint8_t *)malloc((size_t)w * (size_t)h * 3u);
    if (!CHECK(img != 0)) return;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            uint8_t *p = img + ((size_t)y * (size_t)w + (size_t)x) * 3u;
            p[0] = (uint8_t)(((x / 3) ^ (y % 5)) * 40);
            p[1] = (uint8_t)(x & 1 ? 255 : 0);
            p[2] = (uint8_t)(x + 2 * (y % 5));
        }
    roundtrip(img, w, h);
    free(img);
}

static void t_png_bad_args(void)
{
    uint8_t px[3] = {1, 2, 3}, *png = (uint8_t *)px;
    uint32_t len = 99;
    CHECK_EQ(png_encode_rgb(px, 0, 1, &png, &len), -1);
    CHECK(png == 0 && len == 0);
    CHECK_EQ(png_encode_rgb(px, 1, -3, &png, &len), -1);
    CHECK_EQ(png_encode_rgb(0, 1, 1, &png, &len), -1);
    CHECK_EQ(png_encode_rgb(px, 1, 1, 0, &len), -1);
    CHECK_EQ(png_encode_rgb(px, 1 << 20, 1 << 20, &png, &len), -1); /* too large */
}

/* ---------------------------------------------------------------- renderer */

#define RW 160
#define M_PI_ 3.14159265358979323846
#define RH 120

static const double cube_pos[8 * 3] = {
    -1, -1, -1,  1, -1, -1,  1, 1, -1,  -1, 1, -1,
    -1, -1, 1,   1, -1, 1,   1, 1, 1,   -1, 1, 1};
static const uint32_t cube_fs[7] = {0, 4, 8, 12, 16, 20, 24};
static const uint32_t cube_cv[24] = {0, 3, 2, 1,  4, 5, 6, 7,  0, 1, 5, 4,
                                     2, 3, 7, 6,  1, 2, 6, 5,  0, 4, 7, 3};

static render_mesh mk_mesh(const double *pos, uint32_t nv, const uint32_t *fs, const uint32_t *cv, uint32_t nf)
{
    render_mesh m;
    memset(&m, 0, sizeof m);
    m.num_verts = nv;
    m.pos = pos;
    m.num_faces = nf;
    m.face_start = fs;
    m.corner_vert = cv;
    return m;
}

static render_opts mk_opts(double yaw, double pitch, int edges)
{
    render_opts o;
    render_opts_default(&o);
    o.width = RW;
    o.height = RH;
    o.yaw_deg = yaw;
    o.pitch_deg = pitch;
    o.edges = edges;
    return o;
}

/* Renders; returns the image (caller frees) or 0 after a failed check. */
static uint8_t *rend(const render_mesh *m, const render_opts *o)
{
    uint8_t *img = 0;
    int w = 0, h = 0;
    if (!CHECK_EQ(render_rgb(m, o, &img, &w, &h), 0)) return 0;
    if (!CHECK(img != 0 && w == RW && h == RH)) { free(img); return 0; }
    return img;
}

static const uint8_t *pix(const uint8_t *img, int x, int y)
{
    return img + ((size_t)y * RW + (size_t)x) * 3u;
}

static uint8_t g_bg[3];
static int g_bg_ready;

/* The background colour is whatever an empty mesh renders to (not hard-coded here). */
static int is_bg(const uint8_t *p)
{
    if (!g_bg_ready) {
        uint8_t *img = 0;
        int w = 0, h = 0;
        if (render_rgb(0, 0, &img, &w, &h) == 0 && img) memcpy(g_bg, img, 3);
        free(img);
        g_bg_ready = 1;
    }
    return p[0] == g_bg[0] && p[1] == g_bg[1] && p[2] == g_bg[2];
}

static uint32_t count_non_bg(const uint8_t *img)
{
    uint32_t n = 0;
    int x, y;
    for (y = 0; y < RH; y++)
        for (x = 0; x < RW; x++) n += !is_bg(pix(img, x, y));
    return n;
}

static uint32_t count_dark(const uint8_t *img) /* edge / line pixels; faces are brighter */
{
    uint32_t n = 0;
    int x, y;
    for (y = 0; y < RH; y++)
        for (x = 0; x < RW; x++) {
            const uint8_t *p = pix(img, x, y);
            n += p[0] < 70 && p[1] < 70 && p[2] < 70;
        }
    return n;
}

static int corners_bg(const uint8_t *img)
{
    return is_bg(pix(img, 0, 0)) && is_bg(pix(img, RW - 1, 0)) && is_bg(pix(img, 0, RH - 1)) &&
           is_bg(pix(img, RW - 1, RH - 1));
}

static void t_render_empty(void)
{
    render_mesh m = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 0);
    render_opts o = mk_opts(30, 20, 1);
    uint8_t *img = rend(&m, &o);
    int x, y, uniform = 1;
    if (!img) return;
    (void)is_bg(img);
    CHECK(g_bg[0] > 200 && g_bg[1] > 200 && g_bg[2] > 200); /* light background */
    for (y = 0; y < RH; y++)
        for (x = 0; x < RW; x++) uniform &= is_bg(pix(img, x, y));
    CHECK(uniform);
    free(img);
    /* No mesh at all, no options: default size, still all background. */
    {
        uint8_t *im2 = 0;
        int w = 0, h = 0;
        size_t i;
        CHECK_EQ(render_rgb(0, 0, &im2, &w, &h), 0);
        CHECK_EQ(w, 800);
        CHECK_EQ(h, 600);
        if (im2) {
            for (i = 0; i < (size_t)w * (size_t)h; i++) uniform &= memcmp(im2 + 3 * i, g_bg, 3) == 0;
            CHECK(uniform);
        }
        free(im2);
    }
    CHECK_EQ(render_rgb(0, 0, 0, 0, 0), -1);
}

static void t_render_cube(void)
{
    render_mesh m = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    render_opts o = mk_opts(30, 20, 1);
    uint8_t *img = rend(&m, &o), *again, *noedge;
    uint32_t area, dark;
    if (!img) return;
    area = count_non_bg(img);
    dark = count_dark(img);
    CHECK(area > 0);
    CHECK(!is_bg(pix(img, RW / 2, RH / 2)));
    CHECK(corners_bg(img));
    /* Framed with a ~5% margin: silhouette spans most of the height, within a plausible
     * fraction of the picture (a hexagon inside the 90% box). */
    CHECK(area > (uint32_t)(RW * RH) / 5u);
    CHECK(area < (uint32_t)(RW * RH) * 4u / 5u);
    {
        int y, top = -1, bot = -1;
        for (y = 0; y < RH; y++) {
            int x, any = 0;
            for (x = 0; x < RW; x++) any |= !is_bg(pix(img, x, y));
            if (any && top < 0) top = y;
            if (any) bot = y;
        }
        CHECK(top >= 2 && top <= RH / 10 + 2);
        CHECK(bot >= RH - RH / 10 - 3 && bot <= RH - 3);
    }
    CHECK(dark > 100u); /* visible edges: 9 of them, ~40 px each */
    again = rend(&m, &o);
    if (again) CHECK(memcmp(img, again, (size_t)RW * RH * 3u) == 0); /* deterministic */
    free(again);
    o.edges = 0;
    noedge = rend(&m, &o);
    if (noedge) {
        CHECK_EQ(count_dark(noedge), 0);
        /* Edges lie on the surface; silhouette edges may straddle the outline by a pixel. */
        uint32_t a2 = count_non_bg(noedge);
        CHECK(a2 <= area && (area - a2) * 20u < area);
    }
    free(noedge);
    free(img);
}

static void t_render_cube_hidden_edges(void)
{
    /* Straight on (yaw 0, pitch 0) only the front face is visible: its 4 edges lie on the
     * silhouette; the back face's edges coincide in projection, and the 4 depth edges are
     * seen end-on. Nothing dark may appear strictly inside the front face. */
    render_mesh m = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    render_opts o = mk_opts(0, 0, 1);
    uint8_t *img = rend(&m, &o);
    int x, y, inner_dark = 0, inner_px = 0;
    if (!img) return;
    for (y = RH / 2 - 40; y < RH / 2 + 40; y++)
        for (x = RW / 2 - 40; x < RW / 2 + 40; x++) {
            const uint8_t *p = pix(img, x, y);
            inner_px += !is_bg(p);
            inner_dark += p[0] < 70 && p[1] < 70 && p[2] < 70;
        }
    CHECK_EQ(inner_px, 80 * 80);
    CHECK_EQ(inner_dark, 0);
    free(img);

    /* Tilted view: find the cube corner farthest from the viewer with an own copy of the
     * view transform and framing; the 3 edges meeting there are hidden, so a 9x9 window
     * around its image holds no dark pixel (visible edges are > 20 px away). */
    o = mk_opts(30, 20, 1);
    img = rend(&m, &o);
    if (img) {
        double vx[8], vy[8], vz[8], x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9, s, sx, sy;
        double cy = cos(30.0 * M_PI_ / 180.0), sny = sin(30.0 * M_PI_ / 180.0);
        double cp = cos(20.0 * M_PI_ / 180.0), snp = sin(20.0 * M_PI_ / 180.0);
        int k, far = 0, px, py, dark = 0, face_px = 0;
        for (k = 0; k < 8; k++) {
            const double *q = cube_pos + 3 * k;
            double xr = cy * q[0] + sny * q[2], zr = -sny * q[0] + cy * q[2];
            vx[k] = xr;
            vy[k] = cp * q[1] - snp * zr;
            vz[k] = snp * q[1] + cp * zr;
            if (vz[k] < vz[far]) far = k;
            x0 = fmin(x0, vx[k]); x1 = fmax(x1, vx[k]);
            y0 = fmin(y0, vy[k]); y1 = fmax(y1, vy[k]);
        }
        s = fmin(0.9 * RW / (x1 - x0), 0.9 * RH / (y1 - y0));
        sx = 0.5 * RW + (vx[far] - 0.5 * (x0 + x1)) * s;
        sy = 0.5 * RH - (vy[far] - 0.5 * (y0 + y1)) * s;
        for (py = (int)sy - 4; py <= (int)sy + 4; py++)
            for (px = (int)sx - 4; px <= (int)sx + 4; px++) {
                const uint8_t *p;
                if (!CHECK(px >= 0 && py >= 0 && px < RW && py < RH)) continue;
                p = pix(img, px, py);
                face_px += !is_bg(p);
                dark += p[0] < 70 && p[1] < 70 && p[2] < 70;
            }
        CHECK_EQ(face_px, 81);
        CHECK_EQ(dark, 0);
    }
    free(img);
}

static void t_render_tetra_and_tints(void)
{
    static const double tet[4 * 3] = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
    static const uint32_t fs[5] = {0, 3, 6, 9, 12};
    static const uint32_t cv[12] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    static const double tri[3 * 3] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    static const uint32_t tfs[2] = {0, 3};
    static const uint32_t tcv[3] = {0, 1, 2};
    render_mesh m = mk_mesh(tet, 4, fs, cv, 4);
    render_opts o = mk_opts(30, 20, 1);
    uint8_t *img = rend(&m, &o);
    if (img) {
        uint32_t area = count_non_bg(img);
        CHECK(!is_bg(pix(img, RW / 2, RH / 2)));
        CHECK(corners_bg(img));
        CHECK(area > (uint32_t)(RW * RH) / 8u && area < (uint32_t)(RW * RH) * 3u / 4u);
        CHECK(count_dark(img) > 50u);
    }
    free(img);
    /* A single CCW triangle seen from the front, then from behind: different tints
     * (front cool, back warm), neither black nor background. */
    m = mk_mesh(tri, 3, tfs, tcv, 1);
    o = mk_opts(0, 0, 0);
    img = rend(&m, &o);
    if (img) {
        const uint8_t *p = pix(img, RW / 2, RH / 2 + 10);
        CHECK(!is_bg(p));
        CHECK(p[2] > p[0]);
        CHECK(p[0] + p[1] + p[2] > 150);
    }
    free(img);
    o = mk_opts(180, 0, 0);
    img = rend(&m, &o);
    if (img) {
        const uint8_t *p = pix(img, RW / 2, RH / 2 + 10);
        CHECK(!is_bg(p));
        CHECK(p[0] > p[2]);
        CHECK(p[0] + p[1] + p[2] > 150);
    }
    free(img);
}

static void t_render_nan_and_bad_indices(void)
{
    double pos[8 * 3];
    uint32_t cv[24], i;
    render_mesh m;
    render_opts o = mk_opts(30, 20, 1);
    uint8_t *img, *ref;
    memcpy(pos, cube_pos, sizeof pos);
    memcpy(cv, cube_cv, sizeof cv);
    /* One NaN vertex: the 3 faces using it are skipped, the rest still drawn. */
    pos[3 * 6 + 1] = (double)NAN;
    m = mk_mesh(pos, 8, cube_fs, cube_cv, 6);
    img = rend(&m, &o);
    if (img) {
        CHECK(count_non_bg(img) > 0u);
        CHECK(corners_bg(img));
    }
    free(img);
    /* All NaN / infinite: nothing drawable, plain background. */
    for (i = 0; i < 24; i++) pos[i] = (i & 1u) ? (double)NAN : (double)INFINITY;
    img = rend(&m, &o);
    if (img) CHECK_EQ(count_non_bg(img), 0);
    free(img);
    /* Out-of-range vertex index and a reversed face range: those faces are skipped, and the
     * picture equals the one without them (framing ignores unreferenced vertices). */
    {
        static const uint32_t fs_bad[9] = {0, 4, 8, 12, 16, 20, 24, 28, 27};
        uint32_t cvb[28];
        memcpy(cvb, cube_cv, sizeof cube_cv);
        cvb[24] = 0; cvb[25] = 1; cvb[26] = 99; cvb[27] = 2;
        m = mk_mesh(cube_pos, 8, fs_bad, cvb, 8);
        img = rend(&m, &o);
        m = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
        ref = rend(&m, &o);
        if (img && ref) CHECK(memcmp(img, ref, (size_t)RW * RH * 3u) == 0);
        free(img);
        free(ref);
    }
    /* Non-finite view angles fall back to the defaults. */
    m = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    o.yaw_deg = (double)NAN;
    o.pitch_deg = (double)INFINITY;
    img = rend(&m, &o);
    o = mk_opts(30, 20, 1);
    ref = rend(&m, &o);
    if (img && ref) CHECK(memcmp(img, ref, (size_t)RW * RH * 3u) == 0);
    free(img);
    free(ref);
}

static void t_render_degenerate_extent(void)
{
    static const double same[4 * 3] = {3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3};
    static const uint32_t fs[3] = {0, 3, 7};
    static const uint32_t cv[7] = {0, 1, 2, 0, 1, 2, 3};
    static const double flat[4 * 3] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0}; /* collinear */
    render_mesh m = mk_mesh(same, 4, fs, cv, 2);
    render_opts o = mk_opts(30, 20, 1);
    uint8_t *img = rend(&m, &o);
    if (img) CHECK(corners_bg(img));
    free(img);
    m = mk_mesh(flat, 4, fs, cv, 2);
    img = rend(&m, &o);
    if (img) {
        CHECK(corners_bg(img));
        CHECK(count_dark(img) > 0u); /* the edges of the zero-area faces form a line */
    }
    free(img);
}

static void t_render_huge_coordinates(void)
{
    double pos[8 * 3];
    uint32_t i, a0 = 0;
    render_mesh m;
    render_opts o = mk_opts(30, 20, 1);
    uint8_t *ref, *img;
    m = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    ref = rend(&m, &o);
    if (!ref) return;
    a0 = count_non_bg(ref);
    /* Exact scaling by a power of two, and to the very top of the double range: the
     * normalisation makes both pictures identical to the unit cube's. */
    for (i = 0; i < 24; i++) pos[i] = ldexp(cube_pos[i], 1000);
    m = mk_mesh(pos, 8, cube_fs, cube_cv, 6);
    img = rend(&m, &o);
    if (img) CHECK(memcmp(img, ref, (size_t)RW * RH * 3u) == 0);
    free(img);
    for (i = 0; i < 24; i++) pos[i] = cube_pos[i] * 1.7e308;
    img = rend(&m, &o);
    if (img) CHECK(memcmp(img, ref, (size_t)RW * RH * 3u) == 0);
    free(img);
    /* A small cube far from the origin: still framed, same silhouette size (+-5%). */
    for (i = 0; i < 24; i++) pos[i] = 1e12 + cube_pos[i] * 1e3;
    img = rend(&m, &o);
    if (img) {
        uint32_t a = count_non_bg(img);
        CHECK(a * 20u > a0 * 19u && a * 20u < a0 * 21u);
        CHECK(corners_bg(img));
    }
    free(img);
    free(ref);
}

static void t_render_polylines(void)
{
    static const double pos[4 * 3] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 5, 5, 5};
    static const uint32_t ls[3] = {0, 3, 3}; /* one polyline, one empty */
    static const uint32_t lv[3] = {0, 1, 2};
    render_mesh m;
    render_opts o = mk_opts(0, 0, 1);
    uint8_t *img;
    memset(&m, 0, sizeof m);
    m.num_verts = 4;
    m.pos = pos;
    m.num_lines = 2;
    m.line_start = ls;
    m.line_vert = lv;
    img = rend(&m, &o);
    if (img) {
        uint32_t dark = count_dark(img), n = count_non_bg(img);
        CHECK(n > 200u);           /* 2 px lines across most of the frame */
        CHECK(dark > 0u);          /* vertex dots */
        CHECK(n < (uint32_t)(RW * RH) / 4u);
        CHECK(corners_bg(img));
        CHECK(is_bg(pix(img, RW / 4, RH / 4))); /* off the lines: background */
    }
    free(img);
}

static void t_render_png_file(void)
{
    char path[] = "/tmp/tinysubd_png_XXXXXX";
    render_mesh m = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    render_opts o = mk_opts(30, 20, 1);
    uint8_t *img = rend(&m, &o), *buf = 0;
    int fd = mkstemp(path);
    long n;
    FILE *f;
    decoded d;
    if (!CHECK(fd >= 0) || !img) { free(img); return; }
    close(fd);
    CHECK_EQ(render_png_file(path, &m, &o), 0);
    f = fopen(path, "rb");
    if (CHECK(f != 0)) {
        fseek(f, 0, SEEK_END);
        n = ftell(f);
        fseek(f, 0, SEEK_SET);
        buf = (uint8_t *)malloc(n > 0 ? (size_t)n : 1u);
        if (CHECK(buf != 0 && n > 0) && CHECK(fread(buf, 1, (size_t)n, f) == (size_t)n)) {
            if (CHECK_EQ(ref_decode(buf, (size_t)n, &d), 0)) {
                CHECK(d.w == RW && d.h == RH);
                CHECK(memcmp(d.rgb, img, (size_t)RW * RH * 3u) == 0);
                free(d.rgb);
            }
        }
        fclose(f);
    }
    unlink(path);
    free(buf);
    free(img);
    errno = 0;
    CHECK_EQ(render_png_file("/nonexistent-dir-tinysubd/x.png", &m, &o), -1);
    CHECK(errno != 0);
}

/* ---- pictures that show input and result (render_opts.input, labels, auto edges) ---- */

static int is_input_col(const uint8_t *p)
{
    return p[0] == RENDER_INPUT_R && p[1] == RENDER_INPUT_G && p[2] == RENDER_INPUT_B;
}

/* An input-coloured pixel within 1 px of (x, y). */
static int input_near(const uint8_t *img, int x, int y)
{
    int i, j;
    for (j = -1; j <= 1; j++)
        for (i = -1; i <= 1; i++)
            if (x + i >= 0 && y + j >= 0 && x + i < RW && y + j < RH && is_input_col(pix(img, x + i, y + j)))
                return 1;
    return 0;
}

static uint32_t count_input_col(const uint8_t *img)
{
    uint32_t n = 0;
    int x, y;
    for (y = 0; y < RH; y++)
        for (x = 0; x < RW; x++) n += is_input_col(pix(img, x, y));
    return n;
}

/* The cube scaled by k. */
static void scaled_cube(double k, double *pos)
{
    int i;
    for (i = 0; i < 24; i++) pos[i] = k * cube_pos[i];
}

/* Looking down -z (yaw 0, pitch 0), both meshes are framed together: the union's extent is
 * the larger cube's [-1, 1]^2, so scale = min(0.9 RW, 0.9 RH) / 2 and the centre is the
 * picture's; a point (x, y) lands at (RW/2 + s x, RH/2 - s y). The input (the unit cube)
 * around a half-size result: its outline's edge midpoints are input-coloured, the result's
 * own area is not covered, and without the input none of those pixels is. */
static void t_render_input_overlay(void)
{
    double small[24];
    render_mesh res, in = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    render_opts o = mk_opts(0, 0, 1);
    double sc = fmin(0.9 * RW, 0.9 * RH) / 2.0;
    const double mid[4][2] = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};
    uint8_t *img, *plain;
    int k;
    scaled_cube(0.5, small);
    res = mk_mesh(small, 8, cube_fs, cube_cv, 6);
    o.input = &in;
    img = rend(&res, &o);
    o.input = 0;
    plain = rend(&res, &o);
    if (img && plain) {
        for (k = 0; k < 4; k++) {
            int x = (int)floor(RW / 2.0 + sc * mid[k][0]), y = (int)floor(RH / 2.0 - sc * mid[k][1]);
            CHECK(input_near(img, x, y));
            CHECK(!input_near(plain, x, y));
        }
        CHECK_EQ(count_input_col(plain), 0);
        /* the result's face centre shows the result, not the input */
        CHECK(!is_input_col(pix(img, RW / 2 + (int)(0.25 * sc), RH / 2 + (int)(0.25 * sc))));
        CHECK(memcmp(img, plain, (size_t)RW * RH * 3u) != 0);
    }
    free(img);
    free(plain);
}

/* The input inside the result (a pia-like picture): its lines are hidden, so they are
 * dashed: along the input's lower outline edge (y = -1/2), in the middle of the edge, some
 * columns have the input colour and some do not. And the picture differs from the one with
 * the roles swapped (limit-like), which the demo's two icosahedron pictures rely on. */
static void t_render_input_hidden_dashed(void)
{
    double small[24];
    render_mesh big = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6), in;
    render_opts o = mk_opts(0, 0, 1);
    double sc = fmin(0.9 * RW, 0.9 * RH) / 2.0;
    uint8_t *img, *swapped;
    int x, y = (int)floor(RH / 2.0 + 0.5 * sc), on = 0, cols = 0;
    scaled_cube(0.5, small);
    in = mk_mesh(small, 8, cube_fs, cube_cv, 6);
    o.input = &in;
    img = rend(&big, &o);
    o.input = &big;
    swapped = rend(&in, &o);
    if (img && swapped) {
        for (x = (int)(RW / 2.0 - 0.4 * sc); x <= (int)(RW / 2.0 + 0.4 * sc); x++, cols++) {
            int j, hit = 0;
            for (j = -1; j <= 1; j++) hit |= is_input_col(pix(img, x, y + j));
            on += hit;
        }
        CHECK(cols > 20);
        CHECK(on * 4 > cols);     /* drawn ...            */
        CHECK(on * 4 < 3 * cols); /* ... but dashed       */
        CHECK(memcmp(img, swapped, (size_t)RW * RH * 3u) != 0);
    }
    free(img);
    free(swapped);
}

/* An n x n grid of quads over [-1, 1]^2 in the z = 0 plane. */
static render_mesh grid_mesh(uint32_t n, double *pos, uint32_t *fs, uint32_t *cv)
{
    uint32_t i, j, f = 0;
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++) {
            double *p = pos + 3u * (j * (n + 1u) + i);
            p[0] = -1.0 + 2.0 * (double)i / (double)n;
            p[1] = -1.0 + 2.0 * (double)j / (double)n;
            p[2] = 0.0;
        }
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++, f++) {
            uint32_t v = j * (n + 1u) + i;
            fs[f] = 4u * f;
            cv[4u * f] = v;
            cv[4u * f + 1u] = v + 1u;
            cv[4u * f + 2u] = v + n + 2u;
            cv[4u * f + 3u] = v + n + 1u;
        }
    fs[f] = 4u * f;
    return mk_mesh(pos, (n + 1u) * (n + 1u), fs, cv, n * n);
}

/* Auto edges: the mean projected edge of an n x n grid seen face on is 2 s / n pixels
 * (closed form); edges are drawn exactly when that is at least RENDER_DENSE_PX, and --edges
 * (1) and --no-edges (0) override. */
static void t_render_auto_edges(void)
{
    static double pos[3 * 41 * 41];
    static uint32_t fs[40 * 40 + 1], cv[4 * 40 * 40];
    static const uint32_t ns[] = {4, 16, 17, 18, 19, 40};
    double sc = fmin(0.9 * RW, 0.9 * RH) / 2.0;
    size_t t;
    for (t = 0; t < sizeof ns / sizeof ns[0]; t++) {
        uint32_t n = ns[t];
        render_mesh m = grid_mesh(n, pos, fs, cv);
        render_opts o = mk_opts(0, 0, RENDER_EDGES_AUTO);
        render_info info;
        uint8_t *img = 0;
        int w = 0, h = 0;
        double expect = 2.0 * sc / (double)n;
        if (!CHECK_EQ(render_rgb_info(&m, &o, &img, &w, &h, &info), 0)) continue;
        CHECK(fabs(info.mean_edge_px - expect) < 1e-9);
        CHECK_EQ(info.edges_drawn, expect >= RENDER_DENSE_PX);
        CHECK_EQ(count_dark(img) > 0u, expect >= RENDER_DENSE_PX);
        free(img);
        o.edges = 1;
        img = 0;
        if (CHECK_EQ(render_rgb_info(&m, &o, &img, &w, &h, &info), 0)) {
            CHECK_EQ(info.edges_drawn, 1);
            CHECK(count_dark(img) > 0u);
        }
        free(img);
        o.edges = 0;
        img = 0;
        if (CHECK_EQ(render_rgb_info(&m, &o, &img, &w, &h, &info), 0)) {
            CHECK_EQ(info.edges_drawn, 0);
            CHECK_EQ(count_dark(img), 0);
        }
        free(img);
    }
    /* the threshold falls between the n tried: both sides were seen */
    CHECK(2.0 * sc / 17.0 >= RENDER_DENSE_PX && 2.0 * sc / 19.0 < RENDER_DENSE_PX);
}

/* A dense input (mean projected edge under RENDER_INPUT_DENSE_PX) goes beside the result:
 * a grey separator down the middle, shaded pixels in both halves, and no input-coloured
 * lines. A coarse input stays an overlay (input-coloured pixels, no separator). */
static void t_render_input_side_by_side(void)
{
    static double pos[3 * 41 * 41];
    static uint32_t fs[40 * 40 + 1], cv[4 * 40 * 40];
    render_mesh dense = grid_mesh(40, pos, fs, cv), cube = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    render_opts o = mk_opts(30, 20, RENDER_EDGES_AUTO);
    uint8_t *img;
    int y, sep = 1, left = 0, right = 0, x;
    o.input = &dense;
    img = rend(&cube, &o);
    if (img) {
        for (y = 0; y < RH; y++) {
            const uint8_t *p = pix(img, RW / 2, y);
            sep &= p[0] == 150 && p[1] == 150 && p[2] == 150;
        }
        CHECK(sep);
        for (y = 0; y < RH; y++)
            for (x = 0; x < RW; x++)
                if (!is_bg(pix(img, x, y)) && x != RW / 2 && x != RW / 2 - 1) {
                    if (x < RW / 2) left++;
                    else right++;
                }
        CHECK(left > 500 && right > 500);
        CHECK_EQ(count_input_col(img), 0);
    }
    free(img);
    o.input = &cube;
    img = rend(&dense, &o);
    if (img) {
        CHECK(count_input_col(img) > 100u);
        CHECK(!(pix(img, RW / 2, 0)[0] == 150 && pix(img, RW / 2, RH - 1)[0] == 150));
    }
    free(img);
}

/* Captions: the result's in dark grey and the input's in the input colour, at the top left,
 * and the model is framed below them (the rows they take show no shaded face). */
static void t_render_labels(void)
{
    double small[24];
    render_mesh res, in = mk_mesh(cube_pos, 8, cube_fs, cube_cv, 6);
    render_opts o = mk_opts(0, 0, 1);
    uint8_t *img;
    int x, y, dark_top = 0, input_row2 = 0, face_top = 0;
    scaled_cube(0.5, small);
    res = mk_mesh(small, 8, cube_fs, cube_cv, 6);
    o.input = &in;
    o.label = "RESULT 1";
    o.input_label = "INPUT 2";
    img = rend(&res, &o);
    if (img) {
        for (y = 0; y < 12; y++)
            for (x = 0; x < 60; x++) {
                const uint8_t *p = pix(img, x, y);
                dark_top += p[0] == 40 && p[1] == 40 && p[2] == 40;
            }
        for (y = 14; y < 23; y++)
            for (x = 0; x < 60; x++) input_row2 += is_input_col(pix(img, x, y));
        for (y = 0; y < 23; y++)
            for (x = 0; x < RW; x++) {
                const uint8_t *p = pix(img, x, y);
                face_top += !is_bg(p) && !is_input_col(p) && !(p[0] == 40 && p[1] == 40 && p[2] == 40);
            }
        CHECK(dark_top > 20);    /* "RESULT 1": 8 glyphs of a few pixels each */
        CHECK(input_row2 > 20);  /* "INPUT 2" */
        CHECK_EQ(face_top, 0);
    }
    free(img);
}

/* The caption font (render_text.c): widths in closed form; '-' is one 5-pixel bar and '.'
 * a 2x2 block; lower case draws as upper case and an unknown character as '?'; the 36
 * letters and digits are pairwise distinct glyphs; scale 2 has 4 times the pixels. */
static uint32_t text_px(const char *s, int scale, uint8_t *img, int w, int h)
{
    static const uint8_t white[3] = {255, 255, 255}, black[3] = {0, 0, 0};
    uint32_t n = 0;
    int i;
    memset(img, 255, (size_t)w * (size_t)h * 3u);
    render_text(img, w, h, 2, 2, scale, s, black, white);
    for (i = 0; i < w * h; i++) n += img[3 * i] == 0;
    return n;
}

static void t_render_text_font(void)
{
    enum { W = 40, H = 24 };
    static uint8_t a[W * H * 3], b[W * H * 3];
    static const char set[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    int i, j, distinct = 1;
    CHECK_EQ(render_text_width("ABC", 1), 3 * RENDER_GLYPH_W);
    CHECK_EQ(render_text_width("ABC", 2), 6 * RENDER_GLYPH_W);
    CHECK_EQ(render_text_width("", 3), 0);
    CHECK_EQ(text_px("-", 1, a, W, H), 5);
    CHECK_EQ(text_px(".", 1, a, W, H), 4);
    CHECK_EQ(text_px(" ", 1, a, W, H), 0);
    CHECK_EQ(text_px("H", 2, a, W, H), 4u * text_px("H", 1, b, W, H));
    (void)text_px("spot", 1, a, W, H);
    (void)text_px("SPOT", 1, b, W, H);
    CHECK(memcmp(a, b, sizeof a) == 0);
    (void)text_px("~", 1, a, W, H);
    (void)text_px("?", 1, b, W, H);
    CHECK(memcmp(a, b, sizeof a) == 0);
    for (i = 0; set[i]; i++)
        for (j = i + 1; set[j]; j++) {
            char s1[2] = {set[i], 0}, s2[2] = {set[j], 0};
            (void)text_px(s1, 1, a, W, H);
            (void)text_px(s2, 1, b, W, H);
            if (memcmp(a, b, sizeof a) == 0) distinct = 0;
        }
    CHECK(distinct);
    /* clipped at the image border: no write outside the 4 x 4 image (ASan watches) */
    render_text(a, 4, 4, -3, -3, 2, "WWWW", a, b);
}

const test_case suite_png[] = {
    {"png_crc32_check_value", t_crc32_check_value},
    {"png_adler32_check_value", t_adler32_check_value},
    {"png_layout", t_png_layout},
    {"png_roundtrip_small", t_png_roundtrip_small},
    {"png_roundtrip_flat_compresses", t_png_roundtrip_flat_compresses},
    {"png_roundtrip_noise_stored", t_png_roundtrip_noise_stored},
    {"png_roundtrip_patterns", t_png_roundtrip_patterns},
    {"png_bad_args", t_png_bad_args},
    {"render_empty", t_render_empty},
    {"render_cube", t_render_cube},
    {"render_cube_hidden_edges", t_render_cube_hidden_edges},
    {"render_tetra_and_tints", t_render_tetra_and_tints},
    {"render_nan_and_bad_indices", t_render_nan_and_bad_indices},
    {"render_degenerate_extent", t_render_degenerate_extent},
    {"render_huge_coordinates", t_render_huge_coordinates},
    {"render_polylines", t_render_polylines},
    {"render_png_file", t_render_png_file},
    {"render_input_overlay", t_render_input_overlay},
    {"render_input_hidden_dashed", t_render_input_hidden_dashed},
    {"render_auto_edges", t_render_auto_edges},
    {"render_input_side_by_side", t_render_input_side_by_side},
    {"render_labels", t_render_labels},
    {"render_text_font", t_render_text_font},
    {0, 0}
};

#else

const test_case suite_png[] = {
    {0, 0}
};

#endif
