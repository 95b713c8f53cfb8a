/* SPDX-License-Identifier: MIT */
/* Loop subdivision's vertex classification and smooth-rule weights (the rules themselves are
 * inline in loop_rules.h). See loop_rules.h for the definitions; this file holds the parts
 * that walk a mesh or do 64-bit integer arithmetic. */
#include "fp_contract.h" /* first: no float contraction whatever the flags */
#include "loop_rules.h"
#include "wide.h"

int subd_loop_tags_public(const subd_mesh *m, subd_diag *d)
{
    uint32_t v;
    for (v = 0; v < m->num_verts; v++)
        if (m->vert_tag[v] & LOOP_VTAG_PRIVATE) {
            if (d) d->vertex = v;
            return SUBD_ERR_PARAM;
        }
    return SUBD_OK;
}

void subd_loop_classify(const subd_mesh *m, uint32_t v, loop_vinfo *o)
{
    topo_ring r;
    if (m->vert_out[v] == SUBD_NONE || (m->vert_tag[v] & SUBD_VTAG_ISOLATED)) {
        o->valence = 0;
        o->c0 = o->c1 = o->i0 = o->i1 = o->nsharp = 0;
        o->boundary = 0;
        o->regular = 0;
        o->cls = LOOP_ISOLATED;
        return;
    }
    topo_ring_begin(&r, m, v);
    subd_loop_classify_ring(&r, m->edge_tag, (m->vert_tag[v] & SUBD_VTAG_CORNER) != 0u, o, 0);
}

void subd_loop_classify_ring(topo_ring *r, const uint8_t *etag, int corner_tag, loop_vinfo *o, uint32_t *hmin)
{
    uint32_t n = 0, ns = 0, s[2] = {0, 0}, at[2] = {0, 0}, hm = SUBD_NONE;
    o->boundary = 0;
    /* topo.h's walk; on a boundary its tail (the incoming boundary edge) is the last */
    while (topo_ring_step(r)) {
        if (!r->tail && r->he < hm) hm = r->he;
        if (topo_ring_sharp(r, etag)) {
            if (ns < 2u) {
                s[ns] = r->nb;
                at[ns] = n;
            }
            ns++;
        }
        n++;
        if (r->tail) o->boundary = 1;
    }
    if (hmin) *hmin = hm;
    o->valence = n;
    o->nsharp = ns;
    o->c0 = s[0];
    o->c1 = s[1];
    o->i0 = at[0];
    o->i1 = at[1];
    o->cls = loop_class_of(ns, corner_tag);
    o->regular = loop_regular_of(o->cls, n, o->boundary, at[0], at[1]);
}

/* A = 4 (3/8 + c/4) = 3/2 + c lies in [1/2, 5/2] (as an unsigned value * 2^62 < 2^64),
 * (A/4)^2 = A^2 / 2^66 in Q62, rounded half up. */
uint64_t subd_loop_nbeta_q62(uint32_t n)
{
    int64_t c = subd_cos_turns_q62(1, (int32_t)n);
    uint64_t a = ((uint64_t)3 << 61) + (uint64_t)c; /* c >= -2^62 > -3 * 2^61: no wrap */
    return ((uint64_t)5 << 59) - subd_u128_shr_round(subd_u128_mul(a, a), 66u); /* >= 0: (A/4)^2 <= 25/64 < 5/8 */
}

static loop_weights weights_calc(uint32_t n, uint32_t *ovf)
{
    loop_weights w;
    w.b = subd_real_from_q62((int64_t)((subd_loop_nbeta_q62(n) + n / 2u) / n)); /* rounded quotient */
    w.wc = SUBD_REAL_ONE;
    /* b rounds to 0 in Q16.16 from n ~ 30000 on, before n overflows subd_from_int */
    if (w.b != (subd_real)0) w.wc = subd_sub(w.wc, subd_mul(subd_from_int((int32_t)n, ovf), w.b, ovf), ovf);
    return w;
}

loop_weights subd_loop_weights_of(loop_wcache *c, uint32_t n, uint32_t *ovf)
{
    if (n >= LOOP_WCACHE) return weights_calc(n, ovf);
    if (!(c->have & (1u << n))) {
        c->w[n] = weights_calc(n, ovf);
        c->have |= 1u << n;
    }
    return c->w[n];
}
