/* cells: binning by counting sort and gather-style neighbour lists. */
#include "core/cells.h"
#include "core/cells_scan.h"
#include "core/team_loop.h"
#include "core/vec.h"

#include <stdlib.h>
#include <string.h>

/* The widest strip (in cells along x, 1 to CELL_STRIP_WIDTH) that holds at most
 * CELL_STRIP_PARTICLES at the lattice's density. */
static int strip_width_bound(const cell_grid *g, double spacing)
{
    double column = 1.0; /* particles in one column of cells along x, full of liquid */
    for (int d = 0; d < DIM; d++) column *= g->size / spacing * (d > 0 ? g->n[d] : 1);
    double width = floor(CELL_STRIP_PARTICLES / column);
    return width < 1.0 ? 1 : width > CELL_STRIP_WIDTH ? CELL_STRIP_WIDTH : (int)width;
}

int cells_setup(cell_grid *g, const double lo[DIM], const double hi[DIM], double cell_size,
                double spacing)
{
    /* Cubic cells of the side asked for, as many as cover the box: the last one along an axis
       reaches a little past `hi`. Cells grown to cover the box exactly took the largest
       growth of any axis for all three: the 3D benchmark's tank, 0.1 m wide, had cells a
       third wider than the search radius at 7,560 particles and 2.3 times the candidates a
       row scan tests (docs/performance.md). */
    size_t n_cells = 1;
    for (int d = 0; d < DIM; d++) {
        g->origin[d] = lo[d];
        int n = (int)ceil((hi[d] - lo[d]) / cell_size);
        g->n[d] = n < 1 ? 1 : n;
        n_cells *= (size_t)g->n[d];
    }
    g->size = cell_size;
    int widest = spacing > 0.0 ? strip_width_bound(g, spacing) : CELL_STRIP_WIDTH;
    g->strip = g->n[0] / CELL_MIN_STRIPS;
    if (g->strip > widest) g->strip = widest;
    if (g->strip < 1) g->strip = 1;
    g->n_cells = n_cells;
    if (n_cells + 1 > g->cells_capacity) {
        size_t *s = realloc(g->start, (n_cells + 1) * sizeof *s);
        if (!s) return -1;
        g->start = s;
        uint8_t *mark = realloc(g->mark, n_cells + 1);
        if (!mark) return -1;
        g->mark = mark;
        g->cells_capacity = n_cells + 1;
    }
    return 0;
}

void cells_free(cell_grid *g)
{
    free(g->start);
    free(g->item);
    free(g->cell_of);
    free(g->counts);
    free(g->mark);
    free(g->own_xs);
    memset(g, 0, sizeof *g);
}

static inline int cell_coord(const cell_grid *g, int d, double x)
{
    int c = (int)floor((x - g->origin[d]) / g->size);
    if (c < 0) return 0;
    if (c >= g->n[d]) return g->n[d] - 1;
    return c;
}

/* The coordinates of the cell that holds particle i */
static inline void cell_coords_of(const cell_grid *g, double *const x[DIM], size_t i, int c[DIM])
{
    for (int d = 0; d < DIM; d++) c[d] = cell_coord(g, d, x[d][i]);
}

int cells_column(const cell_grid *g, double x) { return cell_coord(g, 0, x); }

size_t cells_n_strips(const cell_grid *g) { return (size_t)((g->n[0] + g->strip - 1) / g->strip); }

/* The index of cell c, which lies in strip `strip` (c[0] / g->strip) */
static inline size_t cell_index_in_strip(const cell_grid *g, int strip, const int c[DIM])
{
    int x0 = strip * g->strip;
    int width = g->n[0] - x0 < g->strip ? g->n[0] - x0 : g->strip;
    size_t rows = 1; /* the rows of cells along x in one strip: n[1] (x n[2]) */
    for (int d = 1; d < DIM; d++) rows *= (size_t)g->n[d];
    size_t row = (size_t)c[DIM - 1];
    for (int d = DIM - 2; d >= 1; d--) row = row * (size_t)g->n[d] + (size_t)c[d];
    return (size_t)x0 * rows + row * (size_t)width + (size_t)(c[0] - x0);
}

static inline size_t cell_index(const cell_grid *g, const int c[DIM])
{
    return cell_index_in_strip(g, c[0] / g->strip, c);
}

/* Room for each of `threads` threads' counts in every cell (cells_bin) */
static int reserve_counts(cell_grid *g, int threads)
{
    size_t need = (size_t)threads * g->n_cells;
    if (need <= g->counts_capacity) return 0;
    uint32_t *counts = realloc(g->counts, need * sizeof *counts);
    if (!counts) return -1;
    g->counts = counts;
    g->counts_capacity = need;
    return 0;
}

int cells_bin(cell_grid *g, double *const x[DIM], size_t n)
{
    if (n > g->item_capacity) {
        uint32_t *item = realloc(g->item, n * sizeof *item);
        if (!item) return -1;
        g->item = item;
        uint32_t *cell_of = realloc(g->cell_of, n * sizeof *cell_of);
        if (!cell_of) return -1;
        g->cell_of = cell_of;
        g->item_capacity = n;
    }
    /* A counting sort, stable: each thread counts its share of the particles in every cell,
       each cell's places go to the threads' shares in order, and each thread fills its own in
       ascending particle order, so a cell lists its particles in ascending order whatever the
       thread count. */
    if (reserve_counts(g, team_loop_threads())) return -1;
#pragma omp parallel
    {
        int t = team_thread(), threads = team_threads();
        size_t first = n * (size_t)t / (size_t)threads, end = n * (size_t)(t + 1) / (size_t)threads;
        uint32_t *mine = g->counts + (size_t)t * g->n_cells;
        memset(mine, 0, g->n_cells * sizeof *mine);
        for (size_t i = first; i < end; i++) {
            int c[DIM];
            cell_coords_of(g, x, i, c);
            g->cell_of[i] = (uint32_t)cell_index(g, c);
            mine[g->cell_of[i]]++;
        }
#pragma omp barrier
#pragma omp single
        {
            size_t place = 0;
            for (size_t c = 0; c < g->n_cells; c++) {
                g->start[c] = place;
                for (int u = 0; u < threads; u++) { /* the count becomes the share's place */
                    uint32_t *count = &g->counts[(size_t)u * g->n_cells + c];
                    size_t k = *count;
                    *count = (uint32_t)place;
                    place += k;
                }
            }
            g->start[g->n_cells] = place;
        }
        for (size_t i = first; i < end; i++) g->item[mine[g->cell_of[i]]++] = (uint32_t)i;
    }
    return 0;
}

void cells_sort_order(const cell_grid *g, size_t n, uint32_t *order)
{
    size_t k = 0;
    for (size_t m = 0; m < g->start[g->n_cells]; m++) {
        uint32_t i = g->item[m];
        if (i < n) order[k++] = i;
    }
}

void neighbours_free(neighbour_list *nl)
{
    free(nl->count);
    free(nl->near);
    free(nl->packed);
    free(nl->base);
    free(nl->index);
    memset(nl, 0, sizeof *nl);
}

/* The cells' coordinates lo[d] .. hi[d] of the 3^DIM cells around cell c0, within the box */
static inline void cells_around(const cell_grid *g, const int c0[DIM], int lo[DIM], int hi[DIM])
{
    for (int d = 0; d < DIM; d++) {
        lo[d] = c0[d] > 0 ? c0[d] - 1 : 0;
        hi[d] = c0[d] < g->n[d] - 1 ? c0[d] + 1 : g->n[d] - 1;
    }
}

/* Whether a cell of the 3^DIM around cell c (by its coordinates) holds a mark */
static bool marked_around(const cell_grid *g, const int c0[DIM])
{
    int lo[DIM], hi[DIM];
    cells_around(g, c0, lo, hi);
    int c[DIM];
#if DIM == 3
    for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
#endif
        for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
            for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++)
                if (g->mark[cell_index(g, c)] & 1) return true;
    return false;
}

void cells_mark(cell_grid *g, const uint8_t *flag, size_t n)
{
#pragma omp parallel for schedule(static)
    for (size_t c = 0; c < g->n_cells; c++) {
        uint8_t marked = 0;
        for (size_t m = g->start[c]; m < g->start[c + 1] && !marked; m++)
            marked = g->item[m] < n && flag[g->item[m]];
        g->mark[c] = marked;
    }
    /* bit 1: a mark in the cell or one beside it, cell by cell through their coordinates */
    size_t rows = g->n_cells / (size_t)g->n[0];
#pragma omp parallel for schedule(static)
    for (size_t r = 0; r < rows; r++) {
        int c[DIM];
        size_t rest = r;
        for (int d = 1; d < DIM; d++) {
            c[d] = (int)(rest % (size_t)g->n[d]);
            rest /= (size_t)g->n[d];
        }
        for (c[0] = 0; c[0] < g->n[0]; c[0]++)
            if (marked_around(g, c)) g->mark[cell_index(g, c)] |= 2;
    }
}

/* Scans the 3^DIM cells around particle i in a fixed order into the row. */
static void scan_neighbours(const cell_grid *g, double *const x[DIM], size_t i, double r2max,
                            scan_row *row, cells_scan_fn scan)
{
    int c0[DIM], lo[DIM], hi[DIM];
    cell_coords_of(g, x, i, c0);
    cells_around(g, c0, lo, hi);
    vec xi = vec_load(x, i);
    int c[DIM];
#if DIM == 3
    for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
#endif
        for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
            /* cells adjacent along x are contiguous in the item array within a strip: one
             * run of cells, or two where the row crosses into the next strip */
            for (int from = lo[0], strip = lo[0] / g->strip; from <= hi[0]; strip++) {
                int strip_end = (strip + 1) * g->strip - 1;
                int to = hi[0] < strip_end ? hi[0] : strip_end;
                c[0] = from;
                size_t first = g->start[cell_index_in_strip(g, strip, c)];
                c[0] = to;
                size_t last = g->start[cell_index_in_strip(g, strip, c) + 1];
                scan(g, first, last, xi, (uint32_t)i, r2max, row);
                from = to + 1;
            }
}

/* Row `row` (count entries) in 16 bits (neighbour_list): packed[] and its two windows' bases;
 * false when an entry lies beyond its window. The fluid's indices all lie below the ghosts',
 * so the row's least and greatest entries bound the two windows from outside; the selections
 * are masks, which GCC 12 vectorises (and each window's bounds variables of their own: its
 * vectoriser got an array indexed by row[n] >= n_rows wrong at -O3). */
static bool pack_row(const int32_t *row, int32_t count, int32_t n_rows, uint16_t *packed,
                     int32_t base[2])
{
    int32_t lo = INT32_MAX, hi = -1, fluid_hi = -1, ghosts_lo = INT32_MAX;
    for (int32_t n = 0; n < count; n++) {
        int32_t j = row[n], ghost = -(int32_t)(j >= n_rows); /* all ones for a ghost */
        int32_t as_fluid = j | ghost, as_ghost = j | (~ghost & INT32_MAX); /* else -1, MAX */
        lo = j < lo ? j : lo;
        hi = j > hi ? j : hi;
        fluid_hi = as_fluid > fluid_hi ? as_fluid : fluid_hi;
        ghosts_lo = as_ghost < ghosts_lo ? as_ghost : ghosts_lo;
    }
    int32_t fluid = fluid_hi >= 0 ? lo : 0, ghosts = ghosts_lo < INT32_MAX ? ghosts_lo : 0;
    if (fluid_hi >= 0 && fluid_hi - fluid >= NEIGHBOUR_WINDOW) return false;
    if (ghosts_lo < INT32_MAX && hi - ghosts >= NEIGHBOUR_WINDOW) return false;
    for (int32_t n = 0; n < count; n++)
        packed[n] =
            (uint16_t)(row[n] >= n_rows ? NEIGHBOUR_WINDOW + (row[n] - ghosts) : row[n] - fluid);
    base[0] = fluid;
    base[1] = ghosts;
    return true;
}

/* Room for n_rows rows of the list's length in its form (packed or wide); 0 or -1. The array is
 * reallocated when too small, or when an eighth or more of it would lie unused. */
static int reserve_rows(neighbour_list *nl, size_t n_rows)
{
    if (n_rows > nl->capacity_rows) {
        neighbour_count *count = realloc(nl->count, n_rows * sizeof *count);
        if (!count) return -1;
        nl->count = count;
        int32_t *base = realloc(nl->base, 2 * n_rows * sizeof *base);
        if (!base) return -1;
        nl->base = base;
        neighbour_count *near = realloc(nl->near, n_rows * sizeof *near);
        if (!near) return -1;
        nl->near = near;
        nl->capacity_rows = n_rows;
    }
    size_t need = (n_rows ? n_rows : 1) * nl->row_capacity;
    bool held = nl->wide ? nl->index != NULL : nl->packed != NULL; /* the form's array exists */
    if (held && need <= nl->index_capacity && need > nl->index_capacity - nl->index_capacity / 8)
        return 0;
    free(nl->packed);
    free(nl->index);
    nl->packed = NULL;
    nl->index = NULL;
    nl->index_capacity = 0;
    if (nl->wide)
        nl->index = malloc(need * sizeof *nl->index);
    else
        nl->packed = malloc(need * sizeof *nl->packed);
    if (!nl->index && !nl->packed) return -1;
    nl->index_capacity = need;
    return 0;
}

/* Points g->xs at room for the binned positions: the lent room, or the grid's own. */
static int place_positions(cell_grid *g, size_t binned, cells_room lent)
{
    double *room = lent.at;
    if (!room || lent.doubles < DIM * binned) {
        if (DIM * binned > g->own_xs_capacity) {
            free(g->own_xs);
            g->own_xs = malloc(DIM * binned * sizeof *g->own_xs);
            g->own_xs_capacity = g->own_xs ? DIM * binned : 0;
            if (!g->own_xs) return -1;
        }
        room = g->own_xs;
    }
    for (int d = 0; d < DIM; d++) g->xs[d] = room + (size_t)d * binned;
    return 0;
}

/* Particle i's row into `row` (room for cap + CELLS_SPLIT_SLACK entries): the neighbours
 * within the kernel's support (squared distance below near2) first, then the skin, each part
 * in the scan's order (cells_split_fn), with the near part's count in *near. Returns the
 * row's count, which may exceed cap (then the row is not whole and the build is redone).
 * `scanned` is room for the scan's row and its squared distances, `skin` for the split. */
static int32_t row_of(const cell_grid *g, double *const x[DIM], size_t i, double r2max,
                      double near2, scan_row *scanned, int32_t *row, int32_t *skin,
                      neighbour_count *near, cells_scan_fn scan, cells_split_fn split)
{
    scanned->found = 0;
    scan_neighbours(g, x, i, r2max, scanned, scan);
    if (scanned->found <= scanned->cap)
        *near = split(scanned->entries, scanned->r2, scanned->found, near2, row, skin);
    return scanned->found;
}

/* neighbours_build's rows, from the positions' copy in g->xs. */
static int build_rows(neighbour_list *nl, const cell_grid *g, double *const x[DIM], size_t n_rows,
                      double radius, double near2)
{
    double r2max = radius * radius;
    cells_scan_fn scan = cells_scan_form();
    cells_split_fn split = cells_split_form();
    nl->radius = radius;
    nl->n_rows = n_rows;
    /* rows sized by the last build's longest (neighbour counts change little from step to
       step); the first build guesses, 64 entries in 2D and 128 in 3D, and at rest a particle
       has about 48 (2D) or 127 (3D) within 2h and the skin */
    if (nl->longest > 0)
        nl->row_capacity = neighbours_row_room(nl->longest);
    else if (nl->row_capacity == 0)
        nl->row_capacity = DIM == 2 ? 64 : 128;
    for (;;) {
        if (reserve_rows(nl, n_rows)) return -1;
        int32_t cap = (int32_t)nl->row_capacity, most = 0;
        bool misfit = false;
        TEAM_LOOP_SHARES(q, n_rows, TEAM_CHUNK);
#pragma omp parallel reduction(max : most) reduction(|| : misfit)
        {
            /* the scan's row and distances, the room of the split, and the row laid out */
            int32_t entries[cap], skin[cap + CELLS_SPLIT_SLACK], row[cap + CELLS_SPLIT_SLACK];
            double r2[cap];
            scan_row scanned = {.entries = entries, .r2 = r2, .cap = cap};
            TEAM_LOOP_FOR (&q, begin, end)
                for (size_t i = begin; i < end; i++) {
                    size_t at = i * (size_t)cap;
                    int32_t k = row_of(g, x, i, r2max, near2, &scanned, row, skin, nl->near + i,
                                       scan, split);
                    if (k <= cap) { /* else the row is not whole, and the build is redone */
                        if (nl->wide)
                            memcpy(nl->index + at, row, (size_t)k * sizeof *row);
                        else if (!pack_row(row, k, (int32_t)n_rows, nl->packed + at,
                                           nl->base + 2 * i))
                            misfit = true;
                    }
                    nl->count[i] = (neighbour_count)k; /* whole only when k <= cap */
                    if (k > most) most = k;
                }
        }
        nl->longest = most;
        if (!misfit && most <= cap) return 0;
        if (misfit) nl->wide = true; /* a row beyond its 16-bit windows: 32 bits from now on */
        if (most > NEIGHBOUR_ROW_MAX) return -1;
        /* a row overflowed (strong compression): redo with room to spare */
        if (most > cap) nl->row_capacity = neighbours_row_room(most);
    }
}

int neighbours_build(neighbour_list *nl, cell_grid *g, double *const x[DIM], size_t n_rows,
                     double radius, double near2, cells_room lent)
{
    size_t binned = g->start[g->n_cells];
    /* the binned positions in item order, which the scan reads a block at a time */
    if (place_positions(g, binned, lent)) return -1;
#pragma omp parallel for schedule(static)
    for (size_t m = 0; m < binned; m++)
        for (int d = 0; d < DIM; d++) g->xs[d][m] = x[d][g->item[m]];
    int status = build_rows(nl, g, x, n_rows, radius, near2);
    for (int d = 0; d < DIM; d++) g->xs[d] = NULL; /* the lent room goes back to its owner */
    return status;
}
