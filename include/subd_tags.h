/* SPDX-License-Identifier: MIT */
/* Tag files: crease edges, corner and fixed vertices for a mesh, as text in a memory buffer,
 * so a firmware image can carry (or receive) the same tag files as the host tool's --tags.
 * Included by subd.h.
 *
 * Format, one tag per line (LF, CRLF or lone CR line ends, as the OBJ and OFF readers):
 *   crease I J    the edge between vertices I and J gets SUBD_ETAG_CREASE (both half-edges)
 *   corner I      vertex I gets SUBD_VTAG_CORNER
 *   fixed I       vertex I gets SUBD_VTAG_FIXED
 * Vertex numbers are 1-based, as in OBJ, and written as plain decimal digits. Fields are
 * separated by spaces or tabs; '#' starts a comment that runs to the end of the line; blank
 * and comment-only lines are skipped. Keywords are lower case. An empty buffer is a valid
 * file with no tags.
 *
 * Memory: none. Tags are bits in the mesh's own vert_tag and edge_tag arrays, so there is no
 * plan call and no arena; work is O(buffer length + sum over crease lines of the valences
 * of their two vertices); stack use is a few dozen bytes.
 */
#ifndef SUBD_TAGS_H
#define SUBD_TAGS_H

#include "subd.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a tag file holds (or, on failure, what the failing line named). */
typedef struct subd_tags_report {
    uint32_t creases;     /* crease lines (an edge named twice counts twice)              */
    uint32_t vertex_tags; /* corner and fixed lines                                       */
    /* On SUBD_ERR_INDEX from a crease line whose two vertices exist but share no edge:
     * those vertices (0-based). SUBD_NONE otherwise. */
    uint32_t edge[2];
} subd_tags_report;

/* Validates the tag file buf[0..len) against mesh m without changing anything, and counts
 * its tags into *report (may be NULL). Returns
 *   SUBD_OK              every line is a valid tag for m
 *   SUBD_ERR_PARAM       m NULL, or buf NULL with len > 0
 *   SUBD_ERR_PARSE       diag.line: not 'crease I J', 'corner I' or 'fixed I' (unknown
 *                        keyword, wrong number of fields, a field that is not a number)
 *   SUBD_ERR_INDEX       diag.line: a vertex number outside 1..num_verts (diag.vertex =
 *                        SUBD_NONE), or a crease pair that shares no edge (diag.vertex = I-1,
 *                        report->edge = {I-1, J-1})
 * The first failing line is reported. */
int subd_tags_check(const char *buf, uint32_t len, const subd_mesh *m, subd_tags_report *report, subd_diag *diag);

/* Checks the whole file as subd_tags_check does and, only when every line is valid, sets
 * the tag bits in m (existing tags are kept; tags are only ever added). Same returns; on
 * any failure m is unchanged. */
int subd_tags_apply(const char *buf, uint32_t len, subd_mesh *m, subd_tags_report *report, subd_diag *diag);

#ifdef __cplusplus
}
#endif

#endif
