/* SPDX-License-Identifier: MIT */
/* Host-only file wrappers for the subd tool and the benchmarks: whole-file read/write and
 * "read a mesh file by its extension into an exactly planned arena". Uses malloc and stdio;
 * never linked into device images. */
#ifndef FILEIO_H
#define FILEIO_H
#include <stdint.h>
#include <stdio.h>
#include "subd.h"

/* Inputs larger than this are refused before anything is read (the tool reads an input
 * whole into memory; lengths are uint32_t). */
#define HOST_INPUT_MAX 2147483648ull
#define HOST_INPUT_MAX_STR "2147483648"

/* host_read_file's failures besides -1 (errno set). */
#define HOST_READ_NOT_REGULAR (-2) /* a FIFO, device, socket or directory: refused unread */
#define HOST_READ_TOO_BIG (-3)     /* more than HOST_INPUT_MAX bytes                         */

/* Reads the whole regular file into a malloc'd buffer (*buf, *len bytes, plus a NUL
 * terminator that is not counted). Returns 0; -1 with errno set (ENOMEM when out of memory);
 * HOST_READ_NOT_REGULAR without opening a FIFO or device (which would block or never end);
 * HOST_READ_TOO_BIG for a file over HOST_INPUT_MAX bytes. *buf is NULL on failure. */
int host_read_file(const char *path, char **buf, uint32_t *len);

/* The reason for a failed host_read_file (its return value; errno for -1), for messages. */
const char *host_read_error_str(int rc);

/* Writes buf[0..len) to path (created or truncated). Returns 0, or -1 with errno set; a
 * partially written regular file is removed (a device or FIFO path is left alone). */
int host_write_file(const char *path, const void *buf, uint32_t len);

/* An output file written through one fixed buffer (HOST_OUT_BUF bytes), so writing a mesh
 * costs no memory beyond the mesh: the writers format straight into the buffer
 * (host_out_room) and it goes to the file whenever it is full. */
#define HOST_OUT_BUF 65536u
#define HOST_OUT_ROOM_MAX 1024u /* the most host_out_room hands out at once */
typedef struct host_out {
    FILE *f;
    const char *path;
    int regular;       /* a regular file: removed again when the write fails            */
    int err;           /* errno of the first failure (0: none)                           */
    uint32_t fill;     /* bytes in buf                                                   */
    uint64_t bytes;    /* bytes handed to the file so far                                */
    char buf[HOST_OUT_BUF];
} host_out;

/* Creates or truncates path for writing. Returns 0, or -1 with errno set. */
int host_out_open(host_out *o, const char *path);
/* n <= HOST_OUT_ROOM_MAX bytes of room at o->buf + o->fill (writing the buffer out first when
 * needed); the caller writes there and adds what it used to o->fill. NULL after a write
 * error (o->err set). */
char *host_out_room(host_out *o, uint32_t n);
/* Writes the buffer out and closes; with ok == 0 (the caller failed) or any write failure a
 * partially written regular file is removed (a device or FIFO is left alone). Returns 0, or
 * -1 with errno set (o->err). o->bytes is the file's length on success. */
int host_out_close(host_out *o, int ok);

/* The library's text for numbers (subd_real_format) in the writers' record shapes:
 * host_fmt_u32 writes v in decimal (<= 10 bytes); host_fmt_xyz writes kw (NUL-terminated,
 * <= 8 bytes) then the three reals separated by spaces and a newline (<= 8 + 3 * 24 bytes):
 * "v x y z\n", "vn x y z\n", the bytes src/obj.c and src/off.c write. Both return the length. */
uint32_t host_fmt_u32(char *b, uint32_t v);
uint32_t host_fmt_xyz(char *b, const char *kw, const subd_real *p);

/* File formats known by extension (case-insensitive). */
typedef enum host_format {
    HOST_FMT_UNKNOWN = 0,
    HOST_FMT_OBJ,
    HOST_FMT_OFF,
    HOST_FMT_PNG,
    HOST_FMT_XYZ, /* output only: "x y z" per line, a blank line between polylines (CNC) */
    HOST_FMT_STL, /* read (binary or ASCII); written as binary STL by the streams (subd_stream.c) */
    HOST_FMT_PLY, /* input only: ASCII or binary little-endian PLY                          */
    HOST_FMT_GCODE /* output only (.gcode, .nc), written by alpha --stream                */
} host_format;

host_format host_format_of(const char *path);
const char *host_format_name(host_format f); /* "obj", "off", "png", "xyz", "stl", "ply" or "unknown" */
/* True for the formats host_read_mesh reads (.obj, .off, .stl, .ply). */
int host_format_readable(host_format f);
#define HOST_READABLE ".obj, .off, .stl or .ply" /* for messages */

/* Statuses of host_read_mesh besides the library's subd_status values (which are 0 or
 * negative): I/O failure (errno set) and an extension host_read_mesh does not read. */
#define HOST_ERR_IO 1
#define HOST_ERR_FORMAT 2
#define HOST_ERR_OOM 3

/* A mesh read from a file, living in its own malloc'd arena. */
typedef struct host_mesh {
    subd_mesh mesh;
    subd_arena arena;   /* the arena the mesh lives in; more may be allocated after it   */
    void *mem;          /* malloc'd block behind the arena (free with host_mesh_free)    */
    uint32_t planned;   /* bytes the reader's plan call asked for                         */
    uint32_t file_bytes;
    host_format format;
    int read_rc;        /* host_read_file's return value (for host_read_error_str)        */
    int big_endian_ply; /* the read failed at a `format binary_big_endian` line (message)  */
} host_mesh;

/* Reads an .obj, .off, .stl or .ply file (the library's reader by extension). The arena is sized from the reader's plan call: exactly the plan
 * when budget is NULL, or *budget bytes when given (a simulated device arena; the rest stays
 * free for later operations). Returns
 *   SUBD_OK              hm filled; hm->arena.peak is the bytes the read used
 *   a subd_status < 0    diag filled by the library (diag->line for input errors). When the
 *                        plan exceeds *budget: SUBD_ERR_NOMEM with diag->bytes_needed = plan
 *   HOST_ERR_IO          the file cannot be read (errno set), is not a regular file or is
 *                        over HOST_INPUT_MAX (host_mesh.read_rc says which)
 *   HOST_ERR_FORMAT      the extension is not one of HOST_READABLE
 *   HOST_ERR_OOM         the host is out of memory
 * parse_ns, when not NULL, receives the nanoseconds spent in the library (plan + read). */
int host_read_mesh(const char *path, const uint32_t *budget, host_mesh *hm, subd_diag *diag,
                   double *parse_ns);
void host_mesh_free(host_mesh *hm);

/* Allocates a block of `bytes` usable arena bytes aligned to SUBD_ARENA_ALIGN and inits the
 * arena over exactly that many bytes. Returns the malloc'd pointer to free, or NULL. */
void *host_arena_alloc(subd_arena *a, uint32_t bytes);

/* Monotonic clock in nanoseconds. */
double host_now_ns(void);
#endif
