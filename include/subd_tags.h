/* SPDX-License-Identifier: MIT */
/* Tag files: crease edges, corner and fixed vertices for a mesh, and the alpha parameters of
 * the semi-stationary operators (subd_alpha.h), as text in a memory buffer, so a firmware
 * image can carry (or receive) the same tag files as the host tool's --tags.
 * Included by subd.h.
 *
 * Format, one tag per line (LF, CRLF or lone CR line ends, as the OBJ and OFF readers):
 *   crease I J    the edge between vertices I and J gets SUBD_ETAG_CREASE (both half-edges)
 *   corner I      vertex I gets SUBD_VTAG_CORNER
 *   fixed I       vertex I gets SUBD_VTAG_FIXED
 *   alpha I A     vertex I's alpha is A (alpha curves; alpha surfaces of odd order)
 *   falpha F A    face F's alpha is A (alpha surfaces of even order)
 * A is an alpha value, one grammar for a tag file and the tool's --alpha (both parse it with
 * subd_tags_parse_alpha), exact, with no locale and no floating point:
 *   A       = turns | degrees
 *   turns   = sign? digit+ ( "/" digit+ )?     N or N/D turns, |N| <= 10^9, D in 1..10^9
 *   degrees = sign? digits "deg"               X degrees, |X| <= 36000, where digits is
 *             digit+ ( "." digit* )? | "." digit+   with at most 4 decimals
 *   sign    = "+" | "-"
 * No exponent ("4.5e1deg"), no hexadecimal, no blanks inside, no sign after the '/'; a value
 * is the reduced fraction of a turn (degrees: X 10^4 / 3600000, reduced), so "45deg", "1/8"
 * and "2/16" are the same value. Alpha lines set
 * no mesh bits: subd_tags_alpha turns them into numerators for subd_alpha_opts.tag_num; a
 * later line for the same element wins. Face numbers are 1-based in face order (the order
 * of OBJ f records). Vertex numbers are 1-based, as in OBJ, and written as plain decimal
 * digits. Fields are
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
    uint32_t vertex_alphas; /* alpha lines                                                */
    uint32_t face_alphas;   /* falpha lines                                               */
    /* The least common denominator of every alpha value (each a reduced fraction of a
     * turn; degrees are tenths of thousandths over 3600000): 1 with no alpha lines, 0 when
     * it does not fit int32. A den for subd_tags_alpha that makes every value exact. */
    int32_t alpha_den;
    /* The line of the first 'alpha' and of the first 'falpha' line (0: none), e.g. for a
     * caller's message when a line names the kind of element its operator does not tag. */
    uint32_t alpha_line[2];
    /* On SUBD_ERR_INDEX from a crease line whose two vertices exist but share no edge:
     * those vertices (0-based). SUBD_NONE otherwise. */
    uint32_t edge[2];
} subd_tags_report;

/* subd_tags_check: validates the tag file buf[0..len) against mesh m without changing
 * anything, and counts its tags into *report (may be NULL).
 * Memory: none (no arena; a few dozen bytes of stack).
 * Cost: O(buffer length + sum over crease lines of the valences of their two vertices).
 * Errors: SUBD_OK when every line is a valid tag for m, else the first failing line's:
 *   SUBD_ERR_PARAM       m NULL, or buf NULL with len > 0
 *   SUBD_ERR_PARSE       diag.line: not 'crease I J', 'corner I', 'fixed I', 'alpha I A'
 *                        or 'falpha F A' (unknown keyword, wrong number of fields, a field
 *                        that is not a number, an alpha value not in the syntax above; the
 *                        value is checked before the element number)
 *   SUBD_ERR_INDEX       diag.line: a vertex number outside 1..num_verts or a face number
 *                        outside 1..num_faces (diag.vertex = SUBD_NONE), or a crease pair
 *                        that shares no edge (diag.vertex = I-1, report->edge = {I-1, J-1})
 * The first failing line is reported. */
int subd_tags_check(const char *buf, uint32_t len, const subd_mesh *m, subd_tags_report *report, subd_diag *diag);

/* subd_tags_apply: checks the whole file as subd_tags_check does and, only when every line
 * is valid, sets the tag bits in m (existing tags are kept; tags are only ever added).
 * Memory: none. Errors: as subd_tags_check; on any failure m is unchanged.
 * Cost: two passes of subd_tags_check's cost. */
int subd_tags_apply(const char *buf, uint32_t len, subd_mesh *m, subd_tags_report *report, subd_diag *diag);

/* subd_tags_alpha: checks the whole file as subd_tags_check does and, only when every line
 * is valid and every alpha value A is a whole number of 1/den turns (A * den an integer within
 * +-SUBD_ALPHA_MAX_NUM), stores A * den for each 'alpha I A' line in vert_num[I-1] and for
 * each 'falpha F A' line in face_num[F-1] (num_verts and num_faces entries; either may be
 * NULL, then those lines are checked but not stored). Entries no line names keep their
 * values (fill them with the uniform alpha_num first). Mesh bits are not set (that is
 * subd_tags_apply).
 * Memory: none.
 * Errors: as subd_tags_check, plus SUBD_ERR_PARAM (den <= 0) and SUBD_ERR_RANGE (diag.line:
 *   a value that is not a whole number of 1/den turns or out of range; report->alpha_den is
 *   a den that avoids the first case). On any failure nothing is stored.
 * Cost: O(buffer length) (two passes). */
int subd_tags_alpha(const char *buf, uint32_t len, const subd_mesh *m, int32_t den, int32_t *vert_num,
                    int32_t *face_num, subd_tags_report *report, subd_diag *diag);

/* subd_tags_parse_alpha: parses one alpha value text[0..len) (no NUL needed) in the grammar
 * above into the reduced fraction of a turn *num / *den (den >= 1, gcd(|num|, den) = 1): the
 * parser of a tag file's alpha and falpha lines, for callers that take the same value from
 * elsewhere (the tool's --alpha), so both accept exactly the same texts.
 * Memory: none (a few words of stack).
 * Errors: SUBD_ERR_PARAM (text, num or den NULL); SUBD_ERR_PARSE (not in the grammar or out
 *   of its bounds). On failure *num and *den are unchanged.
 * Cost: O(len). */
int subd_tags_parse_alpha(const char *text, uint32_t len, int32_t *num, int32_t *den);

/* subd_tags_common_den: the least common multiple of two alpha denominators a and b (the
 * den over which values of either are whole numbers, as report.alpha_den for a file), or 0
 * when a or b is below 1 or the result exceeds INT32_MAX; e.g. a caller's --alpha den and a
 * file's report.alpha_den.
 * Memory: none. Errors: none (0 as said). Cost: O(log min(a, b)) (Euclid). */
int32_t subd_tags_common_den(int32_t a, int32_t b);

#ifdef __cplusplus
}
#endif

#endif
