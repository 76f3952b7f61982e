/* region.c - the built-in region shapes: disk, rectangle, polygon. */
#include "mpm.h"

/* Even-odd rule: a ray to +x crosses the boundary an odd number of times. */
static int polygon_contains(const lm_region *r, double x, double y)
{
    int in = 0;
    for (int a = 0, b = r->nv - 1; a < r->nv; b = a++) {
        double ya = r->vy[a], yb = r->vy[b];
        if ((ya > y) != (yb > y)) {
            double xc = r->vx[a] + (y - ya) * (r->vx[b] - r->vx[a]) / (yb - ya);
            if (x < xc) in = !in;
        }
    }
    return in;
}

int lm_region_contains(const lm_region *r, double x, double y)
{
    switch (r->kind) {
    case LM_REGION_DISK: {
        double dx = x - r->cx, dy = y - r->cy;
        return dx * dx + dy * dy <= r->r * r->r;
    }
    case LM_REGION_RECT:
        return x >= r->x0 && x <= r->x1 && y >= r->y0 && y <= r->y1;
    case LM_REGION_POLYGON:
        return polygon_contains(r, x, y);
    }
    return 0;
}
