/* sim3_walls.c - walls per face of the 3D grid: the 2D rules of
 * grid.c and grid_walls.c with six faces instead of four
 * (docs/decisions.md "Walls for the wider bases", docs/3d.md).
 *
 * A face is an axis a and a side (the node plane i_a = 0 or n_a). With the
 * quadratic B-spline the grid has a ring of ghost nodes one node beyond
 * each face, and the ghost means the image of its mirror node (one node
 * inside): symmetry - the mirror image (normal component -1, tangential
 * and scalar +1); fixed - the antisymmetric one (every component -1, so a
 * point on the wall interpolates zero velocity for either basis); free -
 * no image (ghosts are ordinary nodes). Scatters fold the ghosts into
 * their mirrors, gathers fill them, faces taken x, then y, then z over the
 * whole padded plane so an edge or corner ghost gets every image. */
#include "grid_mirror.h"
#include "sim3_walls.h"

/* The nodes of the padded plane i_a = layer, numbered k = 0 .. count-1
 * over the two other indices. */
static long plane_count(const lm3_grid *g, int a)
{
    return g->s[(a + 1) % 3] * g->s[(a + 2) % 3];
}

/* The k-th node of the plane i_a = layer (k < plane_count) */
static long plane_node(const lm3_grid *g, int a, int layer, long k)
{
    int b = (a + 1) % 3, c = (a + 2) % 3;
    int idx[3];
    idx[a] = layer;
    idx[b] = (int)(k % g->s[b]) - g->pad;
    idx[c] = (int)(k / g->s[b]) - g->pad;
    return lm3_node(g, idx[0], idx[1], idx[2]);
}

void lm3_grid_apply_bc(const lm3_grid *g, double *const u[3])
{
    for (int f = 0; f < LM3_FACES; f++) {
        lm_bc bc = g->bc[f];
        if (bc == LM_BC_FREE) continue;
        int a = f / 2, layer = f % 2 ? g->n[a] : 0;
        long cnt = plane_count(g, a);
        for (long k = 0; k < cnt; k++) {
            long i = plane_node(g, a, layer, k);
            if (bc == LM_BC_FIXED) u[0][i] = u[1][i] = u[2][i] = 0;
            else u[a][i] = 0;
        }
    }
}

static double image_sign(lm_bc bc, int axis, int comp)
{
    if (comp == LM3_SCALAR) return 1;
    if (bc == LM_BC_FIXED) return -1;
    return comp == axis ? -1 : 1;   /* symmetry */
}

/* fold = 1: f[mirror] += s f[ghost], f[ghost] = 0; fold = 0:
 * f[ghost] = s f[mirror]. */
static void walls(const lm3_grid *g, int nf, double *const *fl, const int *comp, int fold)
{
    if (g->pad == 0) return;
    for (int f = 0; f < LM3_FACES; f++) {
        lm_bc bc = g->bc[f];
        if (bc == LM_BC_FREE) continue;
        int a = f / 2;
        int ghost = f % 2 ? g->n[a] + 1 : -1, mirror = f % 2 ? g->n[a] - 1 : 1;
        double s[16];
        for (int c = 0; c < nf; c++) s[c] = image_sign(bc, a, comp[c]);
        long cnt = plane_count(g, a);
        for (long k = 0; k < cnt; k++) {
            long gh = plane_node(g, a, ghost, k), mi = plane_node(g, a, mirror, k);
            lm_grid_mirror(nf, fl, s, gh, mi, fold);
        }
    }
}

void lm3_grid_fold(const lm3_grid *g, int nf, double *const *f, const int *comp)
{
    walls(g, nf, f, comp, 1);
}

void lm3_grid_fill(const lm3_grid *g, int nf, double *const *f, const int *comp)
{
    walls(g, nf, f, comp, 0);
}
