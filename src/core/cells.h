/* cells: the cell list (particles binned in cubes whose side is the search radius), the sort of
 * the fluid by cell, and per-particle neighbour lists built from it. */
#ifndef VCSPH_CELLS_H
#define VCSPH_CELLS_H

#include "core/dim.h"
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct {
    double origin[DIM]; /* lower corner of cell (0, 0[, 0]) */
    double size;        /* cell side: the search radius (cells_setup) */
    int n[DIM];         /* cells per axis */
    int strip;          /* cells per strip along x (CELL_STRIP_WIDTH, or fewer in a short box) */
    size_t n_cells;
    size_t *start;     /* n_cells + 1: items of cell c are item[start[c] .. start[c+1]) */
    uint32_t *item;    /* particle indices, ascending within each cell */
    uint32_t *cell_of; /* cell of each binned particle */
    uint32_t *counts;  /* threads x n_cells: cells_bin's counts of each thread's share */
    uint8_t *mark;     /* n_cells: cells_mark's flags (bit 0: in the cell, 1: around it) */
    double *xs[DIM];   /* their positions in item order, during neighbours_build only (NULL
                          after it): in the room the caller lends, or else in own_xs */
    double *own_xs;    /* DIM x own_xs_capacity doubles, allocated only when no room is lent */
    size_t item_capacity, cells_capacity, own_xs_capacity, counts_capacity;
} cell_grid;

/* Memory a caller lends neighbours_build for the copy of the binned positions in item order
 * (DIM doubles a binned particle), memory idle while the lists are built: the solver lends
 * its RK4 work arrays, which hold nothing between steps (scheme/solver.h), and so the grid
 * holds no copy of the positions between builds (3 doubles a particle and image in 3D). */
typedef struct {
    double *at;
    size_t doubles;
} cells_room;

/* Neighbour lists: row i holds the indices j != i within `radius` of i, in a fixed order (so
 * every sum over them is the same for any number of threads): first the near[i] within the
 * kernel's support at the positions of the build, then the skin, those beyond it, each part in
 * the order of the cell scan. A pass at those positions (the step's preparation and the first
 * stage of RK4: no pass moves a particle) has all its pairs within 2h in the near part and
 * reads only that part (neighbours_near); once the particles have moved, a pair of the skin may
 * come within 2h, and the whole row is read. A row is kept
 * in 16 bits an entry: j = base[2 i + w] + e, with e < NEIGHBOUR_WINDOW, in one of two windows
 * w (the entry's top bit): the fluid (j < n_rows) and the ghosts after it (the walls' images
 * and an MPI halo at the store's tail, far from the fluid in index but close to one another).
 * With the fluid sorted by cell, a row's fluid lies within three rows of cells of one strip or
 * two strips (cells_setup), a few thousand indices in the cases of docs/performance.md. A
 * build where some row does not fit its windows keeps every row whole, 32 bits an entry
 * (`wide`), and so do the builds after it. neighbour_row reads either. */
#define NEIGHBOUR_WINDOW 32768
/* A row's number of entries: 16 bits (a row of more than NEIGHBOUR_ROW_MAX, some 500 times
 * the lattice's density within 2h, fails the build: the flow has blown up long before) */
typedef uint16_t neighbour_count;
#define NEIGHBOUR_ROW_MAX UINT16_MAX
typedef struct {
    size_t n_rows, row_capacity, capacity_rows, index_capacity;
    neighbour_count *count;
    neighbour_count *near; /* n_rows: the entries of each row within the support at the build */
    uint16_t *packed;      /* n_rows x row_capacity entries; unless wide */
    int32_t *base;         /* n_rows x 2: each row's windows' first indices; unless wide */
    int32_t *index;        /* n_rows x row_capacity indices; when wide */
    bool wide;
    int32_t longest; /* the longest row of the last build, which sizes the next one's rows */
    double radius;
} neighbour_list;

/* Particle i's row as indices: the stored row when the list is wide, else the row unpacked
 * into `entries` (room for the row's count). */
static inline const int32_t *neighbour_row(const neighbour_list *nl, size_t i, int32_t *entries)
{
    if (nl->wide) return nl->index + i * nl->row_capacity;
    const uint16_t *e = nl->packed + i * nl->row_capacity;
    /* read before the loop: a store to entries[] could change nl->count as far as the compiler
       knows, which would keep it from unpacking several entries at once */
    int32_t count = nl->count[i], fluid = nl->base[2 * i], ghosts = nl->base[2 * i + 1];
    for (int32_t n = 0; n < count; n++)
        entries[n] = (e[n] >= NEIGHBOUR_WINDOW ? ghosts - NEIGHBOUR_WINDOW : fluid) + e[n];
    return entries;
}

/* The list whose rows are the near parts of nl's (a view: the same arrays, nothing of its own
 * to free), for the pair loops at the positions of the build: the same pairs within 2h in the
 * same order as the whole rows give there, without the skin's, which add exactly zero. */
static inline neighbour_list neighbours_near(const neighbour_list *nl)
{
    neighbour_list near = *nl;
    near.count = nl->near;
    return near;
}

/* Whether row i may hold a ghost (a wall's image or a halo particle): the packed form's ghost
 * window has a base, the least ghost index (>= n_rows), only then (pack_row); the wide form
 * cannot tell and says yes. */
static inline bool neighbour_row_has_ghosts(const neighbour_list *nl, size_t i)
{
    return nl->wide || nl->base[2 * i + 1] != 0;
}

/* Cells are numbered strip by strip: the box is cut along x into strips of CELL_STRIP_WIDTH
 * cells, and within a strip row by row (x fastest, then y, then z). The particles, sorted by
 * cell, then have their neighbours within three rows of one strip (nine in 3D), whatever the
 * tank's length: numbered row by row across the whole box, a 2D tank of 1e6 particles put
 * twice the L2 cache between a particle and its neighbours above and below
 * (docs/performance.md). A strip's particles are also one contiguous range of the sorted
 * order, which is what the MPI build's slabs are made of (docs/mpi.md), whole strips each: a
 * box of fewer than CELL_MIN_STRIPS x CELL_STRIP_WIDTH cells along x, whose window is small
 * anyway, has strips of 1/CELL_MIN_STRIPS of its cells (at least one cell), so that it can be
 * split among up to CELL_MIN_STRIPS processes in slabs balanced to a strip. And a strip full
 * of liquid at the lattice's density holds at most CELL_STRIP_PARTICLES (narrower strips in a
 * tall or wide box, at least one cell): a row's fluid spans about one strip's particles where
 * it reaches into the next strip, which must fit the neighbour rows' 16-bit window, with room
 * for the liquid to be compressed or heaped up in one strip by sloshing. */
#define CELL_STRIP_WIDTH     16
#define CELL_MIN_STRIPS      16
#define CELL_STRIP_PARTICLES (NEIGHBOUR_WINDOW / 2)

#define cells_setup      DIM_NAME(cells_setup)
#define cells_column     DIM_NAME(cells_column)
#define cells_n_strips   DIM_NAME(cells_n_strips)
#define cells_mark       DIM_NAME(cells_mark)
#define cells_free       DIM_NAME(cells_free)
#define cells_bin        DIM_NAME(cells_bin)
#define cells_sort_order DIM_NAME(cells_sort_order)
#define neighbours_build DIM_NAME(neighbours_build)
#define neighbours_free  DIM_NAME(neighbours_free)

/* Lays out cubic cells of side cell_size over the box [lo, hi], the last along an axis reaching
 * past hi; particles outside it are clamped into the border cells (still found, just less
 * efficiently). `spacing` is the particles' lattice spacing, which bounds the strips' width
 * (CELL_STRIP_PARTICLES); 0: no bound from it. */
int cells_setup(cell_grid *g, const double lo[DIM], const double hi[DIM], double cell_size,
                double spacing);
void cells_free(cell_grid *g);
/* The column of cells (the cell coordinate along x) of position x along x, clamped into the
 * box as binning clamps it. */
int cells_column(const cell_grid *g, double x);
size_t cells_n_strips(const cell_grid *g);
/* Marks the cells that hold a binned particle j < n with flag[j] set, and those beside them,
 * for cells_marked_around. */
void cells_mark(cell_grid *g, const uint8_t *flag, size_t n);
/* Whether the cell of binned particle i, or one beside it, holds a particle cells_mark
 * marked: the 3^DIM cells a neighbour row of i is scanned from (with the binning's positions).
 * No marked neighbour can lie in a row where this is false. */
static inline bool cells_marked_around(const cell_grid *g, size_t i)
{
    return g->mark[g->cell_of[i]] & 2;
}
/* The first column of cells of strip k (of the box's end for k = cells_n_strips). */
static inline int cells_strip_column(const cell_grid *g, size_t k) { return (int)k * g->strip; }
/* The strip that holds position x along x. */
static inline size_t cells_strip_of(const cell_grid *g, double x)
{
    return (size_t)(cells_column(g, x) / g->strip);
}
/* Bins particles [0, n) by position: a stable counting sort. */
int cells_bin(cell_grid *g, double *const x[DIM], size_t n);
/* After cells_bin of n particles: order[k] = the particle that goes to slot k when particles
 * are sorted by cell (stable: ascending index within a cell). */
void cells_sort_order(const cell_grid *g, size_t n, uint32_t *order);
/* The row length neighbours_build gives rows whose longest has `longest` entries: a
 * sixteenth more, so that the rows a step later, whose particles have moved by less than the
 * skin, rarely overflow (on INM1 at N = 100 and INM2 3D at N = 20, only the first build
 * did). Not rounded to the SIMD scan's blocks of eight: the scan stores a whole block only
 * where the row has room for it, and appends the last few entries one by one. */
static inline size_t neighbours_row_room(int32_t longest)
{
    size_t room = (size_t)longest + (size_t)longest / 16;
    return room < NEIGHBOUR_ROW_MAX ? room : NEIGHBOUR_ROW_MAX;
}
/* Lists, for each of the first n_rows particles, its neighbours within `radius` among all the
 * binned particles, those at a squared distance below near2 first (the kernel's support2;
 * the squared distance added as vec_norm2 adds it, so a pair loop finds the same near pairs
 * to the bit); the positions' copy goes into `lent` where it is large enough (cells_room;
 * (cells_room){0}: the grid's own). Returns 0, or -1 when out of memory or when a row would
 * hold more than NEIGHBOUR_ROW_MAX entries. */
int neighbours_build(neighbour_list *nl, cell_grid *g, double *const x[DIM], size_t n_rows,
                     double radius, double near2, cells_room lent);
void neighbours_free(neighbour_list *nl);

#endif
