/* SPDX-License-Identifier: MIT */
/* Corpus replay for make test: feeds every file of fuzz/corpus/<target>/ to the same entry
 * function libFuzzer calls (fuzz_obj.c, fuzz_off.c, fuzz_stl.c, fuzz_ply.c, fuzz_schemes.c,
 * fuzz_sr48s.c, compiled here with
 * -DFUZZ_ENTRY=fz_<target>_entry), so CI runs the fuzz checks with gcc and ASan+UBSan and
 * needs no clang. A violated check aborts (test/scripts/run_suite.sh counts that as a failure), after
 * this program has printed which file it was running.
 * usage: replay TARGET DIR [TARGET DIR ...]   (TARGET: obj, off, stl, ply, schemes, ladapt, sr48s) */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fz_obj_entry(const uint8_t *data, size_t size);
int fz_off_entry(const uint8_t *data, size_t size);
int fz_stl_entry(const uint8_t *data, size_t size);
int fz_ply_entry(const uint8_t *data, size_t size);
int fz_schemes_entry(const uint8_t *data, size_t size);
int fz_ladapt_entry(const uint8_t *data, size_t size);
int fz_sr48s_entry(const uint8_t *data, size_t size);

typedef int (*entry_fn)(const uint8_t *, size_t);

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static unsigned replay_dir(const char *target, entry_fn fn, const char *dir, unsigned *failed)
{
    DIR *d = opendir(dir);
    if (!d) {
        printf("FAIL %s: cannot open %s\n", target, dir);
        (*failed)++;
        return 0;
    }
    char **names = NULL;
    size_t n = 0, cap = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            names = (char **)realloc(names, cap * sizeof *names);
            if (!names)
                abort();
        }
        names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, n, sizeof *names, cmp_names);
    unsigned passed = 0;
    for (size_t i = 0; i < n; i++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        FILE *f = fopen(path, "rb");
        if (!f) {
            printf("FAIL %s: cannot read %s\n", target, path);
            (*failed)++;
            continue;
        }
        uint8_t *buf = NULL;
        size_t len = 0, bcap = 0;
        for (;;) {
            if (len == bcap) {
                bcap = bcap ? 2 * bcap : 4096;
                buf = (uint8_t *)realloc(buf, bcap);
                if (!buf)
                    abort();
            }
            size_t got = fread(buf + len, 1, bcap - len, f);
            if (got == 0)
                break;
            len += got;
        }
        fclose(f);
        /* an exact-size copy, so ASan sees any read past the input */
        uint8_t *in = (uint8_t *)malloc(len ? len : 1);
        if (!in)
            abort();
        memcpy(in, buf, len);
        free(buf);
        fprintf(stderr, "running %s %s\n", target, path);
        fflush(stderr);
        fn(in, len);
        free(in);
        printf("ok %s %s\n", target, path);
        fflush(stdout);
        passed++;
        free(names[i]);
    }
    free(names);
    return passed;
}

int main(int argc, char **argv)
{
    unsigned passed = 0, failed = 0;
    for (int i = 1; i + 1 < argc; i += 2) {
        entry_fn fn = strcmp(argv[i], "obj") == 0       ? fz_obj_entry
                      : strcmp(argv[i], "off") == 0     ? fz_off_entry
                      : strcmp(argv[i], "stl") == 0     ? fz_stl_entry
                      : strcmp(argv[i], "ply") == 0     ? fz_ply_entry
                      : strcmp(argv[i], "schemes") == 0 ? fz_schemes_entry
                      : strcmp(argv[i], "ladapt") == 0  ? fz_ladapt_entry
                      : strcmp(argv[i], "sr48s") == 0   ? fz_sr48s_entry
                                                        : NULL;
        if (!fn) {
            printf("FAIL unknown target %s\n", argv[i]);
            failed++;
            continue;
        }
        unsigned p = replay_dir(argv[i], fn, argv[i + 1], &failed);
        if (p == 0) {
            printf("FAIL %s: no corpus files in %s\n", argv[i], argv[i + 1]);
            failed++;
        }
        passed += p;
    }
    if (argc < 3 || (argc - 1) % 2 != 0) {
        printf("usage: replay TARGET DIR [TARGET DIR ...]\n");
        failed++;
    }
    printf("%u passed, %u failed\n", passed, failed);
    return failed ? 1 : 0;
}
