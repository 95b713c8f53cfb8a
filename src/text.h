/* SPDX-License-Identifier: MIT */
/* Private helpers shared by the text readers and writers (obj.c, off.c): a line cursor over
 * a memory buffer that understands LF, CRLF and lone CR, token scanning, integer parsing,
 * and an output sink that either writes into a buffer or only counts bytes. */
#ifndef SUBD_TEXT_H
#define SUBD_TEXT_H
#include "subd.h"

typedef struct text_cursor {
    const char *p, *end;   /* whole buffer [p, end) still to read                      */
    const char *line;      /* current line [line, line_end)                            */
    const char *line_end;
    uint32_t lineno;       /* 1-based number of the current line                       */
} text_cursor;

void subd_text_init(text_cursor *t, const char *buf, uint32_t len);
/* Advances to the next line; returns 0 at end of buffer. */
int subd_text_next_line(text_cursor *t);
/* Skips spaces and tabs (and a trailing CR) from *s. */
const char *subd_text_skip_ws(const char *s, const char *end);
/* End of the token at s (first space, tab, CR, or end). */
const char *subd_text_token_end(const char *s, const char *end);
/* True when [s, e) equals the NUL-terminated word w. */
int subd_text_token_is(const char *s, const char *e, const char *w);
/* Parses an optionally signed decimal integer token [s, e) exactly (no trailing garbage).
 * Returns SUBD_OK, SUBD_ERR_PARSE, or SUBD_ERR_INDEX when the magnitude exceeds 2^31-1. */
int subd_text_parse_int(const char *s, const char *e, int32_t *out);
/* True if every byte of [s, e) is printable text (tab, space, 0x21..0x7e or >= 0x80). */
int subd_text_line_is_text(const char *s, const char *e);
/* Parses one real token at *s (after skipping blanks); the token must end at a blank or the
 * line end. */
int subd_text_parse_real(const char **s, const char *e, subd_real *out);

/* x / 65536 as exact decimal text (subd_real_format of the Q16.16 build, src/real_format.c;
 * int32 only, so it exists in the float build too). At most 23 bytes, no NUL. */
uint32_t subd_q16_format(int32_t x, char *buf);

/* Output sink: writes while there is room, always counts. */
typedef struct text_sink {
    char *buf;
    uint32_t cap, len;
    int overflow;          /* the count no longer fits 32 bits */
} text_sink;
void subd_sink_str(text_sink *k, const char *s);
void subd_sink_chars(text_sink *k, const char *s, uint32_t n);
void subd_sink_u32(text_sink *k, uint32_t v);
void subd_sink_real(text_sink *k, subd_real x);
/* Runs a writer, the one size-then-write of every text writer: emit(job) once to count (so
 * a too-small buffer is left untouched), then once more into buf. *len = the bytes, also
 * when buf is a null pointer (a size query); SUBD_ERR_TOO_BIG when the count does not fit
 * 32 bits, SUBD_ERR_NOMEM when it exceeds cap. The contract of subd_obj_write,
 * subd_off_write and subd_path_write (whose arguments the callers check first). */
typedef void (*text_job_fn)(const void *job, text_sink *k);
int subd_text_run(text_job_fn emit, const void *job, char *buf, uint32_t cap, uint32_t *len);
/* subd_text_run of a mesh writer (obj.c, off.c): SUBD_ERR_PARAM without m or len. */
typedef void (*text_emit_fn)(const subd_mesh *m, const subd_real *normals, text_sink *k);
int subd_text_write(text_emit_fn emit, const subd_mesh *m, const subd_real *normals, char *buf, uint32_t cap,
                    uint32_t *len);
#endif
