/* Loop subdivision, Loop limit positions and normals, and progressive interpolation
 * (paper: loop-progressive-interpolation.txt; formulas and traps in REFERENCE.md).
 * Included by subd.h. */
#ifndef SUBD_LOOP_H
#define SUBD_LOOP_H

/* Boundary (and crease) rules, named after where they come from. */
typedef enum subd_loop_boundary {
    /* Paper, section 4: boundary vertex 3/4 v + 1/8 (c0 + c1); boundary edge midpoint when
     * both ends are regular or both extraordinary, else 5/8 regular + 3/8 extraordinary. */
    SUBD_LOOP_BOUNDARY_PAPER = 0,
    /* Midpoint on every boundary edge (a cubic B-spline boundary curve), as OpenSubdiv
     * and CGAL do. */
    SUBD_LOOP_BOUNDARY_BSPLINE = 1
} subd_loop_boundary;

/* subd_loop_opts.flags */
#define SUBD_LOOP_ADJACENCY 0x1u /* give the final level full adjacency (twin, vert_out, tags) */

typedef struct subd_loop_opts {
    uint32_t levels;             /* 1..SUBD_MAX_LEVELS                                   */
    subd_loop_boundary boundary;
    uint32_t flags;
} subd_loop_opts;

/* Exact arena bytes subd_loop needs for this input and options. The input must be an
 * all-triangle mesh (SUBD_ERR_FACE_SIZE otherwise) with adjacency (twin, vert_out: a mesh
 * from the builder or readers, or a subd_loop output made with SUBD_LOOP_ADJACENCY;
 * SUBD_ERR_PARAM otherwise). The plan is the output arrays plus level L-1's arrays with
 * twins (pos, corners, twins, vert_out, tags): peak = input + output + previous level.
 * O(corners) work, no arena use. */
int subd_loop_plan(const subd_mesh *in, const subd_loop_opts *o, uint32_t *bytes);

/* `levels` steps of Loop subdivision (Loop's original weights) of an all-triangle mesh.
 * Edges tagged SUBD_ETAG_CREASE follow the boundary rules; vertices tagged
 * SUBD_VTAG_CORNER (and vertices with three or more sharp edges, Hoppe et al. 1994) stay
 * where they are; isolated vertices are copied. Vertices keep their indices (vertex i of the
 * input is vertex i of the output), new vertices follow, one per edge in the order of the
 * edge's lower half-edge index. Face f's children are faces 4f..4f+3: (v_i, m_i, m_{i-1})
 * for i = 0, 1, 2 and (m0, m1, m2), with v_i face f's corners and m_i the new vertex on
 * edge v_i -> v_{i+1}. Child edges of crease/boundary edges keep their tags; CORNER and
 * FIXED vertex tags are kept (FIXED changes no rule); polylines are not carried over
 * (num_lines = 0). The input is not modified; *out's arrays are in the arena, and after the
 * call the arena holds only them. Without SUBD_LOOP_ADJACENCY the output has pos,
 * face_start, corner_vert, corner_face, vert_tag and edge_tag, and twin/vert_out are NULL;
 * with it the output equals subd_mesh_build of its own face list (plus the crease and
 * corner tags). Rules, regular/extraordinary classification and memory layout: src/loop.c.
 * Errors: SUBD_ERR_PARAM, SUBD_ERR_FACE_SIZE, SUBD_ERR_TOO_BIG, SUBD_ERR_NOMEM
 * (diag.bytes_needed), SUBD_ERR_RANGE (fixed-point overflow). On failure the arena is back
 * where it was and *out is untouched. Every rule is a convex combination whose Q16.16
 * weights sum to exactly 1, so RANGE cannot occur in Q16.16; in float32 it means a sum
 * near FLT_MAX rounded to infinity. Work O(4^levels * corners); stack about 550 bytes. */
int subd_loop(subd_arena *a, const subd_mesh *in, const subd_loop_opts *o, subd_mesh *out, subd_diag *d);

/* ------------------------------------------------------------------------------------ */
/* Limit positions and normals                                                            */

/* Exact arena bytes of subd_loop_limit (3 * num_verts subd_reals per requested array plus
 * working memory). */
int subd_loop_limit_plan(const subd_mesh *in, subd_loop_boundary b, int normals, uint32_t *bytes);

/* Limit-surface positions of every control vertex (3 * num_verts, in the arena) and, when
 * normals != NULL, unit limit normals (3 * num_verts; a vertex where the tangents vanish
 * gets (0, 0, 0)). Interior: the paper's formula (3); boundary: the rule set b; creases
 * follow the boundary rules; corners and isolated vertices stay. Errors as subd_loop. */
int subd_loop_limit(subd_arena *a, const subd_mesh *in, subd_loop_boundary b, subd_real **pos,
                    subd_real **normals, subd_diag *d);

/* ------------------------------------------------------------------------------------ */
/* Progressive interpolation (paper, sections 2-4)                                        */

typedef enum subd_pia_method {
    SUBD_PIA_PAPER = 0, /* V <- V + (P - L V), boundary first then interior (the paper)   */
    SUBD_PIA_FAST = 1   /* an accelerated iteration; see pia.c for the convergence argument */
} subd_pia_method;

typedef struct subd_pia_opts {
    subd_loop_boundary boundary;
    subd_real tol;       /* stop when max |P - L V| <= tol (input units)                  */
    uint32_t max_iter;   /* stop after this many iterations (>= 1)                        */
    subd_pia_method method;
} subd_pia_opts;

typedef struct subd_pia_result {
    uint32_t iterations;
    subd_real max_err;   /* max over vertices of |P - L V| (Euclidean) at the end         */
    subd_real mean_err;  /* mean of the same                                              */
    int converged;       /* 1 when max_err <= tol                                        */
} subd_pia_result;

/* Exact arena bytes of subd_pia for this input and options: PAPER 2 arrays of 3 * num_verts
 * subd_reals (V, L V); FAST 4 such arrays (V, L V, search direction, L of it) plus one
 * subd_real and one byte per vertex, each rounded up to SUBD_ARENA_ALIGN. Validates like
 * subd_pia (SUBD_ERR_PARAM, SUBD_ERR_FACE_SIZE, SUBD_ERR_TOO_BIG). */
int subd_pia_plan(const subd_mesh *in, const subd_pia_opts *o, uint32_t *bytes);

/* Control positions V (3 * num_verts, in the arena) whose Loop limit surface passes through
 * the input mesh's vertices P within tol: max over vertices of the Euclidean distance
 * |P_i - (L V)_i| <= tol, L being subd_loop_limit's operator with rule o->boundary (creases
 * and corners of the input honoured). The input needs full adjacency (twin, vert_out) and
 * triangles only. PAPER starts from V = P and repeats V += P - L V, on the boundary vertices
 * until they are within tol, then on the rest with the boundary fixed (paper, sections 2
 * and 4). FAST (conjugate gradients, or Chebyshev iteration when a crease ends inside the
 * surface; see src/pia.c for the convergence argument) reaches the same tol in fewer
 * iterations. An iteration is one update of V; result->iterations counts them over all
 * phases and never exceeds max_iter; max_err and mean_err are over
 * all vertices (corners and isolated vertices stay where they are, error 0). A phase whose
 * error stops decreasing for 10 iterations (the arithmetic's rounding floor) ends early.
 * Not converging within max_iter is not an error: result->converged says so.
 * tol: float32 any positive finite value; Q16.16 at least 2 LSB (2^-15): L's rounding floor
 * is about 1 LSB per coordinate, sqrt(3) LSB in norm.
 * Errors: SUBD_ERR_PARAM (NULL pointer, mesh without adjacency, bad boundary or method,
 * max_iter == 0, tol not positive, NaN/inf or below the Q16.16 minimum), SUBD_ERR_FACE_SIZE
 * (diag.face: the first non-triangle), SUBD_ERR_TOO_BIG, SUBD_ERR_NOMEM (diag.bytes_needed),
 * SUBD_ERR_RANGE (a control point or error leaves the Q16.16 range, or is not finite in
 * float32). On failure the arena is back where it was and *pos and *result are untouched;
 * on success only V stays in the arena. */
int subd_pia(subd_arena *a, const subd_mesh *in, const subd_pia_opts *o, subd_real **pos,
             subd_pia_result *result, subd_diag *d);

#endif
