/* l_pressure3.h - a 3D particle's "pressure", one definition for every
 * reader of a 3D run (body:particles(), the frame's colour and slice, VTK),
 * as the 2D field table's (src/mpm/fields.c; docs/api.md "Particle
 * fields"): a gas's equation of state (gamma - 1) rho e ([F] eq 22),
 * without the artificial viscosity q of the step's stress; any other
 * body's mean stress's negative -tr sigma / 3. */
#ifndef LAMINA_L_PRESSURE3_H
#define LAMINA_L_PRESSURE3_H

#include <stddef.h>

#include "mpm3.h"

static inline double la_pressure3(const lm3_sim *s, size_t q)
{
    const lm3_particles *p = &s->p;
    const lm3_material *m = &s->mats[p->mat[q]];
    if (m->kind == LM3_GAS) return (m->gamma - 1) * p->rho[q] * p->e[q];
    return -(p->s[0][q] + p->s[1][q] + p->s[2][q]) / 3.0;
}

#endif
