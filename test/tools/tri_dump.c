/* SPDX-License-Identifier: MIT */
/* Test helper of test/scripts/tool_test.sh (compiled there with cc): prints the corners of a
 * triangle file, one line per corner in face order, as the hex bits of float32 coordinates,
 * so outputs of different formats compare with cmp/sort:
 *   tri_dump FILE.stl   "x y z" per corner; checks the binary STL layout (size = 84 + 50 n,
 *                       header not "solid", attribute 0) and that each facet normal is the
 *                       unit normal of its vertices (or 0 for a degenerate one)
 *   tri_dump FILE.obj   "x y z" per corner of each f record (v parsed with strtof), and
 *                       " nx ny nz" after it when the corner has a normal (f a//n)
 *   tri_dump FILE.off   "x y z" per corner
 *   tri_dump -v FILE.obj  only the v records, one per line
 * Exit 0, or 1 with a message on stderr. Host only (stdio, malloc). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(const char *what, const char *path)
{
    fprintf(stderr, "tri_dump: %s: %s\n", path, what);
    return 1;
}

static unsigned long get_u32(const unsigned char *p)
{
    return (unsigned long)p[0] | (unsigned long)p[1] << 8 | (unsigned long)p[2] << 16 | (unsigned long)p[3] << 24;
}

static float get_f32(const unsigned char *p)
{
    unsigned long u = get_u32(p);
    unsigned int w = (unsigned int)u;
    float f;
    memcpy(&f, &w, sizeof f);
    return f;
}

static unsigned int bits(float f)
{
    unsigned int w;
    memcpy(&w, &f, sizeof w);
    return w;
}

static void put3(const float *p, const char *end)
{
    printf("%08x %08x %08x%s", bits(p[0]), bits(p[1]), bits(p[2]), end);
}

static int dump_stl(FILE *f, const char *path)
{
    unsigned char head[84], t[50];
    unsigned long n, i;
    int k, c;
    if (fread(head, 1, 84, f) != 84) return fail("shorter than 84 bytes", path);
    if (memcmp(head, "solid", 5) == 0) return fail("header starts with 'solid'", path);
    n = get_u32(head + 80);
    for (i = 0; i < n; i++) {
        float v[3][3], nr[3];
        double u[3], w[3], x[3], len;
        if (fread(t, 1, 50, f) != 50) return fail("fewer triangles than the count", path);
        if (t[48] || t[49]) return fail("attribute not 0", path);
        for (k = 0; k < 3; k++) nr[k] = get_f32(t + 4 * k);
        for (c = 0; c < 3; c++)
            for (k = 0; k < 3; k++) v[c][k] = get_f32(t + 12 + 12 * c + 4 * k);
        for (k = 0; k < 3; k++) {
            u[k] = (double)v[1][k] - (double)v[0][k];
            w[k] = (double)v[2][k] - (double)v[0][k];
        }
        x[0] = u[1] * w[2] - u[2] * w[1];
        x[1] = u[2] * w[0] - u[0] * w[2];
        x[2] = u[0] * w[1] - u[1] * w[0];
        len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (k = 0; k < 3; k++)
            if (fabs((double)nr[k] - (len > 0.0 ? x[k] / len : 0.0)) > 1e-4) return fail("facet normal wrong", path);
        for (c = 0; c < 3; c++) put3(v[c], "\n");
    }
    if (fgetc(f) != EOF) return fail("more bytes than the count says", path);
    return 0;
}

/* Growing float arrays of 3-vectors. */
typedef struct vec3s {
    float *p;
    unsigned long n, cap;
} vec3s;

static int push3(vec3s *a, const float *p)
{
    if (a->n == a->cap) {
        unsigned long cap = a->cap ? 2 * a->cap : 1024;
        float *q = (float *)realloc(a->p, 3 * cap * sizeof *q);
        if (!q) return -1;
        a->p = q;
        a->cap = cap;
    }
    memcpy(a->p + 3 * a->n++, p, 3 * sizeof *p);
    return 0;
}

static int read3(const char *s, float *p)
{
    char *e;
    int k;
    for (k = 0; k < 3; k++) {
        p[k] = strtof(s, &e);
        if (e == s) return -1;
        s = e;
    }
    return 0;
}

static int dump_obj(FILE *f, const char *path, int only_v)
{
    char line[1024];
    vec3s v = {NULL, 0, 0}, vn = {NULL, 0, 0};
    float p[3];
    while (fgets(line, sizeof line, f)) {
        if (line[0] == 'v' && line[1] == ' ') {
            if (read3(line + 2, p) || push3(&v, p)) return fail("bad v", path);
            if (only_v) put3(p, "\n");
        } else if (line[0] == 'v' && line[1] == 'n' && line[2] == ' ') {
            if (read3(line + 3, p) || push3(&vn, p)) return fail("bad vn", path);
        } else if (line[0] == 'f' && line[1] == ' ' && !only_v) {
            char *s = line + 1, *e;
            int c;
            for (c = 0; c < 3; c++) {
                unsigned long a = strtoul(s, &e, 10), b = 0;
                if (e == s || a < 1 || a > v.n) return fail("bad f index", path);
                s = e;
                if (s[0] == '/' && s[1] == '/') {
                    b = strtoul(s + 2, &e, 10);
                    if (b < 1 || b > vn.n) return fail("bad f normal index", path);
                    s = e;
                }
                put3(v.p + 3 * (a - 1), b ? " " : "\n");
                if (b) put3(vn.p + 3 * (b - 1), "\n");
            }
        }
    }
    free(v.p);
    free(vn.p);
    return 0;
}

static int dump_off(FILE *f, const char *path)
{
    char line[1024];
    vec3s v = {NULL, 0, 0};
    unsigned long nv, nf, i;
    float p[3];
    if (!fgets(line, sizeof line, f) || strncmp(line, "OFF", 3) != 0) return fail("no OFF line", path);
    if (!fgets(line, sizeof line, f) || sscanf(line, "%lu %lu", &nv, &nf) != 2) return fail("no counts", path);
    for (i = 0; i < nv; i++)
        if (!fgets(line, sizeof line, f) || read3(line, p) || push3(&v, p)) return fail("bad vertex", path);
    for (i = 0; i < nf; i++) {
        unsigned long k, a[3];
        if (!fgets(line, sizeof line, f) || sscanf(line, "%lu %lu %lu %lu", &k, &a[0], &a[1], &a[2]) != 4 || k != 3 ||
            a[0] >= nv || a[1] >= nv || a[2] >= nv)
            return fail("bad face", path);
        for (k = 0; k < 3; k++) put3(v.p + 3 * a[k], "\n");
    }
    free(v.p);
    return 0;
}

int main(int argc, char **argv)
{
    int only_v = argc == 3 && strcmp(argv[1], "-v") == 0, rc;
    const char *path = argv[argc - 1];
    size_t n;
    FILE *f;
    if (argc != 2 + only_v) {
        fprintf(stderr, "usage: tri_dump [-v] FILE.stl|FILE.obj|FILE.off\n");
        return 1;
    }
    f = fopen(path, "rb");
    if (!f) return fail("cannot open", path);
    n = strlen(path);
    if (n > 4 && strcmp(path + n - 4, ".stl") == 0) rc = dump_stl(f, path);
    else if (n > 4 && strcmp(path + n - 4, ".off") == 0) rc = dump_off(f, path);
    else rc = dump_obj(f, path, only_v);
    fclose(f);
    return rc;
}
