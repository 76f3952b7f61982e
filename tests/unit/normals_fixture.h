/* normals_fixture.h - point sets shared by the normals unit tests. */
#ifndef LAMINA_NORMALS_FIXTURE_H
#define LAMINA_NORMALS_FIXTURE_H

#include <math.h>

/* n points spread evenly (a golden-angle spiral) over the octant x, y, z
 * >= 0 of the sphere of radius r about the origin ([N] Fig 5, 11). */
static void sphere_octant(int n, double r, double *x, double *y, double *z)
{
    const double pi = 3.14159265358979323846;
    double golden = (3 - sqrt(5.0)) * pi;
    for (int k = 0; k < n; k++) {
        double c = (k + 0.5) / n, s = sqrt(1 - c * c), ph = 0.5 * pi * fmod(k * golden, 1.0);
        x[k] = r * s * cos(ph);
        y[k] = r * s * sin(ph);
        z[k] = r * c;
    }
}

#endif
