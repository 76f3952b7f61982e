/* test_seed.c - clipped seeding (seed.c, sim:body{fill = "clipped"}): the
 * cut sub-cells add up to the region's area, their centroids lie inside it,
 * whole sub-cells keep their centre, and a grid-aligned rectangle seeds as
 * the centres rule does. */
#include <math.h>

#include "check.h"
#include "mpm.h"

static int in_region(void *ctx, double x, double y)
{
    return lm_region_contains(ctx, x, y);
}

/* Sum of the clipped areas over every sub-cell of the grid; counts the cut
 * and the whole sub-cells and checks each centroid against the region. */
static double clipped_area(const lm_grid *g, int np, lm_region *r, int *cut, int *whole)
{
    lm_seed_range range = lm_seed_range_for(g, np, np, g->x0, g->y0,
                                            g->x0 + g->nx * g->hx, g->y0 + g->ny * g->hy);
    double sub = g->hx * g->hy / (np * np), area = 0;
    *cut = *whole = 0;
    for (size_t k = 0; k < lm_seed_count(&range); k++) {
        double x, y, cx, cy;
        lm_seed_point(g, &range, k, &x, &y);
        double part = lm_seed_clip(g, np, np, x, y, in_region, r, &cx, &cy);
        CHECK(part >= 0 && part <= 1);
        if (part == 0) continue;
        CHECK(lm_region_contains(r, cx, cy));
        CHECK(fabs(cx - x) <= 0.5 * g->hx / np && fabs(cy - y) <= 0.5 * g->hy / np);
        if (part == 1) {
            (*whole)++;
            CHECK(cx == x && cy == y);
        } else (*cut)++;
        area += part * sub;
    }
    return area;
}

int main(void)
{
    lm_grid g = {0};
    g.x0 = 0; g.y0 = 0; g.hx = g.hy = 0.1; g.nx = g.ny = 10;
    int cut, whole;

    /* the disk of [N] §8 (radius 0.5 about the origin, a quarter inside the
     * grid) at 16 ppc: area pi r^2 / 4 to the 1/256 sampling of the cut
     * sub-cells, where the centres rule misses by up to a sub-cell row */
    lm_region disk = { .kind = LM_REGION_DISK, .cx = 0, .cy = 0, .r = 0.5,
                       .x0 = -0.5, .y0 = -0.5, .x1 = 0.5, .y1 = 0.5 };
    double exact = acos(-1.0) * 0.25 * 0.25;
    double a = clipped_area(&g, 4, &disk, &cut, &whole);
    CHECK(cut > 20 && whole > 250);
    CHECK_NEAR(a / exact, 1.0, 5e-5);

    /* a rectangle on sub-cell lines: nothing is cut, the area is exact */
    lm_region rect = { .kind = LM_REGION_RECT, .x0 = 0.2, .y0 = 0.1, .x1 = 0.65, .y1 = 0.4 };
    a = clipped_area(&g, 4, &rect, &cut, &whole);
    CHECK(cut == 0 && whole == 18 * 12);
    CHECK_NEAR(a, 0.45 * 0.3, 1e-12);
    return CHECK_DONE();
}
