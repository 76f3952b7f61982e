/* fields.h - the particle quantities, each defined once (issue 33 item 2).
 *
 * Every quantity a frame colours by, sim:vtk writes, sim:record samples or
 * body:particles() returns is an entry of one table (fields.c): its name,
 * unit, components, the body kinds that have it, and the evaluator that
 * computes it from the particle state. The bindings read the table; none
 * of them derives physics of its own (a gas particle has one pressure
 * everywhere: its equation of state, [F] eq 22).
 *
 * Public (src/mpm/include): the bindings include it. */
#ifndef LAMINA_FIELDS_H
#define LAMINA_FIELDS_H

#include "mpm.h"

/* Body kinds as bits of lm_field.kinds. */
#define LM_FIELD_ELASTIC (1u << LM_ELASTIC)
#define LM_FIELD_MEMBRANE (1u << LM_MEMBRANE)
#define LM_FIELD_GAS (1u << LM_GAS)
#define LM_FIELD_FLUID (1u << LM_LINEAR_FLUID)
#define LM_FIELD_ALL (LM_FIELD_ELASTIC | LM_FIELD_MEMBRANE | LM_FIELD_GAS | LM_FIELD_FLUID)

#define LM_FIELD_MAX_COMP 4

typedef struct lm_field {
    const char *name;       /* the quantity's name (a scalar's is also its
                               component's: frames, records, particles()) */
    const char *unit;       /* dimensions: L length, T time, M mass,
                               F force, E energy; "1" a pure number */
    const char *meaning;    /* one line, as docs/api.md lists it */
    int ncomp;              /* 1 a scalar; 2 or 4 a vector or tensor */
    const char *comp[LM_FIELD_MAX_COMP];   /* the components' names (a
                               scalar's: NULL, the field's name) */
    const char *alias;      /* body:particles()'s older key when it differs
                               (docs/api.md before issue 33), else NULL */
    const char *vtk;        /* sim:vtk's array name, NULL: not written */
    unsigned kinds;         /* LM_FIELD_* bits: bodies that have it; the
                               others read 0 */
    int diverging;          /* signed about 0: frames' default map is rdbu */
    int tangents;           /* needs the membranes' tangents (a prepared
                               sim) */
    /* Writes the ncomp values of particle q to out. */
    void (*at)(const lm_sim *sim, size_t q, double *out);
} lm_field;

/* The table: entries 0 .. lm_field_count() - 1, in docs/api.md's order. */
int lm_field_count(void);
const lm_field *lm_field_get(int i);

/* The field whose name or a component's name is `name` (a scalar's
 * component is 0); the alias is not looked up. NULL when none. */
const lm_field *lm_field_find(const char *name, int *comp);

/* Does particle q's body kind have f? */
int lm_field_has(const lm_sim *sim, const lm_field *f, size_t q);

/* Component comp (-1: all, interleaved, ncomp per particle) of f at
 * particles first .. first + n - 1 into out; 0 where the kind lacks it. */
void lm_field_fill(const lm_sim *sim, const lm_field *f, int comp, size_t first, size_t n,
                   double *out);

/* Component comp of f at particle q (0 where its kind lacks it). */
double lm_field_value(const lm_sim *sim, const lm_field *f, int comp, size_t q);

#endif
