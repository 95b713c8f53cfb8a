/* SPDX-License-Identifier: MIT */
/* Text cursor, token helpers and output sink shared by the OBJ and OFF readers/writers. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "text.h"

void subd_text_init(text_cursor *t, const char *buf, uint32_t len)
{
    t->p = buf;
    t->end = len ? buf + len : buf; /* (NULL, 0) is accepted: no arithmetic on NULL */
    t->line = t->line_end = buf;
    t->lineno = 0;
}

int subd_text_next_line(text_cursor *t)
{
    const char *s = t->p;
    if (s >= t->end) return 0;
    t->line = s;
    while (s < t->end && *s != '\n' && *s != '\r') s++;
    t->line_end = s;
    if (s < t->end && *s == '\r') s++;
    if (s < t->end && *s == '\n' && (s == t->line_end || s[-1] == '\r')) s++;
    t->p = s;
    t->lineno++;
    return 1;
}

const char *subd_text_skip_ws(const char *s, const char *end)
{
    while (s < end && (*s == ' ' || *s == '\t' || *s == '\r')) s++;
    return s;
}

const char *subd_text_token_end(const char *s, const char *end)
{
    while (s < end && *s != ' ' && *s != '\t' && *s != '\r') s++;
    return s;
}

int subd_text_token_is(const char *s, const char *e, const char *w)
{
    while (s < e && *w && *s == *w) { s++; w++; }
    return s == e && *w == 0;
}

int subd_text_parse_int(const char *s, const char *e, int32_t *out)
{
    int neg = 0;
    uint32_t v = 0;
    if (s < e && (*s == '-' || *s == '+')) { neg = (*s == '-'); s++; }
    if (s >= e) return SUBD_ERR_PARSE;
    for (; s < e; s++) {
        if (*s < '0' || *s > '9') return SUBD_ERR_PARSE;
        if (v > 214748364u) return SUBD_ERR_INDEX;
        v = v * 10u + (uint32_t)(*s - '0');
        if (v > 2147483647u) return SUBD_ERR_INDEX;
    }
    *out = neg ? -(int32_t)v : (int32_t)v;
    return SUBD_OK;
}

int subd_text_line_is_text(const char *s, const char *e)
{
    for (; s < e; s++) {
        unsigned char c = (unsigned char)*s;
        if (c < 0x20u && c != '\t') return 0;
        if (c == 0x7fu) return 0;
    }
    return 1;
}

int subd_text_parse_real(const char **s, const char *e, subd_real *out)
{
    const char *p = subd_text_skip_ws(*s, e);
    int st;
    if (p >= e) return SUBD_ERR_PARSE;
    st = subd_real_parse(&p, e, out);
    if (st != SUBD_OK) return st;
    if (p < e && *p != ' ' && *p != '\t' && *p != '\r') return SUBD_ERR_PARSE;
    *s = p;
    return SUBD_OK;
}

void subd_sink_chars(text_sink *k, const char *s, uint32_t n)
{
    uint32_t i;
    if (k->overflow || n > UINT32_MAX - k->len) { k->overflow = 1; return; }
    if (k->buf && k->len + n <= k->cap)
        for (i = 0; i < n; i++) k->buf[k->len + i] = s[i];
    k->len += n;
}

void subd_sink_str(text_sink *k, const char *s)
{
    uint32_t n = 0;
    while (s[n]) n++;
    subd_sink_chars(k, s, n);
}

void subd_sink_u32(text_sink *k, uint32_t v)
{
    char b[10];
    uint32_t n = 0;
    do { b[9u - n] = (char)('0' + (int)(v % 10u)); v /= 10u; n++; } while (v);
    subd_sink_chars(k, b + 10u - n, n);
}

void subd_sink_real(text_sink *k, subd_real x)
{
    char b[32];
    subd_sink_chars(k, b, subd_real_format(x, b));
}

int subd_text_run(text_job_fn emit, const void *job, char *buf, uint32_t cap, uint32_t *len)
{
    text_sink k = {0, 0, 0, 0};
    emit(job, &k);
    if (k.overflow) return SUBD_ERR_TOO_BIG;
    *len = k.len;
    if (!buf) return SUBD_OK;
    if (k.len > cap) return SUBD_ERR_NOMEM;
    k.buf = buf;
    k.cap = cap;
    k.len = 0;
    emit(job, &k);
    return SUBD_OK;
}

/* A mesh writer as a subd_text_run job. */
typedef struct text_mesh_job {
    text_emit_fn emit;
    const subd_mesh *m;
    const subd_real *normals;
} text_mesh_job;

static void text_mesh_emit(const void *job, text_sink *k)
{
    const text_mesh_job *j = (const text_mesh_job *)job;
    j->emit(j->m, j->normals, k);
}

int subd_text_write(text_emit_fn emit, const subd_mesh *m, const subd_real *normals, char *buf, uint32_t cap,
                    uint32_t *len)
{
    text_mesh_job j;
    if (!m || !len) return SUBD_ERR_PARAM;
    j.emit = emit;
    j.m = m;
    j.normals = normals;
    return subd_text_run(text_mesh_emit, &j, buf, cap, len);
}
