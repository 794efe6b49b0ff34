/* packing_figures: what diag/packing.h measures, in a header without the particle code, for
 * the command line that prints it (`vcsph volume`). */
#ifndef VCSPH_PACKING_FIGURES_H
#define VCSPH_PACKING_FIGURES_H

/* A particle is clumped when a fluid neighbour lies closer than this, in units of dr. */
#define PACKING_CLUMPED 0.5

typedef struct {
    long n_free;    /* free-surface particles */
    long n_clumped; /* of those, with a fluid neighbour closer than PACKING_CLUMPED dr */
    /* the mean distance to the nearest fluid neighbour within 2h, in dr, over the particles
       that have one: on the free surface, in the rest of S_F, off S_F */
    double nearest_free, nearest_band, nearest_interior;
} surface_packing;

#endif
