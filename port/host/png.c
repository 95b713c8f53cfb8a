/* SPDX-License-Identifier: MIT */
/* Own PNG writer (host only, no zlib): 8-bit RGB, per-row filter None or Sub (whichever has
 * the smaller sum of absolute residuals), one IDAT holding a zlib stream. The deflate data is
 * a single fixed-Huffman block with greedy LZ77 (hash chains, 32 KiB window) -- rendered
 * pictures are mostly flat, so this shrinks them a lot -- unless stored blocks would be
 * smaller, in which case stored blocks (<= 65535 bytes each) are written instead. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include "render.h"

/* ---------------------------------------------------------------- checksums */

uint32_t png_crc32(const uint8_t *p, uint32_t n)
{
    static uint32_t table[256];
    static int ready;
    uint32_t c = 0xFFFFFFFFu, i;
    if (!ready) {
        for (i = 0; i < 256u; i++) {
            uint32_t v = i;
            int k;
            for (k = 0; k < 8; k++) v = (v & 1u) ? 0xEDB88320u ^ (v >> 1) : v >> 1;
            table[i] = v;
        }
        ready = 1;
    }
    for (i = 0; i < n; i++) c = table[(c ^ p[i]) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

uint32_t png_adler32(const uint8_t *p, uint32_t n)
{
    uint32_t a = 1, b = 0;
    while (n > 0) {
        uint32_t k = n < 5552u ? n : 5552u; /* largest run without uint32 overflow */
        n -= k;
        while (k--) { a += *p++; b += a; }
        a %= 65521u;
        b %= 65521u;
    }
    return (b << 16) | a;
}

/* ---------------------------------------------------------------- growable byte buffer */

typedef struct buf {
    uint8_t *p;
    size_t n, cap;
    int oom;
    uint32_t bits; /* pending bits, LSB first */
    int nbits;
} buf;

static void buf_reserve(buf *b, size_t extra)
{
    size_t want, cap;
    uint8_t *q;
    if (b->oom) return;
    if (extra > (size_t)-1 - b->n) { b->oom = 1; return; }
    want = b->n + extra;
    if (want <= b->cap) return;
    cap = b->cap ? b->cap : 4096u;
    while (cap < want) {
        if (cap > (size_t)-1 / 2u) { cap = want; break; }
        cap *= 2u;
    }
    q = (uint8_t *)realloc(b->p, cap);
    if (!q) { b->oom = 1; return; }
    b->p = q;
    b->cap = cap;
}

static void buf_put(buf *b, const void *d, size_t n)
{
    buf_reserve(b, n);
    if (b->oom) return;
    memcpy(b->p + b->n, d, n);
    b->n += n;
}

static void buf_byte(buf *b, uint8_t v) { buf_put(b, &v, 1); }

static void buf_be32(buf *b, uint32_t v)
{
    uint8_t t[4];
    t[0] = (uint8_t)(v >> 24); t[1] = (uint8_t)(v >> 16);
    t[2] = (uint8_t)(v >> 8);  t[3] = (uint8_t)v;
    buf_put(b, t, 4);
}

/* Appends `n` (<= 16) bits of `v`, least significant first (deflate bit order). */
static void bits_put(buf *b, uint32_t v, int n)
{
    b->bits |= (v & ((1u << n) - 1u)) << b->nbits;
    b->nbits += n;
    while (b->nbits >= 8) {
        buf_byte(b, (uint8_t)b->bits);
        b->bits >>= 8;
        b->nbits -= 8;
    }
}

static void bits_flush(buf *b)
{
    if (b->nbits > 0) buf_byte(b, (uint8_t)b->bits);
    b->bits = 0;
    b->nbits = 0;
}

/* Huffman codes are sent most significant bit first: reverse, then send LSB first. */
static void huff_put(buf *b, uint32_t code, int len)
{
    uint32_t r = 0;
    int i;
    for (i = 0; i < len; i++) r |= ((code >> i) & 1u) << (len - 1 - i);
    bits_put(b, r, len);
}

/* ---------------------------------------------------------------- deflate, fixed Huffman */

static const uint16_t len_base[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                      2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t dist_base[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129,
                                       193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097,
                                       6145, 8193, 12289, 16385, 24577};
static const uint8_t dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6,
                                       6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

static void fixed_sym(buf *b, unsigned sym)
{
    if (sym < 144u) huff_put(b, 0x30u + sym, 8);
    else if (sym < 256u) huff_put(b, 0x190u + (sym - 144u), 9);
    else if (sym < 280u) huff_put(b, sym - 256u, 7);
    else huff_put(b, 0xC0u + (sym - 280u), 8);
}

static void fixed_match(buf *b, unsigned len, unsigned dist)
{
    unsigned i = 28, d = 29;
    while (len_base[i] > len) i--;
    fixed_sym(b, 257u + i);
    if (len_extra[i]) bits_put(b, len - len_base[i], len_extra[i]);
    while (dist_base[d] > dist) d--;
    huff_put(b, d, 5);
    if (dist_extra[d]) bits_put(b, dist - dist_base[d], dist_extra[d]);
}

#define WIN 32768u
#define HBITS 15
#define MAX_CHAIN 48u
#define MIN_MATCH 3u
#define MAX_MATCH 258u

static uint32_t hash3(const uint8_t *p)
{
    uint32_t v = ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2];
    return (v * 2654435761u) >> (32 - HBITS);
}

/* One final fixed-Huffman block. Returns 0, or -1 when out of memory. */
static int deflate_fixed(buf *out, const uint8_t *d, size_t n)
{
    /* head[h] / prev[pos % WIN] hold position + 1 (0 = none). */
    size_t *head = (size_t *)calloc((size_t)1 << HBITS, sizeof(size_t));
    size_t *prev = (size_t *)calloc(WIN, sizeof(size_t));
    size_t i = 0;
    if (!head || !prev) { free(head); free(prev); return -1; }
    bits_put(out, 1u, 1); /* BFINAL */
    bits_put(out, 1u, 2); /* BTYPE = 01, fixed Huffman */
    while (i < n) {
        size_t best_len = 0, best_dist = 0;
        if (n - i >= MIN_MATCH) {
            uint32_t h = hash3(d + i);
            size_t cand = head[h];
            size_t maxlen = n - i < MAX_MATCH ? n - i : MAX_MATCH;
            unsigned chain = 0;
            while (cand && chain < MAX_CHAIN) {
                size_t c = cand - 1, l = 0;
                if (i - c > WIN - 262u) break; /* keep well inside the window */
                while (l < maxlen && d[c + l] == d[i + l]) l++;
                if (l > best_len) {
                    best_len = l;
                    best_dist = i - c;
                    if (l == maxlen) break;
                }
                cand = prev[c % WIN];
                if (cand && cand - 1 >= c) break; /* stale slot: chains only go backwards */
                chain++;
            }
        }
        if (best_len >= MIN_MATCH) {
            size_t k;
            fixed_match(out, (unsigned)best_len, (unsigned)best_dist);
            for (k = 0; k < best_len; k++, i++) {
                if (n - i >= MIN_MATCH) {
                    uint32_t h = hash3(d + i);
                    prev[i % WIN] = head[h];
                    head[h] = i + 1;
                }
            }
        } else {
            if (n - i >= MIN_MATCH) {
                uint32_t h = hash3(d + i);
                prev[i % WIN] = head[h];
                head[h] = i + 1;
            }
            fixed_sym(out, d[i]);
            i++;
        }
        if (out->oom) break;
    }
    fixed_sym(out, 256u);
    bits_flush(out);
    free(head);
    free(prev);
    return out->oom ? -1 : 0;
}

static void deflate_stored(buf *out, const uint8_t *d, size_t n)
{
    size_t pos = 0;
    do {
        size_t k = n - pos > 65535u ? 65535u : n - pos;
        uint8_t h[5];
        h[0] = (uint8_t)(pos + k == n ? 1u : 0u); /* BFINAL, BTYPE = 00 */
        h[1] = (uint8_t)k;
        h[2] = (uint8_t)(k >> 8);
        h[3] = (uint8_t)~k;
        h[4] = (uint8_t)(~k >> 8);
        buf_put(out, h, 5);
        buf_put(out, d + pos, k);
        pos += k;
    } while (pos < n && !out->oom);
}

/* zlib stream (RFC 1950) of d[0..n). Returns 0 or -1. */
static int zlib_compress(buf *out, const uint8_t *d, size_t n)
{
    size_t start = out->n;
    size_t stored_size = n + 5u * (n / 65535u + 1u);
    buf_byte(out, 0x78); /* CM = 8, CINFO = 7 (32 KiB window) */
    buf_byte(out, 0x01); /* FLEVEL 0, no dictionary; 0x7801 % 31 == 0 */
    if (deflate_fixed(out, d, n) != 0) return -1;
    if (out->n - start - 2u > stored_size) { /* incompressible: stored blocks instead */
        out->n = start + 2u;
        deflate_stored(out, d, n);
    }
    buf_be32(out, png_adler32(d, (uint32_t)n));
    return out->oom ? -1 : 0;
}

/* ---------------------------------------------------------------- PNG container */

static void chunk(buf *b, const char *type, const uint8_t *data, uint32_t n)
{
    size_t at;
    buf_be32(b, n);
    at = b->n;
    buf_put(b, type, 4);
    if (n) buf_put(b, data, n);
    if (b->oom) return;
    buf_be32(b, png_crc32(b->p + at, n + 4u));
}

int png_encode_rgb(const uint8_t *rgb, int width, int height, uint8_t **png, uint32_t *len)
{
    static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    buf raw = {0, 0, 0, 0, 0, 0}, z = {0, 0, 0, 0, 0, 0}, out = {0, 0, 0, 0, 0, 0};
    size_t stride, rawn, y, x;
    uint8_t ihdr[13];
    if (!png || !len) return -1;
    *png = 0;
    *len = 0;
    if (!rgb || width <= 0 || height <= 0 || width > (1 << 24) || height > (1 << 24)) return -1;
    stride = (size_t)width * 3u;
    /* Keep the filtered data, and so every chunk length, comfortably below 2^31. */
    if ((size_t)height > ((size_t)1 << 30) / (stride + 1u)) return -1;
    rawn = (stride + 1u) * (size_t)height;

    buf_reserve(&raw, rawn);
    if (raw.oom) return -1;
    for (y = 0; y < (size_t)height; y++) {
        const uint8_t *row = rgb + y * stride;
        uint8_t *dst = raw.p + y * (stride + 1u);
        unsigned long sum0 = 0, sum1 = 0;
        for (x = 0; x < stride; x++) {
            uint8_t s = (uint8_t)(row[x] - (x >= 3u ? row[x - 3u] : 0u));
            sum0 += row[x] < 128u ? row[x] : 256u - row[x];
            sum1 += s < 128u ? s : 256u - s;
        }
        if (sum1 < sum0) {
            dst[0] = 1; /* Sub */
            for (x = 0; x < stride; x++) dst[1 + x] = (uint8_t)(row[x] - (x >= 3u ? row[x - 3u] : 0u));
        } else {
            dst[0] = 0; /* None */
            memcpy(dst + 1, row, stride);
        }
    }
    raw.n = rawn;

    if (zlib_compress(&z, raw.p, raw.n) != 0 || z.n > 0x7FFFFFFFu - 64u) goto fail;

    ihdr[0] = (uint8_t)(width >> 24); ihdr[1] = (uint8_t)(width >> 16);
    ihdr[2] = (uint8_t)(width >> 8);  ihdr[3] = (uint8_t)width;
    ihdr[4] = (uint8_t)(height >> 24); ihdr[5] = (uint8_t)(height >> 16);
    ihdr[6] = (uint8_t)(height >> 8);  ihdr[7] = (uint8_t)height;
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering */
    ihdr[12] = 0; /* no interlace */
    buf_put(&out, sig, 8);
    chunk(&out, "IHDR", ihdr, 13);
    chunk(&out, "IDAT", z.p, (uint32_t)z.n);
    chunk(&out, "IEND", 0, 0);
    if (out.oom) goto fail;
    free(raw.p);
    free(z.p);
    *png = out.p;
    *len = (uint32_t)out.n;
    return 0;
fail:
    free(raw.p);
    free(z.p);
    free(out.p);
    return -1;
}

int render_png_file(const char *path, const render_mesh *m, const render_opts *o)
{
    uint8_t *rgb = 0, *png = 0;
    uint32_t len = 0;
    int w = 0, h = 0, rc = 0;
    FILE *f;
    if (!path) { errno = EINVAL; return -1; }
    if (render_rgb(m, o, &rgb, &w, &h) != 0) { errno = ENOMEM; return -1; }
    if (png_encode_rgb(rgb, w, h, &png, &len) != 0) { free(rgb); errno = ENOMEM; return -1; }
    free(rgb);
    f = fopen(path, "wb");
    if (!f) { free(png); return -1; }
    if (fwrite(png, 1, len, f) != len) rc = -1;
    if (fclose(f) != 0) rc = -1;
    if (rc != 0 && errno == 0) errno = EIO;
    free(png);
    return rc;
}
