/* grid_mirror.h - one ghost node against its mirror node across a wall,
 * shared by the 2D walls (grid_walls.c) and the 3D ones (sim3_walls.c):
 * folding adds the ghost's sum into the mirror with each field's image sign
 * s (a symmetry wall reverses the normal component, a fixed wall every
 * component) and empties the ghost; filling copies the mirror back out. */
#ifndef LAMINA_GRID_MIRROR_H
#define LAMINA_GRID_MIRROR_H

static inline void lm_grid_mirror(int nf, double *const *f, const double *s, long gh, long mi,
                                  int fold)
{
    for (int c = 0; c < nf; c++) {
        if (fold) {
            f[c][mi] += s[c] * f[c][gh];
            f[c][gh] = 0;
        } else {
            f[c][gh] = s[c] * f[c][mi];
        }
    }
}

#endif
