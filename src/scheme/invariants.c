/* invariants: the debug build's checks of a step's state (invariants.h). */
#include "scheme/invariants.h"
#include "core/invariant.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int particle_broken(const solver *s, size_t i, char *what, size_t size)
{
    const particles *p = &s->p;
    vec x = vec_load(p->x, i), u = vec_load(p->u, i);
    for (int d = 0; d < DIM; d++)
        if (!isfinite(x.c[d]) || !isfinite(u.c[d])) {
            snprintf(what, size, "particle %zu (id %lld): non-finite position or velocity", i,
                     (long long)p->id[i]);
            return 1;
        }
    if (!(p->rho[i] > 0.0 && isfinite(p->rho[i]) && p->m[i] > 0.0 && isfinite(p->m[i]))) {
        snprintf(what, size, "particle %zu (id %lld): density %g, mass %g", i, (long long)p->id[i],
                 p->rho[i], p->m[i]);
        return 1;
    }
    if (!tank_contains(&s->tank, x)) {
        snprintf(what, size, "particle %zu (id %lld) outside the tank after bounce-back, at x =", i,
                 (long long)p->id[i]);
        for (int d = 0; d < DIM; d++) {
            size_t used = strlen(what);
            snprintf(what + used, size - used, " %.17g", x.c[d]);
        }
        return 1;
    }
    return 0;
}

static int row_broken(const solver *s, const neighbour_list *nl, size_t i, int32_t *entries,
                      char *what, size_t size)
{
    const int32_t *row = neighbour_row(nl, i, entries);
    for (int32_t n = 0; n < nl->count[i]; n++) {
        int32_t j = row[n];
        if (j < 0 || (size_t)j >= s->p.n_total || (size_t)j == i) {
            snprintf(what, size, "row %zu, entry %d: particle %d (the store holds %zu)", i, (int)n,
                     (int)j, s->p.n_total);
            return 1;
        }
    }
    return 0;
}

static double total_mass(const particles *p)
{
    double sum = 0.0;
    for (size_t i = 0; i < p->n_fluid; i++) sum += p->m[i];
    return sum;
}

int solver_invariants_broken(const solver *s, double mass_reference, char *what, size_t size)
{
    const particles *p = &s->p;
    for (size_t i = 0; i < p->n_fluid; i++)
        if (particle_broken(s, i, what, size)) return 1;
    if (s->nl.n_rows > 0) {
        int32_t *entries = malloc((s->nl.row_capacity + 1) * sizeof *entries);
        if (!entries) {
            snprintf(what, size, "out of memory");
            return 1;
        }
        int broken = 0;
        for (size_t i = 0; i < s->nl.n_rows && !broken; i++)
            broken = row_broken(s, &s->nl, i, entries, what, size);
        free(entries);
        if (broken) return 1;
    }
    if (mass_reference > 0.0) {
        double change = total_mass(p) / mass_reference - 1.0;
        if (!(fabs(change) <= INVARIANT_MASS_TOLERANCE)) {
            snprintf(what, size,
                     "the liquid's total mass changed by %.3g (relative) since the "
                     "first check",
                     change);
            return 1;
        }
    }
    return 0;
}

void solver_check_invariants(solver *s)
{
    if (!INVARIANTS_ON) return;
    if (!s->domain && s->mass_reference == 0.0) s->mass_reference = total_mass(&s->p);
    char what[256];
    if (solver_invariants_broken(s, s->domain ? 0.0 : s->mass_reference, what, sizeof what))
        invariant_broken("the step's state", what);
}
