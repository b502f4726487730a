/* SPDX-License-Identifier: MIT */
/* Private: the painter's sort, one implementation for the renderer's
 * STP_HIDDEN_PAINTER (raster.c) and direct drawing's
 * stp_direct_frame_sort (direct.c): polygons far to near by the depth key
 * of each one's farthest vertex (ascending: a larger key is nearer, keys
 * as the projection gives them), ties by their order of entry (index), so
 * the order does not depend on the sort's own order of work and is the
 * same for every route that enters the same faces in the same order.
 * Static inline: each user is one call a frame. */
#ifndef STIPPLE_SORT_PRIVATE_H
#define STIPPLE_SORT_PRIVATE_H

#include <stddef.h>

#include "stipple/render.h" /* stp_sort_entry */

static inline int stp_sort_less(const stp_sort_entry *a, const stp_sort_entry *b)
{
    return a->key < b->key || (a->key == b->key && a->index < b->index);
}

/* *to = *from member by member: word loads and stores (a 16-byte
 * structure copy may be a memcpy call, a byte loop in a minimal libc) */
static inline void stp_sort_copy(stp_sort_entry *to, const stp_sort_entry *from)
{
    to->index = from->index;
    to->key = from->key;
    to->style = from->style;
    to->transmission = from->transmission;
}

/* The heap e[root + 1 ..] below root, with v placed at root, made a heap
 * again (end entries): the larger child moved up into the hole while it
 * is larger than v, then v stored once (a move a level, not a swap). */
static inline void stp_sort_sift(stp_sort_entry *e, size_t root, size_t end, const stp_sort_entry *v)
{
    size_t child;
    while ((child = 2 * root + 1) < end) {
        if (child + 1 < end && stp_sort_less(&e[child], &e[child + 1]))
            child++;
        if (!stp_sort_less(v, &e[child]))
            break;
        stp_sort_copy(&e[root], &e[child]);
        root = child;
    }
    stp_sort_copy(&e[root], v);
}

/* e[0 .. n - 1] sorted far to near (stp_sort_less): a heap sort, in
 * place, no recursion, O(n log n).  (key, index) orders every pair, so any
 * correct sort gives this order. */
static inline void stp_sort_far_to_near(stp_sort_entry *e, size_t n)
{
    size_t i;
    if (n < 2)
        return;
    for (i = n / 2; i-- > 0;) {
        stp_sort_entry v;
        stp_sort_copy(&v, &e[i]);
        stp_sort_sift(e, i, n, &v);
    }
    for (i = n - 1; i > 0; i--) {
        stp_sort_entry last;
        stp_sort_copy(&last, &e[i]);
        stp_sort_copy(&e[i], &e[0]); /* the greatest left, to its place */
        stp_sort_sift(e, 0, i, &last);
    }
}

#endif
