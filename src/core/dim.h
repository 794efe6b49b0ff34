/* dim: compile-time number of space dimensions and the symbol suffix that lets the 2D and 3D
 * builds of the particle code live in one binary (docs/architecture.md). */
#ifndef VCSPH_DIM_H
#define VCSPH_DIM_H

#ifndef DIM
#error "compile the particle code with -DDIM=2 or -DDIM=3"
#endif
#if DIM != 2 && DIM != 3
#error "DIM must be 2 or 3"
#endif

#define DIM_PASTE_(name, n) name##_##n##d
#define DIM_PASTE(name, n)  DIM_PASTE_(name, n)
/* DIM_NAME(cells_build) is cells_build_2d or cells_build_3d. Headers of the particle code
 * rename their public functions with it, so callers write the plain name. */
#define DIM_NAME(name) DIM_PASTE(name, DIM)

#endif
