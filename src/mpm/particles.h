/* particles.h - storage of the particle arrays (internal). */
#ifndef LAMINA_PARTICLES_H
#define LAMINA_PARTICLES_H

#include "mpm.h"

int lm_particles_reserve(lm_particles *p, size_t cap);
void lm_particles_free(lm_particles *p);

#endif
